"""The deck's runs made for real where a pass with them skipped cannot tell what the deck reads.

Field rounds 10 and 11 (D1, D2): after a run in which spheres fall, ``set region low diameter 0.02``,
a group by region, an atom-style variable of z, ``set region low type 2``, an ``if`` on a count
after a pour or on a position, a pour that may have finished before a ``set``: the pass whose runs
LAMMPS skips meets the atoms where they were before the runs, so such a set was refused and such a
stage's rows marked ``may_differ`` / ``if_poured``, although LAMMPS runs every one of these decks.
Now LAMMPS makes the runs (outputs not written, within ``--run-budget``) and the audit reads the
state they reach: each deck's last stage holds the types and sizes LAMMPS holds at the deck's end,
and its eps is LAMMPS' own head-on (4000 to 16000 steps per contact, dt -> 0). ``--run-budget 0``,
or a budget that runs out, keeps the refusal or the mark, and says which option raises it."""

from pathlib import Path

import pytest

from deck_cli import LAMMPS_TWO, agrees_with_lammps, as_without_runs, lammps_held_at_end, needs_lammps, run

FIELD = Path(__file__).resolve().parents[1]
VISCO = "pair_coeff * * hertz/material 1e7 {} 0.3 damping viscoelastic tangential linear_nohistory 1 0.3"
RESTITUTION = "pair_coeff {} hertz/material 1e7 {} 0.3 damping coeff_restitution tangential linear_nohistory 1 0.3"

HOOKE = "pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"

#: deck -> (the contact lines in force at its last run, as it types them; what the pass with runs
#: skipped does with it)
DECKS = {
    "field11/decks/a23_atomvar_position_after_run": (VISCO.format("3e6"), "refused"),
    "field11/decks/a24_set_region_after_fall": (VISCO.format("3e6"), "refused"),
    "field11/decks/a25_group_region_after_fall": (VISCO.format("3e6"), "refused"),
    "field11/decks/a35_set_type_region_after_fall": ("\n".join(
        RESTITUTION.format(pair, e) for pair, e in (("1 1", 0.9), ("2 2", 0.3), ("1 2", 0.6))), "refused"),
    "field11/decks/a26_if_position_after_fall": (VISCO.format("3e5"), "may_differ"),
    "field11/decks/a01_if_count_after_pour": (RESTITUTION.format("* *", 0.9), "may_differ"),
    # field round 13 (D1): fix adapt ... reset no grows the diameters from 0.004 to 0.006 in the first
    # run; the later stage was audited at the sizes before it, silently (a38 types 1 2: 0.4973 where
    # LAMMPS gives 0.2551)
    "field13/decks/a07_adapt_grow_then_set_density": (HOOKE, "may_differ"),
    "field13/decks/a38_adapt_grow_then_run": (HOOKE, "may_differ"),
    # field round 13 (D4): fix halt ends the run at step 10900, so `if "$(step) < 50000"` sets density
    # 1000; the halt was not executed and the step read as the run's end (types 1 1: 0.4973 where
    # LAMMPS gives 0.6470)
    "field13/decks/a25b_halt_then_step_branch": (HOOKE, "may_differ"),
    # field round 14 (D4): fix adapt/fep grows type 2 from 0.004 to 0.006 in the first run; it was taken
    # for an unknown force and the later stage audited at the sizes before it (2 2: 0.4973 where LAMMPS
    # gives 0.2551)
    "field14/decks/r06_adapt_fep_diameter": (HOOKE, "may_differ"),
    # field round 14 (D1): in the runs made for real, the marker's run of no step after each run set up
    # fix adapt once more: a ramp() growth back at its start, a scale yes factor applied twice (r18 1 2:
    # 0.4973, r02: 0.0340, where LAMMPS gives 0.2551)
    "field14/decks/r18_adapt_ramp_growth": (HOOKE, "may_differ"),
    "field14/decks/r02_adapt_diameter_scale_yes": (HOOKE, "may_differ"),
    # field round 13 (D5): a count after a pour (count(all) in a variable, immediate, the atoms
    # keyword) picks an if's branch, and loops end on a count, an energy, the step: the pass with
    # the runs skipped took the other branch or ran its loop out and stopped (Set command on system
    # without atoms; an undefined loop variable), which the deck run by hand never does
    "field13/decks/a03_count_after_pour_if": (HOOKE, "stopped"),
    "field13/decks/a03b_count_immediate_after_pour_if": (HOOKE, "stopped"),
    "field13/decks/a03c_atoms_thermo_after_pour": (HOOKE, "stopped"),
    "field13/decks/a27_loop_pour_until_count": (HOOKE, "stopped"),
    "field13/decks/a30_pe_energy_threshold_loop": (HOOKE, "stopped"),
    "field13/decks/a33_step_loop_until": (HOOKE + "\n" + HOOKE.replace("* *", "1 2").replace("3000", "2500"), "stopped"),
    # field round 14 (r10): an if on a fix ave/time's value after the run; the runs made stopped on the
    # audit's stand-in for the fix ("Mismatched fix in variable formula"): it now runs, its file dropped
    "field14/decks/r10_ave_time_value_read": (HOOKE, "may_differ"),
    # field round 15 (D1): fix set (LAMMPS 2025) sets a diameter every step, or a density, during the
    # first run; it was taken for a force and its sizes never read (n03b 1 1: 0.4972 where LAMMPS gives
    # 0.4691; n04 2 2: 0.2551 where LAMMPS gives 0.0408)
    "field15/decks/n03b_fix_set_diameter_hertz": ("pair_coeff * * hertz/material 1e7 1.4e7 0.3 damping "
                                                             "viscoelastic tangential linear_nohistory 1 0.3",
                                                             "may_differ"),
    "field15/decks/n04_fix_set_density_then_unfix": (HOOKE, "may_differ"),
    "field10/decks/f04_pour_done_then_set": ("pair_coeff * * hooke 1000 0.02 damping velocity tangential "
                                             "linear_nohistory 0 0", "if_poured"),
}


def _json(path, *args):
    import json
    status, out, err = run(path, "--g", "1", "--json", *args)
    return status, (json.loads(out) if status == 0 else None), err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("name", sorted(DECKS))
def test_the_runs_made_give_the_engines_types_sizes_and_eps(name):
    path = FIELD / name / "in.deck"
    lines, before = DECKS[name]
    status, got, err = _json(path)
    assert status == 0, err
    assert err.count("for real") == 1 and "reads a value the runs change" not in err, err
    last = got["stages"][-1]
    held = lammps_held_at_end(path)
    assert all(len(sizes) == 1 for sizes in held.values()), held
    sizes = {t: next(iter(s)) for t, s in held.items()}
    # the types the last run sees are those LAMMPS holds, each pair once, none marked
    assert sorted(tuple(p["types"]) for p in last["pairs"]) == [(i, j) for i in sorted(sizes) for j in sorted(sizes)
                                                              if i <= j], (last["pairs"], held)
    assert not any(p.get(k) for p in last["pairs"] + last["walls"] for k in ("may_differ", "if_poured", "at"))
    ntypes = int(path.read_text().split("create_box", 1)[1].split()[0])
    # (coeff_restitution at e 0.3: LAMMPS' own values at 4000 to 16000 steps per contact still move by
    # 2e-5, first order in dt, so its extrapolation is good to some 1e-6 only)
    agrees_with_lammps(last["pairs"], sizes, lines, ntypes, tol=1e-5 if "a35" in name else 1e-6)
    # without the runs made: what the pass with them skipped did
    status, got, err = _json(path, "--run-budget", "0")
    as_without_runs(status, got, err, before)


BOX = LAMMPS_TWO + """{line}
fix grav all gravity 9.81 vector 0 0 -1
fix integ all nve/sphere
timestep 1e-5
run {steps}
region low block INF INF INF INF INF 0.02 units box
set region low diameter 0.02
run 10
""".replace("{line}", VISCO.format("3e6"))


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("steps, args, said", [
    (5000000, ["--run-budget", "1"], "ran out of the audit's --run-budget 1 s"),
    (20000000, [], "the audit makes at most 10000000 steps for real"),
])
def test_runs_beyond_the_budget_keep_the_refusal_and_say_why(tmp_path, steps, args, said):
    """A run the budget does not allow (wall time, or more steps than the audit makes): the pass
    with runs skipped stands, its refusal in one line naming the budget and the option."""
    (tmp_path / "in.deck").write_text(BOX.replace("{steps}", str(steps)))
    status, got, err = _json(tmp_path / "in.deck", *args)
    assert status == 2 and len(err.strip().splitlines()) == 1, err
    assert "where the run left them" in err and said in err, err
    assert "--run-budget SECONDS allows more" in err or "steps" in said, err


def test_the_run_budget_is_checked():
    status, _, err = run(FIELD / "field11/decks/a24_set_region_after_fall/in.deck", "--g", "1", "--run-budget", "-1")
    assert status == 2 and "run_budget" in err and len(err.strip().splitlines()) == 1, err


SETTLE = BOX.replace("run {steps}\n", 'variable zz equal z[1]\nlabel settle\nrun 1000\n'
                     'if "${zz} > 0.02" then "jump SELF settle"\n').replace("atom_style sphere\n",
                                                                        "atom_style sphere\natom_modify map array\n")


@needs_lammps
@pytest.mark.dem
def test_a_settle_loop_on_a_position_ends_in_the_runs_made(tmp_path):
    """Issue 52's settle loop: ``run 1000`` until the first sphere is below z = 0.02, then a set by
    region. With the runs skipped the loop never ends (its budget ends it, the set by region never
    reached, the stage audited at the spheres' first size, marked); made, it ends after 6 runs, as
    LAMMPS run by hand does, and the last stage is the resized spheres' (r 0.01, mass kept)."""
    assert SETTLE.count("jump SELF settle") == 1 and "{steps}" not in SETTLE
    (tmp_path / "in.deck").write_text(SETTLE)
    status, got, err = _json(tmp_path / "in.deck", "--budget", "1")
    assert status == 0 and "made the deck's 6 runs (5010 steps) for real" in err, err
    held = lammps_held_at_end(tmp_path / "in.deck")
    assert list(held) == [1] and [(r, pytest.approx(rho, rel=1e-12)) for r, rho in held[1]] == [(0.01, 2.5)], held
    last = got["stages"][-1]["pairs"]
    assert [p["types"] for p in last] == [[1, 1]] and last[0]["overlap_limit"] == pytest.approx(0.02, rel=1e-12)
    agrees_with_lammps(last, {1: (0.01, 2.5)}, VISCO.format("3e6"), 1)



FALL = """units si
atom_style sphere
boundary p p f
comm_modify vel yes
region box block 0 0.04 0 0.04 0 0.1 units box
create_box 2 box
pair_style granular
{line}
fix floor all wall/gran granular hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL
fix integ all nve/sphere
timestep 1e-5
create_atoms 1 single 0.02 0.02 0.05
create_atoms 1 single 0.01 0.01 0.09
set type 1 diameter 0.004 density 2500
velocity all set 0 0 -1
{output}
run 2000
region low block INF INF INF INF INF 0.02 units box
set region low type 2
set type 2 diameter 0.006 density 1000
run 100
""".replace("{line}", HOOKE)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("output", ["", 'fix out all print 1000 "falling"', "fix out all ave/time 100 1 100 c_thermo_temp"])
def test_an_output_fix_not_run_moves_no_atom_in_the_runs_made(tmp_path, output):
    """The fix standing for an output fix not run was nve/noforce, which moved every atom at its
    velocity once more in the runs made for real: the sphere falling at 1 m/s reached z 0.01 in
    2000 steps instead of 0.03, set region low made it type 2, and the audit printed rows for
    type 2, which LAMMPS run by hand never holds."""
    (tmp_path / "in.deck").write_text(FALL.format(output=output))
    status, got, err = _json(tmp_path / "in.deck")
    held = lammps_held_at_end(tmp_path / "in.deck")
    assert status == 0 and "for real" in err, err
    assert sorted(held) == [1] and [p["types"] for p in got["stages"][-1]["pairs"]] == [[1, 1]], (held, got)

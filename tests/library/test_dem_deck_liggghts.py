"""`restitution deck` on LIGGGHTS decks, which the LIGGGHTS binary interprets itself (issue 52):
the classes the hand-written reader got wrong, the deck as untrusted input, and the one line where
LIGGGHTS is not installed.

Each expected eps was checked in LIGGGHTS 3.8.0 itself: head-on runs of two spheres with the
deck's contact lines at three time steps (t_c/2000 to t_c/8000), extrapolated to dt = 0; the
engine test below repeats it."""

import json
import re
import subprocess
from pathlib import Path

import pytest

from cli_run import run_cli
from deck_cli import LIGGGHTS_BOX, needs_liggghts, outside_file, outside_file_outcome
from restitution.dem.contact import Contact
from restitution.dem.engines.liggghts import deck_run
from restitution.dem.engines.liggghts import run as liggghts_run
from restitution.dem.engines.liggghts.contact import liggghts_contact
from restitution.dem.extrapolate import richardson
from restitution.dem.pair import Pair

HEAD = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 0 0.15 units box
create_box 1 reg
neighbor 0.002 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 {e}
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
"""
TAIL = """timestep 0.00001
create_atoms 1 single 0 0 0.05
set type 1 diameter 0.01 density 2500
fix integr all nve/sphere
run 1
"""
PAIR = Pair.spheres(0.005, 0.005, 2500.0, 2500.0)
#: class 5: a later pair_style gran without limitForce sets it afresh (off)
RESTYLED = ("pair_style gran model hertz tangential history limitForce on\npair_coeff * *\n"
            "pair_style gran model hertz tangential history\npair_coeff * *\n")
PLAIN = "pair_style gran model hertz tangential history\npair_coeff * *\n"


def deck(tmp_path, text: str):
    (tmp_path / "in.deck").write_text(text)
    return run_cli(["deck", str(tmp_path / "in.deck"), "--g", "1.0", "--json"])


def pairs(tmp_path, text: str) -> tuple[dict, str]:
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    return {tuple(p["types"]): p for p in json.loads(out)["pairs"]}, err


@needs_liggghts
def test_limit_force_does_not_survive_a_later_pair_style_without_it(tmp_path):
    """LIGGGHTS gives 0.500 (extrapolated: 0.49999996); the old reader kept limitForce on and said 0.550."""
    p, _ = pairs(tmp_path, HEAD.format(e=0.5) + RESTYLED + TAIL)
    assert p[(1, 1)]["end"] == "overlap" and "limitForce off" in p[(1, 1)]["model"]
    assert all(e == pytest.approx(0.5, rel=1e-9) for e in p[(1, 1)]["eps"])


@needs_liggghts
def test_e_one_which_liggghts_accepts_gives_eps_one(tmp_path):
    """coefficientRestitution 1.0: LIGGGHTS runs it without damping (1 - 1.4e-12 extrapolated); the
    old reader stopped on it ('must be a restitution coefficient in (0, 1)')."""
    p, _ = pairs(tmp_path, HEAD.format(e=1.0) + PLAIN + TAIL)
    row = p[(1, 1)]
    assert row["eps"] == [1.0] * 5 and row["D2"] == 0.0 and row["exact_line"].endswith("peratomtypepair 1 1")
    # the undamped contact's time (a closed form in Gamma functions), against the integral it solves
    from scipy.integrate import quad
    delta = (2.5 * 1.0 / (2.0 * row["D1"])) ** 0.4
    t_c = 2.0 * delta / 1.0 * quad(lambda u: (1.0 - u ** 2.5) ** -0.5, 0.0, 1.0, limit=200)[0]
    assert row["steps_per_contact"][2] == pytest.approx(t_c / 1e-5, rel=1e-10)


@needs_liggghts
@pytest.mark.dem
@pytest.mark.parametrize("e, lines", [(0.5, RESTYLED), (1.0, PLAIN)], ids=["restyled", "e = 1"])
def test_liggghts_gives_what_the_audit_says(tmp_path, e, lines):
    """Both decks' contact lines in LIGGGHTS, head-on at g = 1, extrapolated to dt = 0: within 1e-6."""
    p, _ = pairs(tmp_path, HEAD.format(e=e) + lines + TAIL)
    contact = liggghts_contact(PAIR, E=5e6, nu=0.45, e=e)
    t_c = contact.contact_time(1.0)
    box = "create_box 1 box\n" + "\n".join(HEAD.format(e=e).splitlines()[10:]) + "\n" + lines
    eps = liggghts_run.liggghts_eps_runs(PAIR, [(box, 1.0, t_c / 2000 / k, 1.5 * t_c) for k in (1, 2, 4)])
    got = richardson(*eps, 0.25) if e < 1 else eps[-1]
    assert abs(got - p[(1, 1)]["eps"][2]) <= 1e-6, eps


#: hooke with ktToKnUser on (its tangential stiffness 2/7 of the normal one): field round 26, L23 was
#: refused as a keyword that may change the normal force
HOOKE_KT = ("fix m5 all property/global characteristicVelocity scalar 1.0\n"
            "pair_style gran model hooke tangential history ktToKnUser on\npair_coeff * *\n")


@needs_liggghts
@pytest.mark.dem
def test_kt_to_kn_user_changes_no_head_on_contact(tmp_path):
    """LIGGGHTS' hooke model scales only kt by it: the row is e's, the keyword named as idle, and
    LIGGGHTS' head-on runs (t_c/2000 to t_c/8000, extrapolated) give it within 1e-6."""
    p, err = pairs(tmp_path, HEAD.format(e=0.6) + HOOKE_KT + TAIL)
    row = p[(1, 1)]
    assert all(e == pytest.approx(0.6, rel=1e-9) for e in row["eps"]) and "hooke" in row["model"], row
    t_c = row["steps_per_contact"][2] * 1e-5
    box = "create_box 1 box\n" + "\n".join(HEAD.format(e=0.6).splitlines()[10:]) + "\n" + HOOKE_KT
    eps = liggghts_run.liggghts_eps_runs(PAIR, [(box, 1.0, t_c / 2000 / k, 1.5 * t_c) for k in (1, 2, 4)])
    assert abs(richardson(*eps, 0.25) - 0.6) <= 1e-6, eps


@needs_liggghts
def test_a_liggghts_deck_runs_nothing_that_writes_or_runs_code(tmp_path):
    target = tmp_path / "TOUCHED"
    text = HEAD.format(e=0.5) + PLAIN + f"""shell touch {target}
shell touch TOUCHED_HERE
print "x" file printed.txt
dump d all custom 1 dump.out id
""" + TAIL + "write_restart restart.out\n"      # after the atoms exist: before, LIGGGHTS stops on it by hand
    before = set(tmp_path.iterdir())
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    assert not target.exists() and set(tmp_path.iterdir()) == before | {tmp_path / "in.deck"}
    for word in ("shell", "print", "dump"):
        assert f"restitution deck: {word} (line" in err
    # a restart file is written into the audit's scratch copy, where a later read_restart reads it
    # (as LAMMPS'), never beside the deck (its folder is unchanged, above): not named as skipped
    assert "restitution deck: write_restart (line" not in err


@needs_liggghts
@pytest.mark.parametrize("absolute", [True, False], ids=["absolute", "climbing"])
def test_a_file_outside_the_deck_folder_named_by_a_variable_is_not_run(tmp_path, absolute):
    """LIGGGHTS resolves ``include ${f}`` as it runs, after the copy was made safe: a file outside
    the deck's folder ran as written, and its shell touched the file (issue 52's hole)."""
    folder, target, name = outside_file(tmp_path, absolute)
    before = sorted(tmp_path.rglob("*"))
    status, out, err = deck(folder, HEAD.format(e=0.5) + PLAIN + f"variable f string {name}\ninclude ${{f}}\n" + TAIL)
    assert not target.exists() and sorted(tmp_path.rglob("*")) == sorted(before + [folder / "in.deck"])
    outside_file_outcome((status, out, err), absolute, folder, 18)


@needs_liggghts
@pytest.mark.parametrize("how", ["name", "folder"])
def test_a_file_inside_the_deck_folder_named_by_a_variable_is_run(tmp_path, how):
    """By its name, or by the deck's folder's own absolute path: LIGGGHTS reads the safe copy."""
    target = tmp_path / "TOUCHED"
    name = "part.in" if how == "name" else str(tmp_path / "part.in")
    (tmp_path / "part.in").write_text(f"shell touch {target}\n" + PLAIN)
    p, _ = pairs(tmp_path, HEAD.format(e=0.5) + f"variable f string {name}\ninclude ${{f}}\n" + TAIL)
    assert not target.exists()
    assert all(e == pytest.approx(0.5, rel=1e-9) for e in p[(1, 1)]["eps"])


@needs_liggghts
def test_a_settle_loop_ends_within_its_budget(tmp_path):
    """A loop on a value no one-step run changes ends by the budget; the contact is answered."""
    text = HEAD.format(e=0.5) + PLAIN + TAIL + 'label l\nrun 1000\nvariable z equal 1\nif "${z} > 0" then "jump SELF l"\n'
    (tmp_path / "in.deck").write_text(text)
    from restitution.dem.deck import audit_deck
    res = audit_deck(text, [1.0], path=tmp_path / "in.deck", budget=8.0)
    # whichever part of the budget ends it first, the note names it (LIGGGHTS' one-step runs may
    # echo the 16 MB before the 8 s)
    assert any(re.search(r"LIGGGHTS had not ended the deck within the audit's budget \((8 s of wall time in a loop|16 MB of "
                         r"echo);", note) for note in res["notes"])
    assert res["pairs"][0]["eps"][0] == pytest.approx(0.5, rel=1e-9)


def test_without_liggghts_one_line_names_the_debian_package(tmp_path, monkeypatch):
    monkeypatch.setattr(deck_run.shutil, "which", lambda name: None)
    status, out, err = run_cli(["deck", str(_write(tmp_path, HEAD.format(e=0.5) + PLAIN + TAIL)), "--g", "1"])
    assert status == 2 and out == "" and err.count("\n") == 1 and "apt-get install liggghts" in err, err


def _write(tmp_path, text: str):
    path = tmp_path / "in.deck"
    path.write_text(text)
    return path


# ---------------------------------------------------------------- LIGGGHTS' own tutorials
LIGGGHTS_EXAMPLES = Path("/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public")
#: the tutorials the audit answers (with --radius where a type holds two sizes), as
#: test_dem_deck_official.py's table lists them
TUTORIALS = [("cohesion/in.noCohesion", {}), ("contactModels/in.newModels", {}), ("heatTransfer_1/in.heatGran", {}),
             ("heatTransfer_2/in.heatGran", {}), ("hysteresis/in.noHysteresis", {}), ("meshGran/in.meshGran", {}),
             ("movingMeshGran/in.movingMeshGran", {}),
             ("chute_wear/in.chute_wear", {1: 0.0015}), ("conveyor/in.conveyor", {1: 0.015}),
             ("insert_stream/in.insert_stream", {1: 0.015}), ("packing/in.packing", {1: 0.005})]


@needs_liggghts
@pytest.mark.skipif(not LIGGGHTS_EXAMPLES.is_dir(), reason="LIGGGHTS examples not installed: as root, apt-get "
                    "install liggghts-doc (make test does it)")
@pytest.mark.dem
@pytest.mark.slow
@pytest.mark.parametrize("name, radius", TUTORIALS, ids=[n for n, _ in TUTORIALS])
def test_every_answered_tutorial_agrees_with_liggghts(name, radius):
    """Types 1 1 of each tutorial at g = 1, head-on in LIGGGHTS with the materials and pair style
    LIGGGHTS executed (its own substitution), three steps t_c/2000..t_c/8000 extrapolated: within
    1e-6 of the audit (measured: 6.7e-8 at most, the e = 0.3 decks)."""
    from restitution.dem.contact import Contact
    from restitution.dem.deck import audit_deck, engine_read
    path = LIGGGHTS_EXAMPLES / name
    deck, _ = engine_read(path, radius)
    res = audit_deck(path.read_text(), [1.0], radius, path=path)
    d = deck.stages[-1][1] if deck.stages else deck
    lines = [f"create_box {d.ntypes} box"] + ["soft_particles yes"] * d.soft + ["hard_particles yes"] * d.hard
    lines += [f"{d.prop_fix[k]} property/global {k} {' '.join(v)}" for k, (_, v) in d.props.items()]
    lines += [f"pair_style gran model {d.model} tangential history" + " limitForce on" * d.limit_force, "pair_coeff * *"]
    p = next(p for p in res["pairs"] if p["types"] == [1, 1])
    pair = Pair.spheres(d.radius[1], d.radius[1], d.density[1], d.density[1])
    t_c = Contact(p["alpha"], p["gamma"], p["D1"], p["D2"], p["end"]).contact_time(1.0)
    eps = liggghts_run.liggghts_eps_runs(pair, [("\n".join(lines), 1.0, t_c / 2000 / k, 1.5 * t_c) for k in (1, 2, 4)])
    assert abs(richardson(*eps, p["gamma"]) - p["eps"][0]) <= 1e-6, eps


@needs_liggghts
def test_a_processors_layout_for_several_processes_is_not_a_refusal(tmp_path):
    """`processors 6 1 1` (a public deck run under mpirun -np 6): the audit's serial engine stops on
    it ("Specified processors != physical processors"); the layout has no part in a contact."""
    text = HEAD.replace("units si\n", "units si\nprocessors 6 1 1\n").format(e=0.5) + PLAIN + TAIL
    got, err = pairs(tmp_path, text)
    assert got[(1, 1)]["eps"] == pytest.approx([0.5] * 5, abs=1e-12)
    assert "processors (line 7 and any like it): not executed" in err


#: Two templates of one type inserted from a discrete distribution, a law whose eps depends on size
#: (hooke/stiffness with absolute damping: eps depends on m_eff). LIGGGHTS 3.8.0 inserted 758 atoms
#: of exactly the templates' radii (448 of 0.002, 310 of 0.003): every pair of sizes meets
DISTRIBUTION = LIGGGHTS_BOX.replace("create_box 2", "create_box 1") + """{contact}
timestep 1e-6
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002
fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant 0.003
fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.3 pts2 0.7
fix ins all insert/pack seed 32452867 distributiontemplate pdd1 maxattempt 200 insert_every once overlapcheck yes &
    all_in yes vel constant 0. 0. 0. region reg volumefraction_region 0.05
fix integr all nve/sphere
run 1
"""
STIFFNESS = """fix m1 all property/global kn peratomtypepair 1 800
fix m2 all property/global kt peratomtypepair 1 400
fix m3 all property/global gamman_abs peratomtypepair 1 0.02
fix m4 all property/global gammat_abs peratomtypepair 1 0.01
fix m5 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hooke/stiffness tangential history absolute_damping on
pair_coeff * *"""


@needs_liggghts
@pytest.mark.dem
def test_two_templates_of_a_distribution_are_audited_at_the_sizes_liggghts_inserts(tmp_path):
    """The ends of the range are the two templates' spheres each against its own size (both are
    inserted many times), checked head-on in LIGGGHTS at 2000, 4000 and 8000 steps per contact:
    measured 0.8420854825 and 0.9107764087, 3e-11 from the audit's after extrapolation."""
    (tmp_path / "in.dist").write_text(DISTRIBUTION.format(contact=STIFFNESS))
    status, out, err = run_cli(["deck", str(tmp_path / "in.dist"), "--g", "1", "--json"])
    assert status == 0, err
    rows = json.loads(out)["pairs"]
    assert [(r["sizes"], r["at"]) for r in rows] == [
        ("smallest eps", [[0.002, 2500.0], [0.002, 2500.0]]), ("largest eps", [[0.003, 2500.0], [0.003, 2500.0]])]
    lines = "create_box 1 box\n" + STIFFNESS
    for r in rows:
        (r1, rho1), (r2, rho2) = r["at"]
        t_c = Contact(r["alpha"], r["gamma"], r["D1"], r["D2"], r["end"]).contact_time(1.0)
        runs = liggghts_run.liggghts_eps_runs(Pair.spheres(r1, r2, rho1, rho2),
                                              [(lines, 1.0, t_c / n, 1.5 * t_c) for n in (2000, 4000, 8000)])
        assert richardson(*runs, 1) == pytest.approx(r["eps"][0], rel=1e-8), (r["at"], runs)
    assert not list(tmp_path.glob("log.liggghts"))


@needs_liggghts
def test_liggghts_nve_group_filled_by_the_insertion_moves_every_sphere(tmp_path):
    """Field test r10 (L11): LIGGGHTS' usual nve_group, a region group made before any atom and
    filled by the deck's one insertion, holds every sphere there is: no "a sphere outside the
    group never moves" (there is none)."""
    text = LIGGGHTS_BOX + """\
group nve_group region reg
fix m1 all property/global youngsModulus peratomtype 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.45 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.3 0.3 0.3 0.3
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-6
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002
fix pdd all particledistribution/discrete 32452843 1 pts1 1.0
region ins block -0.04 0.04 -0.04 0.04 0.02 0.08 units box
fix ins nve_group insert/pack seed 32452867 distributiontemplate pdd maxattempt 100 insert_every once overlapcheck yes all_in yes vel constant 0 0 -1 region ins particles_in_region 10
fix integr nve_group nve/sphere
run 10
"""
    deck = tmp_path / "in.liggghts"
    deck.write_text(text)
    status, out, err = run_cli(["deck", str(deck), "--g", "1.0"])
    assert status == 0 and "never moves" not in err and "cannot type" not in err, err
    assert "types 1 1" in out


@needs_liggghts
def test_an_integrators_group_given_again_after_the_insertion_moves_the_inserted_spheres(tmp_path):
    """Field round 12, D6 (L14): a region group made before any atom holds none, so its integrator
    moves nothing in the first run; given again after the insertion's run, it holds the inserted
    spheres, which LIGGGHTS then moves (their mean height falls from 0.10035 to 0.08839). The
    audit kept one stage, said that no fix integrates type 1 and dropped every pair: the second run
    is now a stage of its own, audited as free spheres (the group's atoms untyped, said)."""
    text = LIGGGHTS_BOX + """\
fix m1 all property/global youngsModulus peratomtype 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.6 0.5 0.5 0.4
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-5
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.003
fix pdd1 all particledistribution/discrete 32452843 1 pts1 1.0
region bc block -0.04 0.04 -0.04 0.04 0.05 0.09 units box
group early region reg
fix ins all insert/pack seed 32452867 distributiontemplate pdd1 vel constant 0 0 -0.5 insert_every once overlapcheck yes all_in yes particles_in_region 20 region bc
fix integr early nve/sphere
run 100
group early region reg
run 100
"""
    deck = tmp_path / "in.liggghts"
    deck.write_text(text)
    status, out, err = run_cli(["deck", str(deck), "--g", "1.0", "--json"])
    assert status == 0, err
    first, last = json.loads(out)["stages"]
    assert first["pairs"] == [] and "no fix integrates type 1" in err
    (row,) = [p for p in last["pairs"] if p["types"] == [1, 1]]
    assert row["eps"][0] == pytest.approx(0.6, abs=1e-9) and "cannot type" in err


@needs_liggghts
@pytest.mark.parametrize("command", ["balance 1.0 x uniform", "timer timeout 0 every 1", "write_coeff c.txt"])
def test_a_command_liggghts_does_not_have_stops_the_deck_as_it_stops_liggghts(tmp_path, command):
    """Field round 33, G28 G29: balance, a no-op in the audit's pass (it may write a file), was
    answered where LIGGGHTS 3.8.0 stops ('Unknown command': it has none of these). Such a command is
    left as written in LIGGGHTS' pass, which stops on it: refused in one line, in its words."""
    status, out, err = deck(tmp_path, HEAD.format(e=0.5) + PLAIN + TAIL.replace("run 1\n", f"run 1\n{command}\nrun 1\n"))
    assert status == 2 and out == "", out
    assert err.strip().endswith(f"LIGGGHTS stops here: Unknown command: {command}"), err
    assert "#restitution" not in err


@needs_liggghts
@pytest.mark.parametrize("ending", ["clear\n", "next e\nclear\njump SELF loop\n"],
                         ids=["clear last", "a loop's last jump skipped"])
def test_a_deck_that_ends_after_clear_is_audited(tmp_path, ending):
    """Field round 45, M02 M03 and LIGGGHTS-PFM's contact-model tests (R12-R19): a deck that clears
    after its last run (its last line, or a loop whose jump the exhausted next skips) was refused,
    "LIGGGHTS stops here: Dumping an atom property that isn't allocated": the audit's own dump of
    the atoms at the deck's end met no box and no radius after the clear. LIGGGHTS runs such a deck
    to its end (M02: 0.499928 with e 0.5; M03: 0.499928 and 0.700061), as LAMMPS' pass does."""
    loop = "variable e universe 0.5 0.7\nlabel loop\n" if ending.startswith("next") else ""
    text = loop + HEAD.format(e="${e}" if loop else 0.5) + PLAIN + TAIL + ending
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    eps = [next(p for p in stage["pairs"] if p["types"] == [1, 1])["eps"][0] for stage in json.loads(out)["stages"]]
    assert eps == pytest.approx([0.5, 0.7] if loop else [0.5], rel=1e-9), (eps, err)


@needs_liggghts
def test_a_deck_that_stops_after_clear_is_still_refused(tmp_path):
    """The end's dump is the audit's own only where nothing after the clear made a box: a stop of the
    deck's own after it, or a box of atoms without a radius, stays the deck's refusal."""
    for after, said in (("fix f all nve/sphere\n", "Fix command before simulation box is defined"),
                        ("region r2 block 0 1 0 1 0 1 units box\ncreate_box 1 r2\n", "not spheres")):
        status, out, err = deck(tmp_path, HEAD.format(e=0.5) + PLAIN + TAIL + "clear\n" + after)
        assert status == 2 and out == "" and said in err, err


@needs_liggghts
@pytest.mark.dem
def test_an_include_between_a_runs_parts_is_read_as_liggghts_reads_it_after_the_run(tmp_path):
    """Field round 35, L06: LIGGGHTS 3.8.0 only opens a file a run's every includes and reads it
    after the whole run, the file opened last first (measured here with prints), where LAMMPS runs
    it at once after the part. The audit had made the include act from the second part on (e 0.6
    printed where LIGGGHTS kept 0.5), then refused such runs; the copy now reads the files after
    the run in LIGGGHTS' order: e 0.5 in every part, and the later run has the file read last
    (m.in, e 0.9; n.in read last would give 0.7)."""
    (tmp_path / "a.in").write_text("print A_$(step)\n")
    (tmp_path / "b.in").write_text("print B_$(step)\n")
    (tmp_path / "in.order").write_text(HEAD.format(e=0.5) + PLAIN + TAIL
                                       + 'run 20 every 10 "include a.in" "print PART_$(step)" "include b.in"\n')
    done = subprocess.run(["liggghts", "-in", "in.order", "-log", "none"], cwd=tmp_path, capture_output=True,
                          text=True, timeout=120)
    said = re.findall(r"^([A-Z]+_\d+)$", done.stdout, re.M)
    assert said == ["PART_11", "PART_21", "B_21", "A_21", "B_21", "A_21"], done.stdout[-2000:]
    for name, e in (("m.in", 0.9), ("n.in", 0.7)):
        (tmp_path / name).write_text(f"fix m3 all property/global coefficientRestitution peratomtypepair 1 {e}\n")
    status, out, err = deck(tmp_path, HEAD.format(e=0.5) + PLAIN + TAIL
                            + 'run 40 every 10 "include m.in" "include n.in"\nrun 10\n')
    assert status == 0, err
    stages = json.loads(out)["stages"]
    eps = [next(p for p in stage["pairs"] if p["types"] == [1, 1])["eps"][0] for stage in stages]
    assert eps[:-1] and all(e == pytest.approx(0.5, rel=1e-9) for e in eps[:-1]), (eps, err)
    assert eps[-1] == pytest.approx(0.9, rel=1e-9), (eps, err)

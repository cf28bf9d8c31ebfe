"""A loop on the engine's step or time whose passes change the contact (field round 12, D5):
``label L`` / ``run 100`` / a pair_coeff, a wall or a coefficientRestitution set from the pass
before / ``if "$(time) < 0.0025" then "jump SELF L"``. In the pass whose runs are skipped (LAMMPS)
or one step long (LIGGGHTS) the step hardly moves, so the loop does not end there, and a value
stepped each pass (doubled, lowered) leaves its range: the engine stopped in that pass (LAMMPS on an
``inf`` coefficient, LIGGGHTS on a coefficientRestitution below 0.05) and the audit refused the deck
with that stop as its reason, although the deck run by hand ends its loop after three passes. Now
the engine makes the runs for real: the loop ends where the engine ends it and each of its stages is
audited, each eps the engine's own head-on (dt -> 0)."""

import pytest

from deck_cli import LAMMPS_TWO, LIGGGHTS_BOX, agrees_with_lammps, needs_lammps, needs_liggghts, run

BOX = LAMMPS_TWO + """fix integ all nve/sphere
timestep 1e-5
"""
LAW = "hertz/material 1e7 {} 0.3 damping viscoelastic tangential linear_nohistory 1 0.3"
#: pair_coeff doubled each pass of a loop on the time: LAMMPS run by hand makes 3 passes and a last
#: run, at eta 1e6, 2e6, 4e6 and 8e6
ON_TIME = BOX + f"""variable eta equal 1e6
pair_coeff * * {LAW.format("${eta}")}
label L
run 100
variable eta equal ${{eta}}*2
pair_coeff * * {LAW.format("${eta}")}
if "$(time) < 0.0025" then "jump SELF L"
run 100
"""
#: a wall re-made each pass of a loop on the step, its eta tripled: 1e6, 3e6, 9e6 and 2.7e7
ON_STEP = BOX + f"""pair_coeff * * {LAW.format("1e6")}
variable eta equal 1e6
fix w all wall/gran granular {LAW.format("${eta}")} zplane 0 NULL
label L
run 100
variable eta equal ${{eta}}*3
unfix w
fix w all wall/gran granular {LAW.format("${eta}")} zplane 0 NULL
if "$(step) < 250" then "jump SELF L"
run 100
"""


def _json(path, *args):
    import json
    status, out, err = run(path, "--g", "1", "--json", *args)
    return status, (json.loads(out) if status == 0 else None), err


def _lammps_truth(path, name: str) -> tuple:
    """(step, variable ``name``) where LAMMPS has run the deck to its end, runs made."""
    import os

    import lammps
    here = os.getcwd()
    os.chdir(path.parent)
    lmp = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        lmp.file(path.name)
        return lmp.get_thermo("step"), lmp.extract_variable(name)
    finally:
        lmp.close()
        os.chdir(here)


def _four_stages(tmp_path, text: str, eta: float, rows: str) -> list:
    """The audit's stages of a LAMMPS deck ``text`` whose loop LAMMPS run by hand ends after 400
    steps at ``eta``: four, made for real, one row each of ``rows`` ("pairs" or "walls")."""
    path = tmp_path / "in.deck"
    path.write_text(text)
    assert _lammps_truth(path, "eta") == (400, eta)
    status, got, err = _json(path)
    assert status == 0 and "LAMMPS made the deck's 4 runs (400 steps) for real" in err, err
    stages = got["stages"]
    assert len(stages) == 4 and all(len(s[rows]) == 1 for s in stages), stages
    return stages


@needs_lammps
@pytest.mark.dem
@pytest.mark.slow
def test_a_loop_on_the_time_ends_as_lammps_ends_it_and_each_stage_is_lammps_own(tmp_path):
    stages = _four_stages(tmp_path, ON_TIME, 8e6, "pairs")
    for stage, eta in zip(stages, (1e6, 2e6, 4e6, 8e6)):
        assert stage["pairs"][0]["D2"] == pytest.approx(stages[0]["pairs"][0]["D2"] * eta / 1e6, rel=1e-12)
        agrees_with_lammps(stage["pairs"], {1: (0.001, 2500.0)}, f"pair_coeff * * {LAW.format(eta)}", 1)


@needs_lammps
@pytest.mark.dem
@pytest.mark.slow
def test_a_wall_remade_in_a_loop_on_the_step_is_audited_at_every_pass(tmp_path):
    from restitution.dem.contact import Contact
    from restitution.dem.engines.lammps.run import lammps_wall_eps
    from restitution.dem.extrapolate import richardson
    stages = _four_stages(tmp_path, ON_STEP, 2.7e7, "walls")
    for stage, eta in zip(stages, (1e6, 3e6, 9e6, 2.7e7)):
        row = stage["walls"][0]
        g = row["speeds"][2]
        t_c = Contact(row["alpha"], row["gamma"], row["D1"], row["D2"], row["end"]).contact_time(g)
        lines = (f"pair_style granular\npair_coeff * * {LAW.format(1e6)}\n"
                 f"fix w all wall/gran granular {LAW.format(eta)} zplane 0.0 NULL")
        e1, e2, e4 = (lammps_wall_eps(0.001, 2500.0, lines, g, t_c / 4000 / k, 1.5 * t_c) for k in (1, 2, 4))
        engine = richardson(e1, e2, e4, 1)
        print(eta, row["eps"][2], engine, e1)
        assert abs(engine / row["eps"][2] - 1) < 1e-6, (eta, row["eps"][2], engine)


#: LIGGGHTS: e lowered by 0.2 each pass of a loop on the step; run by hand it ends at step 300, its
#: passes' e 0.9, 0.7, 0.5 and 0.3 (the one-step pass lowered it below 0.05, where LIGGGHTS stops)
LIGGGHTS_ON_STEP = LIGGGHTS_BOX + """fix m1 all property/global youngsModulus peratomtype 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3
variable e equal 0.9
fix m3 all property/global coefficientRestitution peratomtypepair 2 ${e} 0.5 0.5 0.4
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-5
create_atoms 1 single 0 0 0.02 units box
create_atoms 1 single 0.01 0 0.02 units box
set type 1 diameter 0.006 density 2500
fix integr all nve/sphere
label L
run 100
variable e equal ${e}-0.2
fix m3 all property/global coefficientRestitution peratomtypepair 2 ${e} 0.5 0.5 0.4
if "{clock} < 250" then "jump SELF L"
print "END step $(step) e ${e}"
run 10
"""


@needs_liggghts
@pytest.mark.dem
@pytest.mark.slow
@pytest.mark.parametrize("clock", ["$(step)", "${s}"])
def test_liggghts_ends_a_loop_on_the_step_and_each_stage_is_its_own(tmp_path, clock):
    import subprocess

    from restitution.dem.contact import Contact
    from restitution.dem.engines.liggghts import run as liggghts_run
    from restitution.dem.pair import Pair
    text = LIGGGHTS_ON_STEP.replace("{clock}", clock)
    if clock == "${s}":
        text = text.replace("label L\n", "variable s equal step\nlabel L\n")
    path = tmp_path / "in.deck"
    path.write_text(text)
    (tmp_path / "engine").mkdir()
    (tmp_path / "engine" / "in.deck").write_text(text)
    by_hand = subprocess.run(["liggghts", "-in", "in.deck", "-log", "none", "-nocite"], cwd=tmp_path / "engine",
                             capture_output=True, text=True, check=True, stdin=subprocess.DEVNULL).stdout
    assert "END step 300 e 0.3" in by_hand, by_hand[-2000:]
    status, got, err = _json(path)
    assert status == 0 and "LIGGGHTS made the deck's 4 runs (310 steps) for real" in err, err
    stages = got["stages"]
    assert [[tuple(p["types"]) for p in s["pairs"]] for s in stages] == [[(1, 1)]] * 4, stages
    for stage, e in zip(stages, (0.9, 0.7, 0.5, 0.3)):
        # the referee's two spheres are of types 1 and 2 (its box has two): type 2 given type 1's
        # e, as it has its modulus, ratio and size, they meet as two of type 1
        r = stage["pairs"][0]
        g = r["speeds"][2]
        lines = ("create_box 2 box\n" + "\n".join(ln for ln in text.splitlines() if ln.startswith(
            ("fix m", "pair_style", "pair_coeff")) and "${" not in ln)
            + f"\nfix m3 all property/global coefficientRestitution peratomtypepair 2 {e} {e} {e} 0.4")
        t_c = Contact(r["alpha"], r["gamma"], r["D1"], r["D2"], r["end"]).contact_time(g)
        engine = liggghts_run.liggghts_eps_extrapolated(Pair.spheres(0.003, 0.003, 2500.0), lines, [g], {g: t_c},
                                                        r["gamma"], steps=4000)[g]
        print(e, r["eps"][2], engine)
        assert abs(engine[0] / r["eps"][2] - 1) < 1e-6, (e, r["eps"][2], engine)

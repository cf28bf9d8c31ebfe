"""Field round 23. U: a deck in units cgs was audited at --g taken in its own speed unit (cm/s) with
no word of it, so a user thinking in m/s read 0.7533 where LAMMPS gives 0.4972 at 1 m/s (u02): the
speed unit is now said. Round 22's mild y09/t13: a type with one sphere had its pair with itself
printed as if two of them could meet: the row is now marked. The engine's numbers are round 23's
head-on probes (dt 1e-8 s, good to about 1e-5)."""

import json

import pytest

from deck_cli import needs_lammps, needs_liggghts, run

#: Two types, hooke kn 2000 gamma 3000 (the field rounds' base), spheres made by the caller
BASE = """\
units {units}
atom_style sphere 1
boundary p p f
comm_modify vel yes
region box block 0 {L} 0 {L} 0 {H} units box
create_box 2 box
pair_style granular
pair_coeff * * {law} tangential linear_nohistory 1 0.3
fix integ all nve/sphere
timestep 1e-5
"""
#: Viscoelastic Hertz in SI, and the same in cgs numbers (E in Ba = 0.1 Pa; the damping in 1/(cm s) =
#: 100 /(m s))
SI = dict(units="si", L=0.04, H=0.1, law="hertz/material 1e7 1.4e7 0.3 damping viscoelastic")
CGS = dict(units="cgs", L=4, H=10, law="hertz/material 1e8 1.4e5 0.3 damping viscoelastic")


def _rows(deck, *g):
    status, out, err = run(deck, "--g", *g, "--json")
    assert status == 0, err
    return json.loads(out), err


@needs_lammps
@pytest.mark.dem
def test_the_speed_unit_of_a_cgs_deck_is_said(tmp_path):
    """The same two spheres in si and in cgs: the audit at 1 m/s (si) equals the cgs audit at 100 cm/s,
    and both name their unit (before: the cgs deck's rows said nothing of cm/s)."""
    spheres = {"si": "create_atoms 1 single 0.01 0.01 0.01\ncreate_atoms 1 single 0.03 0.03 0.01\n"
                     "set type 1 diameter 0.004 density 2500\nrun 10\n",
               "cgs": "create_atoms 1 single 1 1 1\ncreate_atoms 1 single 3 3 1\n"
                      "set type 1 diameter 0.4 density 2.5\nrun 10\n"}
    got = {}
    for units, setting, g in (("si", SI, "1"), ("cgs", CGS, "100")):
        (tmp_path / units).mkdir()
        deck = tmp_path / units / "in.deck"
        deck.write_text(BASE.format(**setting) + spheres[units])
        res, _ = _rows(deck, g)
        got[units] = res
        status, out, _ = run(deck, "--g", g)
        assert ("# speeds g in cm/s" in out) == (units == "cgs"), out
    assert got["si"]["speed_unit"] == "m/s" and got["cgs"]["speed_unit"] == "cm/s"
    si, cgs = (got[u]["pairs"][0]["eps"][2] for u in ("si", "cgs"))
    assert cgs == pytest.approx(si, rel=1e-6) and si < 0.9     # a damping that tells the units apart


@needs_lammps
@pytest.mark.dem
def test_a_type_with_one_sphere_marks_its_pair_with_itself(tmp_path):
    """Two type-1 spheres and one type-2: 2 2 is marked lone (text and JSON); 1 1 and 1 2 are not.
    A pour of type 2 makes more of it: then 2 2 is not marked."""
    law = dict(units="si", L=0.04, H=0.1, law="hooke 2000 3000 damping mass_velocity")
    three = ("create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 1 single 0.02 0.03 0.01\n"
             "create_atoms 2 single 0.01 0.01 0.01\nset type 1 diameter 0.004 density 2500\n"
             "set type 2 diameter 0.006 density 2500\n")
    deck = tmp_path / "in.deck"
    deck.write_text(BASE.format(**law) + three + "run 100\n")
    res, _ = _rows(deck, "1")
    lone = {tuple(r["types"]): bool(r.get("lone")) for r in res["pairs"]}
    assert lone == {(1, 1): False, (1, 2): False, (2, 2): True}
    status, out, _ = run(deck, "--g", "1")
    assert "types 2 2 [type 2 has one sphere at this run" in out and "types 1 1 [" not in out
    poured = (BASE.format(**law) + three + "region top block 0.005 0.035 0.005 0.035 0.05 0.09 units box\n"
              "fix grav all gravity 9.81 vector 0 0 -1\nfix ins all pour 5 2 4767548 region top diam one 0.006 dens 2500 2500\nrun 100\n")
    deck.write_text(poured)
    res, _ = _rows(deck, "1")
    assert not any(r.get("lone") for r in res["pairs"]), res["pairs"]


#: Round 23's base (its r22 and R11): two types on a floor, hooke kn 2000 gamma 3000, gravity, a p p f box
FLOOR = BASE.format(units="si", L=0.04, H=0.1, law="hooke 2000 3000 damping mass_velocity") + """\
fix grav all gravity 9.81 vector 0 0 -1
fix floor all wall/gran granular hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL
create_atoms 1 single 0.02 0.02 0.01
create_atoms 2 single 0.01 0.01 0.01
set type 1 diameter 0.004 density 2500
set type 2 diameter 0.006 density 2500
"""
NEXT = "pair_coeff * * hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n"


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("first, stop", [
    # a sphere thrown out through the open top: LAMMPS stops, "Lost atoms" (its default lost error)
    ("group t2 type 2\nvelocity t2 set 0 0 200\nthermo 100\nrun 1000\n", "Lost atoms"),
    # a fix halt with error hard (its default) whose condition the first run meets
    ("variable t equal time\nfix h all halt 10 v_t > 0.0005 error hard\nrun 100\n", "Fix halt condition"),
    # error soft: the run ends there and LAMMPS makes no step in any later run (R12)
    ("variable t equal time\nfix h all halt 10 v_t > 0.0005 error soft\nrun 100\nunfix h\n", "error soft")])
def test_a_deck_the_engine_stops_in_a_run_is_refused(tmp_path, first, stop):
    """Before: rc 0, the second stage (kn 5000) audited for a deck LAMMPS ends in its first run."""
    deck = tmp_path / "in.deck"
    deck.write_text(FLOOR + first + NEXT)
    status, out, err = run(deck, "--g", "1")
    assert status == 2 and out == "", err
    assert "stops in this run, made for real" in err and stop in err and "restitution-" not in err


@needs_lammps
@pytest.mark.dem
def test_runs_that_keep_every_sphere_are_audited_as_made(tmp_path):
    """The same deck with no throw: the runs are made for real only to see that LAMMPS ends each (a
    sphere could have left through the f face); it does, so the pass stands, nothing said, and the
    second stage is audited at kn 5000 (its rows differ from stage 1's kn 2000)."""
    deck = tmp_path / "in.deck"
    deck.write_text(FLOOR + "run 1000\n" + NEXT)
    res, err = _rows(deck, "1")
    assert "for real" not in err and "was not run to see" not in err
    first, second = ({tuple(r["types"]): r["eps"][2] for r in s["pairs"]} for s in res["stages"])
    assert first[(1, 2)] != pytest.approx(second[(1, 2)], rel=1e-3)


#: Round 23 L37 (LIGGGHTS hooke/stiffness, so eps depends on the masses): the type 2 sphere thrown out of the
#: f f f box in run 1, which LIGGGHTS drops without a word; a new type 2 atom then gets its id
L37 = """\
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 -0.01 0.15 units box
create_box 3 reg
neighbor 0.002 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3
fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5
fix k1 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000
fix k2 all property/global kt peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000
fix k3 all property/global gamman peratomtypepair 3 500 500 500 500 500 500 500 500 500
fix k4 all property/global gammat peratomtypepair 3 500 500 500 500 500 500 500 500 500
pair_style gran model hooke/stiffness tangential history
pair_coeff * *
fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0
create_atoms 1 single 0.01 0 0.01 units box
create_atoms 2 single -0.01 0 0.01 units box
set type 1 diameter 0.004 density 2500
set type 2 diameter 0.006 density 1500
timestep 1e-5
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix integr all nve/sphere
group up type 2
velocity up set 0 0 200
run 1000
create_atoms 2 single -0.01 0 0.05 units box
set atom 2 diameter 0.006 density 500
run 100
"""


@needs_liggghts
@pytest.mark.dem
def test_a_sphere_liggghts_lost_is_gone_from_the_later_runs(tmp_path):
    """Before: rc 0 with a phantom: types 1 2 over two sizes, 0.8513 at the new atom left at the default
    size (the audit's set atom 2 hit the lost sphere). LIGGGHTS (head-on, dt 1e-7): 0.902977."""
    deck = tmp_path / "in.deck"
    deck.write_text(L37)
    res, err = _rows(deck, "1")
    assert "for real" in err
    (row,) = [r for r in res["stages"][-1]["pairs"] if r["types"] == [1, 2]]
    assert "sizes" not in row and row["eps"][2] == pytest.approx(0.902977, abs=1e-4)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("first", [
    # a halt that goes on (continue), one whose condition no run meets, a soft one whose forced timeout
    # the deck lifts (timer timeout off): LAMMPS makes the second run at kn 5000 in each
    "variable t equal time\nfix h all halt 10 v_t > 0.0005 error continue\nrun 100\nunfix h\n",
    "variable t equal time\nfix h all halt 10 v_t > 5.0 error hard\nrun 100\n",
    "variable t equal time\nfix h all halt 10 v_t > 0.0005 error soft\nrun 100\nunfix h\ntimer timeout off\n"])
def test_halts_that_leave_the_later_runs_are_audited(tmp_path, first):
    deck = tmp_path / "in.deck"
    deck.write_text(FLOOR + first + NEXT)
    res, _ = _rows(deck, "1")
    assert len(res["stages"]) == 2


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("line, said", [
    ("run 1e2", "Expected integer parameter instead of '1e2'"), ("run -100", "Invalid run command N value: -100"),
    ('run 100 every 0 "print hi"', "Invalid run every argument: 0"),
    ("run 100 pre maybe", "Expected boolean parameter instead of 'maybe'"),
    ("run 100 start 0 stop 50", "Run command stop value 50 is before end of run at step 100"),
    ("run 100 start 200 stop 300", "Run command start value 200 is after start of run at step 0")])
def test_a_run_lammps_stops_on_is_refused(tmp_path, line, said):
    """LAMMPS stops at each of these (round 23, R23-R29, measured); its -skiprun pass never read them."""
    deck = tmp_path / "in.deck"
    deck.write_text(FLOOR.replace("pair_coeff * * hooke 2000", "pair_coeff * * hooke 5000") + line + "\n")
    status, out, err = run(deck, "--g", "1")
    assert status == 2 and out == "" and f"LAMMPS stops here: {said}" in err, err


@needs_lammps
@pytest.mark.dem
def test_a_run_upto_after_a_longer_run_is_refused(tmp_path):
    """R30: run 200, then run 100 upto: LAMMPS stops ("Invalid run command upto value"); the audit
    answered the stage after it, which LAMMPS never reaches."""
    deck = tmp_path / "in.deck"
    deck.write_text(FLOOR + "run 200\nrun 100 upto\n" + NEXT)
    status, out, err = run(deck, "--g", "1")
    assert status == 2 and "Invalid run command upto value: 100" in err, err

"""LIGGGHTS' sjkr cohesion adds cohesionEnergyDensity times the contact area to the normal force: a
pair whose entry is 0 gets the contact law alone. A public deck (a calibration template of a
vibrated drum) names ``cohesion sjkr`` with every entry 0, and was refused as an unmapped model;
its pairs are audited now, named, and a pair with a nonzero entry is still refused in one line."""

import json

import pytest

from deck_cli import LIGGGHTS_BOX, needs_liggghts, run
from restitution.dem.contact import Contact
from restitution.dem.engines.liggghts import run as liggghts_run
from restitution.dem.pair import Pair

MATERIALS = """fix m1 all property/global youngsModulus peratomtype 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.4 0.4
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.66 0.66 0.66 0.66
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
fix m6 all property/global cohesionEnergyDensity peratomtypepair 2 {k} 0 0 0
pair_style gran model hertz tangential history cohesion sjkr
pair_coeff * *
"""
SPHERES = """create_atoms 1 single 0 0 0.02 units box
set atom 1 diameter 0.004 density 1580
timestep 1e-6
fix integr all nve/sphere
run 10
"""


@needs_liggghts
@pytest.mark.dem
def test_sjkr_without_cohesion_energy_is_the_contact_law(tmp_path):
    """Before: refused at the pair_style line. LIGGGHTS with that pair style gives e (0.66) head-on."""
    (tmp_path / "in.deck").write_text(LIGGGHTS_BOX + MATERIALS.format(k=0) + SPHERES)
    status, out, err = run(tmp_path / "in.deck", "--g", "1.0", "--json")
    assert status == 0, err
    (row,) = json.loads(out)["pairs"]
    assert row["types"] == [1, 1] and "cohesion sjkr (cohesionEnergyDensity 0 here: no force)" in row["model"]
    assert row["eps"][2] == pytest.approx(0.66, abs=1e-9)
    t_c = Contact(row["alpha"], row["gamma"], row["D1"], row["D2"], row["end"]).contact_time(1.0)
    lines = "create_box 2 box\n" + MATERIALS.format(k=0)
    engine = liggghts_run.liggghts_eps_extrapolated(Pair.spheres(0.002, 0.002, 1580.0), lines, [1.0], {1.0: t_c},
                                                    row["gamma"])[1.0][0]
    print(row["eps"][2], engine)
    assert abs(engine / row["eps"][2] - 1) < 1e-5


@needs_liggghts
@pytest.mark.dem
def test_sjkr_with_cohesion_energy_is_refused_at_its_entry(tmp_path):
    (tmp_path / "in.deck").write_text(LIGGGHTS_BOX + MATERIALS.format(k=50000) + SPHERES)
    status, out, err = run(tmp_path / "in.deck", "--g", "1.0")
    assert status == 2 and out == "" and len(err.splitlines()) == 1, err
    assert "(types 1 1): cohesion sjkr with cohesionEnergyDensity 50000 adds an attractive normal force" in err


WALL = "fix w all wall/gran model hertz tangential history cohesion sjkr primitive type 2 zplane 0.0\n"


@needs_liggghts
@pytest.mark.dem
def test_a_wall_with_sjkr_without_cohesion_energy_is_audited(tmp_path):
    """Field round 9, D6: the wall's contacts were "not audited" (cohesion sjkr not mapped) where its
    pairs, under the same zero entries, were. LIGGGHTS drops the sphere on that wall: e (0.66)."""
    (tmp_path / "in.deck").write_text(LIGGGHTS_BOX + MATERIALS.format(k=0) + WALL + SPHERES)
    status, out, err = run(tmp_path / "in.deck", "--g", "1.0", "--json")
    assert status == 0, err
    (row,) = json.loads(out)["walls"]
    assert row["types"] == [1] and "cohesion sjkr (cohesionEnergyDensity 0 here: no force)" in row["model"]
    assert row["eps"][2] == pytest.approx(0.66, abs=1e-9)
    t_c = Contact(row["alpha"], row["gamma"], row["D1"], row["D2"], row["end"]).contact_time(1.0)
    lines = "create_box 2 box\n" + MATERIALS.format(k=0)
    eps = liggghts_run.liggghts_wall_eps_runs(0.002, 1580.0, [(lines, 1.0, t_c / n, 1.5 * t_c, 1, 2) for n in (1000, 2000)],
                                              wall=WALL.replace("fix w ", "fix wall "))
    engine = 2 * eps[1] - eps[0]         # first order in dt
    print(row["eps"][2], eps, engine)
    assert abs(engine / row["eps"][2] - 1) < 1e-4


@needs_liggghts
@pytest.mark.dem
def test_a_wall_with_sjkr_cohesion_energy_is_not_audited(tmp_path):
    """A nonzero entry of the sphere's type with the wall's: named, the wall's contacts not audited."""
    (tmp_path / "in.deck").write_text(LIGGGHTS_BOX + MATERIALS.format(k=0).replace("2 0 0 0 0", "2 0 5e4 5e4 0")
                                      + WALL + SPHERES)
    status, out, err = run(tmp_path / "in.deck", "--g", "1.0", "--json")
    assert status == 0, err
    assert json.loads(out)["walls"] == []
    assert "cohesionEnergyDensity 50000 for the wall's type 2 adds an attractive normal force" in err, err

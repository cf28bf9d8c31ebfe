"""A run with ``pre no`` after a command that makes LAMMPS' ghost atoms anew (field round 32, SW-P):
``displace_atoms`` (even by 0), ``change_box`` (even to the same box), ``balance`` or ``comm_style``
rebuild the ghosts (pbc, exchange, borders) without building the neighbour lists, and a run with
pre no builds none, so its lists index the old ghost atoms: two spheres meeting across a periodic
boundary were found late (PB20: LAMMPS 3.005689) where the audit printed 0.414916 at first touch.
Every pair of such a run in a box with a periodic boundary is left out with the reason; without
pre no the pair is audited and agrees with LAMMPS."""

import json

import pytest

from deck_cli import audited_and_measured, lammps_separation_speed, needs_lammps, run

#: two spheres (4 mm type 1, 6 mm type 2) meeting at 1 m/s across the periodic x face in the
#: second run, 586 steps per contact
ACROSS = """units si
atom_style sphere 1
boundary p p f
comm_modify vel yes
region box block 0 0.04 0 0.04 0 0.1 units box
create_box 2 box
pair_style granular
pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3
fix move all nve/sphere
timestep 1e-6
create_atoms 1 single 0.03745 0.02 0.05
create_atoms 2 single 0.00355 0.02 0.05
set atom 1 diameter 0.004 density 2500
set atom 2 diameter 0.006 density 2500
velocity all set 0 0 0
set atom 1 vx 0.7714285714
set atom 2 vx -0.2285714286
run 1000
{between}
run 3000{pre}
"""

BETWEEN = ["displace_atoms all move 0 0 0 units box", "change_box all x final 0 0.04 units box",
           "balance 1.0 x uniform"]


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("between", BETWEEN, ids=["displace_atoms", "change_box", "balance"])
def test_pre_no_after_the_ghost_atoms_are_made_anew_leaves_the_pairs_out(tmp_path, between):
    deck = ACROSS.format(between=between, pre=" pre no")
    (tmp_path / "in.deck").write_text(deck)
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    assert status == 2 or json.loads(out)["pairs"] == [], out
    assert f"({between}): a run with pre no after it made the ghost atoms anew" in err, err
    assert abs(abs(lammps_separation_speed(deck, tmp_path)) - 0.4149) > 0.05        # found late


@needs_lammps
@pytest.mark.dem
def test_without_pre_no_the_run_is_set_up_and_audited(tmp_path):
    printed, engine, err = audited_and_measured(ACROSS.format(between=BETWEEN[0], pre=""), tmp_path)
    assert abs(printed - abs(engine)) < 0.004, (printed, engine, err)

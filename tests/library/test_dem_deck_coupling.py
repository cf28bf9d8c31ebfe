"""Field round 47a's avoidable refusals, in the usual layout of CFDEM's coupled cases (the DEM deck
in DEM/ beside CFD/): LIGGGHTS runs each deck (0.500006 for the pair below), the audit refused it.

- ``fix couple/cfd ... mpi`` and its sub-fixes were made a stand-in that holds none of the per-atom
  forces a variable or a compute reads (``f_cfd2[1]``, ``dragforce``): the audit's pass stopped,
  "Mismatched fix in variable formula", on CFDEM's own Ergun run decks;
- ``thermo_log ../DEM/post/thermo.txt`` opened a folder the copy does not hold: "Cannot open thermo
  log file" in the audit's pass only;
- a run deck reading the restart its init deck wrote (CFDEM's init/run split) was refused, as the
  audit holds no account of a LIGGGHTS restart's coefficients, though the run deck gives its
  materials and pair style again (a LIGGGHTS restart holds no fix)."""

import subprocess

import pytest

from deck_cli import PERIODIC_PAIR, needs_lammps, needs_liggghts, run

PAIR = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box 1 reg
neighbor 0.001 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-6
create_atoms 1 single -0.0021 0 0 units box
create_atoms 1 single 0.0021 0 0 units box
set atom * diameter 0.004 density 2500
group p1 id 1
group p2 id 2
velocity p1 set 0.5 0 0
velocity p2 set -0.5 0 0
fix integr all nve/sphere
"""
COUPLED = ("fix cfd all couple/cfd couple_every 100 mpi\nfix cfd2 all couple/cfd/force/implicit\n"
           "variable dragX equal f_cfd2[1]\nthermo_style custom step atoms v_dragX\n")


def _in_dem(tmp_path, deck: str):
    (tmp_path / "DEM" / "post").mkdir(parents=True)
    (tmp_path / "CFD").mkdir()
    (tmp_path / "DEM" / "in.deck").write_text(deck)
    return tmp_path / "DEM" / "in.deck"


def _liggghts_eps(path) -> float:
    """LIGGGHTS running the deck as written in its folder, the pair's separation speed after it."""
    path.with_name("in.engine").write_text(path.read_text() + 'variable e equal vx[2]-vx[1]\nprint "EPS ${e}"\n')
    done = subprocess.run(["liggghts", "-in", "in.engine", "-log", "none"], cwd=path.parent, capture_output=True,
                          text=True, timeout=300)
    return float(next(line for line in done.stdout.splitlines() if line.startswith("EPS")).split()[1])


@needs_liggghts
@pytest.mark.dem
@pytest.mark.parametrize("extra", [COUPLED, "thermo_log ../DEM/post/thermo.txt\n"], ids=["couple-cfd", "thermo-log"])
def test_a_cfdem_deck_is_audited_as_liggghts_runs_it(tmp_path, extra):
    deck = _in_dem(tmp_path, PAIR + extra + "run 5000\n")
    status, out, err = run(deck, "--g", "1")
    assert status == 0 and "eps 0.5000000000" in out, err
    assert not (tmp_path / "DEM" / "post" / "thermo.txt").exists()       # the audit writes nothing there
    # measured 0.500006 (the law's 0.5 at dt -> 0; 558 steps per contact)
    assert abs(_liggghts_eps(deck) - 0.5) < 1e-4


@needs_liggghts
@pytest.mark.dem
def test_a_coupling_through_files_is_still_not_run(tmp_path):
    deck = _in_dem(tmp_path, PAIR + "fix cfd all couple/cfd couple_every 100 file ../CFD/couplingFiles/\n"
                                    "fix cfd2 all couple/cfd/force\nrun 5000\n")
    status, out, err = run(deck, "--g", "1")
    assert status == 0 and "fix couple/cfd (line 26 and any like it): not executed" in err, err
    assert not (tmp_path / "CFD" / "couplingFiles").exists()


@needs_lammps
@pytest.mark.dem
def test_thermo_log_stops_lammps_as_in_the_deck(tmp_path):
    (tmp_path / "in.deck").write_text(PERIODIC_PAIR.replace("run 1000", "thermo_log t.txt\nrun 1000"))
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and "Unknown command: thermo_log" in err, err


RUN_AFTER_INIT = """atom_style granular
atom_modify map array
communicate single vel yes
newton off
read_restart post/pair.restart
neigh_modify delay 0
""" + PAIR.split("timestep 1e-6\n")[0].split("neigh_modify delay 0\n")[1] + """timestep 1e-6
fix integr all nve/sphere
run 5000
"""


@needs_liggghts
@pytest.mark.dem
@pytest.mark.parametrize("again", [True, False], ids=["style-again", "style-from-file"])
def test_a_run_deck_reading_its_init_decks_restart(tmp_path, again):
    deck = _in_dem(tmp_path, RUN_AFTER_INIT if again else RUN_AFTER_INIT.replace("pair_style gran model hertz "
                                                                                 "tangential history\n", ""))
    (tmp_path / "DEM" / "in.init").write_text(PAIR + "run 10\nwrite_restart post/pair.restart\n")
    subprocess.run(["liggghts", "-in", "in.init", "-log", "none"], cwd=deck.parent, capture_output=True, timeout=300,
                   check=True)
    status, out, err = run(deck, "--g", "1")
    if again:
        assert status == 0 and "eps 0.5000000000" in out, err
        assert abs(_liggghts_eps(deck) - 0.5) < 1e-4           # measured 0.500006
    else:
        assert status == 2 and "pair_style gran (its model the file's), of which the engine gives no account" in err, err


@needs_liggghts
@pytest.mark.dem
def test_a_deck_no_fix_moves_is_refused_in_liggghts_words(tmp_path):
    """B10 (a CFD case whose sphere is held): the refusal quoted a LAMMPS warning LIGGGHTS does not print."""
    deck = _in_dem(tmp_path, PAIR.replace("fix integr all nve/sphere\n", "") + "run 5000\n")
    status, out, err = run(deck, "--g", "1")
    assert status == 2 and "no fix integrates any atom in the deck's runs: no contact" in err, err

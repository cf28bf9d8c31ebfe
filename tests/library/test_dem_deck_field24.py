"""Field round 24's finds on round 23's fixes. H01: a soft halt with ``message no`` hid the halt the
audit reads; H02/H03: any timer command had disabled the check, where only a timer timeout after the
halt lifts it. S16: an error inside a run in a box with no fixed face (a thermo variable dividing by
zero) went unseen: every run followed by a run is now made for real to see that the engine ends it.
R22: a run's stop substituted at the pass's step was checked as if it were the deck's (a false
refusal). With --run-budget 0 the check is not made, and now said."""

import pytest

from deck_cli import needs_lammps, run
from test_dem_deck_field23 import FLOOR, NEXT

HALT = "variable t equal time\nfix h all halt 10 v_t > 0.0005 error soft{extra}\nrun 100\nunfix h\n"


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("before, halt", [
    ("", HALT.format(extra=" message no")),                  # H01
    ("timer full\n", HALT.format(extra="")),                 # H02
    ("timer timeout off\n", HALT.format(extra=""))])         # H03: lifted before the halt, not after it
def test_a_soft_halt_met_is_refused_whatever_the_deck_prints_or_times(tmp_path, before, halt):
    deck = tmp_path / "in.deck"
    deck.write_text(FLOOR + before + halt + NEXT)
    status, out, err = run(deck, "--g", "1")
    assert status == 2 and out == "" and "error soft" in err, err


@needs_lammps
@pytest.mark.dem
def test_an_error_in_a_run_of_a_periodic_box_is_refused(tmp_path):
    """S16: LAMMPS stops at step 50 ("Divide by 0"); the second stage was audited."""
    deck = tmp_path / "in.deck"
    periodic = "".join(line + "\n" for line in FLOOR.splitlines() if "wall/gran" not in line and "gravity" not in line)
    deck.write_text(periodic.replace("boundary p p f", "boundary p p p")
                    + "variable x equal 1/(step-50)\nthermo_style custom step v_x\nthermo 10\nrun 100\n" + NEXT)
    status, out, err = run(deck, "--g", "1")
    assert status == 2 and "Divide by 0" in err and "stops in this run" in err, err


@needs_lammps
@pytest.mark.dem
def test_a_stop_the_pass_substitutes_at_its_own_step_is_not_refused(tmp_path):
    """R22: stop $(step+100) after run 200 is 300 in LAMMPS, the run's end: legal."""
    deck = tmp_path / "in.deck"
    deck.write_text(FLOOR + "run 200\n" + NEXT.replace("run 100", "run 100 start 0 stop $(step+100)"))
    status, out, err = run(deck, "--g", "1")
    assert status == 0, err


@needs_lammps
@pytest.mark.dem
def test_without_runs_made_for_real_the_unseen_end_is_said(tmp_path):
    deck = tmp_path / "in.deck"
    deck.write_text(FLOOR + "run 1000\n" + NEXT)
    status, out, err = run(deck, "--g", "1", "--run-budget", "0")
    assert status == 0 and "with --run-budget 0 LAMMPS was not run to see whether it does" in err, err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("branch", ['if 1 then "include kn.in"', 'if 0 then "print no" else "include kn.in"',
                                    'if 1 then "jump kn.in"'])
def test_a_file_an_if_includes_is_read(tmp_path, branch):
    """V07, V18, V21: kn.in's pair_coeff (kn 5000) was never read, the kn 2000 rows printed (types 1 2
    0.4149159 where LAMMPS gives 0.580584, head-on at dt 1e-8)."""
    (tmp_path / "kn.in").write_text(NEXT)
    deck = tmp_path / "in.deck"
    deck.write_text(FLOOR + "run 100\n" + branch + "\n")
    status, out, err = run(deck, "--g", "1", "--json")
    assert status == 0, err
    import json
    rows = {tuple(r["types"]): r["eps"][2] for r in json.loads(out)["pairs"]}
    assert rows[(1, 2)] == pytest.approx(0.580584, abs=2e-5)


@needs_lammps
@pytest.mark.dem
def test_a_wall_only_an_if_includes_is_audited(tmp_path):
    """V29: the deck's one wall, in wall.in, had no row."""
    wall = next(line for line in FLOOR.splitlines() if "wall/gran" in line)
    (tmp_path / "wall.in").write_text(wall.replace("hooke 2000", "hooke 5000") + "\n")
    deck = tmp_path / "in.deck"
    deck.write_text(FLOOR.replace(wall + "\n", 'if 1 then "include wall.in"\n') + "run 100\n")
    status, out, err = run(deck, "--g", "1", "--json")
    assert status == 0, err
    import json
    (row,) = [r for r in json.loads(out)["walls"] if r["types"] == [1]]
    assert row["eps"][2] == pytest.approx(0.536982, abs=2e-5)      # LAMMPS, a sphere dropped on it

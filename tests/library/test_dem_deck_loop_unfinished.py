"""A loop the audit's pass does not finish (its time budget or the echo's cap) may end in the engine,
which then runs what follows it. Field round 18, b40: a finite loop of 10 000 short runs filled the
echo's cap, the stiffness changed after it for the production run, and the audit printed the settling
run's 1 2 (0.4972621) where LAMMPS' production run gives 0.7238405, saying the loop never ends and
that --budget would help (it did not: the cap was fixed). Now the line after the loop is named and the
deck is not audited; a larger budget reads the whole loop and answers."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, run

DECK = Path(__file__).resolve().parents[1] / "field18" / "decks" / "b40_long_loop_echo_then_change" / "in.deck"


@needs_lammps
@pytest.mark.dem
def test_a_line_after_an_unfinished_loop_that_may_change_a_contact_stops_the_audit(tmp_path):
    status, out, err = run(DECK, "--g", "1")
    assert status == 2 and out == "", out
    assert "line 33 (pair_coeff" in err and "--budget" in err and len(err.strip().splitlines()) == 1, err


@needs_lammps
@pytest.mark.dem
def test_a_larger_budget_reads_the_whole_loop_and_the_production_stage(tmp_path):
    status, out, err = run(DECK, "--g", "1", "--budget", "40", "--json")
    assert status == 0, err
    last = json.loads(out)["stages"][-1]
    (row,) = [r for r in last["pairs"] if tuple(r["types"]) == (1, 2)]
    # LAMMPS, head-on at this stiffness (field round 18's referee): 0.7238405
    assert row["eps"][0] == pytest.approx(0.7238405, abs=2e-7)


@needs_lammps
@pytest.mark.dem
def test_an_unfinished_loop_followed_only_by_output_and_runs_is_answered(tmp_path):
    text = DECK.read_text().replace("pair_coeff * * hooke 9000", "print 'done' # pair_coeff * * hooke 9000")
    (tmp_path / "in.deck").write_text(text)
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    assert status == 0 and "audited as far as it ran" in err, err

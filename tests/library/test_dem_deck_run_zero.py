"""A run that makes no step (run 0; run N upto at step N already) sees no contact: it is no stage.
Field round 19, C1: b10 and c10 reported the coefficients set before such a run as the deck's last
stage (1 2 0.66858548 under hooke 9000), where LAMMPS makes no step under them; the contacts happen
under the first run's (1 2 0.41491590)."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, run

DECKS = Path(__file__).resolve().parents[1] / "field19" / "decks"


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("name", ["b10_coeff_change_then_run0", "c10_run_upto_zero_steps"])
def test_a_run_of_no_step_is_no_stage(name):
    status, out, err = run(DECKS / name / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    got = json.loads(out)
    assert len(got["stages"]) == 1
    (row,) = [r for r in got["pairs"] if tuple(r["types"]) == (1, 2)]
    assert row["eps"][0] == pytest.approx(0.4149158989, rel=1e-9)

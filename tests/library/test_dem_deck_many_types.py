"""A deck of many atom types (one per size class, as polydisperse decks with neighbor multi have) is
audited: its present types' pairs, and one line for the empty ones. Field round 18, D6: b41's 120
types were refused ("an atom type must be an integer in 1..100")."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, run

DECK = Path(__file__).resolve().parents[1] / "field18" / "decks" / "b41_many_types_120" / "in.deck"


@needs_lammps
@pytest.mark.dem
def test_a_deck_of_120_types_is_audited_with_its_empty_types_in_one_line():
    status, out, err = run(DECK, "--g", "1", "--json")
    assert status == 0, err
    got = json.loads(out)
    assert {tuple(r["types"]) for r in got["pairs"]} == {(1, 1), (1, 60), (1, 120), (60, 60), (60, 120), (120, 120)}
    assert [ln for ln in err.splitlines() if "no particle" in ln] == [
        "restitution deck: types 2-59, 61-119 have no particle (walls only, unused, or deleted): their sphere pairs "
        "cannot happen there and are not audited"]

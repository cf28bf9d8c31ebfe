"""An inserting fix unfixed before any run inserts nothing: its type is not said to be inserted "as the
runs go". Field round 19, c30 (a false word: the type had no row, rightly, but the note named the pour)."""

from pathlib import Path

import pytest

from deck_cli import needs_lammps, run

DECK = Path(__file__).resolve().parents[1] / "field19" / "decks"


@needs_lammps
@pytest.mark.dem
def test_a_pour_unfixed_before_any_run_is_not_said_to_insert():
    (deck,) = DECK.glob("c30*/in.deck")
    status, out, err = run(deck, "--g", "1")
    assert status == 0, err
    assert "inserted by fix p" not in err and "type 2 has no particle" in err, err

"""A pair style's OpenMP variant typed by name (gran/hertz/history/omp) computes the plain style's
forces, as the plain name under `suffix omp` does: audited as the plain style. Field round 19, C2:
c26 was refused ("not mapped")."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, run

DECK = Path(__file__).resolve().parents[1] / "field19" / "decks" / "c26_gran_hertz_history_omp_typed" / "in.deck"


def _rows(path: Path) -> list:
    status, out, err = run(path, "--g", "1", "--json")
    assert status == 0, err
    return [(r["types"], r["eps"]) for r in json.loads(out)["pairs"]]


@needs_lammps
@pytest.mark.dem
def test_a_typed_omp_style_is_audited_as_the_plain_style(tmp_path):
    plain = tmp_path / "in.deck"
    plain.write_text(DECK.read_text().replace("gran/hertz/history/omp", "gran/hertz/history"))
    assert _rows(DECK) == _rows(plain) and len(_rows(DECK)) == 3

"""The sub-models of a LAMMPS granular pair_coeff that take no part in a head-on contact: ``rolling
none`` and ``twisting none`` add nothing, and LAMMPS runs them (field round 16, D6: R02 and p01 were
refused, "keyword twisting is not mapped", exit 2)."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, run

FIELD16 = Path(__file__).resolve().parents[1] / "field16" / "decks"


@needs_lammps
@pytest.mark.dem
def test_rolling_none_and_twisting_none_are_audited(tmp_path):
    """The rows are those of the same deck without the two words (R02b, refereed in LAMMPS)."""
    status, out, err = run(FIELD16 / "p01_rolling_none_twisting_none" / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    text = (FIELD16 / "p01_rolling_none_twisting_none" / "in.deck").read_text()
    assert "rolling none" in text and "twisting none" in text
    bare = tmp_path / "in.deck"
    bare.write_text(text.replace(" rolling none", "").replace(" twisting none", ""))
    status2, out2, err2 = run(bare, "--g", "1", "--json")
    assert status2 == 0, err2
    assert [r["eps"] for r in json.loads(out)["pairs"]] == [r["eps"] for r in json.loads(out2)["pairs"]]

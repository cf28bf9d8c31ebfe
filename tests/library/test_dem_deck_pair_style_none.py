"""``pair_style none`` (a settling stage without forces between spheres) is no stage: field round 19,
a10 was refused whole ("pair_style none is not mapped") though its production run is mapped."""

import json
from pathlib import Path

from deck_cli import needs_lammps, run
import pytest

DECKS = Path(__file__).resolve().parents[1] / "field19" / "decks"


@needs_lammps
@pytest.mark.dem
def test_a_run_under_pair_style_none_is_no_stage(tmp_path):
    deck = (DECKS / "a10_pair_style_none_then_granular" / "in.deck").read_text()
    status, out, err = run(DECKS / "a10_pair_style_none_then_granular" / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    got = json.loads(out)
    assert len(got["stages"]) == 1 and "pair_style none" in err and "no force between spheres" in err
    # the same deck without its settling run: the production run's rows, equal
    alone = deck.replace("pair_style none\n", "").replace("run 100\npair_style granular", "pair_style granular", 1)
    assert alone.count("run 100") == 1
    (tmp_path / "in.deck").write_text(alone)
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    def rows(pairs):
        return [(r["types"], r["model"], r["eps"]) for r in pairs]
    assert rows(json.loads(out)["pairs"]) == rows(got["pairs"])

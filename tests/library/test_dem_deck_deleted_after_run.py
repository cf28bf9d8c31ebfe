"""delete_atoms group G after a run that inserted atoms deletes those too (the engine's pass, its runs
skipped, never held them): the types G holds whole have no pair in the stages after. Field round 18,
D2: b24 (pour), b45 (deposit), G48 (LIGGGHTS insert/pack) still printed 1 2 and 2 2 in the second
stage, where LAMMPS and LIGGGHTS hold type 1 only."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, needs_liggghts, run

DECKS = Path(__file__).resolve().parents[1] / "field18" / "decks"


def _stages(name: str) -> list:
    status, out, err = run(DECKS / name / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    return [{tuple(r["types"]) for r in stage["pairs"]} for stage in json.loads(out)["stages"]], err


@pytest.mark.dem
@pytest.mark.parametrize("name", [pytest.param("b24_delete_after_pour_run", marks=needs_lammps),
                                  pytest.param("b45_delete_after_deposit_run", marks=needs_lammps),
                                  pytest.param("G48_delete_after_insert_run", marks=needs_liggghts)])
def test_a_type_deleted_after_an_inserting_run_has_no_pairs_after_it(name):
    (first, second), err = _stages(name)
    assert {(1, 2), (2, 2)} <= first
    assert second == {(1, 1)}, err
    assert "walls only, unused, or deleted" in err

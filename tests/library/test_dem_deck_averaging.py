"""Averaging fixes beside the contact: they push no atom and are named so (field round 16, D5)."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, run

FIELD16 = Path(__file__).resolve().parents[1] / "field16" / "decks"


def _json(path, *speeds):
    status, out, err = run(path, "--g", *map(str, speeds), "--json")
    return status, (json.loads(out) if status == 0 else None), err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("deck", ["v01b_avechunk_if_stiffness", "v03_avecorrelate_if", "v04_fix_vector_if"])
def test_averaging_fixes_are_not_called_forces(deck):
    """fix ave/chunk, ave/correlate and vector push nothing (field round 16, D5: "not understood: may
    add forces" was said of each)."""
    status, got, err = _json(FIELD16 / deck / "in.deck", 1.0)
    assert status == 0, err
    assert "may add forces" not in err and not got["unknown_lines"], err

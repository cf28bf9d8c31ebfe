"""`units` sets the units' default time step in both engines, whatever a `timestep` before it said.
Field round 19, C3: c13 (LAMMPS) and L30 (LIGGGHTS) gave 4.66 steps per contact at dt 1e-4 and the eps
spread there, where the engines ran 46 576 steps per contact at 1e-8."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, needs_liggghts, run

DECKS = Path(__file__).resolve().parents[1] / "field19" / "decks"


@pytest.mark.dem
@pytest.mark.parametrize("name", [pytest.param("c13_timestep_before_units_large", marks=needs_lammps),
                                  pytest.param("L30_liggghts_timestep_before_units", marks=needs_liggghts)])
def test_a_timestep_before_units_is_not_the_decks(name):
    status, out, err = run(DECKS / name / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    for row in json.loads(out)["pairs"]:
        assert row["dt"] == pytest.approx(1e-8) and min(row["steps_per_contact"]) > 1e4

"""A set after a run that inserted atoms resizes them too (the engine's pass never held them): by a
group that holds its types whole it is read as set type is, and where the reader cannot follow it (a
deposit's atoms) the runs are made for real. Field round 18, D4: b25, b46, b49 were refused with
"give --radius". The checks are the dashpot's closed form at the sizes LAMMPS holds (hooke with
mass_velocity damping: m_eff x'' = -k x - eta m_eff x', contact ending at zero overlap)."""

import json
import math
from pathlib import Path

import pytest

from deck_cli import needs_lammps, run

DECKS = Path(__file__).resolve().parents[1] / "field18" / "decks"


def _dashpot(m_eff: float, k: float = 2e4, eta: float = 30.0) -> float:
    zeta = eta / (2.0 * math.sqrt(k / m_eff))
    return math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta * zeta))


def _last(deck: Path) -> dict:
    status, out, err = run(deck, "--g", "1", "--json")
    assert status == 0, err
    stage = json.loads(out)["stages"][-1]
    return {tuple(r["types"]): r["eps"][0] for r in stage["pairs"]}


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("name, radius, density", [("b25_set_density_after_deposit_run", 0.25, 2.0),
                                                    ("b49_set_group_density_after_deposit_run", 0.5, 5.0)])
def test_a_set_after_a_deposit_run_is_answered_at_the_sizes_the_engine_holds(name, radius, density):
    m1, m2 = 4 / 3 * math.pi * 3.0, 4 / 3 * math.pi * radius ** 3 * density    # type 1: diameter 2, density 3
    got = _last(DECKS / name / "in.deck")
    assert got[(2, 2)] == pytest.approx(_dashpot(m2 / 2), rel=1e-9)
    assert got[(1, 2)] == pytest.approx(_dashpot(m1 * m2 / (m1 + m2)), rel=1e-9)


@needs_lammps
@pytest.mark.dem
def test_set_group_of_a_whole_type_after_a_pour_is_set_type(tmp_path):
    deck = DECKS / "b46_set_group_after_pour_run" / "in.deck"
    (tmp_path / "in.deck").write_text(deck.read_text().replace("set group t2 diameter", "set type 2 diameter"))
    assert _last(deck) == _last(tmp_path / "in.deck")

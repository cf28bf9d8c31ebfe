"""fix deposit ... mol TEMPLATE makes the template's spheres, of its size, at type offset + its type
(the fix's type word is an offset, 0 allowed). Field round 18: b53 printed only type 2's 4 mm rows
while LAMMPS deposited 6 mm, 0.0009 kg spheres of type 2 (2 2 at g 1: audit 0.4972102, LAMMPS
0.0263036); b04 said type 2 had no particle; s04 and s13 (offset 0) were refused. The LAMMPS numbers
are the field round's head-on referee runs (tests/field18/FINDINGS.md, D1)."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, run

DECKS = Path(__file__).resolve().parents[1] / "field18" / "decks"


def _audit(name: str) -> dict:
    status, out, err = run(DECKS / name / "in.deck", "--g", "0.1", "1", "--json")
    assert status == 0, err
    return json.loads(out)


def _eps(rows: list, types: tuple) -> list:
    return [r["eps"] for r in rows if tuple(r["types"]) == types]


@needs_lammps
@pytest.mark.dem
def test_a_deposited_template_sphere_is_audited_at_its_own_size_beside_the_types_others():
    got = _audit("b53_deposit_mol_offset_type_present")
    # LAMMPS head-on: two deposited spheres 0.12595218 / 0.02630355, a 4 mm and a deposited one 0.51806076 /
    # 0.35366672, a deposited one on the floor 0.01698698 / 0.00172432 (g 0.1 / 1)
    assert min(e[0] for e in _eps(got["pairs"], (2, 2))) == pytest.approx(0.12595218, abs=2e-6)
    assert min(e[1] for e in _eps(got["pairs"], (2, 2))) == pytest.approx(0.02630355, abs=1e-6)
    assert min(e[1] for e in _eps(got["pairs"], (1, 2))) == pytest.approx(0.35366672, abs=1e-6)
    floor = [w["eps"] for w in got["walls"] if w["types"] == [2]]
    assert min(e[0] for e in floor) == pytest.approx(0.01698698, abs=1e-6)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("name", ["b04_deposit_mol_type_offset", "s04_deposit_mol_template"])
def test_a_deposit_of_a_template_gives_its_type_pairs(name):
    got = _audit(name)
    assert _eps(got["pairs"], (1, 2)) and _eps(got["pairs"], (2, 2))

"""A size an inserting fix draws with weight 0, or a template no insertion draws, is never made: it is
not a size present. Field round 19, C5 (silently wrong): c31 (fix pour diam poly with probability 0
for 2 mm) printed 2 2 "largest over the sizes present" 0.89251824 at g 0.1 where every LAMMPS contact
is 6 mm on 6 mm, 0.37166038; c36 and c37 (molfrac 0) the same; LIGGGHTS' L37 (weight 0), L39 (a
template no distribution draws), L40 (a type only a weight-0 template has), L41 (a distribution no
insertion uses). The engine numbers are the field round's head-on referee runs."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, needs_liggghts, run

DECKS = Path(__file__).resolve().parents[1] / "field19" / "decks"


def _pairs(name: str) -> dict:
    status, out, err = run(DECKS / name / "in.deck", "--g", "0.1", "1", "--json")
    assert status == 0, err
    rows: dict = {}
    for r in json.loads(out)["pairs"]:
        rows.setdefault(tuple(r["types"]), []).append(r["eps"])
    return rows


@needs_lammps
@pytest.mark.dem
def test_a_poly_diameter_of_probability_zero_is_not_a_size_present():
    rows = _pairs("c31_pour_poly_zero_probability")
    (two_two,) = rows[(2, 2)]                         # one size: one row
    assert two_two == pytest.approx([0.37166038, 0.20278427], abs=1e-6)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("name", ["c36_pour_mol_molfrac_zero", "c37_deposit_mol_molfrac_zero"])
def test_a_template_of_molfrac_zero_is_not_a_size_present(name):
    (two_two,) = _pairs(name)[(2, 2)]
    assert two_two[0] == pytest.approx(0.12595218, abs=1e-6)      # 6 mm on 6 mm, LAMMPS


@needs_liggghts
@pytest.mark.dem
@pytest.mark.parametrize("name", ["L37_distribution_weight_zero", "L39_unused_template",
                                  "L41_distribution_not_inserted"])
def test_liggghts_templates_never_drawn_are_not_sizes_present(name):
    rows = _pairs(name)
    assert len(rows[(2, 2)]) == 1 and len(rows[(1, 2)]) == 1


@needs_liggghts
@pytest.mark.dem
def test_a_type_only_a_weight_zero_template_has_has_no_pairs():
    assert not any(3 in pair for pair in _pairs("L40_distribution_zero_weight_other_type"))

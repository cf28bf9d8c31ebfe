"""Field round 22's silent classes. E1: a dynamic group's members after a run are where the run left
the atoms (t16: a set of it after a fall set atoms LAMMPS no longer held in it; y13 the reverse).
E2: atoms lost in a run (thermo_modify lost ignore or warn, fix evaporate) are gone from the later
runs (v01: a sphere that fell out of the box was audited beside the two the engine kept; z06, z08:
set atom N then met another atom). Both are answered by making the runs for real. E3: a carriage
return without a line feed is part of a line to the engines, a line end to a reader of text (y01,
y14): refused. The engine's numbers are round 22's head-on probes at g = 1 (dt 1e-8, good to about
1e-5; tests/field22/FINDINGS.md)."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, needs_liggghts, run

DECKS = Path(__file__).resolve().parents[1] / "field22" / "decks"


def at_g1(name):
    folder = next(DECKS.glob(f"{name}_*"))
    status, out, err = run(folder / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    # --g 1: five speeds over two decades, g = 1 the third
    return {tuple(r["types"]): r["eps"][2] for r in json.loads(out)["pairs"]}, err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("name, engine", [
    ("t16", {(1, 1): 0.497260, (2, 2): 0.255068}), ("y13", {(1, 1): 0.271356, (2, 2): 0.044248}),
    ("v01", {(1, 2): 0.414918}), ("z06", {(1, 2): 0.471593}), ("z08", {(2, 2): 0.044248})])
def test_what_the_runs_did_to_groups_and_atoms_is_the_engines(name, engine):
    got, err = at_g1(name)
    assert "for real" in err
    for types, eps in engine.items():
        assert got[types] == pytest.approx(eps, abs=2e-5), (types, got)


@pytest.mark.dem
@pytest.mark.parametrize("name", [pytest.param("y01", marks=needs_lammps), pytest.param("y14", marks=needs_liggghts)])
def test_a_lone_carriage_return_is_refused(name):
    folder = next(DECKS.glob(f"{name}_*"))
    status, out, err = run(folder / "in.deck", "--g", "1")
    assert status == 2 and "carriage return not followed by a line feed" in err and out == ""


@needs_lammps
@pytest.mark.dem
def test_crlf_line_ends_are_line_ends():
    got, err = at_g1("q01")
    assert got[(1, 1)] == pytest.approx(0.646973, abs=2e-5)   # kn 5000: LAMMPS head-on, round 21 (a13)

"""A LIGGGHTS insertion inserts nothing before its ``start`` step, and LIGGGHTS stops where that step
is not after the one the runs reach. Field round 19, C4: L33 (start 100000, one run of 2000), L34
(insert/rate/region, start 5000) and L36 (start 3000, two runs of 2000) reported the pairs of type-2
spheres LIGGGHTS never made (or made only in the second run), nothing said. Also c29: a LAMMPS deck
whose only run is ``run 0`` is audited as set up, and now says so."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, needs_liggghts, run

DECKS = Path(__file__).resolve().parents[1] / "field19" / "decks"


def pairs(stage):
    return sorted(tuple(r["types"]) for r in stage["pairs"])


@needs_liggghts
@pytest.mark.dem
@pytest.mark.parametrize("name", ["L33_insert_start_after_run", "L34_insert_rate_region_start_after_run"])
def test_an_insertion_starting_after_the_runs_makes_no_pair(name):
    status, out, err = run(DECKS / name / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    got = json.loads(out)
    assert pairs(got) == [(1, 1)]
    assert all(tuple(w["types"]) != (2,) for w in got["walls"])
    assert "type 2 has no particle (the runs before step" in err and "fix ins" in err


@needs_liggghts
@pytest.mark.dem
def test_an_insertion_starting_in_the_second_run_makes_its_pairs_there():
    status, out, err = run(DECKS / "L36_insert_start_in_second_run" / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    first, second = json.loads(out)["stages"]
    assert pairs(first) == [(1, 1)]
    assert pairs(second) == [(1, 1), (1, 2), (2, 2)]


@needs_liggghts
@pytest.mark.dem
@pytest.mark.parametrize("start, refused", [(2000, True), (2001, False)])
def test_a_start_not_after_the_step_reached_is_refused(tmp_path, start, refused):
    # LIGGGHTS 3.8.0 measured: start 2000 defined after run 2000 stops ("'start' step can not be
    # before current step"), start 2001 inserts
    deck = (DECKS / "L33_insert_start_after_run" / "in.deck").read_text().splitlines()
    ins = next(line for line in deck if line.startswith("fix ins"))
    body = [line for line in deck if not line.startswith("fix ins")]
    body += [ins.replace("start 100000", f"start {start}"), "run 500"]
    (tmp_path / "in.deck").write_text("\n".join(body) + "\n")
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    if refused:
        assert status == 2 and f"start {start} is not after step 2000" in err and not out
    else:
        assert status == 0, err
        assert pairs(json.loads(out)["stages"][-1]) == [(1, 1), (1, 2), (2, 2)]


@needs_liggghts
@pytest.mark.dem
def test_a_liggghts_run_of_a_fraction_makes_no_step(tmp_path):
    # LIGGGHTS reads run 0.5 as atoi does: 0 steps (measured: the step stays 0)
    deck = (DECKS / "L33_insert_start_after_run" / "in.deck").read_text()
    # new stiffnesses after the run: a run that made steps under them would be a second stage
    stiffer = "fix m4 all property/global kn peratomtypepair 3 9000 9000 9000 9000 9000 9000 9000 9000 9000"
    (tmp_path / "in.deck").write_text(deck.replace("\nrun 2000", f"\nrun 2000\n{stiffer}\nrun 0.5"))
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    assert len(json.loads(out)["stages"]) == 1


@needs_lammps
@pytest.mark.dem
def test_a_deck_whose_runs_make_no_step_says_so():
    status, out, err = run(DECKS / "c29_pour_then_run0_only" / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    assert "makes no step, as every run of the deck" in err

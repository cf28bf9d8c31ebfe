"""A sphere no fix integrates stays in place, yet holds whatever velocity a velocity command or an
inserting fix gave it, and the contact's damping reads that velocity (field round 17, w21: type 2
given 0.3 0.3 0.3 and never integrated, head-on at g = 1: LAMMPS 0.56423 where a still sphere gives
0.61384, the audit's value; LIGGGHTS the same, G17). Such pairs are named, not audited."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, run

FIELD = Path(__file__).resolve().parents[1] / "field15" / "decks"
HEAD = (FIELD / "n02_neigh_stale_lists" / "in.deck").read_text().split("\nneighbor 1e-5 bin")[0] + "\n"


def _audit(tmp_path, velocity: str):
    deck = HEAD.replace("fix integ all nve/sphere\n", "") + (
        f"group t1 type 1\ngroup t2 type 2\n{velocity}fix integ t1 nve/sphere\nrun 100\n")
    (tmp_path / "in.deck").write_text(deck)
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    return status, (json.loads(out) if status == 0 else None), err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("velocity, named", [("velocity t2 set 0.3 0.3 0.3\n", True),
                                             ("velocity all set 0 0 -1\n", True),
                                             ("velocity t2 set 0 0 0\n", False), ("", False)])
def test_pairs_with_a_held_sphere_that_holds_a_velocity_are_named(tmp_path, velocity, named):
    status, got, err = _audit(tmp_path, velocity)
    assert status == 0, err
    audited = {tuple(r["types"]) for r in got["pairs"]}
    assert ((1, 2) not in audited) == named, err
    assert ("gives type 2's spheres a velocity" in err) == named, err
    assert (1, 1) in audited


def _stages(tmp_path, runs: str):
    deck = HEAD.replace("fix integ all nve/sphere\n", "") + f"group t1 type 1\ngroup t2 type 2\n{runs}"
    (tmp_path / "in.deck").write_text(deck)
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    got = json.loads(out)
    return [{tuple(r["types"]) for r in stage["pairs"]} for stage in got.get("stages", [got])], err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("runs, named", [
    # type 2 falls under gravity in the first run; held from the second on, it keeps the velocity it fell with
    ("fix integ all nve/sphere\nrun 100\nunfix integ\nfix integ t1 nve/sphere\nrun 100\n", True),
    ("fix integ all nve/sphere\nrun 100\nrun 100\n", False),
    # a velocity command between two runs whose contacts are otherwise the same (they were one stage)
    ("fix integ t1 nve/sphere\nrun 100\nvelocity t2 set 0.3 0 0\nrun 100\n", True),
    ("fix integ t1 nve/sphere\nrun 100\nvelocity t2 set 0 0 0\nrun 100\n", False)])
def test_a_held_sphere_keeps_the_velocity_of_an_earlier_run(tmp_path, runs, named):
    stages, err = _stages(tmp_path, runs)
    assert (1, 2) in stages[0] or named is False and len(stages) == 1, err
    assert ((1, 2) not in stages[-1]) == named, err
    assert all((1, 1) in s for s in stages)

"""Neighbour lists the engine rebuilds only every K steps (issue 52, field round 15, D2): two bodies
that close by more than the skin between two builds are first looked at when they already overlap,
and the engine's eps is no longer the law's (LAMMPS, ``neighbor 1e-5 bin`` with ``neigh_modify every
200 check no``: 5.99 to 0.82 by the starting gap where the contact gives 0.4025; LIGGGHTS the same,
its walls too). The rows said the law's eps at every speed; now no eps above skin / (K dt)."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, needs_liggghts, run

FIELD = Path(__file__).resolve().parents[1] / "field15" / "decks"


def _json(path, *speeds):
    status, out, err = run(path, "--g", *map(str, speeds), "--json")
    return status, (json.loads(out) if status == 0 else None), err


@pytest.mark.dem
@pytest.mark.parametrize("deck, walls", [pytest.param("n02_neigh_stale_lists", False, marks=needs_lammps),
                                         pytest.param("L15_neigh_stale_lists", True, marks=needs_liggghts)])
def test_no_eps_is_given_where_the_lists_find_the_contact_late(deck, walls):
    path = FIELD / deck / "in.deck"
    status, got, err = _json(path, 0.001, 1.0)
    assert status == 0, err
    assert "may first meet already overlapping" in err and "= 0.005" in err, err
    rows = got["pairs"] + (got["walls"] if walls else [])
    assert rows and all(r["eps"][0] is not None and r["eps"][1] is None and r["late"] == [False, True]
                        and r["late_above"] == pytest.approx(0.005) for r in rows)
    if not walls:     # LAMMPS' fix wall/gran loops over its atoms, no neighbour list
        assert all("late" not in w and None not in w["eps"] for w in got["walls"])

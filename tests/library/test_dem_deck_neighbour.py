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


#: field round 16's deck shape (LAMMPS, hooke with mass_velocity damping, two free spheres and a floor)
HEAD = (FIELD / "n02_neigh_stale_lists" / "in.deck").read_text().split("\nneighbor 1e-5 bin")[0] + "\n"


def _audit(tmp_path, tail, *speeds):
    (tmp_path / "in.deck").write_text(HEAD + tail)
    return _json(tmp_path / "in.deck", *speeds)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("every", [2, 10])
def test_lists_checked_every_k_steps_find_two_spheres_late_at_any_speed(tmp_path, every):
    """``check yes`` with every K > 1 (field round 16, n01, n04): a rebuild waits for an atom to have
    moved half the skin, seen only at the next check, and two spheres closing on each other have each
    moved half the skin just as they touch. LAMMPS measured, at the deck's own step, 0.498 to 0.722 by
    the starting gap at g = 0.05 (every 10, skin 1e-4) and up to 0.516 at g = 0.5 (every 2, skin
    2e-5), where the contact gives 0.4829 to 0.4983 with the usual lists; the audit said 0.497262
    below skin / (K dt). Now no sphere pair has an eps at any speed; LAMMPS' wall/gran rows keep theirs."""
    status, got, err = _audit(tmp_path, f"neighbor 2e-5 bin\nneigh_modify every {every} delay 0 check yes\nrun 100\n",
                              0.05, 0.5)
    assert status == 0, err
    assert "at any speed" in err and f"up to {every - 1} steps" in err, err
    assert got["pairs"] and all(r["late"] == [True, True] and r["eps"] == [None, None] and r["late_above"] == 0
                                for r in got["pairs"])
    assert got["walls"] and all("late" not in w and None not in w["eps"] for w in got["walls"])


@needs_lammps
@pytest.mark.dem
def test_lists_set_for_a_later_run_with_the_same_contacts_are_read(tmp_path):
    """A first run with the usual lists, then ``neighbor 1e-5`` and ``every 20 check no`` before a
    second run with the same contact settings (field round 16, n07: LAMMPS 0.498 to 1.037 by the
    starting gap at g = 1 in the second run): the stage held the first run's lists only, and gave
    0.497262 at every speed. Now the second run's lists count: it is a stage of its own (how often the
    lists are rebuilt is each run's own; field round 28, N41), the first keeps its eps at every speed."""
    status, got, err = _audit(tmp_path, "run 100\nneighbor 1e-5 bin\nneigh_modify every 20 delay 0 check no\nrun 100\n",
                              0.01, 1.0)
    assert status == 0, err
    assert len(got["stages"]) == 2 and "= 0.05 may first meet" in err, err
    assert all(r["late"] == [False, True] and r["eps"][0] is not None for r in got["pairs"])
    assert all("late" not in r and None not in r["eps"] for r in got["stages"][0]["pairs"])


@needs_lammps
@pytest.mark.dem
def test_neigh_modify_include_names_the_pairs_outside_its_group(tmp_path):
    """``neigh_modify include g1`` (type 1): LAMMPS builds no list for a pair of type-2 atoms, which
    passed through each other (field round 16, n06); the audit gave 2 2 the law's eps."""
    status, got, err = _audit(tmp_path, "create_atoms 2 single 0.03 0.03 0.01\nset type 2 diameter 0.006 density 2500\n"
                              "group g1 type 1\natom_modify first g1\nneigh_modify include g1\nrun 100\n", 1.0)
    assert status == 0, err
    assert {tuple(r["types"]) for r in got["pairs"]} == {(1, 1)}
    assert "types 2 2: neigh_modify include g1" in err and "types 1 2: neigh_modify include g1" in err, err
    # LAMMPS threw a type-2 sphere off the floor at 24 to 60 times its impact speed
    assert {w["types"][0] for w in got["walls"]} == {1} and "type 2: neigh_modify include g1" in err


FIELD16 = Path(__file__).resolve().parents[1] / "field16" / "decks"


@needs_liggghts
@pytest.mark.dem
def test_liggghts_walls_of_spheres_outside_an_include_group_are_named():
    """LIGGGHTS finds its walls through the same lists (field round 16, L22): a type-2 sphere outside
    ``neigh_modify include g1`` was thrown off the floor at 43 times its impact speed, where the audit
    printed the law's 0.45; now its wall row is named, type 1's kept."""
    status, got, err = _json(FIELD16 / "L22_neigh_include_group" / "in.deck", 1.0)
    assert status == 0, err
    assert "type 2: neigh_modify include g1" in err and "thrown off a wall" in err, err
    assert {w["types"][0] for w in got["walls"]} == {1}
    assert {tuple(r["types"]) for r in got["pairs"]} == {(1, 1)}



@needs_lammps
@pytest.mark.dem
def test_a_run_whose_every_changes_the_lists_finds_contacts_late_from_its_second_part():
    """``run 1000 every 500 "neigh_modify every 10 delay 0 check no"`` (field round 16, n25): the
    second part's lists find contacts late; 0.497 was printed, then the deck was refused. The run is
    now made as its two parts, the command between them: the stage that holds the second part (its
    lists as the engine's) has no eps above skin / (10 dt) = 1 m/s."""
    status, got, err = _json(FIELD16 / "n25_run_every_neigh_modify" / "in.deck", 0.5, 2.0)
    assert status == 0, err
    assert "made as its 2 parts" in err and "every 10 steps without looking" in err, err
    last = got["stages"][-1]
    assert last["pairs"] and all(r["eps"][0] is not None and r["eps"][1] is None for r in last["pairs"]), last


@needs_lammps
@pytest.mark.dem
def test_lists_built_once_per_run_find_no_contact_in_time(tmp_path):
    """``neigh_modify once yes`` (field round 17, a07): LAMMPS builds its lists at the run's start
    only; two spheres 1.1 mm or more apart (skin 1 mm) passed through each other, and 0.497 was
    printed. Now no eps at any speed; LAMMPS' wall/gran rows keep theirs."""
    status, got, err = _audit(tmp_path, "neigh_modify once yes\nrun 100\n", 0.1, 1.0)
    assert status == 0, err
    assert "once yes" in err and all(r["late_above"] == 0 and r["eps"] == [None, None] for r in got["pairs"]), err
    assert got["walls"] and all(None not in w["eps"] for w in got["walls"])


@needs_lammps
@pytest.mark.dem
def test_the_lists_bound_is_read_at_the_largest_step_a_dt_reset_may_take(tmp_path):
    """A fix dt/reset raises the step during the run (field round 17, a19: 1e-6 to 1e-4 at once,
    LAMMPS up to 3.3 at g = 0.5 where 0.497 was printed below the bound at the deck's step). The bound
    skin / (10 dt) is read at its largest step, 1e-4: 0.1, not 1.0 at the deck's 1e-5."""
    status, got, err = _audit(tmp_path, "neighbor 1e-4 bin\nneigh_modify every 10 delay 0 check no\n"
                              "fix dtr all dt/reset 1 1e-7 1e-4 0.01 units box\nrun 100\n", 0.05, 0.5)
    assert status == 0, err
    assert all(r["late"] == [False, True] and r["late_above"] == pytest.approx(0.1) for r in got["pairs"]), err

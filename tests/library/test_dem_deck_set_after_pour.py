"""A ``set type T diameter|density|mass`` after a fix pour's run (R3): LAMMPS resizes the atoms the
pour made in the runs before, which the engine's pass (its runs skipped) never made; the audit kept
the pour's size for them. Measured in LAMMPS 22 Jul 2025 (a pour of diameter 0.01, density 2500, run
3000 steps, 269 atoms poured, then ``set type 1 diameter 0.006`` and 3000 more steps): the 269 have
radius 0.003 and their mass kept (density 2500 (5/3)^3 = 11574.07); the 131 poured later the pour's
size; a ``set type 1 density 1000`` then gives every atom of the type the mass of density 1000 at its
own radius. ``set`` changes the atoms that exist, never those poured later."""

import json

import pytest

from deck_cli import lammps_held_at_end, lammps_pour, needs_lammps, run
from restitution.dem.contact import Contact
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.pair import Pair

LINE = "pair_coeff * * hertz 1e6 300 damping mass_velocity tangential linear_nohistory 1 0.3"
DECK = lammps_pour(LINE, ntypes=2, sphere=(2, 0.004, 3000.0)) + """timestep 1e-5
run 100
{between}{set}
run 100
"""


def _audit(tmp_path, between: str, set_: str, *args):
    (tmp_path / "in.deck").write_text(DECK.format(between=between, set=set_))
    status, out, err = run(tmp_path / "in.deck", "--g", "0.5", "--json", *args)
    return status, (json.loads(out) if status == 0 else None), err


def _engine(r, sizes):
    """LAMMPS' own eps for the row's pair at the row's spheres, head-on, 4000 to 16000 steps per contact."""
    g = r["speeds"][2]
    (r1, d1), (r2, d2) = sizes
    t_c = Contact(r["alpha"], r["gamma"], r["D1"], r["D2"], r["end"]).contact_time(g)
    return lammps_run.lammps_eps_extrapolated(Pair.spheres(r1, r2, d1, d2), LINE, g, t_c, types=(1, 1))


@needs_lammps
@pytest.mark.dem
def test_a_set_after_the_pour_ran_resizes_the_poured_atoms(tmp_path):
    """Before: type 1 audited at the pour's radius 0.005, density 2500. The pour unfixed, the type's
    atoms are the 269 the set resized: radius 0.003, mass kept."""
    status, got, err = _audit(tmp_path, "unfix p\n", "set type 1 diameter 0.006")
    assert status == 0, err
    last = {tuple(r["types"]): r for r in got["stages"][-1]["pairs"]}
    rho = 2500 * (0.005 / 0.003) ** 3
    row = last[(1, 1)]
    assert "sizes" not in row, row.get("at")
    assert row["overlap_limit"] == pytest.approx(0.006, rel=1e-12)      # R1 + R2
    engine = _engine(row, [(0.003, rho), (0.003, rho)])
    print(row["eps"][2], engine)
    assert abs(engine[0] / row["eps"][2] - 1) < 1e-6
    stale = _engine(row, [(0.005, 2500.0), (0.005, 2500.0)])[0]
    assert abs(stale / row["eps"][2] - 1) > 1e-3          # the size it had before would be audited wrongly


@needs_lammps
@pytest.mark.dem
def test_atoms_poured_after_the_set_get_the_pours_size_again(tmp_path):
    """The pour still in force: the type holds both, the set's (radius 0.003, mass kept) and the
    pour's (0.005, 2500); a density set after gives every existing atom density 1000. So where the
    runs are not made (--run-budget 0); made, the sizes are those LAMMPS holds
    (test_the_runs_made_hold_what_lammps_holds)."""
    status, got, err = _audit(tmp_path, "", "set type 1 diameter 0.006", "--run-budget", "0")
    assert status == 0, err
    rows = [r for r in got["stages"][-1]["pairs"] if r["types"] == [1, 1]]
    at = sorted({tuple(s) for r in rows for s in r["at"]})
    assert at == [(0.003, pytest.approx(2500 * (0.005 / 0.003) ** 3, rel=1e-9)), (0.005, 2500.0)], at
    # field test r10 (f04): a pour that has made all its atoms makes no more, and the audit cannot
    # tell whether it has: the pour's own size is marked as holding only if it has not finished
    assert [r.get("if_poured") for r in rows if [0.005, 2500.0] in r["at"]] == [["p"]], rows
    assert [r.get("if_poured") for r in rows if [0.005, 2500.0] not in r["at"]] == [None]
    assert "spheres of radius 0.005 density 2500 exist only if fix p had not finished inserting" in err, err
    for r in rows:
        engine = _engine(r, r["at"])
        print(r["at"], r["eps"][2], engine)
        assert abs(engine[0] / r["eps"][2] - 1) < 1e-6
    status, got, err = _audit(tmp_path, "", "set type 1 diameter 0.006\nrun 100\nunfix p\nset type 1 density 1000",
                              "--run-budget", "0")
    assert status == 0, err
    rows = [r for r in got["stages"][-1]["pairs"] if r["types"] == [1, 1]]
    assert sorted({tuple(s) for r in rows for s in r["at"]}) == [(0.003, 1000.0), (0.005, 1000.0)]
    # those the pour made in the run after the first set, if it had not finished, are still in doubt
    assert [r.get("if_poured") for r in rows if [0.005, 1000.0] in r["at"]] == [["p"]], rows


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("set_", ["set region ins diameter 0.006", "set region ins type 2 diameter 0.006"])
def test_a_set_the_reader_cannot_follow_on_poured_atoms_is_refused(tmp_path, set_):
    """Which poured atoms a region holds resized, moved to another type or not: refused in one line
    where the runs are not made (poured atoms moved to another type alone are read:
    test_dem_deck_set_type_after_pour.py); made, the sizes are those LAMMPS holds
    (test_the_runs_made_hold_what_lammps_holds)."""
    status, got, err = _audit(tmp_path, "unfix p\n", set_, "--run-budget", "0")
    assert status == 2 and got is None, err
    # (by region after a run: the atoms the run left there, which no pass knows, field test r11)
    assert len(err.strip().splitlines()) == 1 and "where the run left them (region ins)" in err, err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("between, set_", [("", "set type 1 diameter 0.006"),
                                           ("unfix p\n", "set region ins diameter 0.006"),
                                           ("unfix p\n", "set region ins type 2 diameter 0.006")])
def test_the_runs_made_hold_what_lammps_holds(tmp_path, between, set_):
    """A pour that may have finished before a set, or a set by region after it: LAMMPS makes the
    runs, and the last stage's types and sizes are those LAMMPS holds at the deck's end (run to it
    here), each row's eps LAMMPS' own head-on, no row marked ``if_poured``."""
    status, got, err = _audit(tmp_path, between, set_)
    assert status == 0 and "for real" in err, err
    held = lammps_held_at_end(tmp_path / "in.deck")
    rows = got["stages"][-1]["pairs"]
    seen: dict = {}
    for r in rows:
        assert not r.get("if_poured") and not r.get("may_differ"), r
        for t, at in zip(r["types"], r.get("at") or [None, None]):
            seen.setdefault(t, set()).add(None if at is None else tuple(at))
    for t, sizes in held.items():
        # a row's ends are among the sizes LAMMPS holds, and a type of one size is that size
        ends = {s for s in seen[t] if s is not None}
        assert all(any(s == pytest.approx(h, rel=1e-9) for h in sizes) for s in ends), (t, ends, sizes)
        assert ends or len(sizes) == 1, (t, sizes)
    for r in rows:
        at = r.get("at") or [next(iter(held[t])) for t in r["types"]]
        engine = _engine(r, at)
        print(r["types"], at, r["eps"][2], engine)
        assert abs(engine[0] / r["eps"][2] - 1) < 1e-6


@needs_lammps
@pytest.mark.dem
def test_a_set_of_velocities_on_a_region_leaves_the_poured_sizes_known(tmp_path):
    """Which poured atoms a region holds does not matter where the set sizes none of them (before:
    refused as though it resized them)."""
    status, got, err = _audit(tmp_path, "unfix p\n", "set region ins vx 0 omega 0 0 0")
    assert status == 0, err
    row = {tuple(r["types"]): r for r in got["stages"][-1]["pairs"]}[(1, 1)]
    assert "at" not in row and row["overlap_limit"] == pytest.approx(0.01, rel=1e-12)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("args", [[], ["--run-budget", "0"]])
def test_a_pour_unfixed_before_a_set_leaves_no_size_in_doubt(tmp_path, args):
    """Field round 13 (a26, a37): pour, run, ``unfix``, ``set type 1 density 1000``: the set
    resizes every atom the pour made, whether or not it had finished (here it has not: 400 asked,
    fewer made in 100 steps), so the stage after it holds one size. Before, an empty entry of the
    pour's sizes in doubt made the runs for real, with the false cause "whose sizes include a
    pour's own only if it has not finished", and under ``--run-budget 0`` the same rows stood
    without it: now neither run makes the runs, no row is marked, and each eps is LAMMPS' own at
    the sizes LAMMPS holds at the deck's end."""
    status, got, err = _audit(tmp_path, "unfix p\n", "set type 1 density 1000", *args)
    assert status == 0, err
    assert "for real" not in err and "pour's own" not in err and "not finished" not in err, err
    held = lammps_held_at_end(tmp_path / "in.deck")
    assert [(r, pytest.approx(rho, rel=1e-12)) for r, rho in held[1]] == [(0.005, 1000.0)], held
    rows = {tuple(r["types"]): r for r in got["stages"][-1]["pairs"]}
    assert sorted(rows) == [(1, 1), (1, 2), (2, 2)], rows
    for types, r in rows.items():
        assert not r.get("if_poured") and not r.get("may_differ") and "at" not in r, r
        engine = _engine(r, [next(iter(held[t])) for t in types])
        print(types, r["eps"][2], engine)
        assert abs(engine[0] / r["eps"][2] - 1) < 1e-6

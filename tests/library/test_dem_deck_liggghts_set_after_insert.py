"""A ``set type T diameter|density|mass`` after a LIGGGHTS insertion's run (insert/rate/region of a
sphere template): the engine's pass runs each run for one step, so the atoms inserted after that
step never exist there, and the audit kept the template's size for them. Measured in LIGGGHTS 3.8.0
(template radius 0.005, density 2500, insertion from step 500 of a 1000-step run, 120 atoms, then
``set type 1 diameter 0.006``): the 120 have radius 0.003 and mass 2.82743e-4, the template's density
at the new radius (LAMMPS keeps the mass instead); atoms inserted after the set get the template's
size again; ``set ... density`` gives the mass of that density at the atom's radius; ``set ... mass``
sets the mass and leaves LIGGGHTS' per-atom density as it was, which a later ``diameter`` reads
(mass 1e-3, then diameter 0.006: mass 1000 * V(0.003), 1000 the density set before).

hooke/stiffness makes eps size dependent (kn / m): 0.76294 at the template's size, 0.88216 at the
set's."""

import json
import math
import subprocess

import pytest

from deck_cli import LIGGGHTS_BOX, needs_liggghts, run
from restitution.dem.engines.liggghts import run as liggghts_run
from restitution.dem.engines.liggghts.contact import liggghts_stiffness_contact
from restitution.dem.pair import Pair

#: kn, kt, gamman, gammat and friction, the same for every pair of types
VALUES = [("kn", 2000), ("kt", 1000), ("gamman", 300), ("gammat", 100), ("coefficientFriction", 0.3)]


def materials(n: int) -> str:
    return "".join(f"fix p{k} all property/global {name} peratomtypepair {n}{f' {v}' * n * n}\n"
                   for k, (name, v) in enumerate(VALUES))


STYLE = "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
DECK = LIGGGHTS_BOX + materials(2) + STYLE + """timestep 1e-5
fix gr all gravity 9.81 vector 0 0 -1
fix pts all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.005
fix pdd all particledistribution/discrete 32452843 1 pts 1.0
region ins block -0.04 0.04 -0.04 0.04 0.05 0.09 units box
create_atoms 2 single 0 0 0.01 units box
set type 2 diameter 0.004 density 3000
fix integr all nve/sphere
fix ins all insert/rate/region seed 86028157 distributiontemplate pdd nparticles 200 particlerate 20000 \
insert_every 100 start 500 overlapcheck yes vel constant 0 0 -0.5 region ins ntry_mc 10000
run 1000
{between}{set}
run 1000
"""
#: The contact of two type-1 spheres, as LIGGGHTS' head-on runs take it (one type: every entry of
#: the deck's matrices is the same)
LINES = "create_box 1 box\n" + materials(1) + STYLE


def _audit(tmp_path, between: str, set_: str, *args):
    (tmp_path / "in.deck").write_text(DECK.format(between=between, set=set_))
    status, out, err = run(tmp_path / "in.deck", "--g", "0.5", "--json", *args)
    return status, (json.loads(out) if status == 0 else None), err


def _liggghts_sizes(tmp_path, between: str, set_: str) -> set:
    """The (radius, density) of the type-1 atoms LIGGGHTS holds at the deck's end, the runs run."""
    folder = tmp_path / "engine"
    folder.mkdir()
    (folder / "in.deck").write_text(DECK.format(between=between, set=set_) + "write_dump all custom atoms "
                                    'type radius mass modify format "%d %.17g %.17g"\n')
    subprocess.run(["liggghts", "-in", "in.deck", "-echo", "none", "-log", "none", "-nocite"], cwd=folder,
                   capture_output=True, check=True, stdin=subprocess.DEVNULL)
    rows = [ln.split() for ln in (folder / "atoms").read_text().splitlines()[9:]]
    return {(float(r), float(f"{float(m) / (4 / 3 * math.pi * float(r) ** 3):.9g}")) for t, r, m in rows if t == "1"}


def _engine(r, size, other=None):
    """LIGGGHTS' own eps for the row's pair at ``size`` and ``other`` (radius, density; ``other``
    the same where not given), head-on, 4000, 8000 and
    16000 steps per contact, extrapolated to dt -> 0."""
    other = other or size
    g, pair = r["speeds"][2], Pair.spheres(size[0], other[0], size[1], other[1])
    # the run's length only: the contact time of the law at that size
    t_c = liggghts_stiffness_contact(pair, model="hooke/stiffness", kn=2000.0, gamman=300.0, absolute_damping=False,
                                     limit_force=False).contact_time(g)
    return liggghts_run.liggghts_eps_extrapolated(pair, LINES, [g], {g: t_c}, r["gamma"], steps=4000)[g]


@needs_liggghts
@pytest.mark.dem
def test_a_set_after_the_insertion_ran_resizes_the_inserted_atoms(tmp_path):
    """Before: type 1 audited at the template's radius 0.005 (eps 0.76294, exit 0). The insertion
    unfixed, the type's atoms are the 120 the set resized: radius 0.003 at density 2500."""
    status, got, err = _audit(tmp_path, "unfix ins\n", "set type 1 diameter 0.006")
    assert status == 0, err
    assert _liggghts_sizes(tmp_path, "unfix ins\n", "set type 1 diameter 0.006") == {(0.003, 2500.0)}
    row = {tuple(r["types"]): r for r in got["stages"][-1]["pairs"]}[(1, 1)]
    assert "at" not in row and row["overlap_limit"] == pytest.approx(0.006, rel=1e-12)
    engine = _engine(row, (0.003, 2500.0))
    print(row["eps"][2], engine)
    assert abs(engine[0] / row["eps"][2] - 1) < 1e-6
    stale = _engine(row, (0.005, 2500.0))[0]
    assert abs(stale / row["eps"][2] - 1) > 1e-3          # the template's size would be audited wrongly


#: The insertion still in force at a set: the type holds the set's size and the template's; a
#: density set after gives each atom the mass of that density at its own radius
AFTER = [("set type 1 diameter 0.006", {(0.003, 2500.0), (0.005, 2500.0)}),
         ("set type 1 diameter 0.006\nrun 1000\nunfix ins\nset type 1 density 1000", {(0.003, 1000.0), (0.005, 1000.0)})]


@needs_liggghts
@pytest.mark.dem
@pytest.mark.parametrize("set_, sizes", AFTER, ids=["diameter", "then density"])
def test_atoms_inserted_after_the_set_get_the_templates_size_again(tmp_path, set_, sizes):
    """Each pair of the type's sizes audited as LIGGGHTS gives it."""
    status, got, err = _audit(tmp_path, "", set_)
    assert status == 0, err
    held = _liggghts_sizes(tmp_path, "", set_)
    assert held == sizes
    rows = [r for r in got["stages"][-1]["pairs"] if r["types"] == [1, 1]]
    assert {tuple(s) for r in rows for s in r["at"]} == held
    for r in rows:
        engine = _engine(r, *r["at"])
        print(r["at"], r["eps"][2], engine)
        assert abs(engine[0] / r["eps"][2] - 1) < 1e-6


@needs_liggghts
@pytest.mark.dem
@pytest.mark.parametrize("set_", ["set type 1 mass 0.001", "set region ins diameter 0.006"])
def test_a_set_the_reader_does_not_follow_on_inserted_atoms_is_refused(tmp_path, set_):
    """A mass (LIGGGHTS keeps a density beside it that a later diameter reads), or which inserted
    atoms a region holds: refused in one line; the second where LIGGGHTS does not make the runs
    (--run-budget 0); made, the atoms it holds are audited."""
    status, got, err = _audit(tmp_path, "unfix ins\n", set_, "--run-budget", "0")
    assert status == 2 and got is None, err
    # (by region after a run: the atoms the run left there, which no pass knows, field test r11)
    said = "where the run left them (region ins)" if "region" in set_ else "insertions"
    assert len(err.strip().splitlines()) == 1 and said in err, err
    if "region" not in set_:
        return
    status, got, err = _audit(tmp_path, "unfix ins\n", set_)
    assert status == 0 and "LIGGGHTS made the deck's 2 runs" in err, err
    held = _liggghts_sizes(tmp_path, "unfix ins\n", set_)
    rows = [r for r in got["stages"][-1]["pairs"] if r["types"] == [1, 1]]
    # (the spheres the run left in the region resized, those that had left it not)
    assert {tuple(s) for r in rows for s in r.get("at") or []} == held, (held, rows)
    for r in rows:
        for size in r.get("at") or [next(iter(held))] * 2:
            assert any(size[0] == h[0] and size[1] == pytest.approx(h[1], rel=1e-8) for h in held), (size, held)
        engine = _engine(r, *(r.get("at") or [next(iter(held))] * 2))
        print(r.get("at"), r["eps"][2], engine)
        assert abs(engine[0] / r["eps"][2] - 1) < 1e-6


@needs_liggghts
@pytest.mark.dem
def test_runs_whose_length_a_variable_gives_are_made_for_real(tmp_path):
    """``run ${n}`` with n = 1000.4: LIGGGHTS runs 1000 steps (it reads a length by its leading
    digits). Before, the length was the deck's unsubstituted text, "not a number", and the runs
    the set by region needs were not made (field round 15, R01)."""
    deck = DECK.format(between="unfix ins\n", set="set region ins diameter 0.006").replace(
        "timestep 1e-5\n", "timestep 1e-5\nvariable n equal 2000.8/2\n").replace("run 1000\n", "run ${n}\n")
    (tmp_path / "in.deck").write_text(deck)
    status, out, err = run(tmp_path / "in.deck", "--g", "0.5", "--json")
    assert status == 0 and "LIGGGHTS made the deck's 2 runs (2000 steps)" in err, err
    assert "not a number" not in err
    rows = [r for r in json.loads(out)["stages"][-1]["pairs"] if r["types"] == [1, 1]]
    assert rows and all(r["eps"] for r in rows)

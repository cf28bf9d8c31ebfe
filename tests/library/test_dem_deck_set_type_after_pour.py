"""A ``set ... type/fraction|type/ratio|type/subset|type`` after a fix pour's run (field round 9,
c03): LAMMPS moves some (or all) of the atoms the pour made in the runs before to another type;
the engine's pass (its runs skipped) never made them. Before, the audit said their size was not
known (exit 2) where the pour was the only source of atoms. The poured atoms of the set's types
may become the new type: both types get the pour's sizes. Measured in LAMMPS 22 Jul 2025 on the
deck below: 269 atoms poured, after ``set type 1 type/fraction 2 0.5 5678`` 144 of type 1 and 125
of type 2, every one of radius 0.005 and mass 0.0013089969 (density 2500)."""

import json

import pytest

from deck_cli import lammps_pour, needs_lammps, run
from restitution.dem.contact import Contact
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.pair import Pair

LINES = {(1, 1): "pair_coeff 1 1 hertz 1e6 300 damping mass_velocity tangential linear_nohistory 1 0.3",
         (1, 2): "pair_coeff 1 2 hertz 2e6 200 damping mass_velocity tangential linear_nohistory 1 0.3",
         (2, 2): "pair_coeff 2 2 hertz 4e6 100 damping mass_velocity tangential linear_nohistory 1 0.3"}
DECK = lammps_pour("\n".join(LINES.values()), ntypes=2, sphere=None) + """timestep 1e-5
run 100
unfix p
{set}
run 100
"""


def _audit(tmp_path, set_: str):
    (tmp_path / "in.deck").write_text(DECK.format(set=set_))
    status, out, err = run(tmp_path / "in.deck", "--g", "0.5", "--json")
    return status, (json.loads(out) if status == 0 else None), err


def _engine(r, types):
    """LAMMPS' own eps for the row's pair, both spheres the pour's (radius 0.005, density 2500)."""
    g = r["speeds"][2]
    t_c = Contact(r["alpha"], r["gamma"], r["D1"], r["D2"], r["end"]).contact_time(g)
    line = LINES[types].replace(f"pair_coeff {types[0]} {types[1]}", "pair_coeff * *")
    return lammps_run.lammps_eps_extrapolated(Pair.spheres(0.005, 0.005, 2500.0), line, g, t_c)[0]


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("set_", ["set type 1 type/fraction 2 0.5 5678", "set type 1 type/ratio 2 0.5 5678",
                                  "set group all type/subset 2 100 5678"])
def test_poured_atoms_that_may_change_type_give_both_types_the_pours_size(tmp_path, set_):
    """Before: exit 2, "their size is not known". Every pair of types 1 and 2 audited at the pour's
    sphere, each eps LAMMPS' own for that pair's coefficients."""
    status, got, err = _audit(tmp_path, set_)
    assert status == 0, err
    rows = {tuple(r["types"]): r for r in got["stages"][-1]["pairs"]}
    assert sorted(rows) == [(1, 1), (1, 2), (2, 2)], err
    for types, r in rows.items():
        assert "at" not in r and r["overlap_limit"] == pytest.approx(0.01, rel=1e-12)
        if set_.endswith("type/fraction 2 0.5 5678"):
            engine = _engine(r, types)
            print(types, r["eps"][2], engine)
            assert abs(engine / r["eps"][2] - 1) < 1e-6


@needs_lammps
@pytest.mark.dem
def test_poured_atoms_all_moved_leave_their_type_without_them(tmp_path):
    """``set type 1 type 2``: every poured atom becomes type 2, the pour unfixed: type 1 holds none,
    so its pairs cannot happen; 2 2 at the pour's sphere."""
    status, got, err = _audit(tmp_path, "set type 1 type 2")
    assert status == 0, err
    rows = {tuple(r["types"]): r for r in got["stages"][-1]["pairs"]}
    assert sorted(rows) == [(2, 2)], err
    assert rows[(2, 2)]["overlap_limit"] == pytest.approx(0.01, rel=1e-12)

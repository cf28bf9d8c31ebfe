"""A LAMMPS ``fix pour ... mol TEMPLATE`` whose molecule template holds one atom pours single spheres
of the template's diameter and mass (field test: refused as rigid clumps though LAMMPS pours spheres).
LAMMPS ignores the pour's diam and dens then, and gives the atom density 1 where the template has no
Masses section (measured in LAMMPS 22 Jul 2025). Each eps is checked in LAMMPS, head-on, dt -> 0."""

import json
import math

import pytest

from deck_cli import needs_lammps, run
from restitution.dem.contact import Contact
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.pair import Pair

#: a law whose eps depends on the spheres' masses and radii
HERTZ = "gran/hertz/history 1e6 NULL 3000 NULL 0.5 0"


def _deck(tmp_path, template: str, offset: int = 0, more: dict | None = None) -> list:
    (tmp_path / "one.mol").write_text(template)
    for name, text in (more or {}).items():
        (tmp_path / name).write_text(text)
    files = " ".join(["one.mol", *(more or {})])
    (tmp_path / "in.deck").write_text(f"""units si
atom_style sphere
comm_modify vel yes
region box block 0 1 0 1 0 1
create_box 2 box
molecule m1 {files}
pair_style {HERTZ}
pair_coeff * *
region slab block 0.1 0.9 0.1 0.9 0.5 0.9
fix ins all pour 20 {offset} 4767 region slab mol m1 diam one 0.05 dens 500 500{" molfrac 0.5 0.5" if more else ""}
fix 1 all nve/sphere
fix g all gravity 9.81 vector 0 0 -1
timestep 1e-6
run 10
""")
    return run(tmp_path / "in.deck", "--g", "1.0", "--json")


def _in_lammps(row: dict, radius: float, density: float) -> float:
    t_c = Contact(row["alpha"], row["gamma"], row["D1"], row["D2"], row["end"]).contact_time(1.0)
    return lammps_run.lammps_eps_extrapolated(Pair.spheres(radius, radius, density, density), "pair_coeff * *",
                                              1.0, t_c, style=HERTZ)[0]


def _one(diameter: float, mass: float | None) -> str:
    text = f"# one sphere\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 {diameter}\n"
    return text + (f"\nMasses\n\n1 {mass}\n" if mass is not None else "")


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("mass, density, offset", [(4 / 3 * math.pi * 0.01 ** 3 * 3000, 3000.0, 0),
                                                   (None, 1.0, 1)])
def test_a_pour_of_a_one_atom_template_is_audited_at_its_size(tmp_path, mass, density, offset):
    """Before: refused ("rigid clumps"). The pour's diam 0.05 and dens 500 are not the spheres'."""
    status, out, err = _deck(tmp_path, _one(0.02, mass), offset)
    assert status == 0, err
    rows = json.loads(out)["pairs"]
    assert [r["types"] for r in rows] == [[1 + offset, 1 + offset]]
    engine = _in_lammps(rows[0], 0.01, density)
    print(rows[0]["eps"][2], engine)
    assert abs(engine / rows[0]["eps"][2] - 1) < 1e-6


TWO = "# two spheres\n2 atoms\n{tie}\nCoords\n\n1 0 0 0\n2 0.03 0 0\n\nTypes\n\n1 1\n2 2\n\nDiameters\n\n1 0.02\n2 0.01\n"


@needs_lammps
@pytest.mark.dem
def test_a_pour_of_a_template_of_untied_atoms_pours_each_as_a_sphere(tmp_path):
    """Field round 46, I03: refused as clumps, where LAMMPS pours each atom of a template that no
    bond ties (and no rigid or shake keyword) as a free sphere: here types 1 and 2, of their sizes."""
    status, out, err = _deck(tmp_path, TWO.format(tie=""))
    assert status == 0, err
    rows = {tuple(r["types"]): r for r in json.loads(out)["pairs"]}
    assert sorted(rows) == [(1, 1), (1, 2), (2, 2)], rows
    engine = _in_lammps(rows[(1, 1)], 0.01, 1.0)
    assert abs(engine / rows[(1, 1)]["eps"][2] - 1) < 1e-6


@needs_lammps
@pytest.mark.dem
def test_a_pour_of_a_bonded_template_stays_refused(tmp_path):
    status, out, err = _deck(tmp_path, TWO.format(tie="1 bonds\n"))
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and "holds 2 atoms, tied" in err, err


@needs_lammps
@pytest.mark.dem
def test_a_pour_of_a_set_of_one_atom_templates_is_audited_over_its_sizes(tmp_path):
    """Field test r7: ``molecule grains small.mol big.mol`` poured with molfrac was refused ("several
    files or keywords"); LAMMPS pours spheres of both templates' sizes into type 1. The range's ends
    are the two same-size pairs, each checked in LAMMPS head-on (dt -> 0)."""
    heavy = 4 / 3 * math.pi * 0.015 ** 3 * 2000
    status, out, err = _deck(tmp_path, _one(0.02, 4 / 3 * math.pi * 0.01 ** 3 * 3000),
                             more={"big.mol": _one(0.03, heavy)})
    assert status == 0, err
    rows = json.loads(out)["pairs"]
    ends = sorted((a[0], round(a[1], 9), b[0], round(b[1], 9)) for a, b in (r["at"] for r in rows))
    assert ends == [(0.01, 3000.0, 0.01, 3000.0), (0.015, 2000.0, 0.015, 2000.0)]
    for row in rows:
        (radius, density), _ = row["at"]
        assert abs(_in_lammps(row, radius, density) / row["eps"][2] - 1) < 1e-6, row

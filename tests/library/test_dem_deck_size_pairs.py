"""A type of several sizes gives each pair the range of eps over the sizes present, with the spheres
at its ends. A size with itself is an end only where two spheres of it can meet: a type holding one
atom of radius 0.003 and two of 0.005 (hertz with mass_velocity damping, whose eps grows as the
spheres shrink) had its largest-eps end at 0.003 against 0.003 (0.76526 at g = 0.5, exit 0), a contact
that cannot happen; the largest is 0.003 against 0.005 (0.73052, LAMMPS head-on 0.73052). Where a
pour keeps making that size, two spheres of it meet, and the end stays."""

import pytest

from deck_cli import agrees_with_lammps, audit, needs_lammps, run

LINE = "pair_coeff * * hertz 1e6 300 damping mass_velocity tangential linear_nohistory 1 0.3"
DECK = f"""units si
atom_style sphere
comm_modify vel yes
region box block -1 1 -1 1 -1 1
create_box 1 box
create_atoms 1 single 0 0 0
create_atoms 1 single 0.5 0 0
create_atoms 1 single -0.5 0 0
set type 1 diameter 0.01 density 2500
set atom 1 diameter 0.006 density 2500
fix integrate all nve/sphere
pair_style granular
{LINE}
{{pour}}timestep 1e-6
run 100
"""
POUR = """region ins block -1 1 -1 1 0.5 1
fix g all gravity 9.81 vector 0 0 -1
fix p all pour 10 1 123 region ins diam one 0.006 dens 2500 2500
"""


def _rows(tmp_path, pour: str = ""):
    (tmp_path / "in.deck").write_text(DECK.format(pour=pour))
    got, _ = audit(tmp_path / "in.deck", "--g", "0.5")
    return got["pairs"]


@needs_lammps
@pytest.mark.dem
def test_a_size_one_atom_alone_has_meets_only_the_others(tmp_path):
    rows = _rows(tmp_path)
    assert [(r["sizes"], r["at"]) for r in rows] == [
        ("smallest eps", [[0.005, 2500.0], [0.005, 2500.0]]), ("largest eps", [[0.003, 2500.0], [0.005, 2500.0]])]
    for r in rows:
        (a, b) = r["at"]
        agrees_with_lammps([{**r, "types": [1, 2]}], {1: tuple(a), 2: tuple(b)}, LINE, 2)


@needs_lammps
@pytest.mark.dem
def test_a_size_a_pour_keeps_making_meets_itself(tmp_path):
    rows = _rows(tmp_path, POUR)
    assert [r["at"] for r in rows] == [[[0.005, 2500.0], [0.005, 2500.0]], [[0.003, 2500.0], [0.003, 2500.0]]]


@needs_lammps
@pytest.mark.dem
def test_a_type_of_one_sphere_of_each_of_two_sizes_meets_at_those_two_alone(tmp_path):
    """Before: 0.003 against 0.003 and 0.005 against 0.005, neither of which can happen."""
    (tmp_path / "in.deck").write_text(DECK.format(pour="").replace("create_atoms 1 single -0.5 0 0\n", ""))
    status, out, err = run(tmp_path / "in.deck", "--g", "0.5")
    assert status == 0, err
    assert "types 1 1 (spheres of several sizes, of which only these meet: radius 0.003 density 2500 and radius " \
           "0.005 density 2500)" in out, out
    got, _ = audit(tmp_path / "in.deck", "--g", "0.5")
    (row,) = got["pairs"]
    assert row["sizes"] == "only" and row["eps"][2] == pytest.approx(0.7305232343, rel=1e-9)

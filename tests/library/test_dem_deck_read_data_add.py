"""``read_data FILE add append offset toff ... shift ...`` (field round 9, b10): LAMMPS adds the
file's atoms to those held, their types moved up by toff (and the file's pair coefficients with
them). Before, refused ("read_data option add is not mapped"). The audit reads the atoms from the
engine at each run, and the coefficients with the offset applied."""

import pytest

from deck_cli import agrees_with_lammps, audit, needs_lammps

DATA = """LAMMPS data file

2 atoms
1 atom types

-0.1 0.1 xlo xhi
-0.1 0.1 ylo yhi
-0.1 0.1 zlo zhi
{coeffs}
Atoms # sphere

1 1 {d} 2500 0 0 0
2 1 {d} 2500 0 0 0.05
"""
HM = "pair_coeff * * hertz/material 1e7 1.1e6 0.3 damping viscoelastic tangential linear_nohistory 0 0"
HOOKE = "hooke 1e5 2.0 damping velocity tangential linear_nohistory 0 0"
START = "units si\natom_style sphere\natom_modify map array\nboundary f f f\ncomm_modify vel yes\n"


@needs_lammps
@pytest.mark.dem
def test_atoms_read_with_a_type_offset_are_audited(tmp_path):
    """The field deck's shape: one file read twice, the second time as type 2, 0.05 aside."""
    (tmp_path / "data.a").write_text(DATA.format(coeffs="", d=0.01))
    (tmp_path / "in.deck").write_text(START + "read_data data.a extra/atom/types 1\n"
                                      "read_data data.a add append offset 1 0 0 0 0 shift 0.05 0 0\n"
                                      f"pair_style granular\n{HM}\npair_coeff 2 2 {HOOKE}\n"
                                      "fix 1 all nve/sphere\ntimestep 1e-6\nrun 100\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    rows = {tuple(r["types"]): r for r in got["pairs"]}
    assert sorted(rows) == [(1, 1), (1, 2), (2, 2)], err
    agrees_with_lammps([rows[(1, 1)], rows[(1, 2)]], {1: (0.005, 2500.0), 2: (0.005, 2500.0)}, HM, 2)
    agrees_with_lammps([rows[(2, 2)]], {2: (0.005, 2500.0)}, f"pair_coeff * * {HOOKE}", 2)


@needs_lammps
@pytest.mark.dem
def test_a_data_files_coefficients_move_with_its_types(tmp_path):
    """The added file's Pair Coeffs for its type 1 set the deck's type 2 (offset 1)."""
    (tmp_path / "data.a").write_text(DATA.format(coeffs="", d=0.01))
    (tmp_path / "data.b").write_text(DATA.format(coeffs=f"\nPair Coeffs # granular\n\n1 {HOOKE}\n", d=0.008))
    (tmp_path / "in.deck").write_text(START + "read_data data.a extra/atom/types 1\n"
                                      f"pair_style granular\n{HM}\n"
                                      "read_data data.b add append offset 1 0 0 0 0 shift 0.05 0 0\n"
                                      "fix 1 all nve/sphere\ntimestep 1e-6\nrun 100\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    rows = {tuple(r["types"]): r for r in got["pairs"]}
    assert sorted(rows) == [(1, 1), (1, 2), (2, 2)], err
    assert rows[(2, 2)]["model"].startswith("LAMMPS hooke") and rows[(1, 1)]["model"].startswith("LAMMPS hertz")
    agrees_with_lammps([rows[(2, 2)]], {2: (0.004, 2500.0)}, f"pair_coeff * * {HOOKE}", 2)

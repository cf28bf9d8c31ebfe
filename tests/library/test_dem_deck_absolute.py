"""A file the deck names by an absolute path (a cluster's parameter file, a shared data file): the
audit copies it into its scratch, makes it safe as it makes the deck's folder, and the engine reads
the copy (field round 8: refused, "copy the file beside the deck", though the same file reached by
../ was followed and LAMMPS runs the deck)."""

import pytest

from deck_cli import agrees_with_lammps, audit, lammps_spheres, needs_lammps

LINE = "pair_coeff * * hooke 1000.0 0.7 damping coeff_restitution tangential linear_nohistory 0 0"


@needs_lammps
@pytest.mark.dem
def test_an_include_by_absolute_path_is_read_made_safe(tmp_path):
    shared, case = tmp_path / "shared", tmp_path / "case"
    shared.mkdir(), case.mkdir()
    touched = tmp_path / "TOUCHED"
    (shared / "materials.in").write_text(f"shell touch {touched}\n{LINE}\n")
    (case / "in.deck").write_text(lammps_spheres((0.004, 2500.0)) + f"include {shared / 'materials.in'}\n"
                                  "timestep 1e-6\nrun 10\n")
    got, err = audit(case / "in.deck", "--g", "1")
    (row,) = got["pairs"]
    assert row["typed_e"] == 0.7 and row["file"] == str(shared / "materials.in") and row["line"] == 2
    agrees_with_lammps(got["pairs"], {1: (0.002, 2500.0)}, LINE, 1)
    assert not touched.exists() and "shell" in err
    assert sorted(p.name for p in tmp_path.rglob("*")) == ["case", "in.deck", "materials.in", "shared"]


@needs_lammps
@pytest.mark.dem
def test_a_data_file_by_absolute_path_is_read(tmp_path):
    shared, case = tmp_path / "shared", tmp_path / "case"
    shared.mkdir(), case.mkdir()
    (shared / "spheres.data").write_text("spheres\n\n2 atoms\n1 atom types\n-1 1 xlo xhi\n-1 1 ylo yhi\n"
                                         "-1 1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.006 2000 0 0 0\n"
                                         "2 1 0.006 2000 0.5 0 0\n")
    (case / "in.deck").write_text(f"units si\natom_style sphere\ncomm_modify vel yes\n"
                                  f"read_data {shared / 'spheres.data'}\nfix integrate all nve/sphere\n"
                                  f"pair_style granular\n{LINE.replace('hooke 1000.0 0.7 damping coeff_restitution', 'hooke 1000.0 0.3 damping viscoelastic')}\n"
                                  "timestep 1e-6\nrun 10\n")
    got, err = audit(case / "in.deck", "--g", "1")
    agrees_with_lammps(got["pairs"], {1: (0.003, 2000.0)},
                       LINE.replace("hooke 1000.0 0.7 damping coeff_restitution", "hooke 1000.0 0.3 damping viscoelastic"),
                       1)


@needs_lammps
@pytest.mark.dem
def test_a_file_by_absolute_path_named_in_a_variable_gives_its_coefficients(tmp_path):
    """variable f string /abs/materials.in, then include ${f}: the copy's lines are known as that
    file's, by their text."""
    shared, case = tmp_path / "shared", tmp_path / "case"
    shared.mkdir(), case.mkdir()
    (shared / "materials.in").write_text(f"{LINE}\n")
    (case / "in.deck").write_text(lammps_spheres((0.004, 2500.0)) + f"variable f string {shared / 'materials.in'}\n"
                                  "include ${f}\ntimestep 1e-6\nrun 10\n")
    got, err = audit(case / "in.deck", "--g", "1")
    (row,) = got["pairs"]
    assert row["typed_e"] == 0.7 and row["file"] == str(shared / "materials.in")


@needs_lammps
@pytest.mark.dem
def test_an_absolute_name_with_two_spaces_is_read_as_the_engine_opens_it(tmp_path):
    """variable k file "/abs/k  v.txt": the scan for absolute names split it at whitespace, so the
    file was not copied and the confined engine stopped (an avoidable refusal, its message showing
    the name with one space). The name is one word, spaces kept: its copy is read, not the decoy
    of one space beside it."""
    shared, case = tmp_path / "shared  dir", tmp_path / "case"
    shared.mkdir(), case.mkdir()
    (shared / "k  v.txt").write_text("0.7\n")
    (shared / "k v.txt").write_text("0.2\n")
    (case / "in.deck").write_text(lammps_spheres((0.004, 2500.0)) + f'variable e file "{shared / "k  v.txt"}"\n'
                                  + LINE.replace("0.7", "${e}") + "\ntimestep 1e-6\nrun 10\n")
    got, err = audit(case / "in.deck", "--g", "1")
    (row,) = got["pairs"]
    assert row["typed_e"] == 0.7
    agrees_with_lammps(got["pairs"], {1: (0.002, 2500.0)}, LINE, 1)


@needs_lammps
@pytest.mark.dem
def test_a_data_file_written_and_read_at_an_absolute_name_with_spaces_is_read_back(tmp_path):
    """write_data "/abs/o  x.data", then read_data of it: the write was redirected into the scratch
    under the name cut at its first space, an unclosed quote the engine stopped on. The file is
    written in the scratch and read back from there; nothing is written at the path."""
    outside, case = tmp_path / "out  dir" / "o  x.data", tmp_path / "case"
    case.mkdir()
    (case / "in.deck").write_text(lammps_spheres((0.004, 2500.0)) + LINE + "\n"
                                  f'write_data "{outside}"\ndelete_atoms group all\n'
                                  f'read_data "{outside}" add merge\ntimestep 1e-6\nrun 10\n')
    got, err = audit(case / "in.deck", "--g", "1")
    (row,) = got["pairs"]
    assert row["typed_e"] == 0.7
    assert not outside.parent.exists() and sorted(p.name for p in case.iterdir()) == ["in.deck"]


@needs_lammps
@pytest.mark.dem
def test_a_file_above_the_folder_named_with_two_spaces_is_included(tmp_path):
    """include "../m  m.in": the scan of names above the folder split it at whitespace and did not
    copy it, and the check of an include's reach read its first half ('"../m'), a name outside the
    copy: refused, though LAMMPS reads the file. Its coefficient now, not the decoy's of one space."""
    case = tmp_path / "case"
    case.mkdir()
    (tmp_path / "m  m.in").write_text(LINE + "\n")
    (tmp_path / "m m.in").write_text(LINE.replace("0.7", "0.2") + "\n")
    (case / "in.deck").write_text(lammps_spheres((0.004, 2500.0)) + 'include "../m  m.in"\ntimestep 1e-6\nrun 10\n')
    got, err = audit(case / "in.deck", "--g", "1")
    (row,) = got["pairs"]
    assert row["typed_e"] == 0.7
    agrees_with_lammps(got["pairs"], {1: (0.002, 2500.0)}, LINE, 1)


@needs_lammps
@pytest.mark.dem
def test_a_name_that_climbs_back_into_the_folder_is_read_there(tmp_path):
    """include "sub dir/../k  k.in" names a file of the deck's own folder: read as one word, its ..
    was taken for a climb out of the folder and the deck refused (field round 32, Q18)."""
    (tmp_path / "sub dir").mkdir()
    (tmp_path / "k  k.in").write_text(LINE + "\n")
    (tmp_path / "in.deck").write_text(lammps_spheres((0.004, 2500.0)) + 'include "sub dir/../k  k.in"\n'
                                      "timestep 1e-6\nrun 10\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    (row,) = got["pairs"]
    assert row["typed_e"] == 0.7

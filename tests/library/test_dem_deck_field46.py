"""Field round 46's avoidable refusals: the copy made every file of the deck's folder safe line by
line, binary ones and data files too.

- A binary file (a mesh in binary STL) lost bytes where a "line" of it was made safe (Y11: LIGGGHTS
  0.699141, refused as "Corrupt STL file"), and its lone carriage returns refused a deck with an
  ``include ${f}`` (Y08-Y10: LAMMPS 0.413435).
- A molecule template titled ``run 7 template`` had its title made a run's marker (Z04: refused as
  "Unknown run keyword", LAMMPS 0.413435; Z09: a phantom stage)."""

import pytest

from deck_cli import PERIODIC_PAIR, needs_lammps, run

BINARY = b"solid\x00\x00\rrun 7\n$x shell touch made\n" + bytes(range(256))


def audited(folder, deck: str) -> tuple:
    (folder / "in.deck").write_text(deck)
    return run(folder / "in.deck", "--g", "1")


@needs_lammps
@pytest.mark.dem
def test_a_binary_file_the_deck_does_not_run_is_left_as_it_is(tmp_path):
    (tmp_path / "mesh.stl").write_bytes(BINARY)
    (tmp_path / "part.in").write_text("# nothing\n")
    status, out, err = audited(tmp_path, PERIODIC_PAIR.replace("run 1000\n", "variable f string part.in\n"
                                                                              "include ${f}\nrun 1000\n"))
    assert status == 0 and "types 1 2" in out, err
    assert (tmp_path / "mesh.stl").read_bytes() == BINARY and not (tmp_path / "made").exists()


@needs_lammps
@pytest.mark.dem
def test_a_binary_file_the_deck_runs_is_refused(tmp_path):
    (tmp_path / "bin.in").write_bytes(b"# \x00\npair_coeff 1 2 hooke 5000 3000 damping mass_velocity tangential "
                                      b"linear_nohistory 1 0.3\n")
    status, out, err = audited(tmp_path, PERIODIC_PAIR + "include bin.in\nrun 1000\n")
    assert status == 2 and "or a NUL byte (binary)" in err, err


@needs_lammps
@pytest.mark.dem
def test_a_template_titled_like_a_run_is_read_as_a_template(tmp_path):
    (tmp_path / "m1.mol").write_text("run 7 template\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 2\n\nDiameters\n\n"
                                      "1 0.006\n\nMasses\n\n1 2.8274e-4\n")
    deck = PERIODIC_PAIR.replace("run 1000\n", "fix grav all gravity 9.81 vector 0 0 -1\nmolecule m1 m1.mol\nregion pr block 0.002 0.038 0.002 0.038 0.08 "
                                               "0.095 units box\nfix po all pour 2 0 4767 region pr mol m1\nrun 3000\n")
    status, out, err = audited(tmp_path, deck)
    assert status == 0 and "stage" not in err, err
    assert "0.4149158989" in out, out

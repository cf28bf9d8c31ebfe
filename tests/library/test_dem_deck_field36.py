"""Field round 36's SW-MV class, each measured here in LAMMPS 22 Jul 2025 running the deck as written:
a script the engine runs whose lines the audit had not mapped, so their commands came back
untagged and were taken for the engine's own output. The copy maps and makes safe the deck and
the files it names, as the deck's folder holds them when copied; it passed over links and files
over 20 MB, and a ``shell mv`` (which the engine runs, in the copy) puts a file the copy never
mapped in place of a named one. F09: ``shell mv new.in pc.in`` then ``include pc.in`` printed the
law before it (0.4149) where LAMMPS ran its kn 5000 (0.578975); F14, F17: an include of a link; F19:
a 22 MB include. A link to a file is now copied as the file it points to (read where the deck's
folder has it), and the others are refused in one line."""

import os

import pytest

from deck_cli import HEAD_ON, audited_and_measured, lammps_separation_speed, needs_lammps, run

LAW = "hooke {kn} 300 damping mass_velocity tangential linear_nohistory 1 0.3"
BASE = HEAD_ON.format(line=f"pair_coeff * * {LAW.format(kn=1000)}")


def _coeff(kn: int) -> str:
    return f"pair_coeff 1 2 {LAW.format(kn=kn)}\n"


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("outside", [False, True], ids=["in the folder", "outside it"])
def test_an_include_of_a_link_runs_the_file_it_points_to(tmp_path, outside):
    """F14 (the link and its file in the deck's folder) and F15 (a link to ../shared/mat.in: the
    confined engine could not open it, and the deck was refused as one LAMMPS stops on)."""
    folder = tmp_path / "deck"
    shared = tmp_path / "shared" if outside else folder
    folder.mkdir()
    shared.mkdir(exist_ok=True)
    (shared / "real.in").write_text(_coeff(3000))
    os.symlink("../shared/real.in" if outside else "real.in", folder / "link.in")
    deck = BASE + "include link.in\nrun 40000\n"
    eps, measured, err = audited_and_measured(deck, folder)
    assert abs(eps - measured) < 5e-5, (eps, measured, err)
    assert abs(lammps_separation_speed(BASE + "run 40000\n", folder) - measured) > 1e-3
    assert os.path.islink(folder / "link.in")          # the user's link left as it was


@needs_lammps
@pytest.mark.dem
def test_an_include_of_a_file_shell_mv_put_in_place_is_refused(tmp_path):
    """F09: the engine runs the moved file's pair_coeff (measured here: the law differs from the one
    before it), which the audit would not see: refused in one line naming the mv."""
    (tmp_path / "new.in").write_text(_coeff(3000))
    deck = BASE + "shell mv new.in pc.in\ninclude pc.in\nshell mv pc.in new.in\nrun 40000\n"
    assert abs(lammps_separation_speed(deck, tmp_path) - lammps_separation_speed(BASE + "run 40000\n", tmp_path)) > 1e-3
    (tmp_path / "in.deck").write_text(deck)
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert "line 19 (include pc.in): it runs a file that line 18 (shell mv new.in pc.in) names" in err, err
    assert (tmp_path / "new.in").exists() and not (tmp_path / "pc.in").exists()


@needs_lammps
@pytest.mark.dem
def test_a_script_too_big_to_map_is_refused(tmp_path):
    """F19: a 22 MB include (comments, then the pair_coeff) was passed over by the copy's mapping."""
    with open(tmp_path / "big.in", "w") as big:
        big.write(("# " + "x" * 77 + "\n") * (21 * 2 ** 20 // 80 + 1) + _coeff(3000))
    (tmp_path / "in.deck").write_text(BASE + "include big.in\nrun 40000\n")
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and out == "" and "a script the deck runs holds more than 20 MB" in err, err

"""Field round 37's classes around files, each measured here in LAMMPS 22 Jul 2025 running the deck
as written. The copy of the deck's folder holds a link as the file it points to and hard links as
files of their own, so a write or a removal under one name was unseen under the other (SW-LINK,
F03: print ... append real.in, then include link.in: the old real.in's law printed, 0.4921, where
LAMMPS ran kn 5000, 0.578975; F47 through write_restart, read_restart link.rst). A jump was not
among the reads checked against a shell mv or a skipped writer (SW-JUMP, F22), and a script over
20 MB reached through a variable or a link ran unmapped (SW-BIG, F20 F21). Each is refused in one
line now."""

import os

import pytest

from deck_cli import HEAD_ON, lammps_separation_speed, needs_lammps, run

LAW = "hooke {kn} 300 damping mass_velocity tangential linear_nohistory 1 0.3"
BASE = HEAD_ON.format(line=f"pair_coeff * * {LAW.format(kn=1000)}")
NEW = f"pair_coeff 1 2 {LAW.format(kn=5000)}"


def _refused(folder, deck: str, said: str) -> None:
    (folder / "in.deck").write_text(deck)
    status, out, err = run(folder / "in.deck", "--g", "1")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert said in err, err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("link, writer", [("symbolic", f"print '{NEW}' append real.in screen no"),
                                          ("hard", f"print '{NEW}' append real.in screen no"),
                                          ("symbolic", "shell mv new.in real.in")],
                         ids=["a link, print append", "a hard link, print append", "a link, shell mv"])
def test_a_file_read_under_another_name_after_a_write_is_refused(tmp_path, link, writer):
    """F01 F02 F03: the engine reads the rewritten file through the link (measured: another law).
    (A hard link keeps the old file where shell mv puts a new one in place: refused all the same.)"""
    (tmp_path / "real.in").write_text(f"pair_coeff 1 2 {LAW.format(kn=3000)}\n")
    (tmp_path / "new.in").write_text(NEW + "\n")
    (os.symlink if link == "symbolic" else os.link)("real.in" if link == "symbolic" else tmp_path / "real.in",
                                                   tmp_path / "link.in")
    deck = BASE + f"{writer}\ninclude link.in\nrun 40000\n"
    old = BASE + "include link.in\nrun 40000\n"
    engine = tmp_path / "engine"
    engine.mkdir()
    for name in ("real.in", "new.in"):
        (engine / name).write_text((tmp_path / name).read_text())
    (os.symlink if link == "symbolic" else os.link)("real.in" if link == "symbolic" else engine / "real.in",
                                                   engine / "link.in")
    assert abs(lammps_separation_speed(deck, engine) - lammps_separation_speed(old, tmp_path)) > 1e-3
    _refused(tmp_path, deck, "line 19 (include link.in): it r")


@needs_lammps
@pytest.mark.dem
def test_a_jump_to_a_file_shell_mv_put_in_place_is_refused(tmp_path):
    """F22: the jump runs the moved file (its pair_coeff, its run, a jump back)."""
    (tmp_path / "new.in").write_text(f"{NEW}\nrun 40000\njump in.deck back\n")
    _refused(tmp_path, BASE + "shell mv new.in j.in\njump j.in\nlabel back\n",
             "line 19 (jump j.in): it runs a file that line 18 (shell mv new.in j.in) names")


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("how", ["variable", "link"])
def test_a_script_too_big_to_map_reached_by_a_variable_or_a_link_is_refused(tmp_path, how):
    """F20 F21: the size check of the copy looked at scripts named as written only."""
    with open(tmp_path / "big.in", "w") as big:
        big.write(("# " + "x" * 77 + "\n") * (21 * 2 ** 20 // 80 + 1) + NEW + "\n")
    if how == "link":
        os.symlink("big.in", tmp_path / "link.in")
        deck = BASE + "include link.in\nrun 40000\n"
    else:
        deck = BASE + "variable f string big.in\ninclude ${f}\nrun 40000\n"
    _refused(tmp_path, deck, "holds more than 20 MB")

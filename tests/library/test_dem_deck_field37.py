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

from deck_cli import HEAD_ON, audited_and_measured, lammps_separation_speed, needs_lammps, run

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


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("links", [{"a.in": "b.in", "b.in": "a.in"}, {"x.in": "x.in"}], ids=["a loop", "a link to itself"])
def test_a_loop_of_links_no_command_names_is_copied_as_it_is(tmp_path, links):
    """Field round 38, A20 A26: the copy's walk resolved every link and stopped on a loop with a
    traceback ('Symlink loop'); LAMMPS never opens them (0.578975)."""
    for name, target in links.items():
        os.symlink(target, tmp_path / name)
    eps, measured, err = audited_and_measured(BASE + f"{NEW}\nrun 40000\n", tmp_path)
    assert abs(eps - measured) < 5e-5, (eps, measured, err)


@needs_lammps
@pytest.mark.dem
def test_shell_cd_up_with_a_link_in_the_folder_is_audited(tmp_path):
    """Field round 38, A18: shell cd sub, include pc.in, shell cd ..: the copy copies the folder
    above the deck's (named by ..) over its own, and a link copied twice stopped it ('File
    exists'), refused as a folder that changed while copied."""
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "pc.in").write_text(NEW + "\n")
    (tmp_path / "r.in").write_text(NEW + "\n")
    os.symlink("../r.in", tmp_path / "sub" / "other.in")
    eps, measured, err = audited_and_measured(BASE + "shell cd sub\ninclude pc.in\nshell cd ..\nrun 40000\n", tmp_path)
    assert abs(eps - measured) < 5e-5, (eps, measured, err)


@needs_lammps
@pytest.mark.dem
def test_a_name_climbing_back_from_a_folder_shell_cd_entered_is_the_decks_own(tmp_path):
    """Field round 38, A19: shell cd sub, include ../l.in (the deck's own l.in, a link to r.in):
    refused as a file outside the deck's folder; LAMMPS reads it (0.578975)."""
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "keep.txt").write_text("x\n")
    (tmp_path / "r.in").write_text(NEW + "\n")
    os.symlink("r.in", tmp_path / "l.in")
    eps, measured, err = audited_and_measured(BASE + "shell cd sub\ninclude ../l.in\nshell cd ..\nrun 40000\n",
                                              tmp_path)
    assert abs(eps - measured) < 5e-5, (eps, measured, err)


@needs_lammps
@pytest.mark.dem
def test_a_per_process_restart_read_through_links_after_a_write_is_refused(tmp_path):
    """Field round 38, R26: the folder holds lbase.rst -> rbase.rst and l0.rst -> r0.rst; the deck
    writes r%.rst and reads l%.rst. The read's % was not matched to the links' names, and the copy
    read the stale files the links had pointed to when it was made (0.3809 where LAMMPS reads the
    deck's own, 0.413435)."""
    from deck_cli import PERIODIC_PAIR
    lammps_separation_speed(PERIODIC_PAIR + "set atom 2 density 8000\nwrite_restart r%.rst\n", tmp_path)
    (tmp_path / "in.engine").unlink()
    for name in ("base", "0"):
        os.symlink(f"r{name}.rst", tmp_path / f"l{name}.rst")
    deck = PERIODIC_PAIR + ("write_restart r%.rst\nclear\nread_restart l%.rst\npair_style granular\n"
                            "pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n"
                            "comm_modify vel yes\nfix move all nve/sphere\nrun 3000\n")
    _refused(tmp_path, deck, "read_restart l%.rst): it reads, under another name of the same file")


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("printed", ["print ${kk}", 'print "${kk}" screen no', "print $(v_kk)"])
def test_a_print_of_a_number_then_an_include_is_audited(tmp_path, printed):
    """Field round 35, E77, refused since the writers' checks took every word of a skipped print for
    a file it may write: a print with no file keyword writes none, and a variable that is a number
    cannot bring one (LAMMPS 0.490898 with kn 3000 from the included file)."""
    (tmp_path / "pc.in").write_text("pair_coeff 1 2 " + LAW.format(kn="${kk}") + "\n")
    printed_eps, engine, err = audited_and_measured(BASE + f"variable kk equal 3000\n{printed}\ninclude pc.in\n"
                                                    "run 40000\n", tmp_path)
    assert abs(printed_eps - abs(engine)) < 5e-5, (printed_eps, engine, err)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("writer", ["dump d all custom ${df} d.txt id x vx",
                                    "dump d all custom 100 d.txt id x vx\ndump_modify d every ${df}\nundump d",
                                    "restart ${df} r.*", "write_dump all custom d.txt id x modify every ${df}"],
                         ids=["dump", "dump_modify", "restart", "write_dump"])
def test_a_writer_with_a_number_from_a_variable_then_an_include_is_audited(tmp_path, writer):
    """Field round 45, M15 (and M10 M12 M14, LIGGGHTS-PFM's epsd tc0 deck R23), refused since every
    word of a skipped writer other than print was taken for a file it may write, a variable's word
    for any file: a dump whose every is ${df} then an include of another file. Only the word where
    the writer names its file can (LAMMPS 0.490898 with kn 3000 from the included file)."""
    (tmp_path / "pc.in").write_text("pair_coeff 1 2 " + LAW.format(kn="${kk}") + "\n")
    printed_eps, engine, err = audited_and_measured(BASE + f"variable kk equal 3000\nvariable df equal 100000\n"
                                                    f"{writer}\ninclude pc.in\nrun 40000\n", tmp_path)
    assert abs(printed_eps - abs(engine)) < 5e-5, (printed_eps, engine, err)


@needs_lammps
@pytest.mark.dem
def test_a_writer_whose_file_is_a_variable_then_an_include_stays_refused(tmp_path):
    """A variable in the writer's file word may name the file read (here it does)."""
    (tmp_path / "pc.in").write_text(f"pair_coeff 1 2 {LAW.format(kn=3000)}\n")
    _refused(tmp_path, BASE + "variable f string pc.in\ndump d all custom 100 ${f} id x\ninclude pc.in\nrun 40000\n",
             "dump d all custom 100 ${f} id x")


@needs_lammps
@pytest.mark.dem
def test_a_print_whose_unquoted_string_may_hold_a_file_keyword_stays_refused(tmp_path):
    """A string variable substituted unquoted is read again as words: here it names the file."""
    (tmp_path / "pc.in").write_text(f"pair_coeff 1 2 {LAW.format(kn=3000)}\n")
    _refused(tmp_path, BASE + f"variable s string '\"{NEW}\" file pc.in'\nprint ${{s}}\ninclude pc.in\nrun 40000\n",
             "print ${s}")

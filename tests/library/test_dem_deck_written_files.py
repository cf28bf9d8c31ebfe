"""Files a deck writes and reads back, and commands the audit does not run that a later read
depends on (field round 8). The engine's pass writes a data file into its scratch copy, so a
read_data of it reads what the deck wrote (before: refused, or, with an old file of that name in
the folder, its spheres audited, exit 0: 0.944 where LAMMPS gives 0.7616); a shell command the
engine does itself (cd, putenv, ...) runs in the confined copy; a read of a file that a command
the audit does not run names (shell cp, print to a file) is refused in one line (before: the old
file's eps, exit 0, with a note that the shell 'has no part in a contact')."""

import pytest

from deck_cli import agrees_with_lammps, audit, lammps_held_at_end, lammps_spheres, needs_lammps, run
from restitution.dem.dialect.sandbox import available as confining

HOOKE = "pair_coeff * * hooke 2000 0.05 damping velocity tangential linear_nohistory 0 0"
LINE = "pair_coeff * * hooke 1000.0 {e} damping coeff_restitution tangential linear_nohistory 0 0"
START = """units si
atom_style sphere
comm_modify vel yes
boundary f f f
"""


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("stale", [False, True], ids=["no old file", "an old file of that name"])
def test_a_data_file_the_deck_writes_is_read_back(tmp_path, stale):
    if stale:     # spheres of diameter 0.008 and density 7000, which the deck's own write replaces
        (tmp_path / "settled.data").write_text("stale\n\n2 atoms\n1 atom types\n0 0.1 xlo xhi\n0 0.1 ylo yhi\n"
                                               "0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.008 7000 0.02 0.05 0.05\n"
                                               "2 1 0.008 7000 0.04 0.05 0.05\n")
    old = (tmp_path / "settled.data").read_bytes() if stale else None
    (tmp_path / "in.deck").write_text(START + "region box block 0 0.1 0 0.1 0 0.1 units box\ncreate_box 1 box\n"
                                      "create_atoms 1 single 0.02 0.05 0.05\ncreate_atoms 1 single 0.04 0.05 0.05\n"
                                      f"set type 1 diameter 0.004 density 2500\npair_style granular\n{HOOKE}\n"
                                      "fix integ all nve/sphere\ntimestep 1e-6\nrun 10\nwrite_data settled.data\n"
                                      f"clear\n{START}read_data settled.data\npair_style granular\n{HOOKE}\n"
                                      "fix integ all nve/sphere\ntimestep 1e-6\nrun 10\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    for stage in got["stages"]:
        agrees_with_lammps(stage["pairs"], {1: (0.002, 2500.0)}, HOOKE, 1)
    # nothing written beside the deck: an old file stays as it was
    assert ((tmp_path / "settled.data").read_bytes() if stale else (tmp_path / "settled.data").exists()) == (
        old if stale else False)


@needs_lammps
@pytest.mark.dem
def test_a_data_file_written_after_a_pour_is_refused(tmp_path):
    """The engine's pass skips runs: the poured spheres are not in the file it writes."""
    (tmp_path / "in.deck").write_text(lammps_spheres((0.004, 2500.0)) + HOOKE + "\n"
                                      "region slab block -0.5 0.5 -0.5 0.5 0.5 0.9\nfix grav all gravity 9.81 vector 0 0 -1\n"
                                      "fix p all pour 10 1 4767548 vol 0.01 10 diam one 0.004 region slab\n"
                                      "timestep 1e-6\nrun 10\nwrite_data poured.data\nclear\n" + START +
                                      "read_data poured.data\npair_style granular\n" + HOOKE + "\n"
                                      "fix integ all nve/sphere\nrun 10\n")
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert "read_data poured.data" in err and "lacks them" in err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("writer", ["shell cp params_e09.in params.in",
                                    'print "' + LINE.format(e=0.9) + '" file params.in screen no'],
                         ids=["shell cp", "print to a file"])
def test_a_read_of_a_file_a_skipped_command_names_is_refused(tmp_path, writer):
    (tmp_path / "params.in").write_text(LINE.format(e=0.5) + "\n")
    (tmp_path / "params_e09.in").write_text(LINE.format(e=0.9) + "\n")
    (tmp_path / "in.deck").write_text(lammps_spheres((0.004, 2500.0)) + f"{writer}\ninclude params.in\n"
                                      "timestep 1e-6\nrun 10\n")
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert "include params.in" in err and "names, which the audit does not run" in err
    assert (tmp_path / "params.in").read_text() == LINE.format(e=0.5) + "\n"      # the deck's folder untouched


@needs_lammps
@pytest.mark.dem
@pytest.mark.skipif(not confining(), reason="the engine's own shell commands run only where the pass is confined")
def test_the_engines_own_shell_commands_run_in_the_copy(tmp_path, monkeypatch):
    """shell cd and putenv are LAMMPS' own (no program runs): a later include and getenv read what
    they set, as LAMMPS run by hand does; the deck's folder is left as it was."""
    monkeypatch.delenv("DECK_E", raising=False)
    (tmp_path / "case2").mkdir()
    (tmp_path / "params.in").write_text(LINE.format(e=0.5) + "\n")
    (tmp_path / "case2" / "params.in").write_text("shell putenv DECK_E=0.8\nvariable e getenv DECK_E\n"
                                                  + LINE.format(e="${e}") + "\n")
    (tmp_path / "in.deck").write_text(lammps_spheres((0.004, 2500.0)) + "shell cd case2\ninclude params.in\n"
                                      "shell mkdir post\ntimestep 1e-6\nrun 10\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert [r["typed_e"] for r in got["pairs"]] == [0.8]
    agrees_with_lammps(got["pairs"], {1: (0.002, 2500.0)}, LINE.format(e=0.8), 1)
    assert any("DECK_E" in n and "'0.8'" in n for n in got["notes"])
    assert sorted(p.name for p in tmp_path.rglob("*")) == ["case2", "in.deck", "params.in", "params.in"]


@needs_lammps
@pytest.mark.dem
def test_a_type_of_many_sizes_held_once_each_reaches_its_ends(tmp_path):
    """405 spheres of random diameters, each size held by one sphere: the range is over the sizes
    sampled, which now keep the two smallest and two largest (the smallest pair that can meet is
    the two smallest spheres), said as sampled. LAMMPS: the two smallest give 0.45473, the two
    largest 0.76119 (field round 8); before, 0.48034 and 0.75142 'over the sizes present'."""
    (tmp_path / "in.deck").write_text(START + "region box block 0 0.1 0 0.1 0 0.1 units box\ncreate_box 1 box\n"
                                      "lattice sc 0.01\nregion fill block 0.01 0.09 0.01 0.09 0.01 0.05 units box\n"
                                      "create_atoms 1 region fill\nvariable d atom 0.002+0.002*random(0,1,48271)\n"
                                      "set type 1 diameter v_d\nset type 1 density 2500\npair_style granular\n"
                                      f"{HOOKE}\nfix integ all nve/sphere\ntimestep 1e-6\nrun 10\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    low, high = got["pairs"]
    assert low["sizes"] == "smallest eps" and high["sizes"] == "largest eps" and low["sampled"] and high["sampled"]
    assert low["eps"][0] == pytest.approx(0.45473, abs=1e-5) and high["eps"][0] == pytest.approx(0.76119, abs=1e-5)
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert "over the sizes sampled" in out and "the sizes left out may reach beyond it" in err


@needs_lammps
@pytest.mark.dem
def test_a_clear_after_a_pour_starts_afresh(tmp_path):
    """A pour, a run, clear, a new system: the reader dropped the pour twice (a traceback, found
    while writing the test above); the second system is audited alone."""
    (tmp_path / "in.deck").write_text(lammps_spheres((0.004, 2500.0)) + HOOKE + "\n"
                                      "region slab block -0.5 0.5 -0.5 0.5 0.5 0.9\nfix grav all gravity 9.81 vector 0 0 -1\n"
                                      "fix p all pour 10 1 4767548 vol 0.01 10 diam one 0.004 region slab\n"
                                      "timestep 1e-6\nrun 10\nclear\n" + lammps_spheres((0.006, 2500.0)) + HOOKE + "\n"
                                      "timestep 1e-6\nrun 10\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert [r["types"] for r in got["pairs"]] == [[1, 1]] and "sizes" not in got["pairs"][0]
    agrees_with_lammps(got["pairs"], {1: (0.003, 2500.0)}, HOOKE, 1)


@needs_lammps
@pytest.mark.dem
def test_a_set_after_a_pour_only_run_sets_the_poured_spheres(tmp_path):
    """Field rounds 8 and 9: a pour makes the only atoms, a run, then set type 1 density 9000. The
    engine's pass skips the run, so the set met no atom and LAMMPS stopped there ("Set command on
    system without atoms"); the deck was refused though LAMMPS runs it and sets the 200 poured
    spheres. The copy now guards each set: where no atom is there, it is printed, substituted, and
    read as the deck's set. The second run's pairs of 9000 are LAMMPS' own; the pour's 2500, which
    it may still insert, ends the range."""
    (tmp_path / "in.deck").write_text(
        "units si\natom_style sphere\nboundary f f f\ncomm_modify vel yes\n"
        "region box block 0 0.1 0 0.1 0 0.2 units box\ncreate_box 1 box\nneighbor 0.001 bin\n"
        f"pair_style granular\n{HOOKE}\ntimestep 1e-6\nfix integ all nve/sphere\n"
        "fix grav all gravity 9.81 vector 0 0 -1\nregion slab block 0.01 0.09 0.01 0.09 0.1 0.19 units box\n"
        "fix ins all pour 200 1 300719 region slab diam one 0.004 dens 2500 2500\nrun 1\n"
        "variable rho equal 9000\nset type 1 density ${rho}\nrun 100\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1", "--run-budget", "0")
    assert len(got["stages"]) == 2 and "reads a value the runs change" not in err
    rows = {row["at"][0][1]: row for row in got["stages"][1]["pairs"]}
    assert sorted(rows) == [2500.0, 9000.0] and all(row["at"][0] == row["at"][1] for row in rows.values())
    for density, row in rows.items():
        agrees_with_lammps([row], {1: (0.002, density)}, HOOKE, 1)
    # the runs made (the pour's 2500 holds only if it has not finished): the sizes LAMMPS holds
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    held = lammps_held_at_end(tmp_path / "in.deck")
    assert "for real" in err and len(held[1]) == 1, (err, held)
    rows = got["stages"][1]["pairs"]
    assert len(rows) == 1 and "at" not in rows[0] and not rows[0].get("if_poured"), rows
    agrees_with_lammps(rows, {1: next(iter(held[1]))}, HOOKE, 1)


@needs_lammps
@pytest.mark.dem
def test_a_set_before_any_atom_still_stops_as_lammps_does(tmp_path):
    """The guard of the set above must not hide a deck LAMMPS stops on: a set before any atom
    exists, with no pour that ran, is refused with LAMMPS' own message."""
    (tmp_path / "in.deck").write_text(
        "units si\natom_style sphere\nboundary f f f\ncomm_modify vel yes\n"
        "region box block 0 0.1 0 0.1 0 0.2 units box\ncreate_box 1 box\nset type 1 density 9000\n"
        "create_atoms 1 single 0.02 0.05 0.05\ncreate_atoms 1 single 0.04 0.05 0.05\n"
        f"pair_style granular\n{HOOKE}\nfix integ all nve/sphere\ntimestep 1e-6\nrun 10\n")
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert "line 7 (set type 1 density 9000): LAMMPS stops here: Set command on system without atoms" in err, err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("poured", [True, False])
def test_a_velocity_after_a_pour_only_run_is_read_as_lammps_runs_it(tmp_path, poured):
    """Field round 9: pour, settle, velocity all set 0 0 0 (a common pattern) was refused with
    "Velocity command with no atoms existing", an error of the audit's pass alone. Without a pour
    run before it, LAMMPS' own refusal stays."""
    pour = ("fix grav all gravity 9.81 vector 0 0 -1\nregion slab block 0.01 0.09 0.01 0.09 0.1 0.19 units box\n"
            "fix ins all pour 200 1 300719 region slab diam one 0.004 dens 2500 2500\nrun 1\n") if poured else ""
    (tmp_path / "in.deck").write_text(
        "units si\natom_style sphere\nboundary f f f\ncomm_modify vel yes\n"
        "region box block 0 0.1 0 0.1 0 0.2 units box\ncreate_box 1 box\nneighbor 0.001 bin\n"
        f"pair_style granular\n{HOOKE}\ntimestep 1e-6\nfix integ all nve/sphere\n{pour}"
        "velocity all set 0 0 0\nrun 100\n")
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    if poured:
        got, err = audit(tmp_path / "in.deck", "--g", "1")
        agrees_with_lammps(got["pairs"], {1: (0.002, 2500.0)}, HOOKE, 1)
        assert "reads a value the runs change" not in err and "restitution_unset" not in err, err
    else:
        assert status == 2 and "LAMMPS stops here: Velocity command with no atoms existing" in err, err

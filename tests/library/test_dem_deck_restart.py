"""A restart across ``clear`` (R2): ``write_restart f``, ``clear``, ``read_restart f`` was refused,
though LAMMPS runs it. The write now runs into the audit's scratch copy (never beside the deck), and
the reader takes, after the read, the settings the deck had at the write that LAMMPS stores (pair
style and coefficients, time step, groups, labels), checked against what LAMMPS says it holds
(``info``); fixes, regions and neigh_modify exclusions are not stored (measured: an exclusion set
before the write no longer holds after the read). Each pair's eps is checked against LAMMPS running
the deck's own lines through the restart, head-on."""

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest

from deck_cli import PERIODIC_PAIR, audited_and_measured, lammps_separation_speed, needs_lammps, run
from restitution.dem.contact import Contact
from restitution.dem.engines.lammps import run as lammps_run

SIZES = {1: (0.005, 2500.0), 2: (0.003, 7000.0)}
HEAD = """units si
atom_style sphere
atom_modify map array
comm_modify vel yes
boundary f f f
region box block 0 1 0 1 0 1
create_box 2 box
create_atoms 1 single 0.3 0.5 0.5
create_atoms 2 single 0.6 0.5 0.5
create_atoms 1 single 0.3 0.2 0.5
create_atoms 2 single 0.6 0.2 0.5
set type 1 diameter 0.01 density 2500
set type 2 diameter 0.006 density 7000
group two type 2
neigh_modify exclude type 1 2
pair_style granular
pair_coeff * * hertz 1e6 300 damping mass_velocity tangential linear_nohistory 1 0.3
pair_coeff 1 2 hooke 1e4 20 damping mass_velocity tangential linear_nohistory 1 0.3
timestep 1e-6
write_restart {name}
clear
read_restart {name}
"""
#: (the pair style given again after the read: LAMMPS keeps no granular cutoff through a restart, and
#: with none it misses pairs in two bins, across a periodic boundary or two processes' sub-domains,
#: an nsq list's too: test_a_pair_inside_a_box_with_no_periodic_boundary_after_read_restart_is_left_out)
TAIL = "pair_style granular\nneighbor 0.001 nsq\nfix 1 all nve/sphere\nrun 10\n"


def _through_restart(tmp_path, types, g: float, dt: float, t_run: float) -> float:
    """LAMMPS' eps of the deck's own lines through its restart: two spheres of ``types`` (atoms 1
    and 2 or 1 and 4 or 3 and 4 of the deck), placed touching after the read, head-on at g."""
    ids = {(1, 2): (1, 2), (1, 1): (1, 3), (2, 2): (2, 4)}[types]
    (r1, rho1), (r2, rho2) = SIZES[types[0]], SIZES[types[1]]
    m1, m2 = (rho * 4 / 3 * math.pi * r ** 3 for r, rho in ((r1, rho1), (r2, rho2)))
    v1, v2 = g * m2 / (m1 + m2), -g * m1 / (m1 + m2)
    others = [k for k in (1, 2, 3, 4) if k not in ids]
    # four atoms: no binning (nsq) and no sorting; with bins, the third LAMMPS instance of a process
    # stopped at its run on "box size << cutoff" or "Too many atom sorting bins" (seen after a
    # (1, 2) run, never alone): binning plays no part in the collision
    text = HEAD.format(name=str(tmp_path / "engine.restart")) + "neighbor 0.001 nsq\natom_modify sort 0 0.0\n" + "".join(
        f"set atom {k} x 0.1 y {0.1 + 0.2 * n} z 0.1\n" for n, k in enumerate(others)) + f"""
set atom {ids[0]} x 0.5 y 0.5 z 0.5
set atom {ids[1]} x {0.5 + r1 + r2!r} y 0.5 z 0.5
velocity all set 0 0 0
set atom {ids[0]} vx {v1!r}
set atom {ids[1]} vx {v2!r}
fix 1 all nve/sphere
timestep {dt!r}
run {math.ceil(t_run / dt)}
"""
    # in a process of its own: several LAMMPS instances in one test process, after other LAMMPS
    # tests there, crashed the worker now and then
    text += (f"variable a equal vx[{ids[0]}]\nvariable b equal vx[{ids[1]}]\n"
             'print "RESULT $(v_a:%.17g) $(v_b:%.17g)"\n')
    (tmp_path / "engine.in").write_text(text)
    lmp = Path(sys.executable).with_name("lmp")
    env = {**os.environ, "LD_LIBRARY_PATH": str(Path(sys.prefix) / "lib")}
    done = subprocess.run([str(lmp), "-in", "engine.in", "-log", "none", "-nocite"], cwd=tmp_path, env=env,
                          capture_output=True, text=True, check=True)
    a, b = (float(w) for w in next(ln for ln in done.stdout.splitlines() if ln.startswith("RESULT")).split()[1:])
    return float(-(a - b) / g)


@needs_lammps
@pytest.mark.dem
def test_a_restart_across_clear_is_audited_as_lammps_holds_it(tmp_path):
    """Before: refused ("read_restart: ... a binary restart file"). Every pair, the exclusion gone."""
    (tmp_path / "in.deck").write_text(HEAD.format(name="state.restart") + TAIL)
    status, out, err = run(tmp_path / "in.deck", "--g", "0.5", "--json")
    assert status == 0, err
    assert not (tmp_path / "state.restart").exists()          # written in the scratch copy alone
    _as_through_restart(tmp_path, json.loads(out)["pairs"])


def _as_through_restart(tmp_path, rows) -> None:
    """Every pair of the deck's restart audited, each eps LAMMPS' through its own restart (head-on,
    2000, 4000 and 8000 steps per contact, extrapolated) to 1e-6."""
    assert [r["types"] for r in rows] == [[1, 1], [1, 2], [2, 2]]
    assert rows[1]["model"] == "LAMMPS hooke, damping mass_velocity"
    for r in rows:
        g = r["speeds"][2]
        t_c = Contact(r["alpha"], r["gamma"], r["D1"], r["D2"], r["end"]).contact_time(g)
        runs = [_through_restart(tmp_path, tuple(r["types"]), g, t_c / n, 1.5 * t_c) for n in (2000, 4000, 8000)]
        engine = lammps_run.richardson(*runs, 1)
        print(r["types"], r["eps"][2], engine, runs)
        assert abs(engine / r["eps"][2] - 1) < 1e-6
        assert all(abs(e / r["eps"][2] - 1) < 1e-3 for e in runs)


@needs_lammps
@pytest.mark.dem
def test_a_restart_file_the_deck_did_not_write_is_refused(tmp_path):
    """A restart file lying beside the deck (a binary the reader does not read): one line."""
    (tmp_path / "old.restart").write_bytes(b"\0" * 16)
    (tmp_path / "in.deck").write_text(HEAD.format(name="state.restart").replace(
        "read_restart state.restart", "read_restart old.restart") + TAIL)
    status, out, err = run(tmp_path / "in.deck", "--g", "0.5")
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1, err


@needs_lammps
@pytest.mark.dem
def test_coefficients_given_again_after_the_read_replace_the_stored_ones(tmp_path):
    """pair_coeff after the read: LAMMPS' (and the reader's) latest line for the pair."""
    deck = HEAD.format(name="state.restart") + \
        "pair_coeff 1 2 hooke 2e4 20 damping mass_velocity tangential linear_nohistory 1 0.3\n" + TAIL
    (tmp_path / "in.deck").write_text(deck)
    status, out, err = run(tmp_path / "in.deck", "--g", "0.5", "--json")
    assert status == 0, err
    rows = {tuple(r["types"]): r for r in json.loads(out)["pairs"]}
    assert rows[(1, 2)]["line"] == deck.splitlines().index(deck.splitlines()[-5]) + 1


@needs_lammps
@pytest.mark.dem
def test_a_restart_written_to_an_absolute_path_is_redirected_into_the_scratch(tmp_path):
    """write_restart /abs/path then read_restart of it: the confined engine stopped on its read-only
    file system ("Cannot open restart file"), and the deck was refused. The file is now written into
    the audit's scratch and read back from there; nothing is written at the path. Each pair's eps
    against LAMMPS through its own restart, head-on, at 2000, 4000 and 8000 steps per contact."""
    outside = tmp_path / "elsewhere" / "state.restart"
    folder = tmp_path / "deck"
    folder.mkdir()
    (folder / "in.deck").write_text(HEAD.format(name=str(outside)) + TAIL)
    status, out, err = run(folder / "in.deck", "--g", "0.5", "--json")
    assert status == 0, err
    assert not outside.parent.exists() and sorted(p.name for p in folder.iterdir()) == ["in.deck"]
    _as_through_restart(tmp_path, json.loads(out)["pairs"])


ACROSS = PERIODIC_PAIR + ("write_restart across.restart\nclear\nread_restart across.restart\n{again}"
                          "comm_modify vel yes\nfix move all nve/sphere\nrun 3000\n")


#: the same law as LAMMPS' older style (kn 2000, damping 3000 of the relative velocity; no friction)
OLDER = ("pair_style gran/hooke/history 2000 NULL 3000 NULL 0 0\npair_coeff * *\n")
STYLES = pytest.mark.parametrize("style", ["granular", "gran/hooke/history"])


def _across(style: str, again: bool) -> str:
    """ACROSS under ``style``, given again after the read or not."""
    deck = ACROSS.format(again="{again}")
    if style != "granular":
        deck = deck.replace("pair_style granular\npair_coeff * * hooke 2000 3000 damping mass_velocity tangential "
                            "linear_nohistory 1 0.3\n", OLDER)
    return deck.format(again=(OLDER if style != "granular" else "pair_style granular\n") if again else "")


@needs_lammps
@pytest.mark.dem
@STYLES
def test_a_pair_across_a_periodic_boundary_after_read_restart_is_left_out(tmp_path, style):
    """LAMMPS keeps no granular cutoff through a restart: 'Communication cutoff is 0.0', no ghost
    atoms, so two spheres meeting across the periodic x boundary are found late in overlap (field
    round 32, R04: LAMMPS 8.094838, RP05 under gran/hooke/history 0.483961; the audit printed
    0.414916 at first touch). Every pair of the stage after the read is left out with the reason
    and the remedy."""
    deck = _across(style, again=False)
    (tmp_path / "in.deck").write_text(deck)
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    assert json.loads(out)["pairs"] == []
    assert f"types 1 2: after read_restart LAMMPS holds pair_style {style} with no cutoff" in err
    assert f"give pair_style {style} again after the read" in err
    # LAMMPS itself is not checked here: it reads the cutoff it never set from memory, so its outcome
    # varies from run to run (met late in overlap, 8.094838 in round 32; a stop, "box size <<
    # cutoff", once in 5 under load; met in time, 0.414679, once in a clean-clone run): the audit
    # cannot know which, which is why the pairs are left out


@needs_lammps
@pytest.mark.dem
def test_a_pair_inside_a_box_with_no_periodic_boundary_after_read_restart_is_left_out(tmp_path):
    """Round 32, RZ03 RZ07: after the read LAMMPS bins the box by its extent along x and looks in one
    bin, so a pair along z whose centres lie in two bins is found late (8.228907) with no periodic
    boundary at all: left out too."""
    deck = (ACROSS.format(again="").replace("boundary p p f", "boundary f f f")
            .replace("create_atoms 1 single 0.03745 0.02 0.05", "create_atoms 1 single 0.02 0.02 0.04745")
            .replace("create_atoms 2 single 0.00355 0.02 0.05", "create_atoms 2 single 0.02 0.02 0.05355")
            .replace("set atom 1 vx 0.7714285714", "set atom 1 vz 0.7714285714")
            .replace("set atom 2 vx -0.2285714286", "set atom 2 vz -0.2285714286"))
    (tmp_path / "in.deck").write_text(deck)
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    assert json.loads(out)["pairs"] == [] and "in two bins" in err, err


@needs_lammps
@pytest.mark.dem
@STYLES
def test_pair_style_granular_given_again_after_the_read_is_audited(tmp_path, style):
    """The remedy: with the pair style given again after the read, LAMMPS meets the pair at first
    touch (0.414679 at 586 steps per contact) and the audit prints it."""
    printed, engine, err = audited_and_measured(_across(style, again=True), tmp_path)
    engine = abs(engine)       # (the atoms' order in LAMMPS' arrays after the read decides the sign)
    assert abs(printed - engine) < 0.004 and abs(engine - 0.4149) < 0.004


#: Field round 36, M15 M17: a restart file named by the step (``*``) after a run
STEP_NAMED = PERIODIC_PAIR + ("set atom 2 density 5000\nwrite_restart r.*\n{between}clear\nread_restart {read}\n"
                              "pair_style granular\npair_coeff * * hooke 2000 3000 damping mass_velocity tangential "
                              "linear_nohistory 1 0.3\ncomm_modify vel yes\nfix move all nve/sphere\nrun 3000\n")


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("between, read, written", [
    ("reset_timestep 0\nset atom 2 density 2500\nwrite_restart r.*\n", "r.*", "write_restart r.*"),
    ("", "r.1000", "write_restart r.*"), ("", "r.1000", "if '1 > 0' then 'write_restart r.*'"),
    ("", "r.1000", "variable f string r.*\nwrite_restart ${f}")],
    ids=["the largest step read", "the step named", "in an if", "named by a variable"])
def test_a_restart_named_by_the_step_is_the_one_lammps_writes(tmp_path, between, read, written):
    """LAMMPS puts the step in place of a ``*`` in write_restart's name: r.1000 after the first run.
    The audit's pass, its runs skipped, wrote r.0 twice, the second over the first, and read that
    (M15: 0.4149 printed, sphere 2 at density 2500, where LAMMPS reads r.1000 at 5000: 0.390402),
    or stopped on a missing r.1000 (M17). A * so written after a run now makes the pass clocked:
    each file is written at the deck's step and the read finds the file LAMMPS reads; also where
    the write is an if's branch or its name a variable's (field round 37, R26 R27, read as written
    before)."""
    deck = STEP_NAMED.format(between=between, read=read).replace("write_restart r.*\n", written + "\n", 1)
    printed, engine, err = audited_and_measured(deck, tmp_path)
    engine = abs(engine)       # (the atoms' order in LAMMPS' arrays after the read decides the sign)
    assert abs(printed - engine) < 0.004, (printed, engine, err)
    # the file of density 2500 gives another eps: the test tells the two files apart
    assert abs(engine - 0.4149) > 0.02, engine


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("writer, read", [("restart 500 r.*", "r.1000"), ("restart 1000 r.1000 s.1000", "r.1000"),
                                          ("restart 500 r%.*", "r%.1000"),
                                          ('run 1000 every 1000 "write_restart r.1000"', "r.1000")],
                         ids=["by the step", "toggled", "per process", "in a run's every"])
def test_a_restart_file_the_runs_would_write_is_not_read_from_a_stale_copy(tmp_path, writer, read):
    """Field round 36, M05 M06: ``restart N r.*`` during a run, then ``read_restart r.1000``. The
    pass makes no run, so it writes no such file, and where the deck's folder held an r.1000 from
    an earlier run (here sphere 2 at density 5000), the copy read that one where LAMMPS overwrites
    it first. A read of a file a skipped command names, its * read as any step, is refused in one
    line, the user's file untouched; also a % (field round 37, R07: r%.1000 was not matched) and a
    writer in a run's every, which the pass never runs where the run is kept whole (F16 F35)."""
    folder = tmp_path / "deck"
    folder.mkdir()
    lammps_separation_speed(PERIODIC_PAIR + "set atom 2 density 5000\nwrite_restart r.1000\n", folder)
    (folder / "in.engine").unlink()
    stale = (folder / "r.1000").read_bytes()
    (folder / "in.deck").write_text(PERIODIC_PAIR.replace("run 1000\n", f"{writer}\nrun 1000\n")
                                    + "clear\n" + STEP_NAMED.split("clear\n", 1)[1].format(read=read))
    if read != "r.1000":
        lammps_separation_speed(PERIODIC_PAIR + "set atom 2 density 5000\nwrite_restart r%.1000\n", folder)
    status, out, err = run(folder / "in.deck", "--g", "1")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    said = writer.split('"')[1] if '"' in writer else writer
    assert f"read_restart {read}): it reads a file that line 18 ({said}) names" in err, err
    assert (folder / "r.1000").read_bytes() == stale

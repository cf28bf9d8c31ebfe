"""A value read from ``step`` or ``time`` after a run (field round 9, D2: c10, c11, c15): the pass
skips the runs, so it read step 0 and audited settings the deck never runs (eta 0.5 where the
deck's second run has 1.0: 0.7346 printed, LAMMPS 0.5347), with a note. Where every run is a
``run N`` of a literal N, the pass is made again with LAMMPS' step and time set after each run to
those the deck's run reaches (reset_timestep): the stage audited is the deck's. LAMMPS refuses to
set the step where a time-dependent fix (a pour) is defined: there the first pass and its note stand."""

import pytest

from deck_cli import agrees_with_lammps, audit, lammps_spheres, needs_lammps

LINE = "pair_coeff * * hooke 1e4 {eta} damping velocity tangential linear_nohistory 0 0"
DECK = (lammps_spheres((0.01, 2500.0)) + LINE.format(eta=0.5) + "\ntimestep 1e-6\nPOURrun 1000\n"
        "READ\n" + LINE.format(eta="${eta}") + "\nrun 1000\n")


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("read", ["variable eta equal 0.5+0.5*step/1000", "variable eta equal 0.5+500*time",
                                  'if "$(step) >= 1000" then "variable eta equal 1.0" else "variable eta equal 0.5"'])
def test_a_value_of_the_step_after_a_run_is_the_decks(tmp_path, read):
    (tmp_path / "in.deck").write_text(DECK.replace("POUR", "").replace("READ", read))
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert len(got["stages"]) == 2, err
    agrees_with_lammps(got["stages"][1]["pairs"], {1: (0.005, 2500.0)}, LINE.format(eta=1.0), 1)
    # (a variable an if's branch defines is one the clock cannot follow: LAMMPS then makes the runs)
    assert "set LAMMPS' step and time to those the deck's run reaches" in err or read.startswith("if"), err
    assert "reads a value the runs" not in err and ("for real" in err) == read.startswith("if"), err


@needs_lammps
@pytest.mark.dem
def test_with_a_pour_defined_the_pass_without_the_clock_stands_and_says_so(tmp_path):
    pour = "fix g all gravity 9.81 vector 0 0 -1\nregion ins block -0.5 0.5 -0.5 0.5 0.5 0.9\nfix p all pour 10 1 4767548 region ins diam one 0.01 dens 2500 2500\n"
    (tmp_path / "in.deck").write_text(DECK.replace("POUR", pour).replace("READ", "variable eta equal 0.5+0.5*step/1000"))
    # LAMMPS makes the runs: the stage is the deck's
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert "for real" in err and "reads a value the runs change" not in err, err
    assert not any(row.get("may_differ") for stage in got["stages"] for row in stage["pairs"])
    agrees_with_lammps(got["stages"][-1]["pairs"], {1: (0.005, 2500.0)}, LINE.format(eta=1.0), 1)
    # the runs not made (--run-budget 0): the pass without the clock stands, and says so
    got, err = audit(tmp_path / "in.deck", "--g", "1", "--run-budget", "0")
    assert "reads a value the runs change (time, step" in err and "set LAMMPS' step" not in err, err
    # field test r11 (D2): the stage built on it (here the one stage of both runs, as the pass read
    # the same eta at both) says so in its rows, not only on stderr
    assert all(row.get("may_differ") for row in got["stages"][-1]["pairs"]), got["stages"][-1]["pairs"]

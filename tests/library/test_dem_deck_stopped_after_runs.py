"""Where the engine stops in the audit's pass on a value the runs before would have made (field
round 9, c33: ``mass(all)/count(all)`` after a pour-only run, which the pass, its runs skipped, never
poured: "Divide by 0"), the engine makes the runs for real and the audit reads the value they give
(the deck run by hand never stops there); where it may not make them (``--run-budget 0``), the
refusal says so, not "LAMMPS stops here", which the deck run by hand never says; no value is guessed."""

import math

import pytest

from deck_cli import agrees_with_lammps, lammps_pour, needs_lammps, run

LINE = "pair_coeff * * hertz 1e6 {eta} damping mass_velocity tangential linear_nohistory 1 0.3"
DECK = lammps_pour(LINE.format(eta=300), sphere=None) + """timestep 1e-5
run 100
variable mmean equal mass(all)/count(all)
variable eta equal 300*v_mmean/0.001309
""" + LINE.format(eta="${eta}") + "\nrun 100\n"


@needs_lammps
@pytest.mark.dem
def test_a_value_of_atoms_a_skipped_run_pours_is_refused_truly(tmp_path):
    (tmp_path / "in.deck").write_text(DECK)
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--run-budget", "0")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert "stops here" not in err and "runs before are skipped" in err and "fix p" in err, err
    assert "Divide by 0" in err and "line 17" in err


@needs_lammps
@pytest.mark.dem
def test_a_value_of_atoms_the_runs_pour_is_read_from_the_runs_made(tmp_path):
    """The runs made, the pour's spheres (d 0.01, density 2500) are there at line 17: eta is
    300 m / 0.001309 of their mass, and the last stage's eps LAMMPS' own head-on."""
    import json
    (tmp_path / "in.deck").write_text(DECK)
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    assert status == 0 and "LAMMPS made the deck's 2 runs (200 steps) for real" in err, err
    last = json.loads(out)["stages"][-1]["pairs"]
    eta = 300 * 2500 * math.pi / 6 * 0.01 ** 3 / 0.001309
    assert [p["types"] for p in last] == [[1, 1]] and last[0]["D2"] == pytest.approx(eta, rel=1e-12), last
    agrees_with_lammps(last, {1: (0.005, 2500.0)}, LINE.format(eta=repr(eta)), 1)


@needs_lammps
@pytest.mark.dem
def test_an_error_no_run_changes_stays_lammps_own(tmp_path):
    """A command LAMMPS does not know, after a run: LAMMPS stops on it by hand too."""
    (tmp_path / "in.deck").write_text(DECK.replace("variable mmean", "pair_coef * *\nvariable mmean"))
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and "LAMMPS stops here: Unknown command" in err, err

"""Where the engine stops in the audit's pass on a value the runs before would have made (field
round 9, c33: ``mass(all)/count(all)`` after a pour-only run, which the pass, its runs skipped, never
poured: "Divide by 0"), the refusal says so, not "LAMMPS stops here", which the deck run by hand
never says; no value is guessed."""

import pytest

from deck_cli import lammps_pour, needs_lammps, run

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
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert "stops here" not in err and "runs before are skipped" in err and "fix p" in err, err
    assert "Divide by 0" in err and "line 17" in err


@needs_lammps
@pytest.mark.dem
def test_an_error_no_run_changes_stays_lammps_own(tmp_path):
    """A command LAMMPS does not know, after a run: LAMMPS stops on it by hand too."""
    (tmp_path / "in.deck").write_text(DECK.replace("variable mmean", "pair_coef * *\nvariable mmean"))
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and "LAMMPS stops here: Unknown command" in err, err

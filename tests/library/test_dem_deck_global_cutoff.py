"""A global cutoff given again by ``pair_style granular C`` (the same style: LAMMPS keeps the
coefficients and reads the new cutoff into its lists at the next set-up) is the next run's: its
reach decides whether that run's pairs meet (field round 33, C07)."""

import pytest

from deck_cli import PERIODIC_PAIR, audit, audited_and_measured, lammps_separation_speed, needs_lammps


@needs_lammps
@pytest.mark.dem
def test_a_global_cutoff_given_again_is_the_next_runs(tmp_path):
    """Field round 33, C07 C09 C11: pair_style granular 0.02, a run, pair_style granular 0.001 (the
    same style: LAMMPS keeps the coefficients and reads the new cutoff at the next set-up): the two
    runs were one stage, audited with 0.02 (0.414916 printed, LAMMPS 8.094838). The second run is a
    stage of its own, whose pair is left out with the lists' reach; 0.001 then 0.02 is printed."""
    first = PERIODIC_PAIR.replace("pair_style granular\n", "pair_style granular 0.02\n")
    deck = first + "pair_style granular 0.001\nrun 3000\n"
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert [[1, 2] in [r["types"] for r in s["pairs"]] for s in got["stages"]] == [True, False], got["stages"]
    assert "cutoff 0.001: LAMMPS' neighbour lists reach the largest cutoff plus the skin" in err, err
    assert abs(abs(lammps_separation_speed(deck, tmp_path)) - 0.4149) > 0.05
    back = PERIODIC_PAIR.replace("pair_style granular\n", "pair_style granular 0.001\n") + \
        "pair_style granular 0.02\nrun 3000\n"
    printed, engine, err = audited_and_measured(back, tmp_path)
    assert abs(printed - abs(engine)) < 0.004, (printed, engine, err)

"""Field round 21's silent classes, on decks written here from round 20's z30 (hooke 2000, two 4 mm
spheres; kn 9000 gives 0.72384049 and kn 2000 0.49726208 head-on in LAMMPS, round 18).

D1: LAMMPS reads typographic quotes as ASCII ones (it warns and goes on), so an ``if`` written with
them runs its branch; the audit did not see it (a05: 0.49726 printed, LAMMPS 0.692795). D2: every
evaluation of a variable drawn from random() draws, and the engine run by hand draws where the pass
does not (thermo output as the runs go, a print): a later read differs (r25, r19). D3: a quit quoted
in an if's branch of a run's every ends the deck (c28)."""

from pathlib import Path

import json
import pytest

from deck_cli import needs_lammps, needs_liggghts, run

BASE = (Path(__file__).resolve().parents[1] / "field20" / "decks" / "z30_partition_yes_1_pair_coeff" / "in.deck")
KN9000 = "pair_coeff * * hooke 9000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"


def deck(tmp_path, last):
    """z30 with its partition line replaced by ``last`` (text before the run)."""
    lines = [ln for ln in BASE.read_text(encoding="utf-8").splitlines() if not ln.startswith(("partition", "run"))]
    (tmp_path / "in.deck").write_text("\n".join(lines + [last]) + "\n", encoding="utf-8")
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    return status, (json.loads(out) if status == 0 else None), err


def eps11(got):
    return [r["eps"][0] for r in got["stages"][-1]["pairs"] if r["types"] == [1, 1]]


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("quotes", ["\u201c\u201d", "\u2018\u2019"])
def test_an_if_in_typographic_quotes_runs_its_branch(tmp_path, quotes):
    a, b = quotes
    status, got, err = deck(tmp_path, f"if {a}1 > 0{b} then {a}{KN9000}{b}\nrun 100")
    assert status == 0, err
    assert eps11(got) == [pytest.approx(0.72384049, abs=2e-7)]


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("between", ["thermo_style custom step v_r\nthermo 10\nrun 100",
                                     'print "${r}"', 'print "$(random(0,1,99))"'])
def test_a_random_variable_read_after_draws_the_pass_does_not_make_is_refused(tmp_path, between):
    status, got, err = deck(tmp_path, "variable r equal random(1000,9000,4711)\n" + between +
                            '\nif "${r} > 5000" then "' + KN9000 + '"\nrun 100')
    assert status == 2 and "random() or normal()" in err, err


@needs_lammps
@pytest.mark.dem
def test_a_random_variable_read_before_any_other_draw_is_audited(tmp_path):
    # a seed drawn once and read at once: the pass draws as the engine does
    status, got, err = deck(tmp_path, "variable r equal random(1000,9000,4711)\nvariable kn equal ${r}\nrun 100")
    assert status == 0, err


@needs_lammps
@pytest.mark.dem
def test_a_quit_quoted_in_an_every_if_branch_is_refused(tmp_path):
    status, got, err = deck(tmp_path, "run 200 every 100 \"if '$(step) >= 100' then 'print done' 'quit'\"\n"
                            + KN9000 + "\nrun 100")
    assert status == 2 and "may quit" in err, err


@needs_liggghts
@pytest.mark.dem
def test_a_liggghts_deck_whose_liggghts_lines_are_included_runs_in_liggghts(tmp_path):
    # field round 21, N01: every line only LIGGGHTS knows sat in an included settings file, and the
    # deck was run in LAMMPS, which stopped on it; LIGGGHTS' hertz returns the typed e (0.5)
    lines = (BASE.parents[1] / "L86_liggghts_quit_minimal" / "in.deck").read_text().splitlines()
    settings = [ln for ln in lines[:lines.index("run 1000")] if not ln.startswith("#")]
    (tmp_path / "in.settings").write_text("\n".join(settings) + "\n")
    (tmp_path / "in.deck").write_text("include in.settings\nrun 1000\n")
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    assert [r["eps"][0] for r in json.loads(out)["pairs"] if r["types"] == [1, 1]] == [pytest.approx(0.5, abs=2e-7)]

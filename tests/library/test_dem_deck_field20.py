"""Field round 20's classes: what the engine ran that the audit did not see.

D1 (silently wrong): a LIGGGHTS ``quit`` (L86) and a ``quit`` a run's ``every`` runs (e27, L93) end
the deck, and the runs after them were audited as its last stage. D5: ``partition yes 1 CMD`` runs
CMD in an engine of one partition (z30, L98; ``partition no 2`` stops it, z31), ``timer timeout 0``
ends the runs before their steps (z28), ``fix ttm`` pushes the atoms (z40), ``ndx2group`` fills a
group (z36): each was said to have no part in a contact. D2, D3: ``unfix`` and ``timestep`` run
between a run's parts (e03, e15, L72) were neither run nor refused; refused then, they now run as
the engine runs them (the run written out in its parts, :func:`restitution.dem.deck.scratch.split_every`). Each eps compared here is the
engine's: LIGGGHTS' typed e for the hertz rows (its hertz damping returns e exactly, Eq. (10)), and
round 18's LAMMPS head-on runs for hooke 2000 and 9000 (0.49726208, 0.72384049)."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, needs_liggghts, run

DECKS = Path(__file__).resolve().parents[1] / "field20" / "decks"


def audit(name):
    status, out, err = run(DECKS / name / "in.deck", "--g", "1", "--json")
    return status, (json.loads(out) if status == 0 else None), err


def eps(got, types):
    return [r["eps"][0] for r in got["pairs"] if tuple(r["types"]) == types]


@pytest.mark.dem
@pytest.mark.parametrize("name, types, expected", [
    pytest.param("L86_liggghts_quit_minimal", (1, 1), 0.5, marks=needs_liggghts),
    pytest.param("L93_run_every_quit", (1, 1), 0.6, marks=needs_liggghts),
    pytest.param("e27_run_every_quit", (1, 2), 0.49726208, marks=needs_lammps)])
def test_a_quit_ends_the_deck(name, types, expected):
    status, got, err = audit(name)
    assert status == 0, err
    assert len(got["stages"]) == 1
    assert eps(got, types) == [pytest.approx(expected, abs=2e-7)]


@pytest.mark.dem
@pytest.mark.parametrize("name, types, expected", [
    pytest.param("z30_partition_yes_1_pair_coeff", (1, 1), 0.72384049, marks=needs_lammps),
    pytest.param("L98_liggghts_partition_yes_1_property", (1, 1), 0.3, marks=needs_liggghts)])
def test_partition_1_runs_its_command(name, types, expected):
    status, got, err = audit(name)
    assert status == 0, err
    assert eps(got, types) == [pytest.approx(expected, abs=2e-7)]


@pytest.mark.dem
@pytest.mark.parametrize("name, said", [
    pytest.param("z31_partition_no_2_set_density", "LAMMPS stops here", marks=needs_lammps),
    pytest.param("z28_timer_timeout_zero", "a timeout of no time", marks=needs_lammps)])
def test_what_the_pass_cannot_show_is_refused(name, said):
    status, got, err = audit(name)
    assert status == 2 and said in err


@needs_lammps
@pytest.mark.dem
def test_a_floor_unfixed_by_a_runs_every_is_gone_from_the_runs_after():
    """e03: ``run 100 every 100 "unfix floor"``, ``run 100``: refused since round 20, now the command
    runs after the run's one part as LAMMPS runs it, and the second run has no floor (LAMMPS' second
    run: the sphere passes z = 0, ENGINE.txt)."""
    status, got, err = audit("e03_run_every_unfix_floor")
    assert status == 0, err
    assert [bool(stage["walls"]) for stage in got["stages"]] == [True, False], got["stages"]
    assert eps(got, (1, 2)) == [pytest.approx(0.49726208, abs=2e-7)]


@pytest.mark.dem
@pytest.mark.parametrize("name, dt", [pytest.param("e15_run_every_timestep_coarser", 2e-4, marks=needs_lammps),
                                      pytest.param("L72_run_every_timestep", 1e-4, marks=needs_liggghts)])
def test_a_time_step_a_runs_every_sets_is_the_one_stated(name, dt):
    """e15, L72: the time step set between a run's parts is the one the engine's later runs take
    (round 20: the steps per contact were stated at the old one); the coarsest is stated."""
    status, got, err = audit(name)
    assert status == 0, err
    assert f"at the deck's time step {dt:g} a contact lasts" in err, err


@needs_lammps
@pytest.mark.dem
def test_a_pushing_skipped_fix_is_named_as_pushing():
    status, got, err = audit("z40_fix_ttm_drag_periodic")
    assert status == 0, err
    assert "fix ttm" in err and "may add forces to its atoms" in err and "no part in a contact" not in err


@needs_lammps
@pytest.mark.dem
def test_ndx2group_fills_its_group():
    # LAMMPS holds two 6 mm type-2 spheres, made so through the group the index file fills
    status, got, err = audit("z36_ndx2group_then_set_mapped")
    assert status == 0, err
    assert eps(got, (2, 2)) and "type 2 has no particle" not in err


@needs_liggghts
@pytest.mark.dem
@pytest.mark.parametrize("name, stages, expected", [
    ("L97_liggghts_if_else_run", 1, 0.6), ("L95_liggghts_run_inside_if", 2, 0.3),
    ("L84_liggghts_if_quit", 1, 0.6)])
def test_a_liggghts_if_runs_its_run_or_quit(name, stages, expected):
    # LIGGGHTS stops on an include inside an if, which the audit's marker was: refused with an error
    # LIGGGHTS never gives (field round 20); its hertz rows are its typed e
    status, got, err = audit(name)
    assert status == 0, err
    assert len(got["stages"]) == stages
    assert eps(got, (1, 1)) == [pytest.approx(expected, abs=2e-7)]


@needs_liggghts
@pytest.mark.dem
def test_a_liggghts_if_runs_a_run_of_a_variable_length(tmp_path):
    deck = (DECKS / "L97_liggghts_if_else_run" / "in.deck").read_text()
    (tmp_path / "in.deck").write_text(deck.replace('then "run 500" else "run 800"',
                                                   'then "variable n equal 400" "run ${n}" else "run 800"'))
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    got = json.loads(out)
    assert [r["eps"][0] for r in got["pairs"] if tuple(r["types"]) == (1, 1)] == [pytest.approx(0.6, abs=2e-7)]


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("folder", ["field19/decks/f02_adapt_diameter_reset_yes",
                                    "field20/decks/s18_adapt_reset_yes_scale_off_run"])
def test_a_fix_adapt_with_reset_yes_is_read_at_its_runs_sizes(tmp_path, folder):
    # rounds 19 and 20 (f02, s18): refused. LAMMPS' marker now dumps the atoms at the run's set-up,
    # where the adapted 8 mm spheres are, before the run's end puts 4 mm back; the same deck with
    # the sizes set by hand (diameter then density: the mass follows, as fix adapt keeps it) gives
    # the same rows, stage by stage
    deck = (DECKS.parents[1] / folder / "in.deck").read_text()
    by_hand = deck.replace("fix ad all adapt 1 atom diameter v_dd reset yes", "set type * diameter 0.008 density 2500")
    by_hand = by_hand.replace("unfix ad", "set type * diameter 0.004 density 2500")
    assert by_hand.count("set type * diameter") == 2
    (tmp_path / "in.deck").write_text(by_hand)

    def rows(path):
        status, out, err = run(path, "--g", "1", "--json")
        assert status == 0, err
        return [[(r["types"], r["eps"]) for r in stage["pairs"]] for stage in json.loads(out)["stages"]]
    adapted, by_hand_rows = rows(DECKS.parents[1] / folder / "in.deck"), rows(tmp_path / "in.deck")
    # the adapted run's pairs are named, not audited: LAMMPS builds its lists with the 4 mm spheres
    # before the fix makes them 8 mm (field round 30, A01, A05: met late, 1.59 for 0.37)
    assert len(adapted) == 2 and adapted[0] == [] and by_hand_rows[0] and adapted[1] == by_hand_rows[1]

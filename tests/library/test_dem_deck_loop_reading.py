"""A loop of thousands of runs read from what the engine executed: a pass that only defines its pours
again (new seeds) before a run the engine did not set up again joins the stage without its settings
being keyed again, and a pass that changes anything is read as before (no engine needed: the
commands are given as the engine's echo would give them)."""

import pytest

from restitution.dem.deck import reader
from restitution.dem.deck.stream import Executed


def _loop(passes: int, wide_at: int | None = None, coeff_at: int | None = None) -> list:
    """The commands of a loop that pours type 1 (a new seed each pass) and runs; pass ``wide_at``
    pours diameter 0.2 instead of 0.1, pass ``coeff_at`` sets another pair_coeff before its run.
    Only the first run's marker wrote the atoms (type 2 holds one)."""
    out = [Executed((None, 1), "create_box 2 b"), Executed((None, 2), "pair_style granular"),
           Executed((None, 3), "pair_coeff * * hooke 10 1")]
    for n in range(passes):
        diam = 0.2 if n == wide_at else 0.1
        out.append(Executed((None, 5), f"fix p all pour 2 1 {1000 + n} region r diam one {diam} dens 1 1"))
        if n == coeff_at:
            out.append(Executed((None, 4), "pair_coeff * * hooke 20 1"))
        out.append(Executed((None, 6), "run 1", 0, n == 0))
    return out


def _stages(deck) -> list:
    """(runs, type 1's radii, its k_n) of each stage: the spheres a pass poured stay in the later runs."""
    return [(len(runs), tuple(sorted({r for r, _ in snap.sizes[1]})) if 1 in snap.sizes else (snap.radius[1],),
             snap.coeffs[(1, 1)][1][4]) for runs, snap, _ in deck.stages]


def test_a_pass_that_pours_again_joins_the_stage_unkeyed(monkeypatch):
    keyed = []
    monkeypatch.setattr(reader, "contact_key", lambda deck, key=reader.contact_key: keyed.append(1) or key(deck))
    deck = reader.read_executed(_loop(200), [{2: {(0.5, 2.0)}}])
    assert _stages(deck) == [(200, (0.05,), "10")]
    assert len(keyed) <= 2, f"the settings were keyed at {len(keyed)} of 200 runs"


@pytest.mark.parametrize("change, stages", [
    ({"wide_at": 0}, [(1, (0.1,), "10"), (199, (0.05, 0.1), "10")]),
    ({"wide_at": 1}, [(1, (0.05,), "10"), (199, (0.05, 0.1), "10")]),
    ({"wide_at": 120}, [(120, (0.05,), "10"), (80, (0.05, 0.1), "10")]),
    ({"coeff_at": 120}, [(120, (0.05,), "10"), (80, (0.05,), "20")])])
def test_a_pass_that_changes_the_contact_is_a_stage_of_its_own(change, stages):
    deck = reader.read_executed(_loop(200, **change), [{2: {(0.5, 2.0)}}])
    assert _stages(deck) == stages


def test_pours_after_the_last_run_are_read_as_settings_no_run_used():
    tail = [Executed((None, 5), "fix p all pour 2 1 7 region r diam one 0.3 dens 1 1")]
    deck = reader.read_executed(_loop(20) + tail, [{2: {(0.5, 2.0)}}])
    assert _stages(deck) == [(20, (0.05,), "10")]
    assert (0.15, 1.0) in deck.sizes[1]

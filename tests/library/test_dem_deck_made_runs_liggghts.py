"""LIGGGHTS makes a deck's runs for real where its pass, each run one step long, cannot tell what
the deck reads after a run (field rounds 10 and 11: L05, a set by region after a fall, refused; L04,
e from the step after ``run 1000``, read at step 1 and marked; f10-L04, an insertion finished before
a set, its template's size marked ``if_poured``): the state LIGGGHTS reaches is audited, as for
LAMMPS (test_dem_deck_made_runs.py)."""

from pathlib import Path

import pytest

from deck_cli import as_without_runs, liggghts_held_at_end, needs_liggghts, run

FIELD = Path(__file__).resolve().parents[1]


def _json(path, *args):
    import json
    status, out, err = run(path, "--g", "1", "--json", *args)
    return status, (json.loads(out) if status == 0 else None), err


#: LIGGGHTS decks -> what the pass whose runs are one step long does with it (:func:`as_without_runs`)
LIGGGHTS_DECKS = {
    "field11/decks/L05_set_region_after_fall": "refused",
    "field11/decks/L04_step_after_run": "may_differ",
    "field10/decks/L04_stiffness_set_after": "if_poured",
}


@needs_liggghts
@pytest.mark.dem
@pytest.mark.parametrize("name", sorted(LIGGGHTS_DECKS))
def test_liggghts_makes_the_runs_and_its_state_is_audited(tmp_path, name):
    """LIGGGHTS' pass runs each run for one step: L05's set by region after the fall was refused,
    L04's e from ``step`` after ``run 1000`` read at step 1 (e 0.3002, marked), f10-L04's insertion
    that had inserted all its spheres before a set marked ``if_poured``. LIGGGHTS now makes the
    runs; the last stage's sizes are those it holds at the deck's end, each eps its own head-on."""
    from restitution.dem.contact import Contact
    from restitution.dem.engines.liggghts import run as liggghts_run
    from restitution.dem.pair import Pair
    path = FIELD / name / "in.deck"
    status, got, err = _json(path)
    assert status == 0 and err.count("for real") == 1 and "LIGGGHTS made the deck's" in err, err
    held = liggghts_held_at_end(path, tmp_path)
    last = got["stages"][-1]
    assert not any(p.get(k) for p in last["pairs"] + last["walls"] for k in ("may_differ", "if_poured", "at"))
    text = path.read_text()
    ntypes = int(text.split("create_box", 1)[1].split()[0])
    lines = f"create_box {ntypes} box\n" + "\n".join(ln for ln in text.splitlines() if ln.startswith(
        ("fix m", "pair_style", "pair_coeff")) and "${" not in ln)
    if "L04_step" in name:      # e from the step LIGGGHTS reaches: 0.3 + 0.2 * 1000 / 1000
        lines += "\nfix m3 all property/global coefficientRestitution peratomtypepair 1 0.5"
    assert sorted(tuple(p["types"]) for p in last["pairs"]) == [(i, j) for i in sorted(held) for j in sorted(held)
                                                              if i <= j], (last["pairs"], held)
    for r in last["pairs"]:
        (i, j), g = r["types"], r["speeds"][2]
        (ri, di), (rj, dj) = (next(iter(held[t])) for t in (i, j))
        assert len(held[i]) == len(held[j]) == 1, held
        pair = Pair.spheres(ri, rj, di, dj)
        t_c = Contact(r["alpha"], r["gamma"], r["D1"], r["D2"], r["end"]).contact_time(g)
        engine = liggghts_run.liggghts_eps_extrapolated(pair, lines, [g], {g: t_c}, r["gamma"], steps=4000)[g]
        print(name, r["types"], r["eps"][2], engine)
        assert abs(engine[0] / r["eps"][2] - 1) < 1e-6, (r["eps"][2], engine)
    before = LIGGGHTS_DECKS[name]
    status, got, err = _json(path, "--run-budget", "0")
    as_without_runs(status, got, err, before)


@needs_liggghts
@pytest.mark.dem
@pytest.mark.slow
def test_a_deck_the_engine_crashes_on_when_its_runs_are_made_is_refused():
    """Field round 14, L15: LIGGGHTS 3.8.0 crashes (signal 11) on ``fix adapt ... scale yes`` run by
    hand; the audit named the crash of its runs made for real and printed both stages from its
    one-step pass (type 1 at r 1.08e-7, exit 0). A crash making the deck's own runs refuses the deck."""
    status, got, err = _json(FIELD / "field14/decks/L15_adapt_scale_hookestiff/in.deck")
    assert status == 2 and got is None
    assert err.count("\n") == 1 and "LIGGGHTS crashed making the deck's runs for real (Segmentation fault)" in err

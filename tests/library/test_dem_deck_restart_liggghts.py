"""A LIGGGHTS restart across ``clear`` (field round 13, D7, L05): ``write_restart``, ``clear``,
``read_restart`` of the same file, the materials given again with another gamman, then ``set type
2 density 1000``. The audit did not run the write, and LIGGGHTS stopped its pass at the read
("Cannot open restart file"), though LIGGGHTS runs the deck. As for LAMMPS
(test_dem_deck_restart.py), the write now runs into the audit's scratch copy (never beside the
deck) and the reader takes, after the read, what a LIGGGHTS restart stores (measured: the pair
style with its model, groups; not the time step, nor any fix, so the materials must be given again,
as LIGGGHTS stops the next run without them), checked against LIGGGHTS' own ``info``. Each pair of
the stage after the read is LIGGGHTS' own head-on eps at the sizes it holds at the deck's end."""

from pathlib import Path

import pytest

from deck_cli import liggghts_held_at_end, needs_liggghts, run

DECK = Path(__file__).resolve().parents[1] / "field13/decks/L05_write_read_restart/in.deck"


def _contact_lines(text: str) -> str:
    """The deck's materials and pair style as a head-on run takes them."""
    return "create_box 2 box\n" + "\n".join(ln for ln in text.splitlines()
                                            if ln.startswith(("fix m", "pair_style", "pair_coeff")))


@needs_liggghts
@pytest.mark.dem
@pytest.mark.slow
def test_a_liggghts_restart_in_one_deck_is_audited_from_its_settings_after_the_read(tmp_path):
    import json

    from restitution.dem.contact import Contact
    from restitution.dem.engines.liggghts import run as liggghts_run
    from restitution.dem.pair import Pair
    before = sorted(p.name for p in DECK.parent.iterdir())
    status, out, err = run(DECK, "--g", "1", "--json")
    assert status == 0, err
    assert sorted(p.name for p in DECK.parent.iterdir()) == before      # the restart stayed in the scratch
    stages = json.loads(out)["stages"]
    assert [[r["line"] for r in s["runs"]] for s in stages] == [[29], [54]]
    held = liggghts_held_at_end(DECK, tmp_path)
    assert {t: len(s) for t, s in held.items()} == {1: 1, 2: 1}, held
    text = DECK.read_text()
    first, after = text.split("\nread_restart", 1)
    rows = {tuple(r["types"]): r for r in stages[-1]["pairs"]}
    assert sorted(rows) == [(1, 1), (1, 2), (2, 2)]
    for (i, j), r in rows.items():
        assert not r.get("may_differ") and "at" not in r, r
        (ri, di), (rj, dj) = next(iter(held[i])), next(iter(held[j]))
        g = r["speeds"][2]
        t_c = Contact(r["alpha"], r["gamma"], r["D1"], r["D2"], r["end"]).contact_time(g)
        engine = liggghts_run.liggghts_eps_extrapolated(Pair.spheres(ri, rj, di, dj), _contact_lines(after), [g],
                                                        {g: t_c}, r["gamma"], steps=4000)[g]
        print((i, j), r["eps"][2], engine)
        assert abs(engine[0] / r["eps"][2] - 1) < 1e-6, (r["eps"][2], engine)
    # the stage before the read has the first gamman: another eps for the same spheres of type 1
    assert stages[0]["pairs"][0]["types"] == [1, 1] and "gamman peratomtypepair 2 3000" in first
    assert abs(stages[0]["pairs"][0]["eps"][2] - rows[(1, 1)]["eps"][2]) > 0.1


@needs_liggghts
@pytest.mark.dem
@pytest.mark.slow
def test_a_liggghts_restart_with_the_runs_made_reads_its_own_account(tmp_path):
    """After the read, a density set by the step the restart holds: 1000 steps when LIGGGHTS runs
    the deck, 1 in the pass whose runs are one step long. LIGGGHTS makes the runs for real, reads
    the restart its own runs wrote (the account of each pass is its own), and the last stage is at
    the density LIGGGHTS holds at the deck's end."""
    import json
    text = DECK.read_text().replace("set type 2 density 1000", 'if "$(step) > 500" then "set type 2 density 1000"')
    assert text != DECK.read_text()
    (tmp_path / "deck").mkdir()
    path = tmp_path / "deck" / "in.deck"
    path.write_text(text)
    status, out, err = run(path, "--g", "1", "--json")
    assert status == 0 and "LIGGGHTS made the deck's 2 runs" in err, err
    held = liggghts_held_at_end(path, tmp_path)
    assert [(r, pytest.approx(rho, rel=1e-9)) for r, rho in held[2]] == [(0.003, 1000.0)], held
    last = {tuple(r["types"]): r for r in json.loads(out)["stages"][-1]["pairs"]}
    one = json.loads(run(DECK, "--g", "1", "--json")[1])["stages"][-1]["pairs"]
    # the same spheres and contacts as the deck that sets the density unconditionally (checked
    # against LIGGGHTS head-on above)
    assert [last[tuple(r["types"])]["eps"] for r in one] == [r["eps"] for r in one]

"""Pours in a loop (field round 13, a06): a ``variable k loop 3`` pours type 1, then type 2 twice,
one ``fix ins ... pour`` line, its stiffness changed each pass, so each pass is a stage. Before,
stderr said "type 2 is inserted by a fix (deposit) as the runs go, at sizes the audit does not
read: its pairs are not audited", where the fix is a pour, type 2 merely has no atom before its
first pour, and its pairs are audited; and the three stages' headings all said "the run at line
21", not which pass of the loop each is."""

import json
from pathlib import Path

import pytest

from deck_cli import needs_lammps, run

DECK = Path(__file__).resolve().parents[1] / "field13/decks/a06_pours_in_loop_stages/in.deck"


@needs_lammps
@pytest.mark.dem
def test_a_type_poured_at_a_later_pass_is_named_by_its_pour():
    status, out, err = run(DECK, "--g", "1")
    assert status == 0, err
    assert "deposit" not in err and "is inserted by" not in err, err
    assert ("type 2 has no particle at some runs (those before fix ins (pour) makes its atoms): its sphere pairs "
            "cannot happen there and are not audited") in err, err
    heads = [ln for ln in out.splitlines() if ln.startswith("# stage")]
    assert heads == ["# stage 1 of 3: the contact settings of the run at line 21 (pass 1)",
                     "# stage 2 of 3: the contact settings of the run at line 21 (pass 2)",
                     "# stage 3 of 3: the contact settings of the runs at line 21 (pass 3), line 25"], heads
    status, out, _ = run(DECK, "--g", "1", "--json")
    stages = json.loads(out)["stages"]
    assert [[r.get("pass") for r in s["runs"]] for s in stages] == [[1], [2], [3, None]]
    # type 2's pairs are audited from its first pour on
    assert [sorted({tuple(p["types"]) for p in s["pairs"]}) for s in stages] == [
        [(1, 1)], [(1, 1), (1, 2), (2, 2)], [(1, 1), (1, 2), (2, 2)]]


@needs_lammps
@pytest.mark.dem
def test_many_passes_of_one_run_are_said_as_a_span():
    """A loop of ``run 500`` until an energy falls (a30): 13 passes, one stage, said once."""
    status, out, err = run(DECK.parents[1] / "a30_pe_energy_threshold_loop/in.deck", "--g", "1")
    assert status == 0, err
    heads = [ln for ln in out.splitlines() if ln.startswith("# stage")]
    assert heads[0] == "# stage 1 of 2: the contact settings of the runs at line 22 (passes 1 to 13)", heads

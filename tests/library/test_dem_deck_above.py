"""Files a deck names above its folder (R2), as CFDEM cases do (``read_data ../DEM/data.txt``,
``include ../common.in``): the scratch held the deck's folder alone, so such decks were refused. What
the deck names there is copied at the same place relative to the copy (its lines made safe as the
deck's: a shell line there is not run), never written beside the user's files; a file further up
than MAX_UP folders is refused in one line. The eps are checked against LAMMPS head-on."""

import json

import pytest

from deck_cli import agrees_with_lammps, needs_lammps, run
from restitution.dem.deck.scratch import MAX_UP

SIZES = {1: (0.005, 2500.0), 2: (0.003, 7000.0)}
DATA = """data

2 atoms
2 atom types

0 1 xlo xhi
0 1 ylo yhi
0 1 zlo zhi

Atoms # sphere

1 1 0.01 2500 0.3 0.5 0.5
2 2 0.006 7000 0.6 0.5 0.5
"""
LINES = """pair_coeff * * hertz 1e6 300 damping mass_velocity tangential linear_nohistory 1 0.3
pair_coeff 1 2 hooke 1e4 20 damping mass_velocity tangential linear_nohistory 1 0.3
"""
DECK = """units si
atom_style sphere
comm_modify vel yes
read_data ../DEM/data.txt
include {include}
fix 1 all nve/sphere
timestep 1e-6
run 10
"""


def _case(root):
    (root / "CFD").mkdir(parents=True)
    (root / "DEM").mkdir()
    (root / "DEM" / "data.txt").write_text(DATA)
    (root / "common.in").write_text("shell touch pwned\npair_style granular\n" + LINES)
    return root / "CFD" / "in.deck"


@needs_lammps
@pytest.mark.dem
def test_files_named_above_the_decks_folder_are_copied_and_audited(tmp_path):
    """Before: LAMMPS stops (the data file is not in the copy). Each pair against LAMMPS head-on."""
    deck = _case(tmp_path)
    deck.write_text(DECK.format(include="../common.in"))
    before = sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*"))
    status, out, err = run(deck, "--g", "0.5", "--json")
    assert status == 0, err
    assert sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*")) == before     # nothing written there
    assert "shell (../common.in line 1 and any like it): not executed" in err, err
    rows = json.loads(out)["pairs"]
    assert [r["types"] for r in rows] == [[1, 1], [1, 2], [2, 2]]
    agrees_with_lammps(rows, SIZES, LINES, 2)


@needs_lammps
@pytest.mark.dem
def test_a_file_further_up_than_the_limit_is_refused_in_one_line(tmp_path):
    far = tmp_path.joinpath(*["d"] * MAX_UP)
    deck = _case(far)
    (tmp_path / "common.in").write_text("pair_style granular\n" + LINES)
    deck.write_text(DECK.format(include="../" * (MAX_UP + 1) + "common.in"))
    status, out, err = run(deck, "--g", "0.5")
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and f"{MAX_UP + 1} folders above the deck's" in err, err

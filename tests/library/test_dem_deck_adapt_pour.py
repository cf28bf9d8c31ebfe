"""A fix pour beside a fix adapt of a constant diameter, and a pour unfixed: which sizes the type
holds in LAMMPS (22 Jul 2025, runs made for real, hertz with mass_velocity damping, whose eps
depends on size):

- adapt 0 on group all: after the first run the atom created has the adapted radius 0.003, the 269
  poured the pour's 0.005; at the second run's set-up all 270 are resized, the 131 poured in it keep
  0.005. adapt 10: every atom has radius 0.003 after each run. The audit held both sizes but said
  of the adapt "its size is not computed" beside the eps it printed (eps_engine None).
- pour, run, ``set type 1 diameter 0.006``, unfix, run: every atom has radius 0.003 (density 2500
  (5/3)^3, the mass kept); the audit kept the unfixed pour's 0.005 as the small-eps end of a range
  (0.63330, where the run's atoms give 0.60073).
- pour, unfix, run: nothing is poured; the audit gave the type the pour's size beside the atom's.
- adapt 0 beside a pour, run, unfix the pour, run: every atom has radius 0.003 in the second run;
  the audit kept the pour's 0.005.
"""

import pytest

from deck_cli import agrees_with_lammps, audit, lammps_pour, needs_lammps

LINE = "pair_coeff * * hertz 1e6 300 damping mass_velocity tangential linear_nohistory 1 0.3"
DECK = "variable d equal 2*0.003\ntimestep 1e-5\n{rest}\n"


def _audit(tmp_path, rest: str, first: float = 0.01):
    deck = lammps_pour(LINE, sphere=(1, first, 2500.0), dynamic=True) + DECK.format(rest=rest)
    (tmp_path / "in.deck").write_text(deck)
    return audit(tmp_path / "in.deck", "--g", "0.5")


def _sizes(rows: list) -> list:
    return sorted({tuple(s) for r in rows for s in r.get("at", [])})


def _check(rows: list) -> None:
    """Each row against LAMMPS head-on at the spheres it names (``at``), or the one size given."""
    for r in rows:
        (a, b) = r["at"]
        agrees_with_lammps([{**r, "types": [1, 2]}], {1: tuple(a), 2: tuple(b)}, LINE, 2)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("every", [0, 10])
def test_a_constant_adapt_beside_a_pour_is_followed_and_said_so(tmp_path, every):
    got, err = _audit(tmp_path, f"fix ad all adapt {every} atom diameter v_d\nrun 1000\nrun 1000")
    rows = got["stages"][-1]["pairs"]
    assert _sizes(rows) == [(0.003, 2500.0), (0.005, 2500.0)], _sizes(rows)
    for r in rows:
        (entry,) = [b for b in r["beside"] if b["style"] == "adapt"]
        assert entry["eps_engine"] == r["eps"] and "not computed" not in entry["why"], entry["why"]
        assert "pour's size until the adapt resizes them" in entry["why"], entry["why"]
    _check(rows)


@needs_lammps
@pytest.mark.dem
def test_a_pour_unfixed_after_a_set_adds_its_size_no_more(tmp_path):
    """Before: a range whose small-eps end was the pour's radius 0.005 (0.63330, exit 0)."""
    got, err = _audit(tmp_path, "run 1000\nset type 1 diameter 0.006\nunfix p\nrun 1000")
    (row,) = got["stages"][-1]["pairs"]
    assert "at" not in row and row["overlap_limit"] == pytest.approx(0.006, rel=1e-12), row.get("at")
    rho = 2500 * (0.005 / 0.003) ** 3
    agrees_with_lammps([row], {1: (0.003, rho)}, LINE, 1)


@needs_lammps
@pytest.mark.dem
def test_a_pour_unfixed_before_any_run_pours_nothing(tmp_path):
    """Before: the type held the pour's radius 0.005 beside the created atom's 0.004."""
    got, err = _audit(tmp_path, "unfix p\nrun 1000", first=0.008)
    (row,) = got["pairs"]
    assert "at" not in row and row["overlap_limit"] == pytest.approx(0.008, rel=1e-12), row.get("at")


@needs_lammps
@pytest.mark.dem
def test_poured_atoms_resized_by_a_later_set_up_leave_the_pours_size_behind(tmp_path):
    """adapt 0: the second run's set-up resizes the atoms poured in the first; the pour unfixed
    before it, the type holds the adapted size alone (before: a range with the pour's 0.005)."""
    got, err = _audit(tmp_path, "fix ad all adapt 0 atom diameter v_d\nrun 1000\nunfix p\nrun 1000")
    (row,) = got["stages"][-1]["pairs"]
    assert "at" not in row and row["overlap_limit"] == pytest.approx(0.006, rel=1e-12), row.get("at")
    agrees_with_lammps([row], {1: (0.003, 2500.0)}, LINE, 1)

"""A fix adapt that sets the atoms' diameter from a constant equal-style variable: LAMMPS sets it at
the run's set-up (N = 0) or every N steps, the engine's pass holds the adapted size (set up by its
marker), and the audit uses it; its note said "its size is not computed" all the same. With
``reset yes`` LAMMPS puts the sizes back when the run ends, before the marker writes the atoms: the
audit printed eps 0.63330 at the original diameter 0.01 with exit 0, where the run has 0.006
(0.76526); it was refused next, and is now read at the run's set-up, where the run's sizes are.
Measured in LAMMPS 22 Jul 2025."""

import pytest

from deck_cli import agrees_with_lammps, audit, lammps_spheres, needs_lammps

LINE = "pair_coeff * * hertz 1e6 300 damping mass_velocity tangential linear_nohistory 1 0.3"
DECK = lammps_spheres((0.01, 2500.0)).replace("atom_style sphere", "atom_style sphere 1") + LINE + """
variable d equal {value}
fix ad all adapt {every} atom diameter v_d{keys}
timestep 1e-6
run 100
"""


def _deck(tmp_path, value="0.006", every=0, keys=""):
    tmp_path.mkdir(parents=True, exist_ok=True)
    (tmp_path / "in.deck").write_text(DECK.format(value=value, every=every, keys=keys))
    return tmp_path / "in.deck"


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("every", [0, 10])
def test_a_constant_diameter_is_audited_at_the_adapted_size_and_said_so(tmp_path, every):
    """LAMMPS keeps the density (adapt's mass yes): radius 0.003, density 2500, head-on."""
    got, err = audit(_deck(tmp_path, every=every), "--g", "0.5")
    (row,) = got["pairs"]
    assert row["overlap_limit"] == pytest.approx(0.006, rel=1e-12)
    agrees_with_lammps([row], {1: (0.003, 2500.0)}, LINE, 1)
    (note,) = [ln for ln in err.splitlines() if "fix adapt" in ln]
    assert "not computed" not in note and "leaves the eps the engine measures the contact's" in note, note
    assert "v_d = 0.006" in note and row["beside"][0]["eps_engine"] == row["eps"]


@needs_lammps
@pytest.mark.dem
def test_a_diameter_that_may_change_as_the_run_goes_is_not_computed(tmp_path):
    """A diameter that grows as the run goes may bring a pair within reach of lists built with the
    smaller spheres (field round 30, A13: LAMMPS 0.721610 where the audit printed 0.414916): the
    pair is named, not audited."""
    got, err = audit(_deck(tmp_path, value="0.006+1e-6*step"), "--g", "0.5")
    assert got["pairs"] == [] and "fix ad adapt sizes the spheres of type 1" in err, err


@needs_lammps
@pytest.mark.dem
def test_an_adapt_on_a_group_the_audit_cannot_type_names_the_group(tmp_path):
    """Field round 39, D12: an adapt on an ID group of a type 2 sphere was said to size "type 1"."""
    deck = _deck(tmp_path, value="0.006+1e-6*step")
    deck.write_text(deck.read_text().replace("fix ad all adapt", "group one id 1\nfix ad one adapt"))
    got, err = audit(deck, "--g", "0.5")
    assert got["pairs"] == [] and "fix ad adapt sizes the spheres of group one after" in err, err


@needs_lammps
@pytest.mark.dem
def test_sizes_put_back_after_the_run_are_read_as_the_run_sees_them(tmp_path):
    """Before: eps at the original diameter 0.01, exit 0; then refused. LAMMPS' marker now dumps the
    atoms at the run's set-up, where the adaptation stands: the rows are those of reset no, whose
    sizes LAMMPS keeps after the run (radius 0.003, density 2500, checked head-on above)."""
    put_back, _ = audit(_deck(tmp_path / "yes", keys=" reset yes"), "--g", "0.5")
    kept, _ = audit(_deck(tmp_path / "no"), "--g", "0.5")
    assert [(r["types"], r["eps"], r["overlap_limit"]) for r in put_back["pairs"]] == \
        [(r["types"], r["eps"], r["overlap_limit"]) for r in kept["pairs"]]
    assert put_back["pairs"][0]["overlap_limit"] == pytest.approx(0.006, rel=1e-12)

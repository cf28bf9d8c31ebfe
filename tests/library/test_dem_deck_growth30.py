"""Field round 30's classes, each measured here in LAMMPS 22 Jul 2025 running the deck as written.

G: a growth before ``run N pre no`` that the sizes a type holds do not show: one sphere grown to the
size another of its type already has while a third keeps the old one, two swapping sizes, or a
sphere retyped into a type that held no atom at the last set-up. LAMMPS' lists, built with the old
radius, meet the pair late (G01: 0.841701 where the audit printed 0.414916). The audit now reads the
atoms one by one, by ID, and leaves the pairs of such a run out with the reason.
R: ``neigh_modify exclude type 1 2``, then a retype out of the pair before ``run N pre no``: the
lists built with the exclusion hold no pair of the retyped sphere (R09: 0.841701).
A: ``fix adapt`` of atom diameter: LAMMPS builds a run's lists at its set-up before the fix sizes the
spheres, so a pair a growth brings within reach is met late (A01: 1.591978 where the audit printed
0.370354)."""

import pytest

from deck_cli import HEAD_ON, audit, lammps_separation_speed, needs_lammps

LAW = "pair_coeff * * hooke 2000 300 damping mass_velocity tangential linear_nohistory 1 0.3"


def _apart(types: int = 2) -> str:
    """Two 1 cm spheres 15.5 mm apart (out of each other's lists: their radii and the 1 mm skin
    reach 11 mm), approaching at 1 m/s, and two still type-2 spheres far off, of 2 cm and 1 cm: a
    type-2 sphere grown to 2 cm leaves the sizes type 2 holds the same set."""
    deck = HEAD_ON.format(line=LAW).replace("single -0.0051 0 0", "single -0.00775 0 0")
    deck = deck.replace("single 0.0051 0 0", "single 0.00775 0 0").replace("create_box 2 box", f"create_box {types} box")
    return deck + ("create_atoms 2 single 0 0.03 0\ncreate_atoms 2 single 0 -0.03 0\n"
                   "set atom 3 diameter 0.02 density 2500\nset atom 4 diameter 0.01 density 2500\n")


def _left_out(deck: str, tmp_path, pair: list, why: str) -> None:
    """The audit leaves ``pair`` out of the deck's last stage, saying ``why``; LAMMPS, running the
    deck as written, meets the pair late: far from the eps the same deck without pre no gives."""
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert pair not in [r["types"] for r in got["stages"][-1]["pairs"]], (got["stages"][-1]["pairs"], err)
    assert why in err, err
    late = lammps_separation_speed(deck, tmp_path)
    in_time = lammps_separation_speed(deck.replace(" pre no", ""), tmp_path)
    assert abs(late - in_time) > 0.1, (late, in_time)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("change", ["set atom 2 diameter 0.02 density 2500",
                                    "set atom 2 diameter 0.02 density 2500\nset atom 3 diameter 0.01 density 2500"])
def test_a_growth_the_sizes_of_its_type_hide_before_pre_no_leaves_the_pair_out(tmp_path, change):
    """A growth to a size the type already holds, while another sphere keeps the old one (G01), and
    two spheres swapping sizes (G03)."""
    _left_out(_apart() + f"run 1\n{change}\nrun 40000 pre no\n", tmp_path, [1, 2], "pre no after type 2")


@needs_lammps
@pytest.mark.dem
def test_a_sphere_retyped_into_an_empty_type_and_grown_before_pre_no_leaves_the_pair_out(tmp_path):
    """G04: type 3 held no atom at the last set-up, so no size of it could show a growth."""
    _left_out(_apart(3) + "run 1\nset atom 2 type 3 diameter 0.02 density 2500\nrun 40000 pre no\n", tmp_path,
              [1, 3], "pre no after type 3")


@needs_lammps
@pytest.mark.dem
def test_a_sphere_retyped_out_of_an_excluded_pair_before_pre_no_leaves_the_pair_out(tmp_path):
    """R09: the lists built with the exclusion hold no pair of the sphere retyped out of it; the
    spheres 10.5 mm apart, in each other's reach but for the exclusion."""
    deck = _apart(3).replace("single -0.00775 0 0", "single -0.00525 0 0").replace("single 0.00775 0 0",
                                                                                  "single 0.00525 0 0")
    deck = deck.replace("run 1\n", "") + "neigh_modify exclude type 1 2\nrun 1\nset atom 2 type 3\nrun 40000 pre no\n"
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert [1, 3] not in [r["types"] for r in got["stages"][-1]["pairs"]], (got["stages"][-1]["pairs"], err)
    assert "retyped where an exclusion is in force" in err, err
    # LAMMPS as written: the pair passes through, or is met late
    late = lammps_separation_speed(deck, tmp_path)
    assert abs(late - lammps_separation_speed(deck.replace(" pre no", ""), tmp_path)) > 0.1, late


@needs_lammps
@pytest.mark.dem
def test_a_fix_adapt_growing_spheres_after_the_lists_are_built_leaves_their_pairs_out(tmp_path):
    """A01: at the run's set-up the lists are built with 1 cm spheres, then the adapt makes type 2
    2 cm wide, 0.5 mm from touching: LAMMPS meets the pair late."""
    deck = _apart().replace("atom_style sphere\n", "atom_style sphere 1\n")     # radii that may change
    deck += "variable dd equal 0.02\ngroup two id 2\nfix ad two adapt 0 atom diameter v_dd reset no\nrun 40000\n"
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert [1, 2] not in [r["types"] for r in got["stages"][-1]["pairs"]], (got["stages"][-1]["pairs"], err)
    assert "fix ad adapt sizes the spheres" in err, err
    grown_first = deck.replace("fix ad two adapt", "set atom 2 diameter 0.02\nfix ad two adapt")
    assert abs(lammps_separation_speed(deck, tmp_path) - lammps_separation_speed(grown_first, tmp_path)) > 0.1


@needs_lammps
@pytest.mark.dem
def test_a_sphere_made_at_a_new_id_before_pre_no_larger_than_its_type_held_leaves_the_pair_out(tmp_path):
    """Field round 31, SW-G: lv2 deleted (compress no) and made again at a new ID, of the 2 cm a
    still sphere of its type already had: the sizes the type holds and every old ID look unchanged,
    the first touch was printed; LAMMPS' lists, built before the sphere was made, meet it late."""
    remade = ("run 1\ngroup two id 2\ndelete_atoms group two compress no\ncreate_atoms 2 single 0.00775 0 0\n"
              "set atom 5 diameter 0.02 density 2500\nset atom 5 vx -0.5\nrun 40000 pre no\n")
    deck = _apart() + remade
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert [1, 2] not in [r["types"] for r in got["stages"][-1]["pairs"]], (got["stages"][-1]["pairs"], err)
    assert "pre no after type 2" in err, err

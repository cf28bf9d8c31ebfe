"""Two integrators on the same atoms (field round 9, D3 / c29: ``fix 1 all nve/sphere`` and ``fix 2
all nve/sphere``): each advances the atoms by a whole step, so a contact lasts half the steps, and
the eps at the deck's time step is not one integrator's (LAMMPS, hooke at dt 4e-5: 0.8290 with the
two, 0.7335 with one, which the audit stated on stderr). Now the steps per contact are halved, no
eps at the deck's time step is stated, and stderr says why; at dt -> 0 the eps is one integrator's
(LAMMPS with the two: 0.7345665, the audit's 0.7345668)."""

import pytest

from deck_cli import audit, lammps_spheres, needs_lammps

LINE = "pair_coeff * * hooke 1e4 0.5 damping velocity tangential linear_nohistory 0 0"


@needs_lammps
@pytest.mark.dem
def test_a_type_integrated_twice_states_no_eps_at_the_decks_step(tmp_path):
    deck = lammps_spheres((0.01, 2500.0)).replace("fix integrate all nve/sphere\n", "")
    (tmp_path / "in.deck").write_text(deck + LINE + "\nfix 1 all nve/sphere\nfix 2 all nve/sphere\n"
                                      "timestep 4e-5\nrun 100\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    row, = got["pairs"]
    assert row["eps"][2] == pytest.approx(0.7345667552, abs=1e-9)
    assert row["steps_per_contact"][2] == pytest.approx(10.09, abs=0.01)       # 20.2 with one integrator
    assert all(e is None for e in row["eps_at_dt"]) and all(w is None for w in row["dt_within_tol"])
    assert "integrated 2 times each step" in err and "eps there" not in err and "not stated" in err, err


@needs_lammps
@pytest.mark.dem
def test_two_types_integrated_a_different_number_of_times_are_not_audited_together(tmp_path):
    deck = lammps_spheres((0.01, 2500.0), (0.01, 2500.0)).replace("fix integrate all nve/sphere\n", "")
    (tmp_path / "in.deck").write_text(deck + LINE + "\ngroup two type 2\nfix 1 all nve/sphere\n"
                                      "fix 2 two nve/sphere\ntimestep 1e-6\nrun 100\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert [r["types"] for r in got["pairs"]] == [[1, 1], [2, 2]]
    assert "types 1 2: integrated a different number of times each step" in err, err
    assert "eps at dt -> 0 is one integrator's" in err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("group", ["group two id 2", "region r block 0.4 0.6 -0.1 0.1 -0.1 0.1\ngroup two region r"],
                         ids=["by id", "by region"])
@pytest.mark.parametrize("second", ["nve/sphere", "move linear -0.1 0 0"])
def test_a_second_integrator_on_a_group_the_audit_cannot_type_leaves_its_pairs_out(tmp_path, group, second):
    """Field round 32, F13 F16 F21 (LIGGGHTS L11): fix nve/sphere on all and a second on a group made
    by ID or region, which the audit cannot type: the pair was printed with the untyped group's note
    ('a sphere outside the group never moves'), while the group's spheres are advanced twice a step
    (LAMMPS 0.323422 where one integrator gives 0.413435); I05, fix move linear on lv2 beside the
    integrator: LAMMPS 0.465219. Every pair of a type both may move is left out with the reason."""
    deck = lammps_spheres((0.01, 2500.0), (0.01, 2500.0)).replace("fix integrate all nve/sphere\n", "")
    (tmp_path / "in.deck").write_text(deck + LINE + f"\n{group}\nfix 1 all nve/sphere\nfix 2 two {second}\n"
                                      "timestep 1e-6\nrun 100\n")
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert got["pairs"] == [], got["pairs"]
    assert "types 1 2: fix 1 (group all), fix 2 (group two) may each move type 1's spheres" in err, err
    assert "advanced twice a step" in err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("grown", [False, True], ids=["apart", "lid grown after"])
def test_groups_made_apart_by_subtract_are_moved_once_each(tmp_path, grown):
    """Field round 33, M12 (a modeller's lid): a lid picked by region and moved by fix move, the rest
    integrated as ``group mobile subtract all lid``: no sphere is in both, and LAMMPS meets the pair
    as one integrator gives (0.413435), where the audit left every pair out. A group command that
    adds to the lid afterwards may put a mobile sphere in it: left out again."""
    deck = lammps_spheres((0.01, 2500.0), (0.01, 2500.0)).replace("fix integrate all nve/sphere\n", "")
    deck += (LINE + "\nregion top block -0.1 0.1 -0.1 0.1 0.5 0.6\ngroup lid region top\n"
             "group mobile subtract all lid\n" + ("group lid type 1\n" if grown else "")
             + "fix 1 mobile nve/sphere\nfix 2 lid move linear 0 0 0\ntimestep 1e-6\nrun 100\n")
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert ([1, 2] in [r["types"] for r in got["pairs"]]) is not grown, (got["pairs"], err)
    assert ("may each move type 1's spheres" in err) is grown, err

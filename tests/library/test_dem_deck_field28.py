"""Field round 28's classes, each measured here in LAMMPS 22 Jul 2025 running the deck as written.

Q: ``run N pre no`` after a sphere grew. LAMMPS does not build its neighbour lists again at such a
run, so lists built with the smaller radii meet the pair late, deep in overlap (Q01: 0.841701 where
the audit printed 0.414916). The grown type's pairs of such a run are now left out with the reason
(walls use no list); a ``neighbor`` skin changed before it is refused, as a changed coefficient is
(Q46: not read by LAMMPS).
N: where a pair_style granular cutoff may leave a pair out, the neighbour lists' reach (the largest
cutoff plus the skin) is each run's own: a skin set after the first run was read as the first's
(N19: a pair LAMMPS met 8.09 deep was printed as met at first touch; N15 the other way). A
``neighbor ... nsq`` list has no bins: it takes every pair within the radii plus the skin, so in a
box with no periodic boundary a small cutoff leaves no pair out on one process (N01); on several
it misses a pair across two sub-domains (round 34), and the pair is left out.
R: ``set ... type/fraction`` after a run draws each atom with a seed made from its position, which
the pass (its runs skipped) does not know (R22, R25: the other atom retyped); such a deck now has its
runs made for real first."""

import pytest

from deck_cli import HEAD_ON, audit, audited_and_measured, lammps_separation_speed, needs_lammps, run

LAW = "pair_coeff * * hooke 2000 300 damping mass_velocity tangential linear_nohistory 1 0.3"


def _grown(pre: str) -> str:
    """Two 1 cm spheres 15.5 mm apart (out of each other's lists: their radii and the 1 mm skin reach
    11 mm), approaching at 1 m/s; after one step type 2 is made 2 cm wide, so they touch after a
    further 0.5 mm, before either has moved the half skin that makes LAMMPS build its lists again."""
    deck = HEAD_ON.format(line=LAW).replace("single -0.0051 0 0", "single -0.00775 0 0")
    return deck.replace("single 0.0051 0 0", "single 0.00775 0 0") + \
        f"run 1\nset type 2 diameter 0.02\nrun 40000 pre {pre}\n"


@needs_lammps
@pytest.mark.dem
def test_a_run_with_pre_no_after_a_sphere_grew_leaves_its_pairs_out_as_lammps_meets_them_late(tmp_path):
    """With pre yes the audit's eps is LAMMPS'; with pre no LAMMPS' lists still hold the small
    sphere and meet the pair deep in overlap: the audit leaves the grown type's pairs of that run
    out, saying why (its other pairs and walls stay audited)."""
    (tmp_path / "in.deck").write_text(_grown("yes"))
    got, _ = audit(tmp_path / "in.deck", "--g", "1")
    row = next(r for r in got["pairs"] if r["types"] == [1, 2])
    set_up = lammps_separation_speed(_grown("yes"), tmp_path)
    assert abs(row["eps"][0] - set_up) < 1e-4, (row["eps"], set_up)
    late = lammps_separation_speed(_grown("no"), tmp_path)
    assert abs(late - set_up) > 0.05, (late, set_up)
    (tmp_path / "in.deck").write_text(_grown("no"))
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert [r["types"] for r in got["stages"][-1]["pairs"]] == [[1, 1]], got["stages"][-1]     # 1 1: lone
    assert "types 1 2: line 20 (run 40000 pre no): pre no after type 2 came to hold spheres larger" in err, err


@needs_lammps
@pytest.mark.dem
def test_a_shrink_before_a_run_with_pre_no_is_audited(tmp_path):
    """A sphere made smaller keeps every pair the lists held: LAMMPS meets it at first touch."""
    deck = HEAD_ON.format(line=LAW) + "run 1\nset type 2 diameter 0.009\nrun 40000 pre no\n"
    eps, measured, err = audited_and_measured(deck, tmp_path)
    assert abs(eps - measured) < 1e-4, (eps, measured, err)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("given", ["neighbor 0.005 bin", "neighbor 0.001 nsq", "neighbor 0.001 bin"])
def test_a_skin_changed_before_a_run_with_pre_no_is_refused_only_where_a_cutoff_makes_it_count(tmp_path, given):
    """LAMMPS reads a new skin or list style only when it sets a run up, which pre no skips: its lists
    keep the last set-up's reach, which holds every contact where no cutoff is set (field round 29,
    Q28, Q29: refused, though LAMMPS met the pair at first touch); with a cutoff the reach decides."""
    eps, measured, err = audited_and_measured(HEAD_ON.format(line=LAW) + f"run 1\n{given}\nrun 40000 pre no\n",
                                              tmp_path)
    assert abs(eps - measured) < 1e-4, (eps, measured, err)
    (tmp_path / "in.deck").write_text(_cut(f"neighbor 0.01 bin\nrun 1\n{given}\nrun 40000 pre no\n"))
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and "pre no after a contact setting changed" in err, err


def _cut(lines: str, boundary: str = "") -> str:
    return HEAD_ON.format(line=LAW + " cutoff 0.001").replace("units si\n", f"units si\n{boundary}") + lines


@needs_lammps
@pytest.mark.dem
def test_each_run_reaches_as_far_as_its_own_skin(tmp_path):
    """Cutoff 0.001 on 1 cm spheres: a skin of 0.01 reaches them (0.011), one of 0.001 does not
    (0.002). Made small after the first run, the pair of the second is left out with the reach
    that run has; made large, the second run's pair is met at first touch (LAMMPS' eps)."""
    (tmp_path / "in.deck").write_text(_cut("neighbor 0.01 bin\nrun 1\nneighbor 0.001 bin\nrun 30000\n"))
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert [[1, 2] in [r["types"] for r in s["pairs"]] for s in got["stages"]] == [True, False], got["stages"]
    assert "reach the largest cutoff plus the skin (0.002)" in err, err
    deck = _cut("neighbor 0.001 bin\nrun 1\nneighbor 0.01 bin\nrun 30000\n")
    eps, measured, err = audited_and_measured(deck, tmp_path)
    assert abs(eps - measured) < 1e-4, (eps, measured, err)


@needs_lammps
@pytest.mark.dem
def test_an_nsq_list_short_of_the_contact_is_left_out_in_any_box(tmp_path):
    """An nsq list in a box with no periodic boundary meets the pair at first touch on one process
    (field round 28, N01), but on two (processors 2 1 1: the spheres in two sub-domains, held
    through ghost atoms that reach the cutoff and skin only) never (field round 34: they pass
    through each other). The audit, which cannot know how many processes run the deck, leaves the
    pair out with the reason, as across a periodic boundary."""
    deck = _cut("neighbor 0.001 nsq\nrun 30000\n", boundary="boundary f f f\n")
    one = lammps_separation_speed(deck, tmp_path)
    two = lammps_separation_speed(deck.replace("units si\n", "units si\nprocessors 2 1 1\n"), tmp_path, processes=2)
    assert abs(two - one) > 0.1, (one, two)
    for boundary in ("boundary f f f\n", ""):
        (tmp_path / "in.deck").write_text(_cut("neighbor 0.001 nsq\nrun 30000\n", boundary=boundary))
        status, out, err = run(tmp_path / "in.deck", "--g", "1")
        assert status == 2 and out == "" and "two processes' sub-domains" in err, err      # no pair audited


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("before", ["", "boundary p p p\n"])
def test_a_box_read_from_a_restart_has_the_files_boundary(tmp_path, before):
    """Field round 29, N11 and N25: a restart of a box with no periodic boundary was read as periodic
    (the default after clear, or a boundary given before the read); the boundary is the file's, as
    LAMMPS' info says. With the pair style given again after the read and no cutoff short of the
    contact, LAMMPS meets the pair at first touch and the audit prints it."""
    again = (f"write_restart a.rst\nclear\n{before}read_restart a.rst\ncomm_modify vel yes\n"
             "pair_style granular\nfix integrate all nve/sphere\ntimestep 1e-7\nrun 30000\n")
    deck = HEAD_ON.format(line=LAW).replace("units si\n", "units si\nboundary f f f\n") + again
    eps, measured, err = audited_and_measured(deck, tmp_path)
    assert abs(eps - measured) < 1e-4, (eps, measured, err)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("first", ["neigh_modify every 2000000 delay 0 check no", "neigh_modify once yes",
                                   "neigh_modify delay 2000000"])
def test_a_later_run_rebuilds_its_lists_as_its_own_neigh_modify_says(tmp_path, first):
    """A first run whose lists may find the pair late (a rebuild every 2e6 steps unlooked: above
    5 mm/s at this skin and step; once; a long delay) made the later runs' pair go without an eps
    too (field round 28, N41, N47, N48): the later run, rebuilding every step, meets it at first touch."""
    deck = HEAD_ON.format(line=LAW) + f"{first}\nrun 1\nneigh_modify every 1 delay 0 check yes once no\nrun 40000\n"
    eps, measured, err = audited_and_measured(deck, tmp_path)
    assert abs(eps - measured) < 1e-4, (eps, measured, err)


def _drawn(seed: int) -> str:
    """Two spheres of type 1 meet in the second run; between the runs one of them may be drawn into
    type 2 (a fraction of a half, by the seed), whose pair with type 1 is stiffer."""
    deck = HEAD_ON.format(line=LAW).replace("create_atoms 2 single", "create_atoms 1 single")
    deck = deck.replace("set type 2 diameter 0.01 density 2500\n", "")
    return deck + (f"pair_coeff 1 2 hooke 8000 300 damping mass_velocity tangential linear_nohistory 1 0.3\n"
                   f"run 1000\nset group all type/fraction 2 0.5 {seed}\nrun 40000\n")


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("seed", [2, 5, 11])
def test_a_type_fraction_after_a_run_retypes_the_atoms_lammps_retypes(tmp_path, seed):
    """The audit's last stage holds the one pair LAMMPS' draw makes (a 1 2 pair under kn 8000 where
    one sphere was drawn, 1 1 or 2 2 under kn 2000 where none or both were): its eps is the one
    LAMMPS measures."""
    deck = _drawn(seed)
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    measured = lammps_separation_speed(deck, tmp_path)
    rows = [r for r in got["stages"][-1]["pairs"] if not r.get("lone")]    # not a type's one sphere with itself
    assert len(rows) == 1 and abs(rows[0]["eps"][0] - measured) < 1e-4, (rows, measured, err)


def _later(lines: str) -> str:
    """The head-on pair 0.5 mm apart, meeting after 5000 steps (in the deck's second run)."""
    deck = HEAD_ON.format(line=LAW).replace("single -0.0051 0 0", "single -0.00525 0 0")
    return deck.replace("single 0.0051 0 0", "single 0.00525 0 0") + lines


@needs_lammps
@pytest.mark.dem
def test_a_variable_redefined_from_the_step_in_an_every_is_read_as_lammps_reads_it(tmp_path):
    """V63: defined before the run, redefined from $(step) between its parts, the variable's value
    after the run was read as the pass's step 0 (kn 8000 printed, LAMMPS ran kn 5000): the read after
    the run now has the runs made."""
    law = LAW.split(None, 3)[3]
    deck = _later(f'variable s equal 1\nrun 3000 every 1000 "variable s equal $(step)"\n'
                  f'if "${{s}} == 3000" then "pair_coeff 1 2 {law.replace("2000", "5000")}" '
                  f'else "pair_coeff 1 2 {law.replace("2000", "8000")}"\nrun 40000\n')
    eps, measured, err = audited_and_measured(deck, tmp_path)
    assert abs(eps - measured) < 1e-3, (eps, measured, err)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("line", ["include k$(step).in", "variable n equal step\ninclude k${n}.in"])
def test_a_file_named_from_the_step_after_a_run_is_the_one_lammps_reads(tmp_path, line):
    """V81, V78: an include named from the step after a run read k0.in in the pass (runs skipped),
    k3000.in in LAMMPS; an include was not among the commands whose reads make the runs for real."""
    law = LAW.split(None, 3)[3]
    (tmp_path / "k0.in").write_text(f"pair_coeff 1 2 {law.replace('2000', '8000')}\n")
    (tmp_path / "k3000.in").write_text(f"pair_coeff 1 2 {law.replace('2000', '5000')}\n")
    deck = _later(f"run 3000\n{line}\nrun 40000\n")
    eps, measured, err = audited_and_measured(deck, tmp_path)
    assert abs(eps - measured) < 1e-3, (eps, measured, err)


@needs_lammps
@pytest.mark.dem
def test_a_sphere_grown_to_a_size_a_pour_made_before_pre_no_leaves_its_pairs_out(tmp_path):
    """Field round 29, Q08: a pour makes one 2 cm type-2 sphere, then the 1 cm type-2 sphere of the
    head-on pair is set to 2 cm before run N pre no. LAMMPS' lists keep its 6 mm and meet the pair
    deep in overlap (measured here: more than 0.05 from the same deck set up); the sizes held after
    show no new one, only the 1 cm one gone, which the audit now reads as a growth."""
    pour = ("fix fall all gravity 9.81 vector 0 0 -1\n"      # the same on both: their meeting unchanged
            "region ins block -0.04 0.04 -0.04 0.04 0.03 0.045 units box\n"
            "fix p all pour 1 2 4767 region ins diam one 0.02 dens 2500 2500\n")
    deck = _grown("no").replace("set type 2 diameter 0.02", "set atom 2 diameter 0.02").replace(
        "run 1\n", pour + "run 1\n")
    assert abs(lammps_separation_speed(deck, tmp_path) - lammps_separation_speed(
        deck.replace("pre no", "pre yes"), tmp_path)) > 0.05
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    assert [1, 2] not in [r["types"] for r in got["stages"][-1]["pairs"]], got["stages"][-1]["pairs"]
    assert "pre no after type 2 came to hold spheres larger" in err, err


#: Round 28's Q58 (the sweep of session 25 found it still printed): two 4 mm type-1 spheres meeting
#: at 1 m/s; cutoff 0.001 on every pair, then pair 1 1 given again without it before run pre no
Q58 = """units si
atom_style sphere 1
boundary p p f
comm_modify vel yes
region box block 0 0.04 0 0.04 0 0.1 units box
create_box 2 box
pair_style granular
pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 cutoff 0.001
fix integ all nve/sphere
timestep 1e-6
create_atoms 1 single 0.01745 0.02 0.05
create_atoms 1 single 0.02255 0.02 0.05
set type 1 diameter 0.004 density 2500
velocity all set 0 0 0
set atom 1 vx 0.5
set atom 2 vx -0.5
run 1000
pair_coeff 1 1 hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3
run 3000 pre no
"""


@needs_lammps
@pytest.mark.dem
def test_pre_no_after_a_like_pairs_cutoff_changed_is_refused(tmp_path):
    """A like pair's own cutoff is read into the lists' reach at a set-up only: with pre no LAMMPS
    keeps the short lists and finds the pair late (measured below; round 28 Q58: -0.507), where the
    audit printed the new law's 0.497262. Refused in one line, as for any setting pre no leaves."""
    (tmp_path / "in.deck").write_text(Q58)
    status, out, err = run(tmp_path / "in.deck", "--g", "1")
    assert status == 2 and "pre no after a contact setting changed" in err, (out, err)
    assert abs(abs(lammps_separation_speed(Q58, tmp_path)) - 0.4973) > 0.05

"""What the audit's pass cannot see, said (field round 39): it skips the runs, so it does not know
whether a contact is under way where the deck changes the contact law or the atoms between runs.

- SW-SPAN: a pair law changed between runs, or between the parts of a run's every, while the pair is
  in contact (E08: run 300 with the pair meeting at step 100, kn 2000 then 5000: LAMMPS 0.798 where
  0.4149 and 0.5806 were printed with no word); a velocity set between a run's parts (E03: LAMMPS
  0.332, 0.4149 printed).
- SW-WALL-REGION: fix wall/region was taken to push nothing (W20: a harmonic region wall near the
  floor, LAMMPS 0.514 where the floor's 0.3630 was printed with no word).

Field round 40 found the same hole in other forms: a law whose eps stays while its stiffness changes
(A01: coeff_restitution 0.5 at kn 2000 then 5000, LAMMPS 0.771), a sphere retyped mid-contact (A41,
0.323), change_box with remap (A17, 0.117), fix deform with its default remap x (B23, 0.331), the floor
defined again 0.1 mm higher (A59, 0.620) or unfixed (A15: the contact never ends)."""

import json

import pytest

from deck_cli import PERIODIC_PAIR, lammps_separation_speed, needs_lammps, run

STIFFER = "pair_coeff 1 2 hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"


def audited(deck: str, tmp_path) -> tuple:
    (tmp_path / "in.deck").write_text(deck)
    status, out, err = run(tmp_path / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    return json.loads(out), err


def stage_eps(got: dict) -> list:
    return [next(r["eps"][0] for r in stage["pairs"] if r["types"] == [1, 2]) for stage in got["stages"]]


@needs_lammps
@pytest.mark.dem
def test_a_law_changed_while_the_pair_may_be_in_contact_is_said(tmp_path):
    # PERIODIC_PAIR's run 1000 ends 100 steps before the pair meets; the next run ends within the contact
    # (one stage with the first: the same law; 1,300 steps, longer than the contact)
    deck = PERIODIC_PAIR + f"run 300\n{STIFFER}\nrun 2000\n"
    got, err = audited(deck, tmp_path)
    first, second = stage_eps(got)
    engine = abs(lammps_separation_speed(deck, tmp_path))
    assert min(abs(engine - first), abs(engine - second)) > 0.05, (engine, first, second)   # neither law's
    assert ("types 1 2: the contact law changes at the start of stage 2 of 2; a contact under way at such a "
            "change (one lasts up to 586 steps at the deck's time step) feels both stages' laws") in err, err


@needs_lammps
@pytest.mark.dem
def test_a_law_changed_after_the_contact_is_said_without_the_short_stage(tmp_path):
    got, err = audited(PERIODIC_PAIR + f"run 3000\n{STIFFER}\nrun 2000\n", tmp_path)
    assert "the contact law changes at the start of stage 2 of 2" in err, err
    assert "fewer steps than one contact lasts" not in err, err
    assert "changes the atoms (their" not in err, err


@needs_lammps
@pytest.mark.dem
def test_a_run_whose_parts_change_the_law_says_each_part_is_shorter_than_a_contact(tmp_path):
    deck = PERIODIC_PAIR + f'run 2000 every 200 "pair_coeff 1 2 hooke $(2000+2*step) 3000 damping mass_velocity ' \
                           f'tangential linear_nohistory 1 0.3"\n'
    got, err = audited(deck, tmp_path)
    # stage 1: run 1000 and the first part, with the law before the every's first pair_coeff
    assert "stages 2-10 of 10" in err and "stages 2-9 run fewer steps than one contact lasts" in err, err


@needs_lammps
@pytest.mark.dem
def test_a_velocity_set_between_a_runs_parts_is_said_once(tmp_path):
    deck = PERIODIC_PAIR + 'run 2000 every 250 "set atom 2 vx -0.2285714286"\n'
    got, err = audited(deck, tmp_path)
    assert "changes the atoms (their velocities, places, sizes or types, or which atoms there are) or the box between runs: a contact under way" in err, err
    assert err.count("changes the atoms (their") == 1, err        # said once for the line
    engine = abs(lammps_separation_speed(deck, tmp_path))
    assert abs(engine - stage_eps(got)[-1]) > 0.05, engine


@needs_lammps
@pytest.mark.dem
def test_no_velocity_note_where_no_run_follows(tmp_path):
    _, err = audited(PERIODIC_PAIR + "velocity all set 0 0 0\n", tmp_path)
    assert "changes the atoms (their" not in err, err


@needs_lammps
@pytest.mark.dem
def test_a_region_wall_is_named_as_a_force_the_eps_do_not_include(tmp_path):
    deck = PERIODIC_PAIR + "region cage block 0 0.04 0 0.04 0 0.1 units box\n" \
                           "fix soft all wall/region cage harmonic 20.0 0.0 0.0025\nrun 3000\n"
    _, err = audited(deck, tmp_path)
    assert "fix wall/region may add forces to its atoms (group all)" in err, err


SAME_E = "hooke {kn} 0.5 damping coeff_restitution tangential linear_nohistory 1 0.3"


@needs_lammps
@pytest.mark.dem
def test_a_stiffness_changed_under_the_same_eps_is_said(tmp_path):
    deck = PERIODIC_PAIR.replace("hooke 2000 3000 damping mass_velocity", SAME_E.format(kn=2000).rsplit(" tangential", 1)[0]) \
        + f"run 300\npair_coeff 1 2 {SAME_E.format(kn=5000)}\nrun 2000\n"
    got, err = audited(deck, tmp_path)
    assert stage_eps(got)[0] == pytest.approx(stage_eps(got)[1], abs=1e-12)      # the same e printed
    assert "types 1 2: the contact law changes at the start of stage 2 of 2" in err, err
    assert abs(abs(lammps_separation_speed(deck, tmp_path)) - 0.5) > 0.05


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("between", ["set atom 2 type 1", "change_box all x scale 1.02 remap units box"])
def test_a_retype_or_a_box_change_between_runs_is_said(tmp_path, between):
    _, err = audited(PERIODIC_PAIR + f"run 300\n{between}\nrun 2000\n", tmp_path)
    assert f"between runs: a contact under way at that step is changed mid-way, and its eps is none of those " \
           f"printed: {between}" in err, err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("change", ["unfix floor", "fix floor all wall/gran granular hooke 2000 3000 damping mass_velocity "
                                              "tangential linear_nohistory 1 0.3 zplane 0.0001 NULL"])
def test_a_wall_defined_again_or_removed_between_runs_is_said(tmp_path, change):
    floor = "fix floor all wall/gran granular hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 " \
            "zplane 0 NULL\n"
    _, err = audited(PERIODIC_PAIR + floor + f"run 300\n{change}\nrun 2000\n", tmp_path)
    assert "defines again, moves or removes a wall between runs" in err, err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("remap, moved", [("", True), (" remap x", True), (" remap v", False)])
def test_fix_deform_moving_the_atoms_is_said(tmp_path, remap, moved):
    _, err = audited(PERIODIC_PAIR + f"fix df all deform 1 x scale 1.05{remap}\nrun 3000\n", tmp_path)
    assert ("moves the atoms with it (remap x): a contact under way is squeezed or stretched" in err) == moved, err


@needs_lammps
@pytest.mark.dem
def test_atoms_added_between_runs_are_said(tmp_path):
    """Field round 41, M53: read_data ... add append of a sphere at the pair mid-contact (0.407)."""
    (tmp_path / "t.data").write_text("one more\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n"
                                     "0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.0279 0.02 0.05\n")
    _, err = audited(PERIODIC_PAIR + "run 300\nread_data t.data add append\nrun 2000\n", tmp_path)
    assert "changes the atoms (their velocities, places, sizes or types, or which atoms there are) or the box " \
           "between runs" in err and "read_data t.data add append" in err, err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("before, between, said", [
    ("group gx id 5\nfix sf gx setforce 0.0 0.0 0.0\n", "group gx id 2", "defines again a group a fix acts on"),
    ("neigh_modify exclude type 1 2\n", "neigh_modify exclude none", "changes which pairs the engine excludes")],
    ids=["a fix's group filled", "an exclusion lifted"])
def test_a_fix_group_or_an_exclusion_changed_between_runs_is_said(tmp_path, before, between, said):
    """Field round 42, R09 (setforce on a group filled with a sphere of the pair mid-contact: LAMMPS
    0.395 where 0.4149 was printed with no word) and N04 (an exclusion lifted with the spheres in
    overlap: 0.848)."""
    deck = PERIODIC_PAIR.replace("fix move all nve/sphere\n", "fix move all nve/sphere\n" + before) \
        + f"run 300\n{between}\nrun 2000\n"
    _, err = audited(deck, tmp_path)
    assert f"{said}, between runs" in err and between in err, err


@needs_lammps
@pytest.mark.dem
def test_a_pair_left_out_in_the_next_stage_is_said_as_a_change(tmp_path):
    """Field round 42, H01: kn changed mid-contact in a stage whose pair is left out (two integrators
    on groups the audit cannot type): the first stage's 0.4149 stood with no word, LAMMPS 0.798."""
    deck = PERIODIC_PAIR + "group one id 1\ngroup two id 2\nrun 300\n" \
        "pair_coeff 1 2 hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n" \
        "unfix move\nfix i1 one nve/sphere\nfix i2 two nve/sphere\nrun 2000\n"
    got, err = audited(deck, tmp_path)
    assert not any(r["types"] == [1, 2] for r in got["stages"][-1]["pairs"]), got["stages"][-1]
    assert "types 1 2: the contact law changes (or the pair is left out, its reason said) at the start of stage 2" \
        in err, err


#: A plane region wall 2 mm under the pair's centres: neither sphere touches it
PLATE = ("region plate plane 0 0 0.045 0 0 1 units box\nfix plate all wall/gran/region granular hooke 2000 3000 damping "
         "mass_velocity tangential linear_nohistory 1 0.3 region plate\n")
BETWEEN = "is run between runs, and the audit does not know it to leave a contact as it was"


@needs_lammps
@pytest.mark.dem
def test_a_region_moved_under_its_wall_mid_contact_is_said(tmp_path):
    # found while listing the harmless: the region wall's region deleted and defined again 3.5 mm
    # higher, under the type 2 sphere, 200 steps into the contact: LAMMPS 0.337 where 0.4149 was
    # printed with no word (the wall's own words unchanged, so no wall note)
    deck = PERIODIC_PAIR.replace("run 1000\n", PLATE + "run 1000\n") + \
        "run 300\nregion plate delete\nregion plate plane 0 0 0.0485 0 0 1 units box\nrun 2000\n"
    got, err = audited(deck, tmp_path)
    assert f"line 23 {BETWEEN}: a contact under way at that step may be changed mid-way, and its eps may be none " \
           "of those printed: region plate plane 0 0 0.0485 0 0 1 units box" in err, err
    assert abs(abs(lammps_separation_speed(deck, tmp_path)) - stage_eps(got)[-1]) > 0.05


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("between, said", [
    ("fix vv all viscous 0.001", True),
    ("variable f equal 0.01", True),                 # the force of the addforce in force
    ("fix w2 all wall/gran granular hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 "
     "zplane 0.0485 NULL", True),                   # a new wall, under the type 2 sphere
    ("region spare block 0 1 0 1 0 1 units box", False),    # no fix names it
    ("variable q equal 3", False),
    ("fix av all ave/time 10 1 10 c_thermo_temp", False),
    (PLATE.splitlines()[1], False),                  # the wall given again in its own words
    ('print "half way"', False)])
def test_what_runs_between_runs_is_said_unless_it_is_harmless(tmp_path, between, said):
    deck = PERIODIC_PAIR.replace("run 1000\n", f"variable f equal 0.0\nfix af all addforce 0 0 v_f\n{PLATE}run 1000\n") \
        + f"run 300\n{between}\nrun 2000\n"
    _, err = audited(deck, tmp_path)
    assert (f"{BETWEEN}: a contact under way at that step may be changed mid-way, and its eps may be none of those "
            f"printed: {between}" in err) == said, err


@needs_lammps
@pytest.mark.dem
def test_nothing_is_under_way_after_a_run_of_no_steps(tmp_path):
    # run 0 sets up and prints; the spheres have not moved, so what follows it changes no contact
    deck = PERIODIC_PAIR.replace("run 1000\n", "run 0\nfix vv all viscous 0.001\nvelocity all set 0 0 0\n"
                                               "set atom 1 vx 0.7714285714\nset atom 2 vx -0.2285714286\nrun 1000\n")
    _, err = audited(deck, tmp_path)
    assert "between runs" not in err, err


#: Field round 43's pair: 4 mm and 6 mm spheres meeting head-on at 1 m/s at step 100, gravity across
FIELD_PAIR = PERIODIC_PAIR.replace("fix move all nve/sphere", "fix grav all gravity 9.81 vector 0 0 -1\n"
                                   "fix integ all nve/sphere").replace("0.03745 0.02", "0.017950 0.02") \
    .replace("0.00355 0.02", "0.023050 0.02").replace("run 1000\n", "")


@needs_lammps
@pytest.mark.dem
def test_a_part_of_a_wall_region_moved_mid_contact_is_said(tmp_path):
    # field round 43, B73: the wall's region is the intersection of two planes far off; one of them,
    # defined again under the type 2 sphere 200 steps into the contact: LAMMPS 0.365, 0.4149 printed
    deck = FIELD_PAIR + ("region a plane 0.035 0 0 -1 0 0 units box\nregion b plane 0.036 0 0 -1 0 0 units box\n"
                         "region u intersect 2 a b\nfix w2 all wall/gran/region granular hooke 2000 3000 damping "
                         "mass_velocity tangential linear_nohistory 1 0.3 region u\nrun 300\nregion a delete\n"
                         "region a plane 0.0259 0 0 -1 0 0 units box\nrun 2000\n")
    got, err = audited(deck, tmp_path)
    assert f"{BETWEEN}: a contact under way at that step may be changed mid-way, and its eps may be none of those " \
           "printed: region a plane 0.0259 0 0 -1 0 0 units box" in err, err
    assert "region a delete" not in err, err          # its next definition is what is weighed
    assert abs(abs(lammps_separation_speed(deck, tmp_path)) - stage_eps(got)[-1]) > 0.03


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("between, said", [
    # field round 43, B85: a sphere poured at the pair mid-contact (LAMMPS 0.732 where 0.4149 was printed)
    ("region pr block 0.0282 0.0312 0.018 0.022 0.048 0.052 units box\nfix pour all pour 1 1 4767548 region pr "
     "diam one 0.004 dens 2500 2500 vol 1.0 100 vel -10.0 -10.0 0.0 0.0 0.0", True),
    ("variable k equal 0.0", False),              # given again in its own words
    ("region plate delete\nregion plate plane 0 0 0.045 0 0 1 units box", False)])
def test_a_pour_mid_contact_is_said_and_a_definition_repeated_is_not(tmp_path, between, said):
    deck = FIELD_PAIR + f"variable k equal 0.0\nfix af all addforce 0 0 v_k\n{PLATE}run 300\n{between}\nrun 2000\n"
    _, err = audited(deck, tmp_path)
    assert (BETWEEN in err) == said, err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("reset, said", [("", False), (" reset yes", True)])
def test_an_adapt_unfixed_is_said_where_the_engine_puts_the_sizes_back(tmp_path, reset, said):
    # re-audit of rounds 27-42: with reset no (the default) the engine keeps the adapted sizes when the
    # fix goes (round 39, D20: LAMMPS 0.386313 as audited); with reset yes it restores them mid-way
    deck = PERIODIC_PAIR.replace("run 1000\n", f"variable d equal 0.005\nfix ad all adapt 1 atom diameter v_d{reset}\n"
                                               "run 1000\n") + "run 300\nunfix ad\nreset_atoms id\nrun 2000\n"
    _, err = audited(deck, tmp_path)
    assert (f"{BETWEEN}: a contact under way at that step may be changed mid-way, and its eps may be none of those "
            "printed: unfix ad" in err) == said, err
    assert "printed: reset_atoms id" not in err, err      # IDs given anew move no sphere


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("between, said", [("fix grav all gravity 30 vector 0 0 -1", True), ("unfix grav", True),
                                           ("fix grav all gravity 9.81 vector 0 0 -1", False)])
def test_gravity_changed_between_runs_is_said(tmp_path, between, said):
    # each stage weighs its gravity on a sphere at a wall; a contact spanning a change feels both
    deck = PERIODIC_PAIR.replace("run 1000\n", "fix grav all gravity 9.81 vector 0 0 -1\nrun 1000\n") + \
        f"run 300\n{between}\nrun 2000\n"
    _, err = audited(deck, tmp_path)
    assert (f"{BETWEEN}: a contact under way at that step may be changed mid-way, and its eps may be none of those "
            f"printed: {between}" in err) == said, err


@needs_lammps
@pytest.mark.dem
def test_a_wall_region_given_again_under_another_lattice_is_said(tmp_path):
    # field round 44, V09: the same words in lattice units under a finer lattice put the wall 9 mm nearer,
    # under the type 2 sphere mid-contact: LAMMPS 0.365 where 0.4149 was printed with no word
    wall = ("region a plane 3.5 0 0 -1 0 0\nfix w2 all wall/gran/region granular hooke 2000 3000 damping mass_velocity "
            "tangential linear_nohistory 1 0.3 region a\n")
    deck = FIELD_PAIR + f"lattice sc 0.01\n{wall}run 300\nlattice sc 0.0074\nregion a delete\n" \
                        "region a plane 3.5 0 0 -1 0 0\nrun 2000\n"
    got, err = audited(deck, tmp_path)
    assert f"{BETWEEN}: a contact under way at that step may be changed mid-way, and its eps may be none of those " \
           "printed: region a plane 3.5 0 0 -1 0 0" in err, err
    assert abs(abs(lammps_separation_speed(deck, tmp_path)) - stage_eps(got)[-1]) > 0.03


@needs_lammps
@pytest.mark.dem
def test_a_set_keyword_after_one_of_two_values_is_read(tmp_path):
    # field round 44, K23: dipole/random takes two values; the vx after it was read as a value
    deck = PERIODIC_PAIR.replace("atom_style sphere 1", "atom_style hybrid sphere 1 dipole") + \
        "run 300\nset atom 2 dipole/random 4321 1.0 vx 0.5\nrun 2000\n"
    _, err = audited(deck, tmp_path)
    assert "between runs: a contact under way at that step is changed mid-way, and its eps is none of those " \
           "printed: set atom 2 dipole/random 4321 1.0 vx 0.5" in err, err


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("before, said", [("run 300\n", True), ("", False)], ids=["after a run", "before any run"])
def test_a_minimize_after_a_run_is_said(tmp_path, before, said):
    # field round 45, B60: a minimize 200 steps into the contact moves the spheres at once (LAMMPS
    # 0.0053 where 0.4149 was printed with no word); one before any run moves them before a contact
    deck = FIELD_PAIR + f"{before}min_style fire\nminimize 0.0 0.0 200 2000\nrun 2000\n"
    got, err = audited(deck, tmp_path)
    assert (f"{BETWEEN}: a contact under way at that step may be changed mid-way, and its eps may be none of "
            "those printed: minimize 0.0 0.0 200 2000" in err) == said, err
    if said:
        assert abs(abs(lammps_separation_speed(deck, tmp_path)) - stage_eps(got)[-1]) > 0.05


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("style, said", [("fire", True), ("quickmin", True), ("cg", False)])
def test_a_minimizer_that_stops_the_atoms_is_said(tmp_path, style, said):
    # field round 46, Z14 Z16: fire and quickmin set the velocities to zero before any run, so the
    # pair never meets (LAMMPS: at rest 0.1 mm apart) where 0.4149 was printed with no word; cg keeps
    # them (Z15: 0.413435); the velocity lines after such a minimize are no change mid-contact (Z17)
    minimized = FIELD_PAIR + f"min_style {style}\nminimize 0.0 0.0 10 100\n"
    _, err = audited(minimized + "set atom 1 vx 0.7714285714\nrun 3000\n", tmp_path)
    assert (f"minimize under min_style {style} sets every atom's velocity to zero" in err) == said, err
    assert "between runs" not in err, err
    (tmp_path / "check").mkdir()
    assert (abs(lammps_separation_speed(minimized + "run 3000\n", tmp_path / "check")) < 1e-6) == said


@needs_lammps
@pytest.mark.dem
def test_a_group_a_fix_names_as_its_argument_given_again_is_said(tmp_path):
    # field round 45, B29: the second group of a spring couple, filled with a sphere of the pair
    # mid-contact (LAMMPS 4.44 where 0.4149 was printed with no word)
    deck = FIELD_PAIR + ("create_atoms 1 single 0.005 0.02 0.08\nset atom 3 diameter 0.004 density 2500\n"
                         "group g3 id 3\ngroup gx id 3\nfix sp g3 spring couple gx 50.0 0.0 0.0 0.0 0.0\nrun 300\n"
                         "group gx clear\ngroup gx id 2\nrun 2000\n")
    _, err = audited(deck, tmp_path)
    assert "(group g3, and group gx it names)" in err, err
    assert "defines again a group a fix acts on, between runs: a contact under way at that step meets that fix " \
           "(or loses it) mid-way, and its eps is none of those printed: group gx id 2" in err, err


@needs_lammps
@pytest.mark.dem
def test_a_wall_region_whose_part_moves_in_a_run_is_not_audited(tmp_path):
    # field round 45, B54: a plane part of the wall's intersect region moved by move v_dx within the run
    # (LAMMPS 0.365 where 0.4149 was printed with no word)
    deck = FIELD_PAIR + ("variable dx equal -0.0091*(step>=300)\n"
                         "region a plane 0.035 0 0 -1 0 0 move v_dx NULL NULL units box\n"
                         "region far plane 0.0 0.0 0.0 0 0 1 units box\nregion u intersect 2 a far\n"
                         "fix w2 all wall/gran/region granular hooke 2000 3000 damping mass_velocity tangential "
                         "linear_nohistory 1 0.3 region u\nrun 3000\n")
    got, err = audited(deck, tmp_path)
    assert "region a moves (keyword move), a part of region u: its faces may move under a sphere during a contact" \
           in err and "the wall's contacts are not audited" in err, err
    assert not any(s["walls"] for s in got["stages"]), got
    assert abs(abs(lammps_separation_speed(deck, tmp_path)) - stage_eps(got)[-1]) > 0.03


@needs_lammps
@pytest.mark.dem
def test_a_deck_run_again_after_clear_is_not_said_to_change_a_contact(tmp_path):
    # LIGGGHTS-PFM's contact-model tests (field round 45, R12-R19) loop over clear and the deck again:
    # the new deck's create_atoms, set and velocity were each said to change a contact under way
    _, err = audited(PERIODIC_PAIR + "run 300\nclear\n" + PERIODIC_PAIR + "run 300\n", tmp_path)
    assert "between runs" not in err, err


@needs_lammps
@pytest.mark.dem
def test_a_kick_after_a_restart_of_a_contact_under_way_is_said(tmp_path):
    # the atoms a restart file brings back after clear are where the run left them: mid-contact here
    deck = PERIODIC_PAIR + ("run 300\nwrite_restart mid.rst\nclear\nread_restart mid.rst\npair_style granular\n"
                            "pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n"
                            "comm_modify vel yes\nfix move all nve/sphere\nvelocity all set 0 0 0\nrun 2000\n")
    _, err = audited(deck, tmp_path)
    assert "or the box between runs: a contact under way at that step is changed mid-way, and its eps is none of " \
           "those printed: velocity all set 0 0 0" in err, err
    assert "fix move all nve/sphere" not in err, err

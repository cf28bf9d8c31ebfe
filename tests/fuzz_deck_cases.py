"""The fuzz's random decks (issue 28): LAMMPS decks (plain, or written with the input language's
if/jump/label, quotes, loops, stages and formulas), LIGGGHTS decks, flat walls, and damaged copies of
any of them. Generators only; fuzz_deck_checks.py runs them in the engines."""

from __future__ import annotations

import dataclasses
import math

from hypothesis import strategies as st


def _damping_for(normal: str, damping: str, radius: float, density: float, k: float, nu: float, omega: float,
                 g: float) -> float:
    """The damping coefficient of a one-type line (eta_n0) that puts its like pair at
    about ``omega`` at speed g: Omega = D1 g^((alpha-1-2 gamma)/(gamma+1)) D2^(-(alpha+1)/(gamma+1)),
    solved for D2 and mapped back through the LAMMPS dictionary."""
    from restitution.dem.engines.lammps.contact import lammps_contact, lammps_eta_n0
    from restitution.dem.pair import Pair

    pair = Pair.spheres(radius, radius, density, density)
    stiff = {"E": k, "nu": nu} if normal == "hertz/material" else {"k_n": k}
    unit = lammps_contact(pair, normal=normal, damping=damping, limit_damping=False,
                          eta_n0=1.0, **stiff)
    a, c = float(unit.alpha), float(unit.gamma)
    d2 = (omega / (unit.D1 * g ** ((a - 1 - 2 * c) / (c + 1)))) ** (-(c + 1) / (a + 1))
    return lammps_eta_n0(pair, damping, dataclasses.replace(unit, D2=d2))


def _lammps_deck_draws(draw) -> tuple:
    """What a random LAMMPS deck starts from: 1-3 types (radius 0.05-50 mm, density 500-20,000),
    one normal and one damping model, an impact speed: (n, normal, damping, g, types)."""
    log = lambda lo, hi: 10.0 ** draw(st.floats(lo, hi))  # noqa: E731
    n = draw(st.integers(1, 3))
    normal = draw(st.sampled_from(["hooke", "hertz", "hertz/material"]))
    damping = draw(st.sampled_from(["velocity", "mass_velocity", "viscoelastic", "tsuji", "coeff_restitution"]))
    g = log(-2.0, 0.5)
    types = {t: {"radius": log(-4.3, -1.3), "density": log(2.7, 4.3)} for t in range(1, n + 1)}
    return n, normal, damping, g, types


def _coeff_numbers(draw, normal: str, damping: str, m: dict, g: float) -> list[str]:
    """A pair_coeff line's numbers for a type of radius and density ``m``: a stiffness, and a
    damping that puts its like pair at a random Omega in 1e-3..30 at speed g (tsuji,
    coeff_restitution: e in 0.05..0.97), with nu for hertz/material."""
    log = lambda lo, hi: 10.0 ** draw(st.floats(lo, hi))  # noqa: E731
    if normal == "hertz/material":
        k, nu = log(6.0, 11.0), draw(st.floats(0.0, 0.45))
    else:
        k, nu = (log(4.0, 10.0) if normal == "hertz" else log(0.0, 5.0)), 0.0
    if damping in ("tsuji", "coeff_restitution"):
        d = draw(st.floats(0.05, 0.97))
    else:
        d = _damping_for(normal, damping, m["radius"], m["density"], k, nu, log(-3.0, 1.5), g)
    return [f"{k:.8g}", f"{d:.8g}"] + ([f"{nu:.4g}"] if normal == "hertz/material" else [])


def _coeff_text(draw, i, j, normal: str, damping: str, numbers: list) -> str:
    """The pair_coeff line of those numbers, limit_damping on some."""
    limit = " limit_damping" if draw(st.booleans()) else ""
    return f"pair_coeff {i} {j} {normal} {' '.join(numbers)} damping {damping} tangential linear_nohistory 0 0{limit}"


@st.composite
def deck_cases(draw):
    """A random LAMMPS deck: 1-3 atom types (radius 0.05-50 mm, density 500-20,000), one normal
    model (stiffness per type), one damping model with each type's coefficient set for a like-pair
    Omega in 1e-3..30 (tsuji, coeff_restitution: e in 0.05..0.97), limit_damping on some lines, maybe an explicit line
    for a cross pair, maybe a `pair_coeff * *` written first and overridden, maybe numbers through
    variables, maybe a flat wall at z = 0 (on all types or a group); and two impact speeds a decade
    apart. Returns (deck text, speeds, types)."""
    n, normal, damping, g, types = _lammps_deck_draws(draw)
    lines, variables = [], []

    def coeff_line(i, j, t):
        numbers = _coeff_numbers(draw, normal, damping, types[t], g)
        if draw(st.integers(0, 3)) == 0:      # a number through a variable
            name = f"k{len(variables)}"
            variables.append(f"variable {name} equal {numbers[0]}")
            numbers[0] = "${" + name + "}"
        return _coeff_text(draw, i, j, normal, damping, numbers)

    if draw(st.booleans()):
        lines.append(coeff_line("*", "*", 1))
    for t in types:
        lines.append(coeff_line(t, t, t))
    if n > 1 and draw(st.booleans()):
        i, j = sorted(draw(st.sampled_from([(a, b) for a in types for b in types if a < b])))
        lines.append(coeff_line(i, j, i))
    if draw(st.booleans()):   # a flat wall, its model drawn like a type's own line
        lines += _wall_lines(draw, types, "fix floor GROUP wall/gran granular "
                             + coeff_line("*", "*", draw(st.sampled_from(list(types)))).split(" ", 3)[3]
                             + " zplane 0.0 NULL")
    body = "\n".join(_lammps_head(n, types) + variables + ["pair_style granular"] + lines)
    return body + "\n", [g, 10.0 * g], {t: {k: float(f"{v:.8g}") for k, v in m.items()} for t, m in types.items()}


def _lammps_head(n: int, types: dict) -> list[str]:
    """A LAMMPS deck's lines up to its contact lines, ones LAMMPS runs: the box, LAMMPS' ghost
    velocities (its granular pairs need them), one atom of each type (_atoms), an integrator (a run
    without one moves no atom, and its deck is refused)."""
    return (["units si", "atom_style sphere", "comm_modify vel yes", "boundary f f f",
             "region box block -1 1 -1 1 -1 1", f"create_box {n} box"] + _atoms(types)
            + ["fix integrate all nve/sphere"])


def _atoms(types: dict) -> list[str]:
    """One atom of each type, clear of each other and of a wall at z = 0 (at z = 0.5, radii at most
    50 mm), then each type's diameter and density (LAMMPS and LIGGGHTS stop on a set before any atom)."""
    return ([f"create_atoms {t} single {0.5 * (t - 2)} 0 0.5 units box" for t in types]
            + [f"set type {t} diameter {2 * m['radius']:.8g} density {m['density']:.8g}" for t, m in types.items()])


#: Seeds of the particle templates: LIGGGHTS 3.8.0 stops on one that is not a prime above 10,000
#: (these are among those its own message suggests)
_TEMPLATE_SEEDS = (15485863, 15485867, 32452843)


def _wall_lines(draw, types: dict, wall: str) -> list[str]:
    """The ``wall`` line on all types, or (with several) on a group of some of them (its GROUP),
    written where atoms exist (a group holds the atoms present when it is defined)."""
    if len(types) > 1 and draw(st.booleans()):
        members = sorted(draw(st.sets(st.sampled_from(list(types)), min_size=1)))
        return [f"group walled type {' '.join(map(str, members))}", wall.replace("GROUP", "walled")]
    return [wall.replace("GROUP", "all")]


@st.composite
def liggghts_deck_cases(draw):
    """A random LIGGGHTS deck: 1-3 atom types (radius 0.05-50 mm, density 500-20,000, E 1e5-1e11,
    nu 0-0.55), a symmetric coefficientRestitution matrix (0.02-0.97), hertz or hooke (with a
    characteristicVelocity), limitForce on or off, maybe soft_particles / hard_particles yes, maybe
    E through a variable, maybe a wall of one of the types at z = 0 (a plane or a mesh face, its own
    limitForce or none); two speeds a decade
    apart (some draws break LIGGGHTS' own limits on E, nu
    and e: the audit must refuse exactly those). Returns (deck text, speeds, types)."""
    log = lambda lo, hi: 10.0 ** draw(st.floats(lo, hi))  # noqa: E731
    n = draw(st.integers(1, 3))
    model = draw(st.sampled_from(["hertz", "hooke"]))
    g = log(-2.0, 0.5)
    types = {t: {"radius": log(-4.3, -1.3), "density": log(2.7, 4.3)} for t in range(1, n + 1)}
    E = [f"{log(5.0, 11.0) if draw(st.integers(0, 7)) == 0 else log(6.8, 9.0):.6g}" for _ in types]
    nu = [f"{draw(st.floats(0.0, 0.55) if draw(st.integers(0, 9)) == 0 else st.floats(0.0, 0.45)):.4g}"
          for _ in types]
    e = {(i, j): f"{draw(st.floats(0.02, 0.97) if draw(st.integers(0, 9)) == 0 else st.floats(0.06, 0.97)):.4g}"
         for i in types for j in types if i <= j}
    matrix = " ".join(e[min(i, j), max(i, j)] for i in types for j in types)
    # what a run in LIGGGHTS needs: ghost velocities, newton off (shear history), no atom sorting and
    # neighbour bins of the box's scale (bins of a 0.1 mm sphere's size in a 2 m box are too many)
    lines = ["atom_style granular", "atom_modify map array sort 0 0", "units si", "newton off",
             "communicate single vel yes", "neighbor 0.1 bin", "region box block -1 1 -1 1 -1 1 units box",
             f"create_box {n} box"]
    lines += [f"{what}_particles yes" for what in ("soft", "hard") if draw(st.booleans())]
    if draw(st.booleans()):
        lines.append(f"variable E1 equal {E[0]}")
        E[0] = "${E1}"
    lines += [f"fix m1 all property/global youngsModulus peratomtype {' '.join(E)}",
              f"fix m2 all property/global poissonsRatio peratomtype {' '.join(nu)}",
              f"fix m3 all property/global coefficientRestitution peratomtypepair {n} {matrix}",
              f"fix m4 all property/global coefficientFriction peratomtypepair {n} " + " ".join(["0.5"] * n * n)]
    wall = draw(st.sampled_from([None, "hertz", "hooke"]))
    if "hooke" in (model, wall):
        lines.append(f"fix m5 all property/global characteristicVelocity scalar {log(-1.0, 1.0):.4g}")
    limit = draw(st.sampled_from(["on", "off"]))
    tangential = f"tangential {draw(st.sampled_from(['history', 'no_history']))}"
    # an atom of each type before the walls (a group holds the atoms present when it is defined):
    # LIGGGHTS checks a type's material only at a run with atoms of it, the deck's last line
    lines += [f"pair_style gran model {model} {tangential} limitForce {limit}", "pair_coeff * *"] + _atoms(types)
    if wall is not None:
        # a flat wall of one of the types: a plane or a mesh face (plate.stl, written by the check),
        # a model of its own (LIGGGHTS 3.8.0 runs a hooke wall beside hertz pairs, though its manual
        # says it must match) and a limitForce of its own, or none
        models = f"model {wall} {tangential}"
        w, own = draw(st.sampled_from(list(types))), draw(st.sampled_from(["", " limitForce on", " limitForce off"]))
        if draw(st.booleans()):
            lines += _wall_lines(draw, types, f"fix floor GROUP wall/gran {models} primitive type {w} zplane 0.0{own}")
        else:
            lines += [f"fix mesh1 all mesh/surface file plate.stl type {w}"]
            lines += _wall_lines(draw, types, f"fix floor GROUP wall/gran {models} mesh n_meshes 1 meshes mesh1{own}")
    lines += [f"fix pts{t} all particletemplate/sphere {_TEMPLATE_SEEDS[t - 1]} atom_type {t} density constant "
              f"{m['density']:.8g} radius constant {m['radius']:.8g}" for t, m in types.items()]
    return "\n".join(lines + ["fix integr all nve/sphere", "run 1"]) + "\n", [g, 10.0 * g], {t: {k: float(f"{v:.8g}") for k, v in m.items()}
                                                       for t, m in types.items()}


# ------------------------------------------------------------------ decks in the input language
def _disguised(draw, x: str) -> str:
    """A LAMMPS formula whose value is the number ``x``, written with the grammar's corners (unary
    minus above ^, ^ left to right, log base 10, !, ternary, comparisons): LAMMPS evaluates it in
    the engine run, the reader in the audit, and a reader that got a rule wrong gives another
    number."""
    v = float(x)
    forms = [x, f"-(-{x})", f"--{x}", f"({x}/2)*2", f"10^log({x})", f"sqrt({x}^2)", f"exp(ln({x}))",
             f"-{math.sqrt(v)!r}^2", f"{x}*(2^3^2==64)", f"{x}*!0", f"ternary(1<2&&!(3<2),{x},{2 * v!r})",
             f"{x}*(1|^0)", f"{x}+0*round(-2.5)"]
    return draw(st.sampled_from(forms))


@st.composite
def script_deck_cases(draw):
    """A random LAMMPS deck written with the constructs of its input language that decide which
    contact lines run (issue 42): 1-3 run stages, each with new coefficients for every type (1-3
    types, radius 0.05-50 mm), each line written plainly, or behind an if (numbers or strings
    compared, the other branch a decoy), after a jump over a decoy, as the last turn of a loop over
    an index variable, beside a decoy in double or triple quotes; numbers through equal-style
    formulas and $(...); a pair_style of another style between stages (which discards the
    coefficients) or the same style again (which keeps them); type labels. The last line runs the
    last stage. Returns (deck text, speeds, types, the number of head lines)."""
    n, normal, damping, g, types = _lammps_deck_draws(draw)
    labels = draw(st.booleans())
    name = {t: f"{'abc'[t - 1]}{t}" if labels else str(t) for t in types}
    head = _lammps_head(n, types)
    body = [] if not labels else ["labelmap atom " + " ".join(f"{t} {name[t]}" for t in types)]
    body.append("pair_style granular")
    count = iter(range(10 ** 6))

    def line(i, j, t):
        numbers = _coeff_numbers(draw, normal, damping, types[t], g)
        k = next(count)
        how = draw(st.sampled_from(["plain", "variable", "immediate"]))
        if how == "variable":
            body.append(f"variable n{k} equal {_disguised(draw, numbers[0])}")
            numbers[0] = f"${{n{k}}}"
        elif how == "immediate":
            numbers[1] = f"$({_disguised(draw, numbers[1])})"
        return _coeff_text(draw, name[i], name[j], normal, damping, numbers), k

    def decoy(i, j):
        return _coeff_text(draw, name[i], name[j], normal, damping, _coeff_numbers(draw, normal, damping,
                                                                                     types[i], g))

    def write(i, j, t):
        text, k = line(i, j, t)
        how = draw(st.sampled_from(["plain", "if", "string if", "jump", "loop", "quoted", "triple"]))
        if how == "if":
            flag = draw(st.integers(0, 1))
            body.append(f"variable c{k} equal {flag}")
            taken, other = (text, decoy(i, j)) if flag else (decoy(i, j), text)
            body.append(f'if "${{c{k}}} == 1 && 2 > 1" then "{taken}" else "{other}"')
        elif how == "string if":
            body.append(f"variable s{k} string yes{k}")
            body.append(f'if "${{s{k}}} != yes{k}" then "{decoy(i, j)}" elif "${{s{k}}} == yes{k}" "{text}"')
        elif how == "jump":
            body.extend([f"jump SELF skip{k}", decoy(i, j), f"label skip{k}", text])
        elif how == "loop":
            last = text.split()[5]              # the damping, the number after the stiffness
            body.extend([f"variable d{k} index {decoy(i, j).split()[5]} {last}", f"label loop{k}",
                     " ".join(text.split()[:5] + [f"${{d{k}}}"] + text.split()[6:]), f"next d{k}", f"jump SELF loop{k}"])
        elif how == "quoted":
            body.extend([text, f'print "{decoy(i, j)}"'])
        elif how == "triple":
            body.extend([text, 'print """', decoy(i, j), '"""'])
        else:
            body.append(text)

    stages = draw(st.integers(1, 3))
    for s in range(stages):
        if s:
            body.append("run 1")
            restyle = draw(st.sampled_from(["none", "other", "same"]))
            if restyle == "other":       # discards every coefficient: all are written again below
                body += ["pair_style gran/hooke 1000.0 NULL 10.0 NULL 0.5 0", "pair_coeff * *", "pair_style granular"]
            elif restyle == "same":
                body.append("pair_style granular")
        for t in types:
            write(t, t, t)
        if n > 1 and draw(st.booleans()):
            i, j = sorted(draw(st.sampled_from([(a, b) for a in types for b in types if a < b])))
            write(i, j, i)
    body.append("run 1")
    return "\n".join(head + body) + "\n", [g, 10.0 * g], \
        {t: {k: float(f"{v:.8g}") for k, v in m.items()} for t, m in types.items()}, len(head)


#: What a damaged deck word becomes: numbers of every class, unset variables, expressions, ranges
_DECK_DAMAGE = ("x", "", "-1", "0", "1e999", "nan", "inf", "1e-320", "2.5", "${nope}", "$(1/0)", "v_nope", "*", "1*",
                "*0", "NULL", "hertz", "tsuji", "zplane", "primitive", "mesh", "type", "all")


@st.composite
def deck_mutation_cases(draw):
    """A random LAMMPS or LIGGGHTS deck (walls included), or one written with the input language's
    constructs (script_deck_cases), with one line cut short, one word replaced, or a line repeated
    or dropped. Returns the deck text."""
    text = draw(st.sampled_from([deck_cases, liggghts_deck_cases, script_deck_cases]).flatmap(lambda f: f()))[0]
    lines = text.splitlines()
    i = draw(st.integers(0, len(lines) - 1))
    words = lines[i].split()
    how = draw(st.sampled_from(["cut", "word", "repeat", "drop"]))
    if how == "cut":
        lines[i] = " ".join(words[:draw(st.integers(1, len(words)))])
    elif how == "word":
        j = draw(st.integers(0, len(words) - 1))
        lines[i] = " ".join(words[:j] + [draw(st.sampled_from(_DECK_DAMAGE))] + words[j + 1:])
    elif how == "repeat":
        lines.insert(i, lines[i])
    else:
        del lines[i]
    return "\n".join(lines) + "\n"

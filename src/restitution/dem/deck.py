"""What eps does an input deck really give? A reader of LAMMPS (``pair_style granular``) and
LIGGGHTS (``pair_style gran model hertz|hooke``) input scripts, for every type pair.

The reader takes only what decides a head-on two-sphere contact: the contact model and its
coefficients per type pair, the end-of-contact keyword, and each type's radius and density.
Commands that cannot change that contact (output, regions, gravity, walls, integrators, ...) are
passed over; any other line is reported as not understood, one per line, and never guessed. An
option that does change the contact but is not mapped (a cohesion model, JKR, a pair style other
than those two), a type without radius or density, or a type pair without coefficients is refused
with one line (DeckError, exit status 2 in the CLI).

Tangential, rolling and twisting models take no part in a head-on collision and are ignored.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

from ..core.collision import StickError
from ..core.errors import ParameterError
from .calibrate import calibrate
from .codes import Pair, lammps_contact, lammps_eta_n0, liggghts_contact, liggghts_e

__all__ = ["DeckError", "read_deck", "audit_deck"]


class DeckError(ParameterError):
    """One line naming what in the deck cannot be mapped or is missing."""

    def __init__(self, where: str, text, why: str):
        super().__init__(where, text, why)
        shown = "" if text is None else f" ({' '.join(str(text).split())})"
        self.args = (f"{where}{shown}: {why}",)


#: Commands with no bearing on a head-on two-sphere contact (first word, or "fix STYLE"). Not here,
#: so named when met: mass (per-type masses), jump/next (loops may rerun with other values).
_IRRELEVANT = {"units", "atom_style", "atom_modify", "boundary", "newton", "communicate", "comm_modify",
               "processors", "region", "lattice", "change_box", "neighbor", "neigh_modify", "timestep", "thermo",
               "thermo_style", "thermo_modify", "dump", "dump_modify", "undump", "run", "unfix", "compute",
               "uncompute", "group", "velocity", "delete_atoms", "write_restart", "restart", "log", "print",
               "echo", "label", "shell", "clear", "create_atoms", "displace_atoms",
               "write_data", "write_dump", "reset_timestep", "run_style", "min_style", "minimize", "balance",
               "partition", "suffix", "package", "kspace_style", "special_bonds", "hard_particles",
               "soft_particles", "modify_timing"}
_IRRELEVANT_FIXES = {"gravity", "nve/sphere", "nve", "wall/gran", "wall/gran/region", "balance", "insert/pack",
                     "insert/stream", "insert/rate/region", "particledistribution/discrete", "check/timestep/gran",
                     "viscous", "enforce2d", "move", "mesh/surface", "mesh/surface/stress", "freeze", "setforce",
                     "ave/time", "ave/atom", "print", "nve/limit", "move/mesh",
                     "wall/region", "heat/gran", "heat/gran/conduction", "multisphere", "property/atom"}
#: LAMMPS pair_coeff keywords after the normal model: name -> number of arguments
_LAMMPS_TANGENTIAL = {"linear_nohistory": 2, "linear_history": 3, "mindlin": 3, "mindlin_rescale": 3,
                      "mindlin/force": 3, "mindlin_rescale/force": 3}
_LAMMPS_NORMAL_ARGS = {"hooke": 2, "hertz": 2, "hertz/material": 3}


@dataclass
class Deck:
    code: str = ""                                # "LAMMPS" or "LIGGGHTS"
    ntypes: int = 0
    radius: dict = field(default_factory=dict)    # type -> radius
    density: dict = field(default_factory=dict)   # type -> density
    coeffs: dict = field(default_factory=dict)    # (i, j), i <= j -> (line number, tokens) [LAMMPS]
    props: dict = field(default_factory=dict)     # LIGGGHTS property/global name -> (line no, values)
    prop_fix: dict = field(default_factory=dict)  # LIGGGHTS property/global name -> "fix ID group"
    model: str = ""                               # LIGGGHTS normal model
    limit_force: bool = False
    style_line: tuple = ()                        # (line number, text) of pair_style
    unknown: list = field(default_factory=list)   # (line number, text) not understood
    ignored: list = field(default_factory=list)   # what the audit passed over on purpose


_EXPR = re.compile(r"^[0-9eE.+\-*/^() \t]*$")


def _evaluate(expr: str):
    """An equal-style variable's value when it is plain arithmetic of numbers and PI, else None."""
    text = expr.replace("PI", repr(math.pi))
    if not _EXPR.match(text) or re.search(r"[eE][^0-9+\-]", text):
        return None
    try:
        return float(eval(text.replace("^", "**"), {"__builtins__": {}}, {}))   # noqa: S307 - checked above
    except (SyntaxError, ZeroDivisionError, TypeError, OverflowError):
        return None


def _logical_lines(text: str):
    """(line number, text) with comments removed and '&' continuations joined."""
    pending, start = "", 0
    for n, raw in enumerate(text.splitlines(), 1):
        line = re.sub(r"#.*", "", raw).rstrip()    # LAMMPS: '#' starts a comment outside quotes
        if not pending:
            start = n
        if line.endswith("&"):
            pending += line[:-1] + " "
            continue
        line = " ".join((pending + line).split())
        pending = ""
        if line:
            yield start, line


def _types(spec: str, ntypes: int, where: str, text: str) -> range:
    """A LAMMPS type range: 2, *, 1*, *3, 2*4."""
    if ntypes <= 0:
        raise DeckError(where, text, "a type range before create_box: the number of types is unknown")
    m = re.fullmatch(r"(\d*)\*(\d*)|(\d+)", spec)
    if not m:
        raise DeckError(where, text, f"type {spec!r} is not a type or a range such as 1*2")
    if m.group(3):
        lo = hi = int(m.group(3))
    else:
        lo, hi = int(m.group(1) or 1), int(m.group(2) or ntypes)
    if not 1 <= lo <= hi <= ntypes:
        raise DeckError(where, text, f"types must be in 1..{ntypes}")
    return range(lo, hi + 1)


def _number(token: str, where: str, text: str) -> float:
    try:
        return float(token)
    except ValueError:
        raise DeckError(where, text, f"{token!r} is not a number the reader can evaluate") from None


def read_deck(text: str, radius: dict | None = None, density: dict | None = None) -> Deck:
    """Parse a deck; ``radius``/``density`` ({type: value}) override or complete what it states."""
    deck, variables = Deck(), {}
    for n, line in _logical_lines(text):
        where = f"line {n}"

        def subst(m):
            name = m.group(1) or m.group(2)
            if variables.get(name) is None:
                # left visible: an irrelevant command may use it; a value the audit needs fails in _number
                return f"<unevaluated-variable-{name}>"
            value = variables[name]
            return repr(value) if isinstance(value, float) else str(value)
        line = re.sub(r"\$\{(\w+)\}|\$(\w)", subst, line)
        words = line.split()
        cmd = words[0]
        if cmd == "variable" and len(words) >= 4:
            style = words[2]
            if style == "equal":
                variables[words[1]] = _evaluate(" ".join(words[3:]).strip("\"'"))
            elif style == "index" and words[1] in variables:
                pass          # LAMMPS keeps the first definition of an index variable
            elif style in ("index", "string", "world", "universe", "uloop", "loop"):
                variables[words[1]] = words[3].strip("\"'")
            else:
                variables[words[1]] = None
            continue
        if cmd == "create_box":
            deck.ntypes = int(_number(words[1], where, line))
        elif cmd in ("read_data", "read_restart", "include"):
            raise DeckError(where, line, f"{cmd}: the types, sizes or coefficients come from another file, which "
                                         "the reader does not follow")
        elif cmd == "pair_style":
            _pair_style(deck, words, where, line, n)
        elif cmd == "pair_coeff":
            _pair_coeff(deck, words, where, line, n)
        elif cmd == "set" and len(words) >= 3:
            _set(deck, words, where, line, n)
        elif cmd == "fix" and len(words) >= 4:
            _fix(deck, words, where, line, n)
        elif cmd in _IRRELEVANT:
            continue
        else:
            deck.unknown.append((n, line))
    for t, r in (radius or {}).items():
        deck.radius[int(t)] = r
    for t, d in (density or {}).items():
        deck.density[int(t)] = d
    if not deck.code:
        raise DeckError("pair_style", None, "the deck has no pair_style granular (LAMMPS) or pair_style gran "
                                            "(LIGGGHTS) line")
    return deck


def _pair_style(deck, words, where, line, n):
    style = words[1]
    deck.style_line = (n, line)
    if style == "granular":
        deck.code = "LAMMPS"
        return
    if style != "gran":
        raise DeckError(where, line, f"pair_style {style} is not mapped (the reader maps LAMMPS pair_style "
                                     "granular and LIGGGHTS pair_style gran model hertz|hooke)")
    deck.code = "LIGGGHTS"
    i = 2
    while i < len(words):
        key = words[i]
        val = words[i + 1] if i + 1 < len(words) else None
        if key == "model":
            if val not in ("hertz", "hooke"):
                raise DeckError(where, line, f"model {val} is not mapped (hertz and hooke are)")
            deck.model = val
        elif key == "limitForce":
            deck.limit_force = val == "on"
        elif key in ("tangential", "rolling_friction", "tangential_damping"):
            deck.ignored.append(f"{key} {val}")
        elif key == "surface" and val == "default":
            pass
        else:
            raise DeckError(where, line, f"{key} {val} is not mapped (it may change the normal force)")
        i += 2
    if not deck.model:
        raise DeckError(where, line, "pair_style gran without model hertz|hooke")


def _pair_coeff(deck, words, where, line, n):
    if deck.code == "LIGGGHTS":
        return                       # `pair_coeff * *`: the coefficients come from property/global
    if deck.code != "LAMMPS":
        raise DeckError(where, line, "pair_coeff before a pair_style the reader maps")
    for i in _types(words[1], deck.ntypes, where, line):
        for j in _types(words[2], deck.ntypes, where, line):
            deck.coeffs[(min(i, j), max(i, j))] = (n, words)


def _set(deck, words, where, line, n):
    if words[1] == "type":
        types = list(_types(words[2], deck.ntypes, where, line))
    elif words[1] == "group" and words[2] == "all":
        types = list(range(1, deck.ntypes + 1))
    else:
        deck.unknown.append((n, line))
        return
    rest = words[3:]
    for k in range(0, len(rest) - 1, 2):
        if rest[k] == "diameter":
            for t in types:
                deck.radius[t] = 0.5 * _number(rest[k + 1], where, line)
        elif rest[k] == "density":
            for t in types:
                deck.density[t] = _number(rest[k + 1], where, line)
        else:
            # mass, density/disc, velocities, ...: how they combine with a diameter is not guessed
            deck.unknown.append((n, line))
            return


def _fix(deck, words, where, line, n):
    style = words[3]
    if style == "property/global" and len(words) >= 6:
        deck.props[words[4]] = (n, words[5:])
        deck.prop_fix[words[4]] = f"fix {words[1]} {words[2]}"     # the exact line keeps the deck's fix ID
    elif style == "particletemplate/sphere":
        tokens, t = words[5:], None
        for k, tok in enumerate(tokens):
            if tok == "atom_type":
                t = int(_number(tokens[k + 1], where, line))
            elif tok in ("density", "radius") and k + 2 < len(tokens) and tokens[k + 1] == "constant" \
                    and t is not None:
                # other distributions (gaussian, ...) give no single value: the type stays unset
                (deck.density if tok == "density" else deck.radius)[t] = _number(tokens[k + 2], where, line)
    elif style == "pour" and len(words) >= 7:
        t = int(_number(words[5], where, line))
        tokens = words[7:]
        for k, tok in enumerate(tokens):
            if tok == "diam":
                if tokens[k + 1] == "one":
                    deck.radius[t] = 0.5 * _number(tokens[k + 2], where, line)
                elif tokens[k + 1] not in ("range", "poly") and tokens[k + 1] == tokens[k + 2]:
                    deck.radius[t] = 0.5 * _number(tokens[k + 1], where, line)   # older "diam lo hi"
            elif tok == "dens" and tokens[k + 1] == tokens[k + 2]:
                deck.density[t] = _number(tokens[k + 1], where, line)
    elif style in _IRRELEVANT_FIXES:
        return
    else:
        deck.unknown.append((n, line))


def _pair(deck: Deck, i: int, j: int) -> Pair:
    for t in (i, j):
        if t not in deck.radius:
            raise DeckError("radius", f"type {t}", "the deck gives no single radius for this type: give "
                                                   f"--radius {t}=R")
        if t not in deck.density:
            raise DeckError("density", f"type {t}", "the deck gives no single density for this type: give "
                                                    f"--density {t}=RHO")
    return Pair.spheres(deck.radius[i], deck.radius[j], deck.density[i], deck.density[j])


def _lammps_pair(deck: Deck, i: int, j: int, speeds) -> dict:
    if (i, j) not in deck.coeffs:
        raise DeckError("pair_coeff", f"types {i} {j}", "no pair_coeff line covers this type pair (LAMMPS "
                                                         "would mix it; the reader does not)")
    n, words = deck.coeffs[(i, j)]
    where, text = f"line {n}", " ".join(words)
    normal = words[3]
    if normal not in _LAMMPS_NORMAL_ARGS:
        raise DeckError(where, text, f"normal model {normal} is not mapped (hooke, hertz, hertz/material are)")
    args = [_number(a, where, text) for a in words[4:4 + _LAMMPS_NORMAL_ARGS[normal]]]
    damping, limit, k = "viscoelastic", False, 4 + _LAMMPS_NORMAL_ARGS[normal]
    while k < len(words):
        key = words[k]
        if key == "damping":
            damping = words[k + 1]
            k += 2
        elif key == "limit_damping":
            limit = True
            k += 1
        elif key == "tangential" and words[k + 1] in _LAMMPS_TANGENTIAL:
            deck.ignored.append(f"tangential {words[k + 1]}")
            k += 2 + _LAMMPS_TANGENTIAL[words[k + 1]]
        elif key == "rolling" and words[k + 1] == "sds":
            deck.ignored.append("rolling sds")
            k += 5
        elif key == "twisting" and words[k + 1] in ("marshall", "sds"):
            deck.ignored.append(f"twisting {words[k + 1]}")
            k += 2 if words[k + 1] == "marshall" else 5
        else:
            raise DeckError(where, text, f"keyword {key} is not mapped")
    if damping not in ("velocity", "mass_velocity", "viscoelastic", "tsuji"):
        raise DeckError(where, text, f"damping {damping} is not mapped")
    stiffness = ({"E": args[0], "nu": args[2]} if normal == "hertz/material" else {"k_n": args[0]})
    pair = _pair(deck, i, j)
    setting = {"normal": normal, "damping": damping, "eta_n0": args[1], "limit_damping": limit, **stiffness}
    contact = lammps_contact(pair, **setting)
    typed = args[1] if damping == "tsuji" else None
    exact = None
    if typed is not None:
        try:
            cal = calibrate(contact.alpha, contact.gamma, D1=contact.D1, eps=typed, g=speeds[len(speeds) // 2],
                            end=contact.end)
            e_new = lammps_eta_n0(pair, "tsuji", cal.contact)
        except ParameterError:
            e_new = None     # no tsuji e gives that eps under this end rule: no exact line
        if e_new is not None:
            # the pair's own line (a wildcard line names every pair it covers), with tsuji's e replaced
            exact = " ".join(["pair_coeff", str(i), str(j)] + words[3:5] + [f"{e_new:.10g}"] + words[6:])
    return {"types": [i, j], "model": f"LAMMPS {normal}, damping {damping}", "typed_e": typed,
            "end": contact.end, "contact": contact, "exact_line": exact, "line": n}


def _prop(deck: Deck, name: str, required: bool = True):
    if name not in deck.props:
        if required:
            raise DeckError("fix property/global", name, "the deck does not define it (LIGGGHTS needs it)")
        return None, None
    return deck.props[name]


def _liggghts_pair(deck: Deck, i: int, j: int, speeds) -> dict:
    def per_type(name):
        n, vals = _prop(deck, name)
        if vals[0] != "peratomtype" or len(vals) < 1 + deck.ntypes:
            raise DeckError(f"line {n}", " ".join(vals), f"{name} needs peratomtype and one value per type")
        return [_number(v, f"line {n}", name) for v in vals[1:1 + deck.ntypes]]

    E, nu = per_type("youngsModulus"), per_type("poissonsRatio")
    n, vals = _prop(deck, "coefficientRestitution")
    if vals[0] != "peratomtypepair" or len(vals) < 2 + int(vals[1]) ** 2:
        raise DeckError(f"line {n}", " ".join(vals), "coefficientRestitution needs peratomtypepair N and N*N values")
    m = int(vals[1])
    matrix = [_number(v, f"line {n}", "coefficientRestitution") for v in vals[2:2 + m * m]]
    if max(i, j) > m:
        raise DeckError(f"line {n}", " ".join(vals), f"no coefficientRestitution for types {i} {j}")
    e = matrix[(i - 1) * m + (j - 1)]
    extra = {}
    if deck.model == "hooke":
        nv, v = _prop(deck, "characteristicVelocity")
        extra["characteristic_velocity"] = _number(v[-1], f"line {nv}", "characteristicVelocity")
    pair = _pair(deck, i, j)
    kw = {"model": deck.model, "limit_force": deck.limit_force, **extra}
    contact = liggghts_contact(pair, E=E[i - 1], nu=nu[i - 1], E2=E[j - 1], nu2=nu[j - 1], e=e, **kw)
    try:
        cal = calibrate(contact.alpha, contact.gamma, D1=contact.D1, eps=e, g=speeds[len(speeds) // 2],
                        end=contact.end)
        e_new = liggghts_e(cal.contact)
    except ParameterError:
        e_new = None         # no coefficientRestitution gives that eps under this end rule
    exact = None
    if e_new is not None:
        new = list(matrix)
        new[(i - 1) * m + (j - 1)] = new[(j - 1) * m + (i - 1)] = e_new
        head = f"{deck.prop_fix['coefficientRestitution']} property/global coefficientRestitution peratomtypepair {m}"
        exact = head + " " + " ".join(f"{x:.10g}" for x in new)
    return {"types": [i, j], "model": f"LIGGGHTS {deck.model}, limitForce {'on' if deck.limit_force else 'off'}",
            "typed_e": e, "end": contact.end, "contact": contact, "exact_line": exact, "line": n}


def _eps_or_stick(contact, g: float) -> tuple[float, bool]:
    """(eps, False), or (0, True) where the overlap rule's attraction keeps the bodies together."""
    try:
        return contact.eps(g), False
    except StickError:
        return 0.0, True


def audit_deck(text: str, speeds, radius: dict | None = None, density: dict | None = None) -> dict:
    """{"code", "pairs": [...], "unknown_lines": [...], "ignored": [...]}: for every type pair the eps
    the deck really gives at ``speeds`` (relative accuracy 1e-10), beside the e typed (or None)
    and the line that would give that e exactly."""
    speeds = [float(g) for g in speeds]
    if not speeds:
        raise ParameterError("g", speeds, "give at least one impact speed")
    deck = read_deck(text, radius, density)
    if deck.ntypes <= 0:
        raise DeckError("create_box", None, "the deck has no create_box: the number of types is unknown")
    pairs = []
    for i in range(1, deck.ntypes + 1):
        for j in range(i, deck.ntypes + 1):
            row = (_lammps_pair if deck.code == "LAMMPS" else _liggghts_pair)(deck, i, j, speeds)
            contact = row.pop("contact")
            eps = [_eps_or_stick(contact, g) for g in speeds]
            row.update(speeds=speeds, eps=[e for e, _ in eps], sticks=[s for _, s in eps],
                       **{k: v for k, v in contact.as_dict().items() if k != "end"})
            pairs.append(row)
    return {"code": deck.code, "pairs": pairs, "unknown_lines": [{"line": n, "text": t} for n, t in deck.unknown],
            "ignored": sorted(set(deck.ignored))}

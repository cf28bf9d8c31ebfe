"""LIGGGHTS' deck dialect: what ``pair_style gran model hertz|hooke``, its materials (``fix
property/global``: youngsModulus, poissonsRatio, coefficientRestitution, characteristicVelocity),
``model hertz/stiffness|hooke/stiffness`` and their per-pair stiffness and damping (kn, gamman,
gamman_abs with hooke/stiffness's absolute_damping on),
its particle templates and its ``fix wall/gran`` walls (primitive planes, the faces of meshes of the
type their ``fix mesh/surface`` gives) mean for a head-on contact. The generic reader
(:mod:`restitution.dem.deck.reader`) reaches it through its table of dialects, by pair style and by
engine; this module has the same names as every dialect: ``ENGINE``, ``PAIR_STYLES``, ``MAPPED``,
``FIXES``, :func:`pair_style`, :func:`pair_coeff`, :func:`pair_row` and :func:`wall`.

LIGGGHTS' own checks on the materials (its limits on Young's modulus, Poisson's ratio and e) stop
its run before the first step: a deck LIGGGHTS refuses gives no eps. Its aliases of the
property/global styles (atomtype, vector; atomtypepair, matrix) are read.
"""

from __future__ import annotations

import re

from ...dialect.state import (FLAT_WALLS, Deck, DeckError, PairNotMapped, atom_type, exact_e, number, number_or_none,
                              place, pour_into, spheres, wall_faces)
from ....core.errors import ParameterError
from .contact import (LIGGGHTS_E, LIGGGHTS_MODEL_TYPES, LIGGGHTS_MODELS, LIGGGHTS_MODULUS, LIGGGHTS_NU,
                      STIFFNESS_MODELS, STIFFNESS_UNITS, liggghts_accepts_e, liggghts_contact, liggghts_e,
                      liggghts_stiffness_contact)

__all__ = ["ENGINE", "PAIR_STYLES", "MAPPED", "FIXES", "pair_style", "pair_coeff", "pair_row", "wall"]

ENGINE = "LIGGGHTS"
#: The pair styles this dialect reads
PAIR_STYLES = ("gran",)
#: What it maps, as a refusal of another pair style lists it
MAPPED = "LIGGGHTS pair_style gran model hertz|hooke|hertz/stiffness|hooke/stiffness"
#: The normal models it maps
_NORMAL = LIGGGHTS_MODELS + STIFFNESS_MODELS
#: The model keywords each normal model takes that may change its normal force (LIGGGHTS 3.8.0
#: stops on the others: "Unknown argument or wrong keyword order"); tangential_damping, which
#: every one takes, changes only the tangential damping
_NORMAL_KEYS = {"hertz": ("limitForce",), "hooke": ("limitForce",), "hertz/stiffness": ("limitForce",),
                "hooke/stiffness": ("limitForce", "absolute_damping")}
#: The keywords a normal model takes that change its tangential stiffness alone: hooke's ktToKnUser
#: (kt = 2/7 kn where on; LIGGGHTS 3.8.0's hooke model, measured by field round 26, L23: e 0.6 gave
#: 0.600089 head-on at dt 1e-7 s, its step's error)
_TANGENTIAL_KEYS = {"hooke": ("ktToKnUser",)}

def pair_style(deck: Deck, words: list, where: str, line: str) -> None:
    """pair_style gran model hertz|hooke|hertz/stiffness|hooke/stiffness [limitForce on|off]
    [absolute_damping on|off] [tangential, rolling_friction, tangential_damping ...] [surface
    default]: the normal model, limitForce and absolute_damping.

    Parameters
    ----------
    deck : Deck
        Changed in place (``model``, ``limit_force``, ``absolute_damping``, ``ignored``).
    words : list of str
        The command's words.
    where, line : str
        The line, for the refusal.

    Raises
    ------
    DeckError
        Where a keyword may change the normal force, or no model is given.

    Examples
    --------
    >>> deck = Deck()
    >>> pair_style(deck, "pair_style gran model hertz tangential history".split(), "line 1", "")
    >>> deck.model, deck.ignored
    ('hertz', ['tangential history'])
    >>> pair_style(deck, "pair_style gran model hooke tangential history ktToKnUser on".split(), "line 1", "")
    >>> deck.model, deck.ignored[-1]
    ('hooke', 'ktToKnUser on')
    """
    # every pair_style line sets the style afresh: LIGGGHTS' default for what it does not name
    # (limitForce off; checked: on, then a line without it, gives eps = e)
    deck.cohesion, pairs = _cohesion(words[2:])
    try:
        deck.model, deck.limit_force, deck.absolute_damping = _normal(pairs)
    except ValueError as why:
        raise DeckError(where, line, str(why)) from None
    for i in range(2, len(words) - 1, 2):
        if words[i] in _HEAD_ON_IDLE or words[i] in _TANGENTIAL_KEYS.get(deck.model, ()):
            deck.ignored.append(f"{words[i]} {words[i + 1]}")


#: pair style keywords with no part in a head-on contact: the tangential and rolling models and
#: their options (torsionTorque, which LIGGGHTS 3.8.0's rolling model epsd3 registers, adds a
#: torque about the contact normal)
_HEAD_ON_IDLE = ("tangential", "rolling_friction", "tangential_damping", "torsionTorque")


#: LIGGGHTS cohesion models whose force is the cohesionEnergyDensity of the pair times a contact area
_COHESION = ("sjkr", "sjkr2")


def _cohesion(pairs: list) -> tuple[str, list]:
    """(the cohesion model of _COHESION the key-value pairs name, or "", the pairs without it): its
    force is cohesionEnergyDensity times the contact area, audited where that is 0."""
    for i in range(0, len(pairs) - 1, 2):
        if pairs[i] == "cohesion" and pairs[i + 1] in _COHESION:
            return pairs[i + 1], pairs[:i] + pairs[i + 2:]
    return "", pairs


def _no_cohesion(deck: Deck, i: int, j: int) -> None:
    """Refuses a pair a cohesion model gives a force: its cohesionEnergyDensity is not 0."""
    if not deck.cohesion:
        return
    matrix, loc = _matrix(deck, "cohesionEnergyDensity")
    k = matrix[(i - 1) * deck.ntypes + (j - 1)]
    if k != 0:
        # the pair alone: LIGGGHTS runs it, and the deck's other pairs feel no cohesion
        raise PairNotMapped(loc, f"types {i} {j}", f"cohesion {deck.cohesion} with cohesionEnergyDensity {k:g} "
                                                   "adds an attractive normal force, which is not mapped")


def _normal(pairs: list) -> tuple:
    """(normal model, limitForce, absolute_damping) from key-value pairs (a pair style's after
    ``gran``, or a wall's without its wall style and general keywords).

    Raises
    ------
    ValueError
        Naming the first pair that is not mapped (it may change the normal force), or no model.
    """
    model, on = None, {"limitForce": False, "absolute_damping": False}
    for i in range(0, len(pairs), 2):
        key = pairs[i]
        val = pairs[i + 1] if i + 1 < len(pairs) else None
        if key == "model":
            if val not in _NORMAL:
                raise ValueError(f"model {val} is not mapped ({', '.join(_NORMAL)} are)")
            model = val
        elif key in on and model is not None and key in _NORMAL_KEYS[model]:
            on[key] = val == "on"
        elif key in _HEAD_ON_IDLE or key == "surface" and val == "default" \
                or model is not None and key in _TANGENTIAL_KEYS.get(model, ()):
            pass                  # no part in a head-on contact
        else:
            raise ValueError(f"{key} {val} is not mapped (it may change the normal force)")
    if model is None:
        raise ValueError(f"no model {'|'.join(_NORMAL)}")
    return model, on["limitForce"], on["absolute_damping"]


def pair_coeff(deck: Deck, words: list, where: str, line: str, loc) -> None:
    """``pair_coeff * *``: LIGGGHTS' coefficients come from fix property/global, not from it.

    Parameters
    ----------
    deck, words, where, line, loc
        As every dialect's pair_coeff takes them; none is read.

    Examples
    --------
    >>> pair_coeff(Deck(), ["pair_coeff", "*", "*"], "line 7", "pair_coeff * *", (None, 7))
    """


# ---------------------------------------------------------------------------- fixes of its own
def _property_global(deck: Deck, words: list, where: str, line: str, loc) -> None:
    deck.props[words[4]] = (loc, words[5:])
    deck.prop_fix[words[4]] = f"fix {words[1]} {words[2]}"     # the exact line keeps the deck's fix ID


def _sphere_template(deck: Deck, words: list, where: str, line: str, loc) -> None:
    """fix ID group particletemplate/sphere seed atom_type T density constant RHO radius constant R
    (where the engine made the runs, :attr:`Deck.ran`, nothing: what it inserted is among the atoms
    held)."""
    if deck.ran:
        return
    tokens, t, size = words[5:], None, {}
    for k, tok in enumerate(tokens):
        if tok == "atom_type":
            if k + 1 == len(tokens):
                raise DeckError(where, line, "atom_type needs a type")
            t = atom_type(tokens[k + 1], where, line)
        elif tok in ("density", "radius") and k + 2 < len(tokens) and tokens[k + 1] == "constant" \
                and t is not None:
            size[tok] = number(tokens[k + 2], where, line)
            if deck.held is None:       # the hand reader: the template's size is its type's
                (deck.density if tok == "density" else deck.radius)[t] = size[tok]
        elif tok in ("density", "radius") and k + 1 < len(tokens) and t is not None:
            # other distributions (gaussian, ...) give no single value: the type is unset, and says why
            (deck.density if tok == "density" else deck.radius).pop(t, None)
            deck.missing[t] = f"fix {words[1]} gives type {t} a {tok} from a {tokens[k + 1]} distribution"
    # its spheres are made only by an insertion whose distribution draws it (_insertion): a template
    # no insertion uses, or drawn with weight 0, makes none (field round 19, C5: L39, L40 audited
    # sizes and types LIGGGHTS never made)
    deck.sphere_templates[words[1]] = (t, (size["radius"], size["density"])) if len(size) == 2 else None


def _distribution(deck: Deck, words: list, where: str, line: str, loc) -> None:
    """fix ID group particledistribution/discrete[/numberbased|/massbased] seed N template1 weight1 ...:
    the templates it draws from, those of weight 0 left out (LIGGGHTS makes none of them: field round
    19, C5, L37)."""
    drawn = []
    for tid, weight in zip(words[6::2], words[7::2]):
        value = number_or_none(weight)
        if value is None or value > 0:
            drawn.append(tid)
    deck.distributions[words[1]] = drawn


def _insertion(deck: Deck, words: list, where: str, line: str, loc) -> None:
    """fix ID group insert/pack|insert/stream|insert/rate/region ... distributiontemplate D ...: the
    (type, size) of each sphere template D draws from, as the atoms it inserts in the runs get them
    (``pours``; a ``set`` after its runs changes those it made, :func:`~restitution.dem.deck.reader.set_poured`).
    Nothing where a template has no one constant size (its type's entry in ``missing`` says so)."""
    named = [words[k + 1] for k in range(4, len(words) - 1) if words[k] == "distributiontemplate"]
    made = [deck.sphere_templates.get(tid) for tid in deck.distributions.get(named[0], [None])] if named else [None]
    if deck.held is None or deck.ran:
        return
    # LIGGGHTS reads the start step as C's atoi does, and stops where it is not after the step the
    # runs reach (measured: start 2000 after run 2000 stops, 2001 runs); the audit's pass makes no
    # step, so its engine never stops there
    start = [int(m.group(0)) for k in range(4, len(words) - 1) if words[k] == "start"
             and (m := re.match(r"[-+]?\d+", words[k + 1]))]
    if start and deck.step is not None and start[0] <= deck.step:
        raise DeckError(where, line, f"start {start[0]} is not after step {deck.step}, which the deck's runs reach "
                                     "here: LIGGGHTS stops on it ('start' step can not be before current step)")
    if None in made:
        return
    sizes = {t: {size for u, size in made if u == t} for t, _ in made}
    if start and (deck.step is None or start[0] > deck.step + 1):
        # nothing is inserted before the start step (field round 19, C4: L33's spheres were audited
        # where LIGGGHTS, its start after the only run, made none)
        deck.waiting[words[1]] = (start[0], words[3], sizes)
        return
    for t, sizes in sizes.items():
        deck.pours[(words[1], t)] = (t, sizes)
        # its spheres may be inserted after the one step the audit runs: with the type's other sizes
        pour_into(deck, t, sizes)


def _mesh(deck: Deck, words: list, where: str, line: str, loc) -> None:
    # a mesh's atom type (its material), for the walls made of it; None if not given
    typed = [words[k + 1] for k in range(4, len(words) - 1) if words[k] == "type"]
    deck.meshes[words[1]] = int(typed[0]) if typed and typed[0].isdigit() else None


def _servo(deck: Deck, words: list, where: str, line: str, loc) -> None:
    # a servo wall is a mesh whose velocity its controller changes every step to reach a target
    # force: a sphere's contact with it meets an accelerating face, as a shaken mesh's does
    _mesh(deck, words, where, line, loc)
    deck.shaken[words[1]] = (loc, line, words[1])


#: fix style -> (its least number of words, what it does to the deck); shorter, not understood
FIXES = {"property/global": (6, _property_global), "particletemplate/sphere": (4, _sphere_template),
         **{f"particledistribution/discrete{kind}": (6, _distribution) for kind in ("", "/numberbased", "/massbased")},
         **{f"insert/{kind}": (4, _insertion) for kind in ("pack", "stream", "rate/region")},
         # planar: a mesh LIGGGHTS checks to be one plane, met as any other (0.45 for a typed e 0.45)
         "mesh/surface": (4, _mesh), "mesh/surface/stress": (4, _mesh), "mesh/surface/planar": (4, _mesh),
         "mesh/surface/stress/servo": (4, _servo)}


# ---------------------------------------------------------------------------- materials and pairs
#: fix property/global's styles LIGGGHTS 3.8.0 takes for a per-type list and a per-type-pair
#: matrix (its aliases, checked: a deck with each runs)
_PER_TYPE = ("peratomtype", "atomtype", "vector")
_PER_PAIR = ("peratomtypepair", "atomtypepair", "matrix")


def _prop(deck: Deck, name: str):
    if name not in deck.props:
        raise DeckError("fix property/global", name, "the deck does not define it (LIGGGHTS needs it)")
    return deck.props[name]


def _materials(deck: Deck) -> tuple:
    """(E, nu, the coefficientRestitution matrix flattened, its location) from fix property/global."""
    # LIGGGHTS itself stops unless each list has exactly one value per type (per type pair, symmetric)
    def per_type(name):
        loc, vals = _prop(deck, name)
        if vals[0] not in _PER_TYPE:
            raise DeckError(place(loc), " ".join(vals), f"{name} {vals[0]}: LIGGGHTS takes it as one of "
                                                         f"{', '.join(_PER_TYPE)}, one value per type")
        if len(vals) != 1 + deck.ntypes:
            raise DeckError(place(loc), " ".join(vals), f"{name} gives {len(vals) - 1} value(s) for the "
                                                         f"{deck.ntypes} types: LIGGGHTS needs one each")
        return [number(v, place(loc), name) for v in vals[1:]]

    E, nu = per_type("youngsModulus"), per_type("poissonsRatio")
    matrix, loc = _matrix(deck, "coefficientRestitution")
    where = place(loc)
    _limits(deck, E, nu, matrix, where)
    return E, nu, matrix, loc


def _matrix(deck: Deck, name: str) -> tuple:
    """(the per-type-pair property ``name`` flattened row by row, its location), as LIGGGHTS takes
    it: peratomtypepair (or an alias) N, then N x N values, symmetric."""
    loc, vals = _prop(deck, name)
    where, m = place(loc), deck.ntypes
    if vals[0] not in _PER_PAIR:
        raise DeckError(where, " ".join(vals), f"{name} {vals[0]}: LIGGGHTS takes it as one of "
                                               f"{', '.join(_PER_PAIR)} N, then N x N values")
    if len(vals) < 2 or vals[1] != str(m):
        raise DeckError(where, " ".join(vals), f"{name} {vals[0]} gives N = "
                                               f"{vals[1] if len(vals) > 1 else 'nothing'} where the deck has {m} "
                                               f"types: LIGGGHTS needs {vals[0]} {m}")
    if len(vals) != 2 + m * m:
        raise DeckError(where, " ".join(vals), f"{name} {vals[0]} {m} gives {len(vals) - 2} "
                                               f"value(s): LIGGGHTS needs {m}x{m} values, one per type pair")
    matrix = [number(v, where, name) for v in vals[2:]]
    # which of two unequal entries a contact reads would depend on the order of the atoms in the
    # engine's neighbour list
    if any(matrix[(a - 1) * m + b - 1] != matrix[(b - 1) * m + a - 1] for a in range(1, m + 1)
           for b in range(a + 1, m + 1)):
        raise DeckError(where, " ".join(vals), f"the {name} matrix is not symmetric")
    return matrix, loc


def _stiffness(deck: Deck, model: str, limit_force: bool, absolute: bool, pair, i: int, j: int):
    """The contact of types i and j (j a wall's type for a wall) under hooke/stiffness or
    hertz/stiffness: kn and gamman (gamman_abs) as typed for the pair."""
    if deck.units not in STIFFNESS_UNITS:
        raise DeckError("units", deck.units, f"LIGGGHTS divides kn by units {deck.units}'s nktv2p, which is not 1: "
                                             f"model {model} is mapped in units {', '.join(STIFFNESS_UNITS)}")
    damping = "gamman_abs" if absolute else "gamman"
    (kn, loc_k), (gn, loc_g) = _matrix(deck, "kn"), _matrix(deck, damping)
    k = (i - 1) * deck.ntypes + (j - 1)
    try:
        return liggghts_stiffness_contact(pair, model=model, kn=kn[k], gamman=gn[k], absolute_damping=absolute,
                                          limit_force=limit_force)
    except ParameterError as why:
        at = loc_k if why.field in ("kn", "D1") else loc_g
        raise DeckError(place(at), f"types {i} {j}", str(why)) from None


def _label(model: str, limit_force: bool, absolute: bool) -> str:
    """The model as the audit's rows name it."""
    return (f"LIGGGHTS {model}, " + (f"absolute_damping {'on' if absolute else 'off'}, "
                                     if model == "hooke/stiffness" else "")
            + f"limitForce {'on' if limit_force else 'off'}")


def _model(deck: Deck, model: str, limit_force: bool) -> dict:
    """liggghts_contact's keywords for a normal model (hooke needs characteristicVelocity)."""
    kw = {"model": model, "limit_force": limit_force}
    if model == "hooke":
        lv, v = _prop(deck, "characteristicVelocity")
        kw["characteristic_velocity"] = number(v[-1], place(lv), "characteristicVelocity")
    return kw


def pair_row(deck: Deck, i: int, j: int) -> dict:
    """The audit's row for type pair (i, j), before its eps: the contact LIGGGHTS gives it, the e
    typed in coefficientRestitution and the line that gives that e exactly. Its arguments and its
    row are :meth:`~restitution.dem.dialect.state.DeckDialect.pair_row`'s.

    Raises
    ------
    DeckError
        Where a material is missing, not LIGGGHTS' form, or outside LIGGGHTS' limits.

    Examples
    --------
    >>> deck = Deck(ntypes=1, radius={1: 0.005}, density={1: 2500.0}, model="hertz", units="si")
    >>> for name, vals in [("youngsModulus", "peratomtype 5e6"), ("poissonsRatio", "peratomtype 0.45"),
    ...                    ("coefficientRestitution", "peratomtypepair 1 0.9")]:
    ...     deck.props[name], deck.prop_fix[name] = ((None, 3), vals.split()), "fix m all"
    >>> row = pair_row(deck, 1, 1)
    >>> row["model"], row["typed_e"], row["exact_line"]
    ('LIGGGHTS hertz, limitForce off', 0.9, 'fix m all property/global coefficientRestitution peratomtypepair 1 0.9')
    """
    pair = spheres(deck, i, j)
    _no_cohesion(deck, i, j)
    model = _label(deck.model, deck.limit_force, deck.absolute_damping)
    if deck.cohesion:
        model += f", cohesion {deck.cohesion} (cohesionEnergyDensity 0 here: no force)"
    if deck.model in STIFFNESS_MODELS:
        # no e typed: the stiffness and damping are, and no one line gives the pair an eps
        contact = _stiffness(deck, deck.model, deck.limit_force, deck.absolute_damping, pair, i, j)
        loc = _prop(deck, "gamman_abs" if deck.absolute_damping else "gamman")[0]
        return {"types": [i, j], "model": model, "typed_e": None, "end": contact.end, "contact": contact,
                "pair": pair, "line": loc[1], "file": loc[0], "exact_line": None}
    E, nu, matrix, loc = _materials(deck)
    m = deck.ntypes
    e = matrix[(i - 1) * m + (j - 1)]
    kw = _model(deck, deck.model, deck.limit_force)
    contact = liggghts_contact(pair, E=E[i - 1], nu=nu[i - 1], E2=E[j - 1], nu2=nu[j - 1], e=e, **kw)
    return {"types": [i, j], "model": model, "typed_e": e, "end": contact.end, "contact": contact, "pair": pair,
            "line": loc[1], "file": loc[0], "exact_line": _exact_line(deck, matrix, i, j, contact)}


def _exact_line(deck: Deck, matrix: list, i: int, j: int, contact) -> str | None:
    """The coefficientRestitution line with the entry (i, j) replaced by the e that gives
    ``contact`` eps = the e typed there; None where no e does or LIGGGHTS would refuse it."""
    m = deck.ntypes
    # an undamped contact (e = 1) gives eps = 1 = e under either end rule: the line as typed
    e_new = 1.0 if contact.D2 == 0.0 else exact_e(contact, matrix[(i - 1) * m + (j - 1)], liggghts_e)
    if e_new is None or not liggghts_accepts_e(e_new):   # LIGGGHTS would stop on it
        return None
    new = list(matrix)
    new[(i - 1) * m + (j - 1)] = new[(j - 1) * m + (i - 1)] = e_new
    style = deck.props["coefficientRestitution"][1][0]      # the deck's own word: peratomtypepair or an alias
    head = f"{deck.prop_fix['coefficientRestitution']} property/global coefficientRestitution {style} {m}"
    return head + " " + " ".join(f"{x:.10g}" for x in new)


def _limits(deck: Deck, E: list, nu: list, e: list, where_e: str) -> None:
    """LIGGGHTS' own checks on the materials (codes.LIGGGHTS_E, LIGGGHTS_NU, LIGGGHTS_MODULUS),
    which stop its run before the first step: a deck LIGGGHTS refuses gives no eps."""
    where_E = place(deck.props["youngsModulus"][0])
    low, high = LIGGGHTS_MODULUS.get(deck.units, (None, None))
    if low is not None and not deck.soft and min(E) < low:
        raise DeckError(where_E, f"youngsModulus {min(E):g}", f"LIGGGHTS stops: it requires youngsModulus >= {low:g} "
                                                                f"in {deck.units} units unless soft_particles yes")
    if high is not None and not deck.hard and max(E) > high:
        raise DeckError(where_E, f"youngsModulus {max(E):g}", f"LIGGGHTS stops: it requires youngsModulus <= {high:g} "
                                                                f"in {deck.units} units unless hard_particles yes")
    if not all(LIGGGHTS_NU[0] <= v <= LIGGGHTS_NU[1] for v in nu):
        raise DeckError(place(deck.props["poissonsRatio"][0]), "poissonsRatio",
                        f"LIGGGHTS stops: it requires {LIGGGHTS_NU[0]:g} <= poissonsRatio <= {LIGGGHTS_NU[1]:g}")
    if not all(liggghts_accepts_e(v) for v in e):
        raise DeckError(where_e, "coefficientRestitution", f"LIGGGHTS stops: it requires {LIGGGHTS_E[0]:g} < "
                                                           f"coefficientRestitution <= {LIGGGHTS_E[1]:g}")


# ---------------------------------------------------------------------------- walls
#: LIGGGHTS fix wall/gran: the general keywords after the wall style with their number of values
#: (none changes a head-on contact); the model_type/model_name pairs before it are
#: codes.LIGGGHTS_MODEL_TYPES
_LIGGGHTS_WALL_GENERAL = {"shear": 2, "temperature": 1, "store_force": 1, "store_force_contact": 1,
                          "store_force_contact_stress": 1}
#: primitive wall styles and their number of arguments
_LIGGGHTS_PRIMITIVES = {"xplane": 1, "yplane": 1, "zplane": 1, "xcylinder": 3, "ycylinder": 3, "zcylinder": 3}
#: Why a cylinder is audited as a plane: LIGGGHTS 3.8.0's normal models take the sphere's own
#: radius as the effective radius against any wall (checked: a sphere of radius 5 mm inside a
#: zcylinder of 7.5 mm, hertz/stiffness, gives a plane's eps to 2e-9 after time-step
#: extrapolation, where the cylinder's curvature would have lowered it by 0.03)
_FLAT_BY_ENGINE = "LIGGGHTS takes the sphere's own radius as the effective radius against every wall"


def wall(deck: Deck, loc, words: list, unknown: list):
    """fix ID group wall/gran [model_type model_name]... (primitive type W STYLE ARGS | mesh
    n_meshes N meshes ID...) [general keywords] [model keywords], the order LIGGGHTS documents:
    for each surface (a primitive plane or cylinder, the latter a plane to LIGGGHTS' contact, or
    each mesh, whose type is its fix mesh/surface's) a
    triple (mesh ID or None, a function of the wall Pair and the sphere's type giving (contact,
    typed e, model, exact line or None), W): the contact of a type with an atom of type W under the
    wall's own model (its model keywords, limitForce among them, are its own, not the pair
    style's), the wall as the second body. None, with the reason in ``unknown``, where a part is
    not mapped (a cohesion model, an unknown keyword, ...). Its arguments are
    :meth:`~restitution.dem.dialect.state.DeckDialect.wall`'s.

    Raises
    ------
    DeckError
        Where the wall's type is outside the deck's, or its materials are not LIGGGHTS'.

    Examples
    --------
    >>> unknown = []
    >>> wall(Deck(), (None, 9), "fix w all wall/gran model jkr primitive type 1 zcylinder 1 0 0".split(), unknown)
    >>> unknown[0][3]
    "model jkr is not mapped (hertz, hooke, hertz/stiffness, hooke/stiffness are): the wall's contacts are not audited"
    """
    text, where = " ".join(words), place(loc)

    def skip(why):
        unknown.append((*loc, text, f"{why}: the wall's contacts are not audited"))
        return None

    if words[3] != "wall/gran":
        return skip(f"fix {words[3]} is not mapped (LIGGGHTS' walls are fix wall/gran primitives and meshes)")
    k = 4
    while k + 1 < len(words) and words[k] in LIGGGHTS_MODEL_TYPES:
        k += 2
    pairs = words[4:k]            # the model_type/model_name pairs; the model keywords come last
    surfaces = []                 # (mesh ID or None, wall type, what it is, its faces)
    if k < len(words) and words[k] == "primitive":
        if k + 3 >= len(words) or words[k + 1] != "type" or words[k + 3] not in _LIGGGHTS_PRIMITIVES:
            return skip("a primitive wall not read (primitive type W STYLE ARGS)")
        style = words[k + 3]
        if not words[k + 2].isdigit():
            return skip(f"wall type {words[k + 2]} is not a type the reader can read")
        # a primitive plane is met from either side; a mesh's faces may turn anywhere
        surfaces.append((None, int(words[k + 2]), f"{style} wall" if style in FLAT_WALLS else
                         f"{style} wall (audited as a flat wall: {_FLAT_BY_ENGINE})",
                         wall_faces(style, words[k + 4:k + 5], either_side=True)))
        k += 4 + _LIGGGHTS_PRIMITIVES[style]
    elif k < len(words) and words[k] == "mesh":
        n = int(words[k + 2]) if k + 2 < len(words) and words[k + 1] == "n_meshes" and words[k + 2].isdigit() else 0
        if n == 0 or k + 4 + n > len(words) or words[k + 3] != "meshes":
            return skip("a mesh wall not read (mesh n_meshes N meshes ID...)")
        for mesh in words[k + 4:k + 4 + n]:
            if mesh not in deck.meshes:
                return skip(f"mesh {mesh} has no fix mesh/surface before it")
            if deck.meshes[mesh] is None:
                return skip(f"mesh {mesh}'s fix mesh/surface gives no type the reader can read")
            surfaces.append((mesh, deck.meshes[mesh], f"a face of mesh {mesh}", None))
        k += 4 + n
    else:
        return skip("no wall style read (primitive or mesh)")
    while k < len(words):
        key = words[k]
        if key == "shear" and k + 1 < len(words) and surfaces[0][0] is None:
            # a plane's shear along its own normal, or a cylinder's off its axis, moves the wall into or
            # away from the sphere: LIGGGHTS runs it (LAMMPS refuses it), and a zplane with shear z 0.5
            # gave 0.741 at g = 1 where the still floor gives 0.700 (field round 17, G22)
            flat = style in FLAT_WALLS
            if (words[k + 1] == style[0]) == flat:
                return skip(f"shear {' '.join(words[k + 1:k + 3])} moves the wall "
                            f"{'along its own normal' if flat else 'off its axis'}, into or away from the sphere "
                            "during a contact")
        if key in _LIGGGHTS_WALL_GENERAL:
            k += 1 + _LIGGGHTS_WALL_GENERAL[key]
        elif key in ("limitForce", "absolute_damping", "tangential_damping") and k + 1 < len(words):
            pairs, k = pairs + words[k:k + 2], k + 2
        else:
            return skip(f"keyword {key} is not mapped")
    cohesion, pairs = _cohesion(pairs)
    try:
        model, limit, absolute = _normal(pairs)
    except ValueError as why:
        return skip(str(why))
    for _, w, _, _ in surfaces:
        if not 1 <= w <= deck.ntypes:
            raise DeckError(where, text, f"the wall's type must be in 1..{deck.ntypes}")
    label = _label(model, limit, absolute)
    if cohesion:
        # as for a pair: no force where the wall's type's cohesionEnergyDensity with every sphere
        # type is 0 (LIGGGHTS reads the entry of the sphere's type and the wall's)
        matrix, _ = _matrix(deck, "cohesionEnergyDensity")
        for _, w, _, _ in surfaces:
            k = next((matrix[(t - 1) * deck.ntypes + (w - 1)] for t in range(1, deck.ntypes + 1)
                      if matrix[(t - 1) * deck.ntypes + (w - 1)] != 0), 0)
            if k:
                return skip(f"cohesion {cohesion} with cohesionEnergyDensity {k:g} for the wall's type {w} adds an "
                            "attractive normal force, which is not mapped")
        label += f", cohesion {cohesion} (cohesionEnergyDensity 0 here: no force)"
    if model in STIFFNESS_MODELS:
        def stiff_with(w: int, surface: str):
            def contact(pair, t):
                return (_stiffness(deck, model, limit, absolute, pair, t, w), None, f"{label}, {surface} of type {w}",
                        None)
            return contact
        return [(mesh, stiff_with(w, label_), w, faces) for mesh, w, label_, faces in surfaces]
    E, nu, matrix, _ = _materials(deck)
    kw = _model(deck, model, limit)

    def contact_with(w: int, surface: str):
        def contact(pair, t):
            e = matrix[(t - 1) * deck.ntypes + (w - 1)]
            c = liggghts_contact(pair, E=E[t - 1], nu=nu[t - 1], E2=E[w - 1], nu2=nu[w - 1], e=e, **kw)
            # The entry (t, W) of the matrix also sets the sphere pair (t, W). Under either model
            # LIGGGHTS' damping makes eps a function of e and limitForce alone (hertz: Tsuji's
            # scaling; hooke: a damping ratio of e alone), so where the wall's model and limitForce
            # are the pair style's, one e gives both contacts eps = e typed: the pair's exact line.
            # Elsewhere the two want different e's and no line serves both.
            same = (model, limit) == (deck.model, deck.limit_force)
            exact = _exact_line(deck, matrix, t, w, c) if same else None
            return c, e, f"{label}, {surface} of type {w}", exact
        return contact
    return [(mesh, contact_with(w, label), w, faces) for mesh, w, label, faces in surfaces]

"""LAMMPS' deck dialect: what ``pair_style granular`` (and the older gran/hooke, gran/hooke/history,
gran/hertz/history), its ``pair_coeff`` lines and its ``fix wall/gran`` walls mean for a head-on
contact. The generic reader (:mod:`restitution.dem.deck.reader`) reaches it through its table of
dialects, by pair style and by engine; this module has the same names as every dialect:
``ENGINE``, ``PAIR_STYLES``, ``MAPPED``, ``FIXES``, :func:`pair_style`, :func:`pair_coeff`,
:func:`pair_row` and :func:`wall`.

A type pair no ``pair_coeff`` covers is mixed as LAMMPS mixes it (pair_style granular: the same
models for both types, geometric means, Young's moduli combined as 1/E* = sum (1 - nu^2)/E,
limit_damping if either type has it). Tangential, rolling, twisting and heat models take no part
in a head-on collision: named and passed over.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import partial

from ...dialect.state import (DEFAULT_SKIN, FLAT_WALLS, Deck, DeckError, PairNotMapped, exact_e, number, number_or_none, place,
                              spheres, type_pairs, wall_faces)
from ...contact import Contact, ElasticContact
from ...pair import WALL_SIZE, Pair
from .contact import (DAMPING_MODELS, E_DAMPINGS, LAMMPS_GRAN_STYLES, lammps_contact, lammps_eta_n0,
                      lammps_gran_contact)

__all__ = ["ENGINE", "DEFAULT_DT", "SPEED_UNITS", "FTM2V", "NKTV2P", "Region", "read_region", "region_moves", "REGION_UNBOUNDED", "region_number",
           "PAIR_STYLES", "MAPPED", "FIXES", "pair_style", "pair_coeff", "pair_row", "wall", "concave_cylinder",
           "accelerated", "own_cutoff"]

#: LAMMPS' default time step per unit style (checked in LAMMPS 22 Jul 2025), where a deck sets none
DEFAULT_DT = {"lj": 0.005, "real": 1.0, "metal": 0.001, "si": 1e-8, "cgs": 1e-8, "electron": 0.001, "micro": 2.0,
              "nano": 0.00045}

#: The speed unit of each unit style (LAMMPS' units page; LIGGGHTS has si and cgs of them): a deck's
#: --g is taken in its own units, as every length, mass and time it holds
SPEED_UNITS = {"si": "m/s", "cgs": "cm/s", "lj": "LJ velocity units (sigma/tau)", "real": "Angstrom/fs",
               "metal": "Angstrom/ps", "electron": "Bohr/atomic time unit", "micro": "micrometre/microsecond",
               "nano": "nm/ns"}

ENGINE = "LAMMPS"
#: The pair styles this dialect reads
PAIR_STYLES = ("granular", *LAMMPS_GRAN_STYLES)
#: What it maps, as a refusal of another pair style lists it
MAPPED = "LAMMPS pair_style granular, gran/hooke, gran/hooke/history and gran/hertz/history"
#: Fix styles of its own (fix pour and fix wall/gran are the generic reader's)
FIXES: dict = {}

#: LAMMPS pair_coeff keywords after the normal model: name -> number of arguments
_LAMMPS_TANGENTIAL = {"linear_nohistory": 2, "linear_history": 3, "mindlin": 3, "mindlin_rescale": 3,
                      "mindlin/force": 3, "mindlin_rescale/force": 3}
_LAMMPS_NORMAL_ARGS = {"hooke": 2, "hertz": 2, "hertz/material": 3}
#: LAMMPS' adhesive normal models (E, damping, nu, cohesion): at cohesion 0 DMT's pull-off term
#: vanishes and JKR's contact radius is Hertz's, so the force is hertz/material's with the same
#: three numbers (LAMMPS head-on, damping velocity: dmt 0.72967817 and 0.88455275 at g = 0.1 and
#: 10, as hertz/material; jkr the same to 1.5e-9)
_LAMMPS_ADHESIVE = ("dmt", "jkr")
#: LAMMPS pair_coeff heat models (pair_style granular's heat keyword) and their number of arguments:
#: conduction between touching spheres, which changes temperatures, not forces
_LAMMPS_HEAT = {"none": 0, "area": 1, "radius": 1}
#: LAMMPS' pressure conversion nktv2p (update.cpp) of the unit styles where it is not 1: gran/hertz/history
#: and its wall model divide Kn by it (pair_gran_hertz_history.cpp, fix_wall_gran.cpp)
NKTV2P = {"real": 68568.415, "metal": 1.6021765e6, "electron": 2.94210108e13}
#: LAMMPS' force-to-acceleration factor ftm2v (update.cpp) of the unit styles where it is not 1: the
#: integrator moves an atom by ftm2v F / m (fix nve/sphere's dtf = dt ftm2v / 2), F the force the
#: law computes with the atoms' true masses, so the contact's D1 and D2 are ftm2v times the law's
#: (metal, two spheres of mass 83.8 under gran/hooke 200 NULL 0.01: eps 0.4845 in LAMMPS, where the
#: law without the factor gives 0.9928); in every other style (si, cgs, lj, micro, nano) it is 1
FTM2V = {"real": 1.0 / 48.88821291 / 48.88821291, "metal": 1.0 / 1.0364269e-4, "electron": 0.937582899}


def pair_style(deck: Deck, words: list, where: str, line: str) -> None:
    """pair_style granular (its models come per pair_coeff line), or an older gran/* style with one
    law for every type pair.

    Parameters
    ----------
    deck : Deck
        Changed in place (``gran``).
    words : list of str
        The command's words, words[1] one of PAIR_STYLES.
    where, line : str
        The line, for the refusal.

    Raises
    ------
    DeckError
        Where an older style's arguments are not LAMMPS'.

    Examples
    --------
    >>> deck = Deck()
    >>> pair_style(deck, "pair_style gran/hooke 2000 0 50 0 0.5 0".split(), "line 1", "")
    >>> deck.gran["k_n"], deck.gran["limit_damping"]
    (2000.0, False)
    """
    if words[1] != "granular":
        deck.gran = _gran_law(words[1], words[2:], where, line)
    deck.cutoff = number(words[2], where, line) if words[1] == "granular" and len(words) > 2 else None
    deck.restored_cut = False


def accelerated(contact, units: str):
    """The contact as LAMMPS integrates it in ``units``: m delta'' = ftm2v F(delta, delta') (:data:`FTM2V`),
    F the law's force with the atoms' true masses (its damping's m_eff, tsuji's sqrt(m k)), so D1 and
    D2 per unit mass both times ftm2v; the contact itself where ftm2v is 1.

    Parameters
    ----------
    contact : Contact or ElasticContact
        The law's contact, forces as typed.
    units : str
        The deck's unit style.

    Returns
    -------
    Contact or ElasticContact

    Examples
    --------
    >>> from restitution.dem.contact import Contact
    >>> c = accelerated(Contact("1", "0", 2.0, 0.5, "overlap"), "metal")
    >>> round(c.D1 / 2.0, 4), round(c.D2 / 0.5, 4), accelerated(c, "si") is c
    (9648.5338, 9648.5338, True)
    """
    factor = FTM2V.get(units)
    if factor is None:
        return contact
    if isinstance(contact, ElasticContact):
        return ElasticContact(contact.alpha, factor * contact.D1, contact.end)
    return Contact(contact.alpha, contact.gamma, factor * contact.D1, factor * contact.D2, contact.end)


def _in_units(model: str, units: str) -> str:
    """A row's model, with the factor LAMMPS puts on its forces where it is not 1."""
    return f"{model}; units {units}: forces times ftm2v = {FTM2V[units]:.10g}" if units in FTM2V else model


def _older_contact(pair: Pair, law: dict, units: str):
    """The contact an older style's law (:func:`_gran_law`) gives in ``units``: gran/hertz/history's Kn
    divided by nktv2p (:data:`NKTV2P`), and the forces times ftm2v (:func:`accelerated`)."""
    if law["style"] == "gran/hertz/history":
        law = {**law, "k_n": law["k_n"] / NKTV2P.get(units, 1.0)}
    return accelerated(lammps_gran_contact(pair, **law), units)


def _gran_law(style: str, params: list, where: str, line: str) -> dict:
    """codes.lammps_gran_contact's keywords from an older style's Kn Kt gamma_n gamma_t xmu dampflag
    [limit_damping] (Kt, gamma_t, xmu and dampflag act tangentially only), Kn as typed."""
    if len(params) not in (6, 7) or len(params) == 7 and params[6] != "limit_damping":
        raise DeckError(where, line, f"{style} needs Kn Kt gamma_n gamma_t xmu dampflag [limit_damping], as "
                                     "LAMMPS does")
    return {"style": style, "k_n": number(params[0], where, line), "gamma_n": number(params[2], where, line),
            "limit_damping": len(params) == 7}


def pair_coeff(deck: Deck, words: list, where: str, line: str, loc) -> None:
    """pair_coeff I J ...: the line kept for every type pair it covers (read when audited); a heat
    model on it is named.

    Parameters
    ----------
    deck : Deck
        Changed in place (``coeffs``, ``unknown``).
    words : list of str
        The command's words, type labels replaced.
    where, line : str
        The line, for the refusal.
    loc : tuple
        (file or None, line number).

    Raises
    ------
    DeckError
        Before create_box, or where I or J is not a type or a range of types within 1..ntypes.

    Examples
    --------
    >>> deck = Deck(ntypes=2)
    >>> pair_coeff(deck, "pair_coeff * 2 hooke 1000 50".split(), "line 5", "", (None, 5))
    >>> sorted(deck.coeffs)
    [(1, 2), (2, 2)]
    """
    if "heat" in words[4:]:
        k = words.index("heat", 4)
        model = words[k + 1:k + 2 + _LAMMPS_HEAT.get(words[k + 1] if k + 1 < len(words) else "", 0)]
        deck.unknown.append((*loc, line, f"heat {' '.join(model)}: heat conduction, which does not touch the normal "
                                         "force: accepted"))
    if words[1].isdigit() and words[2].isdigit() and int(words[1]) > int(words[2]):
        words = [words[0], words[2], words[1], *words[3:]]      # LAMMPS swaps two single types
    for key in type_pairs(words[1], words[2], deck.ntypes, where, line):
        deck.coeffs[key] = (loc, words)


@dataclass
class _Coeff:
    """One pair_coeff line, as far as a head-on contact is concerned."""
    normal: str
    args: list          # the normal model's numbers: k, damp (hooke, hertz); E, damp, nu (hertz/material)
    damping: str
    limit: bool
    others: list        # the tokens after the normal model's numbers (tangential, rolling, ...)
    models: tuple       # the sub-model names, which LAMMPS requires equal before it mixes two types
    cutoff: float | None = None     # the line's cutoff keyword, None where it has none

    def setting(self, stiffness: dict | None = None) -> dict:
        """codes.lammps_contact's keywords; ``stiffness`` those of a mixed pair (see _mixed), else
        this line's own."""
        if stiffness is None:
            stiffness = ({"normal": self.normal, "E": self.args[0], "nu": self.args[2]}
                         if self.normal == "hertz/material" else {"normal": self.normal, "k_n": self.args[0]})
        return {**stiffness, "damping": self.damping, "eta_n0": self.args[1], "limit_damping": self.limit}


def _coeff(deck: Deck, words: list, where: str, text: str) -> _Coeff:
    named = normal = words[3] if len(words) > 3 else None
    if normal in _LAMMPS_ADHESIVE and len(words) > 7:
        if number(words[7], where, text) != 0.0:
            raise DeckError(where, text, f"normal model {normal} is not mapped at cohesion {words[7]} (adhesion; "
                                         "at cohesion 0 it is hertz/material's force, which is)")
        deck.ignored.append(f"{normal} at cohesion 0 (hertz/material's force)")
        words, normal = [*words[:3], "hertz/material", *words[4:7], *words[8:]], "hertz/material"
    if normal not in _LAMMPS_NORMAL_ARGS:
        raise DeckError(where, text, f"normal model {normal} is not mapped (hooke, hertz, hertz/material are; "
                                     "dmt and jkr at cohesion 0)")
    nargs = _LAMMPS_NORMAL_ARGS[normal]
    if len(words) < 4 + nargs:
        what = "E, damping, nu" if normal == "hertz/material" else "k, damping"
        raise DeckError(where, text, f"normal model {normal} needs {nargs} numbers ({what})")
    args = [number(a, where, text) for a in words[4:4 + nargs]]
    damping, limit, cutoff, k = "viscoelastic", False, None, 4 + nargs
    models = {"tangential": None, "rolling": None, "twisting": None, "heat": None}
    while k < len(words):
        key = words[k]
        nxt = words[k + 1] if k + 1 < len(words) else None
        if key == "damping":
            damping = nxt
            k += 2
        elif key == "limit_damping":
            limit = True
            k += 1
        elif key == "synchronized_verlet":
            # where in the step the tangential and rolling histories are rotated: no part in a
            # head-on contact, whose normal force it leaves alone
            deck.ignored.append(key)
            k += 1
        elif key == "cutoff" and nxt is not None:
            # how far LAMMPS looks for the pair (read against its contact distance in pair_row)
            cutoff = number(nxt, where, text)
            k += 2
        elif key == "tangential" and nxt in _LAMMPS_TANGENTIAL:
            deck.ignored.append(f"tangential {nxt}")
            models["tangential"] = nxt
            k += 2 + _LAMMPS_TANGENTIAL[nxt]
        elif key == "rolling" and nxt == "sds":
            deck.ignored.append("rolling sds")
            models["rolling"] = nxt
            k += 5
        elif key == "heat" and nxt in _LAMMPS_HEAT:
            # heat conduction between the spheres: their temperatures, never the normal force
            deck.ignored.append(f"heat {nxt}")
            models["heat"] = nxt
            k += 2 + _LAMMPS_HEAT[nxt]
        elif key in ("rolling", "twisting") and nxt == "none":
            # no rolling or twisting model: LAMMPS accepts the word and adds nothing (field round 16,
            # D6: R02 and p01 were refused, "keyword twisting is not mapped", where LAMMPS runs them)
            models[key] = None
            k += 2
        elif key == "twisting" and nxt in ("marshall", "sds"):
            deck.ignored.append(f"twisting {nxt}")
            models["twisting"] = nxt
            k += 2 if nxt == "marshall" else 5
        else:
            raise DeckError(where, text, f"keyword {key} is not mapped")
    if damping not in DAMPING_MODELS:
        raise DeckError(where, text, f"damping {damping} is not mapped")
    others = [w for n, w in enumerate(words[4 + nargs:], 4 + nargs)
              if w != "cutoff" and (n == 0 or words[n - 1] != "cutoff")]
    # LAMMPS mixes two types' lines only where their models are the same: dmt with dmt, not with hertz/material
    return _Coeff(normal, args, damping, limit, others, (named, damping, *models.values()), cutoff)


def _mapped(deck: Deck, loc: tuple, words: list) -> _Coeff:
    """A pair_coeff line's coefficients, or :class:`PairNotMapped` where the audit does not map its
    model: the engine has run the line, so only the pairs it covers go unaudited."""
    try:
        return _coeff(deck, words, place(loc), " ".join(words))
    except DeckError as why:
        raise PairNotMapped(loc, " ".join(words), why.args[0].split(": ", 1)[-1]) from None


def _mixed_cohesion(wi: list, wj: list) -> tuple[list, list]:
    """Two types' pair_coeff lines as their mixed pair sees them: where both use one adhesive model
    (jkr, dmt), LAMMPS mixes the cohesion as a geometric mean, so one line at cohesion 0 gives the
    pair cohesion 0, hertz/material's force (field round 14, p12: 1 1 jkr at 0.5, 2 2 at 0: LAMMPS'
    1 2 is bit for bit that of both at 0, yet it was named not mapped at cohesion 0.5).

    Examples
    --------
    >>> a = "pair_coeff 1 1 jkr 1e7 50 0.3 0.5".split()
    >>> _mixed_cohesion(a, "pair_coeff 2 2 jkr 1e7 50 0.3 0".split())[0][7]
    '0'
    >>> _mixed_cohesion(a, "pair_coeff 2 2 jkr 1e7 50 0.3 0.2".split())[0][7]
    '0.5'
    """
    if not (len(wi) > 7 and len(wj) > 7 and wi[3] == wj[3] and wi[3] in _LAMMPS_ADHESIVE):
        return wi, wj
    try:
        zero = float(wi[7]) == 0.0 or float(wj[7]) == 0.0
    except ValueError:
        return wi, wj
    return tuple([*w[:7], "0", *w[8:]] for w in (wi, wj)) if zero else (wi, wj)


def _mixed(a: _Coeff, b: _Coeff) -> tuple[_Coeff, dict]:
    """LAMMPS' mixing of two types' coefficients (pair_style granular, init_one): geometric means,
    for hertz/material the effective modulus 1/E* = (1 - nu_i^2)/E_i + (1 - nu_j^2)/E_j, used as
    k = (4/3) E* (so as hertz with that k), and limit_damping if either has it. Returns the mixed
    coefficients and the stiffness keywords of codes.lammps_contact."""
    def geom(x, y):
        return math.sqrt(x * y)
    if a.normal == "hertz/material":
        (E1, d1, nu1), (E2, d2, nu2) = a.args, b.args
        e_star = 1.0 / ((1.0 - nu1 ** 2) / E1 + (1.0 - nu2 ** 2) / E2)
        nu = geom(nu1, nu2)
        # the E that an explicit hertz/material line with the mixed nu needs for the same E*
        args = [2.0 * (1.0 - nu ** 2) * e_star, geom(d1, d2), nu]
        stiffness = {"normal": "hertz", "k_n": 4.0 / 3.0 * e_star}
    else:
        args = [geom(x, y) for x, y in zip(a.args, b.args)]
        stiffness = {"normal": a.normal, "k_n": args[0]}
    others = []
    for x, y in zip(a.others, b.others):
        try:
            others.append(x if x == y else f"{geom(float(x), float(y)):.10g}")
        except ValueError:
            others = None       # a NULL against a number: no single line to write
            break
    cuts = [c for c in (a.cutoff, b.cutoff) if c is not None]
    mixed = _Coeff(a.normal, args, a.damping, a.limit or b.limit, others, a.models, min(cuts) if cuts else None)
    return mixed, stiffness


def own_cutoff(words: list) -> str | None:
    """The value a ``pair_coeff``'s own ``cutoff`` keyword gives (pair_style granular), as written;
    None where it gives none.

    Parameters
    ----------
    words : list of str
        The pair_coeff's words after its two types.

    Returns
    -------
    str or None

    Examples
    --------
    >>> own_cutoff(["hooke", "2000", "0", "cutoff", "0.001"]), own_cutoff(["hooke", "2000", "0"])
    ('0.001', None)
    """
    return next((w for k, w in enumerate(words[1:]) if words[k] == "cutoff"), None)


def _largest_cutoff(deck: Deck) -> float:
    """The largest cutoff of any pair (infinite where one has none, its cutoff then the radii's):
    LAMMPS' granular neighbour lists take a pair by its radii and skin, the cutoffs setting only how
    far they reach, the largest of them; so a pair's own small cutoff leaves it out only where every
    cutoff is small (field round 26, CU01: cutoff 0.001 on one pair of 5 mm contact distance, the
    others without: LAMMPS met it at first touch, 0.414777 from a 4 mm gap at dt 1e-7 s, which the
    audit had left out).

    Examples
    --------
    >>> from restitution.dem.dialect.state import Deck
    >>> _largest_cutoff(Deck(coeffs={(1, 1): (1, ["hooke", "1", "0", "cutoff", "0.001"]), (1, 2): (2, ["hooke", "1", "0"])}))
    inf
    >>> _largest_cutoff(Deck(cutoff=0.002, coeffs={(1, 1): (1, ["hooke", "1", "0", "cutoff", "0.001"]), (1, 2): (2, ["hooke"])}))
    0.002
    """
    largest = 0.0
    for _, words in deck.coeffs.values():
        own = own_cutoff(words)
        try:
            cut = float(own) if own is not None else deck.cutoff
        except ValueError:
            cut = None
        if cut is None:
            return math.inf
        largest = max(largest, cut)
    return largest if deck.coeffs else (deck.cutoff if deck.cutoff is not None else math.inf)


def pair_row(deck: Deck, i: int, j: int) -> dict:
    """The audit's row for type pair (i, j), before its eps: the contact LAMMPS gives it, the e typed
    (tsuji, coeff_restitution) and the pair_coeff line that gives that e exactly. Its arguments and
    its row are :meth:`~restitution.dem.dialect.state.DeckDialect.pair_row`'s.

    Raises
    ------
    DeckError
        Where no line covers the pair, LAMMPS cannot mix it, or a line is not mapped.

    Examples
    --------
    >>> deck = Deck(ntypes=1, radius={1: 0.5}, density={1: 1.0})
    >>> pair_coeff(deck, "pair_coeff * * hooke 1000 50".split(), "line 5", "", (None, 5))
    >>> row = pair_row(deck, 1, 1)
    >>> row["model"], row["line"]
    ('LAMMPS hooke, damping viscoelastic', 5)
    """
    if (i, j) not in deck.coeffs and ((i, i) not in deck.coeffs or (j, j) not in deck.coeffs):
        why = (f" (pair_style at {place(deck.reset[0])} discarded the earlier ones)"
               if deck.reset else "")
        mix = f", nor both {i} {i} and {j} {j}, from which LAMMPS would mix it" if i != j else ""
        raise DeckError("pair_coeff", f"types {i} {j}", f"no pair_coeff line covers this type pair{mix}{why}: LAMMPS "
                                                         "stops (all pair coeffs are not set)")
    # after a read_restart (its granular style not given again) LAMMPS' lists and ghost atoms reach
    # nothing: it bins the box by its extent along x and looks in one bin, and no ghost atom stands
    # for a sphere across a periodic boundary (field round 32, R04: 8.094838 where the pair meets
    # across one, 0.414679 with pair_style granular given again after the read; RZ03, a pair along z
    # in an f f f box whose centres lie in two bins: 8.228907; RP05, gran/hooke/history: 0.483961).
    # An nsq list, which has no bins, takes every pair inside a box with no periodic boundary on one
    # process; on several, with no ghost atoms, a pair across two sub-domains is never met (field
    # round 34: processors 2 1 1, mpirun -np 2, the spheres passed through each other)
    if deck.restored_cut and _largest_cutoff(deck) == 0:
        style = deck.style_line[1].split()[1]
        raise PairNotMapped(deck.style_line[0], deck.style_line[1],
                            f"types {i} {j}: after read_restart LAMMPS holds pair_style {style} with no cutoff (the "
                            f"deck does not give pair_style {style} again; LAMMPS: 'Communication cutoff is 0.0'): "
                            "it makes no ghost atoms and looks for partners in one bin only, so a pair whose "
                            "spheres lie in two bins, across a periodic boundary, or in two processes' "
                            "sub-domains where the deck runs on several (an nsq list's too) is found late in "
                            f"overlap or never; give pair_style {style} again after the read")
    # under a hybrid style of several granular sub-styles, the one that gives this pair its force
    older = _older_or_granular(deck, i, j) if deck.granular_of else bool(deck.gran)
    if older:
        pair = spheres(deck, i, j)
        loc = deck.style_line[0]
        contact = _older_contact(pair, deck.gran, deck.units)
        return {"types": [i, j], "model": _in_units(f"LAMMPS {deck.gran['style']}", deck.units), "typed_e": None,
                "end": contact.end,
                "contact": contact, "pair": pair, "exact_line": None, "line": loc[1], "file": loc[0]}
    if (i, j) in deck.coeffs:
        loc, words = deck.coeffs[(i, j)]
        where, text = place(loc), " ".join(words)
        c = _mapped(deck, loc, words)
        stiffness = None
        mixed_from = None
    else:
        # a run with pre no keeps the mix of the last set-up (reader._not_set_up)
        like = {**deck.coeffs, **(deck.mixed_own or {})}
        (loc, wi), (loc_j, wj) = like[(i, i)], like[(j, j)]
        wi, wj = _mixed_cohesion(wi, wj)
        ci, cj = _mapped(deck, loc, wi), _mapped(deck, loc_j, wj)
        if ci.models != cj.models:
            raise DeckError("pair_coeff", f"types {i} {j}", f"types {i} and {j} use different models "
                                                             f"({' '.join(filter(None, ci.models))} against "
                                                             f"{' '.join(filter(None, cj.models))}): LAMMPS "
                                                             "cannot mix them and stops; give pair_coeff "
                                                             f"{i} {j}")
        c, stiffness = _mixed(ci, cj)
        mixed_from = f"mixed from {place(loc)} and {place(loc_j)}" + (
            ", as at the last run set up (a run with pre no does not mix again)" if deck.mixed_own else "")
    pair = spheres(deck, i, j)
    cutoff = c.cutoff if c.cutoff is not None else deck.cutoff
    skin = deck.skin if deck.skin is not None else DEFAULT_SKIN.get(deck.units or "lj", 0.0)
    nsq = deck.neighbor_style == "nsq"
    if cutoff is not None and _largest_cutoff(deck) + skin < pair.R1 + pair.R2:
        # LAMMPS' lists reach the largest cutoff and the skin, its bins perhaps further: spheres
        # that reach each other may first meet deep in overlap (cutoff 0.004 on r 0.005 + 0.005:
        # eps 619 measured), later, or at first touch (field round 27, CU10, CU15). Its nsq lists
        # have no bins and take every pair within its radii and skin: at first touch in a box
        # with no periodic boundary on one process (field round 28, N01, N11, N14, N25), but across
        # a periodic one the ghost atoms reach only the cutoff and skin (N02: met late, 1.904665),
        # and across two processes' sub-domains alike (round 34: processors 2 1 1 on 2, never met)
        how = ("its nsq list finds the pair at first touch inside the box on one process, but across a periodic "
               "boundary, or across two processes' sub-domains where the deck runs on several, its ghost atoms "
               "reach only that far, so there it may find the pair late in overlap or never" if nsq
               else "so whether it finds the pair at first touch, late in overlap or never depends on how it bins "
                    "the atoms")
        raise PairNotMapped(loc, " ".join(words) if (i, j) in deck.coeffs else f"types {i} {j}",
                            f"cutoff {cutoff:g}: LAMMPS' neighbour lists reach the largest cutoff plus the skin "
                            f"({_largest_cutoff(deck) + skin:g}), short of the contact distance "
                            f"{pair.R1 + pair.R2:g} (the sum of their radii); {how}")
    contact = lammps_contact(pair, **c.setting(stiffness))
    typed = c.args[1] if c.damping in E_DAMPINGS else None
    exact = None
    # (where ftm2v is not 1 the e typed is not the law's own: no line is worked back from it)
    if typed is not None and c.others is not None and contact.D2 > 0 and deck.units not in FTM2V:
        e_new = exact_e(contact, typed, partial(lammps_eta_n0, None, c.damping))
        if e_new is not None:
            # the pair's own line (a wildcard or mixed pair gets one naming it), its e replaced
            numbers = [f"{x:.10g}" for x in c.args]
            numbers[1] = f"{e_new:.10g}"
            limit = ["limit_damping"] if c.limit and "limit_damping" not in c.others else []
            # under a hybrid style the line names its sub-style (and instance), as LAMMPS requires
            sub = (deck.granular_of.get((i, j)) or deck.granular_of.get((i, i)) or {deck.substyle}) if deck.hybrid \
                else set()
            exact = " ".join(["pair_coeff", str(i), str(j), *sorted(sub), c.normal, *numbers, *c.others, *limit])
    model = _in_units(f"LAMMPS {c.normal}, damping {c.damping}" + (f" ({mixed_from})" if mixed_from else ""),
                      deck.units)
    contact = accelerated(contact, deck.units)
    return {"types": [i, j], "model": model, "typed_e": typed, "end": contact.end, "contact": contact, "pair": pair,
            "exact_line": exact, "line": loc[1], "file": loc[0]}


def _older_or_granular(deck: Deck, i: int, j: int) -> bool:
    """Under a hybrid style of an older gran/* sub-style and granular, or of several instances of
    granular ("granular 1", ...), whether pair (i, j) takes the older law (else a granular
    pair_coeff line, the last that names the pair). LAMMPS' hybrid mixes a pair no line names only from
    two like pairs of one same sub-style; a pair two sub-styles cover (hybrid/overlay) adds both
    forces, which the reader does not map."""
    subs = deck.granular_of.get((i, j))
    if subs is None:
        subs_i, subs_j = deck.granular_of.get((i, i), set()), deck.granular_of.get((j, j), set())
        if len(subs_i) != 1 or subs_i != subs_j:
            raise DeckError("pair_coeff", f"types {i} {j}", f"no pair_coeff line covers this type pair, and types "
                                                             f"{i} {i} and {j} {j} do not share one sub-style: "
                                                             "LAMMPS' hybrid cannot mix it and stops")
        subs = subs_i
    if len(subs) > 1:
        raise DeckError("pair_coeff", f"types {i} {j}", f"sub-styles {' and '.join(sorted(subs))} both act on this "
                                                         "pair (hybrid/overlay): their forces add, which the reader "
                                                         "does not map")
    return not next(iter(subs)).startswith("granular")


# ---------------------------------------------------------------------------- walls
#: LAMMPS fix wall/gran keywords after the wall style, with their number of values: they move or
#: heat the wall or write output; of them only a wiggle (an oscillating wall) changes a head-on
#: contact's eps at a given impact speed
_LAMMPS_WALL_KEYWORDS = {"wiggle": 3, "shear": 2, "contacts": 0, "temperature": 1}
_WALL_STYLES = FLAT_WALLS + ("zcylinder", "region")
#: fix wall/gran's older models, each the law of the pair style gran/<model>
_OLDER_WALLS = ("hooke", "hooke/history", "hertz/history")


def wall(deck: Deck, loc, words: list, unknown: list):
    """fix ID group wall/gran granular MODEL... xplane|yplane|zplane lo hi | zcylinder R: [(None, a
    function of the wall Pair and the sphere's type giving (contact, typed e, model, exact line or
    None), None)], or None with the reason in ``unknown``. The wall's model is that of a pair_coeff
    line with the wall as the second body (the older hooke, hooke/history and hertz/history: their
    pair style's law, Kn Kt gamma_n gamma_t xmu dampflag [limit_damping]). Of LAMMPS' keywords after
    the wall style, shear moves it along itself, contacts and temperature heat it or write output:
    none changes the contact; a wiggle of nonzero amplitude accelerates it under the sphere, and
    such a wall is named, not audited. A zcylinder is met from inside (LAMMPS' zcylinder confines: a sphere
    outside it overlaps it at every distance), where LAMMPS gives the wall the radius -2 R in the
    effective radius (:func:`concave_cylinder`). Its arguments and result are
    :meth:`~restitution.dem.dialect.state.DeckDialect.wall`'s, each surface's faces those its words
    give (:func:`~restitution.dem.dialect.state.wall_faces`; a region's none).

    Examples
    --------
    >>> [(mesh, wall_type, faces) for mesh, _, wall_type, faces in
    ...  wall(Deck(), (None, 9), "fix w all wall/gran granular hooke 1000 50 zplane 0 NULL".split(), [])]
    [(None, None, [('the face at z = 0', (0.0, 0.0, 1.0))])]
    """
    text = " ".join(words)
    style = words[4] if len(words) > 4 else None
    if style not in ("granular", *_OLDER_WALLS):
        unknown.append((*loc, text, f"wall model {style} is not mapped (granular, {', '.join(_OLDER_WALLS)} are): "
                                    "the wall's contacts are not audited"))
        return None
    if words[3] == "wall/gran/region":
        return _region_wall(deck, loc, words, unknown)
    k = next((n for n, w in enumerate(words) if n > 4 and w in _WALL_STYLES), None)
    if k is None or words[k] not in FLAT_WALLS + ("zcylinder",):
        shape = "no wall style" if k is None else f"a {words[k]} wall"
        unknown.append((*loc, text, f"{shape}: only planes and zcylinders are audited"))
        return None
    n = k + (2 if words[k] == "zcylinder" else 3)   # zcylinder R; xplane|yplane|zplane lo hi
    if n > len(words):
        args = "a radius" if words[k] == "zcylinder" else "lo and hi"
        unknown.append((*loc, text, f"{words[k]} needs {args}: the wall's contacts are not audited"))
        return None
    radius = None
    if words[k] == "zcylinder":
        try:
            radius = number(words[k + 1], place(loc), text)
        except DeckError as why:
            unknown.append((*loc, text, f"{why.args[0].split(': ', 1)[-1]}: the wall's contacts are not audited"))
            return None
    while n < len(words) and words[n] in _LAMMPS_WALL_KEYWORDS:
        if words[n] == "wiggle" and not _still(words[n + 2:n + 3], place(loc), text):
            # the wall accelerates under the sphere during a contact: the eps the engine measures
            # depends on where in the cycle the contact falls (LAMMPS: 0.849 to 1.061 over the
            # phases where the still wall gives 0.956), not on the law alone
            amp, period = words[n + 2:n + 4]
            unknown.append((*loc, text, f"wiggle {' '.join(words[n + 1:n + 4])}: the wall oscillates (amplitude "
                                        f"{amp}, period {period}) and accelerates under the sphere during a "
                                        "contact, so the eps the engine measures depends on where in the cycle "
                                        "a contact falls: the wall's contacts are not audited"))
            return None
        n += 1 + _LAMMPS_WALL_KEYWORDS[words[n]]
    if n < len(words):
        unknown.append((*loc, text, f"keyword {words[n]} is not mapped: the wall's contacts are not audited"))
        return None
    shape = _shape(words[k], radius)
    faces = wall_faces(words[k], words[k + 1:k + 3])
    if style in _OLDER_WALLS:
        return _older_wall(deck, loc, words, k, unknown, radius, faces)
    try:
        c = _coeff(deck, ["pair_coeff", "*", "*", *words[5:k]], place(loc), text)
    except DeckError as why:
        unknown.append((*loc, text, f"{why.args[0].split(': ', 1)[-1]}: the wall's contacts are not audited"))
        return None
    model = _in_units(f"LAMMPS {c.normal}, damping {c.damping}, {shape}", deck.units)
    typed = c.args[1] if c.damping in E_DAMPINGS else None

    def contact_of(pair, t):
        contact = lammps_contact(_against(pair, radius, t, loc, text), **c.setting())
        exact = None
        if typed is not None and contact.D2 > 0 and deck.units not in FTM2V:     # no damping (e = 1): eps is e
            # tsuji's and coeff_restitution's eps depend on e alone (Omega = 1 / A(e)^2 for hooke
            # and hertz), so one e serves every type the wall acts on: the wall's own line with it
            e_new = exact_e(contact, typed, partial(lammps_eta_n0, None, c.damping))
            if e_new is not None:
                exact = " ".join([*words[:7], f"{e_new:.10g}", *words[8:]])
        return accelerated(contact, deck.units), typed, model, exact
    return [(None, contact_of, None, faces)]


def _still(amplitude: list, where: str, text: str) -> bool:
    """Whether a wiggle's amplitude (a one-word list; empty where the line stops short, which
    LAMMPS refuses) leaves the wall where it is."""
    try:
        return bool(amplitude) and number(amplitude[0], where, text) == 0.0
    except DeckError:
        return False


def _region_wall(deck: Deck, loc, words: list, unknown: list):
    """fix ID group wall/gran/region MODEL... region RID [contacts | temperature T]: one surface per
    curvature the region's walls have, each with the effective radius LAMMPS gives a sphere on it
    (:func:`region_surfaces`); a law that does not read the effective radius meets every surface as
    a plane. A region whose curvature the audit cannot know is named, not audited. As :func:`wall`'s
    result."""
    text = " ".join(words)
    k = next((n for n in range(5, len(words)) if words[n] == "region"), None)
    n = len(words) if k is None else k + 2
    while n < len(words) and words[n] in ("contacts", "temperature"):
        n += 1 + _LAMMPS_WALL_KEYWORDS[words[n]]
    if k is None or k + 2 > len(words) or n < len(words):
        unknown.append((*loc, text, "a region wall not read (MODEL... region ID [contacts | temperature T]): the "
                                    "wall's contacts are not audited"))
        return None
    said: list = []               # its model's refusal, said of the deck's own line
    surfaces = wall(deck, loc, words[:3] + ["wall/gran"] + words[4:k] + ["zplane", "0", "NULL"], said)
    if surfaces is None:
        unknown += [(f, line, text, why) for f, line, _, why in said]
        return None
    (_, contact_of, _, _), = surfaces
    if (moving := region_moves(deck, words[k + 1])) is not None:
        unknown.append((*loc, text, f"{moving}: its faces may move under a sphere during a contact, so the eps "
                                    "the engine measures may depend on when and where a contact falls; the wall's "
                                    "contacts are not audited"))
        return None
    # the law reads R_eff where a sphere twice as large, of the same mass, gets another contact
    probes = [contact_of(Pair(r, WALL_SIZE, 1.0, WALL_SIZE), 1)[0] for r in (1.0, 2.0)]
    if probes[0].as_dict() == probes[1].as_dict():
        why = ("region wall, audited as a plane: its law does not read the effective radius, so no surface's "
               "curvature changes the contact")

        def on_region(pair, t):
            contact, typed, model, exact = contact_of(pair, t)
            return contact, typed, model.replace("zplane wall", why), None
        return [(None, on_region, None, None)]
    found = region_surfaces(deck, words[k + 1])
    if isinstance(found, str):
        unknown.append((*loc, text, f"a region wall whose law reads the effective radius, in which LAMMPS gives "
                                    f"each surface of the region its own curvature: {found}; the wall's contacts "
                                    "are not audited"))
        return None

    def on_surface(name: str, wall_radius: float, fits: float | None):
        def contact_on(pair, t):
            contact, typed, model, exact = contact_of(_on_curved(pair, wall_radius, fits, t, loc, text, name), t)
            return contact, typed, model.replace("zplane wall", f"region {words[k + 1]}, {name}"), None
        return contact_on
    return [(None, on_surface(*surface), None, None) for surface in found]


#: Region styles whose surfaces the audit reads, with their number of arguments
_REGION_ARGS = {"block": 6, "plane": 6, "sphere": 4, "cylinder": 6}
#: Region keywords read, each with one value; move and rotate are not among them (a moving wall)
_REGION_KEYWORDS = frozenset({"side", "units", "open"})
#: The bounds a region may give instead of a number: unbounded, or the box's edge
REGION_UNBOUNDED = ("INF", "-INF", "EDGE")


@dataclass(frozen=True)
class Region:
    """A LAMMPS region line as the audit reads it (:func:`read_region`).

    Attributes
    ----------
    style : str
        block, plane, sphere or cylinder.
    args : tuple of str
        Its style's arguments as the line gives them (a cylinder's first is its axis).
    side : str
        ``in`` (LAMMPS' default) or ``out``.
    units : str
        ``lattice`` (LAMMPS' default) or ``box``; :func:`region_number` reads a length in them.
    opened : frozenset of str
        The faces its ``open`` keywords remove (a cylinder's 1 and 2 are its ends, 3 its side).
    """

    style: str
    args: tuple
    side: str = "in"
    units: str = "lattice"
    opened: frozenset = frozenset()


def read_region(deck: Deck, rid: str) -> Region | str:
    """Region ``rid`` of the deck read into its style, arguments and side/units/open keywords, or,
    where the audit does not read it, why (a str): not defined, another style, a keyword such as move
    or rotate (a moving region), too few arguments or a size given by a variable. The one parser of
    region lines: a region wall's curvature (:func:`region_surfaces`) and where its surfaces lie (the
    deck audit's walls that meet at one surface) both read it.

    Parameters
    ----------
    deck : Deck
        The deck at the run audited (its regions).
    rid : str
        The region's ID.

    Returns
    -------
    Region or str

    Examples
    --------
    >>> d = Deck(regions={"can": "region can cylinder z 0 0 0.5 0 INF open 2 side out units box".split(),
    ...                   "spin": "region spin sphere 0 0 0 1 rotate v_a 0 0 0 0 0 1".split()})
    >>> read_region(d, "can")
    Region(style='cylinder', args=('z', '0', '0', '0.5', '0', 'INF'), side='out', units='box', opened=frozenset({'2'}))
    >>> read_region(d, "spin")
    'keyword rotate of the region (a moving or rotating region, or one not read)'
    """
    words = deck.regions.get(rid)
    if words is None:
        return f"region {rid} is not defined at this run"
    style = words[2] if len(words) > 2 else ""
    if style not in _REGION_ARGS:
        return f"a {style} region, whose surfaces' curvature the audit does not read (block, plane, sphere and " \
               "cylinder regions are read)"
    n = 3 + _REGION_ARGS[style]
    args, options, opened = tuple(words[3:n]), {"side": "in", "units": "lattice"}, set()
    while n < len(words) and words[n] in _REGION_KEYWORDS and n + 1 < len(words):
        if words[n] == "open":
            opened.add(words[n + 1])
        else:
            options[words[n]] = words[n + 1]
        n += 2
    if n < len(words):
        return f"keyword {words[n]} of the region (a moving or rotating region, or one not read)"
    if any("v_" in a for a in args):
        return "its size is a variable's, which may change as the run goes"
    if len(args) < _REGION_ARGS[style]:
        return "its arguments are not read"
    return Region(style, args, options["side"], options["units"], frozenset(opened))


def region_moves(deck: Deck, rid: str) -> str | None:
    """Why region ``rid``'s surfaces may move during a run (its ``move`` or ``rotate`` keyword, or a
    size or position given by a variable, which LAMMPS evaluates at every step), None where they do
    not. Whatever its law, a wall on such a region is not a still plane (field round 14, D3: a plane
    region moved by ``v_zw``, a sine in time, under a hooke law was audited as a still plane: 0.5370
    where LAMMPS measures 1.2437, 0.9468, 0.6137 at g = 0.1, 1, 10).

    Parameters
    ----------
    deck : Deck
        The deck at the run audited (its regions).
    rid : str
        The region's ID.

    Returns
    -------
    str or None

    Examples
    --------
    >>> d = Deck(regions={"pl": "region pl plane 0 0 0 0 0 1 move NULL NULL v_zw".split(),
    ...                   "up": "region up block 0 1 0 1 v_lo 1 units box".split(),
    ...                   "box": "region box block 0 1 0 1 0 1 units box".split(),
    ...                   "still": "region still plane 0 0 0 0 0 1 rotate v_th 0 0 0 0 1 0".split()},
    ...          variables={"zw": "0.001*sin(time)", "lo": "0.002*time", "th": "0"})
    >>> region_moves(d, "pl"), region_moves(d, "up"), region_moves(d, "box"), region_moves(d, "still")
    ('region pl moves (keyword move)', 'region up is placed by a variable (v_lo), which LAMMPS evaluates at every step', None, None)

    A union or intersect moves where any of its parts does, however deep:

    >>> d.regions["u"] = "region u intersect 2 box pl".split()
    >>> d.regions["uu"] = "region uu union 1 u units box".split()
    >>> region_moves(d, "uu")
    'region pl moves (keyword move), a part of region u, a part of region uu'
    """
    return _moves(deck, rid, set())


def _moves(deck: Deck, rid: str, seen: set) -> str | None:
    """:func:`region_moves` of ``rid``, the regions in ``seen`` (those it is a part of) left out."""
    words = deck.regions.get(rid) or []
    # the parts of a union or intersect are the regions LAMMPS asks at every step (field round 45,
    # B54: an intersect under a wall whose plane part moved by move v_dx mid-run, LAMMPS 0.365 where
    # 0.4149 was printed with no word)
    if words[2:3] in (["union"], ["intersect"]) and (count := number_or_none(words[3] if len(words) > 3 else "")):
        for part in words[4:4 + int(count)]:
            if part not in seen and (why := _moves(deck, part, seen | {rid})) is not None:
                return f"{why}, a part of region {rid}"
    # a variable that is one number keeps the region where it is (field round 15, w06/w09: a face at
    # v_zl = 0, a rotation by v_th = 0, were named as moving and not audited)
    changing = [w for w in words[3:] if w.startswith("v_") and number_or_none(deck.variables.get(w[2:])) is None]
    keyword = next((w for w in words[3:] if w in ("move", "rotate")), None)
    if keyword is not None and changing:
        return f"region {rid} moves (keyword {keyword})"
    if changing:
        return f"region {rid} is placed by a variable ({changing[0]}), which LAMMPS evaluates at every step"
    return None


def region_surfaces(deck: Deck, rid: str) -> list | str:
    """The kinds of surface a sphere meets on region ``rid`` as the deck defines it, each as (name,
    the wall radius LAMMPS' region gives its contacts, the radius a sphere must stay below to fit
    inside it or None): 0 for a flat one (LAMMPS then takes the
    sphere's radius for R_eff), -R inside a sphere of radius R and R outside it, -2R inside a
    cylinder's side and 2R outside it (curved one way only), the cylinder's ends and edges 0 (LAMMPS'
    region_sphere.cpp and region_cylinder.cpp; R_eff = r Rw / (r + Rw) in its granular wall
    model). Or, where the audit cannot know the curvature, the reason (a str).

    Parameters
    ----------
    deck : Deck
        The deck at the run audited (its regions and lattice).
    rid : str
        The region's ID.

    Returns
    -------
    list of (str, float, float or None), or str

    Examples
    --------
    >>> d = Deck(regions={"drum": "region drum cylinder z 0 0 0.0075 -0.01 0.01 units box".split()})
    >>> region_surfaces(d, "drum")
    [('the inside of its curved side of radius 0.0075', -0.015, 0.0075), ('its flat ends', 0.0, None)]
    >>> region_surfaces(d, "cup")
    'region cup is not defined at this run'
    """
    region = read_region(deck, rid)
    if isinstance(region, str):
        return region
    if region.style in ("block", "plane"):
        return [("its flat faces", 0.0, None)]
    radius = region_number(region.args[3], deck, region.units)
    if isinstance(radius, str):
        return radius
    inside = region.side == "in"
    where, sign, fits = ("inside", -1.0, radius) if inside else ("outside", 1.0, None)
    if region.style == "sphere":
        return [(f"the {where} of its sphere of radius {radius:g}", sign * radius, fits)]
    surfaces = [] if "3" in region.opened else [(f"the {where} of its curved side of radius {radius:g}",
                                                 sign * 2.0 * radius, fits)]
    caps = {"1", "2"} - region.opened if all(a not in REGION_UNBOUNDED for a in region.args[4:6]) else set()
    return surfaces + ([("its flat ends", 0.0, None)] if caps else [])


def region_number(word: str, deck: Deck, units: str) -> float | str:
    """A region's length or coordinate in the box's units: units box as written; units lattice
    scaled by the lattice's spacing, known where the deck's lattice is none (its scale) or absent (1).

    Parameters
    ----------
    word : str
        The number as the region's line gives it.
    deck : Deck
        The deck (its lattice).
    units : str
        The region's ``units`` keyword: box or lattice.

    Returns
    -------
    float or str
        The value, or why it is not known.

    Examples
    --------
    >>> region_number("0.5", Deck(), "lattice"), region_number("0.5", Deck(lattice=["lattice", "none", "2"]), "lattice")
    (0.5, 1.0)
    >>> region_number("1", Deck(lattice=["lattice", "fcc", "0.8"]), "lattice")[:40]
    'its size is in lattice units (the region'
    """
    try:
        value = float(word)
    except ValueError:
        return f"its radius {word} is not a number"
    if units == "box":
        return value
    lattice = deck.lattice
    if not lattice or (len(lattice) >= 3 and lattice[1] == "none"):
        try:
            return value * (float(lattice[2]) if lattice else 1.0)
        except ValueError:
            return f"the lattice spacing {lattice[2]} is not a number"
    return ("its size is in lattice units (the region's default) of a lattice whose spacing the audit does not "
            "read: give it units box")


def _on_curved(pair: Pair, wall_radius: float, fits: float | None, t: int, loc, text: str, name: str) -> Pair:
    """The wall pair a sphere of type ``t`` meets on a surface of wall radius ``wall_radius``: LAMMPS'
    R_eff = r Rw / (r + Rw), the plane's r where Rw is 0; inside a curved surface (``fits`` its
    radius) only a sphere smaller than it fits."""
    if fits is not None and not pair.R1 < fits:
        raise DeckError(place(loc), text, f"a sphere of type {t} (radius {pair.R1:g}) does not fit {name}, which "
                                          "LAMMPS' region wall confines it to")
    return _curved(pair, wall_radius)


def _older_wall(deck: Deck, loc, words: list, k: int, unknown: list, radius: float | None, faces: list | None):
    """A wall of an older model (words[4]) with its Kn Kt gamma_n gamma_t xmu dampflag
    [limit_damping] before the wall style at words[k] (a zcylinder's ``radius``, else None), its
    ``faces``: as wall's result, no e typed."""
    text = " ".join(words)
    try:
        law = _gran_law(f"gran/{words[4]}", words[5:k], place(loc), text)
    except DeckError as why:
        unknown.append((*loc, text, f"{why.args[0].split(': ', 1)[-1]}: the wall's contacts are not audited"))
        return None
    model = _in_units(f"LAMMPS {words[4]} (older wall model), {_shape(words[k], radius)}", deck.units)

    def contact_of(pair, t):
        return _older_contact(_against(pair, radius, t, loc, text), law, deck.units), None, model, None
    return [(None, contact_of, None, faces)]


def _shape(style: str, radius: float | None) -> str:
    """The wall as the audit's rows name it."""
    if radius is None:
        return f"{style} wall"
    return (f"zcylinder wall of radius {radius:g}, the sphere inside (LAMMPS' effective radius R 2Rc / (2Rc - R), "
            "the wall's curvature in it)")


def concave_cylinder(pair: Pair, radius: float) -> Pair:
    """The sphere of a wall Pair against the inside of a cylinder of ``radius`` Rc, as LAMMPS'
    fix wall/gran zcylinder meets it: its mass, and the effective radius R 2Rc / (2Rc - R) that a
    wall of radius -2 Rc gives (LAMMPS' own choice for a cylinder, curved in one direction only;
    checked in LAMMPS: a sphere of radius 5 mm inside a cylinder of 7.5 mm, hertz/material with
    viscoelastic damping, gives this eps to 3e-12 after time-step extrapolation, where a plane's
    effective radius would be off by 1e-5).

    Parameters
    ----------
    pair : Pair
        The sphere against a flat wall (:meth:`~restitution.dem.pair.Pair.wall`).
    radius : float
        The cylinder's, larger than the sphere's.

    Returns
    -------
    Pair
        A pair whose effective mass is the sphere's and whose effective radius is LAMMPS'.

    Examples
    --------
    >>> round(concave_cylinder(Pair.wall(0.005, 2500.0), 0.0075).R, 12)
    0.0075
    """
    return _curved(pair, -2.0 * radius)


def _curved(pair: Pair, wall_radius: float) -> Pair:
    """The sphere of a wall Pair against a wall LAMMPS gives the radius ``wall_radius`` Rw (negative:
    concave): its mass, and LAMMPS' effective radius r Rw / (r + Rw), the sphere's own where Rw is 0."""
    if wall_radius == 0.0:
        return pair
    return Pair(pair.R1 * wall_radius / (pair.R1 + wall_radius), WALL_SIZE, pair.m1, WALL_SIZE)


def _against(pair: Pair, radius: float | None, t: int, loc, text: str) -> Pair:
    """The wall pair a sphere of type ``t`` meets: a plane's as it is, a zcylinder's
    (:func:`concave_cylinder`) where the sphere fits inside it."""
    if radius is None:
        return pair
    if not pair.R1 < radius:
        raise DeckError(place(loc), text, f"a sphere of type {t} (radius {pair.R1:g}) does not fit inside the "
                                          f"zcylinder of radius {radius:g}, which LAMMPS' wall confines it to")
    return concave_cylinder(pair, radius)

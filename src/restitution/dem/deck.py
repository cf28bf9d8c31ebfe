"""What eps does an input deck really give? A reader of LAMMPS (``pair_style granular``) and
LIGGGHTS (``pair_style gran model hertz|hooke``) input scripts, for every type pair.

The reader takes only what decides a head-on two-sphere contact: the contact model and its
coefficients per type pair, the end-of-contact keyword, and each type's radius and density.
Commands that cannot change that contact (output, regions, gravity, integrators, ...) are passed
over; any other line is reported as not understood, one per line, and never guessed. LAMMPS'
older gran/hooke, gran/hooke/history and gran/hertz/history styles give every type pair one law.
An option that does change the contact but is not mapped (a cohesion model, JKR, another pair
style), a type without radius or density, or a type pair without coefficients is refused with
one line (DeckError, exit status 2 in the CLI).

Flat walls (``fix wall/gran`` planes: LAMMPS ``granular`` models, LIGGGHTS primitive planes and
the faces of meshes, of the type their ``fix mesh/surface`` gives) are audited as a sphere of each
type they act on (``group ID type ...`` or all) hitting them head-on, LAMMPS' older wall models
(hooke, hooke/history, hertz/history) with their pair style's law; other walls (cylinders,
regions, a mesh's edges and corners) are named as not audited. A group holds the
atoms present when it is defined (and those a later command inserts into it): a group by type
defined before any atom exists holds none, and its wall, acting on no atom, is named as not
audited; a LAMMPS pour or deposit into the group adds the type it pours, a LIGGGHTS insert fix
or read_data into it atoms of types the reader cannot know (named likewise); else the audit
takes the types it names. A wall removed later (``unfix``) is still listed: it acts until then.

Tangential, rolling and twisting models take no part in a head-on collision and are ignored.

The deck runs as LAMMPS runs it (:mod:`restitution.dem.deck_script`): ``if`` with a condition the
reader can evaluate, ``jump``/``label``, ``next`` loops and ``quit`` decide which lines run; quoted
text is not a command; where which contact lines run depends on what the reader cannot decide,
the deck is refused naming the line. A ``pair_style`` of another style discards the coefficients,
as in LAMMPS; ``clear`` discards every setting. Each ``run`` sees the settings of its moment: every
change between runs is a stage of its own, audited (``run ... every`` with a command that changes the
contact mid-run is refused). Particles that are not single spheres (LIGGGHTS multisphere clumps,
superquadrics) and ``atom_style granular`` in a LAMMPS deck are refused; ``set group all`` sizes
only the types known to have atoms then.

Files the deck names (``include``, ``jump``, ``read_data``) are read through a ``read_file``
callable (the CLI resolves their names against the deck's directory, where LAMMPS is normally
started); a data file's Atoms section gives a type its radius and density where every atom of that
type has the same. A type pair no ``pair_coeff`` covers is mixed as LAMMPS mixes it (pair_style
granular: the same models for both types, geometric means, Young's moduli combined as 1/E* = sum
(1 - nu^2)/E, limit_damping if either type has it). Variables: index and loop (their values in turn, with
``next``), string, world/universe (their first value) and equal-style (evaluated again after each
``next``) or ``$(...)`` formulas in LAMMPS' own grammar (:mod:`restitution.dem.deck_text`); any other
form is named on its line, and a number needed from it ends the audit in one line naming the
sub-expression that has no value.

LAMMPS type labels (``labelmap atom``, a data file's Atom Type Labels) stand for their types; a
``fix pour`` without diam or dens pours LAMMPS' defaults (diameter 1, density 1); ``heat`` models
on a pair_coeff line (conduction) are accepted and named; LIGGGHTS' aliases of property/global
styles are read. A deck with commands only LIGGGHTS has and a pair style only LAMMPS has (a
LIGGGHTS tutorial in LAMMPS' older syntax) runs in neither engine: refused.
"""

from __future__ import annotations

import copy
import math
import re
from dataclasses import dataclass, field
from fractions import Fraction
from functools import lru_cache

from ..core.collision import StickError
from ..core.errors import ParameterError
from .calibrate import calibrate
from .codes import (DAMPING_MODELS, E_DAMPINGS, LAMMPS_GRAN_STYLES, LIGGGHTS_E, LIGGGHTS_MODEL_TYPES,
                    LIGGGHTS_MODULUS, LIGGGHTS_NU, Pair, lammps_contact, lammps_eta_n0, lammps_gran_contact,
                    liggghts_accepts_e, liggghts_contact, liggghts_e)
from .deck_script import LocatedError, Script
from .deck_text import PLACEHOLDER, evaluate

__all__ = ["DeckError", "read_deck", "audit_deck"]


class DeckError(ParameterError):
    """One line naming what in the deck cannot be mapped or is missing."""

    def __init__(self, where: str, text, why: str):
        super().__init__(where, text, why)
        shown = "" if text is None else f" ({' '.join(str(text).split())})"
        self.args = (f"{where}{shown}: {why}",)


#: Commands with no bearing on a head-on two-sphere contact (first word, or "fix STYLE"). Not here,
#: so named when met: mass (per-type masses). The script's control flow (if, jump, label, next,
#: quit, include, variable) is deck_script's.
_IRRELEVANT = {"units", "atom_style", "atom_modify", "boundary", "newton", "communicate", "comm_modify",
               "processors", "region", "lattice", "change_box", "neighbor", "neigh_modify", "timestep", "thermo",
               "thermo_style", "thermo_modify", "dump", "dump_modify", "undump", "run", "unfix", "compute",
               "uncompute", "velocity", "delete_atoms", "write_restart", "restart", "log", "print",
               "echo", "label", "shell", "clear", "create_atoms", "displace_atoms",
               "write_data", "write_dump", "reset_timestep", "run_style", "min_style", "minimize", "balance",
               "partition", "suffix", "package", "kspace_style", "special_bonds", "hard_particles",
               "soft_particles", "modify_timing", "compute_modify", "comm_style"}
_IRRELEVANT_FIXES = {"gravity", "nve/sphere", "nve", "balance", "insert/pack",
                     "insert/stream", "insert/rate/region", "particledistribution/discrete", "check/timestep/gran",
                     "viscous", "enforce2d", "move", "freeze", "setforce",
                     "ave/time", "ave/atom", "print", "nve/limit", "move/mesh",
                     "wall/region", "heat/gran", "heat/gran/conduction", "heat/flow", "multisphere", "property/atom"}
#: LAMMPS pair_coeff keywords after the normal model: name -> number of arguments
_LAMMPS_TANGENTIAL = {"linear_nohistory": 2, "linear_history": 3, "mindlin": 3, "mindlin_rescale": 3,
                      "mindlin/force": 3, "mindlin_rescale/force": 3}
_LAMMPS_NORMAL_ARGS = {"hooke": 2, "hertz": 2, "hertz/material": 3}
#: LAMMPS pair_coeff heat models (pair_style granular's heat keyword) and their number of arguments:
#: conduction between touching spheres, which changes temperatures, not forces
_LAMMPS_HEAT = {"none": 0, "area": 1, "radius": 1}
#: Data-file sections with no bearing on a head-on contact
_DATA_IRRELEVANT = {"Velocities", "Bonds", "Angles", "Dihedrals", "Impropers", "Bond Coeffs", "Angle Coeffs",
                    "Dihedral Coeffs", "Improper Coeffs"}
#: Atom styles whose data-file Atoms lines are: atom-ID atom-type diameter density x y z [image flags]
_SPHERE_STYLES = ("sphere", "granular")
#: Commands the reader needs and their least number of words (the command included): shorter,
#: LAMMPS stops on them too
_NEEDS_WORDS = {"create_box": 2, "pair_style": 2, "pair_coeff": 3}
#: Atom styles whose particles are not spheres (LIGGGHTS' superquadric, LAMMPS' ellipsoid, ...)
_SHAPED_STYLES = ("superquadric", "ellipsoid", "line", "tri", "body")
#: LIGGGHTS particle templates whose particles are not single spheres
_SHAPED_TEMPLATES = {"particletemplate/multisphere": "clumps of spheres (multisphere)",
                     "particletemplate/superquadric": "superquadrics"}
#: Runs with different contact settings the audit reports before it refuses the deck
MAX_STAGES = 100
#: Commands that may sit in a branch of an if whose condition the reader cannot evaluate: they
#: neither make atoms, nor run, nor change what the reader reads (units, atom_style and
#: soft_/hard_particles, though in _IRRELEVANT, are read)
_INERT = frozenset(_IRRELEVANT - {"create_atoms", "run", "clear", "minimize", "label", "delete_atoms", "units",
                                  "atom_style", "soft_particles", "hard_particles"})


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
    style_line: tuple = ()                        # ((file, line number), text) of pair_style
    unknown: list = field(default_factory=list)   # (file or None, line number, text, why) not understood
    ignored: list = field(default_factory=list)   # what the audit passed over on purpose
    atom_style: str = ""
    missing: dict = field(default_factory=dict)   # type -> why a data file gives it no single radius/density
    units: str = "lj"                             # the engines' default unit style
    soft: bool = False                            # LIGGGHTS soft_particles yes / hard_particles yes:
    hard: bool = False                            # its limits on Young's modulus lifted
    groups: dict = field(default_factory=dict)    # group ID -> set of types, or None where not by type
    walls: list = field(default_factory=list)     # (loc, words, the group's types then) of fix wall/gran
    meshes: dict = field(default_factory=dict)    # LIGGGHTS fix mesh/surface ID -> its atom type, or None
    gran: dict = field(default_factory=dict)      # LAMMPS' older gran/* pair style: style, k_n, gamma_n, limit
    # Groups are static: a group holds the atoms present when it is defined, and those a later
    # command inserts into it by name (LAMMPS and LIGGGHTS alike; measured in LAMMPS: a wall on a
    # group by type defined before create_atoms lets the sphere through)
    atoms: bool = False                           # some atom exists at this line
    inserting: bool = False                       # an inserting fix (pour, insert/...) is defined
    empty_groups: set = field(default_factory=set)   # groups by type defined before any atom existed
    # group ID -> [(the command that inserts atoms into it, their types or None where not known)]
    filled_groups: dict = field(default_factory=dict)
    style: str = ""                               # the pair style (LAMMPS keeps coefficients for the same)
    reset: tuple = ()                             # (loc, text) of a pair_style of another that discarded them
    atom_style_loc: tuple = ()                    # (file, line number) of atom_style
    # types known to hold atoms (create_atoms, read_data, a pour or deposit that has run), and
    # whether atoms of types the reader does not know exist: ``set group all`` sizes those only
    present: set = field(default_factory=set)
    present_unknown: bool = False
    shapes: dict = field(default_factory=dict)    # type -> (loc, text, what) where its particles are not spheres
    # (run locations, the deck as that run sees it, its contact key), one per change of contact settings
    stages: list = field(default_factory=list)
    inserts: list = field(default_factory=list)   # inserting fixes' types (a set, or None where unknown)
    reasons: dict = field(default_factory=dict)   # the script's: an unevaluated placeholder -> why
    labels: dict = field(default_factory=dict)    # LAMMPS type label -> atom type (labelmap atom, data files)
    liggghts_mark: tuple = ()                     # (loc, text) of the first command only LIGGGHTS has


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


class _Unevaluated(DeckError):
    """A number the deck gives through a variable or $(...) without a value here: ``mark`` is the
    placeholder, whose reason the script kept (see _explained)."""

    def __init__(self, where: str, text, why: str, mark: str):
        super().__init__(where, text, why)
        self.mark = mark


def _explained(exc: DeckError, reasons: dict) -> DeckError:
    """The refusal with the reason its variable or expression has no value (the sub-expression)."""
    if isinstance(exc, _Unevaluated) and exc.mark in reasons:
        exc.args = (f"{exc.args[0]}: {reasons[exc.mark]}",)
    return exc


def _number(token: str, where: str, text: str) -> float:
    try:
        return float(token)
    except ValueError:
        m = PLACEHOLDER.search(token)
        if m and m.group(1) == "variable":
            raise _Unevaluated(where, text, f"needs variable {m.group(2)}, which has no value the reader can "
                                            "evaluate", m.group(0)) from None
        if m:
            raise _Unevaluated(where, text, "needs a $(...) expression the reader does not evaluate",
                               m.group(0)) from None
        raise DeckError(where, text, f"{token!r} is not a number the reader can evaluate") from None


#: The audit lists every type pair, N (N + 1) / 2 of them: a deck with more types is refused.
MAX_TYPES = 100


def _type(token: str, where: str, text: str, what: str = "an atom type") -> int:
    """A type, or the number of types: an integer in 1..MAX_TYPES, else one line."""
    x = _number(token, where, text)
    if not (math.isfinite(x) and x == int(x) and 1 <= x <= MAX_TYPES):
        raise DeckError(where, text, f"{what} must be an integer in 1..{MAX_TYPES} (the audit lists every type "
                                     "pair)")
    return int(x)


def _where(loc) -> str:
    source, n = loc
    return f"line {n}" if source is None else f"{source} line {n}"


def read_deck(text: str, radius: dict | None = None, density: dict | None = None, read_file=None) -> Deck:
    """Parse a deck.

    Parameters
    ----------
    text : str
        The input script.
    radius, density : dict, optional
        {type: value}, overriding or completing what the deck states.
    read_file : callable, optional
        ``read_file(name)``: the text of a file the deck names (include, jump, read_data), or
        raises OSError (None: such a deck is refused).

    Returns
    -------
    Deck
        The settings after the deck's last line; ``stages`` holds the settings each ``run`` saw,
        one entry per change.
    """
    deck = Deck()
    _read(deck, text, read_file)
    every = [deck] + [snap for _, snap, _ in deck.stages]       # (a clear may have emptied the deck)
    for d in every:
        for t, r in (radius or {}).items():
            d.radius[int(t)] = r
        for t, rho in (density or {}).items():
            d.density[int(t)] = rho
    if not any(d.code for d in every):
        raise DeckError("pair_style", None, "the deck has no pair_style granular (LAMMPS) or pair_style gran "
                                            "(LIGGGHTS) line")
    for d in every:
        if d.code == "LAMMPS" and d.liggghts_mark:
            # a LIGGGHTS tutorial in LAMMPS' older syntax: LIGGGHTS stops on the pair style (checked in
            # LIGGGHTS 3.8.0: gran/hooke, gran/hooke/history, gran/hertz/history and granular are
            # "Invalid pair style"), LAMMPS on the LIGGGHTS commands; neither runs it
            (loc, line), (sloc, sline) = d.liggghts_mark, d.style_line
            raise DeckError(_where(sloc), sline, f"pair_style {d.style} is LAMMPS', in a LIGGGHTS deck ({_where(loc)}: "
                            f"{' '.join(line.split()[:4])}): LIGGGHTS 3.8.0 stops on it (invalid pair style), and "
                            "LAMMPS on LIGGGHTS' commands")
        if d.code == "LAMMPS" and d.atom_style.split()[:1] == ["granular"]:
            raise DeckError(_where(d.atom_style_loc), f"atom_style {d.atom_style}", "LAMMPS has no atom_style "
                            "granular (LIGGGHTS' name; LAMMPS' is sphere): LAMMPS stops on it")
    return deck


def _fetch(read_file, name: str, where: str, line: str) -> str:
    if read_file is None:
        raise DeckError(where, line, "the deck names another file, and it was given as text: give it as a file")
    try:
        return read_file(name)
    except OSError as exc:
        raise DeckError(where, line, f"{name} cannot be read ({exc.strerror or exc})") from None


def _read(deck: Deck, text: str, read_file) -> None:
    def execute(words, line, loc):
        _execute(deck, words, line, loc, read_file)

    def note(loc, line, why):
        deck.unknown.append((*loc, line, why))

    def fetch(name, loc, line):
        return _fetch(read_file, name, _where(loc), line)
    script = Script(execute, evaluate, note, fetch, _INERT)
    deck.reasons = script.reasons           # shared: a later stage's refusal names its reason too
    try:
        script.run(text)
    except LocatedError as why:
        raise DeckError(_where(why.loc), why.text, str(why)) from None
    except DeckError as why:
        raise _explained(why, script.reasons) from None
    if "LIGGGHTS" in {deck.code, *(snap.code for _, snap, _ in deck.stages)} and script.newer:
        loc, line, what = script.newer
        raise DeckError(_where(loc), line, f"{what}: LIGGGHTS 3.8.0 stops on it (its if compares numbers only, "
                                           "without |^, and it has no triple quotes)")


def _execute(deck: Deck, words: list, line: str, loc, read_file) -> None:
    """One command that runs (the script's control flow is deck_script's), as far as a head-on
    contact is concerned."""
    where = _where(loc)
    cmd = words[0]
    words = _unlabeled(deck, words, where, line)
    if not deck.liggghts_mark and _liggghts_only(words):
        deck.liggghts_mark = (loc, line)
    if cmd in _NEEDS_WORDS and len(words) < _NEEDS_WORDS[cmd]:
        raise DeckError(where, line, f"{cmd} needs at least {_NEEDS_WORDS[cmd] - 1} argument(s)")
    elif cmd == "labelmap" and len(words) >= 2:
        _labelmap(deck, words, where, line)
    elif cmd == "create_box":
        deck.ntypes = _type(words[1], where, line, "the number of types")
    elif cmd == "read_data" and len(words) >= 2:
        _read_data(deck, words, where, line, read_file)
        deck.atoms = True
    elif cmd == "create_atoms":
        deck.atoms = True
        if len(words) > 1 and words[1].isdigit():
            deck.present.add(int(words[1]))
        else:
            deck.present_unknown = True
    elif cmd == "run":
        _run_every(words, where, line)
        _stage(deck, loc, line)
        if deck.inserting:
            deck.atoms = True
            _inserted(deck)
    elif cmd == "clear":
        # LAMMPS starts afresh (box, atoms, styles, coefficients); the runs before it stay stages
        fresh = Deck(unknown=deck.unknown, ignored=deck.ignored, stages=deck.stages, reasons=deck.reasons)
        deck.__dict__.update(fresh.__dict__)
    elif cmd == "read_restart":
        raise DeckError(where, line, "read_restart: the types, sizes and coefficients come from a binary restart "
                                     "file, which the reader does not read")
    elif cmd == "atom_style" and len(words) >= 2:
        deck.atom_style, deck.atom_style_loc = " ".join(words[1:]), loc
        if words[1] in _SHAPED_STYLES:
            raise DeckError(where, line, f"atom_style {words[1]}: its particles are not spheres, and the reader "
                                         "audits the head-on contact of spheres only")
    elif cmd == "pair_style":
        _pair_style(deck, words, where, line, loc)
    elif cmd == "pair_coeff":
        _pair_coeff(deck, words, where, line, loc)
    elif cmd == "set" and len(words) >= 3:
        _set(deck, words, where, line, loc)
    elif cmd == "fix" and len(words) >= 4:
        _fix(deck, words, where, line, loc)
    elif cmd == "group" and len(words) >= 3:
        _group(deck, words)
    elif cmd == "units" and len(words) >= 2:
        deck.units = words[1]
    elif cmd in ("soft_particles", "hard_particles") and len(words) >= 2:
        setattr(deck, cmd.split("_")[0], words[1] == "yes")
    elif cmd not in _IRRELEVANT:
        deck.unknown.append((*loc, line, "not understood"))


#: Where LAMMPS commands take an atom type, which may be a type label: command (or "fix STYLE") ->
#: the word positions
_TYPE_WORDS = {"pair_coeff": (1, 2), "create_atoms": (1,), "mass": (1,), "fix pour": (5,), "fix deposit": (5,)}
_LABEL = re.compile(r"[A-Za-z_][^\s*#]*")


def _unlabeled(deck: Deck, words: list, where: str, line: str) -> list:
    """The command with each type label where a type goes replaced by its type (LAMMPS' type
    labels: pair_coeff glass steel ..., create_atoms glass ..., set type glass ..., group g type
    glass ...); a label never defined is refused, as LAMMPS stops on it."""
    key = f"fix {words[3]}" if words[0] == "fix" and len(words) > 3 else words[0]
    at = list(_TYPE_WORDS.get(key, ()))
    if words[0] == "set" and len(words) > 2 and words[1] == "type":
        at = [2]
    elif words[0] == "group" and len(words) > 3 and words[2] == "type":
        at = list(range(3, len(words)))
    out = list(words)
    for k in at:
        if k >= len(out) or not _LABEL.fullmatch(out[k]) or out[k] == "<>":
            continue
        if out[k] not in deck.labels:
            raise DeckError(where, line, f"type label {out[k]} is not defined (labelmap atom, or a data file's Atom "
                                         "Type Labels, before it): LAMMPS stops")
        out[k] = str(deck.labels[out[k]])
    return out


def _labelmap(deck: Deck, words: list, where: str, line: str) -> None:
    """labelmap atom N label ... (the types' labels), labelmap clear; other kinds (bond, ...) and
    labelmap write have no bearing on a contact."""
    if words[1] == "clear":
        deck.labels.clear()
        return
    if words[1] != "atom":
        return
    args = words[2:]
    if len(args) % 2:
        raise DeckError(where, line, "labelmap atom needs pairs of a type and its label (LAMMPS stops)")
    for k in range(0, len(args), 2):
        t = _type(args[k], where, line)
        if not _LABEL.fullmatch(args[k + 1]):
            raise DeckError(where, line, f"{args[k + 1]!r} is not a type label (it must not start with a digit): "
                                         "LAMMPS stops")
        deck.labels[args[k + 1]] = t


#: Commands that LIGGGHTS has and LAMMPS (22 Jul 2025) has not: first word, or "fix STYLE" prefixes
_LIGGGHTS_COMMANDS = ("communicate", "soft_particles", "hard_particles")
_LIGGGHTS_FIXES = ("property/global", "particletemplate/", "particledistribution/", "mesh/surface")


def _liggghts_only(words: list) -> bool:
    """Whether the command exists in LIGGGHTS only (atom_style granular has its own refusal)."""
    if words[0] in _LIGGGHTS_COMMANDS:
        return True
    return words[0] == "fix" and len(words) > 3 and words[3].startswith(_LIGGGHTS_FIXES)


def _run_every(words: list, where: str, line: str) -> None:
    """run N every M c1 c2 ...: LAMMPS runs the commands between the parts of the run; only inert
    ones (output, say) leave the contact as the reader reads it."""
    if "every" not in words:
        return
    for command in words[words.index("every") + 2:]:
        first = command.split()[0] if command.split() else ""
        if first not in _INERT and first != "NULL":
            raise DeckError(where, line, f"run ... every runs {first} during the run, between its parts: the reader "
                                         "does not follow it")


def _inserted(deck: Deck) -> None:
    """After a run, the atoms the deck's inserting fixes have made: their types where named."""
    for types in deck.inserts:
        if types is None:
            deck.present_unknown = True
        else:
            deck.present |= types


def _contact_key(deck: Deck) -> str:
    """What decides the deck's contacts, without the lines it came from: two runs with the same key
    see the same contacts."""
    def plain(x):
        if isinstance(x, (set, frozenset)):
            return tuple(sorted(x))
        if isinstance(x, dict):
            return tuple(sorted((k, plain(v)) for k, v in x.items()))
        if isinstance(x, (list, tuple)):
            return tuple(plain(v) for v in x)
        return x
    return repr(plain((deck.code, deck.style, deck.ntypes, deck.radius, deck.density, deck.units, deck.soft,
                       deck.hard, deck.model, deck.limit_force, deck.gran, deck.atom_style, deck.missing,
                       {k: w for k, (_, w) in deck.coeffs.items()}, {k: v for k, (_, v) in deck.props.items()},
                       [(w, t) for _, w, t in deck.walls], deck.meshes, deck.empty_groups, deck.filled_groups,
                       set(deck.shapes))))


def _stage(deck: Deck, loc, line: str) -> None:
    """A run: the contact settings it sees, kept where they differ from the previous run's."""
    key = _contact_key(deck)
    if deck.stages and deck.stages[-1][2] == key:
        deck.stages[-1][0].append((loc, line))
        return
    if not deck.code:
        return                           # no pair style yet: no contact to audit in this run
    if len(deck.stages) >= MAX_STAGES:
        raise DeckError(_where(loc), line, f"more than {MAX_STAGES} runs with different contact settings: the "
                                           "audit reports each, and stops here")
    stages, deck.stages = deck.stages, []
    # the lists of lines not understood are the whole deck's, shared by every stage
    snap = copy.deepcopy(deck, {id(deck.unknown): deck.unknown, id(deck.ignored): deck.ignored,
                                id(deck.reasons): deck.reasons})
    deck.stages = stages
    stages.append(([(loc, line)], snap, key))


def _read_data(deck: Deck, words: list, where: str, line: str, read_file) -> None:
    """read_data FILE [nocoeff] [group ID]: the number of types, each type's radius and density
    where all its atoms share them, and a data file's Pair Coeffs / PairIJ Coeffs."""
    name, opts, coeffs = words[1], words[2:], True
    k = 0
    while k < len(opts):
        if opts[k] == "nocoeff":
            coeffs, k = False, k + 1
        elif opts[k] == "group" and k + 1 < len(opts):
            deck.filled_groups.setdefault(opts[k + 1], []).append((f"read_data {name} adds", None))
            k += 2
        else:
            raise DeckError(where, line, f"read_data option {opts[k]} is not mapped (it may add, shift or offset "
                                         "types)")
    text = _fetch(read_file, name, where, line)
    section, hint, per_type = None, "", {}
    for n, raw in enumerate(text.splitlines(), 1):
        if n == 1:
            continue                                   # the title line
        body, _, comment = raw.partition("#")
        body = body.strip()
        if not body:
            continue
        here = f"{name} line {n}"
        if section is None and (m := re.fullmatch(r"(\d+)\s+atom\s+types", body)):
            deck.ntypes = _type(m.group(1), here, body, "the number of types")
            continue
        if body[0].isalpha():                          # a section's name; data lines start with a number
            section, hint = body, comment.strip()
            if section in ("Pair Coeffs", "PairIJ Coeffs") and coeffs and deck.code != "LAMMPS":
                raise DeckError(here, body, "a data file's pair coefficients before pair_style granular")
            if section not in {"Atoms", "Pair Coeffs", "PairIJ Coeffs", "Atom Type Labels"} | _DATA_IRRELEVANT:
                deck.unknown.append((name, n, raw.strip(), "data-file section not read"))
            continue
        if section is None:
            continue                                   # header: atoms, box bounds, other counts
        cols = body.split()
        if section == "Atom Type Labels":             # type label, as labelmap atom gives them
            _labelmap(deck, ["labelmap", "atom", *cols[:2]], here, body)
        elif section == "Atoms":
            style = hint or deck.atom_style
            if style not in _SPHERE_STYLES:
                raise DeckError(here, f"Atoms # {style}", "the reader reads the Atoms section of atom_style "
                                                          "sphere or granular (id type diameter density x y z)")
            if len(cols) < 7:
                raise DeckError(here, body, "an Atoms line of atom_style sphere has at least 7 columns")
            t = _type(_unlabeled(deck, ["create_atoms", cols[1]], here, body)[1], here, body)
            d, rho = _number(cols[2], here, body), _number(cols[3], here, body)
            if d <= 0:
                raise DeckError(here, body, "diameter 0 makes a point particle, which has no contact radius")
            per_type.setdefault(t, (set(), set()))
            per_type[t][0].add(d)
            per_type[t][1].add(rho)
        elif section in ("Pair Coeffs", "PairIJ Coeffs") and coeffs:
            i, j = (cols[0], cols[0]) if section == "Pair Coeffs" else (cols[0], cols[1])
            rest = cols[1:] if section == "Pair Coeffs" else cols[2:]
            _pair_coeff(deck, _unlabeled(deck, ["pair_coeff", i, j, *rest], here, body), here, body, (name, n))
    deck.present |= set(per_type)
    for t in range(1, deck.ntypes + 1):
        if t not in per_type:
            deck.missing[t] = f"{name} has no atom of type {t}"
            continue
        diameters, densities = per_type[t]
        if len(diameters) == 1:
            deck.radius[t] = 0.5 * diameters.pop()
        else:
            deck.missing[t] = f"{name} gives type {t} diameters from {min(diameters):g} to {max(diameters):g}"
        if len(densities) == 1:
            deck.density[t] = densities.pop()
        else:
            deck.missing[t] = f"{name} gives type {t} densities from {min(densities):g} to {max(densities):g}"


def _pair_style(deck, words, where, line, loc):
    style = words[1]
    deck.style_line = (loc, line)
    if deck.style and style != deck.style:
        # LAMMPS keeps the coefficients for the same style (its settings change); another style
        # starts without any, and LAMMPS stops at the next run unless new pair_coeff lines follow
        if deck.coeffs or deck.gran:
            deck.reset = (loc, line)
        deck.coeffs, deck.gran = {}, {}
    deck.style = style
    if style == "granular":
        deck.code = "LAMMPS"
        return
    if style in LAMMPS_GRAN_STYLES:
        _gran_style(deck, words, where, line)
        return
    if style != "gran":
        raise DeckError(where, line, f"pair_style {style} is not mapped (the reader maps LAMMPS pair_style "
                                     "granular, gran/hooke, gran/hooke/history and gran/hertz/history, and "
                                     "LIGGGHTS pair_style gran model hertz|hooke)")
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


#: Unit styles whose pressure-to-force conversion (LAMMPS' nktv2p) is 1: gran/hertz/history's Kn as typed
_NKTV2P_ONE = ("si", "cgs", "lj", "micro", "nano")


def _gran_style(deck, words, where, line):
    """pair_style gran/hooke|gran/hooke/history|gran/hertz/history ...: one law for every type pair."""
    deck.code = "LAMMPS"
    deck.gran = _gran_law(words[1], words[2:], deck.units, where, line)


def _gran_law(style: str, params: list, units: str, where: str, line: str) -> dict:
    """codes.lammps_gran_contact's keywords from an older style's Kn Kt gamma_n gamma_t xmu dampflag
    [limit_damping] (Kt, gamma_t, xmu and dampflag act tangentially only)."""
    if len(params) not in (6, 7) or len(params) == 7 and params[6] != "limit_damping":
        raise DeckError(where, line, f"{style} needs Kn Kt gamma_n gamma_t xmu dampflag [limit_damping], as "
                                     "LAMMPS does")
    if style == "gran/hertz/history" and units not in _NKTV2P_ONE:
        raise DeckError(where, line, f"units {units}: gran/hertz/history's Kn is converted from pressure "
                                     f"units there, which the reader does not map ({', '.join(_NKTV2P_ONE)} are)")
    return {"style": style, "k_n": _number(params[0], where, line), "gamma_n": _number(params[2], where, line),
            "limit_damping": len(params) == 7}


def _pair_coeff(deck, words, where, line, loc):
    if deck.code == "LIGGGHTS":
        return                       # `pair_coeff * *`: the coefficients come from property/global
    if deck.code != "LAMMPS":
        raise DeckError(where, line, "pair_coeff before a pair_style the reader maps")
    if "heat" in words[4:]:
        k = words.index("heat", 4)
        model = words[k + 1:k + 2 + _LAMMPS_HEAT.get(words[k + 1] if k + 1 < len(words) else "", 0)]
        deck.unknown.append((*loc, line, f"heat {' '.join(model)}: heat conduction, which does not touch the normal "
                                         "force: accepted"))
    for i in _types(words[1], deck.ntypes, where, line):
        for j in _types(words[2], deck.ntypes, where, line):
            deck.coeffs[(min(i, j), max(i, j))] = (loc, words)


def _set(deck, words, where, line, loc):
    absent = []
    if words[1] == "type":
        types = list(_types(words[2], deck.ntypes, where, line))
    elif words[1] == "group" and words[2] == "all":
        # it sets the atoms there now: a type without any keeps no size from it
        types = sorted(t for t in deck.present if 1 <= t <= deck.ntypes)
        absent = [t for t in range(1, deck.ntypes + 1) if t not in types]
    else:
        deck.unknown.append((*loc, line, "not understood"))
        return
    rest = words[3:]
    for k in range(0, len(rest) - 1, 2):
        if rest[k] in ("diameter", "density"):
            for t in absent:
                unknown = "the reader does not know whether an" if deck.present_unknown else "no"
                deck.missing.setdefault(t, f"{unknown} atom of type {t} exists when {where} sets group all")
        if rest[k] == "diameter":
            for t in types:
                deck.radius[t] = 0.5 * _number(rest[k + 1], where, line)
        elif rest[k] == "density":
            for t in types:
                deck.density[t] = _number(rest[k + 1], where, line)
        else:
            # mass, density/disc, velocities, ...: how they combine with a diameter is not guessed
            deck.unknown.append((*loc, line, "not understood"))
            return


#: Fixes that insert atoms as the run goes, into their own group (and all); LAMMPS' pour and
#: deposit name the atoms' type (fix ID group pour|deposit N type ...), LIGGGHTS' take theirs from
#: particle templates
_INSERTING_FIXES = {"pour", "deposit", "insert/pack", "insert/stream", "insert/rate/region"}


def _fix(deck, words, where, line, loc):
    style = words[3]
    if style in _INSERTING_FIXES:
        deck.inserting = True
        typed = style in ("pour", "deposit") and len(words) > 5 and words[5].isdigit()
        deck.inserts.append({int(words[5])} if typed else None)
        if words[2] != "all":
            deck.filled_groups.setdefault(words[2], []).append(
                (f"fix {words[1]} ({style}) inserts", {int(words[5])} if typed else None))
    if style in _SHAPED_TEMPLATES:
        typed = [words[k + 1] for k in range(4, len(words) - 1) if words[k] == "atom_type"]
        types = [_type(typed[0], where, line)] if typed else range(1, deck.ntypes + 1)
        for t in types:
            deck.shapes[t] = (loc, line, _SHAPED_TEMPLATES[style])
        return
    if style == "property/global" and len(words) >= 6:
        deck.props[words[4]] = (loc, words[5:])
        deck.prop_fix[words[4]] = f"fix {words[1]} {words[2]}"     # the exact line keeps the deck's fix ID
    elif style == "particletemplate/sphere":
        tokens, t = words[5:], None
        for k, tok in enumerate(tokens):
            if tok == "atom_type":
                if k + 1 == len(tokens):
                    raise DeckError(where, line, "atom_type needs a type")
                t = _type(tokens[k + 1], where, line)
            elif tok in ("density", "radius") and k + 2 < len(tokens) and tokens[k + 1] == "constant" \
                    and t is not None:
                (deck.density if tok == "density" else deck.radius)[t] = _number(tokens[k + 2], where, line)
            elif tok in ("density", "radius") and k + 1 < len(tokens) and t is not None:
                # other distributions (gaussian, ...) give no single value: the type is unset, and says why
                (deck.density if tok == "density" else deck.radius).pop(t, None)
                deck.missing[t] = f"fix {words[1]} gives type {t} a {tok} from a {tokens[k + 1]} distribution"
    elif style == "pour" and len(words) >= 7:
        if "mol" in words[7:]:
            raise DeckError(where, line, "fix pour ... mol pours molecules (rigid clumps of spheres), not single "
                                         "spheres: the reader audits the head-on contact of two spheres only")
        _pour_sizes(deck, _type(words[5], where, line), words, where, line)
    elif style == "wall/gran":
        group = words[2]
        deck.walls.append((loc, words, "all" if group == "all" else deck.groups.get(group, "undefined")))
    elif style in ("mesh/surface", "mesh/surface/stress"):
        # LIGGGHTS: a mesh's atom type (its material), for the walls made of it; None if not given
        typed = [words[k + 1] for k in range(4, len(words) - 1) if words[k] == "type"]
        deck.meshes[words[1]] = int(typed[0]) if typed and typed[0].isdigit() else None
    elif style == "wall/gran/region":
        deck.unknown.append((*loc, line, "a region wall (any shape): its contacts are not audited"))
    elif style in _IRRELEVANT_FIXES:
        return
    else:
        deck.unknown.append((*loc, line, "not understood"))


def _pour_sizes(deck: Deck, t: int, words: list, where: str, line: str) -> None:
    """fix ID group pour N type seed [keywords]: the diameter and density it gives type t, LAMMPS'
    defaults where the line has no diam or dens (diameter 1, density 1: its documentation, and a
    poured atom in LAMMPS 22 Jul 2025 has radius 0.5 and mass pi/6). A range or poly of several
    diameters (densities) gives no single one: the type's entry in ``missing`` says so."""
    tokens = words[7:]

    def value(k):
        if k >= len(tokens):
            raise DeckError(where, line, "fix pour's diam or dens keyword is cut short (LAMMPS stops)")
        return _number(tokens[k], where, line)
    diameters, densities = {1.0}, {1.0}
    for k, tok in enumerate(tokens):
        if tok == "diam" and k + 1 < len(tokens) and tokens[k + 1] == "one":
            diameters = {value(k + 2)}
        elif tok == "diam" and k + 1 < len(tokens) and tokens[k + 1] == "range":
            diameters = {value(k + 2), value(k + 3)}
        elif tok == "diam" and k + 1 < len(tokens) and tokens[k + 1] == "poly":
            n = int(value(k + 2))
            diameters = {value(k + 3 + 2 * m) for m in range(n)}
        elif tok == "diam":
            diameters = {value(k + 1), value(k + 2)}          # older LAMMPS: diam lo hi
        elif tok == "dens":
            densities = {value(k + 1), value(k + 2)}
    if len(diameters) == 1:
        deck.radius[t] = 0.5 * diameters.pop()
    else:
        deck.radius.pop(t, None)
        deck.missing[t] = f"fix {words[1]} pours diameters from {min(diameters):g} to {max(diameters):g}"
    if len(densities) == 1:
        deck.density[t] = densities.pop()
    else:
        deck.density.pop(t, None)
        deck.missing[t] = f"fix {words[1]} pours densities from {min(densities):g} to {max(densities):g}"


def _group(deck: Deck, words: list) -> None:
    """group ID type T ... (T, A:B or <> A B): the types a wall acts on. Groups of other styles
    (region, id, molecule, ...) have no types the reader can know: None. A second type line adds."""
    name, style, args = words[1], words[2], words[3:]
    if style in ("delete", "clear"):
        deck.groups.pop(name, None)
        deck.empty_groups.discard(name)
        return
    types = None
    if style == "type" and args:
        if args[0] == "<>" and len(args) == 3 and all(a.isdigit() for a in args[1:]):
            types = set(range(int(args[1]), int(args[2]) + 1))
        elif all(re.fullmatch(r"\d+(:\d+)?", a) for a in args):
            types = set()
            for a in args:
                lo, _, hi = a.partition(":")
                types |= set(range(int(lo), int(hi or lo) + 1))
    if types is not None and deck.atoms:
        deck.empty_groups.discard(name)
    elif types is not None and name not in deck.groups:
        deck.empty_groups.add(name)
    old = deck.groups.get(name, set())
    deck.groups[name] = None if types is None or old is None else old | types


def _pair(deck: Deck, i: int, j: int) -> Pair:
    for t in (i, j):
        if t in deck.shapes:
            loc, text, what = deck.shapes[t]
            raise DeckError(_where(loc), text, f"type {t}'s particles are {what}, not single spheres: the reader "
                                               "audits the head-on contact of two spheres only")
        why = f" ({deck.missing[t]})" if t in deck.missing else (
            " (no set, particle template, pour or data file gives it one: a type without particles?)")
        if t not in deck.radius:
            raise DeckError("radius", f"type {t}", f"the deck gives no single radius for this type{why}: give "
                                                   f"--radius {t}=R")
        if t not in deck.density:
            raise DeckError("density", f"type {t}", f"the deck gives no single density for this type{why}: give "
                                                    f"--density {t}=RHO")
    return Pair.spheres(deck.radius[i], deck.radius[j], deck.density[i], deck.density[j])


@dataclass
class _Coeff:
    """One pair_coeff line, as far as a head-on contact is concerned."""
    normal: str
    args: list          # the normal model's numbers: k, damp (hooke, hertz); E, damp, nu (hertz/material)
    damping: str
    limit: bool
    others: list        # the tokens after the normal model's numbers (tangential, rolling, ...)
    models: tuple       # the sub-model names, which LAMMPS requires equal before it mixes two types

    def setting(self, stiffness: dict | None = None) -> dict:
        """codes.lammps_contact's keywords; ``stiffness`` those of a mixed pair (see _mixed), else
        this line's own."""
        if stiffness is None:
            stiffness = ({"normal": self.normal, "E": self.args[0], "nu": self.args[2]}
                         if self.normal == "hertz/material" else {"normal": self.normal, "k_n": self.args[0]})
        return {**stiffness, "damping": self.damping, "eta_n0": self.args[1], "limit_damping": self.limit}


def _coeff(deck: Deck, words: list, where: str, text: str) -> _Coeff:
    normal = words[3] if len(words) > 3 else None
    if normal not in _LAMMPS_NORMAL_ARGS:
        raise DeckError(where, text, f"normal model {normal} is not mapped (hooke, hertz, hertz/material are)")
    nargs = _LAMMPS_NORMAL_ARGS[normal]
    if len(words) < 4 + nargs:
        what = "E, damping, nu" if normal == "hertz/material" else "k, damping"
        raise DeckError(where, text, f"normal model {normal} needs {nargs} numbers ({what})")
    args = [_number(a, where, text) for a in words[4:4 + nargs]]
    damping, limit, k = "viscoelastic", False, 4 + nargs
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
        elif key == "twisting" and nxt in ("marshall", "sds"):
            deck.ignored.append(f"twisting {nxt}")
            models["twisting"] = nxt
            k += 2 if nxt == "marshall" else 5
        else:
            raise DeckError(where, text, f"keyword {key} is not mapped")
    if damping not in DAMPING_MODELS:
        raise DeckError(where, text, f"damping {damping} is not mapped")
    return _Coeff(normal, args, damping, limit, words[4 + nargs:], (normal, damping, *models.values()))


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
    mixed = _Coeff(a.normal, args, a.damping, a.limit or b.limit, others, a.models)
    return mixed, stiffness


def _lammps_pair(deck: Deck, i: int, j: int) -> dict:
    if (i, j) not in deck.coeffs and ((i, i) not in deck.coeffs or (j, j) not in deck.coeffs):
        why = (f" (pair_style at {_where(deck.reset[0])}, another style, discarded the earlier ones)"
               if deck.reset else "")
        mix = f", nor both {i} {i} and {j} {j}, from which LAMMPS would mix it" if i != j else ""
        raise DeckError("pair_coeff", f"types {i} {j}", f"no pair_coeff line covers this type pair{mix}{why}: LAMMPS "
                                                         "stops (all pair coeffs are not set)")
    if deck.gran:
        pair = _pair(deck, i, j)
        loc = deck.style_line[0]
        contact = lammps_gran_contact(pair, **deck.gran)
        return {"types": [i, j], "model": f"LAMMPS {deck.gran['style']}", "typed_e": None, "end": contact.end,
                "contact": contact, "pair": pair, "exact_line": None, "line": loc[1], "file": loc[0]}
    if (i, j) in deck.coeffs:
        loc, words = deck.coeffs[(i, j)]
        where, text = _where(loc), " ".join(words)
        c = _coeff(deck, words, where, text)
        stiffness = None
        mixed_from = None
    else:
        (loc, wi), (loc_j, wj) = deck.coeffs[(i, i)], deck.coeffs[(j, j)]
        ci = _coeff(deck, wi, _where(loc), " ".join(wi))
        cj = _coeff(deck, wj, _where(loc_j), " ".join(wj))
        if ci.models != cj.models:
            raise DeckError("pair_coeff", f"types {i} {j}", f"types {i} and {j} use different models "
                                                             f"({' '.join(filter(None, ci.models))} against "
                                                             f"{' '.join(filter(None, cj.models))}): LAMMPS "
                                                             "cannot mix them and stops; give pair_coeff "
                                                             f"{i} {j}")
        c, stiffness = _mixed(ci, cj)
        mixed_from = f"mixed from {_where(loc)} and {_where(loc_j)}"
    pair = _pair(deck, i, j)
    contact = lammps_contact(pair, **c.setting(stiffness))
    typed = c.args[1] if c.damping in E_DAMPINGS else None
    exact = None
    if typed is not None and c.others is not None:
        e_new = _exact(contact, typed, c.damping)
        if e_new is not None:
            # the pair's own line (a wildcard or mixed pair gets one naming it), its e replaced
            numbers = [f"{x:.10g}" for x in c.args]
            numbers[1] = f"{e_new:.10g}"
            limit = ["limit_damping"] if c.limit and "limit_damping" not in c.others else []
            exact = " ".join(["pair_coeff", str(i), str(j), c.normal, *numbers, *c.others, *limit])
    model = f"LAMMPS {c.normal}, damping {c.damping}" + (f" ({mixed_from})" if mixed_from else "")
    return {"types": [i, j], "model": model, "typed_e": typed, "end": contact.end, "contact": contact, "pair": pair,
            "exact_line": exact, "line": loc[1], "file": loc[0]}


def _prop(deck: Deck, name: str, required: bool = True):
    if name not in deck.props:
        if required:
            raise DeckError("fix property/global", name, "the deck does not define it (LIGGGHTS needs it)")
        return None, None
    return deck.props[name]


def _exact(contact, eps: float, code: str) -> float | None:
    """The e to type into ``code`` (a LAMMPS damping taking an e, or "liggghts" for
    coefficientRestitution) that gives ``contact``'s law eps = ``eps`` under its end rule; None where
    no e does. Those dampings set D2 = f(e) sqrt(D1) with gamma = (alpha - 1)/2, so Omega = D1 / D2^2
    at every speed and eps depends on e alone: one calibration per law and e (the unit contact,
    D1 = 1 at g = 1) serves every pair and wall of a deck."""
    if contact.gamma != (contact.alpha - 1) / 2:
        raise ValueError(f"an exact e needs gamma = (alpha - 1)/2, not {contact.gamma} for alpha = {contact.alpha}")
    return _unit_exact(contact.alpha, contact.end, float(eps), code)


@lru_cache(maxsize=1024)
def _unit_exact(alpha: Fraction, end: str, eps: float, code: str) -> float | None:
    try:     # no damping gives eps, or the code's e cannot express the one that does
        unit = calibrate(alpha, (alpha - 1) / 2, D1=1.0, eps=eps, g=1.0, end=end).contact
        return liggghts_e(unit) if code == "liggghts" else lammps_eta_n0(None, code, unit)
    except ParameterError:
        return None


#: fix property/global's styles LIGGGHTS 3.8.0 takes for a per-type list and a per-type-pair
#: matrix (its aliases, checked: a deck with each runs)
_PER_TYPE = ("peratomtype", "atomtype", "vector")
_PER_PAIR = ("peratomtypepair", "atomtypepair", "matrix")


def _liggghts_materials(deck: Deck) -> tuple:
    """(E, nu, the coefficientRestitution matrix flattened, its location) from fix property/global."""
    # LIGGGHTS itself stops unless each list has exactly one value per type (per type pair, symmetric)
    def per_type(name):
        loc, vals = _prop(deck, name)
        if vals[0] not in _PER_TYPE:
            raise DeckError(_where(loc), " ".join(vals), f"{name} {vals[0]}: LIGGGHTS takes it as one of "
                                                          f"{', '.join(_PER_TYPE)}, one value per type")
        if len(vals) != 1 + deck.ntypes:
            raise DeckError(_where(loc), " ".join(vals), f"{name} gives {len(vals) - 1} value(s) for the "
                                                          f"{deck.ntypes} types: LIGGGHTS needs one each")
        return [_number(v, _where(loc), name) for v in vals[1:]]

    E, nu = per_type("youngsModulus"), per_type("poissonsRatio")
    loc, vals = _prop(deck, "coefficientRestitution")
    where = _where(loc)
    m = deck.ntypes
    if vals[0] not in _PER_PAIR:
        raise DeckError(where, " ".join(vals), f"coefficientRestitution {vals[0]}: LIGGGHTS takes it as one of "
                                               f"{', '.join(_PER_PAIR)} N, then N x N values")
    if len(vals) < 2 or vals[1] != str(m):
        raise DeckError(where, " ".join(vals), f"coefficientRestitution {vals[0]} gives N = "
                                               f"{vals[1] if len(vals) > 1 else 'nothing'} where the deck has {m} "
                                               f"types: LIGGGHTS needs {vals[0]} {m}")
    if len(vals) != 2 + m * m:
        raise DeckError(where, " ".join(vals), f"coefficientRestitution {vals[0]} {m} gives {len(vals) - 2} "
                                               f"value(s): LIGGGHTS needs {m}x{m} values, one per type pair")
    matrix = [_number(v, where, "coefficientRestitution") for v in vals[2:]]
    if any(matrix[(a - 1) * m + b - 1] != matrix[(b - 1) * m + a - 1] for a in range(1, m + 1)
           for b in range(a + 1, m + 1)):
        raise DeckError(where, " ".join(vals), "the coefficientRestitution matrix is not symmetric")
    _liggghts_limits(deck, E, nu, matrix, where)
    return E, nu, matrix, loc


def _liggghts_model(deck: Deck, model: str, limit_force: bool) -> dict:
    """liggghts_contact's keywords for a normal model (hooke needs characteristicVelocity)."""
    kw = {"model": model, "limit_force": limit_force}
    if model == "hooke":
        lv, v = _prop(deck, "characteristicVelocity")
        kw["characteristic_velocity"] = _number(v[-1], _where(lv), "characteristicVelocity")
    return kw


def _liggghts_pair(deck: Deck, i: int, j: int) -> dict:
    E, nu, matrix, loc = _liggghts_materials(deck)
    m = deck.ntypes
    e = matrix[(i - 1) * m + (j - 1)]
    pair = _pair(deck, i, j)
    kw = _liggghts_model(deck, deck.model, deck.limit_force)
    contact = liggghts_contact(pair, E=E[i - 1], nu=nu[i - 1], E2=E[j - 1], nu2=nu[j - 1], e=e, **kw)
    return {"types": [i, j], "model": f"LIGGGHTS {deck.model}, limitForce {'on' if deck.limit_force else 'off'}",
            "typed_e": e, "end": contact.end, "contact": contact, "pair": pair, "line": loc[1], "file": loc[0],
            "exact_line": _liggghts_exact_line(deck, matrix, i, j, contact)}


def _liggghts_exact_line(deck: Deck, matrix: list, i: int, j: int, contact) -> str | None:
    """The coefficientRestitution line with the entry (i, j) replaced by the e that gives
    ``contact`` eps = the e typed there; None where no e does or LIGGGHTS would refuse it."""
    m = deck.ntypes
    e_new = _exact(contact, matrix[(i - 1) * m + (j - 1)], "liggghts")
    if e_new is None or not liggghts_accepts_e(e_new):   # LIGGGHTS would stop on it
        return None
    new = list(matrix)
    new[(i - 1) * m + (j - 1)] = new[(j - 1) * m + (i - 1)] = e_new
    style = deck.props["coefficientRestitution"][1][0]      # the deck's own word: peratomtypepair or an alias
    head = f"{deck.prop_fix['coefficientRestitution']} property/global coefficientRestitution {style} {m}"
    return head + " " + " ".join(f"{x:.10g}" for x in new)


def _liggghts_limits(deck: Deck, E: list, nu: list, e: list, where_e: str) -> None:
    """LIGGGHTS' own checks on the materials (codes.LIGGGHTS_E, LIGGGHTS_NU, LIGGGHTS_MODULUS),
    which stop its run before the first step: a deck LIGGGHTS refuses gives no eps."""
    where_E = _where(deck.props["youngsModulus"][0])
    low, high = LIGGGHTS_MODULUS.get(deck.units, (None, None))
    if low is not None and not deck.soft and min(E) < low:
        raise DeckError(where_E, f"youngsModulus {min(E):g}", f"LIGGGHTS stops: it requires youngsModulus >= {low:g} "
                                                                f"in {deck.units} units unless soft_particles yes")
    if high is not None and not deck.hard and max(E) > high:
        raise DeckError(where_E, f"youngsModulus {max(E):g}", f"LIGGGHTS stops: it requires youngsModulus <= {high:g} "
                                                                f"in {deck.units} units unless hard_particles yes")
    if not all(LIGGGHTS_NU[0] <= v <= LIGGGHTS_NU[1] for v in nu):
        raise DeckError(_where(deck.props["poissonsRatio"][0]), "poissonsRatio",
                        f"LIGGGHTS stops: it requires {LIGGGHTS_NU[0]:g} <= poissonsRatio <= {LIGGGHTS_NU[1]:g}")
    if not all(liggghts_accepts_e(v) for v in e):
        raise DeckError(where_e, "coefficientRestitution", f"LIGGGHTS stops: it requires {LIGGGHTS_E[0]:g} < "
                                                           f"coefficientRestitution <= {LIGGGHTS_E[1]:g}")


#: LAMMPS fix wall/gran keywords after the wall style, with their number of values: they move or
#: heat the wall or write output, none changes a head-on contact's eps at a given impact speed
_LAMMPS_WALL_KEYWORDS = {"wiggle": 3, "shear": 2, "contacts": 0, "temperature": 1}
#: Walls the audit takes: planes (a sphere against a flat wall). Curved ones are named, not audited.
_FLAT_WALLS = ("xplane", "yplane", "zplane")
_WALL_STYLES = _FLAT_WALLS + ("zcylinder", "region")


def _wall_types(deck: Deck, types, loc, words, unknown: list):
    """The atom types a wall acts on, or None (said in ``unknown``) where the group has none known."""
    if types == "all":
        return list(range(1, deck.ntypes + 1))
    if types is None or types == "undefined":
        why = "not defined before it" if types == "undefined" else "not defined by type"
        unknown.append((*loc, " ".join(words), f"group {words[2]} is {why}: the wall's contacts are not audited"))
        return None
    fillers = deck.filled_groups.get(words[2], [])
    unknown_fill = [what for what, filled in fillers if filled is None]
    if unknown_fill:
        unknown.append((*loc, " ".join(words), f"group {words[2]} also holds the atoms {unknown_fill[0]}, whose "
                                               "types the reader does not know: the wall's contacts are not audited"))
        return None
    # its static members, and the atoms a pour or deposit of a named type inserts into it
    held = (set() if words[2] in deck.empty_groups else set(types)).union(*(filled for _, filled in fillers))
    if not held:
        unknown.append((*loc, " ".join(words), f"group {words[2]} is defined by type before any atom exists (a "
                                               "group holds the atoms present when it is defined): it holds none, "
                                               "and the wall acts on no atom"))
        return None
    return sorted(t for t in held if 1 <= t <= deck.ntypes)


def _lammps_wall(deck: Deck, loc, words: list, unknown: list):
    """fix ID group wall/gran granular MODEL... xplane|yplane|zplane ...: [(None, a function of the
    wall Pair and the sphere's type giving (contact, typed e, model, exact line or None), None)], or
    None with the reason in ``unknown``. The wall's model is that of a pair_coeff line with the wall
    as the second body (the older hooke, hooke/history and hertz/history: their pair style's law, Kn
    Kt gamma_n gamma_t xmu dampflag [limit_damping]), and LAMMPS' keywords after the wall style
    (wiggle, shear, contacts, temperature) move it, heat it or write output: none changes the contact."""
    text = " ".join(words)
    style = words[4] if len(words) > 4 else None
    if style not in ("granular", *_OLDER_WALLS):
        unknown.append((*loc, text, f"wall model {style} is not mapped (granular, {', '.join(_OLDER_WALLS)} are): "
                                    "the wall's contacts are not audited"))
        return None
    k = next((n for n, w in enumerate(words) if n > 4 and w in _WALL_STYLES), None)
    if k is None or words[k] not in _FLAT_WALLS:
        shape = "no wall style" if k is None else f"a {words[k]} wall"
        unknown.append((*loc, text, f"{shape}: only planes are audited"))
        return None
    n = k + 3                                      # xplane|yplane|zplane lo hi
    if n > len(words):
        unknown.append((*loc, text, f"{words[k]} needs lo and hi: the wall's contacts are not audited"))
        return None
    while n < len(words) and words[n] in _LAMMPS_WALL_KEYWORDS:
        n += 1 + _LAMMPS_WALL_KEYWORDS[words[n]]
    if n < len(words):
        unknown.append((*loc, text, f"keyword {words[n]} is not mapped: the wall's contacts are not audited"))
        return None
    if style in _OLDER_WALLS:
        return _older_wall(deck, loc, words, k, unknown)
    try:
        c = _coeff(deck, ["pair_coeff", "*", "*", *words[5:k]], _where(loc), text)
    except DeckError as why:
        unknown.append((*loc, text, f"{why.args[0].split(': ', 1)[-1]}: the wall's contacts are not audited"))
        return None
    model = f"LAMMPS {c.normal}, damping {c.damping}, {words[k]} wall"
    typed = c.args[1] if c.damping in E_DAMPINGS else None

    def contact_of(pair, t):
        contact = lammps_contact(pair, **c.setting())
        exact = None
        if typed is not None:
            # tsuji's and coeff_restitution's eps depend on e alone (Omega = 1 / A(e)^2 for hooke
            # and hertz), so one e serves every type the wall acts on: the wall's own line with it
            e_new = _exact(contact, typed, c.damping)
            if e_new is not None:
                exact = " ".join([*words[:7], f"{e_new:.10g}", *words[8:]])
        return contact, typed, model, exact
    return [(None, contact_of, None)]


#: fix wall/gran's older models, each the law of the pair style gran/<model>
_OLDER_WALLS = ("hooke", "hooke/history", "hertz/history")


def _older_wall(deck: Deck, loc, words: list, k: int, unknown: list):
    """A wall of an older model (words[4]) with its Kn Kt gamma_n gamma_t xmu dampflag
    [limit_damping] before the wall style at words[k]: as _lammps_wall's result, no e typed."""
    text = " ".join(words)
    try:
        law = _gran_law(f"gran/{words[4]}", words[5:k], deck.units, _where(loc), text)
    except DeckError as why:
        unknown.append((*loc, text, f"{why.args[0].split(': ', 1)[-1]}: the wall's contacts are not audited"))
        return None
    model = f"LAMMPS {words[4]} (older wall model), {words[k]} wall"

    def contact_of(pair, t):
        return lammps_gran_contact(pair, **law), None, model, None
    return [(None, contact_of, None)]


#: LIGGGHTS fix wall/gran: the general keywords after the wall style with their number of values
#: (none changes a head-on contact); the model_type/model_name pairs before it are
#: codes.LIGGGHTS_MODEL_TYPES
_LIGGGHTS_WALL_GENERAL = {"shear": 2, "temperature": 1, "store_force": 1, "store_force_contact": 1,
                          "store_force_contact_stress": 1}
#: primitive wall styles and their number of arguments
_LIGGGHTS_PRIMITIVES = {"xplane": 1, "yplane": 1, "zplane": 1, "xcylinder": 3, "ycylinder": 3, "zcylinder": 3}


def _liggghts_wall(deck: Deck, loc, words: list, unknown: list):
    """fix ID group wall/gran [model_type model_name]... (primitive type W STYLE ARGS | mesh
    n_meshes N meshes ID...) [general keywords] [model keywords], the order LIGGGHTS documents:
    for each flat surface (a primitive plane, or each mesh, whose type is its fix mesh/surface's) a
    triple (mesh ID or None, a function as in _lammps_wall, W): the contact of a type with an atom
    of type W under the wall's own model (its model keywords, limitForce among them, are its own,
    not the pair style's), the wall as the second body. None, with the reason in ``unknown``,
    where a part is not mapped (a cylinder, a cohesion model, an unknown keyword, ...)."""
    text, where = " ".join(words), _where(loc)

    def skip(why):
        unknown.append((*loc, text, f"{why}: the wall's contacts are not audited"))
        return None

    model, limit, k = None, False, 4
    while k + 1 < len(words) and words[k] in LIGGGHTS_MODEL_TYPES:
        key, val = words[k], words[k + 1]
        if key == "model" and val in ("hertz", "hooke"):
            model = val
        elif key in ("tangential", "rolling_friction") or key == "surface" and val == "default":
            pass                  # no part in a head-on contact (as for the pair style)
        else:
            return skip(f"{key} {val} is not mapped")
        k += 2
    if model is None:
        return skip("no model hertz|hooke")
    surfaces = []                 # (mesh ID or None, wall type, what it is)
    if k < len(words) and words[k] == "primitive":
        if k + 3 >= len(words) or words[k + 1] != "type" or words[k + 3] not in _LIGGGHTS_PRIMITIVES:
            return skip("a primitive wall not read (primitive type W STYLE ARGS)")
        style = words[k + 3]
        if style not in _FLAT_WALLS:
            return skip(f"a {style} wall (only planes are audited)")
        if not words[k + 2].isdigit():
            return skip(f"wall type {words[k + 2]} is not a type the reader can read")
        surfaces.append((None, int(words[k + 2]), f"{style} wall"))
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
            surfaces.append((mesh, deck.meshes[mesh], f"a face of mesh {mesh}"))
        k += 4 + n
    else:
        return skip("no wall style read (primitive or mesh)")
    while k < len(words):
        key = words[k]
        if key in _LIGGGHTS_WALL_GENERAL:
            k += 1 + _LIGGGHTS_WALL_GENERAL[key]
        elif key == "limitForce" and k + 1 < len(words):
            limit, k = words[k + 1] == "on", k + 2
        elif key == "tangential_damping" and k + 1 < len(words):
            k += 2
        else:
            return skip(f"keyword {key} is not mapped")
    for _, w, _ in surfaces:
        if not 1 <= w <= deck.ntypes:
            raise DeckError(where, text, f"the wall's type must be in 1..{deck.ntypes}")
    E, nu, matrix, _ = _liggghts_materials(deck)
    kw = _liggghts_model(deck, model, limit)

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
            exact = _liggghts_exact_line(deck, matrix, t, w, c) if same else None
            return c, e, f"LIGGGHTS {model}, limitForce {'on' if limit else 'off'}, {surface} of type {w}", exact
        return contact
    return [(mesh, contact_with(w, label), w) for mesh, w, label in surfaces]


def _wall_rows(deck: Deck, speeds) -> tuple[list, list]:
    """For every flat fix wall/gran and every type it acts on, the eps of that type's sphere
    hitting it head-on; and the walls not audited, each with its reason."""
    rows, unknown = [], []
    parse = _lammps_wall if deck.code == "LAMMPS" else _liggghts_wall
    for loc, words, types in deck.walls:
        surfaces = parse(deck, loc, words, unknown)
        if surfaces is None or (types := _wall_types(deck, types, loc, words, unknown)) is None:
            continue
        for mesh, contact_of, wall_type in surfaces:
            for t in types:
                _pair(deck, t, t)            # one line where the type lacks a radius or a density
                pair = Pair.wall(deck.radius[t], deck.density[t])
                contact, typed, model, exact = contact_of(pair, t)
                rows.append(_with_eps({"wall": words[1], "mesh": mesh, "types": [t], "wall_type": wall_type,
                                       "model": model, "typed_e": typed, "end": contact.end, "exact_line": exact,
                                       "line": loc[1], "file": loc[0]}, contact, speeds, pair.R1))
    return rows, unknown


def _with_eps(row: dict, contact, speeds, limit: float) -> dict:
    """The row with eps at every speed, where the engine would push the bodies through each other
    (the largest overlap reaching ``limit``) none, and the contact's parameters."""
    through = [contact.reaches(g, limit) for g in speeds]
    if through[len(speeds) // 2]:   # no eps at the middle speed: no line promising one
        row["exact_line"] = None
    eps = [(None, False) if t else _eps_or_stick(contact, g) for g, t in zip(speeds, through)]
    row.update(speeds=speeds, eps=[e for e, _ in eps], sticks=[s for _, s in eps], passes_through=through,
               overlap_limit=limit, **{k: v for k, v in contact.as_dict().items() if k != "end"})
    return row


def _eps_or_stick(contact, g: float) -> tuple[float, bool]:
    """(eps, False), or (0, True) where the overlap rule's attraction keeps the bodies together."""
    try:
        return contact.eps(g), False
    except StickError:
        return 0.0, True


def audit_deck(text: str, speeds, radius: dict | None = None, density: dict | None = None, read_file=None) -> dict:
    """The eps an input deck really gives, for every type pair and flat wall, at every run.

    Parameters
    ----------
    text : str
        The input script.
    speeds : sequence of float
        Impact speeds.
    radius, density, read_file
        As in :func:`read_deck`.

    Returns
    -------
    dict
        {"code", "stages", "pairs", "walls", "unknown_lines", "ignored"}. ``stages``: one entry
        for each change of the contact settings between runs ({"runs": [{"file", "line", "text"}],
        "pairs", "walls"}; a deck without a run has one stage, its settings at its end); ``pairs``
        and ``walls`` are the last stage's. A pair row holds, for a type pair, the eps the deck
        really gives at ``speeds`` (relative accuracy 1e-10), beside the e typed (or None) and the
        line that would give that e exactly. Where the spheres' centres would meet
        (``passes_through``: the largest overlap reaches ``overlap_limit`` = R1 + R2) eps is None:
        the engine pushes them through each other. A wall row: the same for every type a flat fix
        wall/gran acts on, the sphere hitting the wall head-on (``overlap_limit`` = R: the centre
        reaching the wall; ``wall`` the fix ID, ``wall_type`` the LIGGGHTS wall's atom type; an
        exact line for a LAMMPS tsuji or coeff_restitution wall, the wall's own, and for a LIGGGHTS
        wall whose model and limitForce are the pair style's, the coefficientRestitution line with
        the entry (type, W) replaced, which is then also the sphere pair (type, W)'s exact line).
        Walls not audited are among ``unknown_lines``.
    """
    speeds = [float(g) for g in speeds]
    if not speeds:
        raise ParameterError("g", speeds, "give at least one impact speed")
    deck = read_deck(text, radius, density, read_file)
    stages = [(runs, snap) for runs, snap, _ in deck.stages] or [([], deck)]
    unknown = list(dict.fromkeys(deck.unknown))      # a loop runs its lines again: each named once
    if deck.stages and _contact_key(deck) != _contact_key(deck.stages[-1][1]):    # --radius, --density in both
        (source, n), line = deck.stages[-1][0][-1]
        unknown.append((source, n, line, "the contact settings change after this, the deck's last run: no run uses "
                                         "the later ones, not audited"))
    audited = []
    for runs, snap in stages:
        try:
            pairs, walls, not_audited = _audit_stage(snap, speeds)
        except DeckError as why:
            _explained(why, deck.reasons)
            if len(stages) > 1:          # say which run LAMMPS would stop at
                why.args = (f"{why.args[0]} (the run at {_where(runs[0][0])})",)
            raise
        unknown += [row for row in not_audited if row not in unknown]
        audited.append({"runs": [{"file": f, "line": n, "text": t} for (f, n), t in runs], "pairs": pairs,
                        "walls": walls})
    return {"code": stages[-1][1].code, "stages": audited, "pairs": audited[-1]["pairs"], "walls": audited[-1]["walls"],
            "unknown_lines": [{"file": f, "line": n, "text": t, "why": why} for f, n, t, why in unknown],
            "ignored": sorted(set(deck.ignored))}


def _audit_stage(deck: Deck, speeds: list) -> tuple[list, list, list]:
    """(pair rows, wall rows, walls not audited) of the deck's settings at one stage."""
    if deck.ntypes <= 0:
        raise DeckError("create_box", None, "the deck has no create_box or read_data: the number of types is "
                                            "unknown")
    pairs = []
    for i in range(1, deck.ntypes + 1):
        for j in range(i, deck.ntypes + 1):
            row = (_lammps_pair if deck.code == "LAMMPS" else _liggghts_pair)(deck, i, j)
            contact, pair = row.pop("contact"), row.pop("pair")
            pairs.append(_with_eps(row, contact, speeds, pair.R1 + pair.R2))
    walls, not_audited = _wall_rows(deck, speeds)
    return pairs, walls, not_audited

"""What the deck reader (:mod:`restitution.dem.deck.reader`) and the engines' deck dialects
(:mod:`restitution.dem.engines.lammps.deck`, :mod:`restitution.dem.engines.liggghts.deck`) share:
the settings a deck's commands build (:class:`Deck`), the one-line refusal (:class:`DeckError`),
the readings of words every command makes the same way (numbers, atom types and ranges, type
labels, where a line is), the two spheres of a type pair, the e to type for an eps, and what a
dialect provides (:class:`DeckDialect`).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from fractions import Fraction
from functools import lru_cache
from typing import Protocol

from ...core.errors import InputFileError, ParameterError
from ..calibrate import calibrate
from ..pair import Pair

__all__ = ["DeckError", "PairNotMapped", "Deck", "DeckDialect", "MAX_TYPES", "DEFAULT_SKIN", "FLAT_WALLS", "types", "type_pairs", "number", "number_or_none", "pour_into",
           "atom_type", "place", "fetch", "unlabeled", "labelmap", "spheres", "exact_e", "wall_faces"]


#: The neighbor command's default skin by units (LAMMPS' documentation; LIGGGHTS the same for si)
DEFAULT_SKIN = {"si": 0.001, "cgs": 0.1, "micro": 0.1, "nano": 0.1, "lj": 0.3, "real": 2.0, "metal": 2.0}


class DeckError(InputFileError):
    """One line naming what in the deck cannot be mapped or is missing.

    Parameters
    ----------
    where : str
        The line ("line 12", "data.file line 3") or the setting ("radius", "pair_coeff").
    text
        What stands there (a line, a type pair), or None.
    why : str
        What the reader cannot map, or what is missing.

    Examples
    --------
    >>> str(DeckError("line 3", "pair_style   lj/cut 2.5", "pair_style lj/cut is not mapped"))
    'line 3 (pair_style lj/cut 2.5): pair_style lj/cut is not mapped'
    """

    def __init__(self, where: str, text, why: str):
        super().__init__(where, text, why)
        shown = "" if text is None else f" ({' '.join(str(text).split())})"
        self.args = (f"{where}{shown}: {why}",)


class PairNotMapped(DeckError):
    """A type pair's contact line that the engine runs and the audit does not map (a cohesive normal
    model, an unmapped keyword or damping): that pair alone is not audited, the deck's other pairs
    and walls are (LAMMPS' own examples give jkr to one type beside hertz on another).

    Parameters
    ----------
    loc : tuple
        (file or None, line number) of the line.
    text : str
        The line.
    why : str
        What the audit does not map in it.

    Examples
    --------
    >>> err = PairNotMapped((None, 7), "pair_coeff 1 2 jkr 1e7 50 0.3 0.5", "normal model jkr is not mapped")
    >>> str(err)
    'line 7 (pair_coeff 1 2 jkr 1e7 50 0.3 0.5): normal model jkr is not mapped'
    >>> err.row(1, 2)[3]
    'types 1 2: normal model jkr is not mapped: not audited'
    """

    def __init__(self, loc: tuple, text: str, why: str):
        super().__init__(place(loc), text, why)
        self.loc, self.text, self.why = loc, text, why

    def row(self, i: int, j: int) -> tuple:
        """The (file, line, text, why) the audit lists as not audited, for type pair (i, j)."""
        return (*self.loc, self.text, f"types {i} {j}: {self.why}: not audited")


@dataclass
class Deck:
    """The settings of a deck at one line, as far as a head-on two-sphere contact is concerned.

    Parameters
    ----------
    code : str
        "LAMMPS" or "LIGGGHTS" (the engine of the pair style), "" before any.
    **fields
        The other fields, each commented where declared; all start empty.

    Examples
    --------
    >>> Deck().units, Deck().ntypes
    ('lj', 0)
    """
    code: str = ""                                # "LAMMPS" or "LIGGGHTS"
    ntypes: int = 0
    radius: dict = field(default_factory=dict)    # type -> radius
    density: dict = field(default_factory=dict)   # type -> density
    coeffs: dict = field(default_factory=dict)    # (i, j), i <= j -> (line number, tokens) [LAMMPS]
    props: dict = field(default_factory=dict)     # LIGGGHTS property/global name -> (line no, values)
    prop_fix: dict = field(default_factory=dict)  # LIGGGHTS property/global name -> "fix ID group"
    model: str = ""                               # LIGGGHTS normal model
    limit_force: bool = False
    absolute_damping: bool = False                # LIGGGHTS hooke/stiffness: gamman_abs, not m gamman
    cohesion: str = ""                            # LIGGGHTS cohesion sjkr|sjkr2 of the pair style, "" for none
    style_line: tuple = ()                        # ((file, line number), text) of pair_style
    unknown: list = field(default_factory=list)   # (file or None, line number, text, why) not understood
    ignored: list = field(default_factory=list)   # what the audit passed over on purpose
    atom_style: str = ""
    missing: dict = field(default_factory=dict)   # type -> why a data file gives it no single radius/density
    units: str = "lj"                             # the engines' default unit style
    dimension: int = 3                            # 2 or 3 (fix gravity's direction depends on it)
    soft: bool = False                            # LIGGGHTS soft_particles yes / hard_particles yes:
    hard: bool = False                            # its limits on Young's modulus lifted
    groups: dict = field(default_factory=dict)    # group ID -> set of types, or None where not by type
    walls: list = field(default_factory=list)     # (loc, words, the group's types then) of fix wall/gran
    # type -> ID of the LAMMPS fix deposit making its atoms (None: a set may have resized them since)
    deposits: dict = field(default_factory=dict)
    # type -> the molecule template whose one sphere a fix deposit of ``deposits`` makes (its size,
    # not LAMMPS' default)
    deposited_templates: dict = field(default_factory=dict)
    meshes: dict = field(default_factory=dict)    # LIGGGHTS fix mesh/surface ID -> its atom type, or None
    shaken: dict = field(default_factory=dict)    # LIGGGHTS fix move/mesh ID -> (loc, text, mesh ID) of an oscillation
    gran: dict = field(default_factory=dict)      # LAMMPS' older gran/* pair style: style, k_n, gamma_n, limit
    cutoff: float | None = None                   # LAMMPS pair_style granular's global cutoff, None where none
    # LAMMPS after a read_restart that restored pair_style granular, not given again since: its
    # global cutoff reads as 0 (measured: 'master list distance cutoff = 0', no ghost atoms)
    restored_cut: bool = False
    # Groups are static: a group holds the atoms present when it is defined, and those a later
    # command inserts into it by name (LAMMPS and LIGGGHTS alike; measured in LAMMPS: a wall on a
    # group by type defined before create_atoms lets the sphere through)
    atoms: bool = False                           # some atom exists at this line
    inserting: bool = False                       # an inserting fix (pour, insert/...) is defined
    empty_groups: set = field(default_factory=set)   # groups by type defined before any atom existed
    # group ID -> [(the command that inserts atoms into it, their types or None where not known)]
    filled_groups: dict = field(default_factory=dict)
    # group ID -> the command that made atoms of a type it was defined by after it was defined:
    # those are not its members, so its types no longer say which atoms it holds
    partial_groups: dict = field(default_factory=dict)
    style: str = ""                               # the pair style (LAMMPS keeps coefficients for the same)
    # (where, text, why) of a pair style the reader does not map, in force until another replaces
    # it: refused at a run that uses it, and no run may (a deck replacing it before its first run)
    unmapped: tuple = ()
    reset: tuple = ()                             # (loc, text) of a pair_style of another that discarded them
    # (loc, text, pair style, {pairs}) of a restart file the deck did not write: the pairs whose
    # coefficients only that file holds (LAMMPS keeps them where the deck gives the same style again)
    restart_pairs: tuple = ()
    # the step the runs so far reach (run N, run N upto, reset_timestep), None where unknown (a
    # minimize): a run that makes no step sees no contact
    step: int | None = 0
    atom_style_loc: tuple = ()                    # (file, line number) of atom_style
    # types known to hold atoms (create_atoms, read_data, a pour or deposit that has run), and
    # whether atoms of types the reader does not know exist: ``set group all`` sizes those only
    present: set = field(default_factory=set)
    present_unknown: bool = False
    shapes: dict = field(default_factory=dict)    # type -> (loc, text, what) where its particles are not spheres
    # (run locations, the deck as that run sees it, its contact key), one per change of contact settings
    stages: list = field(default_factory=list)
    inserts: list = field(default_factory=list)   # inserting fixes' types (a set, or None where unknown)
    # type -> {fix ID: style} of the inserting fixes defined so far that name it (a LAMMPS pour or
    # deposit), as ``inserts``: what a note on a type with no atom yet names
    inserters: dict = field(default_factory=dict)
    labels: dict = field(default_factory=dict)    # LAMMPS type label -> atom type (labelmap atom, data files)
    dt: float | None = None                       # the timestep command's, None where the deck has none
    dt_reset: tuple = ()                          # (loc, text, fix ID) of a fix dt/reset in force, else ()
    dt_reset_runs: int = 0                        # the runs recorded when that fix was defined
    skin: float | None = None                     # the neighbor command's skin, None where it has none
    neighbor_style: str = "bin"                   # the neighbor command's style (bin, nsq, multi)
    # whether the box is periodic in some direction (boundary's default p p p): ghost atoms across
    # it reach only the lists' cutoff, whatever the list style
    periodic: bool = True
    # neigh_modify's every, delay and check as set so far (meeting.late_speeds: the engine's defaults
    # where the deck sets none)
    neigh: dict = field(default_factory=dict)
    # (neigh, skin, dt) of the later runs a stage holds (same contacts, other lists or step), for
    # meeting.late_speeds
    lists_seen: list = field(default_factory=list)
    # (loc, line, group) of the velocity commands that may give atoms a velocity (meeting.phantom_velocity)
    velocities: list = field(default_factory=list)
    regions: dict = field(default_factory=dict)   # region ID -> its words as the engine ran them
    lattice: list = field(default_factory=list)   # the words of the last lattice command ([]: none)
    beside: list = field(default_factory=list)    # (loc, words) of fixes acting beside the contact law
                                                  # (restitution.dem.deck.beside), in force now
    held: dict | None = None                      # type -> [(radius, density)] the engine held at a run, or
                                                  # None where the deck was read without its engine
    # type -> the (radius, density) its spheres may have where it has several sizes (the engine's,
    # or a sample of a pour's ranges, their ends included); ``at`` the two spheres a pair row is
    # audited at then, ((R1, rho1), (R2, rho2)), else ()
    sizes: dict = field(default_factory=dict)
    # type -> {(radius, density)} its inserting fixes (a LAMMPS pour, a LIGGGHTS sphere template) add
    # to it as the runs go, kept beside the atoms the engine holds (which a pour's never are)
    poured: dict = field(default_factory=dict)
    # type -> the sizes exactly one of its atoms has at the run (the engine's count): two spheres
    # of such a size meet only where an inserting fix keeps making it
    once: dict = field(default_factory=dict)
    at: tuple = ()
    sampled: dict = field(default_factory=dict)   # type -> how many sizes it held where ``sizes`` is a sample
    # LAMMPS pair_style hybrid or hybrid/overlay ("" otherwise), its granular sub-style, and the
    # pairs another sub-style covers, (i, j) -> {its names}
    hybrid: str = ""
    substyle: str = ""
    # whether the hybrid style has one sub-style alone (its pair_coeff none acts otherwise), and
    # (i, j) -> (where, line) of the pair_coeff that last gave a pair none under it
    hybrid_one: bool = False
    none_at: dict = field(default_factory=dict)
    # where a hybrid style has two granular sub-styles (an older gran/* and granular): the pairs their
    # pair_coeff lines map, (i, j) -> {sub-style names} ({} where it has one)
    granular_of: dict = field(default_factory=dict)
    others: dict = field(default_factory=dict)
    # under hybrid/overlay, the pairs whose other sub-styles carry no force by their coefficients (the
    # zero style, or a prefactor 0), (i, j) -> {their names}: a fix adapt on one gives it a force
    idle: dict = field(default_factory=dict)
    # who meets whom (restitution.dem.deck.meeting): neigh_modify exclude settings in force, (loc,
    # text, [style, args...]); fix ID -> (loc, text, group, style) of the fixes that move atoms (an
    # integrator, fix move); (loc, text) of a command that made bonds (or angles, ...), and special_bonds' lj weights
    excludes: list = field(default_factory=list)
    movers: dict = field(default_factory=dict)
    bonds: tuple = ()
    special_lj: tuple = (0.0, 0.0, 0.0)
    # the bonded interactions with a force: "bond", "angle", ... -> (loc, text) of their style
    # command (not zero or none, which give none)
    bond_forces: dict = field(default_factory=dict)
    # (inserting fix ID, type) -> (the type, the (radius, density) it inserts of that type), for
    # the inserting fixes in force (a LAMMPS pour, a LIGGGHTS insert/* of one-sized sphere
    # templates); type -> why a set after their runs leaves the size of the atoms they made unknown
    pours: dict = field(default_factory=dict)
    # type -> {(radius, density): [(fix ID, where the set was)]}: sizes only a pour still in force
    # after a set resized what it made would give, if it has not finished inserting (which the
    # audit, its runs skipped, does not know)
    pending: dict = field(default_factory=dict)
    # the (file, line) of the runs the engine reached after a command read a value the skipped runs
    # would have changed: the stages they end may not be the deck's
    doubtful_runs: set = field(default_factory=set)
    # whether the engine made the deck's runs (a pass read after a run-dependent reading): the atoms
    # each run's marker wrote are where that run left them, those its inserting fixes made among
    # them, so no inserting fix's sizes are modelled
    ran: bool = False
    # a run's every ran quit: the engine ends the deck after that run's first part; (where, text)
    # of a run whose every may quit (an if's branch): no run with other contact settings may follow
    ended: bool = False
    may_end: tuple = ()
    # what the engine's set-up of the last run that made one read (reader.set_up_key), None before
    # the first run: a run with pre no after a change of it is not set up again
    set_up: str | None = None
    # type -> the radii its atoms held at that set-up, whose neighbour lists hold them till a rebuild
    set_up_radii: dict = field(default_factory=dict)
    # type -> the coefficients of its pair with itself at that set-up, from which a pair of it with
    # another type may be mixed
    set_up_own: dict = field(default_factory=dict)
    # (t, t) -> (loc, words) of those coefficients at that set-up; in a run with pre no after they
    # changed, the pairs LAMMPS mixes from them (no pair_coeff of their own) keep that mix: mixed_own
    set_up_like: dict = field(default_factory=dict)
    mixed_own: dict | None = None
    # type -> (where, line) of a run with pre no after its atoms grew: the neighbour lists hold its
    # smaller radii till their next build, so its pairs are not audited in that run
    stale: dict = field(default_factory=dict)
    # (where, line) of the last command since the last set-up that made LAMMPS' ghost atoms anew
    # (displace_atoms, change_box, balance, comm_style), and of the one a run with pre no met: lists
    # built before it hold ghost atoms' old indices, so a pair across a periodic boundary, or across
    # two processes' sub-domains, is found late (field rounds 32, PB20; 34, P47)
    reghosted: tuple = ()
    ghosts_stale: tuple = ()
    # (where, line) of a replicate since the last set-up, and of the one a run with pre no met: that
    # run moves no atom (field round 34, P76)
    replicated: tuple = ()
    still: tuple = ()
    # pairs of group IDs (frozensets) that share no atom: ``group A subtract B C`` makes A apart from
    # C; a later group command of either may add atoms to it, and ends the pair (field round 33,
    # M12: a lid by region moved by fix move beside nve/sphere on ``all`` minus the lid)
    disjoint: set = field(default_factory=set)
    # the atoms the engine held at the last run read, and at the last run set up (each an
    # engine's snapshot: {type: sizes}, with each atom's type and radius by ID where known)
    seen: dict | None = None
    set_up_seen: dict | None = None
    # the atoms at the run before the last read, and the fix adapts of atom diameter in force there
    seen_before: dict | None = None
    adapts_before: tuple = ()
    # a set of atom diameters run since the last run
    diameters_set: bool = False
    # type -> {charge q} its atoms hold, as the engine holds them at the deck's end (LAMMPS, an atom
    # style with a charge), where no command after the first run changes a charge; None: not known
    charges: dict | None = None
    resized: dict = field(default_factory=dict)
    # LAMMPS molecule template ID -> (template type, radius, density) of its one sphere, or the
    # reason (str) a pour of it is not audited (several atoms, no diameter, keywords)
    templates: dict = field(default_factory=dict)
    # LIGGGHTS particletemplate/sphere ID -> (its type, (radius, density)), None where its size is
    # not one constant; particledistribution/discrete ID -> the template IDs it draws from
    sphere_templates: dict = field(default_factory=dict)
    # variable name -> its equal-style formula as the engine ran it, None for a variable of another
    # style (a fix adapt's size is known where its variable is a constant)
    variables: dict = field(default_factory=dict)
    distributions: dict = field(default_factory=dict)
    # LIGGGHTS insertion fix ID -> (its start step, its style, {type: {(radius, density)}}) where its
    # ``start`` lies beyond the next step: it inserts nothing in the runs that end before that step
    # (field round 19, C4), and becomes a pour at the first run that reaches it
    waiting: dict = field(default_factory=dict)
    # environment variable -> the value a getenv-style variable of the deck read (the engine's pass
    # runs in the user's environment): the answer holds for these values
    environment: dict = field(default_factory=dict)
    putenv: dict = field(default_factory=dict)     # variables the deck's shell putenv set


class DeckDialect(Protocol):
    """What an engine's deck dialect module provides, as the reader's table of dialects uses it.

    Parameters
    ----------
    ENGINE : str
        The engine, a Deck's ``code`` once its pair style is read.
    PAIR_STYLES : tuple of str
        The pair styles it reads.
    MAPPED : str
        What it maps, as a refusal of another pair style lists it.
    FIXES : dict
        Fix style -> (its least number of words, ``f(deck, words, where, line, loc)``): fixes of its own.

    Examples
    --------
    >>> from restitution.dem.engines.lammps import deck as lammps_deck
    >>> lammps_deck.ENGINE, "granular" in lammps_deck.PAIR_STYLES
    ('LAMMPS', True)
    """
    ENGINE: str
    PAIR_STYLES: tuple
    MAPPED: str
    FIXES: dict

    def pair_style(self, deck: Deck, words: list, where: str, line: str) -> None:
        """Read ``pair_style`` ``words`` (words[1] one of PAIR_STYLES) into ``deck``; DeckError where
        it is not mapped, ``where`` and ``line`` naming the line."""

    def pair_coeff(self, deck: Deck, words: list, where: str, line: str, loc) -> None:
        """Read ``pair_coeff`` ``words`` (type labels replaced) into ``deck``; ``loc`` = (file or None,
        line number)."""

    def pair_row(self, deck: Deck, i: int, j: int) -> dict:
        """The audit's row for types i <= j of the settings a run sees, before its eps: {"types",
        "model", "typed_e", "end", "contact", "pair", "exact_line", "line", "file"}; DeckError where
        the deck gives the pair no contact."""

    def wall(self, deck: Deck, loc, words: list, unknown: list):
        """A fix wall/gran's flat surfaces (its words, at ``loc``) as [(mesh ID or None, a function of
        the wall Pair and the sphere's type giving (contact, typed e, model, exact line or None), the
        wall's type or None, its faces as :func:`wall_faces` gives them or None where a face's
        normal may point anywhere)], or None with (file, line, text, why) appended to ``unknown``."""


#: The audit lists every type pair, N (N + 1) / 2 of them: a deck with more types is refused.
MAX_TYPES = 1000
#: Flat walls (a sphere against a plane). Curved ones are each dialect's: audited with the
#: curvature its engine puts in the contact (LAMMPS' zcylinder), as planes where the engine puts
#: none (LIGGGHTS' cylinders), or named, not audited (region walls).
FLAT_WALLS = ("xplane", "yplane", "zplane")


def wall_faces(style: str, args: list, either_side: bool = False) -> list | None:
    """The faces of a primitive wall with the normal each turns to the spheres it meets, as the
    dialects read their walls' words: [(what, (nx, ny, nz))] for planes a sphere meets from one
    known side (LAMMPS' xplane|yplane|zplane lo hi: lo from above, hi from below, NULL none);
    [(what, axis)] with an axis (0, 1, 2) where the normal lies along that axis either way
    (``either_side``: LIGGGHTS' primitive planes); [(what, -axis - 1)] where it lies anywhere
    across that axis (a cylinder along it). None where there is no face.

    Parameters
    ----------
    style : str
        xplane, yplane, zplane, xcylinder, ycylinder or zcylinder.
    args : list of str
        The words after it (a plane's lo and hi, or its one position where ``either_side``).
    either_side : bool, optional
        Whether a plane is met from both sides.

    Returns
    -------
    list or None

    Examples
    --------
    >>> wall_faces("zplane", ["0.0", "2000.0"])
    [('the face at z = 0.0', (0.0, 0.0, 1.0)), ('the face at z = 2000.0', (0.0, 0.0, -1.0))]
    >>> wall_faces("zplane", ["0.0"], either_side=True)
    [('the plane z = 0.0 (met from either side)', 2)]
    >>> wall_faces("zcylinder", ["0.05"])
    [('a zcylinder (its normal across z)', -3)]
    >>> wall_faces("xplane", ["NULL", "NULL"]) is None
    True
    """
    axis = "xyz".index(style[0])
    if style.endswith("cylinder"):
        return [(f"a {style} (its normal across {style[0]})", -axis - 1)]
    if either_side:
        return [(f"the plane {style[0]} = {args[0]} (met from either side)", axis)] if args else None
    faces = []
    for side, at in zip((1.0, -1.0), args[:2]):
        if at != "NULL":
            normal = [0.0, 0.0, 0.0]
            normal[axis] = side
            faces.append((f"the face at {style[0]} = {at}", tuple(normal)))
    return faces or None


def types(spec: str, ntypes: int, where: str, text: str) -> range:
    """A LAMMPS type range: 2, *, 1*, *3, 2*4.

    Parameters
    ----------
    spec : str
        The range as written.
    ntypes : int
        The deck's number of types (0 before create_box).
    where, text : str
        The line, for the refusal.

    Returns
    -------
    range

    Raises
    ------
    DeckError
        Before create_box, or where the range is not one or leaves 1..ntypes.

    Examples
    --------
    >>> list(types("2*", 4, "line 1", "pair_coeff 2* * hooke 1 0"))
    [2, 3, 4]
    """
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


def type_pairs(first: str, second: str, ntypes: int, where: str, text: str) -> list:
    """The type pairs (i, j), i <= j, a ``pair_coeff FIRST SECOND ...`` sets, by LAMMPS' own loop
    for every pair style, hybrid sub-styles too: i over the first range, j from max(jlo, i) over
    the second; two single types put in order first (LAMMPS' input swaps them).

    Parameters
    ----------
    first, second : str
        The two type ranges as written (labels replaced).
    ntypes : int
        The deck's number of types.
    where, text : str
        The line, for the refusal.

    Returns
    -------
    list of tuple

    Raises
    ------
    DeckError
        As :func:`types` for either range.

    Examples
    --------
    >>> type_pairs("*", "2", 3, "line 1", ""), type_pairs("2", "1*3", 3, "line 1", "")
    ([(1, 2), (2, 2)], [(2, 2), (2, 3)])
    >>> type_pairs("3", "2", 3, "line 1", "")
    [(2, 3)]
    """
    if first.isdigit() and second.isdigit() and int(first) > int(second):
        first, second = second, first
    to = types(second, ntypes, where, text)
    return [(i, j) for i in types(first, ntypes, where, text) for j in range(max(to.start, i), to.stop)]


def number(token: str, where: str, text: str) -> float:
    """A word as a number, or the refusal naming it.

    Parameters
    ----------
    token : str
        The word, substituted.
    where, text : str
        The line, for the refusal.

    Returns
    -------
    float

    Raises
    ------
    DeckError
        Where the word is no number.

    Examples
    --------
    >>> number("1e5", "line 1", "")
    100000.0
    """
    try:
        return float(token)
    except ValueError:
        raise DeckError(where, text, f"{token!r} is not a number") from None


def number_or_none(token) -> float | None:
    """A word (or None) as a finite number, None where it is none: for the readings that name what
    they cannot read instead of refusing it.

    Parameters
    ----------
    token : str or None
        The word, substituted.

    Returns
    -------
    float or None

    Examples
    --------
    >>> number_or_none("2.5e-3"), number_or_none("v_x"), number_or_none(None), number_or_none("inf")
    (0.0025, None, None, None)
    """
    try:
        value = float(token)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


def atom_type(token: str, where: str, text: str, what: str = "an atom type") -> int:
    """A type, or the number of types: an integer in 1..MAX_TYPES, else one line.

    Parameters
    ----------
    token : str
        The word.
    where, text : str
        The line, for the refusal.
    what : str
        What the number is, for the refusal.

    Returns
    -------
    int

    Raises
    ------
    DeckError
        Where it is not an integer in 1..MAX_TYPES.

    Examples
    --------
    >>> atom_type("2", "line 1", "create_atoms 2 single 0 0 0")
    2
    """
    x = number(token, where, text)
    if not (math.isfinite(x) and x == int(x) and 1 <= x <= MAX_TYPES):
        raise DeckError(where, text, f"{what} must be an integer in 1..{MAX_TYPES} (the audit lists every type "
                                     "pair)")
    return int(x)


def place(loc) -> str:
    """Where a line is, as the refusals say it.

    Parameters
    ----------
    loc : tuple
        (file name, or None for the deck itself; line number).

    Returns
    -------
    str

    Examples
    --------
    >>> place((None, 3)), place(("data.pour", 12))
    ('line 3', 'data.pour line 12')
    """
    source, n = loc
    return f"line {n}" if source is None else f"{source} line {n}"


def fetch(read_file, name: str, where: str, line: str) -> str:
    """The text of a file the deck names (include, jump, read_data).

    Parameters
    ----------
    read_file : callable or None
        ``read_file(name)``, raising OSError; None where the deck was given as text.
    name : str
        The file's name as the deck writes it.
    where, line : str
        The line naming it, for the refusal.

    Returns
    -------
    str

    Raises
    ------
    DeckError
        Without ``read_file``, or where the file cannot be read.

    Examples
    --------
    >>> fetch({"data.x": "title"}.__getitem__, "data.x", "line 4", "read_data data.x")
    'title'
    """
    if read_file is None:
        raise DeckError(where, line, "the deck names another file, and it was given as text: give it as a file")
    try:
        return read_file(name)
    except OSError as exc:
        raise DeckError(where, line, f"{name} cannot be read ({exc.strerror or exc})") from None


# ---------------------------------------------------------------------------- type labels
#: Where LAMMPS commands take an atom type, which may be a type label: command (or "fix STYLE") ->
#: the word positions
_TYPE_WORDS = {"pair_coeff": (1, 2), "create_atoms": (1,), "mass": (1,), "fix pour": (5,), "fix deposit": (5,)}
_LABEL = re.compile(r"[A-Za-z_][^\s*#]*")


def unlabeled(deck: Deck, words: list, where: str, line: str) -> list:
    """The command with each type label where a type goes replaced by its type (LAMMPS' type
    labels: pair_coeff glass steel ..., create_atoms glass ..., set type glass ..., group g type
    glass ...); a label never defined is refused, as LAMMPS stops on it.

    Parameters
    ----------
    deck : Deck
        Its ``labels``.
    words : list of str
        The command's words.
    where, line : str
        The line, for the refusal.

    Returns
    -------
    list of str

    Raises
    ------
    DeckError
        Where a label is not defined.

    Examples
    --------
    >>> unlabeled(Deck(labels={"glass": 2}), ["create_atoms", "glass", "single", "0", "0", "0"], "line 1", "")
    ['create_atoms', '2', 'single', '0', '0', '0']
    """
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


def labelmap(deck: Deck, words: list, where: str, line: str) -> None:
    """labelmap atom N label ... (the types' labels), labelmap clear; other kinds (bond, ...) and
    labelmap write have no bearing on a contact.

    Parameters
    ----------
    deck : Deck
        Its ``labels``, changed in place.
    words : list of str
        The command's words (at least two).
    where, line : str
        The line, for the refusal.

    Returns
    -------
    None
        The deck is changed in place.

    Raises
    ------
    DeckError
        Where LAMMPS stops on the command.

    Examples
    --------
    >>> deck = Deck()
    >>> labelmap(deck, ["labelmap", "atom", "1", "glass"], "line 1", "")
    >>> deck.labels
    {'glass': 1}
    """
    if words[1] == "clear":
        deck.labels.clear()
        return
    if words[1] != "atom":
        return
    args = words[2:]
    if len(args) % 2:
        raise DeckError(where, line, "labelmap atom needs pairs of a type and its label (LAMMPS stops)")
    for k in range(0, len(args), 2):
        t = atom_type(args[k], where, line)
        if not _LABEL.fullmatch(args[k + 1]):
            raise DeckError(where, line, f"{args[k + 1]!r} is not a type label (it must not start with a digit): "
                                         "LAMMPS stops")
        deck.labels[args[k + 1]] = t


# ---------------------------------------------------------------------------- what the audit needs
def pour_into(deck: Deck, t: int, sizes: set) -> None:
    """Sizes an inserting fix adds to type t as the runs go (a LAMMPS pour, a LIGGGHTS sphere
    template), kept with those every earlier one added and with the atoms of t the engine held at
    the last run: t's radius and density where all share one, else all its sizes.

    Parameters
    ----------
    deck : Deck
        The deck as read so far; ``poured``, ``radius``, ``density`` and ``sizes`` change.
    t : int
        The type filled.
    sizes : set of tuple
        The (radius, density) of the spheres the fix inserts.

    Returns
    -------
    None
        The deck changes in place.

    Examples
    --------
    >>> deck = Deck(held={1: [(0.01, 3000.0)]})
    >>> pour_into(deck, 1, {(0.005, 1000.0)})
    >>> deck.sizes[1], 1 in deck.radius
    ([(0.005, 1000.0), (0.01, 3000.0)], False)
    """
    poured = deck.poured.setdefault(t, set())
    poured |= sizes
    every = poured | set((deck.held or {}).get(t, ()))
    deck.sizes.pop(t, None)
    if len(every) == 1:
        (deck.radius[t], deck.density[t]), = every
        return
    deck.radius.pop(t, None)
    deck.density.pop(t, None)
    deck.sizes[t] = sorted(every)


def spheres(deck: Deck, i: int, j: int) -> Pair:
    """The two spheres of types i and j, or the refusal naming what the deck lacks for them.

    Parameters
    ----------
    deck : Deck
        Its radii, densities and particle shapes.
    i, j : int
        The types.

    Returns
    -------
    Pair

    Raises
    ------
    DeckError
        Where a type is not spheres, or has no single radius or density.

    Examples
    --------
    >>> spheres(Deck(radius={1: 0.5}, density={1: 2.0}), 1, 1).R1
    0.5
    """
    for t in (i, j):
        if t in deck.shapes:
            loc, text, what = deck.shapes[t]
            raise DeckError(place(loc), text, f"type {t}'s particles are {what}, not single spheres: the reader "
                                              "audits the head-on contact of two spheres only")
    if deck.at:           # one choice among a type's several sizes (a clump's spheres refused above)
        (r1, rho1), (r2, rho2) = deck.at
        return Pair.spheres(r1, r2, rho1, rho2)
    for t in (i, j):
        why = f" ({deck.missing[t]})" if t in deck.missing else (
            " (no set, particle template, pour or data file gives it one: a type without particles?)")
        if t not in deck.radius:
            raise DeckError("radius", f"type {t}", f"the deck gives no single radius for this type{why}: give "
                                                   f"--radius {t}=R")
        if t not in deck.density:
            raise DeckError("density", f"type {t}", f"the deck gives no single density for this type{why}: give "
                                                    f"--density {t}=RHO")
    return Pair.spheres(deck.radius[i], deck.radius[j], deck.density[i], deck.density[j])


def exact_e(contact, eps: float, typed_e_of) -> float | None:
    """The e to type into an engine's damping that takes an e (read from a contact by
    ``typed_e_of``) so that ``contact``'s law gives eps = ``eps`` under its end rule; None where
    no e does. Those dampings set D2 = f(e) sqrt(D1) with gamma = (alpha - 1)/2, so Omega = D1 / D2^2
    at every speed and eps depends on e alone: one calibration per law and e (the unit contact,
    D1 = 1 at g = 1) serves every pair and wall of a deck.

    Parameters
    ----------
    contact : Contact
        The law, with gamma = (alpha - 1)/2.
    eps : float
        The eps wanted.
    typed_e_of : callable
        Contact -> the e the engine's damping needs for it (the engine's own inverse, e.g.
        :func:`restitution.dem.engines.liggghts.contact.liggghts_e`); ParameterError where no e
        expresses it.

    Returns
    -------
    float or None

    Raises
    ------
    ValueError
        Where the law's gamma is not (alpha - 1)/2.

    Examples
    --------
    >>> from restitution.dem.engines.liggghts.contact import liggghts_contact
    >>> c = liggghts_contact(Pair.spheres(0.01, 0.01, 2500, 2500), E=5e6, nu=0.3, e=0.8, limit_force=True)
    >>> from restitution.dem.engines.liggghts.contact import liggghts_e
    >>> round(c.eps(1.0), 4), round(exact_e(c, 0.8, liggghts_e), 4)   # limitForce on: e 0.8 gives more
    (0.8081, 0.7912)
    """
    if contact.gamma != (contact.alpha - 1) / 2:
        raise ValueError(f"an exact e needs gamma = (alpha - 1)/2, not {contact.gamma} for alpha = {contact.alpha}")
    unit = _unit_contact(contact.alpha, contact.end, float(eps))
    try:     # the engine's e cannot express the damping that gives eps
        return None if unit is None else typed_e_of(unit)
    except ParameterError:
        return None


@lru_cache(maxsize=1024)
def _unit_contact(alpha: Fraction, end: str, eps: float):
    """The unit contact (D1 = 1, gamma = (alpha - 1)/2) damped to eps at g = 1; None where no damping
    gives eps. Omega does not depend on g or D1 here, so it serves every pair, wall and engine."""
    try:
        return calibrate(alpha, (alpha - 1) / 2, D1=1.0, eps=eps, g=1.0, end=end).contact
    except ParameterError:
        return None

"""What eps does an input deck really give? A reader of LAMMPS (``pair_style granular``) and
LIGGGHTS (``pair_style gran model hertz|hooke|hertz/stiffness|hooke/stiffness``) input scripts, for
every type pair.

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
(hooke, hooke/history, hertz/history) with their pair style's law. Cylinders are audited with the
curvature their engine puts in the contact: LAMMPS' zcylinder, met from inside, with the effective
radius R 2Rc / (2Rc - R) LAMMPS gives it; LIGGGHTS' primitive cylinders as planes (LIGGGHTS takes
the sphere's own radius as the effective radius against every wall), which their rows say. LAMMPS'
region walls (``fix wall/gran/region``), whose every surface has its own curvature, are audited as
planes where their law does not read the effective radius (the linear laws: no curvature changes
their contact), else named as not audited, as are a mesh's edges and corners. A group holds the
atoms present when it is defined (and those a later command inserts into it): a group by type
defined before any atom exists holds none, and its wall, acting on no atom, is named as not
audited; a LAMMPS pour or deposit into the group adds the type it pours, a LIGGGHTS insert fix
or read_data into it atoms of types the reader cannot know (named likewise); else the audit
takes the types it names. A wall removed later (``unfix``) is still listed: it acts until then.

Tangential, rolling and twisting models take no part in a head-on collision and are ignored.

Which spheres meet, and how they move, is :mod:`restitution.dem.deck.meeting`'s: a pair the
engine's neighbour list leaves out (``neigh_modify exclude``, bonded atoms) is named, not audited;
where one sphere of a pair is moved by no integrator (or by ``fix move linear``), the pair's eps is
the other sphere's motion under the engine's force; the pairs of a type whose spheres ``fix rigid``
joins into bodies are named, not audited, and a deck whose runs integrate no atom is refused (the
engine moves none: no contact happens). A wall not audited names the sphere types it acts on.

The deck's engine interprets it (:func:`engine_of` tells which): LAMMPS for a LAMMPS deck (its
Python module, runs skipped), the ``liggghts`` binary for a LIGGGHTS deck (each run one step), both
in a scratch copy of the deck's folder (:mod:`restitution.dem.deck.scratch`) where nothing that
runs code or writes files is executed. Variables, expressions, ``if``, ``jump``/``label``, ``next``
loops, ``include`` and ``quit`` are the engine's own; the audit reads the commands it echoed, in
the order they ran (:mod:`restitution.dem.deck.stream`), and the atoms it held at each run. A
``pair_style`` of another style discards the coefficients, as in the engines; ``clear`` discards
every setting. Each ``run`` sees the settings of its moment: every change between runs is a stage
of its own, audited (``run ... every`` with a command that changes the contact mid-run is
refused). Particles that are not single spheres (LIGGGHTS multisphere clumps, superquadrics, a LAMMPS
``fix pour ... mol`` of a template of several atoms) are refused; a pour of a one-atom template pours
spheres of the template's ``Diameters`` and ``Masses`` (density 1 without Masses, as LAMMPS). A deck its engine stops on is refused with the engine's message and the line.

A type whose atoms have several sizes (or that a ``fix pour`` fills
from a range of diameters, sampled at nine points with its ends) gives each of its pairs two rows,
the smallest and the largest eps at the middle speed with the spheres they are at (``sizes``,
``at``), or one row where the sizes' eps agree to 1e-9 (a law whose eps does not depend on size);
a size with itself only where two spheres of it can meet (more than one atom has it, or a pour
keeps making it). Where the sizes' eps agree, a fix beside the contact whose effect still depends on size (a gravity on a wall) is given at
the sizes that end its range at the middle speed, each with its ``at``.
Under ``pair_style hybrid`` or ``hybrid/overlay`` the granular sub-style is read from the
pair_coeff lines naming it; a pair another sub-style covers is named, not audited. Two granular
sub-styles (an older gran/* and granular) give each pair the one its pair_coeff lines name, as
LAMMPS maps them; a pair both cover (hybrid/overlay) is refused.

Files the deck names (``include``, ``jump``, ``read_data``) are read through a ``read_file``
callable (the CLI resolves their names against the deck's directory, where LAMMPS is normally
started); a data file's Atoms section gives a type its radius and density where every atom of that
type has the same. A type pair no ``pair_coeff`` covers is mixed as LAMMPS mixes it (pair_style
granular: the same models for both types, geometric means, Young's moduli combined as 1/E* = sum
(1 - nu^2)/E, limit_damping if either type has it).

LAMMPS type labels (``labelmap atom``, a data file's Atom Type Labels) stand for their types; a
``fix pour`` without diam or dens pours LAMMPS' defaults (diameter 1, density 1); ``heat`` models
on a pair_coeff line (conduction) are accepted and named; LIGGGHTS' aliases of property/global
styles are read.

This module audits; reading is :mod:`restitution.dem.deck.reader`'s (the commands every engine
shares), each engine's pair style, coefficients and walls its dialect's
(:mod:`restitution.dem.engines.lammps.deck`, :mod:`restitution.dem.engines.liggghts.deck`), and
the words :mod:`restitution.dem.deck_text`'s. ``Deck``, ``DeckError``, ``MAX_STAGES`` and
``MAX_TYPES`` are importable from here too.
"""

from __future__ import annotations

import os
import re
import tempfile
from collections import Counter
from dataclasses import replace
from functools import lru_cache
from pathlib import Path

from ...core.collision import StickError
from ...core.errors import ParameterError
from .beside import ADAPT, effects
from .meeting import excluded, held_contact, integrators, late_speeds, motion, phantom_velocity, unlisted
from .reader import DIALECTS, MAX_STAGES, by_position, contact_key, read_executed
from ..dialect.sandbox import available as confining
from ..dialect.state import MAX_TYPES, Deck, DeckError, PairNotMapped, place, spheres
from ..engines.lammps.deck import DEFAULT_DT, REGION_UNBOUNDED, SPEED_UNITS, read_region, region_number
from ..contact import TIMES_OMEGA_MAX, ElasticContact
from ..pair import Pair
from ..timestep import recommended_dt, verlet_eps

__all__ = ["DeckError", "Deck", "audit_deck", "engine_of", "engine_read", "MAX_STAGES", "MAX_TYPES"]


def _wall_types(deck: Deck, types, loc, words, unknown: list):
    """The atom types a wall acts on, or None (said in ``unknown``) where the group has none known."""
    if types == "all":
        return list(range(1, deck.ntypes + 1))
    if types is None or types == "undefined":
        why = "not defined before it" if types == "undefined" else "not defined by type"
        unknown.append((*loc, " ".join(words), f"group {words[2]} is {why}: the wall's contacts are not audited"))
        return None
    if words[2] in deck.partial_groups and words[2] not in deck.empty_groups:
        unknown.append((*loc, " ".join(words), f"group {words[2]} was defined by type before "
                                               f"{deck.partial_groups[words[2]]} (a group holds the atoms present "
                                               "when it is defined): the wall's contacts are not audited"))
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
        unknown.append((*loc, " ".join(words), f"group {words[2]} was defined before any atom it would hold existed "
                                               "(a group holds the atoms present when it is defined): it holds none, "
                                               "and the wall acts on no atom"))
        return None
    return sorted(t for t in held if 1 <= t <= deck.ntypes)


def _possible_types(deck: Deck, types, words) -> list:
    """The types a wall may act on where :func:`_wall_types` cannot type its group: every type for a
    group by region, id or the like, or one an insertion of unknown types fills; a group by type
    defined before more atoms of its types were made, its types (some of their atoms); none for a
    group defined nowhere or holding no atom."""
    if types == "undefined":
        return []
    if types is None or any(filled is None for _, filled in deck.filled_groups.get(words[2], [])):
        return list(range(1, deck.ntypes + 1))
    if words[2] in deck.partial_groups and words[2] not in deck.empty_groups:
        return sorted(t for t in types if 1 <= t <= deck.ntypes)
    return []


#: A primitive wall's shape word and how many numbers after it place its surface: a plane's
#: position(s) (LAMMPS' lo and hi, LIGGGHTS' one), a cylinder's radius and (LIGGGHTS) its axis
_PLACED = {"xplane": 2, "yplane": 2, "zplane": 2, "xcylinder": 3, "ycylinder": 3, "zcylinder": 3}


def _surfaces_at(words: list, deck: Deck | None = None) -> set | None:
    """Where a wall's surfaces lie, as comparable keys: ("z", 0.0) for a plane at z = 0 (either
    face: the engines push a sphere off a plane from whichever side it overlaps it), a cylinder as
    (style, radius, centre, centre), a sphere as ("sphere", centre, radius); a LAMMPS region's
    (``deck``: its regions) block faces, axis-aligned plane, cylinder side and finite ends. None
    where the audit does not place them: a mesh, another region style, a moving region, one sized by
    a variable or in lattice units it does not read.

    Examples
    --------
    >>> sorted(_surfaces_at("fix w all wall/gran granular hooke 1 1 zplane 0.0 NULL".split()))
    [('z', 0.0)]
    >>> _surfaces_at("fix w all wall/gran model hertz primitive type 2 zcylinder 0.05 0 0".split())
    {('zcylinder', 0.05, 0.0, 0.0)}
    >>> _surfaces_at("fix w all wall/gran granular hooke 1 1 zcylinder 0.05".split())
    {('zcylinder', 0.05, 0.0, 0.0)}
    >>> d = Deck(regions={"cup": "region cup block -1 1 -1 1 0 INF units box".split(),
    ...                   "can": "region can cylinder z 0 0 0.5 0 2 units box".split()})
    >>> sorted(_surfaces_at("fix w all wall/gran/region granular hooke 1 1 region cup".split(), d))
    [('x', -1.0), ('x', 1.0), ('y', -1.0), ('y', 1.0), ('z', 0.0)]
    >>> sorted(_surfaces_at("fix w all wall/gran/region granular hooke 1 1 region can".split(), d), key=str)
    [('z', 0.0), ('z', 2.0), ('zcylinder', 0.5, 0.0, 0.0)]
    >>> _surfaces_at("fix w all wall/gran model hertz mesh n_meshes 1 meshes floor".split()) is None
    True
    """
    if words[3:4] == ["wall/gran/region"]:
        return _region_places(deck, words[words.index("region", 4) + 1]) if deck and "region" in words[4:-1] else None
    for k, word in enumerate(words[4:], 4):
        if word in _PLACED:
            numbers = []
            for arg in words[k + 1:k + 1 + _PLACED[word]]:
                try:
                    numbers.append(float(arg))
                except ValueError:
                    if arg != "NULL":
                        break
            if word.endswith("plane"):
                return {(word[0], at) for at in numbers}
            # LAMMPS' cylinders lie on the axis itself (its one argument, the radius)
            return {(word, *numbers, *[0.0] * (3 - len(numbers)))} if numbers else None
    return None


def _region_places(deck: Deck, rid: str) -> set | None:
    """The surfaces of LAMMPS region ``rid`` (:func:`~restitution.dem.engines.lammps.deck.read_region`)
    as :func:`_surfaces_at` keys, or None where the audit does not place them."""
    region = read_region(deck, rid)
    if isinstance(region, str):
        return None                  # a moving or rotating region, or one not read
    args, units = region.args, region.units
    if region.style == "cylinder":
        axis, numbers = args[0], [region_number(a, deck, units) for a in args[1:4]]
        ends = [region_number(a, deck, units) if a not in REGION_UNBOUNDED else None for a in args[4:6]]
    else:
        numbers = [region_number(a, deck, units) if a not in REGION_UNBOUNDED else None for a in args]
        ends = []
    if any(isinstance(x, str) for x in numbers + ends):
        return None                  # a variable's size, or lattice units not read
    if region.style == "block":
        # faces 1 to 6: xlo, xhi, ylo, yhi, zlo, zhi; an open one is no wall (field round 14, w16:
        # a box open at its bottom was named as a second wall at the floor)
        return {("xyz"[k // 2], at) for k, at in enumerate(numbers) if at is not None and str(k + 1) not in region.opened}
    if region.style == "sphere":
        return {("sphere", *numbers)} if None not in numbers else None
    if region.style == "plane":
        normal = numbers[3:]
        axes = [k for k, n in enumerate(normal) if n]
        return {("xyz"[axes[0]], numbers[axes[0]])} if len(axes) == 1 and None not in numbers[:3] else None
    c1, c2, radius = numbers
    places = set() if "3" in region.opened else {(f"{axis}cylinder", radius, c1, c2)}
    return places | {(axis, at) for face, at in zip("12", ends) if at is not None and face not in region.opened}


def _reach(deck: Deck, t: int) -> float | None:
    """The largest diameter of type ``t``'s spheres at this stage, None where the audit has none."""
    sizes = deck.sizes.get(t) or ([(deck.radius[t], None)] if t in deck.radius else [])
    return 2.0 * max(r for r, _ in sizes) if sizes else None


def _near(at: set, other_at: set, reach: float | None) -> list:
    """The pairs of two walls' surfaces (:func:`_surfaces_at` keys) one sphere may overlap at
    once: the same surface, or parallel planes, coaxial cylinders or concentric spheres closer than
    ``reach``, the sphere's diameter (a sphere overlaps two parallel surfaces together exactly where
    they are less than its diameter apart, at whatever speed; how deep a contact goes at a speed
    would give a narrower rule, per speed, which the audit does not need to name the other wall).

    Examples
    --------
    >>> _near({("z", 0.0)}, {("z", 1e-4)}, 0.004), _near({("z", 0.0)}, {("z", 0.09)}, 0.004)
    ([(('z', 0.0), ('z', 0.0001))], [])
    >>> _near({("zcylinder", 0.05, 0.0, 0.0)}, {("zcylinder", 0.052, 0.0, 0.0), ("z", 0.0)}, 0.004)
    [(('zcylinder', 0.05, 0.0, 0.0), ('zcylinder', 0.052, 0.0, 0.0))]
    """
    found = []
    for a in sorted(at, key=str):
        for b in sorted(other_at, key=str):
            if a == b or reach is not None and (gap := _gap(a, b)) is not None and gap < reach:
                found.append((a, b))
    return found


def _gap(a: tuple, b: tuple) -> float | None:
    """The distance between two surfaces of one kind (:func:`_surfaces_at` keys) that never cross:
    parallel planes (their positions), cylinders about one axis (their radii), spheres about one
    centre (their radii); None for any other two."""
    if a[0] != b[0] or len(a) != len(b):
        return None
    if len(a) == 2:                                      # ("z", at)
        return abs(a[1] - b[1])
    if a[0] == "sphere":                                 # ("sphere", x, y, z, radius)
        return abs(a[4] - b[4]) if a[1:4] == b[1:4] else None
    return abs(a[1] - b[1]) if a[2:] == b[2:] else None  # ("zcylinder", radius, c1, c2)


def _shown(key: tuple) -> str:
    """A surface key as the notes say it: "z = 0", "zcylinder 0.05 0 0"."""
    return f"{key[0]} = {key[1]:g}" if len(key) == 2 else " ".join(f"{x:g}" if isinstance(x, float) else x
                                                                    for x in key)


def _shared_faces(deck: Deck) -> dict:
    """{(wall ID, type): [(other wall's loc, words, where, kind)]} for walls that act on the same type at
    the same plane, cylinder or sphere, or at parallel ones closer than the type's largest diameter
    (:func:`_near`; field round 13: a floor at z = 0 and a plane region at 1e-4, sphere diameter
    0.004: LAMMPS 0.4037 at g 3.162 where either wall's row said 0.5370), or where one of them is not
    placed (a mesh, a region the audit does not read), so that they may meet there: the engine adds
    both walls' forces on a sphere that meets them at one surface (LAMMPS and LIGGGHTS, two
    identical hertz walls of e = 0.5 at z = 0: eps 0.366, where one gives 0.5; a mesh floor on a
    plane the same), a law no row of one wall says. ``kind``: "same" (one surface), "near" (some
    pair of surfaces apart by less than the diameter) or "unplaced"."""
    placed = []
    for loc, words, types in deck.walls:
        held = _wall_types(deck, types, loc, words, [])
        untyped = held is None and bool(held := _possible_types(deck, types, words))
        if held:
            placed.append((loc, words, set(held), _surfaces_at(words, deck), untyped))
    shared = {}
    for loc, words, held, at, _ in placed:
        for other_loc, other, other_held, other_at, untyped in placed:
            if other[1] == words[1]:
                continue
            # a wall whose group the audit cannot type is not audited, but may still act beside
            # this one (field round 14, D2: a floor on a group by region at the same z; the row
            # of the other floor said 0.11699, LAMMPS 0.09315)
            maybe = (f"; wall {other[1]}'s group {other[2]} is not typed by the audit: it may hold type {{t}}'s "
                     "spheres") if untyped else ""
            for t in sorted(held & other_held):
                if at is None or other_at is None:
                    unplaced = words if at is None else other
                    shared.setdefault((words[1], t), []).append((other_loc, other, (
                        f"the audit does not place the surfaces of wall {unplaced[1]}" + maybe.format(t=t)),
                        "unplaced"))
                elif near := _near(at, other_at, reach := _reach(deck, t)):
                    where = ", ".join(_shown(a) if a == b else (
                        f"{_shown(a)} and {_shown(b)}, less than the diameter {reach:g} of type {t}'s "
                        "largest sphere apart, so that a sphere may overlap both") for a, b in near) + maybe.format(t=t)
                    kind = "same" if all(a == b for a, b in near) else "near"
                    shared.setdefault((words[1], t), []).append((other_loc, other, where, kind))
    return shared


def _wall_rows(deck: Deck, speeds, ran: bool) -> tuple[list, list]:
    """For every flat fix wall/gran and every type it acts on, the eps of that type's sphere
    hitting it head-on; and the walls not audited, each with its reason (``ran``: the settings are
    a run's, :func:`restitution.dem.deck.meeting.motion`)."""
    rows, unknown = [], []
    parse = DIALECTS[deck.code].wall
    shared = _shared_faces(deck)
    for loc, words, types in deck.walls:
        said = len(unknown)
        surfaces = parse(deck, loc, words, unknown)
        if surfaces is None:
            # which sphere types meet the wall not audited, where its group says
            held = [t for t in _wall_types(deck, types, loc, words, []) or [] if not _empty(deck, t)]
            unknown[said:] = [(f, n, text, f"{why}; the spheres it acts on: type{'s' if len(held) > 1 else ''} "
                                           f"{', '.join(map(str, held))}" if held else why)
                              for f, n, text, why in unknown[said:]]
            continue
        if (types := _wall_types(deck, types, loc, words, unknown)) is None:
            continue
        for mesh, contact_of, wall_type, faces in surfaces:
            shaking = [text for _, text, moved in deck.shaken.values() if moved == mesh]
            if shaking:
                unknown.append((*loc, " ".join(words), f"mesh {mesh} moves with an acceleration ({shaking[0]}): "
                                                       "its faces accelerate under a sphere during a contact, so "
                                                       "the eps the engine measures depends on when and where on "
                                                       "a face a contact falls: its faces are not audited"))
                continue
            for t in types:
                if _empty(deck, t):          # no sphere of it to meet the wall (named in the notes)
                    continue
                kind, why = motion(deck, t, ran)
                if kind != "free":
                    unknown.append((*loc, " ".join(words), f"type {t}: {why}: its contact with the wall is not "
                                                           "audited"))
                    continue
                if (why := unlisted(deck, t)) is not None:
                    unknown.append((*loc, " ".join(words), why))
                    continue
                if t not in deck.sizes or t in deck.shapes:
                    spheres(deck, t, t)          # one line where the type lacks a radius or a density, or is no sphere
                def wall_row(size, at_speeds, t=t, mesh=mesh, contact_of=contact_of, wall_type=wall_type,
                             faces=faces):
                    pair = Pair.wall(*size)
                    contact, typed, model, exact = contact_of(pair, t)
                    if at_speeds is None:
                        return contact, pair.R1
                    row = _with_eps({"wall": words[1], "mesh": mesh, "types": [t], "wall_type": wall_type,
                                     "model": model, "typed_e": typed, "end": contact.end, "exact_line": exact,
                                     "line": loc[1], "file": loc[0]}, contact, at_speeds, pair.R1, _dt(deck))
                    # another wall at this surface: named beside the row (the engine adds both forces)
                    others = [{"fix": other[1], "style": other[3], "file": other_loc[0], "line": other_loc[1],
                               "what": {"same": f"another wall at the same surface ({where}), whose force the "
                                                "engine adds to this wall's on a sphere that meets both",
                                        "near": f"another wall near this one ({where}): the engine adds both walls' "
                                                "forces on a sphere that overlaps both",
                                        "unplaced": f"another wall, which may meet this one at a surface ({where}): "
                                                    "where it does, the engine adds both walls' forces on a sphere "
                                                    "there"}[kind],
                               "eps_engine": None,
                               "why": "its size is not computed", "along": None}
                              for other_loc, other, where, kind in shared.get((words[1], t), [])]
                    # the other meshes of this one fix (n_meshes 2 or more): LIGGGHTS adds each mesh's
                    # force on a sphere that meets them at one place (field round 13, one plane twice:
                    # 0.2200 where each mesh's row said 0.3630); the audit does not place meshes
                    others += [{"fix": words[1], "style": words[3], "file": loc[0], "line": loc[1],
                                "what": (f"another mesh of this wall ({other_mesh}), which may meet this one at a "
                                         "surface (the audit does not place meshes): where it does, the engine adds "
                                         "both meshes' forces on a sphere there"),
                                "eps_engine": None, "why": "its size is not computed", "along": None}
                               for other_mesh in dict.fromkeys(m for m, *_ in surfaces) if other_mesh != mesh]
                    # sized by _ends on the rows it keeps (_beside)
                    row["_beside"] = lambda at_row: effects(deck, at_row, contact, pair, (t,), faces=faces) + others
                    return row, (tuple(size),) if t in deck.sizes else ()
                rows += _pending_rows(deck, (t,), _sampled_rows(deck, (t,), _time_steps(_ends(_over_sizes(
                    deck.sizes.get(t) or [(deck.radius[t], deck.density[t])], wall_row, speeds)))))
    return rows, unknown


#: Fewer steps per contact than this at the deck's time step: the eps of the engine's integrator
#: there is given beside the dt -> 0 value, and a time step that keeps eps within DT_TOL
FEW_STEPS = 50
#: The relative error in eps that the time step stated keeps
DT_TOL = 1e-3
#: Up to this many steps per contact, a contact whose integrator eps at the deck's time step strays
#: from the dt -> 0 value by more than DT_TOL at some start in a step (:func:`_over_starts`) is
#: stated as those below FEW_STEPS are (field round 30, C29: 147 steps, LAMMPS 0.409793 where
#: 0.414916 was printed with no word; C31: 53 steps, 0.424189). The integrators' largest stray falls
#: as 1/steps (about 2/steps relative for a hooke pair damped to 0.41: 0.36 % at 586 steps); beyond this
#: many the steps per contact alone are said (the docs give the rule), the study costing a tenth of a
#: second a speed here
STRAY_STEPS = 1000


def _with_eps(row: dict, contact, speeds, limit: float, dt: float | None = None) -> dict:
    """The row with eps at every speed, where the engine would push the bodies through each other
    (the largest overlap reaching ``limit``) none, and the contact's parameters; with the deck's
    time step ``dt``, the steps per contact at each speed and, below FEW_STEPS or where it strays
    from the dt -> 0 eps by more than DT_TOL (STRAY_STEPS), the eps velocity
    Verlet gives at that dt (the engines' integrator, :func:`restitution.dem.timestep.verlet_eps`)
    and the time step that keeps it within DT_TOL (:func:`restitution.dem.timestep.recommended_dt`:
    the largest its first-order study allows, run and checked there)."""
    through = [contact.reaches(g, limit) for g in speeds]
    if through[len(speeds) // 2]:   # no eps at the middle speed: no line promising one
        row["exact_line"] = None
    eps = [(None, False) if t else _eps_or_stick(contact, g) for g, t in zip(speeds, through)]
    row.update(speeds=speeds, eps=[e for e, _ in eps], sticks=[s for _, s in eps], passes_through=through,
               overlap_limit=limit, **{k: v for k, v in contact.as_dict().items() if k != "end"})
    # studied by _time_steps on the rows kept (a range of sizes keeps its two ends of many)
    row["_time_step"] = (contact, dt)
    return row


def _time_steps(rows: list) -> list:
    """The rows, each with its deck's time step studied where it has one (:func:`_with_eps`)."""
    for row in rows:
        contact, dt = row.pop("_time_step")
        if dt is not None:
            steps, at_dt, within, spread = zip(*(_time_step(contact, g, dt, e, stick or t) for g, e, stick, t
                                                 in zip(row["speeds"], row["eps"], row["sticks"],
                                                        row["passes_through"])))
            row.update(dt=dt, steps_per_contact=list(steps), eps_at_dt=list(at_dt), dt_within_tol=list(within),
                       dt_tol=DT_TOL, eps_at_dt_spread=list(spread))
    return rows


@lru_cache(maxsize=4096)
def _time_step(contact, g: float, dt: float, e, no_eps: bool) -> tuple:
    """(steps per contact, the integrator's eps at dt where the contact starts on a step, the dt
    within DT_TOL, and the (smallest, largest) eps over where in a step it starts) at one speed; kept,
    as a deck's walls and stages repeat the same contact (a tutorial's six walls over three runs: 18
    times each contact time's quadratures). With a few steps per contact that start decides eps (a
    hooke pair at 7.4 steps: 0.976 to 1.017 in LAMMPS by the start, 1.017 on a step)."""
    t_c = None if no_eps else _contact_time(contact, g)
    n = None if t_c is None else t_c / dt
    few = n is not None and n < FEW_STEPS
    # below 2 steps the integrator does not resolve the contact: no eps is stated for it
    spread = _over_starts(contact, g, dt) if n is not None and 2 <= n <= max(FEW_STEPS, STRAY_STEPS) else None
    if not few and spread is not None and all(abs(x - e) <= DT_TOL * abs(e) for x in spread):
        spread = None           # within DT_TOL from every start: the steps per contact are said alone
    stated = few or spread is not None
    return (n, verlet_eps(contact, g, dt) if spread is not None else None,
            recommended_dt(contact, g, DT_TOL, eps=e, contact_time=t_c).dt if stated else None, spread)


def _over_starts(contact, g: float, dt: float) -> tuple:
    """(smallest, largest) integrator eps over where in a step the contact starts: STARTS starts,
    then STARTS more around each end's (eps is piecewise smooth in the start, with kinks where a
    step boundary crosses the contact's end: the ends to 1/STARTS^2 of a step)."""
    def over(phases):
        return [(verlet_eps(contact, g, dt, phase=p % 1.0), p) for p in phases]
    grid = over(k / STARTS for k in range(STARTS))
    ends = []
    for pick in (min, max):
        _, p0 = pick(grid)
        ends.append(pick(over(p0 + (k - STARTS / 2) / STARTS ** 2 for k in range(STARTS + 1)))[0])
    return tuple(ends)


#: Where in a step a contact may start: the integrator's eps at a coarse dt is stated over this many
#: evenly spread starts, refined as many times around its smallest and largest
STARTS = 32


def _contact_time(contact, g: float) -> float:
    """The contact time; beyond the integrators' Omega (TIMES_OMEGA_MAX: glass-like spheres with a
    small damping, eps within 1e-9 of 1) the undamped contact's, which the damped one approaches as
    Omega grows: they differ by at most 3.1e-5 (relative) at Omega = 1e15 for the laws the engines map
    (measured with the compiled integrator: 3/2, 0 under the force rule the largest, 3/2, 1/2 2e-10),
    a bound on a count of steps, never on an eps."""
    try:
        return contact.contact_time(g, compiled=True)
    except ParameterError:
        if not contact.omega(g) > TIMES_OMEGA_MAX:
            raise
        return ElasticContact(contact.alpha, contact.D1, contact.end).contact_time(g)


def _eps_or_stick(contact, g: float) -> tuple[float, bool]:
    """(eps, False), or (0, True) where the overlap rule's attraction keeps the bodies together."""
    try:
        return contact.eps(g), False
    except StickError:
        return 0.0, True


#: Wall-time budget of an engine's pass through a deck (runs skipped) in a loop, in seconds: its
#: clock runs from the first line the engine runs a second time; a pass that runs no line twice is
#: bounded only by :data:`restitution.dem.dialect.child.CEILING` times it. 10 times the longest pass
#: of the official examples and tutorials on a loaded 2-core machine (2 s); what the engine echoes is
#: capped too (:data:`restitution.dem.dialect.child.MAX_ECHO`)
BUDGET = 20.0
#: The budgets a caller may ask for, in seconds.
BUDGET_RANGE = (1.0, 3600.0)
#: Wall time in seconds the engine may spend making a deck's runs for real, where its pass
#: with runs skipped met a command that reads what they change: a position, a count after a pour,
#: the step, an energy (:func:`_made_runs`). Two spheres' 8000 steps take LAMMPS 0.2 s; a pour of
#: 3000 grains over 25 000 steps about 20 s on a loaded 2-core machine
RUN_BUDGET = 60.0
#: The run budgets a caller may ask for, in seconds (0: the runs are never made)
RUN_BUDGET_RANGE = (0.0, 3600.0)
#: The most steps of all its runs together the engine makes for real: a deck's production runs
#: (10^8 steps) are not the audit's to make, whatever the wall time allowed
MAX_RUN_STEPS = 10_000_000
_LIGGGHTS_DECK = re.compile(r"^\s*(pair_style\s+gran\s+model|atom_style\s+granular|fix\s+\S+\s+\S+\s+"
                            r"(particletemplate|particledistribution|insert/|mesh/surface|property/global))", re.M)


def engine_of(text: str) -> str:
    """The engine a deck is written for: "LIGGGHTS" where it has a command only LIGGGHTS knows
    (``pair_style gran model``, ``atom_style granular``, its templates, insertions, meshes and
    material properties), else "LAMMPS".

    Parameters
    ----------
    text : str
        The input script.

    Returns
    -------
    {"LIGGGHTS", "LAMMPS"}

    Examples
    --------
    >>> engine_of("pair_style gran model hertz tangential history\\n"), engine_of("pair_style granular\\n")
    ('LIGGGHTS', 'LAMMPS')
    """
    return "LIGGGHTS" if _LIGGGHTS_DECK.search(text) else "LAMMPS"


def _with_included(text: str, deck: Path) -> str:
    """The deck's text and that of the files its include and jump lines name as written: a LIGGGHTS
    deck may keep every line only LIGGGHTS knows in an included settings file (field round 21, N01
    was run in LAMMPS, which stopped on it)."""
    from .scratch import scripts_named
    texts = [text]
    for path in scripts_named(deck, literal=True):
        try:
            # a regular file of sane size: not a device or pipe a read would never end
            if path.is_file() and path.stat().st_size <= 2 ** 24:
                texts.append(path.read_text(encoding="utf-8", errors="replace"))
        except OSError:
            continue
    return "\n".join(texts)


def engine_read(path, radius: dict | None = None, density: dict | None = None, budget: float = BUDGET,
                engine: str | None = None, run_budget: float = RUN_BUDGET) -> tuple[Deck, list]:
    """The settings of a deck as its engine ran it: its own pass through a scratch copy of the
    deck's folder (nothing that runs code or writes files executed), read back.

    Parameters
    ----------
    path : path
        The input script.
    radius, density : dict, optional
        {type: value}, overriding or completing what the engine holds.
    budget : float
        Wall-time budget of the engine's pass in a loop, in seconds (a pass that runs no line twice:
        :data:`restitution.dem.dialect.child.CEILING` times it).
    engine : {"LAMMPS", "LIGGGHTS"}, optional
        The engine (:func:`engine_of` the deck's text where None).
    run_budget : float
        Wall time in seconds the engine may spend making the deck's runs for real, where the pass
        with runs skipped met a command that reads what they change (:func:`_made_runs`); 0: never.

    Returns
    -------
    (Deck, list of str)
        The settings (``stages`` those each run saw) and the notes for stderr (commands not
        executed, a budget that ended the pass).

    Raises
    ------
    DeckError
        Where the engine is not installed (how to get it), stops on the deck (its message and the
        line), or the deck holds no contact.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> with tempfile.TemporaryDirectory() as d:       # LAMMPS runs it (the dem extra)
    ...     p = pathlib.Path(d, "in.x")
    ...     _ = p.write_text("atom_style sphere\\nregion b block 0 4 0 4 0 4\\ncreate_box 1 b\\n"
    ...                      "create_atoms 1 single 1 1 1\\nset type 1 diameter 1 density 2\\n"
    ...                      "pair_style granular\\npair_coeff * * hooke 1000 50 tangential linear_nohistory 0 0\\n")
    ...     deck, notes = engine_read(p)
    >>> deck.radius, deck.density
    ({1: 0.5}, {1: 2.0})
    """
    path = Path(path)
    engine = engine or engine_of(path.read_text(encoding="utf-8", errors="replace"))
    from .scratch import MAX_TEXT_BYTES, PUSHING_FIX_PREFIXES, scratch_copy
    from .runtime import fixed_face, lost_in_runs, read_in_run, resized_by_runs, stops_in_runs
    from .stream import (deck_commands, engine_error, random_drawn, skipped, snapshots, unchecked, unmapped_script,
                         written_then_read)
    if engine == "LAMMPS":
        from ..engines.lammps import deck_run
    else:
        from ..engines.liggghts import deck_run
    if not deck_run.available():
        raise DeckError("engine", engine, deck_run.INSTALL)
    with tempfile.TemporaryDirectory(prefix="restitution-deck-") as tmp:
        root = Path(tmp)
        scratch = scratch_copy(path, root, deck_run.marker(root), confined=confining())
        if not any(key.split()[0] in ("pair_style", "if", "read_restart") for key in scratch.lines):
            raise DeckError("pair_style", None, "the deck has no pair_style granular (LAMMPS) or pair_style gran "
                                                "(LIGGGHTS) line")
        done, commands = _engine_pass(deck_run, scratch, budget, path.resolve().parent)
        clocked = None if done.error or done.timed_out else _clocked_pass(deck_run, scratch, commands, budget,
                                                                          path.resolve().parent)
        if clocked is not None:
            done, commands = clocked
        for loc, text in unchecked(commands, scratch):
            if text.split()[0] in ("include", "jump") and "$" in text.split()[1]:
                raise DeckError(place(loc), text, "the file it reads is named by a variable, and this system does not "
                                                  "let the audit run the engine where it sees the deck's folder only "
                                                  "(no user namespaces): it did not run it; name the file as written")
            if text.split()[0] in ("include", "jump"):
                raise DeckError(place(loc), text, "the file it reads lies outside the deck's folder, which the audit "
                                                  "copies and checks first (no shell, python or file output): it did "
                                                  "not run it; copy the file beside the deck")
            if text.split()[0] == "timer":
                raise DeckError(place(loc), text, "a timeout of no time ends every run after it at its first check, "
                                                  "before it makes its steps (LAMMPS measured), which the engine's pass, "
                                                  "its runs skipped, does not show: not audited")
            raise DeckError(place(loc), text, "the command's name comes from a variable: the audit runs only what it "
                                              "can check first (no shell, python or file output), and did not run it")
        if (hit := written_then_read(commands, scratch)) is not None:
            (wrote, writer), (read, reader), aliased = hit
            if aliased:
                raise DeckError(place(read), reader, f"it reads, under another name of the same file (a link or a hard "
                                                     f"link), a file that {place(wrote)} ({writer}) removes or writes: "
                                                     "the audit's copy holds the two names apart, so it would not read "
                                                     "what the engine reads; not audited (name the file as written)")
            if writer.split()[:2] == ["shell", "mv"]:
                raise DeckError(place(read), reader, f"it runs a file that {place(wrote)} ({writer}) names: the engine "
                                                     "runs its commands, but the audit knows a file's commands by the "
                                                     "files the deck's folder held when it copied it, so it would not "
                                                     "see them; not audited (include the file by its own name)")
            raise DeckError(place(read), reader, f"it reads a file that {place(wrote)} ({writer}) names, which the "
                                                 "audit does not run (it may run code or write files): the file read "
                                                 "may not be the one the engine run by hand reads; not audited")
        if (hit := unmapped_script(commands, scratch)) is not None:
            raise DeckError(place(hit[0]), hit[1], f"a script the deck runs holds more than {MAX_TEXT_BYTES >> 20} MB "
                                                   "or a NUL byte (binary), or is a link to such a file: not what the "
                                                   "audit maps line by line; not audited")
        atoms = snapshots(done.atoms) + snapshots(done.at_end)
        if done.timed_out and not atoms:
            # no run and no end reached (a loop without a run): nothing to audit, and "no particle"
            # would be a guess; said before the echo is read any further
            cause = ("a loop that never reaches a run" if done.looped else
                     "a pass that ran no line twice, so no loop: a command that takes longer than the ceiling")
            raise DeckError("deck", None, f"{engine} had not reached a run or the deck's end within the audit's "
                                          f"budget ({done.spent}; runs skipped): {cause} (--budget SECONDS allows "
                                          "more time); not audited")

        parted = {scratch.stages[k][:2]: key for k, (key, _) in scratch.parts.items()}
        if parted and (hit := read_in_run(commands, _source(commands, scratch), set(parted))) is not None:
            loc, text = hit
            raise DeckError(place(loc), parted[loc], _read_in_run(engine, text))

        def read_file(name: str) -> str:
            return (scratch.deck.parent / name).read_text(encoding="utf-8", errors="replace")
        restarts = _restart_infos(root) if scratch.restarts else None
        made = None
        if done.error and (found := _run_dependent(commands, scratch)):
            # the engine stopped after reading what the skipped runs change (a loop on the step or
            # time that never ends in that pass, a value stepped out of its range): the deck run by
            # hand may not stop; the runs made for real tell (a loop ends as the engine ends it)
            made = _made_runs(deck_run, scratch, commands, found, run_budget, path.resolve().parent, done.looped)
        if done.error and (made is None or made[0] is None):
            where, line, message = engine_error(done.error + "\n" + done.echo[-4000:], scratch, done.status)
            if commands:     # echoed before it runs: the last command echoed is the one the engine stopped on
                # (as the deck wrote it, not as the copy guards a set)
                # (an unclosed quote holds the copy's tag comment: not the deck's)
                where, line = place(commands[-1].loc), _untagged(_unguarded(commands[-1].text))
            if _marker_stopped(done.echo, root):
                # the atoms have no radius to write (an atom style without one): the deck's own
                # refusal where it has one (its pair style, say), else this
                try:
                    read_executed(deck_commands(commands, scratch), atoms or [{}], radius, density, read_file, restarts)
                except DeckError as why:
                    if "has no pair_style" not in str(why):
                        raise
                message = (f"{message}: the audit's dump of each type's radius and mass at this run; its atoms have "
                           "no radius (not spheres)")
            named = line.split()[1:2] if line and line.split()[0] in ("include", "jump") else []
            if named and Path(named[0].strip("\"'")).name in scratch.left_out:
                message += (": the deck's folder holds it as a pipe, a device or a link to one, which the audit "
                            "does not copy (its read may never end); not audited")
            elif named and confining() and _outside_folder(
                    named[0].strip("\"'"), scratch.deck.parent, path.resolve().parent):
                message += (": the engine sees the deck's folder only (a copy of it, made safe), so a file outside "
                            "the deck's folder is not run; copy it beside the deck")
            if commands and commands[-1].stage is None and commands[-1].loc in parted:
                # a command a run's every runs, which the copy runs between runs of its own: the
                # engine evaluates it inside its run, where what stopped the copy may be defined
                # (field round 34, E05: elapsed, before read_in_run foresaw it)
                raise DeckError(where, parted[commands[-1].loc], _read_in_run(engine, line, message))
            # where the runs were not made (made[1]: the commands of a pass that made them and stopped
            # too), what the pass read after a run decided where it went, and its stop is its own
            unmade = found if made is None or made[1] is None else []
            said = made[2:] if made else (["--run-budget 0 makes no run for real (a budget in seconds lets the "
                                           "engine make them)"] if unmade else [])
            raise DeckError(where, line or None, "; ".join([_stopped(engine, message, commands, unmade), *said]))
        stop_note = None
        if made is None:
            read = deck_commands(commands, scratch)
            # a timer timeout the audit does not run may end a deck's run early, where the runs
            # made for real make every step (round 24, R34: a later upto legal in LAMMPS failed)
            timed = any(_timeout(entry[2]) for entry in scratch.skipped if entry[0] == "timer")
            try:
                deck, refusal = read_executed(read, atoms, radius, density, read_file, restarts, timed=timed), None
            except DeckError as why:
                if by_position(read) is None:
                    raise
                deck, refusal = None, why       # the runs made for real may answer it
            found = _run_dependent(commands, scratch, clocked is not None)
            resized = resized_by_runs(commands) + lost_in_runs(commands)
            needs = _run_causes(found, by_position(read), deck) + resized
            stops = stops_in_runs(commands)
            causes = sorted(needs + stops, key=lambda c: (str(c[0][0] or ""), c[0][1] or 0))
            made = _made_runs(deck_run, scratch, commands, causes, run_budget, path.resolve().parent,
                              done.timed_out and done.looped) if causes else None
            if stops and not needs and made is None and run_budget <= 0:
                stop_note = (f"{place(stops[0][0])} {stops[0][1]}: with --run-budget 0 {engine} was not run to "
                             "see whether it does, so the stages after it hold only if it does")
            if made is not None and made[0] is None and made[1] and _STOPPED in made[2] \
                    and ("ERROR" in made[2] and not timed or "fix halt" in made[2]):
                # the engine stopped in a run made as the deck makes it (field round 23, r22: "Lost
                # atoms" in the first run; R11, R12: a fix halt): the stages after it never happen
                last = next((cmd for cmd in reversed(made[1]) if cmd.stage is not None), made[1][-1])
                error = made[2].split(_STOPPED, 1)[-1].rsplit(": its runs", 1)[0].split(" Last input line:")[0]
                raise DeckError(place(last.loc), last.text,
                                f"{engine} stops in this run, made for real as the deck makes it: {error}; the "
                                "stages after it are not the deck's: not audited")
            if made is not None and not needs and (engine == "LAMMPS" or made[0] is None or not fixed_face(commands)):
                # the runs were made only to see whether LAMMPS ends each of them (it stops where a
                # sphere leaves a fixed face or a fix halt is met, which the pass cannot show): it
                # does, and the pass stands as it is; LIGGGHTS, which drops a sphere lost through a
                # fixed face and goes on, is read from its runs (L37). Where they could not be made,
                # that is said.
                unchecked = made[0] is None
                made = None
                if unchecked:
                    stop_note = (f"{place(stops[0][0])} {stops[0][1]}: {engine} was not seen to (the audit's "
                                 "limits on runs made for real, or a timer the audit does not run, which may end "
                                 "a run early: round 24, R34), so the stages after it hold only if it does")
        if made is not None and made[0] is not None:
            done, commands, said = made
            atoms = snapshots(done.atoms) + snapshots(done.at_end)
            restarts = _restart_infos(root) if scratch.restarts else None
            deck = read_executed(deck_commands(commands, scratch), atoms, radius, density, read_file, restarts,
                                 ran=True)
            notes = [said]
        else:
            said = [made[2]] if made is not None else []
            if refusal is not None:
                refusal.args = ("; ".join([refusal.args[0], *said]),)
                raise refusal
            notes = _run_dependent_notes(commands, scratch, engine, clocked is not None) + said + (
                [stop_note] if stop_note else [])
            if resized and not said:
                notes.append(f"after a run, {place(resized[0][0])} {resized[0][1]}: with the runs "
                             f"{'skipped' if engine == 'LAMMPS' else 'one step long'} the sizes and masses read "
                             "from here on are those before it, not the deck's")
            # the rows of these runs are marked, not only named on stderr
            deck.doubtful_runs = _runs_after(commands, found) | _runs_after(commands, resized)
        # the runs made for real draw as the runs go as the engine does; a command never run does not
        # (field round 21: r28 read right once its runs were made)
        if (drawn := random_drawn(commands, scratch, runs_draw=not deck.ran)) is not None:
            raise DeckError(place(drawn[0]), drawn[1], "it reads a variable drawn from random() or normal(), whose "
                                                       "every evaluation draws, after the engine run by hand has drawn "
                                                       "from it where the audit's pass does not (its thermo output or "
                                                       "a fix as the runs go, a print or shell line the audit does not "
                                                       "run): the value read here is not the pass's; not audited")
        _hold_charges(deck, commands, deck_run.charges(root) if hasattr(deck_run, "charges") else None)
        # a loop the pass did not finish (nor the runs made for real) may end in the engine, which then
        # runs what follows it (field round 18, b40: 10 000 passes filled the echo's cap, and the
        # production run's new stiffness after the loop was never seen: its 1 2 was printed as the
        # settling run's)
        unseen = _unseen_after(commands, path.resolve()) if done.timed_out else None
    notes += [f"{cmd} ({place(loc)} and any like it): not executed, "
              + ("as the audit runs the engine on one process; it has no part in a contact" if cmd == "processors" else
                 "as the engine runs as partition 1 of 1, which it leaves out" if cmd == "partition no 1" else
                 "as it may run code or write files; it may add forces to its atoms, which the eps printed do not "
                 "include" if cmd.startswith("fix ") and cmd.split()[1].startswith(PUSHING_FIX_PREFIXES) else
                 "as it times the runs; the audit takes each run to make all its steps" if cmd == "timer" else
                 "as it may run code or write files; it has no part in a contact")
              # never run, never checked: a deck LAMMPS stops at such a line (a file it cannot open, a
              # bad argument: field round 23, Q01-Q16) is audited as if it ran past it
              + ("; nor is it checked: where the engine stops on it, the runs after it do not happen"
                 if cmd not in ("processors", "partition no 1") else "")
              for cmd, loc in skipped(commands, scratch).items()]
    if (lost := _lost_not_stopping(commands, engine)) is not None:
        notes.append(lost)
    reached = {cmd.stage for cmd in commands if cmd.stage is not None}
    notes += [f"{place(scratch.stages[k][:2])} ({run}): " + (
        f"made as its {count} parts, the commands its every names run after each, as {engine} makes it; each "
        f"part a run of its own here, with the contact those commands leave (passes 1 to {count} of the line)"
        if count > 1 else f"the commands its every names run after it, as {engine} runs them: the runs after "
                          "it see the contact they leave")
        for k, (run, count) in scratch.parts.items() if k in reached]
    notes += _override_notes(atoms, radius or {}, density or {}, deck.ntypes)
    if unseen is not None:
        loc, text = unseen
        runs = "runs skipped" if engine == "LAMMPS" else "runs of one step"
        raise DeckError(place(loc), text, f"{engine} had not ended the deck within the audit's limits ({done.spent}; "
                                          f"{runs}): the engine reaches this line once the loop before it ends, "
                                          "and it may change a contact, so the contacts read so far may not be the "
                                          "deck's; not audited (--budget SECONDS allows more time and echo)")
    if done.timed_out:
        last = deck.stages[-1][0] if deck.stages else []
        runs = "its runs are skipped" if engine == "LAMMPS" else "its runs are of one step"
        cause = (f"{runs}, so a loop waiting for a value a run would change never ends" if done.looped else
                 "it had run no line twice, so no loop: a command that takes longer than the ceiling")
        notes.append(f"{engine} had not ended the deck within the audit's budget ({done.spent}; {cause}; "
                     "--budget SECONDS allows more time): audited as far as it ran, "
                     f"{len(commands)} commands" + (f"; its last {len(last)} runs all saw the same contact settings"
                                                    if len(last) > 1 else ""))
    return deck, notes


#: Commands that may change the charges atoms hold, or which atoms there are: after a run, the
#: charges the engine holds at the deck's end are not every run's
_CHARGING = re.compile(r"(set\s.*\bcharge\b|fix\s+\S+\s+\S+\s+adapt\s.*\bcharge\b|delete_atoms|read_data|"
                       r"read_restart|fix\s+\S+\s+\S+\s+(evaporate|pour|deposit))")


def _hold_charges(deck: Deck, commands: list, charges: dict | None) -> None:
    """Give the deck and each of its stages the charges its engine held at the deck's end
    (``charges``, :func:`restitution.dem.engines.lammps.deck_run.charges`) where they are every
    run's: no command after the first run changes a charge or the atoms held (then, and where the
    engine gives none, they stay unknown: fix efield is named wherever it may act)."""
    first = next((k for k, cmd in enumerate(commands) if cmd.stage is not None), len(commands))
    if charges is None or any(_CHARGING.match((_unguarded(cmd.text) or "").strip()) for cmd in commands[first:]):
        return
    for held in [deck] + [snap for _, snap, _ in deck.stages]:
        held.charges = charges


def _restart_infos(root: Path) -> list:
    """What the engine held after each read_restart it ran, in order: the blocks its markers' info
    appended (:data:`restitution.dem.dialect.child.RESTART_INFO`)."""
    from ..dialect.child import RESTART_INFO
    try:
        text = (root / RESTART_INFO).read_text(encoding="utf-8", errors="replace")
    except OSError:
        return []
    fence = "Info-Info-Info-Info-Info-Info-Info-Info-Info-Info-Info"
    return [block for block in text.split(fence)[1::2]]


#: What an engine's error says where the confinement, not the deck, stopped it: a write into a
#: folder the view binds read-only (the system's), or a stand-in full (sandbox._STAND_IN)
_CONFINED = ("Read-only file system", "No space left on device")
#: What an engine's error says where what it read may be what the runs before would have made: a
#: formula's value out of its domain (a count of atoms, an energy, 0), or no atom to act on (not a
#: variable that does not exist, which the deck run by hand meets too)
_RUN_STATE = re.compile(r"Divide by 0|Modulo 0|Sqrt of negative|Log of zero|Power by 0|no atoms|without atoms|"
                        r"atoms existing|"
                        # field round 28: a restart file a run writes (C03, R43), a crash on a value
                        # the runs set (V23: a density 0 from the step), the atoms a run moves
                        # out of a region deleted (L06): the engine runs each of these decks
                        r"Cannot open restart file|ended without an error message|Atom types must start from 1")
#: The fixes that make atoms as a run goes, which a pass whose runs are skipped never makes
_INSERTING = re.compile(r"fix\s+\S+\s+\S+\s+(pour|deposit|insert/\S+)\b")


def _read_in_run(engine: str, command: str, stop: str | None = None) -> str:
    """The refusal of a command a run's every runs between its parts that reads, or may read, what
    the engine gives only inside a run (a ramp, a wiggle, the steps elapsed, a compute's value),
    which the copy runs between runs of its own; ``stop``: the engine's message where the copy
    stopped on it.

    Examples
    --------
    >>> _read_in_run("LAMMPS", "pair_coeff * * hooke ${k} 0")[:60]
    'run ... every runs pair_coeff * * hooke ${k} 0 between the r'
    >>> "(LAMMPS stops on it there: x)" in _read_in_run("LAMMPS", "set type 1 density ${d}", "x")
    True
    """
    there = f" ({engine} stops on it there: {stop})" if stop else ""
    return (f"run ... every runs {command} between the run's parts, which reads a value {engine} gives only inside "
            f"a run (a ramp, a wiggle, the steps elapsed, a compute's), and the audit runs it between runs of its "
            f"own copy, where that value is another{there}: not audited; split the run into runs with the commands "
            "between them, each reading what a run leaves")


def _untagged(text: str) -> str:
    """``text`` without the copy's tag comments, which LIGGGHTS repeats in its "Unknown command" and
    an unclosed quote keeps inside the line."""
    return re.sub(r"\s*#restitution-[0-9a-f]+@\S*", "", text)


def _stopped(engine: str, message: str, commands: list, read: list = ()) -> str:
    """The reason a deck is refused where its engine stopped in the audit's pass, said truly: the
    engine's own stop, the audit's confinement, or the pass's runs (skipped by LAMMPS, cut to one
    step by LIGGGHTS), after which what the engine holds is not what the deck's own runs make.
    ``read``: the commands after a run that read before the stop a value the runs change
    (:func:`_run_dependent`), where the runs were not made for real: the branches the pass took
    from the first of them on are its own, not the deck's, so its stop says nothing of the deck's
    (field round 13: a loop of pours until a count, exhausted in the pass alone, stopped it on a
    loop variable LAMMPS run by hand has defined; "LAMMPS stops here" said it was the deck's).

    Examples
    --------
    >>> from restitution.dem.deck.stream import Executed
    >>> _stopped("LAMMPS", "Unknown command: pair_coef", [])
    'LAMMPS stops here: Unknown command: pair_coef'
    >>> print(_stopped("LAMMPS", "Variable m: Divide by 0 in variable formula",
    ...                [Executed((None, 3), "fix p all pour 10 1 5 region r"), Executed((None, 4), "run 10", 0)]))
    LAMMPS stopped here in the audit's pass, in which the runs before are skipped, so it holds none of the atoms the inserting fixes make in them (fix p), nor anything else the runs change: Variable m: Divide by 0 in variable formula; the deck run by hand may not stop here, but what it reads here depends on its runs, which the audit does not make: not audited
    >>> print(_stopped("LAMMPS", "Invalid variable reference v_c in variable formula",
    ...                [Executed((None, 4), "run 10", 0), Executed((None, 5), 'if "$(count(all)) > 9" then "jump SELF d"'),
    ...                 Executed((None, 8), "set type 1 diameter $(v_c)")],
    ...                [((None, 5), 'if "$(count(all)) > 9" then "jump SELF d"')]))
    LAMMPS stopped here in the audit's pass, in which the runs before are skipped, so it holds not what they make of the atoms, the step and the values computed from them, and line 5 (if "$(count(all)) > 9" then "jump SELF d") read such a value before this, which decided the branches and values from there on: Invalid variable reference v_c in variable formula; the deck run by hand may not stop here, but what it reads here depends on its runs, which the audit does not make: not audited
    """
    message = _untagged(message)
    if any(cause in message for cause in _CONFINED):
        return (f"{engine}, run by the audit where it may write only in its copy of the deck's folder and a stand-in "
                f"of the folders outside it, stopped here: {message}; the deck run by hand may not stop here: "
                "not audited")
    runs = [k for k, cmd in enumerate(commands) if cmd.stage is not None]
    # the command it stopped on, where it read such a value itself, is "here" already
    before = [(loc, text) for loc, text in read if not commands or loc != commands[-1].loc]
    if not runs or not (before or _RUN_STATE.search(message)):
        return f"{engine} stops here: {message}"
    inserting = sorted({m.group(0).split()[1] for cmd in commands[:runs[-1]] if (m := _INSERTING.match(cmd.text))})
    cut = "skipped" if engine == "LAMMPS" else "cut to one step"
    held = (f"none of the atoms the inserting fixes make in them ({', '.join(f'fix {i}' for i in inserting)}), nor "
            "anything else the runs change" if inserting else
            "not what they make of the atoms, the step and the values computed from them")
    if before:
        loc, text = before[0]
        held += (f", and {place(loc)} ({' '.join(text.split())}) read such a value before this, which decided the "
                 "branches and values from there on")
    return (f"{engine} stopped here in the audit's pass, in which the runs before are {cut}, so it holds {held}: "
            f"{message}; the deck run by hand may not stop here, but what it reads here depends on its runs, which "
            "the audit does not make: not audited")


def _unguarded(text: str | None) -> str | None:
    """A copied line as the deck wrote it where the copy guards its set (scratch.UNSET): the guard's
    count of atoms is the audit's, not the deck's."""
    from .scratch import UNSET
    if text is None or UNSET not in text:
        return text
    guarded = re.search(r'then "((?:set|velocity) [^"]*)" else', text)
    return guarded.group(1) if guarded else text


def _run_dependent_notes(commands: list, scratch, engine: str, clocked: bool = False) -> list:
    """A line for the commands after a run that read a value the skipped runs would have changed
    (:func:`restitution.dem.deck.runtime.run_dependent`), read in the deck's own text; ``clocked``:
    the pass set the step and time after each run to the deck's (:func:`_clocked_pass`)."""
    found = _run_dependent(commands, scratch, clocked)
    said = (["after each run the audit's pass set LAMMPS' step and time to those the deck's run reaches "
             "(reset_timestep), so the values read from them are the deck's"] if clocked else [])
    if not found:
        return said
    runs = "skipped" if engine == "LAMMPS" else "one step long"
    shown = "; ".join(f"{place(loc)} {text.strip()}" for loc, text in found[:3])
    more = f" and {len(found) - 3} more" if len(found) > 3 else ""
    changed = "energies, positions, computes" if clocked else "time, step, energies, positions, computes"
    return said + [f"after a run, {shown}{more}: reads a value the runs change ({changed}); with the runs {runs} "
                   "it reads the value before them, so the branches taken and the values set from here on, and the "
                   "stages audited after it, may not be those the deck runs"]


def _lost_not_stopping(commands: list, engine: str) -> str | None:
    """The note where a run goes on losing atoms: ``thermo_modify lost ignore`` (or ``warn``) in force
    at a run the engine reached (a thermo_style makes a new thermo, whose lost is error again). The
    engine then drops an atom it loses and goes on (field round 26, N15, N12: a 0.5 m sphere in a
    4 cm periodic box made LAMMPS lose the others at its run's first step, whose pairs were printed
    with no word); the audit sees the atoms a run leaves only where it made the runs for real, so
    the note says so, with the line.

    Examples
    --------
    >>> from restitution.dem.deck.stream import Executed
    >>> cmds = [Executed((None, 3), "thermo_modify lost ignore flush yes"), Executed((None, 4), "run 10", stage=0)]
    >>> _lost_not_stopping(cmds, "LAMMPS")[:40]
    'line 3 (thermo_modify lost ignore flush '
    >>> _lost_not_stopping([cmds[0], Executed((None, 4), "thermo_style one"), cmds[1]], "LAMMPS") is None
    True
    """
    setting = None
    for cmd in commands:
        words = cmd.text.split()
        if words[:1] == ["thermo_style"]:
            setting = None
        elif words[:1] == ["thermo_modify"] and "lost" in words[1:-1]:
            value = words[words.index("lost", 1) + 1]
            setting = None if value == "error" else (cmd.loc, cmd.text)
        elif cmd.stage is not None and setting is not None:
            loc, text = setting
            return (f"{place(loc)} ({text}): {engine} drops an atom it loses in a run and goes on; the audit sees "
                    "which atoms a run leaves only where it makes the runs for real, never in the last: a pair "
                    "whose spheres the engine loses is printed as if it met")
    return None


def _run_causes(found: list, picked: tuple | None, deck: Deck | None) -> list:
    """((file, line), text) of what makes a pass with runs skipped read something else than the
    deck's runs do: the commands after a run that read a value the runs change (``found``), the
    first that picks atoms by where a run left them (``picked``), and the runs whose sizes include
    one only a pour not yet finished gives (``deck``'s stages' ``pending``), in the deck's order."""
    causes = list(found) + ([picked] if picked and picked not in found else [])
    for runs, snap, _ in deck.stages if deck is not None else ():
        # a type whose pours were all unfixed before the set keeps an empty entry: no size in doubt
        # (field round 13, a26: pour, unfix, set type 1 density: every atom the pour made is
        # resized, whether or not it had finished, and the runs were made for a false cause)
        if any(snap.pending.values()):
            causes.append((runs[0][0], f"{runs[0][1]}, whose sizes include a pour's own only if it has not "
                                       "finished"))
        # a set after a run resized atoms an inserting fix made in it, which the pass never held, in a
        # way the reader cannot follow (a deposit's, a group it cannot type): the runs made tell
        # (field round 18, D4: b25, b49 refused with "give --radius")
        elif snap.resized or any(fix is None for fix in snap.deposits.values()):
            causes.append((runs[0][0], f"{runs[0][1]}, whose sizes a set after an inserting run changed in atoms "
                                       "the pass never made"))
    return sorted(causes, key=lambda c: (str(c[0][0] or ""), c[0][1] or 0))


def _run_steps(commands: list) -> int | None:
    """The steps of all the runs the pass met (``run N``, ``minimize``'s iterations at most), None
    where one's length is not a number.

    A length is read as LIGGGHTS 3.8.0 reads it, by its leading digits (``run 38.16`` makes 38
    steps, ``run 1e1`` one: measured); LAMMPS stops on any other length, so it never gets here."""
    steps = 0
    for cmd in commands:
        if cmd.stage is None:
            continue
        split = cmd.text.split()
        n = re.match(r"\d+", split[1] if split[0] == "run" and len(split) > 1 else split[3] if len(split) > 3 else "")
        if n is None:
            return None
        steps += int(n.group())
    return steps


#: How the note of runs made for real that the engine stopped names the stop (read back by the caller)
_STOPPED = "making its runs for real stopped: "
#: LAMMPS' message where a fix halt with error soft meets its condition (22 Jul 2025)
_SOFT_HALT = re.compile(r"Fix halt condition for fix-id (\S+) met on step \d+")


def _timeout(timer: str) -> bool:
    """Whether a ``timer`` command sets a timeout that may end a run (any but ``off``).

    Examples
    --------
    >>> _timeout("timer timeout 0:00:01 every 100"), _timeout("timer timeout off"), _timeout("timer full")
    (True, False, False)
    """
    words = timer.split()
    return "timeout" in words[:-1] and words[words.index("timeout") + 1] != "off"


def _soft(commands: list, fix: str) -> bool:
    """Whether the last ``fix`` of ID ``fix`` among the commands run is a halt with error soft (not
    continue, whose message is the same and which goes on as if nothing happened: round 23, R18)."""
    style = None
    for cmd in commands:
        words = cmd.text.split()
        if words[:2] == ["fix", fix] and len(words) > 3:
            style = words[words.index("error") + 1] if words[3] == "halt" and "error" in words[:-1] else None
    return style == "soft"


def _made_runs(deck_run, scratch, commands: list, causes: list, budget: float, folder: Path, looped: bool = False):
    """The engine's pass through the scratch copy with the deck's runs made for real, where the
    pass with them skipped (``commands``) met the ``causes`` (:func:`_run_causes`): (EngineRun,
    commands, the note that says so), or (None, None, the note that says why it was not made: the
    budget ran out, the runs are longer than :data:`MAX_RUN_STEPS`), or (None, the commands it ran,
    the note) where the engine making them stopped too; None where
    ``budget`` is 0 or the engine cannot make them (``MAKES_RUNS`` of its ``deck_run``). ``looped``: the pass with
    runs skipped was ended in a loop (a settle loop waiting for a value only runs change), so its
    runs tell nothing of the deck's steps, and the wall time alone bounds the runs made.

    The deck's outputs are suppressed as in the first pass; each run's marker writes the atoms
    where the run left them, the atoms the run's pours made among them, so a set by position, a
    count after a pour or a step read afterwards are the engine's own."""
    from .scratch import NOOP, remark
    if budget <= 0 or not getattr(deck_run, "MAKES_RUNS", False):
        return None
    shown = "; ".join(f"{place(loc)} {text.strip()}" for loc, text in causes[:2]) + (
        f" and {len(causes) - 2} more" if len(causes) > 2 else "")
    what = (f"after a run, {shown}: what it reads or holds depends on where the runs before leave the atoms or "
            "on a value they change")
    cut = "skipped" if deck_run.ENGINE == "LAMMPS" else "one step long"
    steps = None if looped else _run_steps(commands)
    if not looped and (steps is None or steps > MAX_RUN_STEPS):
        many = "runs whose length is not a number" if steps is None else f"{steps} steps"
        return None, None, (f"{what}; the audit makes at most {MAX_RUN_STEPS} steps for real and the deck has {many}: "
                            f"its runs {cut}, as said")
    remark(scratch, deck_run.marker(scratch.root, real=True))
    try:
        done = deck_run.run_copy(scratch.deck, scratch.root, budget, original=folder, check_every=True,
                                 tag=scratch.tag, ceiling=budget, real=True)
    finally:
        remark(scratch, deck_run.marker(scratch.root))
    made = _read(done, scratch)
    runs = sum(1 for cmd in made if cmd.stage is not None)
    steps = _run_steps(made)
    if done.timed_out:
        return None, None, (f"{what}; {deck_run.ENGINE} making its runs for real ran out of "
                            f"the audit's --run-budget {budget:g} s ({done.spent}); --run-budget SECONDS allows more: "
                            f"its runs {cut}, as said")
    if done.error and _crashed(done):
        # the engine crashes on the deck run by hand too (field round 14, L15: LIGGGHTS 3.8.0 on fix
        # adapt ... scale yes, rc 139): the one-step pass's sizes are its bug's, not the deck's
        last = next((cmd for cmd in reversed(made) if cmd.stage is not None), None)
        raise DeckError(place(last.loc) if last else "deck", last.text if last else None,
                        f"{deck_run.ENGINE} crashed making the deck's runs for real ({_crash_words(done)}); those "
                        "runs are the deck's own, its outputs aside, so the deck does not run in this engine: "
                        "not audited")
    halted = _SOFT_HALT.search(done.echo or "")
    after = done.echo[halted.end():] if halted else ""
    # a clear after it makes a new timer (round 24, H19: a new simulation that LAMMPS runs)
    cleared = re.search(r"^\s*clear\b", after, re.M)
    after = after[:cleared.start()] if cleared else after
    if not done.error and halted and _soft(made, halted.group(1)) and re.search(r"^\s*(run|rerun)\b", after, re.M) \
            and not any(entry[0] == "timer" and "timeout" in entry[2].split()
                        and re.search(re.escape(NOOP.format(k)) + r"\b", after) for k, entry in enumerate(scratch.skipped)):
        # a soft halt met: LAMMPS forces its timer out, and every run after it makes no step until
        # a timer timeout resets it (field round 23, R12, R17: the later runs' settings never
        # acted); a deck whose timer timeout comes after it (never run by the pass, R16) is left as
        # it was; any other timer command resets nothing (round 24, H02, H03, H08)
        return None, made, (f"{what}; {deck_run.ENGINE} {_STOPPED}{halted.group(0)} (fix halt, error soft): "
                            f"it makes no step in any run after it: its runs {cut}, as said")
    if done.error:
        return None, made, (f"{what}; {deck_run.ENGINE} {_STOPPED}"
                            f"{' '.join(done.error.split())[:300]}: its runs {cut}, as said")
    return done, made, (
        f"{what}: {deck_run.ENGINE} made the deck's {runs} runs ({steps if steps is not None else 'their'} steps) for real, in {done.wall:.2g} s of the "
        f"--run-budget {budget:g} s, its outputs not written: the atoms, sizes, types, branches and values audited "
        "are those its runs reach")


#: What an engine's error output says where a signal, not the engine's own check, ended it
_SIGNALLED = re.compile(r"Process received signal|Segmentation fault|Bus error|Floating point exception|Aborted")


def _crashed(done) -> bool:
    """Whether a pass the budget did not stop ended on a signal (a crash), not on the engine's own
    ERROR message: an exit status beyond 128 or negative, or the MPI library's report of a signal."""
    status = done.status or 0
    return not done.timed_out and (status < 0 or status > 128 or bool(_SIGNALLED.search(done.error or "")))


def _crash_words(done) -> str:
    """A crash in a few words: the signal's name where the error output gives it, else the status."""
    m = re.search(r"Signal: ([A-Za-z ]+?) \(\d+\)", done.error or "") or _SIGNALLED.search(done.error or "")
    return (m.group(1) if m.lastindex else m.group(0)) if m else f"exit status {done.status}"


def _runs_after(commands: list, found: list) -> set:
    """The (file, line) of the runs the engine reached after the first of ``found`` (commands that
    read a value the skipped runs would have changed)."""
    if not found:
        return set()
    first = next((k for k, cmd in enumerate(commands) if cmd.loc == found[0][0]), len(commands))
    return {cmd.loc for cmd in commands[first:] if cmd.stage is not None}


def _clocked_pass(deck_run, scratch, commands: list, budget: float, folder: Path):
    """(EngineRun, commands) of a LAMMPS pass made again with its step and time set after each
    skipped run to those the deck's run reaches (``marker(root, clock=True)``), where the first pass
    (``commands``) read them after a run and every run is a ``run N`` of a literal N; else None.
    LAMMPS refuses to set the step where a time-dependent fix (a pour) is defined: that pass stops,
    and the first one stands (None), as where the deck reads a restart (its record is the pass's)."""
    from .scratch import remark
    clockable = getattr(deck_run, "clockable", None)
    if clockable is None or scratch.restarts or not clockable([key for _, _, key in scratch.stages]):
        return None
    found = _run_dependent(commands, scratch)
    if not found or len(_run_dependent(commands, scratch, clocked=True)) == len(found):
        return None
    remark(scratch, deck_run.marker(scratch.root, clock=True))
    done, again = _engine_pass(deck_run, scratch, budget, folder)
    remark(scratch, deck_run.marker(scratch.root))
    if done.error or done.timed_out:
        return None
    return done, again


#: Commands that change no contact when the engine runs them after a loop the audit's pass did not
#: finish: output, loop control, variables, computes and runs themselves (a jump to another file may
#: hold anything, so only ``jump SELF`` counts)
_NO_CONTACT = frozenset({"run", "print", "thermo", "thermo_style", "thermo_modify", "dump", "dump_modify", "undump",
                         "write_restart", "write_data", "write_dump", "write_coeff", "log", "restart", "next", "label",
                         "variable", "compute", "uncompute", "compute_modify", "info", "echo", "timer", "quit"})


def _unseen_after(commands: list, deck: Path) -> tuple | None:
    """The first command of the deck's files after the furthest line the engine's pass ran in each,
    that may change a contact ((loc, text)), or None where every such line only prints, loops or
    runs: where a pass ended early, what the engine would run after the loop. The files are read as
    the user wrote them (the scratch copy's runs are the audit's includes)."""
    from ..deck_text import logical_lines
    furthest: dict = {}
    for cmd in commands:
        if isinstance(cmd.loc, tuple) and len(cmd.loc) == 2 and cmd.loc[1]:
            furthest[cmd.loc[0]] = max(furthest.get(cmd.loc[0], 0), cmd.loc[1])
    for name, last in sorted(furthest.items(), key=lambda item: (item[0] is not None, str(item[0]))):
        try:
            text = (deck if name is None else deck.parent / name).read_text(encoding="utf-8", errors="replace")
        except OSError:
            continue
        for n, line in logical_lines(text):
            if n <= last or not line or not line.split():
                continue
            words = line.split()
            if words[0] in _NO_CONTACT or words[0] == "jump" and words[1:2] == ["SELF"]:
                continue
            return (name, n), line
    return None


def _run_dependent(commands: list, scratch, clocked: bool = False) -> list:
    """The commands after a run that read a value the skipped runs would have changed
    (:func:`restitution.dem.deck.runtime.run_dependent`), read in the deck's own text."""
    from .runtime import run_dependent
    return run_dependent(commands, _source(commands, scratch), clocked)


def _source(commands: list, scratch) -> dict:
    """(file, line) -> the deck's own text of each line the engine ran (a run the copy made as its
    parts: the run as written, which holds the commands its every runs)."""
    from ..deck_text import logical_lines
    commands_at: dict = {}

    def at(name, folder=None) -> dict:
        """{first physical line: command} of a copied file (of the deck's own, from ``folder``), read once."""
        if (name, folder) not in commands_at:
            path = scratch.deck if name is None else scratch.deck.parent / name
            try:
                text = (path if folder is None else folder / path.relative_to(scratch.deck.parent)).read_text(
                    encoding="utf-8", errors="replace")
            except (OSError, ValueError):
                text = ""
            commands_at[(name, folder)] = dict(logical_lines(text))
        return commands_at[(name, folder)]
    source = {loc: _unguarded(at(loc[0]).get(loc[1])) for loc in {cmd.loc for cmd in commands}
              if isinstance(loc, tuple) and len(loc) == 2 and loc[1]}
    for loc, text in source.items():
        if text and text.startswith("include ") and str(scratch.root) in text:
            # a run made as its parts (scratch.split_every): the copy's line includes them, the
            # deck's own holds the commands its every runs, which run_dependent reads
            written = at(loc[0], scratch.origin).get(loc[1])
            source[loc] = written if written and written.split()[:1] == ["run"] else text
    return {loc: text for loc, text in source.items() if text}


def _engine_pass(deck_run, scratch, budget: float, folder: Path) -> tuple:
    """(EngineRun, list of Executed): the engine's pass through the scratch copy within ``budget``
    seconds in a loop and :data:`~restitution.dem.dialect.child.CEILING` times that in all. LAMMPS' markers check and dump a run met again (a loop) only where something in between
    may have changed what it checks or sees; where the echo shows such a change, the deck runs again,
    every run checked, within what is left of the budget (a budget spent by then: the first pass,
    read up to that run)."""
    from ..dialect.child import CEILING
    from .stream import first_unchecked
    ceiling = CEILING * budget
    done = deck_run.run_copy(scratch.deck, scratch.root, budget, original=folder, tag=scratch.tag, ceiling=ceiling)
    if done.timed_out and not done.atoms.strip() and not done.at_end.strip():
        return done, []       # no run and no end reached: refused, the echo never read
    commands = _read(done, scratch)
    n = first_unchecked(commands, scratch)
    if n is not None:
        # the second pass has what the first left: of the loop's budget, and of the ceiling
        left, left_in_all = budget - done.loop_time, ceiling - done.wall
        if done.timed_out or left <= 0 or left_in_all <= 0:
            del commands[n:]
            done.timed_out = True
            done.spent = done.spent or (f"{budget:g} s of wall time in a loop" if left <= 0 else
                                        f"{ceiling:g} s of wall time in all, the ceiling")
        else:
            done = deck_run.run_copy(scratch.deck, scratch.root, left, original=folder, check_every=True,
                                     tag=scratch.tag, ceiling=left_in_all)
            commands = _read(done, scratch)
    return done, commands


def _read(done, scratch) -> list:
    """The commands of an engine's pass (:func:`restitution.dem.deck.stream.executed`); where the
    budget stopped it at a run's marker before its dump, without that run (whether it was to write
    the atoms is unknown)."""
    from .stream import executed
    commands = executed(done.echo, scratch)
    if done.timed_out and commands and commands[-1].snapshot is False:
        commands.pop()
    return commands


def _override_notes(atoms: list, radius: dict, density: dict, ntypes: int) -> list:
    """A line for each --radius or --density that replaces what a type's particles hold: the flags
    complete walls-only types, so replacing a held size must never pass unsaid; nor one for a type
    the deck does not have (of its ``ntypes``), which sizes nothing."""
    notes = []
    for flag, given, k in (("--radius", radius, 0), ("--density", density, 1)):
        for t, value in sorted(given.items()):
            if int(t) > ntypes:
                notes.append(f"type {t}: {flag} {value:g} names no atom type of the deck (it has {ntypes}): "
                             "not used")
                continue
            held = sorted({size[k] for snap in atoms for size in snap.get(int(t), ()) if size[k] is not None})
            if held and held != [value]:
                what = f"{held[0]:.6g}" if len(held) == 1 else f"{held[0]:.6g} to {held[-1]:.6g}"
                notes.append(f"type {t}: {flag} {value:g} replaces the {what} its particles hold in the deck")
    return notes


def _outside_folder(name: str, copy: Path, folder: Path) -> bool:
    """Whether the file ``name`` the engine was to read (from the copy ``copy`` of the deck's
    folder ``folder``) lies outside that folder."""
    where = Path(os.path.normpath(copy / name))
    return not any(where == base or base in where.parents for base in (copy, folder))


def _marker_stopped(echo: str, root: Path) -> bool:
    """Whether the engine stopped on a run marker's own dump of the atoms (written to ``root``)."""
    before = echo.split("\nERROR", 1)[0].rstrip().rsplit("\n", 1)[-1]
    return before.startswith(f"write_dump all custom {root}")


def audit_deck(text: str, speeds, radius: dict | None = None, density: dict | None = None, read_file=None, *,
               path=None, budget: float = BUDGET, run_budget: float = RUN_BUDGET) -> dict:
    """The eps an input deck really gives, for every type pair and flat wall, at every run.

    Parameters
    ----------
    text : str
        The input script.
    speeds : sequence of float
        Impact speeds, in the deck's own units (m/s for units si, cm/s for cgs: the result's
        ``speed_unit``), as every length, mass and time the deck holds.
    radius, density : dict, optional
        {type: value}, overriding or completing what the engine holds, in the deck's units.
    read_file : callable, optional
        Unused: the engine opens the files the deck names itself, in its scratch copy (kept for
        callers that pass it).
    path : path-like, optional
        The deck's file, whose folder the engine sees (a copy of it); None: the text alone.
    budget : float, optional
        Wall time in seconds the engine's pass may take (within :data:`BUDGET_RANGE`): it ends a
        loop that never reaches a run.
    run_budget : float, optional
        Wall time in seconds (within :data:`RUN_BUDGET_RANGE`) the engine may spend making the
        deck's runs for real where its pass with them skipped met a command that reads what they
        change (a set by position, a count after a pour, the step): the audit is then of the state
        the runs reach, and a note says so; 0, or a budget that runs out, keeps the pass with runs
        skipped (such a set refused, such a stage's rows marked ``may_differ``).

    Returns
    -------
    dict
        {"code", "units", "speed_unit", "stages", "pairs", "walls", "unknown_lines", "ignored"}:
        ``units`` the deck's unit style, ``speed_unit`` the unit of its speeds. ``stages``: one entry
        for each change of the contact settings between runs ({"runs": [{"file", "line", "text"}],
        "pairs", "walls"}, and "why" where it has neither; a deck without a run has one stage, its
        settings at its end; a run of a line the engine ran more than once, in a loop, has "pass":
        the how-manieth time it ran it); ``pairs``
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

    Raises
    ------
    DeckError
        One line naming what in the deck cannot be mapped or is missing (the run it stops at, where
        the deck has several stages).
    ParameterError
        Without a speed, or for a ``budget`` outside :data:`BUDGET_RANGE` seconds.

    Examples
    --------
    >>> deck = ("atom_style sphere\\nregion b block 0 4 0 4 0 4\\ncreate_box 1 b\\ncreate_atoms 1 single 1 1 1\\n"
    ...         "set type 1 diameter 1 density 1\\npair_style granular\\n"
    ...         "pair_coeff * * hooke 1000 50 tangential linear_nohistory 0 0\\n")
    >>> row = audit_deck(deck, [1.0])["pairs"][0]     # LAMMPS runs it (the dem extra)
    >>> row["model"], round(row["eps"][0], 6)
    ('LAMMPS hooke, damping viscoelastic', 0.952439)
    """
    speeds = [float(g) for g in speeds]
    if not speeds:
        raise ParameterError("g", speeds, "give at least one impact speed")
    if not BUDGET_RANGE[0] <= budget <= BUDGET_RANGE[1]:
        raise ParameterError("budget", budget, f"must be in [{BUDGET_RANGE[0]:g}, {BUDGET_RANGE[1]:g}] seconds")
    if not RUN_BUDGET_RANGE[0] <= run_budget <= RUN_BUDGET_RANGE[1]:
        raise ParameterError("run_budget", run_budget,
                             f"must be in [{RUN_BUDGET_RANGE[0]:g}, {RUN_BUDGET_RANGE[1]:g}] seconds")
    engine = engine_of(text if path is None else _with_included(text, Path(path)))
    if path is None:
        with tempfile.TemporaryDirectory(prefix="restitution-text-") as tmp:
            (Path(tmp) / "in.deck").write_text(text)
            deck, notes = engine_read(Path(tmp) / "in.deck", radius, density, budget, engine, run_budget)
    else:
        deck, notes = engine_read(Path(path), radius, density, budget, engine, run_budget)
    stages = [(runs, snap) for runs, snap, _ in deck.stages] or [([], deck)]
    unknown = list(dict.fromkeys(deck.unknown))      # a loop runs its lines again: each named once
    if deck.stages and contact_key(deck) != contact_key(deck.stages[-1][1]):    # --radius, --density in both
        (source, n), line = deck.stages[-1][0][-1]
        unknown.append((source, n, line, "the contact settings change after this, the deck's last run: no run uses "
                                         "the later ones, not audited"))
    if deck.stages and not any(snap.movers for _, snap in stages):
        # the engine's runs move no atom: no two spheres ever meet, and no eps is theirs
        (source, n), line = stages[0][0][0]
        # LAMMPS warns so; LIGGGHTS 3.8.0 says nothing (field round 47a, B10: a CFD case's held sphere)
        said = ' (LAMMPS: "No fixes with time integration, atoms won\'t move")' if deck.code == "LAMMPS" else ""
        raise DeckError(place((source, n)), line, f"no fix integrates any atom in the deck's runs{said}: no contact "
                                                  "ever happens, so there is no eps to audit; an integrator (fix "
                                                  "nve/sphere) makes one")
    audited, unmapped = [], []
    # a loop runs one line many times: each run says which time it is, where there are several
    times = {loc: n for loc, n in Counter(loc for runs, _ in stages for loc, _ in runs).items() if n > 1}
    met: dict = {}
    for runs, snap in stages:
        try:
            pairs, walls, not_audited, not_mapped = _audit_stage(snap, speeds, bool(runs))
        except DeckError as why:
            if len(stages) > 1:          # say which run LAMMPS would stop at
                why.args = (f"{why.args[0]} (the run at {place(runs[0][0])})",)
            raise
        unknown += [row for row in not_audited if row not in unknown]
        unmapped += not_mapped
        late = late_speeds(snap)
        # LAMMPS' fix wall/gran loops over its atoms, no list; LIGGGHTS' walls use its lists
        listed = [] if snap.code == "LAMMPS" else walls
        for kind, rows, what in (("pairs", pairs, "sphere pairs"),
                                 ("walls", [w for w in listed if not w["mesh"]], "walls"),
                                 ("meshes", [w for w in listed if w["mesh"]], "mesh walls")):
            if kind in late and _found_late(rows, late[kind][0]):
                g, why = late[kind]
                said_late = (f"{why}: no eps is given for {what} " + ("at any speed" if g == 0 else "above that speed")
                             + ", where the contact is not the law's")
                if said_late not in notes:
                    notes.append(said_late)
        if any(loc in deck.doubtful_runs for loc, _ in runs):
            # settings read after a run from values the runs change: marked in each row, not only on stderr
            for row in pairs + walls:
                row["may_differ"] = True
        said = []
        for (f, n), t in runs:
            said.append({"file": f, "line": n, "text": t})
            if (f, n) in times:
                met[(f, n)] = said[-1]["pass"] = met.get((f, n), 0) + 1
        audited.append({"runs": said, "pairs": pairs, "walls": walls})
        if not pairs and not walls:
            audited[-1]["why"] = _no_rows(snap)
    if unmapped and not any(stage["pairs"] or stage["walls"] for stage in audited):
        raise unmapped[0]            # nothing the deck's contacts do is mapped: refused, in one line
    notes += _law_changes(audited)
    units = stages[-1][1].units or "lj"      # LAMMPS' default unit style
    return {"code": stages[-1][1].code, "units": units, "speed_unit": SPEED_UNITS.get(units, f"units {units}"),
            "stages": audited, "pairs": audited[-1]["pairs"], "walls": audited[-1]["walls"],
            "unknown_lines": [{"file": f, "line": n, "text": t, "why": why} for f, n, t, why in unknown],
            "ignored": sorted(set(deck.ignored)), "notes": notes + _empty_notes(deck) + _dt_reset_notes(deck) + _environment_notes(deck)}


def _law_changes(stages: list) -> list:
    """A note for each contact whose law differs from one stage to the next: a contact under way at the
    change feels both laws, and its eps is none of the stages' (field round 39, E08: run 300 with the pair
    meeting at step 100, kn 2000 then 5000, LAMMPS 0.798 where 0.4149 and 0.5806 were printed with no word).
    The pass skips the runs, so whether a contact is under way there is not known; a stage shorter than
    the contact leaves none whole.

    Examples
    --------
    >>> row = lambda e: {"types": [1, 2], "eps": [e], "steps_per_contact": [586.0]}
    >>> stage = lambda e, n: {"runs": [{"text": f"run {n}"}], "pairs": [row(e)], "walls": []}
    >>> print(_law_changes([stage(0.41, 300), stage(0.58, 2000)])[0])
    types 1 2: the contact law changes at the start of stage 2 of 2; a contact under way at such a change \
(one lasts up to 586 steps at the deck's time step) feels both stages' laws, and its eps is none of those \
printed; stage 1 runs fewer steps than one contact lasts, so no contact that starts in it ends under its law
    >>> _law_changes([stage(0.41, 300), stage(0.41, 2000)])
    []
    """
    def keyed(stage):
        rows = {(f"types {' '.join(map(str, r['types']))}"): r for r in stage["pairs"]}
        rows.update({f"type {' '.join(map(str, r['types']))} on wall {r['wall']}": r for r in stage["walls"]})
        return rows

    def steps(stage):
        lengths = [re.match(r"run\s+(\d+)\s*(\S*)", run["text"]) for run in stage["runs"]]
        if not lengths or any(m is None or m.group(2) == "upto" for m in lengths):
            return None          # a minimize, or a run to a step the pass does not know
        return sum(int(m.group(1)) for m in lengths)

    changes: dict = {}
    left_out: set = set()
    for k in range(1, len(stages)):
        before, after = keyed(stages[k - 1]), keyed(stages[k])
        # a pair the next stage leaves out (its reason said) is a change too: what it meets there is not
        # audited (field round 42, C02: kn changed after a restart whose stage is left out, 0.4149 stood
        # with no word, LAMMPS 0.798)
        for label in before:                                              # in the rows' order, every run alike
            if label not in after or _law(before[label]) != _law(after[label]):
                lasts = [n for n in before[label].get("steps_per_contact") or [] if n is not None]
                changes.setdefault(label, []).append((k, max(lasts, default=None), steps(stages[k - 1])))
                if label not in after:
                    left_out.add(label)
    notes = []
    for label, at in changes.items():
        longest = max((n for _, n, _ in at if n is not None), default=None)
        short = [k for k, n, length in at if n is not None and length is not None and length < n]
        notes.append(f"{label}: the contact law changes"
                     + (" (or the pair is left out, its reason said)" if label in left_out else "")
                     + f" at the start of stage{'s' * (len(at) > 1)} "
                     f"{_listed([k + 1 for k, _, _ in at])} of {len(stages)}; a contact under way at such a change "
                     + (f"(one lasts up to {longest:.0f} steps at the deck's time step) " if longest else "")
                     + "feels both stages' laws, and its eps is none of those printed"
                     + (f"; stage{'s' * (len(short) > 1)} {_listed(short)} run{'s' * (len(short) == 1)} fewer steps "
                        "than one contact lasts, so no contact that starts in "
                        f"{'them' if len(short) > 1 else 'it'} ends under {'their' if len(short) > 1 else 'its'} law"
                        if short else ""))
    return notes


def _law(row: dict) -> tuple:
    """What of a row tells one contact law from another: its eps, model, parameters, reach and time
    step (field round 40, A01: kn 2000 then 5000 with coeff_restitution 0.5, the same eps in both
    stages and no note, LAMMPS 0.771)."""
    return tuple(repr(row.get(k)) for k in ("eps", "model", "alpha", "gamma", "D1", "D2", "overlap_limit", "dt",
                                            "steps_per_contact"))


def _listed(numbers: list) -> str:
    """Stage numbers in runs: [1, 2, 3, 5] -> "1-3, 5"."""
    spans: list = []
    for n in numbers:
        if spans and spans[-1][1] == n - 1:
            spans[-1][1] = n
        else:
            spans.append([n, n])
    return ", ".join(str(a) if a == b else f"{a}-{b}" for a, b in spans)


def _found_late(rows: list, g_max: float) -> int:
    """Takes the eps out of each row at the speeds above ``g_max`` (:func:`meeting.late_speeds`), marking
    them ``late`` (the row's ``late_above`` says where); how many rows it marked."""
    hit = 0
    for row in rows:
        late = [g > g_max for g in row["speeds"]]
        if not any(late):
            continue
        hit += 1
        row.update(late=late, late_above=g_max, eps=[None if x else e for e, x in zip(row["eps"], late)])
        for key in ("eps_at_dt", "eps_at_dt_spread", "dt_within_tol"):     # the time step's study too
            if row.get(key):
                row[key] = [None if x else e for e, x in zip(row[key], late)]
        if late[len(late) // 2]:
            row["exact_line"] = None
    return hit


def _audit_stage(deck: Deck, speeds: list, ran: bool) -> tuple[list, list, list, list]:
    """(pair rows, wall rows, pairs and walls not audited, the :class:`PairNotMapped` among them) of
    the deck's settings at one stage (``ran``: a run's, not the end of a deck without one)."""
    if deck.ntypes <= 0:
        raise DeckError("create_box", None, "the deck has no create_box or read_data: the number of types is "
                                            "unknown")
    pairs, not_audited, unmapped = [], [], []
    for i in range(1, deck.ntypes + 1):
        for j in range(i, deck.ntypes + 1):
            if _empty(deck, i) or _empty(deck, j):
                continue
            if (i, j) in deck.others or _adapted(deck, deck.idle.get((i, j), ())):
                not_audited.append(_other_force(deck, i, j))
                continue
            # before the exclusions: lists built before a retype hold the pairs as the atoms' old types
            # had them (field round 30, R06: said excluded, LAMMPS met the pair at first touch)
            if deck.ghosts_stale:
                where, line = deck.ghosts_stale
                not_audited.append((*deck.style_line[0], deck.style_line[1],
                                    f"types {i} {j}: {where} ({line}): a run with pre no after it made the ghost "
                                    "atoms anew: LAMMPS does not build its neighbour lists again at this run, and "
                                    "the lists built before index the old ghost atoms, so a pair held through them "
                                    "(across a periodic boundary, or across two processes' sub-domains where the "
                                    "deck runs on several) is found late in overlap or never (LAMMPS measured: 3.01 "
                                    "where the contact gives 0.41): not audited (remove pre no)"))
                continue
            if stale := [deck.stale[t] for t in (i, j) if t in deck.stale]:
                (where, line, *adapt), t = stale[0], i if i in deck.stale else j
                if adapt:
                    not_audited.append((*deck.style_line[0], deck.style_line[1],
                                        f"types {i} {j}: {where} ({line}): {adapt[0]} sizes the spheres of "
                                        f"{adapt[1] or f'type {t}'} "
                                        "after the engine has built the run's neighbour lists at its set-up (and as "
                                        "the run goes, where its diameter varies), so a pair a growth brings within "
                                        "reach is found late, deep in overlap (LAMMPS measured: 1.59 where the contact "
                                        "gives 0.37): not audited"))
                    continue
                not_audited.append((*deck.style_line[0], deck.style_line[1],
                                    f"types {i} {j}: {where} ({line}): pre no after type {t} came to hold spheres "
                                    "larger than at the last run set up (grown, or made since), or a sphere retyped "
                                    "where an exclusion is in force: the engine does not build its neighbour lists "
                                    "again at this run, and lists built with the old radii and types find a contact "
                                    "late in overlap, never, or where the exclusion says none, until their next build "
                                    "(LAMMPS measured: 0.84 where the contact gives 0.41): not audited"))
                continue
            if (why := excluded(deck, i, j)) is not None:
                not_audited.append(why)
                continue
            moves = [motion(deck, t, ran) for t in (i, j)]
            phantom = [why for t, (kind, _) in zip((i, j), moves)
                       if kind == "held" and (why := phantom_velocity(deck, t)) is not None]
            if phantom and moves[0][0] != moves[1][0]:
                not_audited.append((*deck.style_line[0], deck.style_line[1],
                                    f"types {i} {j}: {phantom[0]}: not audited"))
                continue
            for kind, why in moves:     # a moving fix's group not typed: said once
                said = (*deck.style_line[0], deck.style_line[1], why)
                if kind == "free" and why and said not in not_audited:
                    not_audited.append(said)
            if (why := _unmet(deck, i, j, moves)) is not None:
                not_audited.append(why)
                continue

            def pair_row(at, at_speeds, i=i, j=j, moves=moves):
                sized = replace(deck, at=at) if at else deck
                row = DIALECTS[deck.code].pair_row(sized, i, j)
                contact, pair = row.pop("contact"), row.pop("pair")
                if moves[0][0] != moves[1][0]:      # one sphere never moves: the other's motion alone
                    still = [k for k in (0, 1) if moves[k][0] == "held"][0]
                    contact = held_contact(contact, pair, 1 - still)
                    row.update(exact_line=None, held=moves[still][1],
                               model=f"{row['model']}; {moves[still][1]}: the type {(i, j)[1 - still]} sphere's "
                                     "motion alone")
                if at_speeds is None:
                    return contact, pair.R1 + pair.R2
                row = _with_eps(row, contact, at_speeds, pair.R1 + pair.R2, _dt(deck))
                unmoved = [k for k in (0, 1) if moves[k][0] == "held"] if moves[0][0] != moves[1][0] else [None]
                row["_beside"] = lambda at_row: effects(sized, at_row, contact, pair, (i, j),
                                                        lambda k: _frozen_contact(sized, i, j, k), unmoved=unmoved[0])
                return row, at
            try:
                rows = _pending_rows(deck, (i, j), _sampled_rows(deck, (i, j), _time_steps(_ends(_over_sizes(
                    _choices(deck, i, j), pair_row, speeds)))))
                if i == j and _lone(deck, i):
                    # kept, as the settings' own eps for two such spheres, and marked as a pair
                    # this stage cannot have
                    for row in rows:
                        row["lone"] = True
                pairs += rows
            except PairNotMapped as why:     # the engine runs it: the deck's other pairs are audited
                not_audited.append(why.row(i, j))
                unmapped.append(why)
    walls, walls_not = _wall_rows(deck, speeds, ran)
    if deck.dt_reset:
        for row in pairs + walls:
            if "dt" in row:
                row["dt_reset"] = f"{place(deck.dt_reset[0])} fix {deck.dt_reset[2]} dt/reset"
    pairs, walls, doubled = _integrated_again(deck, pairs, walls)
    return pairs, walls, not_audited + walls_not + doubled, unmapped


def _integrated_again(deck: Deck, pairs: list, walls: list) -> tuple[list, list, list]:
    """(pair rows, wall rows, lines for stderr) where a type's spheres are integrated by k > 1 fixes
    (:func:`restitution.dem.deck.meeting.integrators`): each advances them by a whole step with the
    same force, so they move as one integrator's at k times the time step, contact and all: the
    contact lasts 1/k the steps (stated so), its eps at dt -> 0 is one integrator's, and the eps at
    the deck's time step is not stated (velocity Verlet's at k dt is not what k passes of it in one
    step give: LAMMPS, hooke 1e4 0.5 damping velocity, two nve/sphere at dt 4e-5: 0.8290, one at 8e-5:
    0.7782, one at 4e-5: 0.7335; at dt -> 0 with the two: 0.7345665, one integrator's 0.7345668). A
    pair whose two types are integrated a different number of times moves as neither: not audited."""
    said, kept = [], {"pairs": [], "walls": []}
    for kind, rows in (("pairs", pairs), ("walls", walls)):
        for row in rows:
            fixes = [integrators(deck, t) for t in row["types"]]
            counts = {len(f) for f in fixes}
            if counts == {1} or not all(counts):
                kept[kind].append(row)
                continue
            loc = deck.movers[max(fixes, key=len)[-1]][0]
            line = deck.movers[max(fixes, key=len)[-1]][1]
            names = "; ".join(f"type {t} by {', '.join(f'fix {x}' for x in f)}" for t, f in dict(zip(row["types"], fixes)).items())
            what = f"types {' '.join(map(str, row['types']))}" if kind == "pairs" else f"type {row['types'][0]} on wall {row['wall']}"
            if len(counts) > 1:
                why = (f"{what}: integrated a different number of times each step ({names}): the spheres move as "
                       "neither integrator's, not audited")
            else:
                k = counts.pop()
                why = (f"{what}: integrated {k} times each step ({names}, each a whole step with the same force): "
                       f"a contact lasts 1/{k} the steps of one integrator, as stated; the eps at the deck's time "
                       "step is not stated; eps at dt -> 0 is one integrator's")
                if row.get("steps_per_contact"):
                    row["steps_per_contact"] = [None if n is None else n / k for n in row["steps_per_contact"]]
                for key in ("eps_at_dt", "dt_within_tol", "eps_at_dt_spread"):
                    if key in row:
                        row[key] = [None] * len(row[key])
                row["integrated"] = k
                kept[kind].append(row)
            if (*loc, line, why) not in said:
                said.append((*loc, line, why))
    return kept["pairs"], kept["walls"], said


def _unmet(deck: Deck, i: int, j: int, moves: list) -> tuple | None:
    """(file, line, text, why) where the engine's motion of the pair's spheres is not the audit's: the
    audit's law covers two free spheres, or one free and one that never moves."""
    loc, text = deck.style_line
    unknown = [why for kind, why in moves if kind == "unknown"]
    if unknown:
        return (*loc, text, f"types {i} {j}: {unknown[0]}: not audited")
    if all(kind == "held" for kind, _ in moves):
        return (*loc, text, f"types {i} {j}: neither sphere is moved by the contact force ({moves[0][1]}): not "
                            "audited")
    return None


def _adapted(deck: Deck, subs) -> bool:
    """Whether a fix adapt in force changes a coefficient of one of these sub-styles (``pair SUB``)."""
    return any(w[3] in ADAPT and any(a == "pair" and b in subs for a, b in zip(w[4:], w[5:]))
               for _, w in deck.beside)


def _other_force(deck: Deck, i: int, j: int) -> tuple:
    """The line naming a pair of a hybrid pair style that another sub-style covers (or one whose
    force a fix adapt brings in), not audited."""
    (source, n), line = deck.style_line
    names = ", ".join(sorted(deck.others.get((i, j), set()) | set(deck.idle.get((i, j), ()))))
    if deck.hybrid == "hybrid":
        why = (f"types {i} {j}: pair_coeff gives them sub-style {names}, not {deck.substyle}: no granular contact "
               "between them, not audited")
    else:
        why = (f"types {i} {j}: sub-style {names} adds its force to {deck.substyle}'s (hybrid/overlay), which the "
               "audit does not map: not audited")
    return (source, n, line, why)


#: Two eps closer than this (relative) are one: a law whose eps does not depend on size
_SAME_EPS = 1e-9


def _choices(deck: Deck, i: int, j: int) -> list:
    """The spheres a pair (i, j) is audited at: [()] where both types have one size, else every
    choice of ((R_i, rho_i), (R_j, rho_j)) among their sizes (:attr:`Deck.sizes`), each unordered
    choice once where i = j, and a size with itself only where two spheres of it can meet: a
    size one atom alone has at the run (:attr:`Deck.once`), no inserting fix making more of it
    (:attr:`Deck.poured`), meets only the type's other sizes."""
    if i not in deck.sizes and j not in deck.sizes:
        return [()]
    one = {t: deck.sizes.get(t) or [(deck.radius.get(t), deck.density.get(t))] for t in (i, j)}
    for t, options in one.items():
        if options[0][0] is None or options[0][1] is None:
            spheres(deck, t, t)              # one line naming what the type lacks
    # a type with itself: (b, a) is the contact (a, b) is, and comes later: left out
    alone = deck.once.get(i, set()) - deck.poured.get(i, set()) if i == j else set()
    return [(a, b) for m, a in enumerate(one[i]) for n, b in enumerate(one[j])
            if i != j or m < n or m == n and a not in alone]


def _over_sizes(choices: list, row_at, speeds) -> list:
    """[(row, at)] for the choices of sizes that :func:`_ends` may keep, ``row_at(choice, speeds)``
    making each (``row_at(choice, None)``: its contact and overlap limit alone): every choice where
    they are few or their eps at the middle speed all agree (a law whose eps may not depend on size:
    _ends compares them at every speed), else only the two whose eps there is smallest and largest,
    found at that speed alone (what _ends would keep of all: a poured range's 45 pairs of sizes cost
    2 full rows, not 45)."""
    if len(choices) <= 2:
        return [row_at(c, speeds) for c in choices]
    k = len(speeds) // 2
    middle = _middle_eps([row_at(c, None) for c in choices], speeds[k])
    known = [e for e in middle if e is not None]
    if len(known) == len(middle) and all(abs(e - known[0]) <= _SAME_EPS * max(abs(known[0]), 1e-300) for e in known):
        return [row_at(c, speeds) for c in choices]
    keyed = [-1.0 if e is None else e for e in middle]
    lo, hi = min(range(len(choices)), key=keyed.__getitem__), max(range(len(choices)), key=keyed.__getitem__)
    low = row_at(choices[lo], speeds)
    return [low, low if hi == lo else row_at(choices[hi], speeds)]


def _middle_eps(contacts: list, g: float) -> list:
    """eps at g of each (contact, overlap limit) as :func:`_with_eps` gives it (None where the bodies
    pass through, 0 where they stick), the contacts of one law asked of the ladder at once: one
    request of many points runs compiled at once, where many of one point run as plain Python first
    (:func:`restitution.fast.jit.call_kernel`). Where the batch cannot answer (a law outside the
    ladder, a sticking point), each is asked alone."""
    from ...fast.ladder import epsilon
    from ...fast.rung import reference_bound
    out: list = [None] * len(contacts)
    laws: dict = {}
    for n, (contact, limit) in enumerate(contacts):
        if not contact.reaches(g, limit):
            laws.setdefault(getattr(contact, "problem", None), []).append(n)
    for problem, members in laws.items():
        try:
            if problem is None or len(members) < 2:
                raise ParameterError("omega", None, "asked alone")
            got = epsilon(problem, omega=[contacts[n][0].omega(g) for n in members],
                          tol=reference_bound(1e-12, problem.ex), build=False, cached=False).eps
            for n, e in zip(members, got):
                out[n] = float(e)
        except ParameterError:       # StickError among them
            for n in members:
                out[n] = _eps_or_stick(contacts[n][0], g)[0]
    return out


def _pending_rows(deck: Deck, types: tuple, rows: list) -> list:
    """The rows of a range marked ``if_poured`` (the pours' fix IDs) where a sphere of theirs is
    of a size only a pour still in force gives after a set resized what it made: that end of the
    range holds only if the pour has not finished inserting, which the audit does not know."""
    for row in rows:
        fixes = sorted({fix for t, at in zip(types, row.get("at", ())) for fix, _ in
                        deck.pending.get(t, {}).get(tuple(at), ())})
        if fixes:
            row["if_poured"] = fixes
    return rows


def _sampled_rows(deck: Deck, types: tuple, rows: list) -> list:
    """The rows of a range (``sizes`` smallest or largest eps) marked ``sampled`` where a type of
    theirs holds more sizes than were audited: the range is over the sizes sampled, which need
    not hold its ends."""
    if any(t in deck.sampled for t in types):
        for row in rows:
            if row.get("sizes") in ("smallest eps", "largest eps"):
                row["sampled"] = True
    return rows


def _ends(rows: list) -> list:
    """The rows of one pair or wall over the sizes present: the one row where there is one size; else
    the rows of the smallest and the largest eps at the middle speed, each with the sizes it is at
    (``sizes``: "smallest eps" or "largest eps", ``at``: [[R, rho], [R, rho]]), or one row (``sizes``:
    "any", the sizes' eps within 1e-9) where the law's eps does not depend on size, or "only" where
    one choice of sizes alone can meet. A speed where some size passes through or sticks is taken as
    it comes in the row that has it. Each row kept gets what acts beside its contact (:func:`_beside`),
    the rows left out none: it is computed for the rows kept alone."""
    if len(rows) == 1 and not rows[0][1]:
        return [_beside(rows[0][0])]
    if len(rows) == 1:          # of a type's sizes, one pair alone can meet (one sphere of each)
        row, at = rows[0]
        return [{**_beside(row), "sizes": "only", "at": _at(at)}]
    k = len(rows[0][0]["speeds"]) // 2

    def middle(item):
        e = item[0]["eps"][k]
        return -1.0 if e is None else e
    lo, hi = min(rows, key=middle), max(rows, key=middle)
    same = all(all(a is not None and b is not None and abs(a - b) <= _SAME_EPS * max(abs(b), 1e-300)
                   for a, b in zip(r["eps"], lo[0]["eps"])) for r, _ in rows)
    out = []
    for (row, at), end in ([(lo, "any")] if same else [(lo, "smallest eps"), (hi, "largest eps")]):
        out.append({**_beside(row, rows if same else ()), "sizes": end, "exact_line": row["exact_line"] if same else None,
                    "at": _at(at)})
    return out


def _at(at: tuple) -> list:
    """A choice of sizes as the JSON gives it: [[R, rho]] (a wall) or [[R, rho], [R, rho]] (a pair)."""
    return [list(at[0]), list(at[1])] if len(at) == 2 else [list(at[0])]


def _beside(row: dict, over=()) -> dict:
    """The row with what acts beside its contact (``beside``: :func:`restitution.dem.deck.beside.effects`
    at the row's sizes, which _with_eps's caller left as ``row["_beside"]``).

    ``over``: the [(row, at)] of every size of a law whose eps does not depend on size, of which
    ``row`` is the one kept. An effect may still depend on size (a gravity beside a wall shifts eps
    the more the longer a contact lasts, which for Hertz grows with the radius): each effect is
    asked at the middle speed at every size, and one whose eps differs between them (beyond 1e-9)
    is given at the sizes at the ends of its range there (for each face of a wall, its smallest
    and largest), each entry with the sizes it is at (``at``), in that order; an effect that does
    not differ is the kept row's. Only those sizes are computed at every speed."""
    beside, row = row["_beside"], {key: value for key, value in row.items() if key != "_beside"}
    row["beside"] = effects = beside(row)
    if len(over) < 2 or not effects:
        return row
    k = len(row["speeds"]) // 2
    one = ("speeds", "eps", "sticks", "passes_through")
    at_middle = [r["_beside"]({**r, **{key: [r[key][k]] for key in one}}) for r, _ in over]
    full: dict = {}
    out = []
    for n, effect in enumerate(effects):
        values = [_middle_values(sized[n]) for sized in at_middle]
        ends = sorted({pick(range(len(over)), key=lambda m, f=f: values[m][f])
                       for f in range(len(values[0])) if all(v[f] is not None for v in values)
                       for pick in (min, max)
                       if not _all_same([v[f] for v in values])})
        if not ends:
            out.append(effect)
            continue
        for m in ends:
            if m not in full:
                full[m] = over[m][0]["_beside"](over[m][0])
            out.append({**full[m][n], "at": _at(over[m][1])})
    row["beside"] = out
    return row


def _middle_values(effect: dict) -> tuple:
    """An effect's eps at the one speed it was asked at: one per face, or its own (None: not computed)."""
    if effect.get("faces"):
        return tuple(face["eps_engine"][0] if face["eps_engine"] else None for face in effect["faces"])
    return (effect["eps_engine"][0] if effect["eps_engine"] else None,)


def _all_same(values: list) -> bool:
    """Whether these eps agree to _SAME_EPS (relative)."""
    return all(abs(v - values[0]) <= _SAME_EPS * max(abs(values[0]), 1e-300) for v in values)


#: A frozen atom's mass, as a multiple of its own: the engine takes the other atom's mass for m_eff
#: (to this ratio, 1e-12 relative)
_FROZEN = 1e12


def _frozen_contact(deck: Deck, i: int, j: int, k: int):
    """The contact the engine gives type pair (i, j) where the body of type (i, j)[k] is frozen (at
    the sizes the deck is audited at, :attr:`Deck.at`, where the type has several)."""
    if deck.at:
        at = list(deck.at)
        at[k] = (at[k][0], at[k][1] * _FROZEN)
        held = replace(deck, at=tuple(at))
    else:
        t = (i, j)[k]
        held = replace(deck, density={**deck.density, t: deck.density[t] * _FROZEN})
    return DIALECTS[deck.code].pair_row(held, i, j)["contact"]


def _dt(deck: Deck) -> float | None:
    """The time step the deck's runs use (LAMMPS' default for its units where it sets none); None for
    a deck read without its engine."""
    if deck.held is None:
        return None
    return deck.dt if deck.dt is not None else DEFAULT_DT.get(deck.units)


def _empty(deck: Deck, t: int) -> bool:
    """Whether type t has no particle at this run, as the engine holds it, and none is poured into it:
    a type of walls only, or unused; no sphere of it meets another."""
    return (deck.held is not None and t not in deck.held and t not in deck.radius and t not in deck.missing
            and t not in deck.sizes)


def _lone(deck: Deck, t: int) -> bool:
    """Whether type t has exactly one sphere at this run, as the engine holds it (one size, which
    :attr:`Deck.once` says one atom has), and no inserting
    fix (a pour, a deposit, a LIGGGHTS insertion waiting for its start) adds to it: its pair with
    itself cannot happen (field round 22, t13, y09: types 2 2 was printed for a lone sphere as if it
    could): the row is marked ``lone``.

    Examples
    --------
    >>> one = Deck(ntypes=2, held={1: [(0.002, 2500.0)], 2: [(0.003, 2500.0)]}, once={2: {(0.003, 2500.0)}})
    >>> _lone(one, 1), _lone(one, 2)
    (False, True)
    >>> one.poured[2] = {(0.003, 2500.0)}
    >>> _lone(one, 2)
    False
    """
    return (deck.held is not None and len(deck.held.get(t, ())) == 1 and bool(deck.once.get(t))
            and t not in deck.sizes and not deck.poured.get(t) and deck.deposits.get(t) is None
            and not any(t in made for _, _, made in deck.waiting.values()))


def _no_rows(deck: Deck) -> str:
    """Why a stage has no row: no atom held at its run, or none of its pairs and walls audited.

    Examples
    --------
    >>> _no_rows(Deck(ntypes=2, held={}))
    'the engine holds no atom at this run (none made yet, or none left), so no two spheres meet and none meets a wall'
    """
    if all(_empty(deck, t) for t in range(1, deck.ntypes + 1)):
        return ("the engine holds no atom at this run (none made yet, or none left), so no two spheres meet and none "
                "meets a wall")
    return "none of its type pairs or walls is audited: the notes on stderr say why of each"


def _empty_notes(deck: Deck) -> list:
    """One note per type without particles in the deck's runs (its pairs not audited), per type
    audited at a deposit's default size, per type sampled, and per size only a pour that may have
    finished gives."""
    stages = [snap for _, snap, _ in deck.stages] or [deck]
    empty = sorted({t for d in stages for t in range(1, d.ntypes + 1) if _empty(d, t)})
    # the inserting fixes defined at a run where their type has no atom make its atoms as that run
    # goes; one defined only at a later run (field round 13, a06: a loop pours type 1, then type 2)
    # has made none there, and none of its sizes is missing
    inserted = {t: _inserters([d for d in stages if _empty(d, t)], t) for t in empty}
    # ... named only where the type is empty before it has atoms, never after them (deleted: field
    # round 18, b24)
    later = {t: _inserters([d for d in stages if not _empty(d, t)], t) if _empty_first(stages, t) else ""
             for t in empty}
    # a LIGGGHTS insertion whose start step no run before reaches (field round 19, C4)
    waiting = {t: f"the runs before step {start}, where fix {fix} ({style}) starts inserting its spheres"
               for d in stages for fix, (start, style, made) in d.waiting.items() for t in made}
    sampled = {t: (n, len(d.sizes[t])) for d in stages for t, n in d.sampled.items() if t in d.sizes}
    deposited = {t: fix for d in stages for t, fix in d.deposits.items() if fix is not None}
    template = {t: mol for d in stages for t, mol in d.deposited_templates.items()}
    pending = {(t, (fix, where, *size)) for d in stages for t, sizes in d.pending.items()
               for size, fixes in sizes.items() for fix, where in fixes}
    return [(f"type {t}: the atoms fix {fix} (deposit) makes are molecule {template[t]}'s sphere, of its size: "
             f"audited at that size" if t in template else
             f"type {t}: the atoms fix {fix} (deposit) makes get LAMMPS' default size, diameter 1 and density 1, "
             f"whatever set gave the type's atoms before: audited at that size") + _beside_deposited(stages, t)
            for t, fix in sorted(deposited.items())] + [
            f"{_types_named(ts)} {'has' if len(ts) == 1 else 'have'} no particle"
            f"{' at some runs' if len(stages) > 1 else ''} ("
            + why + f"): {'its' if len(ts) == 1 else 'their'} sphere pairs cannot happen there and are not audited"
            for why, ts in _by_reason({t: waiting.get(t) or (f"those before {later[t]} makes its atoms" if later[t]
                                                             else "walls only, unused, or deleted")
                                       for t in empty if not inserted[t]})] + \
        [f"type {t} is inserted by {inserted[t]} as the runs go, at sizes the audit does not read: its pairs "
         f"{'at the runs where it has no atom yet ' if len(stages) > 1 else ''}are not audited"
         for t in empty if inserted[t]] + \
        [f"type {t} holds {n} sizes: audited at {k} of them, spread evenly in radius with the two smallest and "
         "two largest radii and the two lightest and two densest among them; its pairs' eps range is over these, "
         "and the sizes left out may reach beyond it" for t, (n, k) in sorted(sampled.items())] + \
        [f"type {t}: spheres of radius {r:.6g} density {rho:.6g} exist only if fix {fix} had not finished inserting "
         f"when the set at {where} resized those it had made, which the audit (its runs skipped) does not know: the "
         "rows at that size hold only then"
         for t, (fix, where, r, rho) in sorted(pending)]


def _by_reason(reasons: dict) -> list:
    """[(reason, [types])] of a {type: reason}, the types of one reason together, in type order
    (a deck of 120 size classes, 117 of them empty, says so in one line: field round 18, b41)."""
    grouped: dict = {}
    for t in sorted(reasons):
        grouped.setdefault(reasons[t], []).append(t)
    return sorted(grouped.items(), key=lambda item: item[1][0])


def _types_named(ts: list) -> str:
    """"type 3", or "types 2-59, 61" for several, runs of consecutive types joined.

    Examples
    --------
    >>> _types_named([3]), _types_named([2, 3, 4, 7, 9, 10])
    ('type 3', 'types 2-4, 7, 9-10')
    """
    runs: list = []
    for t in ts:
        if runs and t == runs[-1][1] + 1:
            runs[-1][1] = t
        else:
            runs.append([t, t])
    named = ", ".join(f"{a}" if a == b else f"{a}-{b}" for a, b in runs)
    return f"type {named}" if len(ts) == 1 else f"types {named}"


def _empty_first(stages: list, t: int) -> bool:
    """Whether type t is empty only in the stages before its first atoms (not again after them)."""
    empties = [_empty(d, t) for d in stages]
    first = empties.index(False) if False in empties else len(empties)
    return not any(empties[first:])


def _inserters(stages: list, t: int) -> str:
    """The inserting fixes the stages name for type t, as "fix ID (style)" joined by "or" ("": none).

    Examples
    --------
    >>> _inserters([Deck(inserters={2: {"ins": "pour"}}), Deck(inserters={2: {"d": "deposit"}})], 2)
    'fix ins (pour) or fix d (deposit)'
    """
    named = {f"fix {fix} ({style})": None for d in stages for fix, style in d.inserters.get(t, {}).items()}
    return " or ".join(named)


def _beside_deposited(stages: list, t: int) -> str:
    """The other sizes type t holds beside a deposit's (its created or poured atoms), as a deposit's
    note names them: the pairs are audited over all of them."""
    from .reader import DEPOSITED
    others = sorted({size for d in stages for size in d.sizes.get(t, ())} - {DEPOSITED})
    if not others:
        return ""
    shown = ", ".join(f"radius {r:.6g} density {rho:.6g}" for r, rho in others[:3])
    more = f" and {len(others) - 3} more" if len(others) > 3 else ""
    return f", beside the type's other sizes ({shown}{more}), over which its pairs are audited"


def _environment_notes(deck: Deck) -> list:
    """One note per environment variable a getenv-style variable of the deck read: the engine's pass
    ran in the user's environment, and the answer holds for the values it had."""
    return [f"the deck reads the environment variable {name} (a getenv variable), here "
            + (f"'{value}'" if value else "unset or empty") + ": the answer holds for this value"
            for name, value in sorted(deck.environment.items())]


def _dt_reset_notes(deck: Deck) -> list:
    """One note per fix dt/reset some run sees: it changes the time step during the runs, where the
    audit's steps per contact (and the eps the integrator gives at the deck's step) are stated at
    the deck's own timestep."""
    seen = dict.fromkeys(snap.dt_reset for _, snap, _ in deck.stages if snap.dt_reset)
    return [f"{place(loc)} fix {fix} dt/reset changes the time step during the runs ({text}), and an unfix leaves it "
            "where the fix last set it: the steps per contact and the eps at the deck's time step stated here are at "
            "its timestep command's dt (or LAMMPS' default), not at the steps dt/reset takes; eps at dt -> 0 does not "
            "depend on it" for loc, text, fix in seen]

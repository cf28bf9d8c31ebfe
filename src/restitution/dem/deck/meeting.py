"""Which spheres of a deck meet, and how they move when they do: the pairs the engine never lets
touch (``neigh_modify exclude``, bonded atoms whose special_bonds weight is not 1), and the spheres
no fix integrates (an integrator on a group only, ``fix move``, no integrator at all).

A sphere that no fix moves stays where it is whatever the force, while the engines' granular pair
styles still take m_eff = m1 m2 / (m1 + m2) for the force (LAMMPS' pair_granular and LIGGGHTS'
pair gran; only a ``fix freeze`` makes it the other atom's mass, which
:mod:`restitution.dem.deck.beside` handles). The moving sphere's overlap then obeys
delta'' = -F(delta, delta'; m_eff) / m_moving: the law's own equation with D1 and D2 both scaled
by m_eff / m_moving (:func:`held_contact`). A sphere moved by ``fix move linear`` keeps a constant
velocity, so in its frame it is one held still.
"""

from __future__ import annotations

import math
from dataclasses import replace

from ..dialect.state import DEFAULT_SKIN, Deck, number_or_none, place

__all__ = ["MOVERS", "INTEGRATORS", "CLUMP_MOVERS", "BROWNIAN", "neigh_modify", "special_bonds", "excluded", "motion",
           "held_contact", "group_types", "integrators", "late_speeds", "phantom_velocity", "rigid", "unlisted"]

#: Fix styles that move the atoms of their group by integrating the forces on them. Not LIGGGHTS'
#: multisphere: it moves the clumps particletemplate/multisphere makes, never a single sphere of its
#: group (field round 46, lists: the deck's only integrator, no clumps: LIGGGHTS left both spheres as
#: set after 2300 steps, the pair never met, where the audit printed eps 0.5; beside nve/sphere:
#: 0.499929 as with nve/sphere alone, where the audit said each sphere was integrated twice)
INTEGRATORS = frozenset({"nve/sphere", "nve", "nve/limit", "nvt/sphere", "npt/sphere", "nph/sphere", "nvt", "npt",
                         "nph", "nve/asphere", "nve/sphere/omp", "nve/omp", "nve/sphere/kk", "nve/kk", "nvt/sllod",
                         "nve/sphere/limit", "nve/bpm/sphere", "nve/superquadric"})
#: LIGGGHTS' fix multisphere: it moves the clumps particletemplate/multisphere makes (types the
#: reader refuses: deck.shapes), never a single sphere of its group; a run with it moves atoms (no
#: "no fix integrates any atom"), but no single sphere's motion is its (:func:`_moves_spheres`)
CLUMP_MOVERS = frozenset({"multisphere"})
#: Fix styles that move the atoms of their group: the integrators, fix move (a prescribed motion),
#: nve/noforce (each atom at its own velocity, which no force changes) and the clumps' movers
#: Movers whose steps are overdamped and random, the force read as a drift (field round 47, F36: as
#: the only mover the pair never met in LAMMPS, where the audit refused the deck as one no fix moves)
BROWNIAN = frozenset({"brownian", "brownian/sphere", "brownian/asphere"})
MOVERS = INTEGRATORS | {"move", "nve/noforce"} | CLUMP_MOVERS | BROWNIAN
def rigid(style: str) -> bool:
    """Whether a fix style joins its atoms into rigid bodies (rigid, rigid/small, rigid/nve, ...),
    whose pairs are named, not audited (:func:`motion`).

    Examples
    --------
    >>> rigid("rigid/small"), rigid("nve/sphere")
    (True, False)
    """
    return style.startswith("rigid")


#: Of the movers, those that move their atoms without the forces on them
_PRESCRIBED = ("move", "nve/noforce")


def _moves_spheres(deck: Deck, style: str, t: int) -> bool:
    """Whether a moving fix of ``style`` may move type t's particles: any but a clumps' mover
    (CLUMP_MOVERS), which moves a type only where its particles are clumps (deck.shapes).

    Examples
    --------
    >>> _moves_spheres(Deck(ntypes=1), "nve/sphere", 1), _moves_spheres(Deck(ntypes=1), "multisphere", 1)
    (True, False)
    """
    return style not in CLUMP_MOVERS or t in deck.shapes


def _integrates(line: str) -> bool | None:
    """Whether a moving fix's ``line`` integrates its atoms under the forces on them: True for an
    integrator, and for ``fix move`` whose every coordinate is NULL (LAMMPS then "time-integrates
    [it] using the current velocity and force", as fix nve: ``linear NULL NULL NULL``, ``variable``
    with all six NULL); None for a ``fix move`` that prescribes some coordinates and integrates
    others, whose eps depends on the contact's direction; False for a prescribed motion.

    Examples
    --------
    >>> _integrates("fix mv t2 move linear NULL NULL NULL"), _integrates("fix 1 all nve/sphere")
    (True, True)
    >>> _integrates("fix mv t2 move linear NULL NULL 0.0"), _integrates("fix mv t2 move linear 0 0 0")
    (None, False)
    """
    words = line.split()
    if words[3] not in _PRESCRIBED:
        return True
    if words[3] != "move" or len(words) < 5 or words[4] not in ("linear", "variable"):
        return False
    given = words[5:8] if words[4] == "linear" else words[5:11]
    nulls = sum(w == "NULL" for w in given)
    return True if nulls == len(given) else (None if nulls else False)


#: neigh_modify exclude styles and their number of arguments
_EXCLUDE_ARGS = {"type": 2, "group": 2, "molecule/intra": 1, "molecule/inter": 1, "molecule": 1, "none": 0}
#: special_bonds' named settings: their lj weights
_PRESETS = {"fene": (0.0, 1.0, 1.0), "charmm": (0.0, 0.0, 0.0), "amber": (0.0, 0.0, 0.5),
            "dreiding": (0.0, 0.0, 1.0)}


def neigh_modify(deck: Deck, words: list, loc, line: str) -> None:
    """neigh_modify ... exclude STYLE args ...: the exclusions in force (``exclude none`` clears them),
    ``include GROUP`` among them; and every, delay and check, how often the engine may rebuild its
    neighbour lists."""
    k = 1
    while k < len(words):
        if words[k] in ("every", "delay", "check", "once") and k + 1 < len(words):
            value = words[k + 1]
            deck.neigh = {**deck.neigh, words[k]: int(value) if value.isdigit() else value}
            k += 2
        elif words[k] == "include" and k + 1 < len(words):
            # lists built for one group's atoms only (field round 16, n06: two spheres outside it
            # passed through each other in LAMMPS); "include all" lifts it
            kept = [e for e in deck.excludes if e[2][0] != "include"]
            deck.excludes = kept + ([] if words[k + 1] == "all" else [(loc, line, ["include", words[k + 1]])])
            k += 2
        elif words[k] == "exclude" and k + 1 < len(words):
            style = words[k + 1]
            n = _EXCLUDE_ARGS.get(style, 0)
            if style == "none":
                deck.excludes = []
            else:
                deck.excludes = deck.excludes + [(loc, line, [style, *words[k + 2:k + 2 + n]])]
            k += 2 + n
        else:
            k += 1




def late_speeds(deck: Deck) -> dict:
    """Where two bodies may first be in each other's neighbour list when they already overlap, so
    that the engine's eps is not the law's: for each kind of row ("pairs" of spheres, "walls" found
    through the lists, "meshes"), (g, why): no eps holds above the relative speed g, 0 meaning at
    every speed. Read from each run's ``neighbor`` skin, ``neigh_modify`` every K, delay D and check,
    and time step (the stage's own and ``lists_seen``, those of later runs with the same contacts);
    the smallest g of them. Measured in LAMMPS and LIGGGHTS (field rounds 15 and 16):

    * ``check no``: the lists are rebuilt every T steps, T = K rounded up past D; a pair beyond the
      skin at a build closes by g T dt before the next: late above skin / (T dt) (``every 200 check
      no``, skin 1e-5: 5.99 to 0.82 by the starting gap where the contact gives 0.4025).
    * ``check yes`` with K > 1: a rebuild waits for an atom to have moved half the skin, seen at the
      next of the checks K steps apart, and two spheres approaching each other each move half the
      skin just as they touch: they may overlap for up to K - 1 steps unseen, at any speed (``every
      10 check yes``: 0.498 to 0.722 by the starting gap at g = 0.05; ``every 2``: up to 0.516 where
      the deck's step gives 0.498). A sphere against a body found through the lists, which stands
      still, moves the half skin before it touches: late above skin / (2 K dt), and skin / (D dt).
    * ``check yes`` with K = 1 and D > 0: nothing is looked at for D steps after a build: late above
      skin / (D dt).
    * ``once yes``: the lists are built at a run's start only: at every speed.

    LIGGGHTS' mesh walls were found late below those speeds (0.9 times skin / (D dt), delay 10): half
    of each bound, and at every speed where the spheres' pairs are.

    Parameters
    ----------
    deck : Deck
        The deck at the run audited (its time step, neighbor skin, neigh_modify settings, units and
        engine, and ``lists_seen``).

    Returns
    -------
    dict
        Kind -> (g, why) for each kind of row that may be found late; empty where none is.

    Examples
    --------
    >>> d = Deck(dt=1e-5, skin=1e-5, neigh={"every": 200, "delay": 0, "check": "no"}, units="si")
    >>> late_speeds(d)["pairs"][0]
    0.005
    >>> late_speeds(Deck(dt=1e-5, skin=1e-3, units="si"))
    {}
    >>> late_speeds(Deck(code="LIGGGHTS", dt=1e-5, skin=1e-3, units="si"))["pairs"][0]     # its delay 10
    10.0
    >>> late = late_speeds(Deck(dt=1e-5, skin=1e-4, neigh={"every": 10}, units="si"))
    >>> late["pairs"][0], late["walls"][0]
    (0.0, 0.5)
    """
    found: dict = {}
    largest = _reset_largest_dt(deck)
    for neigh, skin, dt in [(deck.neigh, deck.skin, deck.dt), *deck.lists_seen]:
        # an unknown step stays unknown unless the fix's largest says what it reaches
        step = dt if largest is None or (not dt and math.isinf(largest)) else max(dt or 0.0, largest)
        for kind, (g, why) in _late_in(deck, neigh, skin, step).items():
            if step != dt:
                why = (f"{why} (read at the step fix {deck.dt_reset[2]} dt/reset may take: "
                       + (f"{step:g})" if math.isfinite(step) else "any, it has no largest)"))
            if kind not in found or g < found[kind][0]:
                found[kind] = (g, why)
    return found


def _for_meshes(why: str, g: float) -> str:
    """The sentence of a bound said for LIGGGHTS' mesh walls, which are found late from half of it."""
    return f"{why}; LIGGGHTS' mesh walls were found late from about half that speed, {g / 2:.4g}"


def _reset_largest_dt(deck: Deck) -> float | None:
    """The largest step a fix dt/reset in force may take (its Tmax), infinite where it has none
    (NULL), None where no such fix is in force: the lists' bounds are read at that step (field round
    17, a19: dt/reset raised 1e-6 to 1e-4 at once, LAMMPS up to 3.3 at g = 0.5 where 0.497 was
    printed); at an infinite step every bound is 0, every speed."""
    if not deck.dt_reset:
        return None
    words = deck.dt_reset[1].split()
    largest = number_or_none(words[6]) if len(words) > 6 else None
    return float("inf") if largest is None else largest


def _late_in(deck: Deck, neigh: dict, skin, dt) -> dict:
    """:func:`late_speeds` of one run's settings."""
    # the defaults: LAMMPS' every 1 delay 0 check yes; LIGGGHTS 3.8.0 keeps the older delay 10
    every, delay = neigh.get("every", 1), neigh.get("delay", 10 if deck.code == "LIGGGHTS" else 0)
    check = neigh.get("check", "yes")
    skin = skin if skin is not None else DEFAULT_SKIN.get(deck.units or "lj")
    if not isinstance(every, int) or not isinstance(delay, int) or skin is None or not dt:
        return {}
    every = max(every, 1)
    if neigh.get("once") == "yes":
        # lists built at a run's start only: bodies further apart than the skin then never meet
        # (field round 17, a07, G11: LAMMPS and LIGGGHTS let them pass through each other)
        why = (f"neigh_modify once yes with a skin of {skin:g}: the engine builds its neighbour lists at the start "
               "of each run only, so bodies further apart than the skin then never meet, and those closer may be "
               "found late, at any speed")
        return {"pairs": (0.0, why), "walls": (0.0, why), "meshes": (0.0, why)}
    said = f"neigh_modify every {every} delay {delay} check {check} with a skin of {skin:g}"
    if check == "no":
        steps = every * max(1, -(-delay // every))
        if steps <= 1:
            return {}
        g = skin / (steps * dt)
        why = (f"{said}: the engine rebuilds its neighbour lists every {steps} steps without looking, so two bodies "
               f"approaching faster than skin / ({steps} dt) = {g:.4g} may first meet already overlapping")
        return {"pairs": (g, why), "walls": (g, why), "meshes": (g / 2, _for_meshes(why, g))}
    if every > 1:
        wall = min(skin / (2 * every * dt), skin / (delay * dt) if delay else float("inf"))
        why = (f"{said}: the engine looks at its neighbour lists only every {every} steps, rebuilding them once an "
               f"atom has moved half the skin, so two approaching spheres may overlap for up to {every - 1} steps "
               "before their contact is seen, at any speed")
        wall_why = (f"{said}: a sphere approaching a still body faster than {wall:.4g} may first meet it already "
                    "overlapping")
        return {"pairs": (0.0, why), "walls": (wall, wall_why), "meshes": (0.0, why)}
    if delay <= 1:
        return {}
    g = skin / (delay * dt)
    why = (f"{said}: the engine looks at its neighbour lists no sooner than {delay} steps after a build, so two "
           f"bodies approaching faster than skin / ({delay} dt) = {g:.4g} may first meet already overlapping")
    return {"pairs": (g, why), "walls": (g, why), "meshes": (g / 2, _for_meshes(why, g))}


def special_bonds(deck: Deck, words: list, where: str, line: str) -> None:
    """special_bonds: the lj weights of bonded neighbours (each command starts from LAMMPS' 0 0 0)."""
    lj = (0.0, 0.0, 0.0)
    k = 1
    while k < len(words):
        w = words[k]
        if w in _PRESETS:
            lj, k = _PRESETS[w], k + 1
        elif w in ("lj/coul", "lj") and k + 3 < len(words):
            try:
                lj = tuple(float(x) for x in words[k + 1:k + 4])
            except ValueError:
                pass
            k += 4
        else:
            k += 1
    deck.special_lj = lj


def group_types(deck: Deck, group: str):
    """The types a group holds, or None where the audit cannot know them: its static members by
    type (none where it was defined before any atom existed: a group holds the atoms present when
    it is defined), and those an inserting fix of a named type pours into it. A group by type
    before which more atoms of its types were made (``partial_groups``) holds some atoms of those
    types only: None. One made before any atom that every inserting fix fills, and nothing else
    made atoms since, holds every atom.

    Parameters
    ----------
    deck : Deck
        The deck at the run audited (its groups, and those defined before any atom).
    group : str
        The group's ID.

    Returns
    -------
    set of int, or None

    Examples
    --------
    >>> group_types(Deck(ntypes=2, groups={"two": {2}}), "two"), group_types(Deck(ntypes=2), "all")
    ({2}, {1, 2})
    >>> group_types(Deck(ntypes=2, groups={"two": {2}}, empty_groups={"two"}), "two")
    set()
    >>> group_types(Deck(ntypes=2, groups={"two": {2}}, partial_groups={"two": "line 9"}), "two") is None
    True
    """
    if group == "all":
        return set(range(1, deck.ntypes + 1))
    static = deck.groups.get(group)
    fillers = deck.filled_groups.get(group, [])
    if group in deck.empty_groups and group not in deck.partial_groups and deck.inserts and all(
            made in [f for _, f in fillers] for made in deck.inserts):
        # made before any atom, and every atom since made by a fix that fills it (LIGGGHTS'
        # nve_group): it holds every atom there is, of the types they fill it with where known
        if any(filled is None for _, filled in fillers):
            return set(range(1, deck.ntypes + 1))
    elif group in deck.partial_groups and group not in deck.empty_groups:
        return None                      # atoms of its types made after it are not its members
    if any(filled is None for _, filled in fillers) or (static is None and group in deck.groups):
        return None
    if static is None and not fillers:
        return None                      # a group the reader never saw defined
    held = set() if static is None or group in deck.empty_groups else set(static)
    return held.union(*(filled for _, filled in fillers))


def _excluded_types(deck: Deck, value: str):
    if value.isdigit():
        return int(value)
    return deck.labels.get(value)


def unlisted(deck: Deck, t: int) -> str | None:
    """Why spheres of type t may be in no neighbour list (``neigh_modify include GROUP`` with t
    possibly outside the group), or None. Its walls go wrong too (field round 16, n06 and L22: LAMMPS
    threw a type-2 sphere off its fix wall/gran floor at 24 to 60 times its impact speed, LIGGGHTS
    at 43 times, where the audit printed the law's 0.363 and 0.45).

    Parameters
    ----------
    deck : Deck
        The deck at the run audited.
    t : int
        The sphere's type.

    Returns
    -------
    str or None

    Examples
    --------
    >>> d = Deck(ntypes=2, groups={"g1": {1}}, excludes=[((None, 3), "neigh_modify include g1", ["include", "g1"])])
    >>> unlisted(d, 1) is None, unlisted(d, 2)[:36]
    (True, 'type 2: neigh_modify include g1: the')
    """
    for _, _, (style, *args) in deck.excludes:
        if style == "include" and _outside(deck, args[0], t):
            return (f"type {t}: neigh_modify include {args[0]}: the engine builds its neighbour lists for that group's "
                    "atoms only, and a sphere outside it was thrown off a wall at many times its impact speed in "
                    "LAMMPS and LIGGGHTS: not audited")
    return None


def _outside(deck: Deck, group: str, t: int) -> bool:
    """Whether spheres of type t may lie outside ``group`` (or the audit cannot type the group)."""
    held = group_types(deck, group)
    return held is None or t not in held


def excluded(deck: Deck, i: int, j: int) -> tuple | None:
    """(loc, text, why) where the engine never makes a contact between types i and j, cannot be
    known to make it, or adds to it a force of bonds; None where the contact is the law's alone."""
    for loc, line, (style, *args) in deck.excludes:
        if style == "include":
            if _outside(deck, args[0], i) or _outside(deck, args[0], j):
                return (*loc, line, f"types {i} {j}: neigh_modify include {args[0]}: the engine builds its neighbour "
                                    "lists for that group's atoms only, and a pair with an atom outside it (or one the "
                                    "audit cannot type) may never meet: not audited")
        elif style == "type" and len(args) == 2:
            a, b = (_excluded_types(deck, x) for x in args)
            if a is None or b is None:
                return (*loc, line, f"types {i} {j}: the audit cannot read the excluded types: not audited")
            if {a, b} == {i, j}:
                return (*loc, line, f"types {i} {j}: excluded by neigh_modify: no contact between them, not audited")
        elif style == "group" and len(args) == 2:
            ga, gb = (group_types(deck, g) for g in args)
            known = gb if ga is None else ga
            if (ga is None or gb is None) and known is not None and i not in known and j not in known:
                continue       # an excluded pair has an atom in each group: neither type is in the one known
            if ga is None or gb is None:
                return (*loc, line, f"types {i} {j}: neigh_modify excludes pairs of groups whose atoms the audit "
                                    "cannot type: whether they meet is not known, not audited")
            if (i in ga and j in gb) or (i in gb and j in ga):
                return (*loc, line, f"types {i} {j}: excluded by neigh_modify (group {args[0]} with group "
                                    f"{args[1]}): no contact between them, not audited")
        elif style.startswith("molecule") and args:
            held = group_types(deck, args[0])
            if held is None or (i in held and j in held):
                return (*loc, line, f"types {i} {j}: neigh_modify excludes pairs by molecule, which the audit does "
                                    "not read: not audited")
    return _bonded(deck, i, j)


def _bonded(deck: Deck, i: int, j: int) -> tuple | None:
    """(loc, text, why) where the deck has bonds and a pair of types i j may hold bonded atoms whose
    contact is not the law's alone; None where it is. The audit cannot tell which atoms are bonded,
    so every pair is named. LAMMPS scales the pair force of 1-2, 1-3 and 1-4 neighbours along the
    bonds by special_bonds' three lj weights, leaving a weight-0 pair out of its lists (field round 47,
    Y21 Y22 Y27: weights 1 0 1 and 1 1 0 on a chain through the pair: LAMMPS -1, no contact, where the
    audit printed 0.4149 with no word, looking at the 1-2 weight only); and a bond style with a
    force pulls on its atoms during a contact (Y08: harmonic, LAMMPS 0.291769, the audit 0.4149).

    >>> d = Deck(ntypes=1, bonds=((None, 5), "create_bonds single/bond 1 1 3"), special_lj=(1.0, 0.0, 1.0))
    >>> _bonded(d, 1, 1)[3][:60]
    "types 1 1: bonded atoms' neighbours 1-3 get no contact (spec"
    >>> _bonded(replace(d, special_lj=(1.0, 1.0, 1.0)), 1, 1) is None
    True
    >>> _bonded(replace(d, special_lj=(1.0, 1.0, 1.0), bond_forces={"bond": ((None, 4), "bond_style harmonic")}),
    ...         1, 1)[3][:52]
    'types 1 1: bond_style harmonic pulls on bonded atoms'
    """
    if not deck.bonds:
        return None
    if deck.bond_forces:
        kind, (where, text) = next(iter(deck.bond_forces.items()))
        return (*where, text, f"types {i} {j}: {text} pulls on bonded atoms during a contact (a {kind} force beside "
                              "the contact law's), and the audit cannot tell which atoms are bonded: not audited")
    scaled = [(n, w) for n, w in zip(("1-2", "1-3", "1-4"), deck.special_lj) if w != 1.0]
    if not scaled:
        return None
    n, w = scaled[0]
    loc, line = deck.bonds
    what = "no contact" if w == 0 else f"their contact scaled by {w:g}"
    whom = "bonded atoms" if n == "1-2" else f"bonded atoms' neighbours {n}"
    return (*loc, line, f"types {i} {j}: {whom} get {what} (special_bonds' lj weights "
                        f"{' '.join(f'{x:g}' for x in deck.special_lj)}), and the audit cannot tell which atoms are "
                        "bonded: not audited")


def motion(deck: Deck, t: int, ran: bool = True) -> tuple[str, str]:
    """How the engine moves the spheres of type t: ("free", "") where an integrator moves them all
    (("free", why) where a moving fix's group cannot be typed, which why says),
    ("held", why) where none moves them or ``fix move linear`` keeps their velocity, ("unknown",
    why) where the audit cannot tell, or they move otherwise. A run with no moving fix at all moves
    no atom (LAMMPS says so: "No fixes with time integration, atoms won't move"): "held". Settings
    read where the deck has no run (``ran`` False: the decks written to be audited, not run) give
    "free": their pairs are audited as an integrator would move them."""
    if deck.still:
        where, line = deck.still
        return "unknown", (f"{where} ({line}) made the atoms anew and this run has pre no: LAMMPS moves no atom in "
                           "it (measured: positions and velocities unchanged over the run), so no contact happens "
                           "there")
    if not deck.movers:
        if ran:
            return "held", "no fix integrates any atom in this run"
        return "free", ""
    if (body := _in_body(deck, t)) is not None:
        return "unknown", body
    integrated, moved = [], []
    # moving fixes that may hold type t, one of them on a group the audit cannot type: a sphere in
    # two of them is advanced twice a step, or moved and integrated (field round 32, F13: fix
    # nve/sphere on all and on lv2, by ID: 0.414916 printed with the untyped group's note, LAMMPS
    # 0.323422, LIGGGHTS 0.386151; I05, fix move linear on lv2: LAMMPS 0.465219)
    # Groups made apart by subtract share no sphere (round 33, M12: a lid moved, the rest integrated)
    maybe = [(fix, group, held) for fix, (_, line, group, style) in deck.movers.items()
             if not rigid(style) and _moves_spheres(deck, style, t)
             and ((held := group_types(deck, group)) is None or t in held)]
    both = [(a, b) for k, a in enumerate(maybe) for b in maybe[k + 1:]
            if (a[2] is None or b[2] is None) and frozenset((a[1], b[1])) not in deck.disjoint]
    if both:
        named = ", ".join(f"fix {fix} (group {group})" for fix, group, _ in both[0])
        return "unknown", (f"{named} may each move type {t}'s spheres, a group among them the audit cannot type: "
                           "a sphere in two of them is advanced twice a step, and its eps differs")
    for fix, (loc, line, group, style) in deck.movers.items():
        if rigid(style) or not _moves_spheres(deck, style, t):
            continue
        held = group_types(deck, group)
        if held is None:
            # a group by region that an insertion fills, the usual LIGGGHTS deck: audited as free
            # spheres, and said
            return "free", (f"fix {fix} ({style}, {place(loc)}) moves group {group}, whose atoms the audit cannot "
                             "type: the pairs are audited as spheres that move freely; a sphere outside the group "
                             "never moves, and its eps differs")
        if t in held:
            if style in BROWNIAN:
                return "unknown", (f"fix {fix} ({style}) moves type {t} by overdamped random steps, its velocity "
                                   "not the contact's: no eps of the law is its")
            if (integrates := _integrates(line)) is None:
                return "unknown", (f"fix {fix} moves type {t} at a set velocity along some axes and integrates "
                                   "it under the force along the others (NULL): its eps depends on the "
                                   "contact's direction")
            (integrated if integrates else moved).append((fix, line))
    if integrated and moved:
        return "unknown", f"type {t} is both integrated and moved by fix {moved[0][1].split()[3]}"
    if moved:
        fix, line = moved[0]
        words = line.split()
        if words[3] == "nve/noforce":
            return "held", f"fix {fix} (nve/noforce) moves type {t} at its velocity, which no force changes"
        if len(words) > 4 and words[4] == "linear":
            return "held", f"fix {fix} moves type {t} at a constant velocity"
        return "unknown", f"fix {fix} moves type {t} on a path whose velocity changes"
    if integrated:
        return "free", ""
    return "held", f"no fix integrates type {t}: its spheres never move"


def phantom_velocity(deck: Deck, t: int) -> str | None:
    """Why spheres of type t, which no fix moves (none of the deck's moving fixes may hold them),
    may still hold a velocity, or None: a velocity command on a group that may hold them, or an
    inserting fix that made them (it gives its atoms a velocity). The engine leaves such a sphere in place, yet the contact's damping reads
    the velocity it holds (field round 17, w21: a still partner given 0.3 0.3 0.3, head-on at g = 1,
    LAMMPS 0.56423 where the still sphere gives the audit's 0.61384; LIGGGHTS the same, G17).

    Parameters
    ----------
    deck : Deck
        The deck at the run audited.
    t : int
        The sphere's type.

    Returns
    -------
    str or None

    Examples
    --------
    >>> d = Deck(ntypes=2, groups={"t1": {1}, "t2": {2}}, velocities=[((None, 9), "velocity t2 set 0.3 0 0", "t2")],
    ...          movers={"i": ((None, 8), "fix i t1 nve/sphere", "t1", "nve/sphere")})
    >>> phantom_velocity(d, 1) is None, phantom_velocity(d, 2)[:37]
    (True, 'line 9 velocity t2 set 0.3 0 0 gives ')
    """
    # a fix move or nve/noforce moves its atoms at the velocity they hold: what the damping reads
    if any(not _outside(deck, group, t) for _, _, group, style in deck.movers.values()
           if not rigid(style) and _moves_spheres(deck, style, t)):
        return None
    for loc, line, group in deck.velocities:
        held = group_types(deck, group)
        if held is None or t in held:
            return (f"{place(loc)} {line} gives type {t}'s spheres a velocity, and no fix integrates them: the "
                    "engine leaves them in place while the contact's damping reads that velocity")
    for inserted in deck.inserts:
        if inserted is None or t in inserted:
            return (f"an inserting fix makes type {t}'s spheres with a velocity, and no fix integrates them: the "
                    "engine leaves them in place while the contact's damping reads that velocity")
    return None


def _in_body(deck: Deck, t: int) -> str | None:
    """Why type t's spheres are not single spheres where a fix rigid joins some of them into bodies
    (a body's mass and motion are not one sphere's), None where none does. The bodies' atoms are
    the groups a ``group N g1 ... gN`` body style names, else the fix's own group; a type with any
    atom in them counts, and every type where the audit cannot type those groups."""
    for fix, (_, line, group, style) in deck.movers.items():
        if not rigid(style):
            continue
        words = line.split()
        named = (words[6:6 + int(words[5])] if len(words) > 5 and words[4] == "group" and words[5].isdigit()
                 else [group])
        held = [group_types(deck, g) for g in named]
        if any(h is None for h in held):
            return (f"fix {fix} ({style}) joins the atoms of group{'s' if len(named) > 1 else ''} "
                    f"{', '.join(named)} into rigid bodies, which the audit cannot type: a body's mass and "
                    "motion are not one sphere's")
        if any(t in h for h in held):
            return (f"fix {fix} ({style}) joins type {t}'s spheres into rigid bodies: a body's mass and motion are "
                    "not one sphere's")
    return None


def integrators(deck: Deck, t: int) -> list:
    """The fixes that integrate the spheres of type t, by their groups that the audit can type, in the
    deck's order: more than one advances them more than once a step (LAMMPS warns of atoms
    integrated more than once), each by a whole step with the same force.

    Examples
    --------
    >>> deck = Deck(ntypes=1, movers={"1": ((None, 5), "fix 1 all nve/sphere", "all", "nve/sphere"),
    ...                               "2": ((None, 6), "fix 2 all nve/sphere", "all", "nve/sphere")})
    >>> integrators(deck, 1)
    ['1', '2']
    """
    out = []
    for fix, (_, line, group, style) in deck.movers.items():
        if rigid(style) or not _moves_spheres(deck, style, t):
            continue                     # a body, not a sphere: its pairs are not audited (motion)
        held = group_types(deck, group)
        if _integrates(line) and held is not None and t in held:
            out.append(fix)
    return out


def held_contact(contact, pair, moving: int):
    """The contact the moving body ``moving`` (0 or 1) of a pair sees where the other never moves:
    the engine's force (m_eff of both masses) divided by the moving body's mass."""
    share = pair.m / (pair.m1, pair.m2)[moving]
    return replace(contact, D1=contact.D1 * share, D2=contact.D2 * share)


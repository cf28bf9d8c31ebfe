"""What acts on the atoms beside the contact law, and so changes the eps an engine measures: the
fixes of a deck that add a drag (``fix viscous``, the drag of ``fix langevin``), hold atoms still
(``freeze``), replace or cap their motion (``setforce``, ``nve/limit``), change coefficients as
the run goes (``adapt``) or damp every atom (``damping/cundall``, a global damping).

Where the effect has a size, it is computed for the audited collision: the two bodies head-on, the
total momentum zero at first touch (a frozen body at rest), each body's velocity changed by the
contact force and by what the fix adds, until the overlap returns to zero. That is what an engine
measures from the velocities after the bodies part (checked against LAMMPS running the collision
with ``fix viscous`` and ``fix freeze``: tests/library/test_dem_deck_beside.py).
"""

from __future__ import annotations

import math
import re
from functools import lru_cache

from ...core.collision import StickError
from ...fast.dop853 import solve
from ..contact import Contact
from ..dialect.state import number_or_none
from ..engines.lammps.deck import DEFAULT_DT, FTM2V
from ..pair import WALL_SIZE, Pair
from .meeting import group_types, held_contact

__all__ = ["ADAPT", "SETTING", "BESIDE", "adapt_parts", "adapted_diameter", "drag_eps", "effects", "gravity_vector"]

#: The fix adapt styles: adapt/fep (the FEP package) takes adapt's attributes and keywords, with the
#: same defaults (LAMMPS' documentation; field round 14, D4: it was taken for an unknown force)
ADAPT = frozenset({"adapt", "adapt/fep"})
#: Fixes that set their atoms' attributes or types as a run goes (fix set, LAMMPS 2025: the set
#: command every N steps; atom/swap: types swapped): a run that sees one is made for real
SETTING = frozenset({"set", "atom/swap"})
#: Fix style -> what it does to the atoms of its group, beside the contact law
BESIDE = {"viscous": "a drag force -gamma v on every atom of its group",
          "langevin": "a thermostat's drag force -m v / damp and a random force",
          "setforce": "forces set to given values", "freeze": "frozen atoms (no force moves them)",
          "nve/limit": "a cap on how far an atom moves per step",
          "adapt": "coefficients or sizes changed as the run goes",
          "adapt/fep": "coefficients or sizes changed as the run goes",
          "damping/cundall": "a global (Cundall) damping of every force on its atoms",
          "damp/viscous": "a drag force", "viscous/sphere": "a drag torque",
          "spring/self": "a spring tethering each atom to where it was", "addforce": "a force added to each atom",
          "efield": "an electric force q E on each charged atom",
          "gravity": "a gravity on the atoms of its group only",
          "lineforce": "the forces on its atoms cut to their component along a line",
          "planeforce": "the forces on its atoms cut to their components in a plane",
          "aveforce": "the forces on its atoms replaced by their group's average (two spheres of a contact in the "
                      "group: their contact forces cancel)",
          "drag": "a force pulling each atom towards a point",
          "momentum": "its group's momentum removed every few steps, which changes a sphere's velocity against a "
                      "wall, and with angular or rescale the velocities of two spheres unlike",
          "recenter": "its group's atoms shifted to keep their centre of mass in place, which moves a sphere "
                      "against a wall",
          "temp/berendsen": "a thermostat rescaling the velocities", "temp/rescale": "a thermostat rescaling the velocities",
          "temp/csvr": "a thermostat rescaling the velocities", "temp/csld": "a thermostat replacing the velocities",
          # integrators (meeting.INTEGRATORS) with a Nose-Hoover thermostat on the velocities they integrate
          "nvt/sphere": "a Nose-Hoover thermostat on the velocities", "npt/sphere": "a Nose-Hoover thermostat on the velocities",
          "nvt": "a Nose-Hoover thermostat on the velocities", "npt": "a Nose-Hoover thermostat on the velocities"}
#: The relative accuracy of drag_eps (its integration, DOP853, runs at 1e-4 of it: at 1e-3 it met
#: scipy's DOP853 at 1e-13 to 2e-9 only, where LSODA had met it to 8e-10): without drag it met the
#: library's eps to 4.5e-8 at worst over 6 exponent pairs, both end rules, 3 dampings, 3 speeds
RTOL = 1e-7
#: drag_eps's integration tolerance (relative; absolute, times the contact's reach and speed)
_SOLVER_TOL = RTOL / 10000


def drag_eps(contact: Contact, g: float, pair: Pair, drag: tuple = (0.0, 0.0), push: float = 0.0) -> float | None:
    """eps of a head-on collision with a linear drag on each body beside the contact force, and a
    constant acceleration of body 1 towards body 2 (gravity's component along the line of centres
    on a sphere against a wall or an immovable partner).

    Body k feels the contact force and ``-drag[k] m_k v_k`` (a drag rate per unit mass: fix viscous
    gamma / m, fix langevin 1 / damp); body 1 also ``push m_1``. The bodies start touching at
    approach speed ``g``, the total momentum zero; eps = -(v1 - v2) / g when the overlap returns to
    zero. The contact force is the contact's, per unit effective mass m_eff, clipped at zero under
    the force rule (LAMMPS' limit_damping).

    Parameters
    ----------
    contact : Contact
    g : float
        Approach speed at first touch.
    pair : Pair
        The bodies' masses (a wall: :meth:`Pair.wall`, which never moves).
    drag : tuple of float
        Drag rate of each body (1/time), >= 0.
    push : float, optional
        Acceleration of body 1 towards body 2 (negative: away from it), acting throughout.

    Returns
    -------
    float or None
        eps to about RTOL (0.0 where the energy of the relative motion, which a drag equal on both
        bodies only lowers, falls below what a parting at RTOL g needs: a drag that overdamps the
        contact); None where the bodies do not part (within 10^4 drag or contact times: a push
        that holds a slow sphere on the wall).

    Examples
    --------
    >>> c = Contact(1, 0, D1=1e4, D2=10.0, end="overlap")
    >>> p = Pair.spheres(0.5, 0.5, 1.0)
    >>> abs(drag_eps(c, 1.0, p) - c.eps(1.0)) < 1e-7              # no drag: the contact's own
    True
    >>> # a drag rate b on both bodies adds b to the dashpot's: the same eps as D2 + b
    >>> abs(drag_eps(c, 1.0, p, (5.0, 5.0)) - Contact(1, 0, 1e4, 15.0, "overlap").eps(1.0)) < 1e-7
    True
    >>> # a drag far stronger than the spring: the pair creeps apart for ever, eps 0 to RTOL
    >>> drag_eps(c, 1.0, p, (1e4, 1e4))
    0.0
    >>> # a push into a wall: the sphere rebounds slower (in.pour's wall law, gravity 1 into it)
    >>> w = Contact(1, 0, D1=2000 / (math.pi / 6), D2=50.0, end="overlap")
    >>> round(drag_eps(w, 1.0, Pair.wall(0.5, 1.0), push=1.0) - w.eps(1.0), 4)
    -0.0169
    """
    return _drag_eps(contact, float(g), pair, tuple(float(d) for d in drag), float(push))


@lru_cache(maxsize=4096)
def _drag_eps(contact: Contact, g: float, pair: Pair, drag: tuple, push: float) -> float | None:
    """:func:`drag_eps`, kept: a deck's walls of one law (a box's six planes, a stage after stage)
    ask the same collisions again."""
    wall = pair.m2 >= WALL_SIZE
    # each body's share of the force per unit m_eff: m_eff / m_k (a wall's none)
    share = [pair.m / pair.m1, 0.0 if wall else pair.m / pair.m2]
    rate = [float(drag[0]), 0.0 if wall else float(drag[1])]
    v0 = [g, 0.0] if wall else [g * pair.m2 / (pair.m1 + pair.m2), -g * pair.m1 / (pair.m1 + pair.m2)]
    a, c = float(contact.alpha), float(contact.gamma)
    D1, D2, clip = contact.D1, contact.D2, contact.end == "force"
    # the undamped contact's duration and reach: the scales of time and length
    reach = (g * g * (a + 1.0) / (2.0 * D1)) ** (1.0 / (a + 1.0))
    t_el = math.pi * reach / g
    t_max = 1e4 * max([t_el] + [1.0 / r for r in rate if r > 0])

    def force(x, v):
        if x <= 0.0:
            return 0.0
        f = D1 * x ** a + D2 * x ** c * v
        return max(f, 0.0) if clip else f

    def rhs(_t, y):
        x, v1, v2 = y
        f = force(x, v1 - v2)
        return [v1 - v2, -share[0] * f - rate[0] * v1 + push, share[1] * f - rate[1] * v2]

    def parted(_t, y):
        return y[0]
    events, spent = [parted], None
    # each body's drag the same (or a wall): the relative motion alone has an energy (below)
    conserved = wall or rate[0] == rate[1]
    if push > 0.0 and conserved:
        # The relative motion then has the energy E = v^2/2 + k D1 x^(a+1)/(a+1) - push x (per unit
        # m_eff), which the dashpot, an equal drag and the clipping only lower; parting at x = 0
        # needs E = v^2/2 >= 0. Once E < 0 the push holds the sphere for good: stop there, not after
        # t_max of a sphere settling on the wall (10^4 contact times at max_step t_el/50: seconds of
        # CPU per speed, which made the audit of a deck with gravity beside its walls slow).
        floor, k = -1e-9 * g * g, share[0] + share[1]

        def held(_t, y):
            x, v1, v2 = y
            v = v1 - v2
            return 0.5 * v * v + (k * D1 * x ** (a + 1.0) / (a + 1.0) if x > 0.0 else 0.0) - push * x - floor
        events.append(held)
    if push == 0.0 and conserved:
        # The same energy (no push) only falls; once below (RTOL g)^2 / 2 no parting is faster than
        # RTOL g: eps is 0 to RTOL. A drag stronger than the spring leaves the pair creeping apart
        # for ever (an overdamped Hooke contact never reaches x = 0): field round 45, O42, fix
        # langevin damp 1e-4, LAMMPS not parted after 3000 steps, where 10^4 contact times of steps
        # took 50 s per speed and printed a stray 1.6e-4.
        spent_below = 0.5 * (RTOL * g) ** 2

        def spent(_t, y):
            x, v1, v2 = y
            v = v1 - v2
            return 0.5 * v * v + (D1 * x ** (a + 1.0) / (a + 1.0) if x > 0.0 else 0.0) - spent_below
        events.append(spent)
    # Under the force rule the clipped force has a kink where the unclipped one changes sign, which
    # a step across it does not see (it cost 4e-7 of an eps of 0.019): the integration stops
    # there and starts again, the kink's sign flipped (it may come back: a push, a drag).
    def unclipped(_t, y):
        return sign * (D1 * y[0] ** a + D2 * y[0] ** c * (y[1] - y[2])) if y[0] > 0.0 else sign
    y, t, sign = [0.0, *v0], 0.0, 1.0
    kinds = events + ([unclipped] if clip else [])
    while True:
        got = solve(rhs, y, t_max - t, kinds, rtol=_SOLVER_TOL,
                    atol=[reach * _SOLVER_TOL, g * _SOLVER_TOL, g * _SOLVER_TOL], first_step=t_el * 1e-6,
                    max_step=t_el / 50)
        if got is None:
            return None              # not parted by t_max
        if kinds[got[0]] is spent:
            return 0.0               # too little energy left to part faster than RTOL g
        if kinds[got[0]] is not parted and kinds[got[0]] is not unclipped:
            return None              # held on the wall for good
        if kinds[got[0]] is parted or got[2][0] <= 0.0:     # parted (at the kink too, where the two meet)
            _, v1, v2 = got[2]
            return float(-(v1 - v2) / g)
        t, y, sign = t + got[1], got[2], -sign


def _keyword_ratios(words: list, start: int) -> dict:
    """{type: ratio} of the ``scale T ratio`` keywords from words[start:] on."""
    ratios, k = {}, start
    while k < len(words) - 2:
        if words[k] == "scale":
            try:
                ratios[int(words[k + 1])] = float(words[k + 2])
            except ValueError:
                pass
            k += 3
        else:
            k += 1
    return ratios


def effects(deck, row: dict, contact: Contact, pair: Pair, types: tuple, frozen_contact=None,
            faces: list | None = None, unmoved: int | None = None) -> list[dict]:
    """What each fix acting beside the contact does to one audited collision (a type pair, or a
    type on a wall): one dict per fix that acts on a body of it, {"fix", "style", "file", "line",
    "what", "eps_engine" (a list over ``row["speeds"]``, or None where no size is computed),
    "why", "along" (the axes along which a contact has that eps, as ["x"]; None: any)}.

    Parameters
    ----------
    deck : Deck
        The deck at the stage audited (its ``beside`` fixes, groups, units and time step).
    row : dict
        The audited row (``speeds``, ``eps``, ``sticks``, ``passes_through``).
    contact : Contact
    pair : Pair
    types : tuple
        The atom types of the two bodies ((t,) for a wall).
    frozen_contact : callable, optional
        ``frozen_contact(k)``: the contact the engine gives the pair where body k is frozen (its
        mass infinite); needed where a ``fix freeze`` holds one body of a pair.
    faces : list, optional
        A wall's faces with their normals, as its engine's reader gives them
        (:func:`restitution.dem.dialect.state.wall_faces`); None where they may point anywhere.
    unmoved : int, optional
        The body (0 or 1) of a pair that no fix integrates, ``contact`` then the other's motion
        alone (:func:`restitution.dem.deck.meeting.held_contact`).

    Returns
    -------
    list of dict

    Examples
    --------
    >>> from restitution.dem.dialect.state import Deck
    >>> d = Deck(ntypes=1, beside=[((None, 3), ["fix", "v", "all", "viscous", "0.5"])])
    >>> c, p = Contact(1, 0, 1e4, 10.0, "overlap"), Pair.spheres(0.5, 0.5, 1.0)
    >>> row = {"speeds": [1.0], "eps": [c.eps(1.0)], "sticks": [False], "passes_through": [False]}
    >>> e = effects(d, row, c, p, (1, 1))[0]
    >>> e["style"], round(e["eps_engine"][0], 6), round(row["eps"][0], 6)
    ('viscous', 0.841694, 0.854468)
    """
    out = []
    for loc, words in getattr(deck, "beside", []):
        style, group = words[3], words[2]
        if style == "gravity":
            entry = _gravity(deck, loc, words, types, row, contact, pair, frozen_contact, faces, unmoved)
            if entry is not None:
                out.append(entry)
            continue
        held = group_types(deck, group)
        acted = [t in held for t in types] if held is not None else None
        if acted is not None and not any(acted):
            continue
        if len(types) == 2 and acted is not None and all(acted) and (_alike(words) or _same_push(words, pair)):
            continue                       # both spheres shifted alike: their relative motion is as it was
        if style == "efield" and not _charged(deck, words, types, pair, acted):
            continue                       # no charge it acts on, or the same push on both spheres
        entry = {"fix": words[1], "style": style, "file": loc[0], "line": loc[1], "what": BESIDE[style],
                 "eps_engine": None, "why": "", "along": None}
        if acted is None:
            entry["why"] = f"group {group} has atoms the audit cannot type: its size is not computed"
        else:
            _size(entry, deck, row, contact, pair, types, words, acted, frozen_contact, faces)
        out.append(entry)
    return out


def _same_push(words: list, pair: Pair) -> bool:
    """Whether fix ``words`` is an addforce of constant components on every atom of its group, which
    on two spheres of one mass is the same acceleration each: their relative motion is as it was
    (field test round 12, a02: named for a pair of one type, where it changes nothing).

    Examples
    --------
    >>> p, q = Pair.spheres(0.5, 0.5, 1.0), Pair.spheres(0.5, 0.25, 1.0)
    >>> _same_push("fix f all addforce 0 0 -3".split(), p), _same_push("fix f all addforce 0 0 -3".split(), q)
    (True, False)
    >>> _same_push("fix f all addforce 0 0 v_fz".split(), p), _same_push("fix f all addforce 0 0 -3 region r".split(), p)
    (False, False)
    """
    return (words[3] == "addforce" and len(words) >= 7 and pair.m1 == pair.m2 and "region" not in words[7:]
            and all(number_or_none(w) is not None for w in words[4:7]))


def _charged(deck, words: list, types: tuple, pair: Pair, acted: list | None) -> bool:
    """Whether fix efield ``words`` may change one collision's relative motion: not where the charges
    the engine holds (``deck.charges``; {} where its atom style holds none) leave every body it acts
    on uncharged, nor, between two spheres it acts on in a field of constant components, where both
    hold one charge per mass (the same push on each: LAMMPS head-on, two spheres of 1e-7 C in 1e5
    V/m, eps as without the field to 2e-13). Where the charges are not known, it may.

    Examples
    --------
    >>> from restitution.dem.dialect.state import Deck
    >>> ef, p = "fix ef all efield 0 0 1e5".split(), Pair.spheres(0.001, 0.001, 2500.0)
    >>> d = Deck(charges={1: {0.0}, 2: {1e-9}})
    >>> [_charged(d, ef, t, p, [True] * len(t)) for t in ((1, 1), (1, 2), (2, 2), (1,), (2,))]
    [False, True, False, False, True]
    >>> _charged(Deck(charges={}), ef, (1, 2), p, [True, True]), _charged(Deck(), ef, (1, 1), p, [True, True])
    (False, True)
    """
    charges = getattr(deck, "charges", None)
    if charges == {}:
        return False                 # an atom style without a charge (LAMMPS then refuses the fix)
    if charges is None or acted is None or any(t not in charges for t in types):
        return True
    held = [charges[t] if on else {0.0} for t, on in zip(types, acted)]
    if all(q == {0.0} for q in held):
        return False
    constant = len(words) >= 7 and all(number_or_none(w) is not None for w in words[4:7]) and not (
        {"region", "energy", "potential"} & set(words[7:]))
    if len(types) == 2 and constant and all(acted) and all(len(q) == 1 for q in held):
        (q1,), (q2,) = held
        return not math.isclose(q1 * pair.m2, q2 * pair.m1, rel_tol=1e-12, abs_tol=0.0)
    return True


def _alike(words: list) -> bool:
    """Whether fix ``words`` changes the velocities or positions of every atom of its group alike
    (a linear momentum removed without rescaling; a shift of the whole group), which leaves two
    spheres of the group as they move relative to each other."""
    return words[3] == "recenter" or words[3] == "momentum" and not {"angular", "rescale"} & set(words[5:])


def _gravity(deck, loc, words: list, types: tuple, row: dict, contact: Contact, pair: Pair,
             frozen_contact=None, faces: list | None = None, unmoved: int | None = None) -> dict | None:
    """A gravity beside a collision where it changes the bodies' relative motion, or None where it
    cannot: both spheres of a pair in its group (they fall alike) or neither; a wall's sphere outside it.

    On a sphere against a wall it pushes the sphere into the wall (or pulls it off) during the
    contact with its component along the wall's normal, which changes the eps the engine measures
    (a constant force does no net work over a contact that ends where it began, but it shifts where
    the damping acts and when the contact ends). That eps is computed face by face where the
    wall's normal is known (``faces``, as the wall's engine reads them), at the two extreme directions
    where it is not."""
    held = group_types(deck, words[2])
    entry = {"fix": words[1], "style": "gravity", "file": loc[0], "line": loc[1], "what": BESIDE["gravity"],
             "eps_engine": None, "why": "", "along": None}
    if len(types) == 1:
        if held is not None and types[0] not in held:
            return None
        entry["what"] = "a gravity on the sphere, which pushes it into the wall or pulls it off during a contact"
        if _cut(deck, types, entry):
            return entry
        if held is None:
            entry["why"] = f"group {words[2]} has atoms the audit cannot type: the sphere may not fall; "
        _pushed_against(entry, deck, words, types[0], row, contact, pair, faces)
        if entry.get("faces") and not any(face["push"] for face in entry["faces"]):
            return None              # the field lies along every face: it moves the sphere across the contact only
        return entry
    if held is None:
        entry["why"] = (f"group {words[2]} has atoms the audit cannot type: it may accelerate one sphere and not "
                        "the other during a contact; its size is not computed")
        return entry
    acted = [t in held for t in types]
    if any(acted) and _cut(deck, types, entry, alike=acted[0] == acted[1]):
        return entry
    # a fix freeze zeroes the forces the fixes before it added (LAMMPS runs post_force in the order
    # the fixes were defined): a gravity defined after it moves the frozen atom too (measured)
    order = [w[1] for _, w in deck.beside]
    frozen = set().union(*[group_types(deck, w[2]) or set() for _, w in deck.beside
                           if w[3] == "freeze" and order.index(w[1]) > order.index(words[1])])
    still = [t in frozen for t in types]
    # a body no fix integrates, or whose every force a setforce 0 0 0 zeroes after the gravity
    # added its own (or where the gravity adds none), never moves; the engine's contact force
    # (m_eff of both masses) moves the other alone (LAMMPS measured)
    kept, partly = _set_still(deck, words, types, acted, order)
    if unmoved is not None:
        kept[unmoved] = True
    if partly and any(acted) and not any(still):
        entry["why"] = (f"a fix setforce that holds the type {partly[0]} sphere along some axes only, or sets a "
                        "value other than 0: with the gravity its size (which depends on the directions) is not "
                        "computed")
        return entry
    if kept.count(True) == 1 and not any(still):
        moving = kept.index(False)
        alone = contact if unmoved is not None else held_contact(contact, pair, moving)
        return _onto_still(entry, deck, words, row, pair, types, acted, moving, alone,
                           "its partner (which never moves)")
    if kept.count(True) == 2 and not any(still):
        return None                  # neither moves: the collision does not happen (said beside it)
    if still.count(True) == 1 and frozen_contact is not None:
        moving = still.index(False)
        return _onto_still(entry, deck, words, row, pair, types, acted, moving, frozen_contact(1 - moving),
                           "its frozen partner")
    if acted[0] == acted[1]:
        return None                  # both bodies fall alike, or neither falls: the relative motion is the contact's
    pushed = types[acted.index(True)]
    entry["why"] = (f"it accelerates the type {pushed} sphere and not the other, so it pushes the spheres together "
                    "or apart during a contact; its size (which depends on the direction of the field against the "
                    "line of centres) is not computed")
    return entry


def _cut(deck, types: tuple, entry: dict, alike: bool = False) -> bool:
    """Whether a fix lineforce or planeforce acts on a body of the collision, which cuts the
    gravity's force too where it is defined after it: the gravity's size is then not computed
    (entry's why says so). ``alike``: the gravity acts on both bodies of a pair, which it still
    accelerates alike where each cut holds both or neither (then not named here)."""
    cutting = []
    for _, w in deck.beside:
        if w[3] in ("lineforce", "planeforce"):
            held = group_types(deck, w[2])
            on = [True, True] if held is None else [t in held for t in types]
            if any(on) and not (alike and len(types) == 2 and held is not None and on[0] == on[1]):
                cutting.append(w)
    if cutting:
        entry["why"] = (f"beside the fix {cutting[0][3]} ({cutting[0][1]}), which cuts the forces on its atoms to a "
                        "direction (the gravity's too where defined before it), its size is not computed")
    return bool(cutting)


def _onto_still(entry: dict, deck, words: list, row: dict, pair: Pair, types: tuple, acted: list, moving: int,
                alone: Contact, partner: str) -> dict | None:
    """The gravity ``words`` on a pair whose body ``moving`` meets a partner that does not move
    (``alone``: the contact the moving body sees), entry updated; None where the gravity does not
    act on the moving body (the partner's is zeroed, or it has none)."""
    if not acted[moving]:
        return None
    if deck.code != "LAMMPS":
        entry["why"] = (f"it pushes the moving sphere into {partner} or pulls it off during a contact; its size is "
                        "computed for LAMMPS only (whose m_eff there was checked)")
        return entry
    entry["what"] = f"a gravity on the moving sphere, which pushes it into {partner} or pulls it off during a contact"
    _pushed_against(entry, deck, words, types[moving], row, alone,
                    Pair((pair.R1, pair.R2)[moving], WALL_SIZE, (pair.m1, pair.m2)[moving], WALL_SIZE), None,
                    sphere=True)
    return entry


def _set_still(deck, words: list, types: tuple, acted: list, order: list) -> tuple[list, list]:
    """([whether each body of a pair keeps its velocity under the fix setforce that hold it, with the
    gravity ``words``], [types a setforce holds otherwise: along some axes only, to a value, with a
    keyword]). A setforce 0 0 0 zeroes every force the fixes before it added (LAMMPS runs post_force
    in the order the fixes were defined): a gravity after it moves the body, one before it does not."""
    kept, partly = [False] * len(types), []
    for _, w in deck.beside:
        if w[3] != "setforce" or (held := group_types(deck, w[2])) is None:
            continue
        for k, t in enumerate(types):
            if t not in held:
                continue
            if len(w) == 7 and all(number_or_none(v) == 0.0 for v in w[4:7]):
                kept[k] = kept[k] or order.index(w[1]) > order.index(words[1]) or not acted[k]
            elif any(v != "NULL" for v in w[4:7]) or len(w) > 7:
                partly.append(t)
    return kept, partly


#: Unit styles whose force / mass is the acceleration fix gravity's magnitude gives (LAMMPS'
#: force->ftm2v is 1 in them; LIGGGHTS runs si or cgs)
_GRAVITY_UNITS = ("lj", "si", "cgs")


def gravity_vector(words: list, dimension: int = 3) -> tuple | None:
    """fix ID group gravity MAGNITUDE STYLE ARGS as the acceleration vector (gx, gy, gz) the
    engines give a run (LAMMPS' and LIGGGHTS' styles vector, spherical, chute; in 2-d LAMMPS turns
    spherical's theta in the xy plane from +y and ignores phi), or None where it is not a number
    this reads (a variable, another style).

    Parameters
    ----------
    words : list of str
        The fix's words.
    dimension : int, optional
        The deck's (2 or 3).

    Returns
    -------
    tuple of float, or None

    Examples
    --------
    >>> [round(c, 12) + 0.0 for c in gravity_vector("fix 2 all gravity 1.0 spherical 0.0 -180.0".split())]
    [0.0, 0.0, -1.0]
    >>> [round(c, 4) + 0.0 for c in gravity_vector("fix 2 all gravity 1.0 chute 26.0".split())]
    [0.4384, 0.0, -0.8988]
    >>> [round(c, 12) + 0.0 for c in gravity_vector("fix 2 all gravity 1.0 spherical 0.0 -180.0".split(), 2)]
    [0.0, -1.0, 0.0]
    >>> gravity_vector("fix g all gravity 9.81 vector 0 0 -2".split())
    (0.0, 0.0, -9.81)
    >>> gravity_vector("fix g all gravity v_g vector 0 0 -1".split()) is None
    True
    """
    size = number_or_none(words[4]) if len(words) > 4 else None
    style, args = (words[5], [number_or_none(w) for w in words[6:]]) if len(words) > 5 else (None, [])
    if size is None or any(a is None for a in args):
        return None
    if style == "vector" and len(args) == 3 and dimension == 2:
        args[2] = 0.0                        # LAMMPS ignores z in 2-d
    if style == "vector" and len(args) == 3 and any(args):
        norm = math.sqrt(sum(a * a for a in args))
        return tuple(size * a / norm for a in args)
    if style in ("spherical", "chute"):
        # LAMMPS' fix gravity: chute ANGLE is spherical phi = 0, theta = 180 - ANGLE
        phi, theta = (0.0, 180.0 - args[0]) if style == "chute" and len(args) == 1 else (
            tuple(args) if style == "spherical" and len(args) == 2 else (None, None))
        if phi is None:
            return None
        phi, theta = math.radians(phi), math.radians(theta)
        if dimension == 2:
            return (size * math.sin(theta), size * math.cos(theta), 0.0)
        return (size * math.sin(theta) * math.cos(phi), size * math.sin(theta) * math.sin(phi),
                size * math.cos(theta))
    return None


def _pushed_against(entry: dict, deck, words: list, t: int, row: dict, contact: Contact, pair: Pair, faces,
                    sphere: bool = False) -> None:
    """entry's "faces" and "eps_engine" under the gravity ``words``, with every other fix gravity on
    the moving sphere (type ``t``), along the normals ``faces``
    (:func:`restitution.dem.dialect.state.wall_faces`; None: the two extreme directions).
    ``sphere``: the sphere moves against an immovable sphere (``pair`` the moving one against an
    infinite mass, ``contact`` its own)."""
    field, others = _gravities(deck, words, t)
    if field is None or deck.units not in _GRAVITY_UNITS:
        entry["why"] += (f"its size is not computed ({others})" if field is None
                         else f"its size is not computed in units {deck.units}")
        return
    if others:
        entry["why"] += f"with the fix gravity {', '.join(others)} on the same sphere (their sum acts): "
    size = math.sqrt(sum(c * c for c in field))
    partner, line = ("its partner", "line of centres") if sphere else ("the wall", "wall's normal")
    if faces is None:
        pushes = [(f"into {partner}, the {line} along the field" + ("" if sphere else " (not known here)"), size),
                  (f"off {partner}, against the field", -size)]
    else:
        pushes = []
        for what, normal in faces:
            if isinstance(normal, tuple):
                pushes.append((what, -sum(f * n for f, n in zip(field, normal))))
            elif normal >= 0:
                pushes += [(f"{what}, from the side gravity pushes into it", abs(field[normal])),
                           (f"{what}, from the other side", -abs(field[normal]))]
            else:
                across = math.sqrt(sum(c * c for k, c in enumerate(field) if k != -normal - 1))
                pushes += [(f"{what}, where it points along the field's part across it", across),
                           (f"{what}, where it points against it", -across)]
    # a component below 1e-12 of the field is the rounding of sin(180 deg) and the like: none
    pushes = [(what, 0.0 if abs(push) <= 1e-12 * size else push) for what, push in pushes]
    entry["faces"] = [{"face": what, "push": push,
                       "eps_engine": _over_speeds(row, lambda g, p=push: _pushed_eps(contact, g, pair, p))}
                      for what, push in pushes]
    if len(entry["faces"]) == 1:
        entry["eps_engine"] = entry["faces"][0]["eps_engine"]
    entry["why"] += (f"the contact law integrated with gravity's component along the {line} acting on the "
                     f"sphere (0 where the sphere does not leave {partner})")


def _gravities(deck, words: list, t: int) -> tuple:
    """(the acceleration of the gravity ``words`` and every other fix gravity on type t's spheres
    together, [the others' IDs]): LAMMPS and LIGGGHTS add them (field round 47, G07: two fixes of 250
    down, LAMMPS 0.260657 off the floor where each fix's note computed alone said 0.316664). (None,
    why) where one's magnitude or direction is not read, or its group cannot be typed.

    >>> from restitution.dem.dialect.state import Deck
    >>> d = Deck(ntypes=1, groups={"all": {1}}, beside=[((None, 3), "fix a all gravity 9 vector 0 0 -1".split()),
    ...                                                  ((None, 4), "fix b all gravity 3 vector 0 0 -1".split())])
    >>> _gravities(d, d.beside[0][1], 1)
    ((0.0, 0.0, -12.0), ['b'])
    """
    dimension = getattr(deck, "dimension", 3)
    total, others = [0.0, 0.0, 0.0], []
    for _, w in deck.beside:
        if w[3] != "gravity":
            continue
        if w[1] != words[1]:
            held = group_types(deck, w[2])
            if held is None:
                return None, f"beside the fix gravity {w[1]}, whose group the audit cannot type"
            if t not in held:
                continue
            others.append(w[1])
        field = gravity_vector(w, dimension)
        if field is None:
            return None, "a magnitude or direction this does not read"
        total = [a + b for a, b in zip(total, field)]
    return tuple(total), others


def _pushed_eps(contact: Contact, g: float, pair: Pair, push: float) -> float:
    """eps under a constant push; the contact's own where there is none; 0 where it holds the sphere."""
    if push == 0:
        return _eps(contact, g)
    eps = drag_eps(contact, g, pair, push=push)
    return 0.0 if eps is None else eps


def _size(entry: dict, deck, row: dict, contact: Contact, pair: Pair, types: tuple, words: list,
          acted: list, frozen_contact, faces: list | None = None) -> None:
    """The size of one fix's effect, where it has one the audit can compute (entry updated)."""
    style = words[3]
    if style in ("lineforce", "planeforce"):
        _projected(entry, deck, row, contact, pair, types, words, acted, faces)
        return
    wall = len(types) == 1
    masses = (pair.m1,) if wall else (pair.m1, pair.m2)
    drag = None
    if style in ("viscous", "langevin") and deck.units in FTM2V:
        # where LAMMPS' ftm2v is not 1 a drag's rate is not gamma / m (not checked there)
        entry["why"] = f"its size is not computed in units {deck.units}"
        return
    if style == "viscous" and len(words) > 4 and (gamma := number_or_none(words[4])) is not None and gamma >= 0:
        ratios = _keyword_ratios(words, 5)
        drag = tuple(gamma * ratios.get(t, 1.0) / m if on else 0.0 for t, m, on in zip(types, masses, acted))
    elif style == "langevin" and len(words) > 6 and (damp := number_or_none(words[6])) is not None and damp > 0:
        ratios = _keyword_ratios(words, 8)
        drag = tuple(1.0 / (damp * ratios.get(t, 1.0)) if on else 0.0 for t, on in zip(types, acted))
        entry["why"] = ("its drag alone; its random force (temperature from " + words[4] + ") scatters the eps "
                        "around this")
    elif style == "setforce":
        _setforce(entry, deck, row, contact, pair, types, words, acted, faces)
        return
    elif style == "aveforce" and len(words) > 6 and all(v == "NULL" for v in words[4:7]) and len(words) == 7:
        # every component NULL: LAMMPS averages no force (field round 17, a37, a form research decks use)
        entry["eps_engine"], entry["why"] = list(row["eps"]), "every component NULL: it changes no force"
        return
    elif style == "freeze" and deck.code != "LAMMPS":
        entry["why"] = "its size is computed for LAMMPS only (whose m_eff with a frozen atom was checked)"
        return
    elif style == "freeze":
        if all(acted) or wall:
            # freeze zeroes forces and torques, not velocities: a frozen sphere in flight goes on through
            # what it meets (field round 39, X33: through the floor, LAMMPS then loses the atom)
            entry["why"] = ("every body of this collision is frozen (no force moves it; it keeps its velocity): no "
                            "contact force turns them back, so the collision has no eps" if all(acted) else
                            "the sphere is frozen (no force moves it; it keeps its velocity): the wall cannot turn "
                            "it back, so the collision has no eps")
            return
        # the engine's granular pair styles take the moving atom's mass for m_eff where the other
        # is frozen (checked in LAMMPS): the contact of that atom against an immovable one
        moving = frozen_contact(acted.index(True))
        entry["eps_engine"] = _over_speeds(row, lambda g: _eps(moving, g))
        entry["why"] = "a frozen body keeps its velocity whatever the force: eps in its frame"
        return
    elif style == "viscous/sphere":
        entry["eps_engine"] = list(row["eps"])
        entry["why"] = "a torque only: a head-on collision does not turn the bodies, its eps is the contact's"
        return
    elif style == "nve/limit" and len(words) > 4 and (xmax := number_or_none(words[4])) is not None and xmax > 0:
        dt = deck.dt if deck.dt is not None else DEFAULT_DT.get(deck.units)
        if dt:
            cap = xmax / dt
            over = [g for g in row["speeds"] if g > cap]
            entry["why"] = (f"each atom's speed is capped at xmax / dt = {cap:.4g}" + (
                f": at g = {', '.join(f'{g:.4g}' for g in over)} an atom may reach it, and eps is then not the "
                "contact's" if over else ", above every speed audited: eps is the contact's"))
            if not over:
                entry["eps_engine"] = list(row["eps"])
        return
    elif style in ADAPT:
        _adapt(entry, deck, row, words)
        return
    else:
        entry["why"] = "its size is not computed"
        return
    if drag is not None:
        if not wall and len(set(drag)) > 1:
            entry["why"] = (entry["why"] + "; " if entry["why"] else "") + (
                "the bodies' drag rates differ, so eps depends on their common velocity: given where the "
                "total momentum is zero at first touch")
        full = drag if not wall else (drag[0], 0.0)
        entry["eps_engine"] = _over_speeds(row, lambda g: drag_eps(contact, g, pair, full))


#: fix adapt's attributes -> how many words follow each (LAMMPS 22 Jul 2025: pair pstyle pparam I J
#: v_name; bond and angle bstyle bparam v_name; kspace v_name; atom attribute v_name), and its keywords
_ADAPT_ATTRIBUTES = {"pair": 5, "bond": 3, "angle": 3, "kspace": 1, "atom": 2}
#: adapt/fep's atom attribute names the atom type it changes before its variable (diameter 2 v_d)
_FEP_ATTRIBUTES = {**_ADAPT_ATTRIBUTES, "atom": 3}
_ADAPT_KEYWORDS = ("scale", "reset", "mass", "after")


def adapt_parts(words: list) -> tuple[list, dict]:
    """The attributes and keywords of a fix adapt.

    Parameters
    ----------
    words : list of str
        fix ID group adapt N attribute args ... keyword value ..., as the engine ran it.

    Returns
    -------
    tuple
        ([(attribute, its words)], {keyword: value}); a word that is neither ends the reading
        (LAMMPS stops on it).

    Examples
    --------
    >>> adapt_parts("fix a all adapt 0 atom diameter v_d reset yes".split())
    ([('atom', ['diameter', 'v_d'])], {'reset': 'yes'})

    adapt/fep's atom attribute takes a type (its sizes never count as one constant diameter for
    the group):

    >>> adapt_parts("fix a all adapt/fep 1 atom diameter 2 v_d".split())
    ([('atom', ['diameter', '2', 'v_d'])], {})
    """
    attributes = _FEP_ATTRIBUTES if len(words) > 3 and words[3] == "adapt/fep" else _ADAPT_ATTRIBUTES
    parts, keys, k = [], {}, 5
    while k < len(words):
        if words[k] in attributes:
            n = attributes[words[k]]
            parts.append((words[k], words[k + 1:k + 1 + n]))
            k += 1 + n
        elif words[k] in _ADAPT_KEYWORDS and k + 1 < len(words):
            keys[words[k]] = words[k + 1]
            k += 2
        else:
            break
    return parts, keys


#: The names an equal-style formula may hold and still be a constant: numbers, operators and these
#: math functions (a step, time, ramp, another variable, a compute or an atom's value may change)
_CONSTANT_NAMES = frozenset({"sqrt", "exp", "ln", "log", "abs", "sin", "cos", "tan", "asin", "acos", "atan",
                             "atan2", "ceil", "floor", "round", "PI", "e", "E"})


def adapted_diameter(deck, words: list) -> float | None:
    """The one diameter a fix adapt gives the atoms of its group, where its every attribute is
    ``atom diameter v_NAME``, NAME an equal-style variable of a constant formula, and it does not
    scale; else None (it changes coefficients, or sizes as the run goes).

    Parameters
    ----------
    deck : Deck
        The deck as read so far (its equal-style variables).
    words : list of str
        fix ID group adapt N attribute args ... keyword value ..., as the engine ran it.

    Returns
    -------
    float or None

    Examples
    --------
    A constant formula gives its diameter; one that grows with the step gives none:

    >>> from restitution.dem.dialect.state import Deck
    >>> d = Deck(variables={"d": "2*0.003", "t": "0.006+1e-6*step"})
    >>> adapted_diameter(d, "fix a all adapt 0 atom diameter v_d".split())
    0.006
    >>> adapted_diameter(d, "fix a all adapt 0 atom diameter v_t".split()) is None
    True
    """
    parts, keys = adapt_parts(words)
    names = [args[1][2:] for kind, args in parts if kind == "atom" and len(args) == 2 and args[0] == "diameter"
             and args[1].startswith("v_")]
    if not parts or len(names) < len(parts) or keys.get("scale", "no") != "no":
        return None
    values = [_constant(deck.variables.get(name)) for name in names]
    return None if None in values else values[-1]


def _constant(formula: str | None) -> float | None:
    """The value of an equal-style formula of numbers, operators and math functions alone (LAMMPS'
    ^ is a power), None where it holds anything else (a step, time, another variable) or fails."""
    if formula is None or set(re.findall(r"[A-Za-z_]\w*", re.sub(r"\d[eE][-+]?\d", "0", formula))) - _CONSTANT_NAMES:
        return None
    if not re.fullmatch(r"[\w.+\-*/^()\s,]*", formula):
        return None
    names = {name: getattr(math, name.lower(), None) for name in _CONSTANT_NAMES}
    names.update(PI=math.pi, E=math.e, e=math.e, ln=math.log, log=math.log10, abs=abs, round=round)
    try:
        value = eval(formula.replace("^", "**"), {"__builtins__": {}}, names)   # names checked above
    except (ArithmeticError, SyntaxError, TypeError, ValueError):
        return None
    return float(value) if isinstance(value, (int, float)) and math.isfinite(value) else None


def _adapt(entry: dict, deck, row: dict, words: list) -> None:
    """fix adapt whose every attribute is ``atom diameter v_NAME``, NAME an equal-style variable of a
    constant formula: it gives every atom of its group that one diameter at each run's set-up (and
    every N steps) and keeps it so through the run (LAMMPS measured: the engine's pass holds the
    adapted size, and no keyword but reset yes, refused by the reader, undoes it); the sizes audited
    are those, and eps is the contact's. The atoms a LAMMPS pour makes keep the pour's size until
    the adapt resizes them (LAMMPS measured: N = 0, at the next run's set-up; N = 10, within 10
    steps), which the reader follows (:func:`restitution.dem.deck.reader.read_executed`): the sizes
    audited hold both. Anything else changes coefficients or sizes the audit does not follow
    (entry updated)."""
    parts, keys = adapt_parts(words)
    names = [args[1][2:] for kind, args in parts if kind == "atom" and len(args) == 2 and args[0] == "diameter"
             and args[1].startswith("v_")]
    if not parts or len(names) < len(parts) or keys.get("scale", "no") != "no":
        entry["why"] = "it changes coefficients, or sizes otherwise than by a diameter variable: its size is not computed"
        return
    formulas = [deck.variables.get(name) for name in names]
    if adapted_diameter(deck, words) is None:
        entry["why"] = (f"its diameter variable{'s' if len(names) > 1 else ''} "
                        f"{', '.join('v_' + n for n in names)} may change as the run goes (not an equal-style "
                        "constant): its size is not computed")
        return
    inserted = also = ""
    if getattr(deck, "inserting", False):
        if deck.code != "LAMMPS" or deck.deposits:
            entry["why"] = ("a fix inserts atoms as the runs go, which it may resize at a later set-up or step, and "
                            "which the reader follows for LAMMPS' pours only: its size is not computed")
            return
        inserted = ("; the atoms a pour makes keep the pour's size until the adapt resizes them (at the next run's "
                    "set-up where N is 0, within N steps else), which the audit follows")
        also = " and the pour's"
    entry["eps_engine"] = list(row["eps"])
    entry["what"] = "the atoms' diameters set from a variable"
    entry["why"] = (f"it sets the diameter of the atoms of group {words[2]} to the constant "
                    f"{' and '.join(f'v_{n} = {f}' for n, f in zip(names, formulas))} at the run's set-up, which the "
                    f"engine's pass made{inserted}: the sizes audited are the adapted ones{also}, and eps is the "
                    "contact's")


#: fix setforce's components, in order
_AXES = ("x", "y", "z")


def _setforce(entry: dict, deck, row: dict, contact: Contact, pair: Pair, types: tuple, words: list,
              acted: list, faces: list | None = None) -> None:
    """fix ID group setforce fx fy fz: where every component given is a constant zero (the others
    NULL) and no keyword follows, the body of the group keeps its velocity along those axes whatever
    the contact's force. A head-on contact along such an axis then moves the other body alone, under
    the engine's force of both masses (m_eff; unlike freeze, which makes the engine take the other
    body's mass for m_eff): :func:`restitution.dem.deck.meeting.held_contact`. A contact along an
    axis left NULL is the contact's own; an oblique one lies between, not computed. Its torque is not
    set, which a head-on collision does not use. (entry updated)"""
    values, keywords = words[4:7], words[7:]
    zero = [axis for axis, v in zip(_AXES, values) if number_or_none(v) == 0.0]
    set_otherwise = [v for v in values if v != "NULL" and number_or_none(v) != 0.0]
    if len(values) < 3 or keywords or set_otherwise:
        entry["why"] = ("a component set to a value other than 0 or NULL (a force, a variable), or a keyword "
                        "(region): its size is not computed")
        return
    if not zero:
        entry["eps_engine"], entry["why"] = list(row["eps"]), "every component NULL: it sets no force"
        return
    free = [axis for axis in _AXES if axis not in zero]
    # zeroing some components keeps the force's projection on the others: where every contact the
    # collision may have lies along those (a 2d deck's contacts, held in z), it changes nothing
    if free:
        unit = {axis: tuple(float(a == axis) for a in _AXES) for axis in _AXES}
        style, u = ("lineforce", unit[free[0]]) if len(free) == 1 else ("planeforce", unit[zero[0]])
        if _projection_over(style, u, *_contact_normals(deck, types, faces)) == "whole":
            entry["eps_engine"] = list(row["eps"])
            entry["why"] = (f"every contact this collision may have lies along {' and '.join(free)}, which it leaves "
                            "alone")
            return
    if deck.code != "LAMMPS":
        entry["why"] = "its size is computed for LAMMPS only (whose m_eff with a force set to zero was checked)"
        return
    along = (f"along {' and '.join(zero)} (the component{'s' if len(zero) > 1 else ''} it sets to zero)" if free
             else "along any axis")
    if len(types) == 1 or all(acted):
        entry["why"] = (f"{along} {'the sphere' if len(types) == 1 else 'every body of this collision'} keeps its "
                        "velocity whatever the force: no rebound there")
        entry["along"] = zero if free else None
        return
    moving = held_contact(contact, pair, acted.index(False))
    reach = pair.R1 + pair.R2
    entry["eps_engine"] = [None if eps is None or moving.reaches(g, reach) else _eps(moving, g)
                           for g, eps in zip(row["speeds"], row["eps"])]
    entry["along"] = zero if free else None
    entry["why"] = (f"{along} the type {types[acted.index(True)]} body keeps its velocity whatever the force, and "
                    "the engine's force (of both masses) moves the other alone: eps in its frame"
                    + (f"; along {' and '.join(free)} the contact's own, an oblique contact between the two (not "
                       "computed)" if free else ""))


def _kept_along(style: str, u: tuple, n: tuple) -> float:
    """The share of a force along the unit vector ``n`` that fix lineforce or planeforce (unit
    direction ``u``) leaves along ``n``: (n.u)^2 for a line, 1 - (n.u)^2 for a plane's normal."""
    c = sum(a * b for a, b in zip(u, n)) ** 2
    return c if style == "lineforce" else 1.0 - c


def _contact_normals(deck, types: tuple, faces: list | None) -> tuple[str, list | None]:
    """Where a collision's line of centres may point: ("any", None) in 3d, ("circle", [axis]) for
    every direction across an axis (a 2d deck's contacts lie in xy; a cylinder wall's normal lies
    across its axis), ("list", normals) for a wall whose faces' normals are known."""
    axes = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    if len(types) == 1 and faces:
        normals, circles = [], []
        for _, n in faces:
            if isinstance(n, tuple):
                normals.append(n)
            elif n >= 0:
                normals.append(axes[n])
            else:
                circles.append(axes[-n - 1])
        if circles and normals or len(set(circles)) > 1:
            return "any", None
        return ("circle", circles[:1]) if circles else ("list", normals)
    if getattr(deck, "dimension", 3) == 2:
        return "circle", [axes[2]]
    return "any", None


def _projection_over(style: str, u: tuple, kind: str, where: list | None) -> str:
    """"whole" where fix lineforce/planeforce (unit direction ``u``) leaves a contact's force along
    every normal it may have whole, "none" where it removes it along every one, else "mixed"."""
    if kind == "list":
        kept = [_kept_along(style, u, n) for n in where]
    elif kind == "circle":
        # over the directions n across the axis a, (n.u)^2 runs from 0 to |u|^2 - (a.u)^2
        c = sum(x * y for x, y in zip(u, where[0])) ** 2
        across = 1.0 - c
        kept = [0.0, across] if style == "lineforce" else [1.0, 1.0 - across]
    else:
        return "mixed"
    if all(abs(k - 1.0) <= 1e-12 for k in kept):
        return "whole"
    if all(abs(k) <= 1e-12 for k in kept):
        return "none"
    return "mixed"


def _projected(entry: dict, deck, row: dict, contact: Contact, pair: Pair, types: tuple, words: list,
               acted: list, faces: list | None) -> None:
    """fix ID group lineforce|planeforce x y z: each step the force on the group's atoms is cut to
    its component along the line (x, y, z), or to its components in the plane of that normal; their
    velocities are not touched. A head-on contact whose line of centres the force keeps whole has the
    contact's eps; one across the line (along the plane's normal) moves no body of the group: two such
    bodies pass through each other, one keeps its velocity while the engine's force (of both masses)
    moves the other alone (as a setforce 0 along it; LAMMPS measured); one between, an oblique
    collision, is not computed. A pair's force is always cut (LAMMPS computes it before the fixes
    act); a wall's only where the wall's fix is defined before this one (the fixes add and cut
    forces in the order they were defined; LAMMPS measured), which the audit does not follow. Where
    the collision's direction is not known and the effect depends on it, no eps is the engine's.
    (entry updated)"""
    style = words[3]
    u = [number_or_none(w) for w in words[4:7]]
    norm = math.sqrt(sum(x * x for x in u)) if len(u) == 3 and None not in u else 0.0
    if len(words) != 7 or norm == 0.0:
        entry["why"] = "its direction is not three numbers (a variable, a zero vector): its size is not computed"
        return
    u = tuple(x / norm for x in u)
    line = (f"the line ({' '.join(words[4:7])})" if style == "lineforce"
            else f"the plane of normal ({' '.join(words[4:7])})")
    kind, where = _contact_normals(deck, types, faces)
    over = _projection_over(style, u, kind, where)
    across = "across the line" if style == "lineforce" else "along the plane's normal"
    along = "along the line" if style == "lineforce" else "in the plane"
    wall = len(types) == 1
    if over == "whole":
        entry["eps_engine"] = list(row["eps"])
        entry["why"] = f"every contact this collision may have lies {along} ({line}), which keeps its force whole"
        return
    if wall:
        entry["why"] = (f"where the wall's fix is defined before it (the engine adds and cuts the forces in the order "
                        f"the fixes were defined) it cuts the wall's force on the sphere to {line}: "
                        + ("a contact " + across + " then has no force and the sphere passes through the wall; "
                           if over == "none" else
                           f"a contact {along} keeps the contact's eps, one {across} has no force (the sphere passes "
                           "through the wall), one between differs; ")
                        + "where the wall's fix is defined after it, the contact's own: the audit does not follow "
                        "that order, no eps is the engine's")
        return
    if over == "none" and all(acted):
        entry["why"] = (f"it cuts the contact's force on both bodies to {line}, across which every contact this "
                        "collision may have lies: no force moves them apart, they pass through each other (no rebound)")
        return
    if over == "none":
        if deck.code != "LAMMPS":
            entry["why"] = (f"it cuts the force on the type {types[acted.index(True)]} body to {line}, across which "
                            "every contact lies: that body keeps its velocity; its size is computed for LAMMPS only")
            return
        moving = held_contact(contact, pair, acted.index(False))
        reach = pair.R1 + pair.R2
        entry["eps_engine"] = [None if eps is None or moving.reaches(g, reach) else _eps(moving, g)
                               for g, eps in zip(row["speeds"], row["eps"])]
        entry["why"] = (f"it cuts the force on the type {types[acted.index(True)]} body to {line}, across which every "
                        "contact lies: that body keeps its velocity whatever the force, and the engine's force (of "
                        "both masses) moves the other alone: eps in its frame")
        return
    held = ("both bodies pass through each other, no rebound" if all(acted) else
            f"the type {types[acted.index(True)]} body keeps its velocity while the engine's force moves the other "
            "alone")
    entry["why"] = (f"it cuts the force on its atoms to {line}: a contact {along} has the contact's eps, one {across} "
                    f"has no force on them ({held}), an oblique one lies between; the collision's direction is not "
                    "known here: no eps is the engine's")


def _eps(contact: Contact, g: float) -> float:
    """The contact's eps, 0 where the bodies stick."""
    try:
        return contact.eps(g)
    except StickError:
        return 0.0


def _over_speeds(row: dict, eps_at) -> list:
    """eps_at(g) at each speed the row has an eps for (None elsewhere)."""
    return [None if through or stick else eps_at(g)
            for g, stick, through in zip(row["speeds"], row["sticks"], row["passes_through"])]

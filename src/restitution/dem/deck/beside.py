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

from ...core.collision import StickError
from ..contact import Contact
from ..engines.lammps.deck import DEFAULT_DT
from ..pair import WALL_SIZE, Pair
from .meeting import group_types, held_contact

__all__ = ["BESIDE", "drag_eps", "effects"]

#: Fix style -> what it does to the atoms of its group, beside the contact law
BESIDE = {"viscous": "a drag force -gamma v on every atom of its group",
          "langevin": "a thermostat's drag force -m v / damp and a random force",
          "setforce": "forces set to given values", "freeze": "frozen atoms (no force moves them)",
          "nve/limit": "a cap on how far an atom moves per step",
          "adapt": "coefficients or sizes changed as the run goes",
          "damping/cundall": "a global (Cundall) damping of every force on its atoms",
          "damp/viscous": "a drag force", "viscous/sphere": "a drag torque",
          "spring/self": "a spring tethering each atom to where it was", "addforce": "a force added to each atom",
          "efield": "an electric force q E on each charged atom",
          "gravity": "a gravity on the atoms of its group only",
          "temp/berendsen": "a thermostat rescaling the velocities", "temp/rescale": "a thermostat rescaling the velocities",
          "temp/csvr": "a thermostat rescaling the velocities", "temp/csld": "a thermostat replacing the velocities",
          # integrators (meeting.INTEGRATORS) with a Nose-Hoover thermostat on the velocities they integrate
          "nvt/sphere": "a Nose-Hoover thermostat on the velocities", "npt/sphere": "a Nose-Hoover thermostat on the velocities",
          "nvt": "a Nose-Hoover thermostat on the velocities", "npt": "a Nose-Hoover thermostat on the velocities"}
#: The relative accuracy of drag_eps (its integration runs at a thousandth of it): without drag it
#: met the library's eps to 4.5e-8 at worst over 6 exponent pairs, both end rules, 3 dampings, 3 speeds
RTOL = 1e-7


def drag_eps(contact: Contact, g: float, pair: Pair, drag: tuple = (0.0, 0.0)) -> float | None:
    """eps of a head-on collision with a linear drag on each body beside the contact force.

    Body k feels the contact force and ``-drag[k] m_k v_k`` (a drag rate per unit mass: fix viscous
    gamma / m, fix langevin 1 / damp). The bodies start touching at approach speed ``g``, the total
    momentum zero; eps = -(v1 - v2) / g when the overlap returns to zero. The contact force is the contact's, per
    unit effective mass m_eff, clipped at zero under the force rule (LAMMPS' limit_damping).

    Parameters
    ----------
    contact : Contact
    g : float
        Approach speed at first touch.
    pair : Pair
        The bodies' masses (a wall: :meth:`Pair.wall`, which never moves).
    drag : tuple of float
        Drag rate of each body (1/time), >= 0.

    Returns
    -------
    float or None
        eps to about RTOL; None where the bodies do not part (within 10^4 drag or contact times).

    Examples
    --------
    >>> c = Contact(1, 0, D1=1e4, D2=10.0, end="overlap")
    >>> p = Pair.spheres(0.5, 0.5, 1.0)
    >>> abs(drag_eps(c, 1.0, p) - c.eps(1.0)) < 1e-7              # no drag: the contact's own
    True
    >>> # a drag rate b on both bodies adds b to the dashpot's: the same eps as D2 + b
    >>> abs(drag_eps(c, 1.0, p, (5.0, 5.0)) - Contact(1, 0, 1e4, 15.0, "overlap").eps(1.0)) < 1e-7
    True
    """
    from scipy.integrate import solve_ivp     # here: a deck without such a fix does not pay its import
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
        return [v1 - v2, -share[0] * f - rate[0] * v1, share[1] * f - rate[1] * v2]

    def parted(_t, y):
        return y[0]
    parted.terminal, parted.direction = True, -1.0
    sol = solve_ivp(rhs, (0.0, t_max), [0.0, *v0], method="LSODA", events=parted, rtol=RTOL / 1000,
                    atol=[reach * RTOL / 1000, g * RTOL / 1000, g * RTOL / 1000], first_step=t_el * 1e-6,
                    max_step=t_el / 50)
    if not sol.t_events[0].size:
        return None
    _, v1, v2 = sol.y_events[0][0]
    return float(-(v1 - v2) / g)


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


def _number(word: str) -> float | None:
    try:
        value = float(word)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def effects(deck, row: dict, contact: Contact, pair: Pair, types: tuple, frozen_contact=None) -> list[dict]:
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
            entry = _gravity(deck, loc, words, types)
            if entry is not None:
                out.append(entry)
            continue
        held = group_types(deck, group)
        acted = [t in held for t in types] if held is not None else None
        if acted is not None and not any(acted):
            continue
        entry = {"fix": words[1], "style": style, "file": loc[0], "line": loc[1], "what": BESIDE[style],
                 "eps_engine": None, "why": "", "along": None}
        if acted is None:
            entry["why"] = f"group {group} has atoms the audit cannot type: its size is not computed"
        else:
            _size(entry, deck, row, contact, pair, types, words, acted, frozen_contact)
        out.append(entry)
    return out


def _gravity(deck, loc, words: list, types: tuple) -> dict | None:
    """A gravity on some atoms only (``fix ID GROUP gravity``, GROUP not all) beside a pair whose two
    bodies it accelerates differently, or None where it cannot change the pair's relative motion:
    both bodies or neither in its group, or a sphere on a wall (audited without gravity, as where
    gravity acts on every atom)."""
    if len(types) == 1:
        return None
    held = group_types(deck, words[2])
    entry = {"fix": words[1], "style": "gravity", "file": loc[0], "line": loc[1], "what": BESIDE["gravity"],
             "eps_engine": None, "why": ""}
    if held is None:
        entry["why"] = (f"group {words[2]} has atoms the audit cannot type: it may accelerate one sphere and not "
                        "the other during a contact; its size is not computed")
        return entry
    acted = [t in held for t in types]
    if acted[0] == acted[1]:
        return None                  # both bodies fall alike, or neither falls: the relative motion is the contact's
    pushed = types[acted.index(True)]
    entry["why"] = (f"it accelerates the type {pushed} sphere and not the other, so it pushes the spheres together "
                    "or apart during a contact; its size (which depends on the direction of the field against the "
                    "line of centres) is not computed")
    return entry


def _size(entry: dict, deck, row: dict, contact: Contact, pair: Pair, types: tuple, words: list,
          acted: list, frozen_contact) -> None:
    """The size of one fix's effect, where it has one the audit can compute (entry updated)."""
    style = words[3]
    wall = len(types) == 1
    masses = (pair.m1,) if wall else (pair.m1, pair.m2)
    drag = None
    if style == "viscous" and len(words) > 4 and (gamma := _number(words[4])) is not None and gamma >= 0:
        ratios = _keyword_ratios(words, 5)
        drag = tuple(gamma * ratios.get(t, 1.0) / m if on else 0.0 for t, m, on in zip(types, masses, acted))
    elif style == "langevin" and len(words) > 6 and (damp := _number(words[6])) is not None and damp > 0:
        ratios = _keyword_ratios(words, 8)
        drag = tuple(1.0 / (damp * ratios.get(t, 1.0)) if on else 0.0 for t, on in zip(types, acted))
        entry["why"] = ("its drag alone; its random force (temperature from " + words[4] + ") scatters the eps "
                        "around this")
    elif style == "setforce":
        _setforce(entry, deck, row, contact, pair, types, words, acted)
        return
    elif style == "freeze" and deck.code != "LAMMPS":
        entry["why"] = "its size is computed for LAMMPS only (whose m_eff with a frozen atom was checked)"
        return
    elif style == "freeze":
        if all(acted) or wall:
            entry["why"] = ("every body of this collision is held still: it does not happen" if all(acted) else
                            "the sphere is held still: it never meets the wall")
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
    elif style == "nve/limit" and len(words) > 4 and (xmax := _number(words[4])) is not None and xmax > 0:
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


#: fix setforce's components, in order
_AXES = ("x", "y", "z")


def _setforce(entry: dict, deck, row: dict, contact: Contact, pair: Pair, types: tuple, words: list,
              acted: list) -> None:
    """fix ID group setforce fx fy fz: where every component given is a constant zero (the others
    NULL) and no keyword follows, the body of the group keeps its velocity along those axes whatever
    the contact's force. A head-on contact along such an axis then moves the other body alone, under
    the engine's force of both masses (m_eff; unlike freeze, which makes the engine take the other
    body's mass for m_eff): :func:`restitution.dem.deck.meeting.held_contact`. A contact along an
    axis left NULL is the contact's own; an oblique one lies between, not computed. Its torque is not
    set, which a head-on collision does not use. (entry updated)"""
    values, keywords = words[4:7], words[7:]
    zero = [axis for axis, v in zip(_AXES, values) if _number(v) == 0.0]
    set_otherwise = [v for v in values if v != "NULL" and _number(v) != 0.0]
    if len(values) < 3 or keywords or set_otherwise:
        entry["why"] = ("a component set to a value other than 0 or NULL (a force, a variable), or a keyword "
                        "(region): its size is not computed")
        return
    if not zero:
        entry["eps_engine"], entry["why"] = list(row["eps"]), "every component NULL: it sets no force"
        return
    if deck.code != "LAMMPS":
        entry["why"] = "its size is computed for LAMMPS only (whose m_eff with a force set to zero was checked)"
        return
    free = [axis for axis in _AXES if axis not in zero]
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

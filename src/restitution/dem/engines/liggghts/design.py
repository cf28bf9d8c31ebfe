"""The coefficientRestitution that makes LIGGGHTS give an eps (:func:`liggghts_design`), and the
eps each typed e really gives (TYPED_E)."""

from __future__ import annotations

from ...design import calibrated, refuse_passing_through
from ...pair import Pair
from .contact import liggghts_contact, liggghts_e

__all__ = ["liggghts_design", "TYPED_E"]


def liggghts_design(pair: Pair, *, eps: float, model: str, E: float, nu: float, limit_force: bool,
                    characteristic_velocity: float | None = None, g: float = 1.0) -> dict:
    """The coefficientRestitution that makes LIGGGHTS give ``eps`` (at every speed: both models'
    damping makes eps speed-independent, g only names where it is computed, and where the overlap
    must stay below R1 + R2).

    Parameters
    ----------
    pair, eps : Pair, float
        The pair, and the eps to reach (as :meth:`~restitution.dem.engine.Engine.design` takes them).
    model : str
        "hertz" or "hooke".
    E, nu : float
        youngsModulus and poissonsRatio.
    limit_force : bool
        limitForce on (the force rule) or off (the overlap rule).
    characteristic_velocity : float, optional
        characteristicVelocity, for hooke.
    g : float, optional
        The impact speed eps is computed at (1 by default).

    Returns
    -------
    dict
        {"e": the coefficientRestitution to type, "eps", the contact's fields, "contact_time"}.

    Raises
    ------
    ParameterError
        Where no coefficientRestitution LIGGGHTS runs (LIGGGHTS_E) reaches eps, or where the spheres
        would pass through each other at g.

    Examples
    --------
    >>> d = liggghts_design(Pair.spheres(0.0025, 0.0025, 2500.0), eps=0.7, model="hertz", E=5e6, nu=0.45,
    ...                     limit_force=True)
    >>> round(d["e"], 6), round(d["eps"], 9)
    (0.679194, 0.7)
    """
    stiffness = {"model": model, "E": E, "nu": nu, "characteristic_velocity": characteristic_velocity}
    base = liggghts_contact(pair, e=0.5, limit_force=limit_force, **stiffness)
    contact = calibrated(base, eps, g)
    refuse_passing_through(contact, pair, eps, g, "LIGGGHTS")
    e = liggghts_e(contact)
    return {"e": e, "eps": contact.eps(g), **contact.as_dict(), "contact_time": contact.contact_time(g)}


_UNIT_PAIR = Pair(1.0, 1.0, 1.0, 1.0)
#: Each setting's contact as a function of its typed e (eps depends on e alone)
TYPED_E = {
    "LIGGGHTS hertz, limitForce off (default)": lambda e: liggghts_contact(_UNIT_PAIR, E=1.0, nu=0.0, e=e),
    "LIGGGHTS hertz, limitForce on": lambda e: liggghts_contact(_UNIT_PAIR, E=1.0, nu=0.0, e=e, limit_force=True),
    "LIGGGHTS hooke, limitForce off (default)":
        lambda e: liggghts_contact(_UNIT_PAIR, E=1.0, nu=0.0, e=e, model="hooke", characteristic_velocity=1.0),
    "LIGGGHTS hooke, limitForce on":
        lambda e: liggghts_contact(_UNIT_PAIR, E=1.0, nu=0.0, e=e, model="hooke", characteristic_velocity=1.0,
                                   limit_force=True),
}

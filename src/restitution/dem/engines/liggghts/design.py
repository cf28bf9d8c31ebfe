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
    must stay below R1 + R2)."""
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

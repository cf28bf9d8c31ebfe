"""Yade values that give an eps under its clamp (:func:`yade_design`), and the eps each typed en
really gives (TYPED_E)."""

from __future__ import annotations

from ....core.errors import one_of
from ...contact import Contact
from ...design import calibrated, refuse_passing_through
from ...pair import Pair
from .contact import thornton_betan, yade_mindlin_contact, yade_mindlin_en, yade_viscel_contact, yade_viscel_setting

__all__ = ["yade_design", "TYPED_E"]


def yade_design(pair: Pair, *, eps: float, law: str, tc: float | None = None, kn: float | None = None,
                E: float | None = None, nu: float | None = None, g: float = 1.0) -> dict:
    """Yade values that give ``eps`` under its clamp: law "viscel-tc" (en for the given tc),
    "viscel-kn" (cn for the given kn) or "mindlin" (betan, and the en Thornton's fit turns into it).

    Parameters
    ----------
    pair, eps : Pair, float
        The pair, and the eps to reach (as :meth:`~restitution.dem.engine.Engine.design` takes them).
    law : str
        "viscel-tc", "viscel-kn" or "mindlin".
    tc : float, optional
        The contact time (viscel-tc).
    kn : float, optional
        The stiffness (viscel-kn).
    E, nu : float, optional
        The material (mindlin).
    g : float, optional
        The impact speed eps is computed at (1 by default).

    Returns
    -------
    dict
        The values to set ({"tc", "en"}, {"kn", "cn"} or {"betan", "en"}), "eps" and the contact's fields.

    Raises
    ------
    ParameterError
        Another law, a value missing or out of range, or spheres that would pass through each other.

    Examples
    --------
    >>> d = yade_design(Pair.spheres(0.001, 0.001, 2500.0), eps=0.7, law="viscel-tc", tc=1e-4)
    >>> round(d["en"], 6), round(d["eps"], 9)
    (0.679194, 0.7)
    """
    law = one_of("law", law, ("viscel-tc", "viscel-kn", "mindlin"))
    if law == "viscel-tc":
        base = yade_viscel_contact(pair, tc=tc, en=0.5)
        # eps depends on en alone here (Omega = (pi^2 + ln^2 en) / (4 ln^2 en)): keep the tc asked for
        setting = {"tc": tc, "en": yade_viscel_setting(pair, calibrated(base, eps, g), given="tc")["en"]}
        contact = yade_viscel_contact(pair, **setting)
    elif law == "viscel-kn":
        base = yade_viscel_contact(pair, kn=kn, cn=1.0)
        setting = yade_viscel_setting(pair, calibrated(base, eps, g), given="kn")
        contact = yade_viscel_contact(pair, **setting)
    else:
        base = yade_mindlin_contact(pair, E=E, nu=nu, betan=0.5)
        setting = yade_mindlin_en(calibrated(base, eps, g))
        contact = yade_mindlin_contact(pair, E=E, nu=nu, betan=setting["betan"])
    refuse_passing_through(contact, pair, eps, g, "Yade")
    return {**setting, "eps": contact.eps(g), **contact.as_dict()}


_UNIT_PAIR = Pair(1.0, 1.0, 1.0, 1.0)
#: Each setting's contact as a function of its typed en (eps depends on en alone)
TYPED_E = {
    "Yade ViscElMat (tc, en)": lambda e: yade_viscel_contact(_UNIT_PAIR, tc=1.0, en=e),
    "Yade Hertz-Mindlin en": lambda e: Contact("3/2", "1/4", 1.0, 2.0 * thornton_betan(e) * 1.5 ** 0.5, "force"),
}

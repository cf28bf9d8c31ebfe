"""Yade (2023.02a, checked against the engine in tests/library/test_dem_yade.py) <-> the model
(alpha, gamma, D1, D2, end rule), both particles of one material; Yade's laws never let the normal
force turn attractive, so the end rule is "force":

* ``ViscElMat(tc, en)``: k_n = m (pi^2 + ln^2 en) / tc^2, c_n = -2 m ln en / tc with the pair's
  effective mass: alpha = 1, gamma = 0, D1 = (pi^2 + ln^2 en)/tc^2, D2 = -2 ln en / tc. These are
  the overlap rule's formulas: under Yade's clamp eps is above en (0.5503 for en = 0.5).
* ``ViscElMat(kn, cn)``: the values are per particle and Yade joins the two materials in series,
  k_n = kn1 kn2/(kn1 + kn2): for one material D1 = kn/(2m), D2 = cn/(2m) (the documentation
  calls kn "normal elastic stiffness" and does not say it is halved).
* Hertz-Mindlin (``FrictMat`` with ``Ip2_FrictMat_FrictMat_MindlinPhys(en=...)`` or ``betan``):
  F = k_no delta^(3/2) + 2 beta_n sqrt(m (3/2) k_no sqrt(delta)) delta', k_no = (4/3) E* sqrt(R):
  alpha = 3/2, gamma = 1/4, D1 = k_no/m, D2 = 2 beta_n sqrt(3 D1 / 2). Given en, Yade takes beta_n
  from the fit (B6)-(B7) of Thornton, Cummins and Cleary (Powder Technol. 233, 2013, Table 2), made
  for the force rule: eps is en within 3e-4 for en <= 0.9, but 0.9789 for en = 0.99 (:func:`thornton_betan`).
"""

from __future__ import annotations

import math

from ....core.errors import ParameterError, one_of, require_positive_finite
from ...contact import Contact
from ...pair import Pair
from ...typed_e import (THORNTON_H, effective_modulus, linear_from_time_and_e, require_linear, thornton_betan,
                        time_and_e_of_linear)

__all__ = ["yade_viscel_contact", "yade_viscel_setting", "yade_mindlin_contact", "yade_mindlin_en", "thornton_betan",
           "THORNTON_H"]


def yade_viscel_contact(pair: Pair, *, tc: float | None = None, en: float | None = None, kn: float | None = None,
                        cn: float | None = None) -> Contact:
    """Yade ``ViscElMat`` given (tc, en) or (kn, cn), both particles of that material.

    Parameters
    ----------
    pair : Pair
        The colliding pair (its effective mass sets D1 and D2 in the (kn, cn) form).
    tc, en : float, optional
        Contact time and restitution coefficient, given together.
    kn, cn : float, optional
        Per-particle stiffness and damping, given together instead.

    Returns
    -------
    Contact
        alpha = 1, gamma = 0, the force rule.

    Raises
    ------
    ParameterError
        Where both forms or neither is given, or a value is out of range.

    Examples
    --------
    >>> c = yade_viscel_contact(Pair.spheres(0.001, 0.001, 2500.0), tc=1e-4, en=0.5)
    >>> round(c.eps(1.0), 4)          # above en: Yade clamps the attractive force
    0.5503
    """
    if tc is not None or en is not None:
        if kn is not None or cn is not None:
            raise ParameterError("kn", kn, "give either (tc, en) or (kn, cn), as Yade requires")
        return linear_from_time_and_e("tc", tc, "en", en, "force")
    kn, cn = require_positive_finite("kn", kn), require_positive_finite("cn", cn)
    return Contact("1", "0", kn / (2.0 * pair.m), cn / (2.0 * pair.m), "force")   # two materials in series


def yade_viscel_setting(pair: Pair, contact: Contact, *, given: str) -> dict:
    """The ViscElMat values that give ``contact`` (alpha = 1, gamma = 0): {"tc", "en"} when
    ``given`` = "tc" (contact time and en both follow from D1, D2), {"kn", "cn"} for "kn".

    Parameters
    ----------
    pair : Pair
        The colliding pair.
    contact : Contact
        A linear contact (alpha = 1, gamma = 0).
    given : str
        "tc" or "kn": the form of ViscElMat sought.

    Returns
    -------
    dict
        {"tc", "en"} or {"kn", "cn"}.

    Raises
    ------
    ParameterError
        A ``given`` other than "tc" or "kn"; a contact that is not linear (alpha = 1, gamma = 0),
        which neither form gives; for "tc", one that is not underdamped (D2 >= 2 sqrt(D1)).

    Examples
    --------
    >>> pair = Pair.spheres(0.001, 0.001, 2500.0)
    >>> s = yade_viscel_setting(pair, yade_viscel_contact(pair, tc=1e-4, en=0.5), given="tc")
    >>> round(s["tc"], 12), round(s["en"], 9)
    (0.0001, 0.5)
    """
    given = one_of("given", given, ("tc", "kn"))
    require_linear(contact, f"ViscElMat's ({given}, ...) form")
    if given == "kn":
        return {"kn": 2.0 * pair.m * contact.D1, "cn": 2.0 * pair.m * contact.D2}
    tc, en = time_and_e_of_linear(contact, "ViscElMat's (tc, en) form")
    return {"tc": tc, "en": en}


def yade_mindlin_contact(pair: Pair, *, E: float, nu: float, en: float | None = None,
                         betan: float | None = None) -> Contact:
    """Yade Hertz-Mindlin (Law2_ScGeom_MindlinPhys_Mindlin) with en (through Thornton's fit) or betan.

    Parameters
    ----------
    pair : Pair
        The colliding pair.
    E, nu : float
        Young's modulus and Poisson ratio of the material.
    en : float, optional
        The restitution coefficient Thornton's fit turns into betan.
    betan : float, optional
        The damping ratio itself (exactly one of en and betan).

    Returns
    -------
    Contact
        alpha = 3/2, gamma = 1/4, the force rule.

    Raises
    ------
    ParameterError
        Where both or neither of en and betan is given, or a value is out of range.

    Examples
    --------
    >>> c = yade_mindlin_contact(Pair.spheres(0.001, 0.001, 2500.0), E=1e7, nu=0.3, en=0.5)
    >>> str(c.alpha), str(c.gamma), round(c.eps(1.0), 4)
    ('3/2', '1/4', 0.5)
    """
    if (en is None) == (betan is None):
        raise ParameterError("en", en, "give exactly one of en and betan, as Yade requires")
    beta = thornton_betan(en) if en is not None else require_positive_finite("betan", betan)
    D1 = 4.0 / 3.0 * effective_modulus(E, nu) * math.sqrt(pair.R) / pair.m
    return Contact("3/2", "1/4", D1, 2.0 * beta * math.sqrt(1.5 * D1), "force")


def yade_mindlin_en(contact: Contact) -> dict:
    """{"betan", "en"} that give this Hertz-Mindlin contact's D2; en is None where Thornton's fit
    cannot give that betan (the fit is monotonic in en on (0, 1), so one en at most).

    Parameters
    ----------
    contact : Contact
        A Hertz-Mindlin contact (alpha = 3/2, gamma = 1/4).

    Returns
    -------
    dict
        {"betan": the damping ratio, "en": the en that gives it, or None}.

    Examples
    --------
    >>> c = yade_mindlin_contact(Pair.spheres(0.001, 0.001, 2500.0), E=1e7, nu=0.3, en=0.5)
    >>> round(yade_mindlin_en(c)["en"], 9)
    0.5
    """
    from scipy.optimize import brentq     # here: `restitution deck` does not pay its import
    beta = contact.D2 / (2.0 * math.sqrt(1.5 * contact.D1))
    lo, hi = 1e-6, 1.0 - 1e-12
    f = lambda e: thornton_betan(e) - beta   # noqa: E731
    en = brentq(f, lo, hi, xtol=1e-15, rtol=1e-15) if f(lo) * f(hi) < 0 else None
    return {"betan": beta, "en": en}

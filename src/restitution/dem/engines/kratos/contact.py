"""Kratos DEMApplication (10.4.4, checked against the engine in tests/library/test_dem_kratos.py)
<-> the model (alpha, gamma, D1, D2, end rule).

A material relation of MaterialsDEM.json names a discontinuum law and a COEFFICIENT_OF_RESTITUTION
e; Kratos' sphere strategy turns e into the damping ratio DAMPING_GAMMA of that relation (in Python,
sphere_strategy.ModifySubProperties) and the law's C++ applies it:

* ``DEM_D_Hertz_viscous_Coulomb``: k_n = 2 E* sqrt(R delta), F_el = (2/3) k_n delta, c_n = 2 beta
  sqrt(m k_n), beta from e by Thornton's fit (as Yade's Hertz-Mindlin): alpha = 3/2, gamma = 1/4,
  D1 = (4/3) E* sqrt(R) / m, D2 = 2 beta sqrt(3 D1 / 2).
* ``DEM_D_Linear_viscous_Coulomb``: k_n = 1.432 pi 0.31225 E* R between spheres, pi 0.31225 E* R
  against a wall (the factor 1.432 is absent there), c_n = 2 zeta sqrt(m k_n): alpha = 1, gamma =
  0, D1 = k_n / m, D2 = 2 zeta sqrt(D1); zeta is the root, found by bisection on [0, 16] to an
  interval of 1e-4, of e = e_force(zeta), the linear dashpot's eps when the force may not pull
  (:func:`linear_force_eps`). So eps is e only to that bisection: off by up to about 1e-4.

E* = E1 E2 / (E2 (1 - nu1^2) + E1 (1 - nu2^2)) of the two materials (the wall's own E, nu on a
wall), R and m the effective radius and mass (the sphere's on a wall). Both laws set a total normal
force below zero to zero: the end rule is "force". Kratos reads e below 0.001 as 0.001 and gives
no damping at all above 0.999.
"""

from __future__ import annotations

import math

from ....core.errors import ParameterError, one_of, require_positive_finite
from ...contact import Contact
from ...pair import Pair
from ...typed_e import thornton_betan

__all__ = ["KRATOS_LAWS", "KRATOS_E_RANGE", "LINEAR_ZETA_STEP", "kratos_modulus", "linear_force_eps", "kratos_linear_zeta",
           "kratos_damping_ratio", "kratos_contact", "kratos_e", "kratos_typed_e"]

#: The discontinuum laws mapped here: Kratos' name -> ours
KRATOS_LAWS = {"DEM_D_Hertz_viscous_Coulomb": "hertz", "DEM_D_Linear_viscous_Coulomb": "linear"}
#: Kratos' clamp of a typed e: below the first it reads the first, above the second no damping
KRATOS_E_RANGE = (0.001, 0.999)
#: The linear law's stiffness k_n / (E* R): between spheres, and against a wall (sphere_strategy's
#: constants: pi times 0.31225, the chord of a 5 % sagitta, times 1.432 between spheres)
LINEAR_STIFFNESS = {"sphere": 1.432 * math.pi * 0.31225, "wall": math.pi * 0.31225}
#: Kratos' bisection for the linear law's zeta: its interval and the width it stops at
_BISECTION = (0.0, 16.0, 1e-4)
#: The width of its last interval (16 halved until at most 1e-4): its answers are the midpoints
#: of a grid of this spacing
LINEAR_ZETA_STEP = 16.0 / 2 ** 18


def kratos_modulus(E1: float, nu1: float, E2: float | None = None, nu2: float | None = None) -> float:
    """E* = E1 E2 / (E2 (1 - nu1^2) + E1 (1 - nu2^2)), the second material the first by default.

    Parameters
    ----------
    E1, nu1 : float
        Young's modulus (> 0) and Poisson ratio (in (-1, 1)) of the first material.
    E2, nu2 : float, optional
        The second material's (or the wall's); the first's where None.

    Returns
    -------
    float
        The effective modulus E*.

    Raises
    ------
    ParameterError
        Where a modulus is not a finite positive number or a ratio is outside (-1, 1).

    Examples
    --------
    >>> round(kratos_modulus(1e7, 0.3), 1), round(kratos_modulus(1e7, 0.3, 2e11, 0.3), 1)
    (5494505.5, 10988461.6)
    """
    E2 = E1 if E2 is None else E2
    nu2 = nu1 if nu2 is None else nu2
    for name, E in (("E", E1), ("E2", E2)):
        require_positive_finite(name, E)
    for name, nu in (("nu", nu1), ("nu2", nu2)):
        if nu is None or not -1.0 < nu < 1.0:
            raise ParameterError(name, nu, "must be a Poisson ratio in (-1, 1)")
    return E1 * E2 / (E2 * (1.0 - nu1 ** 2) + E1 * (1.0 - nu2 ** 2))


def linear_force_eps(zeta: float) -> float:
    """eps of delta'' + 2 zeta w delta' + w^2 delta = 0 when the total force may not pull (it ends
    where it vanishes), for any damping ratio zeta >= 0 (undamped: 1; under-, critically and overdamped).

    Parameters
    ----------
    zeta : float
        The damping ratio, >= 0.

    Returns
    -------
    float
        eps, in (0, 1] (1 only at zeta = 0).

    Raises
    ------
    ParameterError
        For zeta not a finite number >= 0 (a negative ratio is no dissipative contact).

    Examples
    --------
    >>> round(linear_force_eps(0.1), 6), round(linear_force_eps(1.0), 6), round(linear_force_eps(2.0), 6)
    (0.744079, 0.135335, 0.047769)
    """
    if not (math.isfinite(zeta) and zeta >= 0.0):
        raise ParameterError("zeta", zeta, "must be a finite number >= 0")
    if zeta < 1.0:
        w = math.sqrt(1.0 - zeta * zeta)
        return math.exp(-zeta / w * (math.pi - math.atan2(2.0 * zeta * w, 1.0 - 2.0 * zeta * zeta)))
    if zeta == 1.0:
        return math.exp(-2.0)
    r = zeta / math.sqrt(zeta * zeta - 1.0)
    return math.exp(-r * math.log((r + 1.0) / (r - 1.0)))


def _clamped(e: float) -> float:
    if not 0.0 < e <= 1.0:
        raise ParameterError("COEFFICIENT_OF_RESTITUTION", e, "must be in (0, 1]")
    if e > KRATOS_E_RANGE[1]:
        raise ParameterError("COEFFICIENT_OF_RESTITUTION", e, f"above {KRATOS_E_RANGE[1]} Kratos sets no damping at all "
                                                              "(eps = 1): no viscoelastic contact to map")
    return max(float(e), KRATOS_E_RANGE[0])


def kratos_linear_zeta(e: float) -> float:
    """The zeta Kratos' bisection gives for e (its steps: the midpoint of the last interval).

    Parameters
    ----------
    e : float
        The typed COEFFICIENT_OF_RESTITUTION, in (0, 0.999] (below 0.001 read as 0.001).

    Returns
    -------
    float
        zeta, a midpoint of Kratos' bisection grid (cells LINEAR_ZETA_STEP wide).

    Raises
    ------
    ParameterError
        Where e is outside (0, 1], or above 0.999 (Kratos sets no damping there).

    Examples
    --------
    >>> zeta = kratos_linear_zeta(0.5)
    >>> round(zeta, 6), abs(linear_force_eps(zeta) - 0.5) < 1e-4
    (0.25528, True)
    """
    e = _clamped(e)
    lo, hi, width = _BISECTION
    mid = 0.5 * (lo + hi)
    for _ in range(301):
        if hi - lo <= width:
            break
        f_mid = linear_force_eps(mid) - e
        if (linear_force_eps(lo) - e) * f_mid < 0.0:
            hi = mid
        elif f_mid == 0.0:
            return mid
        else:
            lo = mid
        mid = 0.5 * (lo + hi)
    return mid


def kratos_damping_ratio(law: str, e: float) -> float:
    """DAMPING_GAMMA that Kratos derives from a typed e for ``law`` ("hertz" or "linear").

    Parameters
    ----------
    law : str
        "hertz" (Thornton's fit) or "linear" (Kratos' bisection).
    e : float
        The typed COEFFICIENT_OF_RESTITUTION.

    Returns
    -------
    float
        The damping ratio.

    Raises
    ------
    ParameterError
        For another law, or an e Kratos does not damp with.

    Examples
    --------
    >>> round(kratos_damping_ratio("hertz", 0.5), 6), round(kratos_damping_ratio("linear", 0.5), 6)
    (0.233025, 0.25528)
    """
    law = one_of("law", law, tuple(KRATOS_LAWS.values()))
    return thornton_betan(_clamped(e)) if law == "hertz" else kratos_linear_zeta(e)


def kratos_contact(pair: Pair, *, law: str, e: float, E: float, nu: float, E2: float | None = None,
                   nu2: float | None = None, wall: bool = False) -> Contact:
    """The contact of a Kratos material relation: ``law`` "hertz" or "linear" (or Kratos' name),
    typed e, the materials' E and nu (E2, nu2 of the other material or of the wall, the first by
    default); ``wall``: a sphere on a wall (``pair`` then Pair.wall: effective radius and mass the
    sphere's).

    Parameters
    ----------
    pair : Pair
        The colliding pair.
    law : str
        "hertz", "linear", or Kratos' name of either (``KRATOS_LAWS``).
    e : float
        The typed COEFFICIENT_OF_RESTITUTION.
    E, nu : float
        The first material's Young's modulus and Poisson ratio.
    E2, nu2 : float, optional
        The other material's or the wall's (the first's where None).
    wall : bool, optional
        A sphere on a wall (the linear law's stiffness lacks the factor 1.432 there).

    Returns
    -------
    Contact
        Hertz: alpha = 3/2, gamma = 1/4; linear: alpha = 1, gamma = 0; end rule "force".

    Raises
    ------
    ParameterError
        For another law, a material constant out of range or an e Kratos does not damp with.

    Examples
    --------
    >>> pair = Pair.spheres(0.01, 0.01, 2500.0)
    >>> c = kratos_contact(pair, law="hertz", e=0.5, E=1e7, nu=0.3)
    >>> str(c.alpha), str(c.gamma), c.end, round(c.D1 / 1e8, 6)
    ('3/2', '1/4', 'force', 0.989359)
    """
    law = KRATOS_LAWS.get(law, law)
    law = one_of("law", law, tuple(KRATOS_LAWS.values()))
    Es = kratos_modulus(E, nu, E2, nu2)
    beta = kratos_damping_ratio(law, e)
    if law == "hertz":
        D1 = 4.0 / 3.0 * Es * math.sqrt(pair.R) / pair.m
        return Contact("3/2", "1/4", D1, 2.0 * beta * math.sqrt(1.5 * D1), "force")
    D1 = LINEAR_STIFFNESS["wall" if wall else "sphere"] * Es * pair.R / pair.m
    return Contact("1", "0", D1, 2.0 * beta * math.sqrt(D1), "force")


def kratos_e(contact: Contact) -> dict:
    """{"DAMPING_GAMMA", "COEFFICIENT_OF_RESTITUTION"} that give this contact's D2 (its D1 given by
    the materials): the damping ratio, and the e whose Kratos ratio is it (Hertz: Thornton's fit
    inverted; linear: e_force(zeta), which Kratos' bisection turns back into zeta to 6e-5).

    Parameters
    ----------
    contact : Contact
        Hertz (3/2, 1/4) or linear (1, 0), under the force rule.

    Returns
    -------
    dict
        {"DAMPING_GAMMA": the ratio, "COEFFICIENT_OF_RESTITUTION": e, or None where no e in
        Kratos' range gives it}.

    Raises
    ------
    ParameterError
        For another end rule or other exponents.

    Examples
    --------
    >>> c = kratos_contact(Pair.spheres(0.01, 0.01, 2500.0), law="hertz", e=0.5, E=1e7, nu=0.3)
    >>> round(kratos_e(c)["COEFFICIENT_OF_RESTITUTION"], 12)
    0.5
    """
    from scipy.optimize import brentq     # here: `restitution deck` does not pay its import
    if contact.end != "force":
        raise ParameterError("end", contact.end, "Kratos clips the normal force at zero: only the force rule")
    if (contact.alpha, contact.gamma) == (1.5, 0.25):
        beta = contact.D2 / (2.0 * math.sqrt(1.5 * contact.D1))
        f = lambda x: thornton_betan(x) - beta   # noqa: E731
        lo, hi = KRATOS_E_RANGE
        e = brentq(f, lo, hi, xtol=1e-15, rtol=1e-15) if f(lo) * f(hi) < 0 else None
        return {"DAMPING_GAMMA": beta, "COEFFICIENT_OF_RESTITUTION": e}
    if (contact.alpha, contact.gamma) == (1, 0):
        zeta = contact.D2 / (2.0 * math.sqrt(contact.D1))
        e = linear_force_eps(zeta)
        return {"DAMPING_GAMMA": zeta, "COEFFICIENT_OF_RESTITUTION": e if KRATOS_E_RANGE[0] <= e <= KRATOS_E_RANGE[1]
                else None}
    raise ParameterError("alpha", contact.alpha, "Kratos' viscous Coulomb laws are Hertz (3/2, 1/4) or linear (1, 0)")


def kratos_typed_e(contact: Contact) -> float:
    """The COEFFICIENT_OF_RESTITUTION to type for ``contact``'s damping: Hertz, Thornton's fit
    inverted; linear, the e of the damping ratio nearest on Kratos' bisection grid (its answers are
    the midpoints of cells LINEAR_ZETA_STEP wide), so that Kratos lands on that ratio exactly.
    ParameterError where no e in Kratos' range gives it.

    Parameters
    ----------
    contact : Contact
        As :func:`kratos_e` takes it.

    Returns
    -------
    float
        The e to type, in KRATOS_E_RANGE.

    Raises
    ------
    ParameterError
        Where no e in Kratos' range gives the contact's damping.

    Examples
    --------
    >>> c = kratos_contact(Pair.spheres(0.01, 0.01, 2500.0), law="linear", e=0.5, E=1e7, nu=0.3)
    >>> round(kratos_typed_e(c), 6)     # 0.5 to Kratos' bisection
    0.499995
    """
    if contact.alpha == 1:
        zeta = contact.D2 / (2.0 * math.sqrt(contact.D1))
        e = linear_force_eps((round(zeta / LINEAR_ZETA_STEP - 0.5) + 0.5) * LINEAR_ZETA_STEP)
    else:
        e = kratos_e(contact)["COEFFICIENT_OF_RESTITUTION"]
    if e is None or not KRATOS_E_RANGE[0] <= e <= KRATOS_E_RANGE[1]:
        raise ParameterError("COEFFICIENT_OF_RESTITUTION", e, "Kratos' law reaches this damping with no e in "
                                                              f"[{KRATOS_E_RANGE[0]}, {KRATOS_E_RANGE[1]}]")
    return e

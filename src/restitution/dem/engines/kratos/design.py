"""The COEFFICIENT_OF_RESTITUTION that makes Kratos give an eps (:func:`kratos_design`), and the eps
each typed e really gives (TYPED_E)."""

from __future__ import annotations

from ...design import calibrated, refuse_passing_through
from ...pair import Pair
from .contact import kratos_contact, kratos_typed_e

__all__ = ["kratos_design", "TYPED_E"]


def kratos_design(pair: Pair, *, eps: float, law: str, E: float, nu: float, E2: float | None = None,
                  nu2: float | None = None, wall: bool = False, g: float = 1.0) -> dict:
    """The COEFFICIENT_OF_RESTITUTION of a material relation (``law`` "hertz" or "linear", the
    materials' E, nu, E2, nu2, ``wall`` for a sphere-wall relation) that makes Kratos give ``eps``;
    both laws' eps depends on e alone, g only names where the overlap must stay below R1 + R2.

    Hertz: Thornton's fit inverted, eps reached to the library's accuracy. Linear: Kratos' bisection
    turns e into one of a grid of damping ratios (spaced LINEAR_ZETA_STEP): the e returned is the one whose
    ratio is the grid's nearest to the target's, and ``eps`` the one it really gives (within about
    1e-4 of the target).

    Parameters
    ----------
    pair, eps : Pair, float
        The pair, and the eps to reach (as :meth:`~restitution.dem.engine.Engine.design` takes them).
    law : str
        "hertz" or "linear" (or Kratos' name of either).
    E, nu : float
        The first material's Young's modulus and Poisson ratio.
    E2, nu2 : float, optional
        The other material's or the wall's (the first's where None).
    wall : bool, optional
        A sphere-wall relation.
    g : float, optional
        The impact speed eps is computed at (1 by default).

    Returns
    -------
    dict
        {"COEFFICIENT_OF_RESTITUTION", "eps" (what Kratos gives with it), the contact's fields,
        "contact_time"}.

    Raises
    ------
    ParameterError
        Where no e in Kratos' range reaches eps, or the spheres would pass through each other.

    Examples
    --------
    >>> pair = Pair.spheres(0.01, 0.01, 2500.0)
    >>> d = kratos_design(pair, eps=0.7, law="hertz", E=1e7, nu=0.3)
    >>> round(d["COEFFICIENT_OF_RESTITUTION"], 6), round(d["eps"], 9)
    (0.700227, 0.7)
    >>> round(kratos_design(pair, eps=0.7, law="linear", E=1e7, nu=0.3)["eps"], 6)   # on Kratos' grid
    0.699985
    """
    stiffness = {"law": law, "E": E, "nu": nu, "E2": E2, "nu2": nu2, "wall": wall}
    contact = calibrated(kratos_contact(pair, e=0.5, **stiffness), eps, g)
    refuse_passing_through(contact, pair, eps, g, "Kratos")
    e = kratos_typed_e(contact)
    real = kratos_contact(pair, e=e, **stiffness)
    return {"COEFFICIENT_OF_RESTITUTION": e, "eps": real.eps(g), **real.as_dict(), "contact_time": real.contact_time(g)}


_UNIT_PAIR = Pair(1.0, 1.0, 1.0, 1.0)
#: Each law's contact as a function of its typed e (eps depends on e alone)
TYPED_E = {
    "Kratos DEM_D_Hertz_viscous_Coulomb": lambda e: kratos_contact(_UNIT_PAIR, law="hertz", e=e, E=1.0, nu=0.0),
    "Kratos DEM_D_Linear_viscous_Coulomb": lambda e: kratos_contact(_UNIT_PAIR, law="linear", e=e, E=1.0, nu=0.0),
}

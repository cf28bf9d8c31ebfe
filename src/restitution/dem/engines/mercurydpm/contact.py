"""MercuryDPM <-> the model (alpha, gamma, D1, D2, end rule), from its documentation (MercuryDPM was
not run here).

Its Hertzian viscoelastic species set from an elastic modulus and a restitution coefficient uses
the Tsuji-type law of LIGGGHTS' ``model hertz``; its LinearViscoelastic species set from a
collision time t_c and restitution e (setCollisionTimeAndRestitutionCoefficient with the effective
mass) gives k = m (pi^2 + ln^2 e) / t_c^2, eta = -2 m ln e / t_c: alpha = 1, gamma = 0, D1 = k/m,
D2 = eta/m. The normal force may turn attractive: "overlap".
"""

from __future__ import annotations

from ...contact import Contact
from ...pair import Pair
from ...typed_e import linear_from_time_and_e

__all__ = ["mercury_linear_contact"]


def mercury_linear_contact(pair: Pair, *, t_c: float, e: float) -> Contact:
    """MercuryDPM LinearViscoelastic species from setCollisionTimeAndRestitutionCoefficient(t_c, e, m).

    Parameters
    ----------
    pair : Pair
        The colliding pair.
    t_c : float
        The collision time.
    e : float
        The restitution coefficient, in (0, 1).

    Returns
    -------
    Contact
        alpha = 1, gamma = 0, the overlap rule (eps is e exactly).

    Raises
    ------
    ParameterError
        Where t_c is not finite and positive, or e is not in (0, 1).

    Examples
    --------
    >>> round(mercury_linear_contact(Pair.spheres(0.001, 0.001, 2500.0), t_c=1e-4, e=0.5).eps(1.0), 12)
    0.5
    """
    return linear_from_time_and_e("t_c", t_c, "e", e, "overlap")

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
    """MercuryDPM LinearViscoelastic species from setCollisionTimeAndRestitutionCoefficient(t_c, e, m)."""
    return linear_from_time_and_e("t_c", t_c, "e", e, "overlap")

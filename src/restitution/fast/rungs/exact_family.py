"""The exact family alpha = 2 gamma + 1 as a rung (:mod:`restitution.core.exact_family`): eps is the
linear dashpot's at (gamma+1) Omega in closed form, both end rules, every Omega, no build.

Its bound is at rounding level, EPS_ULPS u (1 + ln(1/eps)) at the smallest eps of the request
(eps rises with Omega under both rules, so that is eps at the smallest Omega); measured against
mpmath a quarter of that or less. It is exact (``Rung.exact``): the chooser takes it first
wherever it serves, before any curve or fit, and builds nothing for these pairs.
"""

from __future__ import annotations

from ..rung import Rung, Setting

__all__ = ["ExactFamily", "EXACT_FAMILY_COST", "family_collision"]

#: Seconds per point (the dashpot's contact time in Python; measured 1-3 microseconds).
EXACT_FAMILY_COST = 3e-6


def family_collision(problem, omega, method: str):
    """The exact collision of alpha = 2 gamma + 1 (core.exact_family.exact_collision: eps within
    8 u (1 + ln(1/eps)), tau_b and tau_c by quadrature to about 1e-14), every Omega > 0; ``method``
    is the name it was asked by, for the message where the pair is outside the family."""
    from ...core.errors import ParameterError
    from ...core.exact_family import exact_collision, in_family
    if not in_family(problem):
        raise ParameterError("method", method, "the closed form is for alpha = 2 gamma + 1 only (alpha = 1, "
                                               "gamma = 0, the linear dashpot, and the family that maps onto it)")
    return exact_collision(problem, omega)


class ExactFamily(Rung):
    """eps = exp(-T_c/2) of the dashpot at (gamma+1) Omega (:func:`restitution.core.exact_family.exact_eps`)
    for alpha = 2 gamma + 1, both end rules, every Omega the ladder accepts (overlap rule: above
1/(4 (gamma+1))); bound EPS_ULPS u (1 + ln(1/eps)) at the request's smallest eps, u = 2^-53."""

    name, cost = "exact-family", EXACT_FAMILY_COST
    ends = ("force", "overlap")
    exact = True
    collides = True

    def collision(self, problem, omega, *, rtol, digits, t_eval=None):
        return family_collision(problem, omega, self.name)

    def outside(self, req):
        from ...core.collision import stick_bound
        from ...core.exact_family import in_family
        if not in_family(req.ex):
            return "alpha != 2 gamma + 1 (the family that maps exactly onto the linear dashpot)"
        if req.end == "overlap" and req.lo <= stick_bound(req.ex):
            # the chooser refuses this as StickError before quoting; a quote alone says why
            return "Omega <= 1/(4 (gamma+1)): the bodies stick under the overlap rule"
        return None

    def bound(self, req, built):
        # an eps below the smallest normal double (the overlap rule just above its threshold)
        # raises UnresolvedError here: every other rung would follow a creep there for minutes
        from ...core.exact_family import eps_bound, exact_eps
        lowest = exact_eps(req.problem, req.lo)
        return float(eps_bound(lowest)), Setting(label="dashpot at (gamma+1) Omega", end=req.end)

    def coefficients(self, req, built):
        return {"exact": "alpha = 2 gamma + 1: the linear dashpot at Omega' = (gamma+1) Omega "
                         "(restitution.core.exact_family)"}

    def evaluate(self, req, built, setting, omega):
        from ...core.exact_family import exact_eps
        return exact_eps(req.problem, omega)

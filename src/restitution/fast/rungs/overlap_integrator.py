"""The compiled integrator under the overlap rule (``collide_fast(..., end="overlap")``), where it
differs from the force rule (alpha > gamma), at rtol at most OVERLAP_RTOL_MAX: the force rule's
bound with a factor and floor of its own (core.conditioning.plain_factor_floor), validated against the mpmath
reference down to eps of 1e-36 (tests/library/test_overlap_fast.py). Below
Omega = 1e-5 the creeping return makes the explicit method slow (~0.4/Omega steps): the scipy
reference (Radau there) takes over. A proved sticking raises StickError, as the reference does."""

from __future__ import annotations

from ..integrator import OVERLAP_RTOL_MAX
from ..master import reference_eps
from ..rung import Setting, integrator_bound, integrator_rtol
from .integrator import Integrator

__all__ = ["OverlapIntegrator"]


class OverlapIntegrator(Integrator):
    """The compiled integrator under the overlap rule, where it differs from the force rule (alpha >
    gamma): rtol at most OVERLAP_RTOL_MAX, bound integrator_bound(rtol) with the overlap rule's own
    factor and floor, from Omega = 1e-5 (the scipy reference takes the creeping return below)."""

    ends = ("overlap",)
    stiff_below = "the creeping return is stiff below"

    def price(self, req):
        return self.cost * req.n * (1.0 + 3e-3 / req.lo)   # ~0.4/Omega steps of the creeping return

    def bound(self, req, built):
        rtol = min(integrator_rtol(req.tol, req.problem), OVERLAP_RTOL_MAX)
        return integrator_bound(rtol, req.problem), Setting(rtol=rtol, end="overlap")

    def evaluate(self, req, built, setting, omega):
        return reference_eps(req.problem, omega, setting.rtol)

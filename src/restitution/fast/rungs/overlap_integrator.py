"""The compiled integrator under the overlap rule (``collide_fast(..., overlap=True)``), where it
differs from the force rule (alpha > gamma), at rtol at most OVERLAP_RTOL_MAX: the force rule's
bound with a factor and floor of its own (core.conditioning.plain_factor_floor), validated against the mpmath
reference down to eps of 1e-36 (tests/library/test_overlap_fast.py). Below
Omega = 1e-5 the creeping return makes the explicit method slow (~0.4/Omega steps): the scipy
reference (Radau there) takes over. A proved sticking raises StickError, as the reference does."""

from __future__ import annotations

from ..integrator import OVERLAP_RTOL_MAX
from ..master import reference_eps, stiff_omega_min
from ..rung import Rung, integrator_bound, integrator_rtol
from .integrator import OMEGA_MAX, integrator_collision, printed

__all__ = ["OverlapIntegrator"]


class OverlapIntegrator(Rung):
    name, cost = "integrator", 6e-5
    conditioned = True
    ends = ("overlap",)
    collides = True

    def collision(self, problem, omega, *, rtol, digits, t_eval=None):
        return integrator_collision(problem, omega, rtol)

    def outside(self, req):
        wmin = stiff_omega_min(req.problem)
        if req.lo < wmin or req.hi > OMEGA_MAX:
            return f"Omega outside [{wmin:g}, {printed(OMEGA_MAX)}] (explicit method; the creeping return is stiff below)"
        return None

    def price(self, req):
        return self.cost * req.n * (1.0 + 3e-3 / req.lo)   # ~0.4/Omega steps of the creeping return

    def bound(self, req, built):
        rtol = min(integrator_rtol(req.tol, req.problem), OVERLAP_RTOL_MAX)
        return integrator_bound(rtol, req.problem), f"rtol={rtol:.3g}, overlap"

    def evaluate(self, req, built, setting, omega):
        return reference_eps(req.problem, omega, min(integrator_rtol(req.tol, req.problem), OVERLAP_RTOL_MAX))

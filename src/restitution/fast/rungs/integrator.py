"""The compiled integrator as a rung (:mod:`restitution.fast.integrator`), force rule: rtol from
the tolerance, bound integrator_bound(rtol) (validated against the mpmath reference)."""

from __future__ import annotations

import math

from ..master import reference_eps, stiff_omega_min
from ..rung import Rung, integrator_bound, integrator_rtol

__all__ = ["Integrator", "OMEGA_MAX", "printed"]

#: Largest Omega the compiled integrator is validated at (as messages print it: 1e14, not 1e+14).
OMEGA_MAX = 1e14


def printed(x: float) -> str:
    return f"{x:g}".replace("e+", "e")


class Integrator(Rung):
    name, cost = "integrator", 6e-5
    conditioned = True

    def outside(self, req):
        wmin = stiff_omega_min(req.ex)
        if req.lo < wmin or req.hi > OMEGA_MAX:
            return f"Omega outside [{printed(wmin)}, {printed(OMEGA_MAX)}] (explicit method; stiff below)"
        return None

    def price(self, req):
        # alpha <= gamma: the creeping return takes ~1/Omega steps; alpha > gamma: the force's zero
        # comes ~ln(1/Omega) relaxation times after the turn (25 times the cost at 1e-300)
        if req.rules_differ:
            return self.cost * req.n * (1.0 + max(0.0, -math.log(req.lo)) / 28.0)
        return self.cost * req.n * (1.0 + 1e-3 / req.lo)

    def bound(self, req, built):
        rtol = integrator_rtol(req.tol, req.ex)
        return integrator_bound(rtol, req.ex), f"rtol={rtol:.3g}"

    def evaluate(self, req, built, setting, omega):
        return reference_eps(req.ex, omega, integrator_rtol(req.tol, req.ex))

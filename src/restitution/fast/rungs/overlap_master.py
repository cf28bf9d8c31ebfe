"""The overlap rule's master curve as a rung (:mod:`restitution.fast.overlap_master`): Chebyshev
panels on Omega in [1e-4, 1e8] (above the sticking boundary where there is one), the viscous law
below them where the bodies cannot stick, the elastic expansion above; the bound of the pieces the
request touches; built on its own in about a second when a request pays for it."""

from __future__ import annotations

import math

from ..builds.overlap_curve import OVERLAP_CURVE
from ..overlap_master import OMEGA_HI, OMEGA_LO, least_bound
from ..rung import Rung, Setting

__all__ = ["OverlapMaster", "OVERLAP_CURVE"]


def _law(req) -> bool:
    return req.ex.alpha < 2 * req.ex.gamma + 1


class OverlapMaster(Rung):
    name, cost = "master", 4e-8
    ends = ("overlap",)

    def outside(self, req):
        curve = req.builds.get(OVERLAP_CURVE)
        lowest = curve.lowest if curve is not None else (0.0 if _law(req) else OMEGA_LO)
        if req.lo < lowest:
            why = ("where eps = C Omega^k leaves the normal doubles" if _law(req)
                   else "the bodies can stick below; the curve starts above the sticking boundary")
            return f"Omega below {lowest:.4g} ({why})"
        return None

    def edges(self, req):
        curve = req.builds.get(OVERLAP_CURVE)
        if curve is None:
            return (OMEGA_LO, OMEGA_HI)
        return (curve.lowest, curve.omega_lo, curve.omega_hi)

    def needs(self, req):
        return OVERLAP_CURVE

    def floor(self, req):
        return least_bound(req.ex)

    def bound(self, req, curve):
        if not curve.covers(req.lo, req.hi):
            return math.inf, Setting(label=f"Omega below {curve.lowest:.4g}, where the curve starts"
                              + (f" above the sticking boundary {curve.stick_below:.6g}" if curve.law is None else ""))
        return curve.bound(req.lo, req.hi), Setting(label=f"{curve.coef.shape[0]} panels", end="overlap")

    def evaluate(self, req, curve, setting, omega):
        return curve.eps(omega)

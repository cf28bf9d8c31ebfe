"""The overlap rule's master curve as a rung (:mod:`restitution.fast.overlap_master`): Chebyshev
panels only, Omega in [1e-4, 1e8] (above the sticking boundary where there is one), its measured
bound; built on its own in about a second when a request pays for it."""

from __future__ import annotations

import math

from ..builds.overlap_curve import OVERLAP_CURVE
from ..overlap_master import OMEGA_HI, OMEGA_LO, least_bound
from ..rung import Rung

__all__ = ["OverlapMaster", "OVERLAP_CURVE"]


class OverlapMaster(Rung):
    name, cost = "master", 4e-8
    ends = ("overlap",)

    def outside(self, req):
        if req.lo < OMEGA_LO or req.hi > OMEGA_HI:
            return f"Omega outside [{OMEGA_LO:g}, {OMEGA_HI:g}] (the overlap curve's range)"
        return None

    def edges(self, req):
        curve = req.builds.get(OVERLAP_CURVE)
        return (OMEGA_LO if curve is None else curve.omega_lo, OMEGA_HI)

    def needs(self, req):
        return OVERLAP_CURVE

    def floor(self, req):
        return least_bound(req.ex)

    def bound(self, req, curve):
        if not curve.covers(req.lo, req.hi):
            return math.inf, (f"Omega below {curve.omega_lo:.4g}, where the curve starts above the sticking "
                              f"boundary {curve.stick_below:.6g}")
        return curve.bound_inside, f"{curve.coef.shape[0]} panels, overlap"

    def evaluate(self, req, curve, setting, omega):
        return curve.eps(omega)

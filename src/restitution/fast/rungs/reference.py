"""The scipy reference (:func:`restitution.core.collision.collide`) as a rung, both end rules, only
where its accuracy was verified (collision.OMEGA_RANGE): bound 10 rtol + 1e-13, more for large
exponents (under the overlap rule, its own: core.conditioning.plain_factor_floor)."""

from __future__ import annotations

import numpy as np

from ..rung import Rung, Setting, reference_bound, reference_rtol

__all__ = ["Reference"]


class Reference(Rung):
    name, cost = "reference", 1e-2
    conditioned = True
    ends = ("force", "overlap")
    collides = trajectories = True

    def outside(self, req):
        from ...core.collision import OMEGA_RANGE
        if req.lo < OMEGA_RANGE[0] or req.hi > OMEGA_RANGE[1]:
            return f"Omega outside [{OMEGA_RANGE[0]:g}, {OMEGA_RANGE[1]:g}] (its verified range)"
        return None

    def edges(self, req):
        from ...core.collision import OMEGA_RANGE
        return OMEGA_RANGE

    def bound(self, req, built):
        rtol = reference_rtol(req.tol, req.problem)
        return reference_bound(rtol, req.problem), Setting(rtol=rtol, end=req.end)

    def evaluate(self, req, built, setting, omega):
        from ...core.collision import collide
        return np.array([collide(req.problem, float(w), rtol=setting.rtol).eps for w in np.ravel(omega)])

    def collision(self, problem, omega, *, rtol, digits, t_eval=None):
        """scipy's DOP853/Radau in smooth variables (core.collision.collide), ``t_eval`` sampled."""
        from ...core.collision import collide
        return collide(problem, omega, rtol=rtol, t_eval=t_eval)

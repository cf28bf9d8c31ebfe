"""The overlap rule's viscous limit law as a rung (:mod:`restitution.core.overlap_limit`): eps = C Omega^k
where gamma < alpha < 2 gamma + 1 and Omega <= LAW_MAX. There the scipy reference follows a creeping
return for seconds, and below its range (1e-12) no other rung answers: the mpmath one would follow
the creep for hours.

Bound: the law's relative deviation decays like exp(-c/Omega) with c -> X^m/m >= 1/(2 gamma + 1)
(core.overlap_limit); at Omega <= 1e-8 that is below exp(-5e6) for every pair the library accepts,
even were the rate a thousand times lower. Left are C's own error (C_error / C, taken twice) and the
rounding of C Omega^k. Measured: the law within 1e-12 of the reference at Omega <= 1e-2 on the
pipeline's pairs (results/dem/overlap_limit.csv) and at 1e-12..1e-8 in tests/library/test_end_rule.py.
"""

from __future__ import annotations

import numpy as np

from ..rung import TOL_FLOOR, Rung, Setting

__all__ = ["OverlapLaw", "LAW_MAX"]

#: Largest Omega the law answers for (the uniform overlap form's range starts here).
LAW_MAX = 1e-8


class OverlapLaw(Rung):
    """eps = C Omega^k, the overlap rule's viscous limit law, gamma < alpha < 2 gamma + 1 and
    Omega <= LAW_MAX (C integrated once, 0.3-0.9 s); bound: twice C's own error plus rounding (its
    exponential correction is below exp(-5e6) there)."""

    # per point (measured 1.8e-8: below the overlap curve's, whose law piece gives the same eps
    # within rounding: where both serve, the law's own evaluation answers, as before the curve had
    # it); the first request of a pair integrates C once (0.3-1.8 s, cached per process)
    name, cost = "overlap-law", 2e-8
    ends = ("overlap",)

    def outside(self, req):
        if not req.ex.alpha < 2 * req.ex.gamma + 1:
            return "alpha >= 2 gamma + 1: the bodies can stick, no law"
        if req.hi > LAW_MAX:
            return f"Omega above {LAW_MAX:g} (where the law's exponential correction may still show)"
        return None

    def edges(self, req):
        return (LAW_MAX,)

    def bound(self, req, built):
        from ...core.overlap_limit import overlap_limit
        lim = overlap_limit(req.ex)
        return 2.0 * lim.C_error / lim.C + 4.0 * TOL_FLOOR, Setting(label=f"C = {lim.C:.12g}, k = {lim.k_exact}")

    def evaluate(self, req, built, setting, omega):
        from ...core.overlap_limit import overlap_limit
        lim = overlap_limit(req.ex)
        om = np.asarray(omega, dtype=float)
        log10_eps = np.log10(lim.C) + lim.k * np.log10(om)
        if np.any(log10_eps < np.log10(np.finfo(float).tiny)):
            raise ArithmeticError(f"eps = C Omega^k = 10^{float(np.min(log10_eps)):.0f} is below the smallest "
                                  "normal double")
        return lim.eps(om)

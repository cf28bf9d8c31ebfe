"""The mpmath reference (:mod:`restitution.core.highprec`) as a rung, both end rules: bound
10^(1 - digits), priced by its digits (it carries log10(1/Omega) more below Omega = 1)."""

from __future__ import annotations

import sys

import numpy as np

from ..rung import Rung, Setting, highprec_bound, highprec_digits

__all__ = ["Highprec", "HIGHPREC_COST", "CREEP_MIN", "highprec_cost"]

#: Seconds per point at 16 digits and Omega >= 1.
HIGHPREC_COST = 0.4


#: Under the overlap rule (alpha > gamma) the return creeps past the force's zero for ~0.2/Omega
#: Taylor steps (measured, 3/2 and 1/2 at 15 digits: 0.8 s at Omega = 1e-3, 7 s at 1e-4, 68 s at
#: 1e-5); below CREEP_MIN it would run for many minutes and hit its step limit, without proving
#: the sticking it may be heading for.
CREEP_MIN = 1e-5


def highprec_cost(omega: np.ndarray, digits: int, creeps: bool = False) -> float:
    """Seconds for the mpmath reference: below Omega = 1 it carries log10(1/Omega) more digits
    (core.highprec), and its time grows like the 2.5th power of the digits (measured, alpha = 3/2,
    gamma = 1/2, 16 digits: 0.15 s at Omega = 1, 0.75 s at 1e-12, 6 s at 1e-60, 190 s at 1e-300);
    a creeping return (``creeps``) multiplies it by 1e-3/Omega below 1e-3."""
    om = np.asarray(omega, float)
    extra = np.maximum(0.0, np.ceil(-np.log10(om)))
    creep = np.maximum(1.0, 1e-3 / om) if creeps else 1.0
    return float(np.sum(HIGHPREC_COST * ((digits + extra) / digits) ** 2.5 * creep))


class Highprec(Rung):
    """The mpmath Taylor reference (:mod:`restitution.core.highprec`): every Omega (alpha <= gamma:
    from 1e-3; the overlap rule: from CREEP_MIN), 0.15 s a point and more at small Omega; bound
    10^(1 - digits), at least the 2.3e-16 of rounding to a double, and its own two-run error
    estimate must agree, else it raises."""

    name, cost = "highprec", HIGHPREC_COST
    ends = ("force", "overlap")
    collides = True

    def outside(self, req):
        if not req.rules_differ and req.lo < 1e-3:
            return "Omega < 1e-3 with alpha <= gamma (creeping)"
        if req.effective_end == "overlap" and req.lo < CREEP_MIN:
            return f"Omega < {CREEP_MIN:g} under the overlap rule (the return creeps for ~0.2/Omega steps)"
        return None

    def edges(self, req):
        if not req.rules_differ:
            return (1e-3,)
        return (CREEP_MIN,) if req.effective_end == "overlap" else ()

    def price(self, req):
        # From the range's ends, not every point: a quote must not cost a pass over a million
        # Omegas for a rung that is almost never chosen (it was a fifth of an epsilon call). The
        # per-point cost is monotone in Omega, so the mean of its two ends times n lies between
        # the cheapest and the dearest point's.
        ends = highprec_cost(np.array([req.lo, req.hi]), highprec_digits(req.tol), req.effective_end == "overlap")
        return ends / 2.0 * req.n

    def bound(self, req, built):
        d = highprec_digits(req.tol)
        return highprec_bound(d), Setting(digits=d, end=req.end)

    def evaluate(self, req, built, setting, omega):
        from ...core.collision import OMEGA_RANGE, collide
        from ...core.highprec import reference_collision
        digits = setting.digits
        seconds = highprec_cost(omega, digits, req.effective_end == "overlap")
        if seconds > 10.0:   # a long wait says so at its start
            print(f"restitution: the mpmath reference on {np.size(omega)} point(s) takes about {seconds:.0f} s",
                  file=sys.stderr if req.stream is None else req.stream, flush=True)
        pulls = req.effective_end == "overlap"
        out = []
        for w in np.ravel(omega):
            w = float(w)
            if pulls and OMEGA_RANGE[0] <= w <= OMEGA_RANGE[1]:
                # mpmath has no proof of sticking and would follow a trapped creep for its whole
                # step budget: the reference integrator's cheap run raises StickError first.
                collide(req.problem, w, rtol=1e-8)
            r = reference_collision(req.problem, w, digits=digits)
            if not r.error_estimate <= 10.0 ** (1 - digits):
                raise ArithmeticError(f"mpmath reference did not converge at Omega = {w} "
                                      f"(estimate {float(r.error_estimate):.3g})")
            out.append(float(r.eps))
        return np.array(out)

    def collision(self, problem, omega, *, rtol, digits, t_eval=None):
        """The mpmath Taylor series at ``digits`` digits, rounded to doubles; its rtol is 10^(1 - digits)."""
        from ...core.highprec import reference_collision
        from ...core.results import Collision
        r = reference_collision(problem, omega, digits=digits)
        return Collision(problem, float(r.omega), "forward", float(r.eps), float(r.tau_b), float(r.x_b),
                         float(r.tau_c), float(r.x_c), r.ended_by, 10.0 ** (1 - r.digits),
                         one_minus_eps=float(1 - r.eps))

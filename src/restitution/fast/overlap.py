"""The rungs of the method ladder that serve the overlap end-of-contact rule.

Under the overlap rule (contact ends when x returns to 0, the force turning attractive on the way)
eps differs from the force rule's wherever the force can vanish during contact (alpha > gamma).
The master curve, the expansions and the relation rungs were built from force-rule collisions, and
the compiled integrator stops at zero force: none of them may answer an overlap request. What can:

* ``closed-form``: the linear dashpot's half period (core.dashpot), Omega > 1/4;
* ``reference``: core.collision.collide(end="overlap"), same bound as for the force rule;
* ``highprec``: core.highprec.reference_collision(end="overlap").

For alpha <= gamma the force stays positive until x = 0, the two rules give the same collision,
and the full ladder serves both (restitution.fast.ladder.Ladder.evaluate decides).
"""

from __future__ import annotations

import math

import numpy as np

from ..core.collision import OMEGA_RANGE, collide
from ..core.exponents import Exponents
from .ladder import COST, TOL_FLOOR, _Quote
from .slow_rungs import _highprec_cost

__all__ = ["overlap_quotes", "OVERLAP_RUNGS"]

#: The rungs that can compute an overlap-rule eps.
OVERLAP_RUNGS = ("closed-form", "reference", "highprec")


def overlap_quotes(ex: Exponents, omega: np.ndarray, tol: float) -> list[_Quote]:
    """The chooser's table for an overlap request: every other rung is listed as unavailable."""
    from .ladder import rung_names

    lo, hi = float(np.min(omega)), float(np.max(omega))
    n = omega.size
    out = []
    if (ex.alpha, ex.gamma) == (1, 0) and lo > 0.25:
        out.append(_Quote("closed-form", 2e-14, COST["closed-dashpot"] * n, "overlap",
                          run=lambda om: _eps(om, lambda w: _dashpot(w))))
    rtol = min(1e-6, max(1e-14, (tol - 1e-13) / 20.0))
    if OMEGA_RANGE[0] <= lo and hi <= OMEGA_RANGE[1]:
        out.append(_Quote("reference", 10.0 * rtol + 1e-13, COST["reference"] * n, f"rtol={rtol:.3g}, overlap",
                          run=lambda om: _eps(om, lambda w: collide(ex, None, w, rtol=rtol, end="overlap").eps)))
    digits = int(min(60, max(15, math.ceil(-math.log10(tol)) + 3)))
    out.append(_Quote("highprec", max(10.0 ** (1 - digits), TOL_FLOOR), _highprec_cost(omega, digits),
                      f"digits={digits}, overlap", run=lambda om: _eps(om, lambda w: _highprec(ex, w, digits))))
    served = {q.name for q in out}
    out += [_Quote(name, math.inf, math.inf, reason="serves the force rule only (or not these Omegas)")
            for name in rung_names(()) if name not in served]
    return out


def _eps(om: np.ndarray, one) -> np.ndarray:
    return np.array([one(float(w)) for w in np.ravel(om)])


def _dashpot(w: float) -> float:
    from ..core.dashpot import dashpot_collision
    return dashpot_collision(w, end="overlap").eps


def _highprec(ex: Exponents, w: float, digits: int) -> float:
    from ..core.highprec import reference_collision
    # mpmath has no proof of sticking and would follow a trapped creep for its whole step budget:
    # the reference integrator's cheap run raises StickError first where the bodies never part.
    if OMEGA_RANGE[0] <= w <= OMEGA_RANGE[1]:
        collide(ex, None, w, rtol=1e-8, end="overlap")
    r = reference_collision(ex, None, w, digits=digits, end="overlap")
    if not r.error_estimate <= 10.0 ** (1 - digits):
        raise ArithmeticError(f"mpmath reference did not converge at Omega = {w} "
                              f"(estimate {float(r.error_estimate):.3g})")
    return float(r.eps)

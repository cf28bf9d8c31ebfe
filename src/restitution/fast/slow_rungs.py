"""The ladder's rungs that call a full integration per point: the scipy reference, the mpmath
reference (with its cost model) and the linear spring-dashpot's exact solution."""

from __future__ import annotations

import sys

import numpy as np

from ..core.exponents import Exponents

#: Seconds per point of the mpmath reference at 16 digits and Omega >= 1 (the ladder's COST["highprec"]).
HIGHPREC_COST = 0.4


def _dashpot_eps(om: np.ndarray) -> np.ndarray:
    from ..core.dashpot import dashpot_collision
    return np.array([dashpot_collision(float(w)).eps for w in np.ravel(om)])


def _scipy_eps(ex: Exponents, om: np.ndarray, rtol: float) -> np.ndarray:
    from ..core.collision import collide
    return np.array([collide(ex, None, float(w), rtol=rtol).eps for w in np.ravel(om)])


def _highprec_cost(omega: np.ndarray, digits: int) -> float:
    """Seconds for the mpmath reference: below Omega = 1 it carries log10(1/Omega) more digits
    (core.highprec), and its time grows like the 2.5th power of the digits (measured, alpha = 3/2,
    gamma = 1/2, 16 digits: 0.15 s at Omega = 1, 0.75 s at 1e-12, 6 s at 1e-60, 190 s at 1e-300)."""
    extra = np.maximum(0.0, np.ceil(-np.log10(np.asarray(omega, float))))
    return float(np.sum(HIGHPREC_COST * ((digits + extra) / digits) ** 2.5))


def _highprec_eps(ex: Exponents, om: np.ndarray, digits: int, stream=None) -> np.ndarray:
    from ..core.highprec import reference_collision
    seconds = _highprec_cost(om, digits)
    if seconds > 10.0:   # a long wait says so at its start
        print(f"restitution: the mpmath reference on {np.size(om)} point(s) takes about {seconds:.0f} s",
              file=sys.stderr if stream is None else stream, flush=True)
    out = []
    for w in np.ravel(om):
        r = reference_collision(ex, None, float(w), digits=digits)
        if not r.error_estimate <= 10.0 ** (1 - digits):
            raise ArithmeticError(f"mpmath reference did not converge at Omega = {w} "
                                  f"(estimate {float(r.error_estimate):.3g})")
        out.append(float(r.eps))
    return np.array(out)

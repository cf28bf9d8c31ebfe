"""Exact solution of the linear spring-dashpot collision (alpha = 1, gamma = 0).

    x'' + x' + Omega x = 0,   x(0) = 0,  x'(0) = 1        (Schwager & Poeschel 2007, Granular Matter 9, 465)

With z = Omega - 1/4 and w = sqrt|z| the motion is x = e^(-tau/2) S(tau), x' = e^(-tau/2) (C - S/2) with

    S = sin(w tau)/w,  C = cos(w tau)      (z > 0, underdamped)
    S = sinh(w tau)/w, C = cosh(w tau)     (z < 0, overdamped)
    S = tau,           C = 1               (z = 0, critical)

Maximum compression (x' = 0): tan(w tau_b) = 2w, resp. tanh(w tau_b) = 2w, so tau_b = 2 at z = 0.
The force -(x' + Omega x) vanishes where x'' = 0: tan(w tau_c) = w / (1/2 - Omega) on the branch in
(0, pi), resp. tanh(w tau_c) = w / (1/2 - Omega); tau_c = 4 at z = 0.

Putting those back into x and x' gives, in every regime,

    x_b = e^(-tau_b/2) / sqrt(Omega),   x_c = e^(-tau_c/2) / Omega,   eps = Omega x_c = e^(-tau_c/2),

so everything hinges on tau_b and tau_c, computed without cancellation (below). Under the overlap
rule (contact ends when x returns to 0, the force turning attractive first) the underdamped motion
ends at its half period, tau_c = pi / w, eps = e^(-pi/(2w)); overdamped and critical motions
never return to x = 0 (the bodies stick).

tau_b and tau_c without cancellation:

- near Omega = 1/4 as tau = theta / w through atan(y)/y or atanh(y)/y, which are smooth in y = O(w) and
  need no special case beyond y = 0;
- for small Omega (strongly overdamped), where tanh(w tau) -> 1, through the logarithmic forms
  w tau_b = log((1 + 2w) / (2 sqrt(Omega))) and w tau_c = log((1/2 - Omega + w) / Omega).
"""

from __future__ import annotations

import math
from .exponents import Exponents

import numpy as np

from .problem import Problem
from .results import Collision, end_rule
from .errors import ParameterError, require_positive_finite

#: Below this argument atanh(y)/y is used; above it the logarithmic forms (no 1 - y cancellation).
_ATANH_SWITCH = 0.5


def _atan_over(y: float) -> float:
    """atan(y)/y, with its limit 1 at y = 0."""
    return math.atan(y) / y if y else 1.0


def _atanh_over(y: float) -> float:
    """atanh(y)/y, with its limit 1 at y = 0."""
    return math.atanh(y) / y if y else 1.0


def contact_times(omega: float) -> tuple[float, float]:
    """(tau_b, tau_c) of the linear dashpot in closed form."""
    omega = require_positive_finite("omega", omega)
    z = omega - 0.25
    if z >= 0:
        w = math.sqrt(z)
        tau_b = 2.0 * _atan_over(2.0 * w)
        half = 0.5 - omega
        if half > 0:
            tau_c = _atan_over(w / half) / half
        else:  # x'' = 0 past a quarter period: the atan2 branch in [pi/2, pi)
            tau_c = math.atan2(w, half) / w
        return tau_b, tau_c
    w = math.sqrt(-z)
    half = 0.5 - omega          # > 1/4 here
    if 2.0 * w < _ATANH_SWITCH:
        tau_b = 2.0 * _atanh_over(2.0 * w)
    else:
        # atanh(2w) = log((1 + 2w)^2 / (1 - 4w^2)) / 2 and 1 - 4w^2 = 4 Omega exactly.
        tau_b = math.log((1.0 + 2.0 * w) / (2.0 * math.sqrt(omega))) / w
    if w / half < _ATANH_SWITCH:
        tau_c = _atanh_over(w / half) / half
    else:
        # (1 + y)/(1 - y) with y = w/half equals (half + w)^2 / Omega^2, since half^2 - w^2 = Omega^2.
        tau_c = math.log((half + w) / omega) / w
    return tau_b, tau_c


def dashpot_collision(omega, end: str = "force", *, excess: float | None = None) -> Collision:
    """The forward collision of the linear dashpot, exact; same fields as collision.collide().

    ``rtol`` is 0.0: nothing is integrated. ``end``: the end-of-contact rule (results.END_RULES);
    "overlap" needs Omega > 1/4 (otherwise the bodies never separate: ParameterError).
    ``excess``: Omega - 1/4 where the caller knows it better than ``omega - 0.25`` of the rounded
    ``omega`` (core.exact_family's (gamma+1) Omega - 1/4, formed exactly): the overlap rule's half
    period pi / sqrt(Omega - 1/4) amplifies an error in it without bound near Omega = 1/4.
    """
    omega = require_positive_finite("omega", omega)
    rule = end_rule(end)
    tau_b, tau_c = contact_times(omega)
    x_b = math.exp(-0.5 * tau_b) / math.sqrt(omega)
    if rule == "overlap":
        z = omega - 0.25 if excess is None else float(excess)
        if not z > 0:
            raise ParameterError("omega", omega, "must be > 1/4 under the overlap rule: an overdamped "
                                 "dashpot never returns to x = 0 (the bodies stick)")
        tau_c = math.pi / math.sqrt(z)
        x_c, how = 0.0, "separation"
    eps = math.exp(-0.5 * tau_c)
    if rule == "force":
        x_c, how = eps / omega, "force"
    return Collision(Problem(Exponents.parse(1, 0), rule), omega, "forward", eps, tau_b, x_b, tau_c, x_c,
                     how, 0.0, None, -math.expm1(-0.5 * tau_c))


def dashpot_trajectory(tau, omega) -> tuple[np.ndarray, np.ndarray]:
    """(x, x') of the linear dashpot at the given tau (any shape, tau >= 0 intended)."""
    omega = require_positive_finite("omega", omega)
    tau = np.asarray(tau, dtype=float)
    z = omega - 0.25
    w = math.sqrt(abs(z))
    if z > 0:
        s = np.sin(w * tau) / w
        c = np.cos(w * tau)
        damp = np.exp(-0.5 * tau)
        return damp * s, damp * (c - 0.5 * s)
    if z == 0 or w == 0.0:
        damp = np.exp(-0.5 * tau)
        return damp * tau, damp * (1.0 - 0.5 * tau)
    return _overdamped(tau, omega, w)


def _overdamped(tau: np.ndarray, omega: float, w: float) -> tuple[np.ndarray, np.ndarray]:
    """e^(-tau/2) sinh(w tau)/w and e^(-tau/2) (cosh - sinh/(2w)) without overflow or cancellation.

    For w tau >= 1 the two exponentials e^((w-1/2) tau) and e^(-(w+1/2) tau) are combined directly
    (w - 1/2 = -Omega/(w + 1/2) avoids cancelling at small Omega); for w tau < 1 sinh and cosh
    are safe and avoid the cancellation in e^(w tau) - e^(-w tau).
    """
    slow_rate = -omega / (w + 0.5)      # w - 1/2
    fast_rate = -(w + 0.5)
    wt = w * tau
    small = np.abs(wt) < 1.0
    with np.errstate(over="ignore", invalid="ignore"):
        damp = np.exp(-0.5 * tau)
        s_small = damp * np.sinh(wt) / w
        c_small = damp * np.cosh(wt)
        slow = np.exp(slow_rate * tau)
        fast = np.exp(fast_rate * tau)
        s_big = (slow - fast) / (2.0 * w)
        c_big = 0.5 * (slow + fast)
    s = np.where(small, s_small, s_big)
    c = np.where(small, c_small, c_big)
    # For large w tau, x' = ((w - 1/2) slow + (w + 1/2) fast) / (2w): no difference of big terms.
    v_big = 0.5 * ((slow_rate / w) * slow + ((w + 0.5) / w) * fast)
    v = np.where(small, c - 0.5 * s, v_big)
    return s, v

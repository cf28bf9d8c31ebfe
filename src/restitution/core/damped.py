"""Closed forms of the damped-only problem (Omega = 0, gamma = 1) that the paper builds on.

Forward:  x'' + x x' = 0 has the first integral x' + x^2/2 = x'(0) + x(0)^2/2.
Inverse:  x'' - x x' = 0 has the first integral x' - x^2/2 = x'(0) - x(0)^2/2.

From x(0) = x0 >= 0, x'(0) = 1 these integrate to tanh (forward) and tan (inverse).
The paper prints for the inverse case G tanh(atanh(x_c/G) + G tau/2) with
G = sqrt(x_c^2 + 2); that function satisfies the *forward* first integral, not the
inverse one (``paper_inverse_closed_form`` keeps it so the discrepancy can be shown).
"""

from __future__ import annotations

import math

import numpy as np

from .errors import ParameterError

SQRT2 = math.sqrt(2.0)


def _start(x_start: float) -> float:
    x = float(x_start)
    if not math.isfinite(x) or x < 0:
        raise ParameterError("x_start", x_start, "must be a finite number >= 0")
    return x


def forward(tau, x_start: float = 0.0):
    """(x, x') of x'' + x x' = 0, x(0) = x_start, x'(0) = 1.

    x' = (G^2 - x^2)/2 with G^2 = x_start^2 + 2, hence x = G tanh(atanh(x_start/G) + G tau/2).
    For x_start = 0 this is sqrt(2) tanh(tau / sqrt(2)).
    """
    x0 = _start(x_start)
    G = math.sqrt(x0 * x0 + 2.0)
    x = G * np.tanh(math.atanh(x0 / G) + 0.5 * G * np.asarray(tau, dtype=float))
    return x, 0.5 * (G * G - x * x)


def inverse(tau, x_start: float = 0.0):
    """(x, x') of x'' - x x' = 0, x(0) = x_start, x'(0) = 1.

    x' = (H^2 + x^2)/2 with H^2 = 2 - x_start^2. For x_start < sqrt(2):
    x = H tan(atan(x_start/H) + H tau/2); x_start = 0 gives sqrt(2) tan(tau / sqrt(2)),
    which blows up at tau = pi/sqrt(2) (the inverse run has negative damping).
    """
    x0 = _start(x_start)
    H2 = 2.0 - x0 * x0
    tau = np.asarray(tau, dtype=float)
    if H2 > 0:
        H = math.sqrt(H2)
        x = H * np.tan(math.atan(x0 / H) + 0.5 * H * tau)
    elif H2 == 0:
        x = x0 / (1.0 - 0.5 * x0 * tau)
    else:
        K = math.sqrt(-H2)
        # x' = (x^2 - K^2)/2 with x > K: x = K coth(acoth(x0/K) - K tau/2).
        x = K / np.tanh(math.atanh(K / x0) - 0.5 * K * tau)
    return x, 0.5 * (H2 + x * x)


def paper_inverse_closed_form(tau, x_c: float):
    """The paper's printed inverse damped-only solution G tanh(atanh(x_c/G) + G tau/2), G = sqrt(x_c^2+2)."""
    x0 = _start(x_c)
    G = math.sqrt(x0 * x0 + 2.0)
    return G * np.tanh(0.5 * math.log((1 + x0 / G) / (1 - x0 / G)) + 0.5 * G * np.asarray(tau, dtype=float))


def forward_first_integral(x, v, gamma=1):
    """x' + x^(gamma+1)/(gamma+1): constant along x'' + x^gamma x' = 0 (= 1 from x = 0, x' = 1)."""
    k = float(gamma) + 1.0
    return np.asarray(v) + np.asarray(x, dtype=float) ** k / k


def inverse_first_integral(x, v, gamma=1):
    """x' - x^(gamma+1)/(gamma+1): constant along x'' - x^gamma x' = 0 (= 1 from x = 0, x' = 1)."""
    k = float(gamma) + 1.0
    return np.asarray(v) - np.asarray(x, dtype=float) ** k / k

"""The energy balance of a collision, for 1 - eps without cancellation.

Near the elastic limit eps = -x'(tau_c) is within rtol of 1, and 1 - eps by subtraction keeps only
its absolute accuracy. The energy lost during contact gives it to relative accuracy instead.
"""

from __future__ import annotations

import numpy as np

__all__ = ["NEAR_ELASTIC", "one_minus_eps", "dissipated"]

#: Below this 1 - eps, eps is taken as 1 - (1 - eps) (see collide).
NEAR_ELASTIC = 1e-3


def one_minus_eps(dissipated: float, potential_end: float, eps: float) -> float:
    """1 - eps without cancellation. The energy E = x'^2/2 + Omega x^(alpha+1)/(alpha+1) starts at
    1/2 and loses dE/dtau = -x^gamma x'^2; at the end of contact E = eps^2/2 + U_c. So
    1 - eps^2 = 2 (D + U_c) with D the dissipated energy and U_c the potential energy left at x_c,
    both positive: 1 - eps = 2 (D + U_c) / (1 + eps)."""
    return 2.0 * (dissipated + potential_end) / (1.0 + eps)


_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(10)


def dissipated(pieces, law) -> float:
    """D = integral of x^gamma x'^2 dtau over the contact: Gauss-Legendre on every step of every
    leg's dense output (``pieces``: the legs of :mod:`restitution.core.collision`, ``law`` its
    exponents). Tau legs have the state (x, v); in u legs x = u^p and dtau = p u^(p-1) du / |v|,
    so the integrand is p u^(q_gamma + p - 1) |v|."""
    total = 0.0
    for piece in pieces:
        ts = np.clip(np.asarray(piece.sol.ts, dtype=float), piece.lo, piece.hi)
        # a leg may end a hair beyond its last step (collision._to_force_end): its dense output
        # polynomial reaches there
        ts = np.unique(np.concatenate([ts, [piece.lo, piece.hi]]))
        if ts.size < 2:
            continue
        mid, half = 0.5 * (ts[1:] + ts[:-1]), 0.5 * (ts[1:] - ts[:-1])
        nodes = (mid[:, None] + half[:, None] * _GAUSS_X).ravel()
        y = piece.sol(nodes)
        if piece.in_u:
            f = law.p * nodes ** (law.qg + law.p - 1) * np.abs(y[0])
        else:
            f = np.abs(y[0]) ** law.gamma * y[1] ** 2
        total += float(np.sum(half[:, None] * _GAUSS_W * f.reshape(half.size, -1)))
    return total

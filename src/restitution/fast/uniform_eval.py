"""The uniform approximations (:mod:`restitution.core.uniform`, both end rules) as compiled loops: the
ladder's uniform rung and the benchmark evaluate them here (the numpy version in core makes a
dozen temporary arrays per call and reaches about half the speed)."""

from __future__ import annotations

import math

import numpy as np

from ..core.uniform import OVERLAP_P, UniformForm
from .jit import njit

__all__ = ["uniform_eps"]


@njit(cache=True)
def _one_plus_minus_u(lx, half_sigma):  # pragma: no cover - compiled
    """1 + u and 1 - u for u = tanh(sigma/2 ln x) = (x^sigma - 1)/(x^sigma + 1), each without cancellation."""
    xs = math.exp(2.0 * half_sigma * lx)
    if xs > 1e300:
        return 2.0, 0.0
    return 2.0 * xs / (xs + 1.0), 2.0 / (xs + 1.0)


@njit(cache=True)
def _power_series(coef, u):  # pragma: no cover - compiled
    """sum coef[j] u^j (Horner)."""
    poly = coef[coef.size - 1]
    for j in range(coef.size - 2, -1, -1):
        poly = poly * u + coef[j]
    return poly


@njit(cache=True)
def _chebyshev_series(coef, u):  # pragma: no cover - compiled
    """sum coef[j] T_j(u) (Clenshaw)."""
    b1, b2 = 0.0, 0.0
    for j in range(coef.size - 1, 0, -1):
        b1, b2 = 2.0 * u * b1 - b2 + coef[j], b1
    return u * b1 - b2 + coef[0]


@njit(cache=True)
def _kernel(om, A, k, b, c_log, c3, half_sigma, m0, m1, coef, out):  # pragma: no cover - compiled
    for i in range(om.size):
        x = b * om[i]
        lx = math.log(x)
        l1 = math.log1p(x)                      # and log1p(1/x) = l1 - lx
        up, um = _one_plus_minus_u(lx, half_sigma)
        u = up - 1.0
        skel = (b * math.exp((1.0 - A) * l1) / x + (c_log * (l1 - lx) + c3) / ((1.0 + x) * (1.0 + x))) / k
        env = 1.0
        for _ in range(m0):
            env *= up
        for _ in range(m1):
            env *= um
        out[i] = 1.0 / (1.0 + skel + env * _power_series(coef, u))


@njit(cache=True)
def _kernel_overlap(om, A, kv, b, lnK, decay_rate, half_sigma, m1, P, coef, out):  # pragma: no cover - compiled
    for i in range(om.size):
        x = b * om[i]
        lx = math.log(x)
        lp = math.log1p(math.exp(P * lx))       # ln(1 + x^P)
        w = math.exp(P * lx - lp)
        um = _one_plus_minus_u(lx, half_sigma)[1]
        u = 1.0 - um
        env = math.exp(-decay_rate / x)
        for _ in range(m1):
            env *= um
        poly = _chebyshev_series(coef, u)
        out[i] = 1.0 / (w + math.exp(lnK - kv * lx + (kv - A) / P * lp + env * poly))


def uniform_eps(form: UniformForm, omegas) -> np.ndarray:
    """eps from the form at each Omega (same values as ``form.eps`` to rounding)."""
    om = np.asarray(omegas, dtype=np.float64)
    flat = np.ascontiguousarray(om.ravel())
    out = np.empty(flat.size)
    s = form.skel
    coef = np.ascontiguousarray(form.coef, dtype=np.float64)
    if form.end == "overlap":
        _kernel_overlap(flat, s.A, s.kv, s.b, math.log(s.K), form.rate, 0.5 * form.sigma, form.m1, float(OVERLAP_P),
                        coef, out)
        return out.reshape(om.shape)
    _kernel(flat, s.A, s.k, s.b, s.c_log, s.c3, 0.5 * form.sigma, form.m0, form.m1, coef, out)
    return out.reshape(om.shape)

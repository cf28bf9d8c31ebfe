"""The uniform closed form (:mod:`restitution.core.uniform`) as one compiled loop: the ladder's
closed-form rung and the benchmark evaluate it here (the numpy version in core makes a dozen
temporary arrays per call and reaches about half the speed)."""

from __future__ import annotations

import math

import numpy as np

from ..core.uniform import UniformForm
from .jit import njit

__all__ = ["uniform_eps"]


@njit(cache=True)
def _kernel(om, A, k, b, c_log, c3, half_sigma, m0, m1, coef, out):  # pragma: no cover - compiled
    n = coef.size
    for i in range(om.size):
        x = b * om[i]
        lx = math.log(x)
        l1 = math.log1p(x)                      # and log1p(1/x) = l1 - lx
        xs = math.exp(2.0 * half_sigma * lx)    # x^sigma; u = (xs - 1)/(xs + 1) = tanh(sigma/2 ln x)
        if xs > 1e300:
            up, um = 2.0, 0.0
        else:
            up, um = 2.0 * xs / (xs + 1.0), 2.0 / (xs + 1.0)   # 1 + u and 1 - u, each without cancellation
        u = up - 1.0
        skel = (b * math.exp((1.0 - A) * l1) / x + (c_log * (l1 - lx) + c3) / ((1.0 + x) * (1.0 + x))) / k
        env = 1.0
        for _ in range(m0):
            env *= up
        for _ in range(m1):
            env *= um
        poly = coef[n - 1]
        for j in range(n - 2, -1, -1):
            poly = poly * u + coef[j]
        out[i] = 1.0 / (1.0 + skel + env * poly)


def uniform_eps(form: UniformForm, omegas) -> np.ndarray:
    """eps from the form at each Omega (same values as ``form.eps`` to rounding)."""
    om = np.asarray(omegas, dtype=np.float64)
    flat = np.ascontiguousarray(om.ravel())
    out = np.empty(flat.size)
    s = form.skel
    _kernel(flat, s.A, s.k, s.b, s.c_log, s.c3, 0.5 * form.sigma, form.m0, form.m1,
            np.ascontiguousarray(form.coef, dtype=np.float64), out)
    return out.reshape(om.shape)

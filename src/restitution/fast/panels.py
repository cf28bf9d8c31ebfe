"""The master curve's compiled evaluation: uniform panels in s = ln Omega, a Chebyshev series of
ln eps in each, and the asymptotic expansions beyond both ends. One fused loop costs a few tens of
nanoseconds per point; the same in numpy needs ~3 array passes per Chebyshev term, i.e. several
times more memory traffic.

Above THREAD_MIN_POINTS points the array is cut into one slice per processor, each evaluated by the
same loop on a thread of its own (the loop releases the GIL): every point gets the same operations
in the same order, so the same double, as in one pass.
"""

from __future__ import annotations

import math

import numpy as np

from .jit import call_kernel, compiled, njit, worker_threads

__all__ = ["PanelRange", "chebyshev_panels_eval"]


@njit(cache=True)
def _viscous_eval(om, vis):
    """Viscous-limit expansion; vis = (kind, k, c_log, c_const, power).

    kind 0 (alpha > gamma): eps = k Omega (1 - Omega (c_log ln(1/Omega) + c_const)).
    kind 1 (alpha < gamma): eps = k Omega^power.
    """
    if vis[0] == 0.0:
        return vis[1] * om * (1.0 - om * (vis[2] * math.log(1.0 / om) + vis[3]))
    return vis[1] * math.exp(vis[4] * math.log(om))


@njit(cache=True)
def _elastic_eval(om, el):
    """Elastic-limit expansion; el = (a, c1, c2, end_power, end_coeff).

    delta = Omega^(-a); eps = 1 - c1 delta + c2 delta^2 + end_coeff delta^end_power.
    """
    dl = math.exp(-el[0] * math.log(om))
    r = 1.0 - el[1] * dl + el[2] * dl * dl
    if el[4] != 0.0:
        r += el[4] * math.exp(el[3] * math.log(dl))
    return r


@njit(cache=True, nogil=True)
def _panels_eval(omegas, s0, inv_w, coef, vis, el, out):
    npan = coef.shape[0]
    deg = coef.shape[1] - 1
    s_hi = s0 + npan / inv_w
    for i in range(omegas.size):
        om = omegas[i]
        s = math.log(om)
        if s < s0:
            out[i] = _viscous_eval(om, vis)
            continue
        if s > s_hi:
            out[i] = _elastic_eval(om, el)
            continue
        z = (s - s0) * inv_w
        j = int(z)
        if j >= npan:
            j = npan - 1
        t = 2.0 * (z - j) - 1.0
        # Clenshaw
        b1 = 0.0
        b2 = 0.0
        t2 = 2.0 * t
        for r in range(deg, 0, -1):
            b0 = coef[j, r] + t2 * b1 - b2
            b2 = b1
            b1 = b0
        out[i] = math.exp(coef[j, 0] + t * b1 - b2)


def chebyshev_panels_eval(omegas, s0: float, width: float, coef: np.ndarray, viscous: np.ndarray,
                          elastic: np.ndarray) -> np.ndarray:
    """eps at each Omega from panel Chebyshev coefficients of ln eps (see master.MasterCurve)."""
    om = np.ascontiguousarray(np.asarray(omegas, dtype=np.float64).ravel())
    out = np.empty(om.size)
    args = (float(s0), 1.0 / float(width), np.ascontiguousarray(coef, dtype=np.float64),
            np.ascontiguousarray(viscous, dtype=np.float64), np.ascontiguousarray(elastic, dtype=np.float64))
    slices = min(worker_threads(), om.size // THREAD_MIN_POINTS)
    if slices < 2:
        call_kernel(om.size, INTERPRETED_MAX_POINTS, _panels_eval, om, *args, out)
        return out
    run = compiled(_panels_eval)
    cuts = np.linspace(0, om.size, slices + 1).astype(int)
    with _pool(slices) as pool:
        done = [pool.submit(run, om[a:b], *args, out[a:b]) for a, b in zip(cuts[:-1], cuts[1:])]
        for d in done:
            d.result()
    return out


#: Arrays of at least twice this many points are cut into slices on threads (a thread's start and
#: join cost tens of microseconds: below this the loop alone is about as fast).
THREAD_MIN_POINTS = 50_000


def _pool(n: int):
    from concurrent.futures import ThreadPoolExecutor
    return ThreadPoolExecutor(max_workers=n)


#: Up to this many Omegas a process that has not started numba evaluates in plain Python (tens
#: of microseconds each, against most of a second for numba's start).
INTERPRETED_MAX_POINTS = 2000


class PanelRange:
    """The Omega range of panels of width ``width`` in s = ln Omega from ``s0``, one per row of
    ``coef`` (both master curves, force and overlap rule, are laid out so)."""

    @property
    def omega_lo(self) -> float:
        return math.exp(self.s0)

    @property
    def omega_hi(self) -> float:
        return math.exp(self.s0 + self.coef.shape[0] * self.width)

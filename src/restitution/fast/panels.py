"""The master curve's compiled evaluation: uniform panels in s = ln Omega, a Chebyshev series of
ln eps in each, and the asymptotic expansions beyond both ends.

Three passes over the array, each at the speed of its kind: numpy's ``log`` (vectorised), one
compiled Clenshaw pass in place, numpy's ``exp`` (vectorised). The compiled pass goes through the
points in blocks and runs the recurrence over a whole block term by term: each point's recurrence
is a chain of dependent steps, and a block gives the processor many independent chains at once
(about three times the speed of the scalar loop with ``math.log`` and ``math.exp``, which also
cannot be vectorised without a vector maths library). numpy's log and exp differ from libm's by at
most an ulp or two, far inside every curve's stated bound (at least 1e-14 inside the panels).

The few points beyond the panels are marked in that pass and evaluated afterwards from Omega itself
by the expansions (an exp of ln eps would lose |ln eps| ulps, where the viscous end is exact to the
last bit).

Above THREAD_MIN_POINTS points the array is cut into one slice per processor, each evaluated by the
same passes on a thread of a pool kept for the process (numpy's loops and the compiled pass
release the GIL): every point gets the same operations in the same order, so the same double, as
in one pass.
"""

from __future__ import annotations

import math
import os

import numpy as np

from .jit import call_kernel, compiled, njit, worker_threads

__all__ = ["PanelRange", "chebyshev_panels_eval"]


@njit(cache=True, nogil=True)
def _viscous_eval(om, vis):
    """Viscous-limit expansion; vis = (kind, k, c_log, c_const, power).

    kind 0 (alpha > gamma): eps = k Omega (1 - Omega (c_log ln(1/Omega) + c_const)).
    kind 1 (alpha < gamma): eps = k Omega^power.
    """
    if vis[0] == 0.0:
        return vis[1] * om * (1.0 - om * (vis[2] * math.log(1.0 / om) + vis[3]))
    return vis[1] * math.exp(vis[4] * math.log(om))


@njit(cache=True, nogil=True)
def _elastic_eval(om, el):
    """Elastic-limit expansion; el = (a, c1, c2, end_power, end_coeff).

    delta = Omega^(-a); eps = 1 - c1 delta + c2 delta^2 + end_coeff delta^end_power.
    """
    dl = math.exp(-el[0] * math.log(om))
    r = 1.0 - el[1] * dl + el[2] * dl * dl
    if el[4] != 0.0:
        r += el[4] * math.exp(el[3] * math.log(dl))
    return r


#: Points per block of the Clenshaw pass: its four work arrays stay in the first-level cache.
BLOCK = 256


@njit(cache=True, nogil=True)
def _panels_ln(s_in, s0, inv_w, coef_t, out):
    """ln eps at s = ln Omega (``s_in``; ``out`` may be the same array) from the panels' Chebyshev
    coefficients, ``coef_t[r, j]`` the r-th of panel j. A point beyond the panels gets NaN; returns
    how many did."""
    deg = coef_t.shape[0] - 1
    npan = coef_t.shape[1]
    s_hi = s0 + npan / inv_w
    n = s_in.size
    idx = np.empty(BLOCK, np.intp)
    tt = np.empty(BLOCK)
    b1 = np.empty(BLOCK)
    b2 = np.empty(BLOCK)
    beyond = 0
    for start in range(0, n, BLOCK):
        m = min(BLOCK, n - start)
        for i in range(m):
            s = s_in[start + i]
            if s < s0 or s > s_hi:
                idx[i] = -1
                tt[i] = 0.0
                b1[i] = 0.0
            else:
                z = (s - s0) * inv_w
                j = int(z)
                if j >= npan:
                    j = npan - 1
                idx[i] = j
                tt[i] = 2.0 * (z - j) - 1.0
                b1[i] = coef_t[deg, j] if deg > 0 else 0.0
            b2[i] = 0.0
        # Clenshaw, term by term over the block (independent chains: the processor overlaps them)
        for r in range(deg - 1, 0, -1):
            row = coef_t[r]
            for i in range(m):
                j = idx[i]
                c = row[j] if j >= 0 else 0.0
                b0 = c + 2.0 * tt[i] * b1[i] - b2[i]
                b2[i] = b1[i]
                b1[i] = b0
        row = coef_t[0]
        for i in range(m):
            j = idx[i]
            if j >= 0:
                out[start + i] = row[j] + tt[i] * b1[i] - b2[i]
            else:
                out[start + i] = math.nan
                beyond += 1
    return beyond


#: How far inside a join (in ln Omega) a marked point is still taken for an end point: the marks
#: come from numpy's log, this pass reads libm's, which may differ by an ulp (1e-12 in ln Omega is
#: a relative 1e-12 in Omega, inside master.JOIN_SLACK, where both sides' bounds hold).
_JOIN_S = 1e-12


@njit(cache=True, nogil=True)
def _ends_eval(omegas, s0, s_hi, vis, el, out):
    """The expansions at the points ``_panels_ln`` marked (NaN): the viscous one below the panels,
    the elastic one above. A NaN from inside the panels (non-finite coefficients) stays NaN, for
    the caller to refuse."""
    for i in range(omegas.size):
        if out[i] != out[i]:
            om = omegas[i]
            s = math.log(om)
            if s <= s0 + _JOIN_S:
                out[i] = _viscous_eval(om, vis)
            elif s >= s_hi - _JOIN_S:
                out[i] = _elastic_eval(om, el)


def _eval_slice(om, out, s0, inv_w, coef_t, vis, el):
    with np.errstate(all="ignore"):   # (per thread) what the compiled passes do silently
        np.log(om, out=out)
        beyond = call_kernel(om.size, INTERPRETED_MAX_POINTS, _panels_ln, out, s0, inv_w, coef_t, out)
        np.exp(out, out=out)
        if beyond:
            call_kernel(om.size, INTERPRETED_MAX_POINTS, _ends_eval, om, s0, s0 + coef_t.shape[1] / inv_w,
                        vis, el, out)


def chebyshev_panels_eval(omegas, s0: float, width: float, coef: np.ndarray, viscous: np.ndarray,
                          elastic: np.ndarray) -> np.ndarray:
    """eps at each Omega from panel Chebyshev coefficients of ln eps (see master.MasterCurve)."""
    om = np.ascontiguousarray(np.asarray(omegas, dtype=np.float64).ravel())
    out = np.empty(om.size)
    args = (float(s0), 1.0 / float(width), np.ascontiguousarray(np.asarray(coef, dtype=np.float64).T),
            np.ascontiguousarray(viscous, dtype=np.float64), np.ascontiguousarray(elastic, dtype=np.float64))
    slices = min(worker_threads(), om.size // THREAD_MIN_POINTS)
    if slices < 2:
        _eval_slice(om, out, *args)
        return out
    compiled(_panels_ln), compiled(_ends_eval)   # made here, so that no thread compiles
    cuts = np.linspace(0, om.size, slices + 1).astype(int)
    pool = _pool(slices)
    for done in [pool.submit(_eval_slice, om[a:b], out[a:b], *args) for a, b in zip(cuts[:-1], cuts[1:])]:
        done.result()
    return out


#: Arrays of at least twice this many points are cut into slices on threads (handing a slice to a
#: pool's thread costs tens of microseconds: below this one pass is about as fast).
THREAD_MIN_POINTS = 50_000

_POOL: dict = {}


def _pool(n: int):
    """A pool of ``n`` threads kept for the process (starting threads on each call cost milliseconds
    on a loaded machine); a forked child makes its own, its parent's threads do not exist in it."""
    from concurrent.futures import ThreadPoolExecutor
    key = (os.getpid(), n)
    if key not in _POOL:
        _POOL.clear()
        _POOL[key] = ThreadPoolExecutor(max_workers=n, thread_name_prefix="restitution-panels")
    return _POOL[key]


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

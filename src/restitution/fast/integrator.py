"""The compiled per-point "exact" integrator: ``collide_fast`` integrates

    x'' + Omega x^alpha + x^gamma x' = 0,   x(0) = 0, x'(0) = 1,

to the end of contact with the adaptive Dormand-Prince 8(5,3) method (scipy's DOP853 tableau, taken
from scipy so the two cannot drift apart). ``solve_ivp`` spends most of its time in Python overhead
per step and a collision needs a few hundred steps; compiled with numba a step costs well under a
microsecond, so a collision takes tens of microseconds instead of tens of milliseconds.

The formulation is the smooth one of :mod:`restitution.core.collision`: the start and the end near
x = 0 in u = x^(1/p) (alpha = q_alpha/p, gamma = q_gamma/p), where the equations are polynomial;
the middle in tau with the force f = Omega x^(alpha-gamma) + x' carried as a state of its own (for
small Omega, f is a tiny difference of nearly equal numbers and must not be formed by subtraction):

1. rise      in u from u = 0, state (v, tau, g), until v has fallen to 1/2;
2. compress  in tau, state (x, v, f), until v = 0 (maximum compression, located exactly), with
             v' = -x^gamma (Omega x^(alpha-gamma) + v) formed from v (no cancellation while v > 0),
             so that an error of v decays instead of moving the turn;
3. release   in tau from (x_b, 0, Omega x_b^(alpha-gamma)) until f = 0 (force end) or x < x_b / 4;
4. land      in u down to u = 0 (separation) unless g = 0 (force end) first.

Under the overlap rule (``end="overlap"``: contact lasts until x = 0, the force pulling on the way)
f = 0 is no end. Once the force pulls (from x_b / 4, or from the located zero of g in leg 4) the
return may creep, and eps may lie a factor Omega^2 below the creep speed (alpha = 3/2, gamma = 1/2:
eps = C Omega^3), so the last leg is that of core.collision._land_pulling:

5. pull      in u down to u = 0, state (g, tau) with g = f and x' = g - Omega u^k (two negative
             terms: no cancellation), g under a purely relative tolerance.

Sticking is reported (END_STUCK) only where it is proved, as in core.collision: alpha = 2 gamma + 1
with Omega <= 1/(4 (gamma + 1)) at once, and for alpha > 2 gamma + 1 once the return is in the trap
x' >= -2 Omega x^(alpha-gamma) where x^(2 gamma + 1 - alpha) >= 4 Omega (alpha - gamma).

g = Omega u^a + u^m v with a = max(k, 0), m = max(-k, 0), k = q_alpha - q_gamma: g = f when
alpha >= gamma and u^m f otherwise, so that g is bounded at u = 0 and has the sign of f. Events
(v = 0, f = 0, g = 0) are located by re-stepping from the start of the crossing step with a step
size from the Illinois variant of regula falsi, so an event is as accurate as a step.

The kernels are :mod:`restitution.fast.collision_kernels`; this module runs them: as plain Python
for a small request in a process that has not started numba (:func:`restitution.fast.jit.call_kernel`),
on several threads for a large one.
"""

from __future__ import annotations

import os

import numpy as np

from . import collision_kernels as kernels
from .collision_kernels import END_FAILED, END_FORCE, END_SEPARATION, END_STUCK, law_parameters
from .jit import HAVE_NUMBA, call_kernel

__all__ = ["HAVE_NUMBA", "collide_fast", "law_parameters", "OVERLAP_RTOL_MAX", "COLUMNS",
           "END_FORCE", "END_SEPARATION", "END_FAILED", "END_STUCK"]

#: Loosest rtol the overlap rule is run at: above about 3e-8 the carried force at x_b / 4 is too
#: coarse for an eps a factor Omega^2 below the creep speed (alpha = 3/2, gamma = 1/2 near
#: Omega = 1e-3: 40-80 rtol at rtol 3e-8 to 1e-7, against at most 2.7 rtol at 1e-8 and below).
OVERLAP_RTOL_MAX = 1e-9


#: Columns of the array ``collide_fast`` returns.
COLUMNS = ("eps", "tau_b", "x_b", "tau_c", "x_c", "ended_by", "steps")


def collide_fast(p: int, qa: int, qg: int, omegas, rtol: float = 1e-12, end: str = "force") -> np.ndarray:
    """Integrate one collision per Omega; returns an (n, 7) array with columns ``COLUMNS``.

    Exponents as integers: alpha = qa/p, gamma = qg/p. ``end``: the end rule, "force" or "overlap"
    (the latter run at rtol at most OVERLAP_RTOL_MAX; pass a Problem's ``effective_end``).
    ``ended_by`` is END_FORCE, END_SEPARATION, END_STUCK (overlap rule, proved) or
    END_FAILED (then the other columns are NaN where undetermined). No input validation: the
    callers (ladder, master) validate.
    """
    om = np.ascontiguousarray(np.atleast_1d(np.asarray(omegas, dtype=np.float64)))
    res = np.empty((om.size, 7))
    overlap = end == "overlap"
    if overlap:
        rtol = min(rtol, OVERLAP_RTOL_MAX)
    threads = _threads(om.size)
    if threads == 1:
        call_kernel(_plain_work(om, rtol, overlap, qa, qg), INTERPRETED_MAX_POINTS, kernels.collide_many, law_parameters(int(p), int(qa), int(qg), 0.0),
                    om, float(rtol), res, bool(overlap))
        return res
    # every thread its own parameter array (the kernel writes Omega into it) and every threads-th
    # point, so that the slow small Omegas of a sorted grid are shared out evenly
    from concurrent.futures import ThreadPoolExecutor

    def part(k):
        sub = np.ascontiguousarray(om[k::threads])
        out = np.empty((sub.size, 7))
        kernels.collide_many(law_parameters(int(p), int(qa), int(qg), 0.0), sub, float(rtol), out, bool(overlap))
        res[k::threads] = out

    with ThreadPoolExecutor(threads) as pool:
        list(pool.map(part, range(threads)))
    return res


#: Up to this many points a process that has not started numba integrates in plain Python (about
#: 10 ms a point against most of a second for numba's start; for a while: jit.PLAIN_BUDGET).
INTERPRETED_MAX_POINTS = 8
#: A creeping return's estimated plain-Python seconds per unit of that limit: 8 units, 0.32 s, stay
#: below numba's start with its compiled run.
PLAIN_POINT_SECONDS = 0.04


def _plain_work(om: np.ndarray, rtol: float, overlap: bool, qa: int, qg: int) -> float:
    """The points' plain-Python cost, counted against INTERPRETED_MAX_POINTS. A creeping
    return (the overlap rule, and the force rule where alpha <= gamma) costs more the smaller Omega
    and rtol; in plain Python, for (5/2, 1), (3/2, 1) and (3/2, 1/2) under the overlap rule, one point
    took 24-39 ms at Omega = 1e-2, 0.10-0.20 s at 1e-3 and 0.39-0.75 s at 1e-4 with rtol 1e-10, and
    80-120 ms, 0.35-0.88 s and 1.6-4.3 s with rtol 1e-14, against 0.5 s for numba's start and the
    compiled run. The estimate below lies above each of those; such a point counts as one per
    PLAIN_POINT_SECONDS of it, an ordinary point (about 10 ms) as one."""
    if not (overlap or qa <= qg):
        return om.size
    seconds = 0.008 * np.maximum(1.0, 0.1 / om) ** 0.75 * max(1.0, 1e-10 / rtol) ** 0.15
    return float(np.sum(np.maximum(1.0, seconds / PLAIN_POINT_SECONDS)))


#: Points from which collide_fast shares the work between threads (the kernel releases the GIL);
#: below, starting threads costs more than it saves.
THREAD_MIN_POINTS = 64


def _threads(n: int) -> int:
    if not HAVE_NUMBA or n < THREAD_MIN_POINTS:
        return 1
    return max(1, min(len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1,
                      n // (THREAD_MIN_POINTS // 2), 8))

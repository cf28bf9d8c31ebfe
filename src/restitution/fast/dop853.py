"""scipy's Dormand-Prince 8(5,3) tableau (DOP853) for the compiled integrator
(:mod:`restitution.fast.collision_kernels`), taken from scipy so the two cannot drift apart; and
:func:`solve`, the same method in plain Python with terminal events, for small systems whose
callers should not pay scipy.integrate's import."""

from __future__ import annotations

import importlib.util
import math
from pathlib import Path

import numpy as np

__all__ = ["N_STAGES", "A", "B", "C", "E3", "E5", "solve"]


def _scipy_dop853():
    """scipy's DOP853 coefficients module, executed from its own file: importing it by name imports
    the whole of scipy.integrate first (about 0.3 s, most of a one-point ``restitution eps`` call)
    for a few hundred numbers that need only numpy."""
    spec = importlib.util.find_spec("scipy")   # locates the package without importing it
    path = Path(spec.origin).parent / "integrate" / "_ivp" / "dop853_coefficients.py"
    if not path.is_file():   # another scipy layout: the ordinary import
        from scipy.integrate._ivp import dop853_coefficients
        return dop853_coefficients
    own = importlib.util.spec_from_file_location("restitution_scipy_dop853_coefficients", path)
    module = importlib.util.module_from_spec(own)
    own.loader.exec_module(module)
    return module


_dop = _scipy_dop853()
#: Stages of the method (12); the arrays below as the kernels read them (C-contiguous float64).
N_STAGES = _dop.N_STAGES
A = np.ascontiguousarray(_dop.A[:N_STAGES, :N_STAGES], dtype=np.float64)
B = np.ascontiguousarray(_dop.B, dtype=np.float64)
C = np.ascontiguousarray(_dop.C[:N_STAGES], dtype=np.float64)
E3 = np.ascontiguousarray(_dop.E3, dtype=np.float64)
E5 = np.ascontiguousarray(_dop.E5, dtype=np.float64)


# The tableau as plain floats, for :func:`solve` (scalar Python arithmetic on a few components is
# several times faster than numpy's on arrays that small)
_A_ROWS = [[(j, float(a)) for j, a in enumerate(A[s, :s]) if a != 0.0] for s in range(N_STAGES)]
_B_TERMS = [(j, float(b)) for j, b in enumerate(B) if b != 0.0]
_C_LIST = [float(c) for c in C]
#: (stage, E3, E5) of the stages either error estimate reads
_E_TERMS = [(j, float(e3), float(e5)) for j, (e3, e5) in enumerate(zip(E3, E5)) if e3 != 0.0 or e5 != 0.0]


def _step(fun, t, y, f0, h):
    """One DOP853 step of size h from (t, y) with f0 = fun(t, y): (y at t + h, fun there, the stages
    with it last, for the error estimate)."""
    n = len(y)
    K = [f0]
    for s in range(1, N_STAGES):
        ys = list(y)
        for j, a in _A_ROWS[s]:
            kj = K[j]
            for i in range(n):
                ys[i] += h * a * kj[i]
        K.append(fun(t + _C_LIST[s] * h, ys))
    ynew = list(y)
    for j, b in _B_TERMS:
        kj = K[j]
        for i in range(n):
            ynew[i] += h * b * kj[i]
    fnew = fun(t + h, ynew)
    K.append(fnew)
    return ynew, fnew, K


def _error(K, h, y, ynew, rtol, atol):
    """scipy's DOP853 error norm of a step (its _estimate_error_norm, for a list of components)."""
    n = len(y)
    e5 = e3 = 0.0
    for i in range(n):
        s3 = s5 = 0.0
        for j, c3, c5 in _E_TERMS:
            k = K[j][i]
            s3 += k * c3
            s5 += k * c5
        scale = atol[i] + max(abs(y[i]), abs(ynew[i])) * rtol
        e5 += (s5 / scale) ** 2
        e3 += (s3 / scale) ** 2
    denom = (e5 + 0.01 * e3) * n
    # both underflow to zero on a component decaying towards 0 (numpy's 0/0 is scipy's nan -> 0)
    return 0.0 if denom == 0.0 else abs(h) * e5 / math.sqrt(denom)


def solve(fun, y0, t_end: float, events, *, rtol: float, atol, first_step: float, max_step: float,
          max_steps: int = 10_000_000):
    """Integrate y' = fun(t, y) from t = 0 with DOP853 until the first of ``events`` falls through
    zero (each a callable e(t, y), positive before; a step that ends at or below zero is cut back to
    where it crosses, by regula falsi on the step's size with each trial a full step from its start).

    scipy's ``solve_ivp(method="DOP853", events=..., max_step=...)`` for a few components, in plain
    Python: importing scipy.integrate costs most of a second, which a caller that integrates a few
    small systems (``restitution deck`` sizing a fix beside a contact) would pay many times over.
    Steps are chosen as scipy chooses them (its error norm, safety 0.9, factors 0.2 to 10).

    Parameters
    ----------
    fun : callable
        fun(t, y) -> list of float.
    y0 : sequence of float
    t_end : float
        The last time integrated to, where no event has happened (> 0).
    events : list of callable
        Terminal events, each met falling through zero.
    rtol : float
    atol : sequence of float
        Per component.
    first_step, max_step : float

    Returns
    -------
    tuple or None
        (index of the event, t, y there), or None where none happened by t_end.

    Examples
    --------
    >>> import math
    >>> k, t, y = solve(lambda t, y: [y[1], -y[0]], [0.0, 1.0], 10.0, [lambda t, y: y[0]],
    ...                 rtol=1e-10, atol=[1e-13, 1e-13], first_step=1e-3, max_step=0.1)
    >>> k, abs(t - math.pi) < 1e-9, abs(y[1] + 1.0) < 1e-9
    (0, True, True)
    """
    t, y = 0.0, [float(v) for v in y0]
    f = fun(t, y)
    h = min(first_step, max_step)
    before = [e(t, y) for e in events]
    for _ in range(max_steps):
        if t >= t_end:
            return None
        h = min(h, max_step, t_end - t)
        while True:
            ynew, fnew, K = _step(fun, t, y, f, h)
            err = _error(K, h, y, ynew, rtol, atol)
            if err <= 1.0:
                break
            h *= max(0.2, 0.9 * err ** (-1.0 / 8.0))
        after = [e(t + h, ynew) for e in events]
        crossed = [k for k, (a, b) in enumerate(zip(before, after)) if a > 0.0 >= b]
        if crossed:
            found, err = _locate(fun, events, crossed, t, y, f, h, before, after, rtol, atol)
            if err <= 1.0:
                return found
            # The step to the event fails the error test though the step over it passed: the
            # right-hand side may change its form at the event (a contact force that ends there,
            # whose x^gamma has an unbounded derivative as x -> 0), which a step across it hides.
            # Step nearer first, each step tested, until the step to the event passes too.
            h = (found[1] - t) * max(0.2, 0.9 * err ** (-1.0 / 8.0))
            continue
        t, y, f, before = t + h, ynew, fnew, after
        h *= 10.0 if err == 0.0 else min(10.0, max(0.2, 0.9 * err ** (-1.0 / 8.0)))
    raise ArithmeticError(f"no event within {max_steps} steps")


def _locate(fun, events, crossed, t, y, f, h, before, after, rtol, atol):
    """((event, t, y), the error norm of the step there) of the first event among ``crossed`` that a
    step of size h from (t, y) meets: each event's crossing found on the step's size (regula falsi,
    Illinois), the earliest kept."""
    best = None
    for k in crossed:
        lo, hi, e_lo, e_hi, side = 0.0, h, before[k], after[k], 0
        y_hi = K_hi = None
        for _ in range(200):
            mid = (lo * e_hi - hi * e_lo) / (e_hi - e_lo)
            if not lo < mid < hi:
                mid = 0.5 * (lo + hi)
            y_mid, _, K_mid = _step(fun, t, y, f, mid)
            e_mid = events[k](t + mid, y_mid)
            if e_mid > 0.0:
                lo, e_lo = mid, e_mid
                if side == -1:
                    e_hi *= 0.5
                side = -1
            else:
                hi, e_hi, y_hi, K_hi = mid, e_mid, y_mid, K_mid
                if side == 1:
                    e_lo *= 0.5
                side = 1
            if hi - lo <= 4.0 * np.finfo(float).eps * (t + hi):
                break
        if y_hi is None:
            y_hi, _, K_hi = _step(fun, t, y, f, hi)
        if best is None or hi < best[0][1] - t:
            best = ((k, t + hi, y_hi), _error(K_hi, hi, y, y_hi, rtol, atol))
    return best

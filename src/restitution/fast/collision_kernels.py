"""The compiled kernels of :func:`restitution.fast.integrator.collide_fast` (whose module
describes the legs they integrate): the right-hand sides in u and tau, one DOP853 step and its
error norm, one leg with its events located, the overlap rule's pulling return, one collision.

They share one file on purpose: a kernel compiled with ``cache=True`` is recompiled when its own
file changes, not when a file it calls into does (:mod:`restitution.fast.jit`), so a kernel
split from the kernels that call it could leave them running its old code.
"""

from __future__ import annotations

import math

import numpy as np

from . import dop853
from .jit import njit

__all__ = ["collide_many", "law_parameters", "END_FORCE", "END_SEPARATION", "END_FAILED", "END_STUCK"]

_A, _B, _C, _E3, _E5 = dop853.A, dop853.B, dop853.C, dop853.E3, dop853.E5

_SAFETY = 0.9
_MIN_FACTOR = 0.2
_MAX_FACTOR = 10.0
_ERR_EXP = -1.0 / 8.0

#: Leg 1 hands over to tau when v has fallen to this (dv/du ~ 1/v stays tame above it).
V_HANDOFF = 0.5
#: u legs take steps of at most their span / U_STEPS_MIN, as the scipy reference does and for the same
#: reason (core.collision._integrate): for p >= 3 the flat start of u^(p-1) lets steps grow past the
#: curvature further out, and the global error exceeded the stated bound (1.2e-10 for 1e-11 at
#: alpha = 2, gamma = 3/4, Omega = 6e5).
U_STEPS_MIN = 16
#: Leg 3 hands over to u when x < SWITCH_FRACTION x_b.
SWITCH_FRACTION = 0.25
#: atol of a component = ATOL_MARGIN * rtol * (its natural size in that leg).
ATOL_MARGIN = 1e-3
#: A collision that needs more steps than this is abandoned (returns END_FAILED); only a creeping
#: return (alpha <= gamma at tiny Omega, where an explicit method is stiffness-limited) gets near.
MAX_STEPS = 2_000_000

END_FORCE = 0
END_SEPARATION = 1
END_FAILED = 2
#: Overlap rule only: proved never to separate (x and x' creep to 0 together).
END_STUCK = 3
#: An absolute tolerance that leaves the relative one in charge (the pulling leg's g).
TINY = 1e-300
#: The pulling leg's time (from 0 at its start): absolute tolerance TIME_MARGIN rtol x / |x'|.
TIME_MARGIN = 1e-6

# numba compiles a kernel called with a literal integer once per literal value. _leg's integer
# arguments are passed as _I(...), so _leg and _locate are compiled once instead of five times each;
# _leg then calls _rk_step with a literal mode, keeping the three mode-specific steps (the inner loop:
# an int64 mode there costs the overlap rule 30 %). Measured: a cold compile 8.4 s -> 5.9 s, the
# same speed, bit-identical results.
_I = np.int64

# parameter vector layout; _P_COMPRESS is 1 while leg 2 runs (see _rhs)
_P_OMEGA, _P_P, _P_QA, _P_QG, _P_ALPHA, _P_GAMMA, _P_A, _P_M, _P_N, _P_COMPRESS = range(10)


def law_parameters(p: int, qa: int, qg: int, omega: float) -> np.ndarray:
    """The float parameter vector the kernels read (exponents as integers of u = x^(1/p))."""
    k = qa - qg
    return np.array([omega, p, qa, qg, qa / p, qg / p, max(k, 0), max(-k, 0), min(qa, qg), 0.0],
                    dtype=np.float64)


# ---------------------------------------------------------------------------- right-hand sides
@njit(cache=True)
def _ipow(u, n):
    """u**n for a small non-negative integer n stored as a float (exact repeated squaring)."""
    k = int(n)
    r = 1.0
    b = u
    while k > 0:
        if k & 1:
            r *= b
        b *= b
        k >>= 1
    return r


@njit(cache=True)
def _rhs(mode, t, y, out, P):
    """mode 0: independent u, state (v, tau, g). mode 1: independent tau, state (x, v, f).
    mode 2: independent u, state (g, tau, 0) with x' = g - Omega u^k (the pulling return, k > 0)."""
    om = P[_P_OMEGA]
    if mode == 2:
        u = t
        g = y[0]
        k = P[_P_QA] - P[_P_QG]
        w = P[_P_P] * _ipow(u, P[_P_P] - 1.0)
        v = g - om * _ipow(u, k)
        out[0] = -w * _ipow(u, P[_P_QG]) * g / v + k * om * _ipow(u, k - 1.0)
        out[1] = w / v
        out[2] = 0.0
        return
    if mode == 0:
        u = t
        v = y[0]
        g = y[2]
        w = P[_P_P] * _ipow(u, P[_P_P] - 1.0)
        wv = w / v
        out[0] = -wv * _ipow(u, P[_P_N]) * g
        out[1] = wv
        dg = -wv * _ipow(u, P[_P_QG]) * g
        a = P[_P_A]
        m = P[_P_M]
        if a > 0.0:
            dg += a * om * _ipow(u, a - 1.0)
        if m > 0.0:
            dg += m * _ipow(u, m - 1.0) * v
        out[2] = dg
    else:
        x = y[0]
        v = y[1]
        f = y[2]
        if x <= 0.0:
            out[0] = np.nan
            out[1] = np.nan
            out[2] = np.nan
            return
        gam = P[_P_GAMMA]
        d = P[_P_ALPHA] - gam
        lx = math.log(x)
        xg = math.exp(gam * lx) if gam != 0.0 else 1.0
        out[0] = v
        if P[_P_COMPRESS] != 0.0:
            # Compressing, v > 0: f = Omega x^d + v is a sum of positive terms, formed without
            # loss, and v' = -x^gamma (Omega x^d + v) pulls an error of v back, as the scipy
            # reference's (x, v) form does. With the carried f, v' ignored v, so v kept every error
            # it picked up while of order 1; at small Omega, where v ends near 0 at a slope of
            # Omega x^alpha, that moved the turn by error/slope (tau_b off by 2.6e-9 at Omega = 1e-9,
            # 6e-6 at 1e-12, at rtol 1e-12) and near Omega = 1e-16 v never reached 0 at all.
            out[1] = -xg * (v + (om * math.exp(d * lx) if d != 0.0 else om))
        else:
            out[1] = -xg * f
        drift = 0.0
        if d != 0.0:
            drift = om * d * math.exp((d - 1.0) * lx) * v
        out[2] = -xg * f + drift


# ---------------------------------------------------------------------------- one RK step
@njit(cache=True)
def _rk_step(mode, t, y, f0, h, P, K, ynew, fnew, A, B, C, tmp):
    """One DOP853 step from (t, y) with derivative f0; fills ynew, fnew and the stages K."""
    for i in range(3):
        K[0, i] = f0[i]
    for s in range(1, 12):
        for i in range(3):
            acc = 0.0
            for j in range(s):
                acc += A[s, j] * K[j, i]
            tmp[i] = y[i] + h * acc
        _rhs(mode, t + C[s] * h, tmp, K[s], P)
    for i in range(3):
        acc = 0.0
        for j in range(12):
            acc += B[j] * K[j, i]
        ynew[i] = y[i] + h * acc
    _rhs(mode, t + h, ynew, fnew, P)
    for i in range(3):
        K[12, i] = fnew[i]


@njit(cache=True)
def _err_norm(K, h, y, ynew, rtol, atol, E3, E5):
    """scipy's DOP853 error norm (5th-order estimate tempered by the 3rd-order one)."""
    e5 = 0.0
    e3 = 0.0
    for i in range(3):
        sc = atol[i] + rtol * max(abs(y[i]), abs(ynew[i]))
        a5 = 0.0
        a3 = 0.0
        for j in range(13):
            a5 += E5[j] * K[j, i]
            a3 += E3[j] * K[j, i]
        a5 /= sc
        a3 /= sc
        e5 += a5 * a5
        e3 += a3 * a3
    if e5 == 0.0 and e3 == 0.0:
        return 0.0
    den = e5 + 0.01 * e3
    return abs(h) * e5 / math.sqrt(den * 3.0)


# ---------------------------------------------------------------------------- one leg
@njit(cache=True)
def _initial_step(mode, t0, y0, f0, direction, rtol, atol, P):
    """scipy's select_initial_step (order 8)."""
    d0 = 0.0
    d1 = 0.0
    for i in range(3):
        sc = atol[i] + abs(y0[i]) * rtol
        d0 += (y0[i] / sc) ** 2
        d1 += (f0[i] / sc) ** 2
    d0 = math.sqrt(d0 / 3.0)
    d1 = math.sqrt(d1 / 3.0)
    if d0 < 1e-5 or d1 < 1e-5:
        h0 = 1e-6
    else:
        h0 = 0.01 * d0 / d1
    y1 = np.empty(3)
    for i in range(3):
        y1[i] = y0[i] + h0 * direction * f0[i]
    f1 = np.empty(3)
    _rhs(mode, t0 + h0 * direction, y1, f1, P)
    d2 = 0.0
    for i in range(3):
        sc = atol[i] + abs(y0[i]) * rtol
        d2 += ((f1[i] - f0[i]) / sc) ** 2
    d2 = math.sqrt(d2 / 3.0) / h0
    if not (d2 < math.inf):  # NaN or inf: the trial step left the region where the rhs is sane
        return h0 * 1e-3
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1.0 / 8.0)
    return min(100.0 * h0, h1)


@njit(cache=True)
def _locate(mode, t0, y0, f0, h_lo, h_hi, e_lo, e_hi, comp, P, K, ynew, fnew, A, B, C, tmp):
    """Step size s in (h_lo, h_hi) where component ``comp`` of y(t0 + s) vanishes (Illinois).

    e_lo, e_hi: the component at h_lo and h_hi (opposite signs). On return ynew holds y(t0 + s).
    """
    side = 0
    s = h_hi
    for _ in range(200):
        # e_hi = e_lo once Illinois' halving has taken a tiny e (Omega ~ 1e-200) to zero: bisect, as
        # plain Python does with the NaN it gets (compiled code raises ZeroDivisionError instead)
        den = e_hi - e_lo
        s = (h_lo * e_hi - h_hi * e_lo) / den if den != 0.0 else math.nan
        if not (min(h_lo, h_hi) < s < max(h_lo, h_hi)):
            s = 0.5 * (h_lo + h_hi)
        _rk_step(mode, t0, y0, f0, s, P, K, ynew, fnew, A, B, C, tmp)
        e = ynew[comp]
        if e == 0.0:
            return s
        if (e < 0.0) == (e_hi < 0.0):
            h_hi = s
            e_hi = e
            if side == 1:
                e_lo *= 0.5
            side = 1
        else:
            h_lo = s
            e_lo = e
            if side == -1:
                e_hi *= 0.5
            side = -1
        if abs(h_hi - h_lo) <= 4e-16 * max(abs(t0 + s), abs(s)):
            break
    # make ynew consistent with the returned s
    _rk_step(mode, t0, y0, f0, s, P, K, ynew, fnew, A, B, C, tmp)
    return s


@njit(cache=True)
def _leg(mode, t0, y0, t_end, h_init, rtol, atol, P, kind, event_comp, stop_comp, stop_value,
         out_y, steps_left, h_max):
    """Integrate one leg; returns (t, status, steps) and leaves the final state in out_y.

    kind 0 (rise): stop after the first accepted step with y[0] <= stop_value; steps that would take
        y[0] below stop_value / 2 are rejected (v must stay away from 0 in u).
    kind 1 (tau legs): stop at the zero of y[event_comp] (located); also, if stop_comp >= 0, after
        the first accepted step with y[stop_comp] < stop_value.
    kind 2 (land): integrate to t_end (u = 0) unless y[event_comp] vanishes first (located).
    kind 4 (release under the overlap rule): as kind 1, but steps that would take y[stop_comp] below
        stop_value / 2 are rejected: with no force event to stop it, one long step would otherwise
        carry x to near 0, where the tau form is singular (x^(alpha-gamma-1)).
    kind 3 (pull, mode 2): integrate to t_end (u = 0); x' stays negative; status 3 as soon as an
        accepted step ends in the trap of _trapped.
    event_comp < 0: no event. status: 0 reached t_end / stop, 1 event, 2 failure, 3 stuck.
    """
    A = _A
    B = _B
    C = _C
    E3 = _E3
    E5 = _E5
    K = np.empty((13, 3))
    tmp = np.empty(3)
    y = y0.copy()
    f = np.empty(3)
    ynew = np.empty(3)
    fnew = np.empty(3)
    _rhs(mode, t0, y, f, P)
    t = t0
    direction = 1.0 if t_end > t0 else -1.0
    h = abs(h_init)
    if h == 0.0:
        h = _initial_step(mode, t0, y, f, direction, rtol, atol, P)
    steps = 0
    rejected = False
    err_prev = 0.0
    while True:
        if steps >= steps_left:
            for i in range(3):
                out_y[i] = y[i]
            return t, 2, steps
        if h > h_max:
            h = h_max
        room = abs(t_end - t)
        last = False
        if h >= room:
            h = room
            last = True
        if h <= 1e-15 * max(abs(t), 1e-300):
            for i in range(3):
                out_y[i] = y[i]
            return t, 2, steps
        hs = h * direction
        if mode == 0:
            _rk_step(0, t, y, f, hs, P, K, ynew, fnew, A, B, C, tmp)
        elif mode == 1:
            _rk_step(1, t, y, f, hs, P, K, ynew, fnew, A, B, C, tmp)
        else:
            _rk_step(2, t, y, f, hs, P, K, ynew, fnew, A, B, C, tmp)
        steps += 1
        err = _err_norm(K, hs, y, ynew, rtol, atol, E3, E5)
        ok = err <= 1.0  # False for NaN
        if ok and kind == 0 and ynew[0] < 0.5 * stop_value:
            ok = False
            err = 2.0 ** 8  # shrink by ~ SAFETY / 2
        if ok and kind == 2 and ynew[0] * y[0] <= 0.0:
            ok = False  # v changed sign in u: cannot happen in the physics, step too long
            err = 2.0 ** 8
        if ok and kind == 4 and not ynew[stop_comp] >= 0.5 * stop_value:
            ok = False
            err = 2.0 ** 8
        if ok and kind == 3 and not ynew[0] < P[_P_OMEGA] * _ipow(t + hs, P[_P_QA] - P[_P_QG]):
            ok = False  # x' = g - Omega u^k changed sign: cannot happen in the physics, step too long
            err = 2.0 ** 8
        if not ok:
            if err != err:
                fac = 0.25
            else:
                fac = max(_MIN_FACTOR, _SAFETY * err ** _ERR_EXP)
            h *= fac
            rejected = True
            continue
        # accepted
        if event_comp >= 0 and (ynew[event_comp] == 0.0 or (ynew[event_comp] < 0.0) != (y[event_comp] < 0.0)):
            e_hi = ynew[event_comp]
            if e_hi == 0.0:
                s = hs
            else:
                s = _locate(mode, t, y, f, 0.0, hs, y[event_comp], e_hi, event_comp, P, K, ynew,
                            fnew, A, B, C, tmp)
            for i in range(3):
                out_y[i] = ynew[i]
            return t + s, 1, steps
        t = t + hs
        for i in range(3):
            y[i] = ynew[i]
            f[i] = fnew[i]
        if kind == 0 and y[0] <= stop_value:
            break
        if (kind == 1 or kind == 4) and stop_comp >= 0 and y[stop_comp] < stop_value:
            break
        if kind == 3 and _trapped(t, y[0], P) >= 0.0:
            for i in range(3):
                out_y[i] = y[i]
            return t, 3, steps
        if last:
            break
        # Grow only as far as the previous accepted step's estimate allows too. DOP853's estimate
        # (h e5^2 / sqrt(e5^2 + 0.01 e3^2)) vanishes with e5 where the 5th-order error term changes
        # sign, while the 8th-order solution's error does not: the step then grew 2.9x on an
        # estimate of 9e-5 and the next step, 3.6x the usual, was accepted at 0.7 with a true error
        # of 925 rtol (the pulling return, alpha = 1, gamma = 1/2, Omega = 0.0043836 at rtol 1e-12:
        # eps off by 2.2e-10 against a bound of 2.3e-11). A single blind estimate no longer grows h.
        seen = max(err, err_prev)
        err_prev = err
        if seen == 0.0:
            fac = _MAX_FACTOR
        else:
            fac = min(_MAX_FACTOR, _SAFETY * seen ** _ERR_EXP)
        if rejected:
            fac = min(1.0, fac)
        h *= fac
        rejected = False
    for i in range(3):
        out_y[i] = y[i]
    return t, 0, steps


@njit(cache=True)
def _trapped(u, g, P):
    """>= 0 exactly where a pulling return provably sticks (core.collision._Trap): s = -x' <=
    2 Omega x^d (g >= -Omega u^k) at an x with x^(2 gamma + 1 - alpha) >= 4 Omega d. Only
    alpha > 2 gamma + 1 has such points."""
    excess = P[_P_QA] - 2.0 * P[_P_QG] - P[_P_P]
    if excess <= 0.0:
        return -1.0
    om = P[_P_OMEGA]
    below = g + om * _ipow(u, P[_P_QA] - P[_P_QG])
    if u <= 0.0:
        return below
    return min(below, 1.0 / _ipow(u, excess) - 4.0 * om * (P[_P_ALPHA] - P[_P_GAMMA]))


@njit(cache=True)
def _pull(P, u0, g0, tau0, rtol, out, steps_total):
    """Leg 5: the pulling return from u0 (g0 = f, about 0 or below) down to u = 0; fills out like _collide_one."""
    om = P[_P_OMEGA]
    k = P[_P_QA] - P[_P_QG]
    out[6] = steps_total
    if _trapped(u0, g0, P) >= 0.0:
        out[5] = END_STUCK
        return
    y = np.empty(3)
    yo = np.empty(3)
    atol = np.empty(3)
    y[0] = g0
    y[1] = 0.0
    y[2] = 0.0
    v0 = g0 - om * _ipow(u0, k)
    atol[0] = TINY
    atol[1] = TIME_MARGIN * rtol * _ipow(u0, P[_P_P]) / abs(v0)
    atol[2] = 1.0
    ue, st, n = _leg(_I(2), u0, y, 0.0, 1e-3 * u0, rtol, atol, P, _I(3), _I(-1), _I(-1), 0.0, yo,
                     MAX_STEPS - steps_total, u0 / U_STEPS_MIN)
    out[6] = steps_total + n
    if st == 3:
        out[5] = END_STUCK
        return
    if st != 0 or not yo[0] < 0.0:   # at u = 0, x' = g
        return
    out[0] = -yo[0]
    out[3] = tau0 + yo[1]
    out[4] = 0.0
    out[5] = END_SEPARATION


# ---------------------------------------------------------------------------- one collision
@njit(cache=True)
def _collide_one(P, rtol, out, overlap):
    """out = (eps, tau_b, x_b, tau_c, x_c, end, steps)."""
    om = P[_P_OMEGA]
    p = P[_P_P]
    alpha = P[_P_ALPHA]
    gamma = P[_P_GAMMA]
    d = alpha - gamma
    k = P[_P_QA] - P[_P_QG]
    m = P[_P_M]
    for i in range(7):
        out[i] = np.nan
    out[5] = END_FAILED
    steps_total = 0
    atol = np.empty(3)
    y = np.empty(3)
    yo = np.empty(3)
    # the overlap rule's self-similar case alpha = 2 gamma + 1 sticks below 1/(4 (gamma+1)) (proved
    # in core.collision._check_separates)
    if overlap and P[_P_QA] == 2.0 * P[_P_QG] + p and om <= 1.0 / (4.0 * (gamma + 1.0)):
        out[5] = END_STUCK
        out[6] = 0
        return

    # ---- leg 1: rise in u
    x_el = ((alpha + 1.0) / (2.0 * om)) ** (1.0 / (alpha + 1.0))
    x_scale = min(1.0, x_el)
    u_scale = x_scale ** (1.0 / p)
    y[0] = 1.0
    y[1] = 0.0
    if k > 0:
        y[2] = 1.0
    elif k < 0:
        y[2] = om
    else:
        y[2] = om + 1.0
    atol[0] = ATOL_MARGIN * rtol
    atol[1] = ATOL_MARGIN * rtol * x_scale
    atol[2] = ATOL_MARGIN * rtol * abs(y[2])
    u_end = 4.0 * max(1.0, x_el) ** (1.0 / p) + 4.0
    # first step: a small fraction of the u-scale of the whole rise (step control takes over)
    u, st, n = _leg(_I(0), 0.0, y, u_end, 1e-3 * u_scale, rtol, atol, P, _I(0), _I(-1), _I(-1), V_HANDOFF, yo,
                    MAX_STEPS - steps_total, u_scale / U_STEPS_MIN)
    steps_total += n
    if st == 2:
        out[6] = steps_total
        return
    x1 = _ipow(u, p)
    v1 = yo[0]
    tau1 = yo[1]
    if m > 0:
        f1 = yo[2] / _ipow(u, m)
    else:
        f1 = yo[2]

    # ---- leg 2: compress in tau until v = 0
    y[0] = x1
    y[1] = v1
    y[2] = f1
    vs = min(1.0, om * x1 ** d)
    atol[0] = ATOL_MARGIN * rtol * x1
    atol[1] = ATOL_MARGIN * rtol * vs
    atol[2] = ATOL_MARGIN * rtol * min(abs(f1), vs)
    t_guard = tau1 + 1e7 * (1.0 + x1)
    P[_P_COMPRESS] = 1.0
    tb, st, n = _leg(_I(1), tau1, y, t_guard, 0.0, rtol, atol, P, _I(1), _I(1), _I(-1), 0.0, yo,
                     MAX_STEPS - steps_total, np.inf)
    P[_P_COMPRESS] = 0.0
    steps_total += n
    if st != 1:
        out[6] = steps_total
        return
    xb = yo[0]
    out[1] = tb
    out[2] = xb

    # ---- leg 3: release in tau until f = 0 or x < x_b / 4
    fb = om * xb ** d
    y[0] = xb
    y[1] = 0.0
    y[2] = fb
    vs = min(1.0, fb)
    # quasi-static force on the slow return: Omega^2 (alpha-gamma) x^(2 alpha - 3 gamma - 1)
    fqs = om * om * abs(d) * xb ** (2.0 * alpha - 3.0 * gamma - 1.0)
    atol[0] = ATOL_MARGIN * rtol * xb
    atol[1] = ATOL_MARGIN * rtol * vs
    atol[2] = ATOL_MARGIN * rtol * max(min(fb, fqs), 1e-300)
    ev = 2 if k > 0 and not overlap else -1
    # first step from rest: the time for x to change by rtol x_b under the force
    xg = xb ** gamma
    h0 = min(1.0 / max(xg, 1e-300), math.sqrt(xb / max(om * xb ** alpha, 1e-300))) * 1e-3
    t_guard = tb + 1e7 * (1.0 + xb / max(vs, 1e-300))
    tc, st, n = _leg(_I(1), tb, y, t_guard, h0, rtol, atol, P, _I(4 if overlap else 1), _I(ev), _I(0),
                     SWITCH_FRACTION * xb, yo, MAX_STEPS - steps_total, np.inf)
    steps_total += n
    if st == 2:
        out[6] = steps_total
        return
    if st == 1:
        eps = -yo[1]
        out[0] = eps
        out[3] = tc
        # at the event Omega x_c^(alpha-gamma) = eps exactly: accurate even when x_c is tiny
        out[4] = (eps / om) ** (1.0 / d)
        out[5] = END_FORCE
        out[6] = steps_total
        return

    # ---- leg 4: land in u down to u = 0
    x3 = yo[0]
    v3 = yo[1]
    f3 = yo[2]
    u3 = x3 ** (1.0 / p)
    if overlap and k > 0 and f3 < 0.0:
        _pull(P, u3, f3, tc, rtol, out, steps_total)
        return
    y[0] = v3
    y[1] = tc
    y[2] = f3 * _ipow(u3, m) if m > 0 else f3
    atol[0] = ATOL_MARGIN * rtol * abs(v3)
    atol[1] = ATOL_MARGIN * rtol * tc
    atol[2] = ATOL_MARGIN * rtol * max(abs(y[2]), 1e-300)
    ev = 2 if k > 0 else -1
    ue, st, n = _leg(_I(0), u3, y, 0.0, 0.0, rtol, atol, P, _I(2), _I(ev), _I(-1), 0.0, yo,
                     MAX_STEPS - steps_total, u3 / U_STEPS_MIN)
    steps_total += n
    out[6] = steps_total
    if st == 2:
        return
    if overlap and st == 1:
        # The force vanished on the way down: from here it pulls. The carried g is accurate only
        # relative to its size at x_b / 4 (its zero is where the true force is still 3e-9 of eps at
        # Omega = 1e5), v relative to itself: restart g from v (it may start just above 0).
        _pull(P, ue, om * _ipow(ue, k) + yo[0], yo[1], rtol, out, steps_total)
        return
    out[0] = -yo[0]
    out[3] = yo[1]
    if st == 1:
        out[4] = (out[0] / om) ** (1.0 / d)
        out[5] = END_FORCE
    else:
        out[4] = 0.0
        out[5] = END_SEPARATION


@njit(cache=True, nogil=True)
def collide_many(P, omegas, rtol, res, overlap):
    out = np.empty(7)
    for i in range(omegas.size):
        P[_P_OMEGA] = omegas[i]
        _collide_one(P, rtol, out, overlap)
        for j in range(7):
            res[i, j] = out[j]

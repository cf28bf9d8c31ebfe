"""Independent high-precision reference for one collision (mpmath Taylor-series integrator).

Solves the scaled problem

    x'' + Omega x^alpha + x^gamma x' = 0,   x(0) = 0, x'(0) = 1,

to a requested number of significant digits, and returns the bound (maximum compression)
point, the end of contact and the coefficient of restitution.

This module exists to check ``restitution.core.collision`` (double precision, scipy), so it
shares no code with it and uses a different method: explicit Taylor series of high order,
whose coefficients come from power-series recurrences (automatic differentiation), with
the step size and the order chosen from the series' own tail. Events are roots of the
local Taylor polynomials, refined by safeguarded Newton iteration at full precision.

Why Taylor series and not mpmath.odefun: odefun works at a fixed point, has no events,
and cannot start at tau = 0 where x^gamma ~ tau^gamma is not analytic. The non-analytic
ends are handled here by changing the independent variable to u = x^(1/p) (alpha =
q_alpha/p, gamma = q_gamma/p), in which the equations are polynomial:

    dv/du   = -p u^(p-1) (Omega u^q_alpha + u^q_gamma v) / v,
    dtau/du =  p u^(p-1) / v,                                 (v = x' = dx/dtau)

analytic at u = 0 as long as v != 0. Three phases:

  A. u increasing from 0 while v > 1/2 (compression start; v falls monotonically);
  B. tau as independent variable, state (x, v), through maximum compression (root of v)
     and on until the force vanishes (root of x'' = v', since x'' = -x^gamma f) or until
     x has come back below x_b/4 with v < 0;
  C. u decreasing towards 0 (v < 0 and monotone), ending at the first root of the force
     f = Omega u^(q_alpha - q_gamma) + v (times a power of u to keep it a polynomial), or
     at u = 0, which is a separation with finite speed -v.

For alpha = gamma the force never vanishes while x > 0 (see _Model), so no force event is
sought there.

Cost at 30 digits: 0.1-0.3 s per run (two runs per call) for Omega in [1e-3, 1e3] when
alpha > gamma. When alpha <= gamma the return to x = 0 is a creep lasting ~1/Omega while
the relaxation rate stays ~x^gamma; an explicit method must resolve the latter, so the
cost grows like 1/Omega (about 1 s per call at Omega = 1e-3, 8 s at 1e-4).

Below CREEP_MAX that creep is taken another way (:func:`highprec_eps`): where the return creeps
and alpha < 2 gamma + 1, the collision is its inner problem entered at a speed ~Omega^(-k), whose
rebound differs from the creep's C by a factor exponentially close to 1 (:func:`creep_distance_bound`),
so eps = C Omega^k with C integrated once per pair in variables where the creep is a short leg
(:func:`creep_rebound_speed`: ~30 Taylor steps at 30 digits, under a second). Measured against the
integration of the whole collision at 25 digits, Omega 1e-3 and 1e-2, four pairs: 2.8e-30 at most.

The error estimate is not a formula: every call integrates twice, at ``digits`` and at
``digits + _CHECK_EXTRA`` (tighter tolerance, higher order and more working precision),
and reports the largest relative difference of eps, tau_b, x_b, tau_c. The values
returned are those of the run at ``digits``, so the estimate describes them.

mpf values are returned at the working precision of the run; arithmetic on them rounds to
whatever mpmath precision the caller has set (15 digits by default).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from fractions import Fraction

import mpmath
from mpmath import mp

from .errors import ParameterError, integer_in
from .exponents import read_through
from .problem import Problem, as_problem

__all__ = ["HighPrecisionCollision", "reference_collision", "creep_rebound_speed", "highprec_eps", "creep_distance_bound", "CREEP_MAX"]

#: Guard digits carried beyond the requested ones, so that rounding in the
#: recurrences (which mix terms of very different size) stays below the tolerance.
_GUARD_DIGITS = 12
#: Local truncation tolerance is 10^-(digits + _TOL_EXTRA): the global error is a
#: sum over steps, so the local target must be tighter than the requested accuracy.
_TOL_EXTRA = 4
#: The comparison run uses this many more digits.
_CHECK_EXTRA = 10
#: Sub-intervals of each step in which sign changes of an event function are sought;
#: more than one so that a pair of roots inside one step is not missed.
_EVENT_SAMPLES = 4
_MAX_STEPS = 200_000
_MIN_DIGITS = 8
_MAX_DIGITS = 300


@dataclass(frozen=True)
class HighPrecisionCollision:
    """Result of :func:`reference_collision` (all times and lengths in scaled units).

    ``problem`` is what was solved (the exponents and the rule asked); ``ended_by`` is "force"
    when contact ends because the total force vanishes (x'' = 0, tau > 0) and "separation" when
    x returns to 0 first (then x_c = 0). ``error_estimate`` is the largest relative difference of eps, tau_b, x_b, tau_c
    between this run and one with ``_CHECK_EXTRA`` more digits (inf if the two runs
    disagree on ``ended_by``). ``steps`` counts Taylor steps of the run at ``digits``.

    Parameters
    ----------
    problem : Problem
        What was solved (``alpha`` and ``gamma`` read through it).
    omega, eps, tau_b, x_b, tau_c, x_c : mpmath.mpf
        Omega and the collision's quantities at working precision.
    ended_by : {"force", "separation"}
        How contact ended.
    digits : int
        The working digits.
    error_estimate : mpmath.mpf
        Relative difference from a run at more digits.
    steps : int
        Taylor steps taken.

    Examples
    --------
    >>> r = reference_collision(("3/2", 1), 0.5, digits=20)
    >>> r.alpha, r.digits, sorted(r.as_floats())[:3]
    (Fraction(3, 2), 20, ['alpha', 'digits', 'end'])
    """

    problem: Problem
    omega: mpmath.mpf
    eps: mpmath.mpf
    tau_b: mpmath.mpf
    x_b: mpmath.mpf
    tau_c: mpmath.mpf
    x_c: mpmath.mpf
    ended_by: str
    digits: int
    error_estimate: mpmath.mpf
    steps: int = 0

    alpha = read_through("problem", "alpha")
    gamma = read_through("problem", "gamma")

    def as_floats(self) -> dict:
        return {
            "alpha": float(self.alpha),
            "gamma": float(self.gamma),
            "omega": float(self.omega),
            "eps": float(self.eps),
            "tau_b": float(self.tau_b),
            "x_b": float(self.x_b),
            "tau_c": float(self.tau_c),
            "x_c": float(self.x_c),
            "end": self.problem.end,
            "ended_by": self.ended_by,
            "digits": self.digits,
            "error_estimate": float(self.error_estimate),
        }


# ----------------------------------------------------------------------------------
# small helpers on mpf coefficient lists


def _lg(x) -> float:
    """log2 |x| as a float (-inf for 0), read off the mantissa: no mp log needed."""
    _, man, exp, bc = x._mpf_
    if not man:
        return -math.inf
    if bc > 53:
        man >>= bc - 53
        exp += bc - 53
    return math.log2(man) + exp


def _horner(c, s):
    r = c[-1]
    for a in reversed(c[:-1]):
        r = r * s + a
    return r


def _derivative(c):
    return [c[k] * k for k in range(1, len(c))]


def _step_bound(components, order: int, log2_tol: float, tail: int = 2) -> float:
    """Largest |h| for which the last ``tail`` Taylor terms of every component stay
    below tol times that component's largest term on the step.

    For one component with coefficients c_k, |c_n| h^n <= tol max_k |c_k| h^k holds
    exactly when h <= max_k (tol |c_k| / |c_n|)^(1/(n-k)), so no iteration is needed.
    Looking at more than the last order guards against a coefficient that happens to be
    small; series that are sparse (at u = 0 only every d-th power appears) need a tail
    longer than the gap d, otherwise a run of zeros would pass for convergence.
    """
    best = math.inf
    for c in components:
        logs = [_lg(a) for a in c[: order + 1]]
        for n in range(order - tail + 1, order + 1):
            ln = logs[n]
            if ln == -math.inf:
                continue
            h = -math.inf
            for k in range(n):
                lk = logs[k]
                if lk != -math.inf:
                    h = max(h, (log2_tol + lk - ln) / (n - k))
            if h != -math.inf:
                best = min(best, h)
    # A component whose tail vanishes identically gives no bound; 1 is a harmless cap
    # because the scaled problem has time and length scales of order one or smaller.
    return 2.0**best if best != math.inf else 1.0


def _first_sign_change(c, h):
    """Sub-interval [a, b] of [0, h] (h may be negative) holding the first sign change
    of the polynomial c away from its sign at 0, or None."""
    f0 = c[0]
    a = mp.zero
    for i in range(1, _EVENT_SAMPLES + 1):
        b = h * i / _EVENT_SAMPLES
        fb = _horner(c, b)
        if fb == 0 or (fb < 0) != (f0 < 0):
            return a, b
        a = b
    return None


def _root(c, a, b):
    """Root of polynomial c between a and b (sign change), safeguarded Newton."""
    dc = _derivative(c)
    fa = _horner(c, a)
    width = abs(b - a)
    tiny = width * mp.eps * 8
    s = (a + b) / 2
    for _ in range(400):
        fs = _horner(c, s)
        if fs == 0:
            return s
        if (fs < 0) == (fa < 0):
            a, fa = s, fs
        else:
            b = s
        d = _horner(dc, s)
        lo, hi = (a, b) if a < b else (b, a)
        t = s - fs / d if d != 0 else (a + b) / 2
        if not (lo < t < hi):
            t = (a + b) / 2
        if abs(t - s) <= tiny or hi - lo <= tiny:
            return t
        s = t
    raise ArithmeticError("root refinement did not converge")


def _binomial_poly(u0, m: int, n: int):
    """Coefficients (up to index n) of (u0 + s)^m, m a non-negative integer."""
    c = [mp.zero] * (n + 1)
    term = mp.one
    for j in range(min(m, n) + 1):
        c[j] = term * u0 ** (m - j) if m - j else term
        term = term * (m - j) / (j + 1)
    return c


def _poly_times_series(poly, series, k: int):
    """k-th coefficient of poly * series; poly is short (few non-zero leading terms)."""
    terms = [(poly[j], series[k - j]) for j in range(min(k, len(poly) - 1) + 1) if poly[j]]
    return mp.fdot(terms) if terms else mp.zero


# ----------------------------------------------------------------------------------
# the two kinds of Taylor series


def _power_series_next(y, w, a1, k: int, inv_y0):
    """w = y^a: w_k from y_0..y_k, w_0..w_{k-1} by y w' = a y' w; a1 = a + 1."""
    ys = y[1 : k + 1]
    ws = w[k - 1 :: -1]
    jy = [y[j] * j for j in range(1, k + 1)]
    return (a1 * mp.fdot(jy, ws) - k * mp.fdot(ys, ws)) * inv_y0 / k


class _Model:
    def __init__(self, alpha: Fraction, gamma: Fraction, omega, order: int):
        self.alpha = alpha
        self.gamma = gamma
        self.omega = omega
        self.order = order
        self.p = math.lcm(alpha.denominator, gamma.denominator)
        self.qa = int(alpha * self.p)
        self.qg = int(gamma * self.p)
        self.a1 = mp.mpf(alpha.numerator) / alpha.denominator + 1
        self.g1 = mp.mpf(gamma.numerator) / gamma.denominator + 1
        # force f = Omega u^(qa - qg) + v, multiplied by u^(qg - m0) so both powers are >= 0
        m0 = min(self.qa, self.qg)
        self.ea, self.eg = self.qa - m0, self.qg - m0
        # For alpha = gamma the force is f = Omega + v and f' = v' = -x^gamma f, so
        # f = f(tau_b) exp(-int x^gamma) never vanishes while x > 0: contact ends by
        # separation. At small Omega f becomes exponentially small and rounding noise
        # in it would be mistaken for a root, hence no force event at all.
        self.force_can_vanish = alpha != gamma

    def _powers(self, X, k, exponent: Fraction, a1, W, inv_x0):
        if exponent == 0:
            return mp.one if k == 0 else mp.zero
        if exponent == 1:
            return X[k]
        return _power_series_next(X, W, a1, k, inv_x0)

    def tau_series(self, x0, v0):
        """Taylor coefficients in s = tau - tau0 of x and v, with x0 > 0."""
        n, om = self.order, self.omega
        X, V = [x0], [v0]
        A = [x0 ** self.alpha_mpf()]
        G = [x0 ** self.gamma_mpf()]
        inv_x0 = 1 / x0
        for k in range(n):
            if k:
                A.append(self._powers(X, k, self.alpha, self.a1, A, inv_x0))
                G.append(self._powers(X, k, self.gamma, self.g1, G, inv_x0))
            if self.gamma == 0:
                gv = V[k]
            else:
                gv = mp.fdot(G[: k + 1], V[k::-1])
            V.append(-(om * A[k] + gv) / (k + 1))
            X.append(V[k] / (k + 1))
        return X, V

    def alpha_mpf(self):
        return mp.mpf(self.alpha.numerator) / self.alpha.denominator

    def gamma_mpf(self):
        return mp.mpf(self.gamma.numerator) / self.gamma.denominator

    def u_series(self, u0, v0, t0):
        """Taylor coefficients in s = u - u0 of v and tau, with v0 != 0."""
        n, om, p = self.order, self.omega, self.p
        pa = _binomial_poly(u0, p - 1 + self.qa, n)
        pg = _binomial_poly(u0, p - 1 + self.qg, n)
        p1 = _binomial_poly(u0, p - 1, n)
        V, T, W = [v0], [t0], []
        inv_v0 = 1 / v0
        for k in range(n):
            if k == 0:
                W.append(inv_v0)
            else:
                W.append(-mp.fdot(V[1 : k + 1], W[k - 1 :: -1]) * inv_v0)
            V.append(-p * (om * _poly_times_series(pa, W, k) + pg[k]) / (k + 1))
            T.append(p * _poly_times_series(p1, W, k) / (k + 1))
        return V, T

    def force_u_series(self, u0, V):
        """Series of Omega u^ea + u^eg v: same sign as the force f for u > 0."""
        n = len(V) - 1
        pe = _binomial_poly(u0, self.ea, n)
        pg = _binomial_poly(u0, self.eg, n)
        return [self.omega * pe[k] + _poly_times_series(pg, V, k) for k in range(n + 1)]


# ----------------------------------------------------------------------------------
# the integration


def _order_for(digits: int) -> int:
    # Cost per unit time ~ N^2 / h with h ~ rho tol^(1/N): minimal near N = ln(1/tol)/2.
    return max(12, int(math.ceil(0.5 * (digits + _TOL_EXTRA) * math.log(10))) + 2)


def _small_omega_digits(omega_in) -> int:
    # At small Omega the end of contact lies in a creep where x'' ~ Omega^2 is the
    # difference of two terms of size Omega, and its slope is ~ Omega^2 too: a relative
    # error delta of the state moves tau_c by about delta / Omega. Those digits are added
    # to the tolerance and to the working precision (eps, x_b, x_c do not need them).
    with mp.workdps(20):
        lg = mp.log10(_to_mpf(omega_in))
    return max(0, int(mp.ceil(-lg)))


def _return_leg(model: _Model, u, v, t, log2_tol: float, seek_force: bool, count) -> dict:
    """Phase C: u decreasing from ``u`` (v < 0) to the first root of the force (when sought) or to
    u = 0, a separation with speed -v."""
    p, order = model.p, model.order
    while True:
        count()
        V, T = model.u_series(u, v, t)
        h = _step_bound((V, T), order, log2_tol)
        last = h >= u
        s_end = -u if last else -h
        while not last and _horner(V, s_end) >= 0:
            s_end /= 2
        hit = None
        if seek_force:
            E = model.force_u_series(u, V)
            hit = _first_sign_change(E, s_end)
        if hit is not None:
            s = _root(E, *hit)
            uc = u + s
            return dict(tau_c=_horner(T, s), x_c=uc**p, eps=-_horner(V, s), ended_by="force")
        if last:
            return dict(tau_c=_horner(T, s_end), x_c=mp.zero, eps=-_horner(V, s_end), ended_by="separation")
        u, v, t = u + s_end, _horner(V, s_end), _horner(T, s_end)


def _integrate(alpha: Fraction, gamma: Fraction, omega_in, digits: int, end: str) -> dict:
    eff = digits + _small_omega_digits(omega_in)
    dps = eff + _GUARD_DIGITS
    with mp.workdps(dps):
        omega = _to_mpf(omega_in)
        # At u = 0 the series are sparse (powers of u^d with d up to p + q): the order must reach
        # past the first gap, or the truncated series would look converged while it is not (with
        # denominators 11 and 12, p = 132 is far beyond the order that the tolerance asks for).
        p_ = math.lcm(alpha.denominator, gamma.denominator)
        order = max(_order_for(eff), p_ + int(max(alpha, gamma) * p_) + 3)
        log2_tol = -(eff + _TOL_EXTRA) * math.log2(10)
        model = _Model(alpha, gamma, omega, order)
        # Under the overlap rule a vanishing force is no end: only x = 0 is.
        seek_force = model.force_can_vanish and end == "force"
        p = model.p
        steps = 0

        def count():
            nonlocal steps
            steps += 1
            if steps > _MAX_STEPS:
                raise ArithmeticError(
                    f"more than {_MAX_STEPS} Taylor steps (alpha={alpha}, gamma={gamma}, "
                    f"Omega={omega_in})")

        # Phase A: u from 0 while v > 1/2.
        u, v, t = mp.zero, mp.one, mp.zero
        while v > 0.5:
            count()
            V, T = model.u_series(u, v, t)
            # at u = 0 the series are sparse: powers of u^d, d | p + q_alpha, p + q_gamma
            tail = 2 if u else model.p + max(model.qa, model.qg) + 1
            h = _step_bound((V, T), order, log2_tol, tail)
            while True:
                v_new = _horner(V, h)
                if v_new > 0.05 * v:
                    break
                h /= 2  # never run into v = 0, where u stops being a good variable
            u, v, t = u + h, v_new, _horner(T, h)

        # Phase B: tau as variable.
        x = u**p
        tau_b = x_b = None
        result = None
        while True:
            count()
            X, V = model.tau_series(x, v)
            h = _step_bound((X, V), order, log2_tol)
            while _horner(X, h) <= 0:
                h /= 2
            if tau_b is None:
                hit = _first_sign_change(V, h)
                if hit is not None:
                    s = _root(V, *hit)
                    tau_b, x_b = t + s, _horner(X, s)
                    t, x, v = tau_b, x_b, mp.zero
                    continue
            elif seek_force:
                D = _derivative(V)
                hit = _first_sign_change(D, h)
                if hit is not None:
                    s = _root(D, *hit)
                    result = dict(tau_c=t + s, x_c=_horner(X, s), eps=-_horner(V, s),
                                  ended_by="force")
                    break
            t, x, v = t + h, _horner(X, h), _horner(V, h)
            if tau_b is not None and v < 0 and x < x_b / 4:
                break

        # Phase C: u decreasing to 0.
        if result is None:
            result = _return_leg(model, mpmath.root(x, p), v, t, log2_tol, seek_force, count)

        result.update(tau_b=tau_b, x_b=x_b, omega=omega, steps=steps)
        # unary plus rounds to the working precision of this run
        return {k: (+val if isinstance(val, mpmath.mpf) else val) for k, val in result.items()}


def _to_mpf(value):
    if isinstance(value, Fraction):
        return mp.mpf(value.numerator) / value.denominator
    return mp.mpf(value)


def _check_omega(omega):
    allowed = "must be a finite number > 0"
    if isinstance(omega, bool):
        raise ParameterError("omega", omega, allowed)
    try:
        with mp.workdps(30):
            val = _to_mpf(omega)
    except (TypeError, ValueError):
        raise ParameterError("omega", omega, allowed) from None
    if not mp.isfinite(val) or val <= 0:
        raise ParameterError("omega", omega, allowed)


_COMPARED = ("eps", "tau_b", "x_b", "tau_c")


def reference_collision(problem: Problem, omega, *, digits: int = 30) -> HighPrecisionCollision:
    """Collision quantities to about ``digits`` significant digits.

    ``omega`` may be a float, int, Fraction, decimal string or mpf (strings and Fractions are read
    at full working precision; a float is taken as the exact binary number it is). Runs the
    integration twice (see module docstring), so it costs about three times one run.

    Parameters
    ----------
    problem : Problem, Exponents or (alpha, gamma)
        The exponents and the end-of-contact rule ("force" or "overlap", where contact lasts until
        x = 0; plain exponents: the force rule).
    omega : float, int, Fraction, str or mpf
        Omega > 0.
    digits : int, optional
        Working significant digits.

    Returns
    -------
    HighPrecisionCollision
        eps, tau_b, x_b, tau_c, x_c as mpf, ``ended_by``, and ``error_estimate`` (the relative
        difference from a run at more digits).

    Raises
    ------
    ParameterError
        For bad inputs.

    Examples
    --------
    >>> from restitution.core.collision import collide
    >>> r = reference_collision(("3/2", 1), 0.5, digits=20)
    >>> r.ended_by, r.error_estimate < 1e-18
    ('force', True)
    >>> abs(float(r.eps) / collide(("3/2", 1), 0.5).eps - 1) < 1e-10     # scipy's reference
    True
    """
    problem = as_problem(problem)
    ex = problem.ex
    _check_omega(omega)
    integer_in("digits", digits, _MIN_DIGITS, _MAX_DIGITS)
    main = _integrate(ex.alpha, ex.gamma, omega, digits, problem.end)
    check = _integrate(ex.alpha, ex.gamma, omega, digits + _CHECK_EXTRA, problem.end)
    with mp.workdps(digits + _CHECK_EXTRA + _GUARD_DIGITS + _small_omega_digits(omega)):
        if main["ended_by"] != check["ended_by"]:
            # The end condition itself is not resolved (force root at x = 0, alpha = gamma).
            err = mp.inf
        else:
            err = max(abs(main[k] - check[k]) / abs(check[k]) for k in _COMPARED)
        err = +err
    return HighPrecisionCollision(
        problem=problem, omega=main["omega"], eps=main["eps"],
        tau_b=main["tau_b"], x_b=main["x_b"], tau_c=main["tau_c"], x_c=main["x_c"],
        ended_by=main["ended_by"], digits=digits, error_estimate=err, steps=main["steps"])

# ----------------------------------------------------------------------------------
# the creeping return at small Omega

#: Below this Omega the creeping return (alpha <= gamma, or the overlap rule) is taken through its
#: inner problem (:func:`creep_rebound_speed`): the Taylor integration above would need ~0.2/Omega steps.
CREEP_MAX = 1e-5


def _creep_speed(alpha: Fraction, gamma: Fraction, digits: int) -> mpmath.mpf:
    """C = -w(0) on the creeping solution of y'' + y^alpha + y^gamma y' = 0 (one run at ``digits``).

    With z = y^(-m), W = w / y^d (m = 2 gamma + 1 - alpha, d = alpha - gamma) the phase-plane equation
    w dw/dy = -y^alpha - y^gamma w reads m z^2 W W_z = 1 + W + d z W^2, and the creep is its solution
    with W -> -1 as z -> 0 (as y -> infinity). Its formal series W = sum b_n z^n has
    b_n = (m (n-1)/2 - d) [W^2]_(n-1) and diverges like m^n n!; truncated at n = N/2 it gives W at
    z0 = 1/(m N) to about e^(-0.85 N). From z0 to z = 1 every other solution is drawn onto the creep by
    exp(-int dz/(m z^2 W^2)) ~ e^(-N), so the start's error arrives damped below e^(-1.8 N). The leg
    z0 -> 1 is stiff only over ~N relaxation lengths, a few dozen Taylor steps (the steps grow with
    z, whose series converge within |s| < z); from y = 1 (z = 1, w = W) to y = 0 the inner problem
    is Omega = 1 of the collision, integrated in u = y^(1/p) as the return leg above.
    """
    eff = digits
    with mp.workdps(eff + _GUARD_DIGITS):
        m, d = 2 * gamma + 1 - alpha, alpha - gamma
        mm, dd = _to_mpf(m), _to_mpf(d)
        p_ = math.lcm(alpha.denominator, gamma.denominator)
        order = max(_order_for(eff), p_ + int(max(alpha, gamma) * p_) + 3)
        log2_tol = -(eff + _TOL_EXTRA) * math.log2(10)
        steps = 0

        def count():
            nonlocal steps
            steps += 1
            if steps > _MAX_STEPS:
                raise ArithmeticError(f"more than {_MAX_STEPS} Taylor steps on the creep (alpha={alpha}, "
                                      f"gamma={gamma})")

        N = int(math.ceil((eff + _TOL_EXTRA + 2) * math.log(10) / 1.8)) + 2
        b = [-mp.one]
        for n in range(1, N // 2 + 1):
            b.append((mm * (n - 1) / 2 - dd) * mp.fdot(b, b[::-1]))
        z = 1 / (mm * N)
        W = _horner(b, z)
        while z < 1:
            count()
            p0, p1, p2 = mm * z * z, 2 * mm * z, mm
            Ws, Qs = [W], [W * W]
            for k in range(order):
                rhs = (1 if k == 0 else 0) + Ws[k] + dd * z * Qs[k] + (dd * Qs[k - 1] if k else 0)
                q = (2 * rhs - p1 * k * Qs[k] - (p2 * (k - 1) * Qs[k - 1] if k else 0)) / (p0 * (k + 1))
                conv = mp.fdot(Ws[1 : k + 1], Ws[k:0:-1]) if k else mp.zero
                Ws.append((q - conv) / (2 * W))
                Qs.append(q)
            h = min(_step_bound((Ws,), order, log2_tol), 1 - z)
            while _horner(Ws, h) >= 0:   # W < 0 all along (w = 0 would be sticking)
                h /= 2
            W = _horner(Ws, h)
            z = mp.one if h == 1 - z else z + h
        model = _Model(alpha, gamma, mp.one, order)
        # under the force rule with alpha < gamma the force cannot vanish while y > 0 (overlap_limit)
        leg = _return_leg(model, mp.one, W, mp.zero, log2_tol, False, count)
        return +leg["eps"]


def creep_rebound_speed(problem, *, digits: int = 30) -> tuple[mpmath.mpf, mpmath.mpf]:
    """The speed C at y = 0 of the creeping return, y'' + y^alpha + y^gamma y' = 0 coming from y = infinity
    along w ~ -y^(alpha-gamma), to about ``digits`` digits: eps ~ C Omega^k at small Omega
    (:mod:`restitution.core.overlap_limit`, which integrates the same C in double precision).

    Parameters
    ----------
    problem : Problem, Exponents or (alpha, gamma)
        The exponents; alpha < 2 gamma + 1.
    digits : int
        Significant digits asked for (8 to 300).

    Returns
    -------
    C, error : mpmath.mpf
        C from a run at ``digits`` and its relative difference from a run at ``digits`` + 10.

    Raises
    ------
    ParameterError
        alpha >= 2 gamma + 1 (the bodies can stick: no creep reaches y = 0), or digits out of range.

    Examples
    --------
    >>> C, err = creep_rebound_speed(("1", "1"), digits=15)     # alpha = gamma: w = -1 exactly
    >>> float(C), float(err) < 1e-15
    (1.0, True)
    """
    ex = as_problem(problem).ex
    integer_in("digits", digits, _MIN_DIGITS, _MAX_DIGITS)
    if not ex.alpha < 2 * ex.gamma + 1:
        raise ParameterError("alpha, gamma", f"{ex.alpha}, {ex.gamma}",
                             "the creeping return needs alpha < 2 gamma + 1 (otherwise the bodies can stick)")
    return _creep_pair(ex.alpha, ex.gamma, digits)


@lru_cache(maxsize=32)
def _creep_pair(alpha: Fraction, gamma: Fraction, digits: int) -> tuple[mpmath.mpf, mpmath.mpf]:
    C = _creep_speed(alpha, gamma, digits)
    check = _creep_speed(alpha, gamma, digits + _CHECK_EXTRA)
    with mp.workdps(digits + _CHECK_EXTRA + _GUARD_DIGITS):
        return C, +abs(C - check) / abs(check)


def creep_distance_bound(problem, omega) -> mpmath.mpf:
    """A bound on |eps / (C Omega^k) - 1| at Omega <= CREEP_MAX: how far the collision's return is from
    the creep (alpha < 2 gamma + 1; the overlap rule, or either where alpha <= gamma).

    In the inner variables the collision is the creep's equation entered at z_b = Omega / x_b^m
    (x_b >= X/2 at such Omega, X = (gamma+1)^(1/(gamma+1))) with W between 0 and -1; the distance to
    the creep contracts by exp(int (d/(m z) - 1/(m z^2 W^2)) dz), and |W| <= 2 on the creep below
    z ~ 1/(2 (|d| + 1)), which gives exp(-(1/z_b - 2 (|d| + 1)) / (4 m)) z_b^(-|d|/m). The tests check
    it against the Taylor integration where the distance is visible (Omega 0.03 and 0.1).

    Parameters
    ----------
    problem : Problem, Exponents or (alpha, gamma)
        The exponents, alpha < 2 gamma + 1.
    omega : float, Fraction, str or mpf
        Omega > 0.

    Returns
    -------
    mpmath.mpf
        The bound (at the caller's working precision).

    Examples
    --------
    >>> float(creep_distance_bound(("3/2", "1"), 1e-3)) < 1e-40
    True
    """
    ex = as_problem(problem).ex
    m, d = 2 * ex.gamma + 1 - ex.alpha, abs(ex.alpha - ex.gamma)
    mm, dd = _to_mpf(m), _to_mpf(d)
    x_lo = _to_mpf(ex.gamma + 1) ** (1 / _to_mpf(ex.gamma + 1)) / 2
    inv_zb = x_lo ** mm / _to_mpf(omega)
    return mp.exp(-(inv_zb - 2 * (dd + 1)) / (4 * mm)) * inv_zb ** (dd / mm)


def highprec_eps(problem: Problem, omega, *, digits: int = 30) -> tuple[mpmath.mpf, mpmath.mpf]:
    """eps and its relative error estimate at any Omega where contact ends: the Taylor integration of
    :func:`reference_collision`, or below CREEP_MAX, where the return creeps (alpha <= gamma, or the
    overlap rule with alpha < 2 gamma + 1), C Omega^k with C from :func:`creep_rebound_speed`.

    Parameters
    ----------
    problem : Problem
        The exponents and the end rule (an Exponents or a pair stands for its force rule).
    omega : float, Fraction, str or mpf
        Omega > 0.
    digits : int
        Significant digits asked for.

    Returns
    -------
    eps, error : mpmath.mpf
        eps, and its relative error estimate: the two runs' difference, plus on the creep the bound
        on its distance from C Omega^k (exponentially small in 1/Omega).

    Raises
    ------
    ParameterError
        Bad inputs.
    ArithmeticError
        The Taylor integration's step limit (a creep where no inner law holds: alpha >= 2 gamma + 1
        under the overlap rule at small Omega, where the bodies may stick).

    Examples
    --------
    >>> eps, err = highprec_eps(Problem.of("3/2", "1", end="overlap"), 1e-9, digits=15)
    >>> round(float(eps / mpmath.mpf(1e-9) ** (mpmath.mpf(4) / 3)), 10), float(err) < 1e-14
    (1.1711635205, True)
    """
    problem = as_problem(problem)
    ex = problem.ex
    _check_omega(omega)
    integer_in("digits", digits, _MIN_DIGITS, _MAX_DIGITS)
    overlap = problem.end == "overlap"
    creeps = ex.alpha <= ex.gamma or (overlap and ex.alpha < 2 * ex.gamma + 1)
    with mp.workdps(20):
        small = _to_mpf(omega) < CREEP_MAX
    if not (creeps and small):
        r = reference_collision(problem, omega, digits=digits)
        return r.eps, r.error_estimate
    C, err = _creep_pair(ex.alpha, ex.gamma, digits)
    with mp.workdps(digits + _GUARD_DIGITS):
        om = _to_mpf(omega)
        k = _to_mpf(ex.gamma + 1) / _to_mpf(2 * ex.gamma + 1 - ex.alpha)
        return +(C * om ** k), +(err + creep_distance_bound(ex, om))

"""The values the paper's matching procedure matches: the reference points and the series there.

Reference points tau_0, tau~_0 are where the damped-only forward / inverse solutions reach x = 1;
the matching conditions (:mod:`restitution.audit.matching`) are Taylor-expanded about them, with
the choices of a :class:`~restitution.audit.readings.Reading`. This module holds the symbols of
those equations, the reference points and the derivatives of the exact series there.

Symbols: a_{n,j} = x_n^(j)(tau_0) and b_{n,j} = x~_n^(j)(tau~_0) (j-th tau derivative of the
Omega^n term). The equations are built with these symbols; their values are exact sympy
expressions in tau_0, tau~_0 (rational coefficients from the series engine, tau_0 a closed form
or an exact integral), evaluated with ``evalf`` only at the end.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache

import mpmath
import sympy as sp

from ..core.errors import ParameterError
from ..core.exponents import Exponents, as_exponents
from ..core.series import falling_factorial, series_for
from .readings import CONVERGED_MAX_POWER, PRINTED_MAX_POWER, Reading

__all__ = ["W", "WT", "D", "DT", "U", "a_sym", "b_sym", "check_gamma_forward", "damped_derivatives",
           "reference_times", "reference_derivatives"]

#: Terms of the Taylor series about tau~ = 0 used when the inverse collision starts at x~_c > 0.
X_TILDE_C_TERMS = 90

W, WT, D, DT = sp.symbols("Omega Omega_t Delta Delta_t")
U = sp.Symbol("u", positive=True)  # Omega~/Omega in the rescaled reading


def a_sym(n: int, j: int) -> sp.Symbol:
    """x_n^(j)(tau_0): j-th derivative of the forward Omega^n term at the reference point."""
    return sp.Symbol(f"a_{n}{j}")


def b_sym(n: int, j: int) -> sp.Symbol:
    """x~_n^(j)(tau~_0): the same for the inverse series."""
    return sp.Symbol(f"b_{n}{j}")


# ------------------------------------------------------------------------------- reference points
def check_gamma_forward(ex: Exponents) -> None:
    if ex.gamma == 0:
        raise ParameterError(
            "gamma", str(ex.gamma),
            "must be > 0 for the connection: with gamma = 0 the damped-only forward solution obeys "
            "x' = 1 - x and only approaches x = 1 as tau -> infinity, so tau_0 does not exist")


def _first_integral_velocity(gamma: sp.Rational, sign: int, x_start=sp.Integer(0)):
    """v(x) along the damped-only solution from x(0) = x_start, x'(0) = 1.

    Forward (sign +1): x' + x^(g+1)/(g+1) = const; inverse (sign -1): x' - x^(g+1)/(g+1) = const.
    """
    x = sp.Symbol("x", positive=True)
    k = gamma + 1
    return x, 1 - sign * (x ** k - x_start ** k) / k


def reference_times(problem, x_tilde_c=0) -> tuple[sp.Expr, sp.Expr]:
    """Exact tau_0, tau~_0: where the damped-only forward / inverse solutions reach x = 1.

    gamma = 1, x~_c = 0: tau_0 = sqrt2 atanh(1/sqrt2), tau~_0 = sqrt2 atan(1/sqrt2). Otherwise the
    quadrature of the first integral, tau = int dx / v(x), returned as an unevaluated sympy Integral.
    gamma = 0 raises ParameterError (the forward solution never reaches 1).
    """
    ex = as_exponents(problem)
    check_gamma_forward(ex)
    g = sp.Rational(ex.gamma.numerator, ex.gamma.denominator)
    xc = _exact(x_tilde_c)
    if g == 1:
        tau0 = sp.sqrt(2) * sp.atanh(1 / sp.sqrt(2))
    else:
        x, v = _first_integral_velocity(g, +1)
        tau0 = sp.Integral(1 / v, (x, 0, 1))
    if g == 1 and xc == 0:
        tau0t = sp.sqrt(2) * sp.atan(1 / sp.sqrt(2))
    elif g == 1:
        H = sp.sqrt(2 - xc ** 2)
        tau0t = 2 / H * (sp.atan(1 / H) - sp.atan(xc / H))
    else:
        x, v = _first_integral_velocity(g, -1, xc)
        tau0t = sp.Integral(1 / v, (x, xc, 1))
    return tau0, tau0t


def damped_derivatives(gamma: Fraction, sign: int, x_start, jmax: int) -> list[sp.Expr]:
    """x0^(j) at the point where the damped-only solution has x0 = 1, exact, j = 0..jmax."""
    g = sp.Rational(gamma.numerator, gamma.denominator)
    x, v = _first_integral_velocity(g, sign, _exact(x_start))
    out, d = [sp.Integer(1)], x  # d/dtau = v(x) d/dx along the trajectory
    for _ in range(jmax):
        d = sp.expand(v * sp.diff(d, x))
        out.append(sp.simplify(d.subs(x, 1)))
    return out


def _exact(value) -> sp.Expr:
    """A float given by the user as the exact decimal it prints as (0.855 -> 171/200)."""
    return sp.Rational(str(value)) if value else sp.Integer(0)


def _series_derivative(terms, t, j: int) -> sp.Expr:
    """sum c (pw)_j t^(pw - j) for exact (power, coeff) pairs: the j-th derivative at t."""
    total = sp.Integer(0)
    for pw, c in terms:
        fall = falling_factorial(pw, j)
        if fall:
            total += sp.Rational((c * fall).numerator, (c * fall).denominator) * \
                t ** sp.Rational((pw - j).numerator, (pw - j).denominator)
    return total


def _taylor_from_start(alpha: Fraction, gamma: Fraction, x_c: float, order: int, n_terms: int,
                       dps: int):
    """Taylor coefficients about tau~ = 0 of the inverse equation from x~(0) = x_c > 0, x~'(0) = 1.

    Returns A[k][n]: coefficient of tau~^k Omega~^n (mpmath numbers). x~ is analytic there because
    x_c > 0; powers x~^alpha use Miller's recurrence on y = x~/x_c.
    """
    with mpmath.workdps(dps):
        xc = mpmath.mpf(x_c)
        al, ga = mpmath.mpf(alpha.numerator) / alpha.denominator, mpmath.mpf(gamma.numerator) / gamma.denominator
        zero = lambda: [mpmath.mpf(0)] * (order + 1)  # noqa: E731
        A = [zero() for _ in range(n_terms)]
        A[0][0], A[1][0] = xc, mpmath.mpf(1)
        y = lambda k: [c / xc for c in A[k]]  # noqa: E731
        wa, wg = [[mpmath.mpf(1)] + [mpmath.mpf(0)] * order], [[mpmath.mpf(1)] + [mpmath.mpf(0)] * order]

        def mul_acc(acc, p, q, scale):
            for i, pi in enumerate(p):
                if pi:
                    for jj in range(order + 1 - i):
                        acc[jj + i] += scale * pi * q[jj]

        def power_next(w, e, k):
            acc = zero()
            for j in range(1, k + 1):
                c = (e + 1) * j - k
                if c:
                    mul_acc(acc, y(j), w[k - j], c)
            w.append([v / k for v in acc])

        xa, xg = mpmath.power(xc, al), mpmath.power(xc, ga)
        for k in range(n_terms - 2):
            while len(wa) <= k:
                power_next(wa, al, len(wa))
            while len(wg) <= k:
                power_next(wg, ga, len(wg))
            rhs = zero()
            for n in range(order):  # -Omega~ x^alpha
                rhs[n + 1] -= xa * wa[k][n]
            acc = zero()  # + x^gamma x'
            for i in range(k + 1):
                m = k - i
                mul_acc(acc, wg[i], A[m + 1], (m + 1) * xg)
            rhs = [r + a for r, a in zip(rhs, acc)]
            A[k + 2] = [r / ((k + 2) * (k + 1)) for r in rhs]
        return A


@dataclass(frozen=True)
class _Values:
    """Numeric a_{n,j}, b_{n,j} for one reading, the reference times and a convergence indicator."""

    a: dict
    b: dict
    tau0: sp.Expr
    tau0_tilde: sp.Expr
    truncation_change: float
    exact: dict | None = None


def _series_value(terms, t: mpmath.mpf, j: int) -> mpmath.mpf:
    """Numeric j-th derivative at t of sum c t^pw (exact rationals, evaluated in mpmath)."""
    total = mpmath.mpf(0)
    for pw, c in terms:
        fall = falling_factorial(pw, j)
        if fall:
            cf = c * fall
            total += mpmath.mpf(cf.numerator) / cf.denominator * \
                mpmath.power(t, mpmath.mpf((pw - j).numerator) / (pw - j).denominator)
    return total


@lru_cache(maxsize=16)
def _series_upto(alpha: Fraction, gamma: Fraction, orders: int, max_power: Fraction, direction: str):
    """Shared by every reading of one run: x_n does not depend on how many orders are computed, so
    the readings with 1, 2 and 4 orders use one derivation (at tau^120 it takes seconds)."""
    return series_for((alpha, gamma), orders, max_power, direction)


def reference_derivatives(problem, reading: Reading, *, jmax: int = 3, digits: int = 30,
                          exact: bool = False) -> _Values:
    """Values of a_{n,j} = x_n^(j)(tau_0), b_{n,j} = x~_n^(j)(tau~_0) for n <= omega_orders, j <= jmax.

    The series coefficients are exact rationals and tau_0, tau~_0 exact expressions; both are
    evaluated at ``digits`` significant digits only here. ``exact=True`` also returns each value as an
    exact sympy expression (``.exact``; not for x~_c > 0, whose series come from a floating Taylor
    recurrence). ``truncation_change`` is the largest change of any value when the converged series
    is cut at 3/4 of its length (a convergence indicator; 0 for the printed truncation).
    """
    ex = as_exponents(problem)
    check_gamma_forward(ex)
    N = reading.omega_orders
    tau0, tau0t = reference_times(ex, reading.x_tilde_c)
    change = 0.0

    def forward_inverse(max_power):
        return (_series_upto(ex.alpha, ex.gamma, max(N, 4), max_power, "forward"),
                _series_upto(ex.alpha, ex.gamma, max(N, 4), max_power, "inverse"))

    converged = reading.truncation == "converged"
    fs, inv = forward_inverse(CONVERGED_MAX_POWER if converged else PRINTED_MAX_POWER)
    x0f = damped_derivatives(ex.gamma, +1, 0, jmax)
    x0i = damped_derivatives(ex.gamma, -1, 0, jmax)
    a, b, exact_map = {}, {}, {} if exact else None
    with mpmath.workdps(digits + 10):
        t0 = mpmath.mpf(str(sp.N(tau0, digits + 10)))
        t0t = mpmath.mpf(str(sp.N(tau0t, digits + 10)))
        fl = lambda v: sp.Float(mpmath.nstr(v, digits + 5), digits)  # noqa: E731
        for n in range(N + 1):
            for j in range(jmax + 1):
                if n == 0 and converged:
                    a[a_sym(n, j)], b[b_sym(n, j)] = sp.Float(x0f[j], digits), sp.Float(x0i[j], digits)
                else:
                    a[a_sym(n, j)] = fl(_series_value(fs.terms(n), t0, j))
                    b[b_sym(n, j)] = fl(_series_value(inv.terms(n), t0t, j))
                if exact:
                    if n == 0 and converged:
                        exact_map[a_sym(n, j)], exact_map[b_sym(n, j)] = x0f[j], x0i[j]
                    else:
                        exact_map[a_sym(n, j)] = _series_derivative(fs.terms(n), tau0, j)
                        exact_map[b_sym(n, j)] = _series_derivative(inv.terms(n), tau0t, j)
        if converged:
            fh, ih = forward_inverse(CONVERGED_MAX_POWER * Fraction(3, 4))
            for n in range(1, N + 1):
                for j in range(jmax + 1):
                    change = max(change,
                                 abs(float(_series_value(fh.terms(n), t0, j) - a[a_sym(n, j)])),
                                 abs(float(_series_value(ih.terms(n), t0t, j) - b[b_sym(n, j)])))

    if reading.x_tilde_c:
        A = _taylor_from_start(ex.alpha, ex.gamma, reading.x_tilde_c, N, X_TILDE_C_TERMS, digits + 10)
        with mpmath.workdps(digits + 10):
            t = mpmath.mpf(str(sp.N(tau0t, digits + 10)))
            for n in range(N + 1):
                for j in range(jmax + 1):
                    val = sum(A[k][n] * mpmath.ff(k, j) * t ** (k - j) for k in range(j, X_TILDE_C_TERMS))
                    b[b_sym(n, j)] = sp.Float(mpmath.nstr(val, digits + 5), digits)
                    if exact:
                        exact_map[b_sym(n, j)] = b[b_sym(n, j)]
            tail = max(abs(A[k][n]) * t ** k for k in range(X_TILDE_C_TERMS - 4, X_TILDE_C_TERMS)
                       for n in range(N + 1))
        change = max(change, float(tail))
    return _Values(a, b, tau0, tau0t, change, exact_map)

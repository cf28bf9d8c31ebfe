"""Connection of the forward and inverse collisions: Omega~ as a function of Omega.

The paper (its Sec. V) joins the forward solution x(tau; Omega) and the inverse one
x~(tau~; Omega~) at maximum compression and writes Omega~ = c0 + c1 Omega + c2 Omega^2
(it prints c0 = 6.0203, c1 = -1.5257, c2 = 0.0256). This module does that three ways.

1. ``paper_procedure``: the paper's own procedure, derived symbolically from the exact series.
   Reference points tau_0, tau~_0 are where the damped-only forward / inverse solutions reach
   x = 1. With Delta = tau_b - tau_0 and Delta~ = tau~_b - tau~_0 the three conditions are

       x'(tau_0 + Delta) = 0,   x~'(tau~_0 + Delta~) = 0,   x(tau_0 + Delta) = s x~(tau~_0 + Delta~),

   each Taylor-expanded about the reference point, with s = 1 as the paper writes it (or the scale
   change s = eps^(1/(gamma+1)) between forward and inverse variables). Substituting
   Omega~ = c0 + c1 Omega + c2 Omega^2 (and Delta, Delta~ as power series in Omega) and comparing
   powers of Omega gives a nonlinear equation for c0 and linear ones for c1, c2 ("comparing term
   by term"). The text leaves several choices open; each is a field of :class:`Reading`.

2. ``exact_omega_tilde`` / ``fit_connection``: the true Omega~(Omega) = Omega eps^((alpha-1-2gamma)/(gamma+1))
   from the reference integrator, and c0-c2 fitted to it by least squares.

3. ``retrace``: the inverse collision started from the forward end state, mapped back to forward
   variables, must reproduce the forward trajectory. That checks the exact connection, including
   the variable change between the two scalings (derived in :func:`retrace`).

Symbols: a_{n,j} = x_n^(j)(tau_0) and b_{n,j} = x~_n^(j)(tau~_0) (j-th tau derivative of the
Omega^n term). The equations are built with these symbols; their values are exact sympy
expressions in tau_0, tau~_0 (rational coefficients from the series engine, tau_0 a closed form
or an exact integral), evaluated with ``evalf`` only at the end.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from fractions import Fraction
from functools import lru_cache

import mpmath
import numpy as np
import sympy as sp

from .errors import ParameterError, require_positive_finite
from .exponents import Exponents, as_exponents
from .series import falling_factorial, perturbation_series

__all__ = [
    "Reading", "ConnectionCoefficients", "FitResult", "RetraceResult",
    "PRINTED_MAX_POWER", "CONVERGED_MAX_POWER",
    "reference_times", "reference_derivatives", "lowest_order_deltas", "printed_deltas",
    "symbolic_system", "paper_procedure", "all_readings",
    "exact_omega_tilde", "fit_connection", "fit_quadratic", "eps_from_connection", "omega_tilde_from_c",
    "connection_validity", "retrace",
]

#: The paper prints every series up to tau^11.
PRINTED_MAX_POWER = Fraction(11)
#: "Converged": the series at tau_0 ~ 1.25 (radius pi/sqrt 2 ~ 2.22) change by < 1e-14 beyond this.
CONVERGED_MAX_POWER = Fraction(120)
#: Terms of the Taylor series about tau~ = 0 used when the inverse collision starts at x~_c > 0.
X_TILDE_C_TERMS = 90
#: c0 is searched in (0, C0_SEARCH_MAX]; every real root found there is reported.
C0_SEARCH_MAX = 200.0

_TRUNCATIONS = ("printed", "converged")
_DELTAS = ("printed", "linear", "quadratic")
_CONVENTIONS = ("sum", "factorial")

W, WT, D, DT = sp.symbols("Omega Omega_t Delta Delta_t")
U = sp.Symbol("u", positive=True)  # Omega~/Omega in the rescaled reading


def a_sym(n: int, j: int) -> sp.Symbol:
    """x_n^(j)(tau_0): j-th derivative of the forward Omega^n term at the reference point."""
    return sp.Symbol(f"a_{n}{j}")


def b_sym(n: int, j: int) -> sp.Symbol:
    """x~_n^(j)(tau~_0): the same for the inverse series."""
    return sp.Symbol(f"b_{n}{j}")


# ----------------------------------------------------------------------------------------- readings
@dataclass(frozen=True)
class Reading:
    """One reading of the paper's (terse) connection procedure.

    truncation
        ``"printed"``: every x_n as printed, up to tau^11 (x0 too). ``"converged"``: x0 from the
        damped-only closed form / first integral, x_n (n >= 1) summed to tau^120 (converged to
        double precision at tau_0 and tau~_0).
    omega_orders
        Highest power of Omega (Omega~) kept in each series: 1 means x0 + Omega x1.
    match_order
        Order in Delta (Delta~) of the Taylor expansion of x (x~) in the matching condition.
    delta
        How Delta, Delta~ follow from x'(tau_b) = 0, x~'(tau~_b) = 0:
        ``"printed"`` the paper's lowest-order formulas Delta = 1 + 2 x1'(tau_0) Omega,
        Delta~ = -1 - (2/3) x~1'(tau~_0) Omega~ (general gamma: same derivation);
        ``"linear"`` x' expanded to first order in Delta with all kept Omega orders, solved exactly;
        ``"quadratic"`` x' expanded to second order in Delta, root nearest the linear one.
    rescale
        False: x(tau_b) = x~(tau~_b) as printed. True: x(tau_b) = s x~(tau~_b) with
        s = eps^(1/(gamma+1)) = (Omega~/Omega)^(1/(alpha-1-2gamma)), the ratio of the two length scales.
    x_tilde_c
        Where the inverse collision starts (x~(0)); the printed series assume 0. A value > 0 replaces
        the inverse series by the Taylor series of the inverse equation about tau~ = 0 from x~_c
        (always converged: nothing of that kind is printed).
    convention
        ``"sum"``: x = sum Omega^n x_n, the paper's Eq. (x), which its printed x_n satisfy.
        ``"factorial"``: x = sum Omega^n x_n / n!, the paper's Eq. (taylor) (the form it introduces
        first), with the printed x_n inserted; this halves x2, divides x3 by 6, x4 by 24.
    """

    truncation: str = "printed"
    omega_orders: int = 1
    match_order: int = 2
    delta: str = "printed"
    rescale: bool = False
    x_tilde_c: float = 0.0
    convention: str = "sum"

    def __post_init__(self):
        if self.convention not in _CONVENTIONS:
            raise ParameterError("convention", self.convention, f"must be one of {_CONVENTIONS}")
        if self.truncation not in _TRUNCATIONS:
            raise ParameterError("truncation", self.truncation, f"must be one of {_TRUNCATIONS}")
        if isinstance(self.omega_orders, bool) or not isinstance(self.omega_orders, (int, np.integer)) \
                or not 1 <= self.omega_orders <= 8:
            raise ParameterError("omega_orders", self.omega_orders, "must be an integer in [1, 8]")
        if self.match_order not in (1, 2):
            raise ParameterError("match_order", self.match_order, "must be 1 or 2")
        if self.delta not in _DELTAS:
            raise ParameterError("delta", self.delta, f"must be one of {_DELTAS}")
        if not isinstance(self.rescale, (bool, np.bool_)):
            raise ParameterError("rescale", self.rescale, "must be true or false")
        x = float(self.x_tilde_c)
        if not math.isfinite(x) or not 0.0 <= x < 1.0:
            raise ParameterError("x_tilde_c", self.x_tilde_c,
                                 "must be a number in [0, 1) (the reference point x~ = 1 must lie ahead)")

    @property
    def label(self) -> str:
        """Short stable identifier, e.g. ``P-N1-K2-Dprinted`` (+ ``-S`` rescaled, ``-xc0.85``)."""
        text = f"{self.truncation[0].upper()}-N{self.omega_orders}-K{self.match_order}-D{self.delta}"
        if self.rescale:
            text += "-S"
        if self.x_tilde_c:
            text += f"-xc{self.x_tilde_c:.4g}"
        if self.convention == "factorial":
            text += "-F"
        return text

    def describe(self) -> str:
        """One sentence for the manuscript."""
        trunc = ("series truncated at tau^11 as printed" if self.truncation == "printed"
                 else "converged series (x0 in closed form, x_n to tau^120)")
        if self.x_tilde_c:
            trunc += f"; inverse series started at x~_c = {self.x_tilde_c:.4g} (converged)"
        orders = "x0 + Omega x1" if self.omega_orders == 1 else f"x0 ... Omega^{self.omega_orders} x{self.omega_orders}"
        delta = {"printed": "Delta, Delta~ from the printed lowest-order formulas",
                 "linear": "Delta, Delta~ from x' expanded to first order in Delta, solved exactly",
                 "quadratic": "Delta, Delta~ from x' expanded to second order in Delta"}[self.delta]
        match = f"match expanded to order {self.match_order} in Delta"
        scale = ("match in common physical units, x = eps^(1/(gamma+1)) x~" if self.rescale
                 else "match x = x~ as printed (no change of scale)")
        conv = "" if self.convention == "sum" else " Series read as sum Omega^n x_n / n! (Eq. taylor)."
        return f"{trunc}; {orders} in each series; {delta}; {match}; {scale}.{conv}"


def all_readings(x_tilde_c: float | None = None) -> list[Reading]:
    """The documented set of readings whose c0-c2 we report (see Reading for the fields).

    1. ``P-N1-K2-Dprinted`` (plain): printed series, x0 + Omega x1, the printed Delta formulas, the
       match expanded to second order in Delta ("up to second order"), x = x~ as printed.
    2-3. the same with the Omega^2 terms and with every printed order (Omega^4).
    4-6. 1-3 with converged series instead of the tau^11 truncation.
    7. the match expanded to first order in Delta only.
    8. Delta, Delta~ from x' expanded to first order in Delta with all kept orders, solved exactly.
    9-10. "expand up to second order" applied to x'(tau_b) = 0 as well (printed / converged series).
    11. the series read with factorials, x = sum Omega^n x_n / n! (the paper's Eq. taylor).
    12-13. the change of scale between forward and inverse variables applied at the match.
    14. (only if ``x_tilde_c`` is given) the inverse series started at x~_c instead of 0.
    """
    plain = Reading()
    out = [
        plain,
        replace(plain, omega_orders=2),
        replace(plain, omega_orders=4),
        replace(plain, truncation="converged"),
        replace(plain, truncation="converged", omega_orders=2),
        replace(plain, truncation="converged", omega_orders=4),
        replace(plain, omega_orders=2, match_order=1),
        replace(plain, omega_orders=2, delta="linear"),
        replace(plain, omega_orders=2, delta="quadratic"),
        replace(plain, truncation="converged", omega_orders=2, delta="quadratic"),
        replace(plain, omega_orders=2, convention="factorial"),
        replace(plain, rescale=True),
        replace(plain, truncation="converged", omega_orders=2, rescale=True),
    ]
    if x_tilde_c:
        out.append(replace(plain, truncation="converged", omega_orders=2, x_tilde_c=float(x_tilde_c)))
    return out


# ------------------------------------------------------------------------------- reference points
def _check_gamma_forward(ex: Exponents) -> None:
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


def reference_times(alpha, gamma, x_tilde_c=0) -> tuple[sp.Expr, sp.Expr]:
    """Exact tau_0, tau~_0: where the damped-only forward / inverse solutions reach x = 1.

    gamma = 1, x~_c = 0: tau_0 = sqrt2 atanh(1/sqrt2), tau~_0 = sqrt2 atan(1/sqrt2). Otherwise the
    quadrature of the first integral, tau = int dx / v(x), returned as an unevaluated sympy Integral.
    gamma = 0 raises ParameterError (the forward solution never reaches 1).
    """
    ex = as_exponents(alpha, gamma)
    _check_gamma_forward(ex)
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


def _damped_derivatives(gamma: Fraction, sign: int, x_start, jmax: int) -> list[sp.Expr]:
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
    return perturbation_series(alpha, gamma, orders, max_power, direction)


def reference_derivatives(alpha, gamma, reading: Reading, *, jmax: int = 3, digits: int = 30,
                          exact: bool = False) -> _Values:
    """Values of a_{n,j} = x_n^(j)(tau_0), b_{n,j} = x~_n^(j)(tau~_0) for n <= omega_orders, j <= jmax.

    The series coefficients are exact rationals and tau_0, tau~_0 exact expressions; both are
    evaluated at ``digits`` significant digits only here. ``exact=True`` also returns each value as an
    exact sympy expression (``.exact``; not for x~_c > 0, whose series come from a floating Taylor
    recurrence). ``truncation_change`` is the largest change of any value when the converged series
    is cut at 3/4 of its length (a convergence indicator; 0 for the printed truncation).
    """
    ex = as_exponents(alpha, gamma)
    _check_gamma_forward(ex)
    N = reading.omega_orders
    tau0, tau0t = reference_times(ex, None, reading.x_tilde_c)
    change = 0.0

    def forward_inverse(max_power):
        return (_series_upto(ex.alpha, ex.gamma, max(N, 4), max_power, "forward"),
                _series_upto(ex.alpha, ex.gamma, max(N, 4), max_power, "inverse"))

    converged = reading.truncation == "converged"
    fs, inv = forward_inverse(CONVERGED_MAX_POWER if converged else PRINTED_MAX_POWER)
    x0f = _damped_derivatives(ex.gamma, +1, 0, jmax)
    x0i = _damped_derivatives(ex.gamma, -1, 0, jmax)
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


# ------------------------------------------------------------------------------------ the equations
def lowest_order_deltas(alpha, gamma) -> tuple[sp.Expr, sp.Expr]:
    """Delta(Omega), Delta~(Omega~) re-derived: x'(tau_0 + Delta) = 0 to first order in Delta and Omega.

    x0'(tau_0) + x0''(tau_0) Delta + Omega x1'(tau_0) = 0 with x0', x0'' at x0 = 1 from the first
    integral. Returned in terms of the symbols a_11 = x1'(tau_0) and b_11 = x~1'(tau~_0).
    """
    ex = as_exponents(alpha, gamma)
    _check_gamma_forward(ex)
    f = _damped_derivatives(ex.gamma, +1, 0, 2)
    i = _damped_derivatives(ex.gamma, -1, 0, 2)
    delta = sp.solve(sp.Eq(f[1] + f[2] * D + W * a_sym(1, 1), 0), D)[0]
    delta_t = sp.solve(sp.Eq(i[1] + i[2] * DT + WT * b_sym(1, 1), 0), DT)[0]
    return sp.expand(delta), sp.expand(delta_t)


def printed_deltas() -> tuple[sp.Expr, sp.Expr]:
    """The paper's printed lowest-order formulas, transcribed (for alpha = 3/2, gamma = 1)."""
    return 1 + 2 * a_sym(1, 1) * W, -1 - sp.Rational(2, 3) * b_sym(1, 1) * WT


def _taylor(sym, n: int, var, order: int, shift: int = 0) -> sp.Expr:
    """sum_{j <= order} sym(n, j + shift) var^j / j!"""
    return sp.Add(*[sym(n, j + shift) * var ** j / sp.factorial(j) for j in range(order + 1)])


def _weight(reading: Reading):
    """Factor multiplying Omega^n x_n: 1 (Eq. x) or 1/n! (Eq. taylor)."""
    if reading.convention == "sum":
        return lambda n: sp.Integer(1)
    return lambda n: 1 / sp.factorial(n)


def symbolic_system(alpha, gamma, reading: Reading):
    """The three conditions of the reading as sympy expressions (each = 0), in a_nj, b_nj symbols.

    Returns (E_forward, E_inverse, E_match, unknowns). Unknowns are (Delta, Delta~, Omega~), or
    (Delta, Delta~, u) with Omega~ = u Omega in the rescaled reading.
    """
    ex = as_exponents(alpha, gamma)
    _check_gamma_forward(ex)
    N, K = reading.omega_orders, reading.match_order
    wf = _weight(reading)
    if reading.delta == "printed":
        delta, delta_t = lowest_order_deltas(ex, None)
        e_f, e_i = D - delta, DT - delta_t
    else:
        jd = 1 if reading.delta == "linear" else 2
        e_f = sp.Add(*[wf(n) * W ** n * _taylor(a_sym, n, D, jd, shift=1) for n in range(N + 1)])
        e_i = sp.Add(*[wf(n) * WT ** n * _taylor(b_sym, n, DT, jd, shift=1) for n in range(N + 1)])
    x_f = sp.Add(*[wf(n) * W ** n * _taylor(a_sym, n, D, K) for n in range(N + 1)])
    x_i = sp.Add(*[wf(n) * WT ** n * _taylor(b_sym, n, DT, K) for n in range(N + 1)])
    if reading.rescale:
        k = ex.alpha - 1 - 2 * ex.gamma
        if k == 0:
            raise ParameterError("rescale", True,
                                 "is undefined when alpha - 1 - 2 gamma = 0 (Omega~ = Omega: the "
                                 "connection does not determine eps)")
        r = sp.Rational(1, 1) / sp.Rational(k.numerator, k.denominator)
        e_m = x_f - U ** r * x_i  # s = (Omega~/Omega)^(1/(alpha-1-2gamma)) = u^r
        subs = {WT: U * W}
        return e_f, e_i.subs(subs), e_m.subs(subs), (D, DT, U)
    return e_f, e_i, x_f - x_i, (D, DT, WT)


# ----------------------------------------------------------------------------------- the solution
@dataclass(frozen=True)
class ConnectionCoefficients:
    """c0, c1, c2 of Omega~ = c0 + c1 Omega + c2 Omega^2 from one reading of the paper's procedure.

    ``defined`` is False (and c's NaN) when the reading has no solution analytic in Omega; ``reason``
    says why. ``c0_roots``: every root of the Omega^0 equation in (0, C0_SEARCH_MAX] (the smallest is
    used). ``delta`` = (Delta_0, Delta_1, Delta_2): Delta = Delta_0 + Delta_1 Omega + Delta_2 Omega^2;
    ``delta_tilde`` likewise as a function of Omega through Omega~(Omega).
    """

    c0: float
    c1: float
    c2: float
    reading: Reading
    defined: bool = True
    reason: str = ""
    tau0: float = math.nan
    tau0_tilde: float = math.nan
    c0_roots: tuple = ()
    delta: tuple = (math.nan, math.nan, math.nan)
    delta_tilde: tuple = (math.nan, math.nan, math.nan)
    truncation_change: float = 0.0
    values: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def c(self) -> tuple[float, float, float]:
        return (self.c0, self.c1, self.c2)

    def as_dict(self) -> dict:
        return {"reading": self.reading.label, "description": self.reading.describe(),
                "c0": self.c0, "c1": self.c1, "c2": self.c2, "defined": self.defined,
                "reason": self.reason, "tau0": self.tau0, "tau0_tilde": self.tau0_tilde,
                "c0_roots": list(self.c0_roots), "delta": list(self.delta),
                "delta_tilde": list(self.delta_tilde), "truncation_change": self.truncation_change}


def _undefined(reading, reason, **kw) -> ConnectionCoefficients:
    return ConnectionCoefficients(math.nan, math.nan, math.nan, reading, False, reason, **kw)


def _roots_1d(fun, lo: float, hi: float, n: int = 4000) -> list[float]:
    """Sign changes of fun on a geometric grid of (lo, hi], refined by bisection (float)."""
    grid = np.geomspace(lo, hi, n)
    vals = np.array([fun(float(x)) for x in grid], dtype=float)
    typical = float(np.nanmedian(np.abs(vals))) if np.any(np.isfinite(vals)) else 1.0
    roots = []
    for i in range(n - 1):
        f0, f1 = vals[i], vals[i + 1]
        if not (np.isfinite(f0) and np.isfinite(f1)):
            continue
        if f0 == 0.0:
            roots.append(float(grid[i]))
        elif f0 * f1 < 0:
            a, b = grid[i], grid[i + 1]
            for _ in range(200):
                m = 0.5 * (a + b)
                fm = fun(float(m))
                if not np.isfinite(fm):
                    break
                if fm * f0 > 0:
                    a, f0 = m, fm
                else:
                    b = m
                if b - a <= 4e-16 * b:
                    break
            r = float(0.5 * (a + b))
            # a sign change across a pole (Delta~ = P/Q with Q = 0) is not a root
            fr = fun(r)
            if np.isfinite(fr) and abs(fr) <= 1e-6 * max(1.0, typical):
                roots.append(r)
    return roots


def _solve_delta(expr, var, guess):
    """Real root of expr (linear or quadratic in var) nearest ``guess``.

    None when there is no real root or the root is double (then the root moves like the square
    root of a perturbation and has no expansion in powers of Omega).
    """
    coeffs = [float(c) for c in sp.Poly(sp.expand(expr), var).all_coeffs()]
    if len(coeffs) == 2:
        return sp.Float(-coeffs[1] / coeffs[0], 30) if coeffs[0] else None
    if len(coeffs) != 3 or coeffs[0] == 0:
        raise ValueError(f"expected a linear or quadratic condition, got degree {len(coeffs) - 1}")
    A, B, C = coeffs
    disc = B * B - 4 * A * C
    if disc <= 1e-12 * max(B * B, abs(4 * A * C)):
        return None
    roots = [(-B + sg * math.sqrt(disc)) / (2 * A) for sg in (1, -1)]
    return sp.Float(min(roots, key=lambda r: abs(r - guess)), 30)


def paper_procedure(alpha, gamma, reading: Reading | None = None, *, digits: int = 30) -> ConnectionCoefficients:
    """c0, c1, c2 from the paper's connection procedure under ``reading`` (cached; see _paper_procedure)."""
    return _paper_procedure(as_exponents(alpha, gamma), reading or Reading(), int(digits))


@lru_cache(maxsize=256)
def _paper_procedure(ex: Exponents, reading: Reading, digits: int) -> ConnectionCoefficients:
    """c0, c1, c2 from the paper's connection procedure under ``reading``.

    Order Omega^0: Delta_0 from the forward condition, Delta~ as a function of c0 from the inverse
    one, and the matching condition becomes one nonlinear equation in c0, whose roots in
    (0, C0_SEARCH_MAX] are all located (the smallest is taken and all are reported). In the
    rescaled reading Omega~ = u Omega, so c0 = 0 and u_0 solves the Omega^0 equation.
    Orders Omega^1, Omega^2: the Omega-derivatives of the three conditions at Omega = 0 are linear in
    the next coefficients (the Jacobian of the system), which gives c1, c2 and the Delta's.
    """
    vals = reference_derivatives(ex, None, reading, digits=digits)
    subs = {**vals.a, **vals.b}
    e_f, e_i, e_m, (y1, y2, y3) = symbolic_system(ex, None, reading)
    e_f, e_i, e_m = (sp.expand(e.subs(subs)) for e in (e_f, e_i, e_m))
    common = dict(tau0=float(sp.N(vals.tau0, 20)), tau0_tilde=float(sp.N(vals.tau0_tilde, 20)),
                  truncation_change=vals.truncation_change,
                  values={str(k): float(v) for k, v in subs.items()})

    # ---- Omega^0
    f0 = e_f.subs(W, 0)
    guess_f = float(sp.solve(_taylor(a_sym, 0, D, 1, shift=1).subs(subs), D)[0])
    d0 = _solve_delta(f0, D, guess_f)
    if d0 is None:
        return _undefined(reading, "the forward condition x'(tau_0 + Delta) = 0 has no simple real root "
                          "at Omega = 0 (Delta is not a power series in Omega)", **common)
    wf = _weight(reading)
    lin_i = lambda wt: sp.solve(sp.Add(*[wf(n) * wt ** n * _taylor(b_sym, n, DT, 1, shift=1)  # noqa: E731
                                         for n in range(reading.omega_orders + 1)]).subs(subs), DT)[0]
    if reading.rescale:
        i0 = e_i.subs(W, 0)
        dt0 = _solve_delta(i0, DT, float(lin_i(0)))
        if dt0 is None:
            return _undefined(reading, "the inverse condition has no simple real root at Omega~ = 0",
                              **common)
        m0 = e_m.subs({W: 0, D: d0, DT: dt0})
        roots = _roots_1d(sp.lambdify(U, m0, "math"), 1e-8, C0_SEARCH_MAX)
        if not roots:
            return _undefined(reading, "the Omega^0 matching equation has no root u_0 = Omega~/Omega > 0",
                              **common)
        y0 = {D: d0, DT: dt0, U: sp.Float(roots[0], digits)}
    else:
        dt_of_c = _delta_tilde_function(e_i, reading, lin_i)
        m_of_c = sp.lambdify((DT, WT), e_m.subs({W: 0, D: d0}), "math")

        def h(c):
            dt = dt_of_c(c)
            return math.nan if dt is None else m_of_c(dt, c)

        roots = _roots_1d(h, 1e-6, C0_SEARCH_MAX)
        if not roots:
            return _undefined(reading, f"the Omega^0 matching equation has no root c0 in (0, {C0_SEARCH_MAX:g}]",
                              **common)
        c0 = roots[0]  # bisection to ~1e-16 relative: far below the digits reported
        y0 = {D: d0, DT: sp.Float(dt_of_c(c0), digits), WT: sp.Float(c0, digits)}

    # ---- Omega^1 and Omega^2 by implicit differentiation
    ys = (y1, y2, y3)
    k1 = sp.symbols("k1_0:3")
    k2 = sp.symbols("k2_0:3")
    path = {y: y0[y] + k1[i] * W + k2[i] * W ** 2 for i, y in enumerate(ys)}
    eqs = [sp.expand(e.subs(path)) if not reading.rescale else e.subs(path) for e in (e_f, e_i, e_m)]
    first = [sp.diff(e, W).subs(W, 0) for e in eqs]
    jac = sp.Matrix([[sp.diff(e, k) for k in k1] for e in first])
    det = float(jac.det())
    scale = float(max(abs(x) for x in jac))
    if abs(det) < 1e-10 * scale ** 3:
        return _undefined(reading, "the Jacobian of the conditions is singular at Omega = 0", **common,
                          c0_roots=tuple(roots))
    s1 = sp.solve(first, k1, dict=True)[0]
    second = [(sp.diff(e, W, 2).subs(W, 0) / 2).subs(s1) for e in eqs]
    s2 = sp.solve(second, k2, dict=True)[0]
    dlt = (float(y0[D]), float(s1[k1[0]]), float(s2[k2[0]]))
    dlt_t = (float(y0[DT]), float(s1[k1[1]]), float(s2[k2[1]]))
    if reading.rescale:
        c = (0.0, float(y0[U]), float(s1[k1[2]]))
    else:
        c = (float(y0[WT]), float(s1[k1[2]]), float(s2[k2[2]]))
    return ConnectionCoefficients(*c, reading, True, "", c0_roots=tuple(roots), delta=dlt,
                                  delta_tilde=dlt_t, **common)


def _delta_tilde_function(e_i, reading: Reading, lin_i):
    """Delta~ at Omega = 0 as a float function of c0 (None where the reading has no real root)."""
    if reading.delta == "printed":
        f = sp.lambdify(WT, sp.solve(e_i.subs(W, 0), DT)[0], "math")
        return lambda c: f(c)
    if reading.delta == "linear":
        f = sp.lambdify(WT, sp.solve(e_i.subs(W, 0), DT)[0], "math")

        def lin(c):
            try:
                return f(c)
            except ZeroDivisionError:
                return None
        return lin
    # quadratic: A Dt^2 + B Dt + C = 0, root nearest the linear one
    poly = sp.Poly(sp.expand(e_i.subs(W, 0)), DT)
    coeffs = [sp.lambdify(WT, co, "math") for co in poly.all_coeffs()]
    lin_num, lin_den = sp.fraction(sp.together(lin_i(WT)))
    lin_num, lin_den = sp.lambdify(WT, lin_num, "math"), sp.lambdify(WT, lin_den, "math")

    def quad(c):
        A, B, C = (f(c) for f in coeffs)
        disc = B * B - 4 * A * C
        if disc < 0 or A == 0:
            return None
        r = [(-B + s * math.sqrt(disc)) / (2 * A) for s in (1, -1)]
        den = lin_den(c)
        if den == 0:
            return None
        return min(r, key=lambda x: abs(x - lin_num(c) / den))
    return quad


# ----------------------------------------------------------------------------- exact connection
def exact_omega_tilde(alpha, gamma, omegas, *, rtol: float = 1e-12) -> dict:
    """The true connection from the reference integrator.

    Omega~ = Omega eps^((alpha-1-2gamma)/(gamma+1)) (the rebound speed g~ = eps g put into the
    definition of Omega). Also returns eps, x_c and x~_c = x_c eps^(-1/(gamma+1)), the start of the
    inverse collision in its own variables.
    """
    from .collision import collide_many

    ex = as_exponents(alpha, gamma)
    omegas = np.asarray(omegas, dtype=float)
    res = collide_many(ex, None, omegas, rtol=rtol)
    k = float(ex.omega_exponent)
    eps = res["eps"]
    return {"omega": omegas, "omega_tilde": omegas * eps ** k, "eps": eps, "x_c": res["x_c"],
            "x_tilde_c": res["x_c"] * eps ** (-1.0 / float(ex.gamma + 1)), "tau_b": res["tau_b"],
            "x_b": res["x_b"], "tau_c": res["tau_c"], "end": res["end"]}


@dataclass(frozen=True)
class FitResult:
    """Least-squares fit Omega~ ~ c0 + c1 Omega + c2 Omega^2 to the exact connection.

    The residuals are model error (a quadratic cannot follow Omega~(Omega) exactly), not noise;
    ``stderr`` is the usual OLS estimate sqrt(diag(s^2 (X^T X)^-1)), s^2 = RSS/(n - 3), and says how
    strongly the coefficients depend on that misfit, not a statistical uncertainty.
    ``max_abs_residual`` bounds |Omega~_exact - fit| over the sampled Omegas.
    """

    c: tuple
    covariance: np.ndarray
    stderr: tuple
    omega: np.ndarray
    omega_tilde: np.ndarray
    residuals: np.ndarray
    max_abs_residual: float
    rms: float
    max_rel_residual: float

    def as_dict(self) -> dict:
        return {"c": list(self.c), "stderr": list(self.stderr),
                "omega_min": float(self.omega.min()), "omega_max": float(self.omega.max()),
                "n": int(self.omega.size), "max_abs_residual": self.max_abs_residual, "rms": self.rms,
                "max_rel_residual": self.max_rel_residual}


def fit_quadratic(omegas, omega_tilde) -> FitResult:
    """OLS fit of omega_tilde on [1, Omega, Omega^2] (see FitResult)."""
    x = np.asarray(omegas, float)
    y = np.asarray(omega_tilde, float)
    if x.size < 4:
        raise ParameterError("omegas", x.size, "need at least 4 points for a 3-parameter fit")
    X = np.vander(x, 3, increasing=True)
    c, *_ = np.linalg.lstsq(X, y, rcond=None)
    resid = y - X @ c
    s2 = float(resid @ resid) / (x.size - 3)
    cov = s2 * np.linalg.inv(X.T @ X)
    return FitResult(tuple(float(v) for v in c), cov, tuple(float(v) for v in np.sqrt(np.diag(cov))),
                     x, y, resid, float(np.max(np.abs(resid))), float(np.sqrt(np.mean(resid ** 2))),
                     float(np.max(np.abs(resid / y))))


def fit_connection(alpha, gamma, omegas, *, rtol: float = 1e-12) -> FitResult:
    """Fit c0-c2 to the exact Omega~(Omega) at the given Omegas (>= 4 of them)."""
    exact = exact_omega_tilde(alpha, gamma, omegas, rtol=rtol)
    return fit_quadratic(exact["omega"], exact["omega_tilde"])


def omega_tilde_from_c(omega, c) -> np.ndarray:
    """c0 + c1 Omega + c2 Omega^2 (+ ...) for a sequence of coefficients c."""
    omega = np.asarray(omega, float)
    return sum(float(ci) * omega ** i for i, ci in enumerate(c))


def eps_from_connection(alpha, gamma, omega, c):
    """eps = (Omega~/Omega)^((gamma+1)/(alpha-1-2gamma)) with Omega~ = c0 + c1 Omega + c2 Omega^2.

    Undefined (ParameterError) when alpha - 1 - 2 gamma = 0: then Omega~ = Omega whatever eps is.
    NaN where Omega~ <= 0 (no real eps). Values above 1 are returned as computed: they are
    unphysical (the rebound would be faster than the impact: energy gained from a dissipative
    force) and flag where the relation fails. With k = alpha - 1 - 2gamma, eps > 1 exactly where
    Omega~ < Omega for k < 0 (the paper's case, k = -1/2) and where Omega~ > Omega for k > 0;
    :func:`connection_validity` gives those Omega intervals for a set of c's.
    """
    ex = as_exponents(alpha, gamma)
    k = ex.omega_exponent
    if k == 0:
        raise ParameterError("alpha, gamma", f"{ex.alpha}, {ex.gamma}",
                             "eps from the connection needs alpha - 1 - 2 gamma != 0 (otherwise "
                             "Omega~ = Omega for every eps)")
    omega = np.asarray(omega, float)
    wt = omega_tilde_from_c(omega, c)
    with np.errstate(invalid="ignore", divide="ignore"):
        out = np.where((wt > 0) & (omega > 0), (wt / omega) ** (1.0 / float(k)), np.nan)
    return float(out) if out.ndim == 0 else out


def connection_validity(alpha, gamma, c) -> dict:
    """Omega > 0 intervals where Omega~ = sum c_i Omega^i gives no eps (Omega~ <= 0) or eps > 1.

    Returns {"omega_tilde_nonpositive": [(lo, hi), ...], "eps_above_one": [(lo, hi), ...]}, from the
    real positive roots of the polynomials (hi = inf for an unbounded interval).
    """
    ex = as_exponents(alpha, gamma)
    k = ex.omega_exponent
    if k == 0:
        raise ParameterError("alpha, gamma", f"{ex.alpha}, {ex.gamma}",
                             "needs alpha - 1 - 2 gamma != 0")
    c = [float(v) for v in c]

    def intervals(poly, bad):
        roots = sorted(r.real for r in np.roots(poly[::-1]) if abs(r.imag) < 1e-12 and r.real > 0) \
            if any(poly[1:]) else []
        edges = [0.0] + roots + [math.inf]
        out = []
        for lo, hi in zip(edges[:-1], edges[1:]):
            mid = 0.5 * (lo + hi) if math.isfinite(hi) else lo + 1.0
            if bad(sum(ci * mid ** i for i, ci in enumerate(poly))):
                out.append((lo, hi))
        return out

    nonpos = intervals(c, lambda v: v <= 0)
    minus = list(c) + [0.0] * max(0, 2 - len(c))
    minus[1] -= 1.0  # Omega~ - Omega
    above = intervals(minus, (lambda v: v < 0) if k < 0 else (lambda v: v > 0))
    # eps > 1 only counts where eps exists: subtract the Omega~ <= 0 intervals
    for a, b in nonpos:
        pieces = []
        for lo, hi in above:
            if hi <= a or lo >= b:
                pieces.append((lo, hi))
                continue
            if lo < a:
                pieces.append((lo, a))
            if hi > b:
                pieces.append((b, hi))
        above = pieces
    as_float = lambda iv: [(float(lo), float(hi)) for lo, hi in iv]  # noqa: E731
    return {"omega_tilde_nonpositive": as_float(nonpos), "eps_above_one": as_float(above)}


# ------------------------------------------------------------------------------------------ retrace
@dataclass(frozen=True)
class RetraceResult:
    """The inverse collision from the forward end state, mapped back onto the forward one.

    ``max_deviation`` = max |x_retraced - x_forward| / x_b over ``tau`` (forward variables);
    ``v_end_error`` = |eps x~'(end) + 1|: the inverse run must arrive with x' = 1 in forward variables;
    ``tau_error`` = |tau_c - s^-gamma tau~_end|: and at forward time 0.
    """

    omega: float
    omega_tilde: float
    eps: float
    x_tilde_start: float
    tau: np.ndarray
    x_forward: np.ndarray
    x_retraced: np.ndarray
    max_deviation: float
    v_end_error: float
    tau_error: float


def retrace(alpha, gamma, omega, *, rtol: float = 1e-12, samples: int = 201) -> RetraceResult:
    """Integrate the inverse collision from the forward end state and compare trajectories.

    Change of variables (derived from the physical scaling xi = A x, t = B tau with
    A = (g/D2)^(1/(gamma+1)), B = (D2 g^gamma)^(-1/(gamma+1)) and the inverse collision scaled with
    the rebound speed g~ = eps g): A~/A = eps^(1/(gamma+1)) =: s, B~/B = eps^(-gamma/(gamma+1)) = s^-gamma,
    and the inverse time runs backwards from t_c. Hence

        x = s x~,   tau = tau_c - s^(-gamma) tau~,   dx/dtau = -eps dx~/dtau~,

    and x'' + Omega x^alpha + x^gamma x' = 0 becomes x~'' + Omega s^(alpha-1-2gamma) x~^alpha - x~^gamma x~' = 0:
    Omega~ = Omega eps^((alpha-1-2gamma)/(gamma+1)), x~(0) = x_c / s, x~'(0) = 1.
    """
    from .collision import collide, inverse_collide

    ex = as_exponents(alpha, gamma)
    omega = require_positive_finite("omega", omega)
    fwd = collide(ex, None, omega, rtol=rtol)
    gp1 = float(ex.gamma + 1)
    s = fwd.eps ** (1.0 / gp1)
    omega_t = omega * fwd.eps ** float(ex.omega_exponent)
    x_start = fwd.x_c / s
    # common samples strictly inside the contact, forward time
    tau = np.linspace(0.0, fwd.tau_c, samples)
    tau_t = (fwd.tau_c - tau) * s ** float(ex.gamma)  # decreasing in tau
    order = np.argsort(tau_t)
    inv = inverse_collide(ex, None, omega_t, x_start, rtol=rtol, t_eval=tau_t[order])
    fwd_traj = collide(ex, None, omega, rtol=rtol, t_eval=tau).trajectory
    x_fwd = np.full(tau.shape, np.nan)
    x_fwd[: fwd_traj.x.size] = fwd_traj.x
    x_ret = np.full(tau.shape, np.nan)
    n = inv.trajectory.x.size
    x_ret[order[:n]] = s * inv.trajectory.x
    # a sample at either end may fall a rounding error beyond the end of a run: compare the rest
    ok = np.isfinite(x_ret) & np.isfinite(x_fwd)
    dev = np.abs(x_ret[ok] - x_fwd[ok]) / fwd.x_b
    return RetraceResult(omega, omega_t, fwd.eps, x_start, tau[ok], x_fwd[ok], x_ret[ok],
                         float(dev.max()), abs(fwd.eps * inv.v_end + 1.0),
                         abs(fwd.tau_c - s ** (-float(ex.gamma)) * inv.tau_end))

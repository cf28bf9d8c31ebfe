"""The paper's matching procedure: the equations for c0-c2 and their solution.

With Delta = tau_b - tau_0 and Delta~ = tau~_b - tau~_0 (reference points from
:mod:`restitution.audit.reference_points`) the three conditions are

    x'(tau_0 + Delta) = 0,   x~'(tau~_0 + Delta~) = 0,   x(tau_0 + Delta) = s x~(tau~_0 + Delta~),

each Taylor-expanded about the reference point, with s = 1 as the paper writes it (or the scale
change s = eps^(1/(gamma+1)) between forward and inverse variables). Substituting
Omega~ = c0 + c1 Omega + c2 Omega^2 (and Delta, Delta~ as power series in Omega) and comparing
powers of Omega gives a nonlinear equation for c0 and linear ones for c1, c2 ("comparing term by
term"). The exact connection these c's approximate is :mod:`restitution.core.connection`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np
import sympy as sp

from ..core.errors import ParameterError
from ..core.exponents import Exponents, as_exponents
from .readings import Reading
from .reference_points import (DT, D, U, W, WT, a_sym, b_sym, check_gamma_forward, damped_derivatives,
                               reference_derivatives)

__all__ = ["ConnectionCoefficients", "lowest_order_deltas", "printed_deltas", "symbolic_system",
           "paper_procedure", "reading_row"]

#: c0 is searched in (0, C0_SEARCH_MAX]; every real root found there is reported.
C0_SEARCH_MAX = 200.0


# ------------------------------------------------------------------------------------ the equations
def lowest_order_deltas(problem) -> tuple[sp.Expr, sp.Expr]:
    """Delta(Omega), Delta~(Omega~) re-derived: x'(tau_0 + Delta) = 0 to first order in Delta and Omega.

    x0'(tau_0) + x0''(tau_0) Delta + Omega x1'(tau_0) = 0 with x0', x0'' at x0 = 1 from the first
    integral. Returned in terms of the symbols a_11 = x1'(tau_0) and b_11 = x~1'(tau~_0).
    """
    ex = as_exponents(problem)
    check_gamma_forward(ex)
    f = damped_derivatives(ex.gamma, +1, 0, 2)
    i = damped_derivatives(ex.gamma, -1, 0, 2)
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


def symbolic_system(problem, reading: Reading):
    """The three conditions of the reading as sympy expressions (each = 0), in a_nj, b_nj symbols.

    Returns (E_forward, E_inverse, E_match, unknowns). Unknowns are (Delta, Delta~, Omega~), or
    (Delta, Delta~, u) with Omega~ = u Omega in the rescaled reading.
    """
    ex = as_exponents(problem)
    check_gamma_forward(ex)
    N, K = reading.omega_orders, reading.match_order
    wf = _weight(reading)
    if reading.delta == "printed":
        delta, delta_t = lowest_order_deltas(ex)
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


def reading_row(problem, reading: Reading) -> dict:
    """The procedure under one reading as a JSON-ready row with ``c``; where the procedure itself
    does not exist for these exponents (ParameterError), a row that says why."""
    try:
        cc = paper_procedure(problem, reading)
    except ParameterError as err:
        return {"reading": reading.label, "description": reading.describe(), "defined": False,
                "reason": str(err), "c": [math.nan] * 3}
    return {**cc.as_dict(), "c": [cc.c0, cc.c1, cc.c2]}


def paper_procedure(problem, reading: Reading | None = None, *, digits: int = 30) -> ConnectionCoefficients:
    """c0, c1, c2 from the paper's connection procedure under ``reading`` (cached; see _paper_procedure)."""
    return _paper_procedure(as_exponents(problem), reading or Reading(), int(digits))


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
    vals = reference_derivatives(ex, reading, digits=digits)
    subs = {**vals.a, **vals.b}
    e_f, e_i, e_m, (y1, y2, y3) = symbolic_system(ex, reading)
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

"""Exact perturbation series of the scaled collision equation.

    x'' + Omega x^alpha + s x^gamma x' = 0,   x(0) = 0, x'(0) = 1,

with s = +1 for the forward collision and s = -1 for the inverse one (time run
backwards, which flips the sign of the dissipative force). We expand

    x(tau; Omega) = sum_n Omega^n x_n(tau),   x_n(tau) = sum_k C[n][k] tau^(k/p),

where p is the common denominator of alpha and gamma. Both expansions are solved
at once: every coefficient of t^k (t = tau^(1/p)) is a polynomial in Omega
truncated at the requested order, and the equation fixes the t^(k+2p) coefficient
from lower ones (a Frobenius-type recurrence). Powers x^alpha = tau^alpha y^alpha
with y = x/tau = 1 + O(t) are formed by the J.C.P. Miller recurrence, which needs
only rational arithmetic, so every coefficient is an exact Fraction.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache

import numpy as np

from .damped import forward as damped_only_forward  # noqa: F401 - closed forms live beside the series
from .damped import inverse as damped_only_inverse  # noqa: F401
from .errors import ParameterError, integer_in
from .exponents import Exponents, as_exponents, read_through

DIRECTIONS = {"forward": 1, "inverse": -1}
#: Highest index k of tau^(k/p) the engine computes (the time grows as its square).
MAX_INDEX = 400

# Truncated polynomials in Omega: tuples of Fractions, index = power of Omega.
_Poly = list


def _poly_mul_acc(acc: _Poly, a: _Poly, b: _Poly, scale: Fraction, order: int) -> None:
    """acc += scale * a * b, truncated at Omega^order; skips zero coefficients."""
    for i, ai in enumerate(a):
        if not ai:
            continue
        ai = ai * scale
        for j in range(order + 1 - i):
            bj = b[j]
            if bj:
                acc[i + j] += ai * bj


def _power_series_power(y: list[_Poly], exponent: Fraction, k: int, w: list[_Poly],
                        order: int) -> None:
    """Append w_k for w = y^exponent, where y_0 = 1 (Miller's recurrence):

    w_k = (1/k) sum_{j=1..k} ((exponent + 1) j - k) y_j w_{k-j}.
    """
    acc = [Fraction(0)] * (order + 1)
    for j in range(1, k + 1):
        c = (exponent + 1) * j - k
        if c:
            _poly_mul_acc(acc, y[j], w[k - j], c, order)
    w.append([a / k for a in acc])


@lru_cache(maxsize=64)
def _coefficients(alpha: Fraction, gamma: Fraction, sign: int, omega_order: int,
                  max_index: int) -> tuple[tuple[Fraction, ...], ...]:
    """C[n][k] for n <= omega_order and k <= max_index (powers tau^(k/p)), kept for reuse."""
    return _derive(alpha, gamma, sign, omega_order, max_index)


def _derive(alpha: Fraction, gamma: Fraction, sign: int, omega_order: int, max_index: int,
            progress=None) -> tuple[tuple[Fraction, ...], ...]:
    """C[n][k] for n <= omega_order and k <= max_index; ``progress(k, total)`` after each power."""
    p = math.lcm(alpha.denominator, gamma.denominator)
    qa, qg = int(alpha * p), int(gamma * p)
    N = omega_order
    zero = lambda: [Fraction(0)] * (N + 1)  # noqa: E731 - a tiny local factory

    C: list[_Poly] = [zero() for _ in range(max_index + 1)]
    if p <= max_index:
        C[p][0] = Fraction(1)  # x = tau + ...
    y: list[_Poly] = []  # y_j = C[j + p]: coefficients of x / tau
    w_alpha: list[_Poly] = []  # (x/tau)^alpha
    w_gamma: list[_Poly] = []  # (x/tau)^gamma

    def y_at(j: int) -> _Poly:
        while len(y) <= j:
            idx = len(y) + p
            y.append(C[idx] if idx <= max_index else zero())
        return y[j]

    def extend(w: list[_Poly], exponent: Fraction, k: int) -> None:
        while len(w) <= k:
            m = len(w)
            if m == 0:
                w.append([Fraction(1)] + [Fraction(0)] * N)
            else:
                y_at(m)
                _power_series_power(y, exponent, m, w, N)

    for k in range(0, max_index - 2 * p + 1):
        rhs = zero()
        # Omega * x^alpha at t^k: x^alpha = t^qa (x/tau)^alpha.
        if k >= qa and N >= 1:
            extend(w_alpha, alpha, k - qa)
            src = w_alpha[k - qa]
            for n in range(N):
                rhs[n + 1] -= src[n]
        # s * x^gamma x' at t^k: x' has t^m coefficient C[m+p] (m+p)/p.
        if k >= qg:
            m_max = k - qg
            extend(w_gamma, gamma, m_max)
            acc = zero()
            for i in range(m_max + 1):
                m = m_max - i
                d_idx = m + p
                _poly_mul_acc(acc, w_gamma[i], C[d_idx], Fraction(d_idx, p), N)
            for n in range(N + 1):
                rhs[n] -= sign * acc[n]
        # x'' at t^k comes from C[k+2p] (k+2p)(k+p)/p^2.
        target = k + 2 * p
        factor = Fraction(p * p, target * (k + p))
        # y and the power series only ever read C below index k + 2p, so the
        # views taken so far stay valid when C[target] is filled in.
        C[target] = [r * factor for r in rhs]
        if progress is not None:
            progress(k + 1, max_index - 2 * p + 1)

    return tuple(tuple(C[k][n] for k in range(max_index + 1)) for n in range(N + 1))


def falling_factorial(x: Fraction, j: int) -> Fraction:
    """x (x-1) ... (x-j+1): the factor d^j/dtau^j brings down from tau^x."""
    out = Fraction(1)
    for i in range(j):
        out *= x - i
    return out


def _as_power(field: str, value) -> Fraction:
    try:
        f = Fraction(str(value)) if not isinstance(value, Fraction) else value
    except (ValueError, ZeroDivisionError):
        raise ParameterError(field, value, "must be a rational number >= 1") from None
    if f < 1:
        raise ParameterError(field, value, "must be a rational number >= 1")
    return f


@dataclass(frozen=True)
class PerturbationSeries:
    """x(tau; Omega) = sum_n Omega^n x_n(tau) with exact rational coefficients."""

    exponents: Exponents
    direction: str
    omega_order: int
    max_power: Fraction
    _coeffs: tuple[tuple[Fraction, ...], ...]

    alpha = read_through("exponents", "alpha")
    gamma = read_through("exponents", "gamma")
    p = read_through("exponents", "p")

    def terms(self, n: int) -> list[tuple[Fraction, Fraction]]:
        """Nonzero (power of tau, coefficient) of x_n, ascending power."""
        return [(Fraction(k, self.p), c) for k, c in enumerate(self._coeffs[n]) if c]

    def as_dict(self) -> dict:
        """JSON-ready form with exact rationals as strings."""
        return {
            "alpha": str(self.alpha),
            "gamma": str(self.gamma),
            "direction": self.direction,
            "p": self.p,
            "orders": {
                str(n): [[str(pw), str(c)] for pw, c in self.terms(n)]
                for n in range(self.omega_order + 1)
            },
        }

    def order_values(self, tau, n: int, derivative: int = 0) -> np.ndarray:
        """x_n^(derivative)(tau) in floating point, tau >= 0."""
        tau = np.asarray(tau, dtype=float)
        out = np.zeros_like(tau)
        for pw, c in self.terms(n):
            fall = float(falling_factorial(pw, derivative))
            if fall == 0.0:
                continue
            e = float(pw) - derivative
            with np.errstate(divide="ignore", invalid="ignore"):
                term = np.where(tau > 0, tau ** e, 0.0 if e > 0 else (1.0 if e == 0 else np.inf))
            out = out + float(c) * fall * term
        return out

    def evaluate(self, tau, omega, order: int | None = None, derivative: int = 0) -> np.ndarray:
        """sum_{n <= order} Omega^n x_n^(derivative)(tau)."""
        order = self.omega_order if order is None else order
        if not 0 <= order <= self.omega_order:
            raise ParameterError("order", order, f"must be an integer in [0, {self.omega_order}]")
        total = 0.0
        for n in range(order + 1):
            total = total + float(omega) ** n * self.order_values(tau, n, derivative)
        return np.asarray(total, dtype=float)

    def to_sympy(self, n: int, tau=None):
        """x_n as a sympy expression in tau with exact rational coefficients."""
        import sympy as sp

        tau = sp.Symbol("tau", positive=True) if tau is None else tau
        return sp.Add(*[sp.Rational(c.numerator, c.denominator)
                        * tau ** sp.Rational(pw.numerator, pw.denominator)
                        for pw, c in self.terms(n)])

    def latex(self, n: int, symbol: str = r"\tau") -> str:
        """x_n as LaTeX with \\frac coefficients, ascending powers."""
        parts = []
        for pw, c in self.terms(n):
            sign = "-" if c < 0 else "+"
            a = abs(c)
            coef = "" if a == 1 else (f"{a.numerator}" if a.denominator == 1
                                      else rf"\frac{{{a.numerator}}}{{{a.denominator}}}")
            power = "" if pw == 1 else (f"^{{{pw.numerator}}}" if pw.denominator == 1
                                        else rf"^{{{pw.numerator}/{pw.denominator}}}")
            parts.append(f"{sign} {coef}{symbol}{power}")
        if not parts:
            return "0"
        text = " ".join(parts)
        return text[2:] if text.startswith("+ ") else "-" + text[2:]


def perturbation_series(alpha, gamma, omega_order: int = 4, max_power=11,
                        direction: str = "forward", progress=None) -> PerturbationSeries:
    """Exact series of the forward or inverse collision up to Omega^omega_order and tau^max_power.

    x(tau; Omega) = sum_n Omega^n x_n(tau), each x_n a finite sum of rational coefficients times
    powers tau^(k/p) (p the exponents' common denominator), derived in exact arithmetic.

    Parameters
    ----------
    alpha, gamma : str, int, Fraction or float
        The exponents (:meth:`Exponents.parse`).
    omega_order : int, optional
        Highest power of Omega kept (0-64).
    max_power : int, str or Fraction, optional
        Highest power of tau kept in each x_n (a rational such as ``"11"`` or ``"21/2"``).
    direction : {"forward", "inverse"}, optional
        The collision from first contact, or the inverse one (time run backwards from the end of
        contact, x~'' + Omega~ x~^alpha - x~^gamma x~' = 0).
    progress : callable, optional
        ``progress(done, total)``, called after each power of tau is derived (then the result is
        not kept for reuse). The cost grows about as the third to fourth power of ``max_power``
        and linearly in ``omega_order``.

    Returns
    -------
    PerturbationSeries
        ``.terms(n)``: the (power of tau, coefficient) pairs of x_n, both Fractions;
        ``.evaluate(tau, omega, order=...)``: the partial sum in floating point.

    Raises
    ------
    ParameterError
        For an unknown direction, an order outside 0-64 or a ``max_power`` beyond the engine's
        limit for these exponents.

    See Also
    --------
    restitution.core.series.PerturbationSeries : What it returns, and its methods.
    restitution.collide : The numerical collision the series approximates.

    Examples
    --------
    >>> from restitution import perturbation_series
    >>> ps = perturbation_series("3/2", 1, omega_order=2, max_power=5)
    >>> ps.terms(0)[:2]                                  # x0 = tau - tau^3/6 + ...
    [(Fraction(1, 1), Fraction(1, 1)), (Fraction(3, 1), Fraction(-1, 6))]
    >>> ps.terms(1)
    [(Fraction(7, 2), Fraction(-4, 35))]
    """
    return series_for((alpha, gamma), omega_order, max_power, direction, progress)


def series_for(problem, omega_order: int = 4, max_power=11,
               direction: str = "forward", progress=None) -> PerturbationSeries:
    """:func:`perturbation_series` with the exponents as one value: a
    :class:`~restitution.core.problem.Problem`, an Exponents or an (alpha, gamma) pair."""
    ex = as_exponents(problem)
    if direction not in DIRECTIONS:
        raise ParameterError("direction", direction, "must be 'forward' or 'inverse'")
    integer_in("omega_order", omega_order, 0, 64)
    max_power = _as_power("max_power", max_power)
    max_index = math.floor(max_power * ex.p)
    if max_index > MAX_INDEX:
        raise ParameterError("max_power", max_power, f"must be at most {Fraction(MAX_INDEX, ex.p)} for p = {ex.p}")
    args = (ex.alpha, ex.gamma, DIRECTIONS[direction], int(omega_order), max_index)
    coeffs = _coefficients(*args) if progress is None else _derive(*args, progress=progress)
    return PerturbationSeries(ex, direction, int(omega_order), max_power, coeffs)

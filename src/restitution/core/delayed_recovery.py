"""Schwager and Poeschel's half-power series for Hertz contact with viscoelastic damping, re-derived.

T. Schwager and T. Poeschel, Phys. Rev. E 78, 051304 (2008), expand the coefficient of restitution of
viscoelastic spheres (alpha = 3/2, gamma = 1/2: x'' + Omega x^(3/2) + x^(1/2) x' = 0 in our scaling) as

    eps = 1 + sum_k h_k s^k,   s = sqrt(beta) v^(1/10) = Omega^(-3/10) = sqrt(delta),

where delta = Omega^(-3/5) is the variable (3/2) A rho^(2/5) g^(1/5) of Ramirez et al., PRE 60, 4465
(1999) (restitution.core.asymptotics). Contact ends when the total force vanishes, before the
deformation has returned to zero ("delayed recovery", our ``force`` rule); the older series of
Ramirez et al. integrated until the deformation returned to zero (our ``overlap`` rule) and holds
integer powers of delta only. Their text is not available to us; this module derives the h_k by a
perturbation expansion in the damping about the elastic Hertz collision, in two steps.

Step 1, the overlap rule. With x = Omega^(-2/5) y, tau = Omega^(-2/5) t the collision is

    y'' + y^(3/2) + delta y^(1/2) y' = 0,   y(0) = 0,  y'(0) = 1,

and eps_o(delta) = -y'(t_o) at the return y(t_o) = 0 is analytic in the damping delta (delta < 0,
an anti-damping, is as regular as delta > 0). Its Taylor coefficients c_n,
eps_o = sum_n c_n delta^n, are the regular perturbation series about the elastic collision:
c_1 = -C1, c_2 = C2 = (3/5) C1^2 in closed form (asymptotics.elastic_limit); c_3, c_4, ... are
computed here as the Taylor coefficients of a Chebyshev interpolant of eps_o on
delta in [-h, h] (each value an integration written in the variable r = sqrt(y) near y = 0, where
the right-hand side is smooth), their accuracy estimated by a second interpolant of other nodes.

Step 2, the end of contact. On the way out let w(y) = -y' > 0. The equation gives exactly

    dw/dy = delta y^(1/2) - y^(3/2)/w,

so w has its maximum where the force vanishes, y_c = delta w(y_c): eps_f = max w and eps_o = w(0).
With y = delta z, w = u + mu v(z), u = eps_o, mu = delta^(5/2), the problem is
dv/dz = z^(1/2) - z^(3/2)/(u + mu v), v(0) = 0, ended at z_c = u + mu v(z_c). Its first two orders
are v0 = (2/3) z^(3/2) - (2/5) z^(5/2)/u and v1' = z^(3/2) v0/u^2, and as v0'(u) = 0

    eps_f = u + (4/15) u^(3/2) delta^(5/2) + (13/150) u^2 delta^5 + O(delta^(15/2)),   u = eps_o(delta).

Substituting u = sum c_n delta^n gives every h_k: h_(2n) = c_n plus, from k = 10 on, the
(13/150) u^2 term; the odd h_k come from the delayed recovery only, h_1 = h_3 = 0, h_5 = 4/15,
h_7 = -(2/5) C1, h_9 = (4/15)((3/2) c_2 + (3/8) c_1^2), ...; the series is exact through s^14.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from .asymptotics import elastic_limit
from .errors import ParameterError

__all__ = ["SchwagerPoeschelSeries", "overlap_damping_coefficients", "schwager_poeschel_series",
           "end_of_contact_eps", "S_POWER", "INTERPOLANTS", "END_COEFFICIENTS"]

#: s = Omega^(-S_POWER): the expansion variable sqrt(delta), delta = Omega^(-(gamma+1)/(alpha+1)).
S_POWER = Fraction(3, 10)

#: eps_f = u + a u^(3/2) delta^(5/2) + b u^2 delta^5 + O(delta^(15/2)): (a, b), derived in the docstring.
END_COEFFICIENTS = (Fraction(4, 15), Fraction(13, 150))

#: (half_width, nodes) of the two Chebyshev interpolants of eps_o: the first gives the c_n, their
#: difference the c_n's accuracy.
INTERPOLANTS = ((0.2, 24), (0.3, 30))

# The velocity on the way in and out is integrated in r = sqrt(y) for y below R_SWITCH**2, where
# y^(1/2) is not smooth in time; in time elsewhere, where the turning point is.
_R_SWITCH = 0.5
_RTOL = 1e-13


def _rise(delta: float) -> float:
    """Speed w = y' on reaching y = R_SWITCH^2; dw/dr = -2 r^4/w - 2 delta r^2 (r = sqrt(y))."""
    from scipy.integrate import solve_ivp

    sol = solve_ivp(lambda r, w: [-2.0 * r ** 4 / w[0] - 2.0 * delta * r * r], (0.0, _R_SWITCH), [1.0],
                    method="DOP853", rtol=_RTOL, atol=1e-15)
    return float(sol.y[0, -1])


def _middle(delta: float, w_in: float) -> float:
    """Speed -y' on returning to y = R_SWITCH^2, through maximum compression (integrated in time)."""
    from scipy.integrate import solve_ivp

    y_s = _R_SWITCH ** 2

    def back(t, s):
        return s[0] - y_s
    back.terminal, back.direction = True, -1.0

    def rhs(t, s):
        r = math.sqrt(max(s[0], 0.0))
        return [s[1], -s[0] * r - delta * r * s[1]]

    sol = solve_ivp(rhs, (0.0, 50.0), [y_s, w_in], method="DOP853", rtol=_RTOL, atol=1e-15, events=back)
    if not sol.t_events[0].size:
        raise ParameterError("delta", delta, "|delta| small enough for the collision to return (<= 0.4)")
    return float(-sol.y_events[0][0][1])


def _release(delta: float, w_out: float) -> float:
    """eps_o = w(0) on the way out; dw/dr = 2 delta r^2 - 2 r^4/w from r = R_SWITCH down to 0."""
    from scipy.integrate import solve_ivp

    sol = solve_ivp(lambda r, w: [2.0 * delta * r * r - 2.0 * r ** 4 / w[0]], (_R_SWITCH, 0.0), [w_out],
                    method="DOP853", rtol=_RTOL, atol=1e-15)
    return float(sol.y[0, -1])


def _eps_overlap(delta: float) -> float:
    return _release(delta, _middle(delta, _rise(delta)))


def overlap_damping_coefficients(order: int = 7, *, half_width: float = 0.2, nodes: int = 24) -> np.ndarray:
    """Taylor coefficients c_0..c_order of eps_o(delta), the overlap rule's eps in the damping delta.

    Parameters
    ----------
    order : int
        Highest power of delta returned (at most ``nodes - 1``).
    half_width : float
        The interpolant's interval is delta in [-half_width, half_width] (0 < half_width <= 0.4).
    nodes : int
        Number of Chebyshev nodes (each an integration of the collision).

    Returns
    -------
    numpy.ndarray
        c_0, ..., c_order; c_0 = 1, c_1 = -C1 and c_2 = (3/5) C1^2 are reproduced to about 1e-10 and
        1e-9; the error grows by about half_width^-1 per order.

    Raises
    ------
    ParameterError
        If ``order``, ``half_width`` or ``nodes`` is outside the ranges above.

    Examples
    --------
    >>> c = overlap_damping_coefficients(3, nodes=16)
    >>> round(float(c[1]), 8), round(float(c[2]), 7)
    (-1.15344886, 0.7982666)
    """
    if not (0 < half_width <= 0.4):
        raise ParameterError("half_width", half_width, "a number in (0, 0.4]")
    if not (isinstance(order, int) and 0 <= order < nodes):
        raise ParameterError("order", order, "an integer in [0, nodes - 1]")
    k = np.arange(nodes)
    x = np.cos(np.pi * (k + 0.5) / nodes)
    values = np.array([_eps_overlap(half_width * xi) for xi in x])
    cheb = np.polynomial.chebyshev.chebfit(x, values, nodes - 1)
    power = np.polynomial.chebyshev.cheb2poly(cheb)
    return np.array([power[n] / half_width ** n for n in range(order + 1)])


def end_of_contact_eps(eps_overlap, delta):
    """eps under the force rule from eps under the overlap rule at the same delta (Step 2).

    Parameters
    ----------
    eps_overlap : float or array_like
        u = eps_o, the speed on returning to zero deformation.
    delta : float or array_like
        The damping, Omega^(-3/5) (>= 0).

    Returns
    -------
    numpy.ndarray
        u + (4/15) u^(3/2) delta^(5/2) + (13/150) u^2 delta^5, to O(delta^(15/2)).

    Examples
    --------
    >>> float(end_of_contact_eps(1.0, 0.0))
    1.0
    >>> round(float(end_of_contact_eps(1.0, 0.1)), 12)
    1.000844140709
    """
    u = np.asarray(eps_overlap, dtype=float)
    d = np.asarray(delta, dtype=float)
    a, b = (float(q) for q in END_COEFFICIENTS)
    return u + a * u ** 1.5 * d ** 2.5 + b * u * u * d ** 5


@dataclass(frozen=True)
class SchwagerPoeschelSeries:
    """eps = sum_k h[k] s^k, s = Omega^(-3/10), under the force rule; ``h_error`` its accuracy.

    ``overlap`` holds c_n (eps_o = sum c_n delta^n, the overlap rule: h_(2n) without the end term).
    """

    h: np.ndarray
    h_error: np.ndarray
    overlap: np.ndarray

    def s(self, omega) -> np.ndarray:
        return np.asarray(omega, dtype=float) ** (-float(S_POWER))

    def eps(self, omega, order: int | None = None) -> np.ndarray:
        """The partial sum through s^order (all terms if None)."""
        kmax = len(self.h) - 1 if order is None else order
        s = self.s(omega)
        return sum(self.h[k] * s ** k for k in range(kmax + 1))


def _series_product(a: np.ndarray, b: np.ndarray, n: int) -> np.ndarray:
    out = np.zeros(n + 1)
    for i in range(min(n, len(a) - 1) + 1):
        for j in range(min(n - i, len(b) - 1) + 1):
            out[i + j] += a[i] * b[j]
    return out


def _power_series(c: np.ndarray, p: float, n: int) -> np.ndarray:
    """Coefficients of (sum c_m d^m)^p through d^n, c_0 = 1 (the J. C. P. Miller recurrence)."""
    out = np.zeros(n + 1)
    out[0] = 1.0
    for m in range(1, n + 1):
        out[m] = sum((p * k - (m - k)) * c[k] * out[m - k] for k in range(1, min(m, len(c) - 1) + 1)) / m
    return out


def _assemble(c: np.ndarray, kmax: int) -> np.ndarray:
    n = kmax // 2 + 1
    h = np.zeros(kmax + 1)
    h[0:kmax + 1:2] = c[:kmax // 2 + 1]
    u32 = _power_series(c, 1.5, n)
    u2 = _series_product(c, c, n)
    a, b = (float(q) for q in END_COEFFICIENTS)
    for m in range(n + 1):
        if 5 + 2 * m <= kmax:
            h[5 + 2 * m] += a * u32[m]
        if 10 + 2 * m <= kmax:
            h[10 + 2 * m] += b * u2[m]
    return h


def schwager_poeschel_series(kmax: int = 10) -> SchwagerPoeschelSeries:
    """Schwager and Poeschel's coefficients h_0..h_kmax (alpha = 3/2, gamma = 1/2, force rule).

    Parameters
    ----------
    kmax : int
        Highest power of s = Omega^(-3/10), 5 <= kmax <= 14 (the end relation is exact to s^14).

    Returns
    -------
    SchwagerPoeschelSeries
        h (the closed forms -C1 and (3/5) C1^2 at s^2 and s^4, the rest as derived in the module
        docstring), h_error (the difference between two interpolants of eps_o for the numerically
        derived terms, 0 for the closed forms and the exact rationals) and the overlap rule's c_n.

    Raises
    ------
    ParameterError
        If kmax is out of range.

    Examples
    --------
    >>> sp = schwager_poeschel_series(7)
    >>> [round(float(x), 6) for x in sp.h]
    [1.0, 0.0, -1.153449, 0.0, 0.798267, 0.266667, -0.522883, -0.46138]
    """
    if not (isinstance(kmax, int) and 5 <= kmax <= 14):
        raise ParameterError("kmax", kmax, "an integer in [5, 14]")
    n = kmax // 2
    order = max(n, 2)
    first, second = (overlap_damping_coefficients(order, half_width=w, nodes=n) for w, n in INTERPOLANTS)
    limit = elastic_limit(("3/2", "1/2"))
    exact = np.array([1.0, -limit.C1, limit.C2])
    c = first.copy()
    c[:3] = exact
    c_err = np.abs(first - second)
    c_err[:3] = 0.0
    h = _assemble(c, kmax)
    # an error in c_m propagates linearly into every h_k it enters
    h_err = np.abs(_assemble(c + c_err, kmax) - h) + np.abs(_assemble(c - c_err, kmax) - h)
    return SchwagerPoeschelSeries(h=h, h_error=h_err, overlap=c[:n + 1])

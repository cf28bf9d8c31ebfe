"""The collision equation x'' + Omega x^alpha + s x^gamma x' = 0 as the right-hand sides the
reference integrator (:mod:`restitution.core.collision`) runs: in tau, in u = x^(1/p) (smooth at
x = 0), and in the force form f = Omega x^(alpha-gamma) + v that keeps a tiny force accurate.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from .exponents import Exponents


@dataclass(frozen=True)
class Law:
    """The scaled equation with integer exponents of u = x^(1/p); sign = +1 forward, -1 inverse."""

    omega: float
    p: int
    qa: int
    qg: int
    sign: int

    @classmethod
    def of(cls, ex: Exponents, omega: float, sign: int) -> "Law":
        return cls(omega, ex.p, ex.q_alpha, ex.q_gamma, sign)

    # Cached: the right-hand sides below read them on every call, millions of times per build.
    @cached_property
    def alpha(self) -> float:
        return self.qa / self.p

    @cached_property
    def gamma(self) -> float:
        return self.qg / self.p

    @cached_property
    def k(self) -> int:
        """p (alpha - gamma): the power of u in Omega u^k + v, the force up to a positive factor."""
        return self.qa - self.qg

    def elastic_scale(self) -> float:
        """x at which the elastic energy alone would absorb the initial kinetic energy 1/2."""
        return ((self.alpha + 1.0) / (2.0 * self.omega)) ** (1.0 / (self.alpha + 1.0))

    def velocity_scale(self, x: float) -> float:
        """|x'| of the slow return, where v creeps along -Omega x^(alpha-gamma); capped at 1."""
        return min(1.0, self.omega * x ** (self.alpha - self.gamma))

    # -- right-hand sides in u, state (v, tau)
    def du_rhs(self, u, y):
        v = y[0]
        w = self.p * u ** (self.p - 1)
        return np.array([-w * (self.omega * u ** self.qa + self.sign * u ** self.qg * v) / v, w / v])

    def du_jac(self, u, y):
        v = y[0]
        w = self.p * u ** (self.p - 1)
        return np.array([[w * self.omega * u ** self.qa / v ** 2, 0.0], [-w / v ** 2, 0.0]])

    # -- right-hand side in tau, state (x, v)
    def dtau_rhs(self, tau, y):
        x, v = y
        return np.array([v, -self.omega * x ** self.alpha - self.sign * x ** self.gamma * v])


@dataclass(frozen=True)
class ForceForm:
    """Forward release with the force carried as a state (see the module docstring).

    In tau the state is (x, v, f), f = Omega x^(alpha-gamma) + v, and v' = -x^gamma f.
    In u the state is (v, tau, g) with g = Omega u^a + u^m v, a = max(k, 0), m = max(-k, 0):
    g = f when alpha >= gamma and g = u^m f otherwise, so g stays bounded at u = 0 and has the
    sign of f. Then Omega u^q_alpha + u^q_gamma v = u^n g with n = min(q_alpha, q_gamma).
    """

    law: Law

    @cached_property
    def a(self) -> int:
        return max(self.law.k, 0)

    @cached_property
    def m(self) -> int:
        return max(-self.law.k, 0)

    @cached_property
    def n(self) -> int:
        return min(self.law.qa, self.law.qg)

    # -- tau, state (x, v, f)
    def dtau_rhs(self, tau, y):
        x, v, f = y
        L = self.law
        xg = x ** L.gamma
        drift = L.omega * (L.alpha - L.gamma) * x ** (L.alpha - L.gamma - 1.0) * v
        return np.array([v, -xg * f, -xg * f + drift])

    def dtau_jac(self, tau, y):
        x, v, f = y
        L = self.law
        d = L.alpha - L.gamma
        xg = x ** L.gamma
        dxg = L.gamma * x ** (L.gamma - 1.0) if L.gamma else 0.0
        ddrift_dx = L.omega * d * (d - 1.0) * x ** (d - 2.0) * v
        ddrift_dv = L.omega * d * x ** (d - 1.0)
        return np.array([
            [0.0, 1.0, 0.0],
            [-dxg * f, 0.0, -xg],
            [-dxg * f + ddrift_dx, ddrift_dv, -xg],
        ])

    def dtau_force(self, tau, y):
        return y[2]

    # -- u, state (v, tau, g)
    def du_rhs(self, u, y):
        v, _, g = y
        L, a, m, n = self.law, self.a, self.m, self.n
        w = L.p * u ** (L.p - 1)
        dv = -w * u ** n * g / v
        dg = -w * u ** L.qg * g / v
        if a:
            dg += a * L.omega * u ** (a - 1)
        if m:
            dg += m * u ** (m - 1) * v
        return np.array([dv, w / v, dg])

    def du_jac(self, u, y):
        v, _, g = y
        L, m, n = self.law, self.m, self.n
        w = L.p * u ** (L.p - 1)
        dg_dv = w * u ** L.qg * g / v ** 2 + (m * u ** (m - 1) if m else 0.0)
        return np.array([
            [w * u ** n * g / v ** 2, 0.0, -w * u ** n / v],
            [-w / v ** 2, 0.0, 0.0],
            [dg_dv, 0.0, -w * u ** L.qg / v],
        ])

    def du_force(self, u, y):
        return y[2]

    def g_from_f(self, u: float, f: float) -> float:
        return f * u ** self.m


@dataclass(frozen=True)
class PullForm:
    """Forward creeping return under the overlap rule, once the force pulls (f < 0, alpha > gamma).

    In u the state is (g, tau) with g = f and x' = v = g - Omega u^k: a sum of two negative terms,
    exact to rounding however small it gets. Carrying v beside f (as ForceForm does) makes the
    system redundant: rounding in v at the creep speed Omega x^(alpha-gamma) is never corrected by
    f's relaxation, and stays as an absolute error in an eps that may be a factor Omega^2 smaller.
    """

    law: Law

    def speed(self, u, g):
        return g - self.law.omega * u ** self.law.k

    def du_rhs(self, u, y):
        g = y[0]
        L = self.law
        w = L.p * u ** (L.p - 1)
        v = self.speed(u, g)
        return np.array([-w * u ** L.qg * g / v + L.k * L.omega * u ** (L.k - 1), w / v])

    def du_jac(self, u, y):
        g = y[0]
        L = self.law
        w = L.p * u ** (L.p - 1)
        v = self.speed(u, g)
        return np.array([[w * u ** L.qg * L.omega * u ** L.k / v ** 2, 0.0], [-w / v ** 2, 0.0]])


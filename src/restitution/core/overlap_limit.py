"""The viscous limit under the overlap rule: how fast impacts rebound when contact lasts until x = 0.

Under the overlap rule (``collide(..., end="overlap")``, the default of LAMMPS, LIGGGHTS and
MercuryDPM) contact ends only when the deformation is back to zero; the total force
Omega x^alpha + x^gamma x' may turn attractive on the way. For small Omega and alpha > gamma the force
rule gives eps ~ k Omega (asymptotics.viscous_limit). The overlap rule gives a different power law.

Derivation. After maximum compression (x close to X = (gamma+1)^(1/(gamma+1))) the motion relaxes onto
the slow manifold x' ~ -Omega x^(alpha-gamma): the return creeps. The creep speeds up relative to x as
x shrinks and inertia is back at x ~ Omega^a. With

    x = Omega^a y,  tau = Omega^b T,   a = 1/(2gamma+1-alpha),  b = -a gamma,

all three terms of x'' + Omega x^alpha + x^gamma x' = 0 scale alike, and y obeys the same equation at
Omega = 1, y'' + y^alpha + y^gamma y' = 0, with the velocity w = y' = Omega^(-a(gamma+1)) x'. In the
phase plane w dw/dy = -y^alpha - y^gamma w, and the creep is the solution with w ~ -y^(alpha-gamma) as
y -> infinity (deviations from it die out on the way in like exp(-y^(2gamma+1-alpha)/(2gamma+1-alpha))).
Its speed at y = 0, C(alpha, gamma) = -w(0), is the rebound speed of the inner problem; hence

    eps ~ C Omega^k,   k = (gamma+1)/(2gamma+1-alpha)   (0 <= alpha < 2 gamma + 1),

and, with Omega = D1 g^((alpha-1-2gamma)/(gamma+1)) D2^(-(alpha+1)/(gamma+1)), the rebound speed

    eps g -> C D1^k D2^(-(alpha+1)/(2gamma+1-alpha)),

a material constant: the creep forgets the impact. The approach to the law is exponentially fast,
relative deviation ~ exp(-c/Omega) with c tending to X^m/m, m = 2gamma+1-alpha (the relaxation
exp(-int x^gamma dtau) accumulated over a creep lasting ~ 1/Omega); measured values are in the
pipeline's output. For alpha < gamma the force cannot vanish while x > 0, both rules coincide and this
is asymptotics.inner_constant's result; for alpha = gamma, C = 1 and k = 1 exactly (w = -1 is the
manifold). For alpha >= 2 gamma + 1 there is no such law: at small Omega the attractive phase stops the
return and the bodies stick (collision.StickError).

C is not elementary; it is integrated here (Radau), first in (s = ln y, W = w / y^(alpha-gamma)),
where the manifold is W = -1 + O(e^(-m s)) and the start is far enough out that the deviation from it
has died out by a factor below 1e-20, then in (y, w) from y = 1 to 0. ``C_error`` is the larger
change of C when the tolerance is loosened a hundredfold or the start moved. No file I/O here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache

import numpy as np

from .errors import ParameterError
from .exponents import as_exponents

__all__ = ["OverlapLimit", "overlap_limit", "inner_rebound_speed"]


def _start(m: float, d: float, shift: float) -> float:
    """s0 = ln(y_start): e^(m s0) >= 50 m + 2 |d| s0-ish decay margin and the manifold term d e^(-m s0) small."""
    E = max(1e3 * max(abs(d), 1.0), 60.0 * m, 10.0) * shift
    return math.log(E) / m


def _integrate(a: float, g: float, rtol: float, shift: float) -> float:
    # imported here: core.uniform reads this module, and a one-point eps call must not pay for scipy.integrate
    from scipy import integrate

    from .radau import Radau

    d = a - g
    m = 2.0 * g + 1.0 - a
    s0 = _start(m, d, shift)

    def rhs_s(s, W):
        return [(-math.exp(m * s) * (1.0 + W[0]) - d * W[0] ** 2) / W[0]]

    def jac_s(s, W):
        return [[math.exp(m * s) / W[0] ** 2 - d]]

    W0 = -1.0 - d * math.exp(-m * s0)
    sol = integrate.solve_ivp(rhs_s, (s0, 0.0), [W0], method=Radau, jac=jac_s, rtol=rtol, atol=1e-15)
    if sol.status != 0 or not sol.y[0, -1] < 0.0:
        raise ArithmeticError(f"overlap inner problem (outer leg) failed: {sol.message}")
    w1 = float(sol.y[0, -1])  # y = 1: w = W

    def rhs_y(y, w):
        return [(-y ** a - y ** g * w[0]) / w[0]]

    def jac_y(y, w):
        return [[y ** a / w[0] ** 2]]

    def stalls(y, w):
        return w[0]
    stalls.terminal = True

    sol = integrate.solve_ivp(rhs_y, (1.0, 0.0), [w1], method=Radau, jac=jac_y, rtol=rtol, atol=1e-15,
                              events=[stalls])
    if sol.status != 0:
        raise ArithmeticError(f"overlap inner problem stalls before y = 0 ({sol.message}): the bodies stick")
    return float(-sol.y[0, -1])


@lru_cache(maxsize=64)
def inner_rebound_speed(problem) -> tuple[float, float]:
    """(C, C_error): the speed at y = 0 of the creeping solution of y'' + y^alpha + y^gamma y' = 0.

    C_error is the largest change of C under a hundredfold looser tolerance or a start moved out by
    a factor 10 in e^(m s0) (both far larger perturbations than the integration's own error).
    """
    ex = as_exponents(problem)
    a, g = float(ex.alpha), float(ex.gamma)
    if not a < 2.0 * g + 1.0:
        raise ParameterError("alpha, gamma", f"{ex.alpha}, {ex.gamma}",
                             "the overlap-rule creep law needs alpha < 2 gamma + 1 (otherwise the bodies "
                             "can stick at small Omega)")
    C = _integrate(a, g, 1e-12, 1.0)
    err = max(abs(_integrate(a, g, 1e-10, 1.0) - C), abs(_integrate(a, g, 1e-12, 10.0) - C))
    return C, float(err)


@dataclass(frozen=True)
class OverlapLimit:
    """eps ~ C Omega^k under the overlap rule as Omega -> 0 (module docstring).

    k: the power (gamma+1)/(2gamma+1-alpha); C: the prefactor, C_error its estimated absolute error;
    force_k: the force rule's eps/Omega limit (alpha > gamma), for the ratio of the two rules;
    decay: X^m/m, the rate c in the relative correction ~ exp(-c/Omega) that the law approaches as
    Omega -> 0 (the measured local rate is lower at moderate Omega).
    """

    alpha: Fraction
    gamma: Fraction
    k: float
    C: float
    C_error: float
    force_k: float
    decay: float

    @property
    def k_exact(self) -> Fraction:
        return (self.gamma + 1) / (2 * self.gamma + 1 - self.alpha)

    @property
    def speed_exponents(self) -> tuple[Fraction, Fraction]:
        """(p1, p2) of the limiting rebound speed C D1^p1 D2^p2 (physical units)."""
        m = 2 * self.gamma + 1 - self.alpha
        return (self.gamma + 1) / m, -(self.alpha + 1) / m

    def eps(self, omega) -> np.ndarray:
        """The leading law C Omega^k."""
        return self.C * np.asarray(omega, dtype=float) ** self.k

    def rebound_speed(self, D1, D2) -> np.ndarray:
        """The limit of eps g for fast impacts (Omega -> 0), in the units of D1, D2."""
        p1, p2 = self.speed_exponents
        return self.C * np.asarray(D1, dtype=float) ** float(p1) * np.asarray(D2, dtype=float) ** float(p2)

    def ratio_to_force(self, omega) -> np.ndarray:
        """Leading ratio eps_overlap / eps_force = (C / force_k) Omega^(k-1) (alpha > gamma)."""
        return self.C / self.force_k * np.asarray(omega, dtype=float) ** (self.k - 1.0)

    def as_dict(self) -> dict:
        p1, p2 = self.speed_exponents
        return {"alpha": str(self.alpha), "gamma": str(self.gamma), "k": str(self.k_exact), "C": self.C,
                "C_error": self.C_error, "force_k": self.force_k, "decay": self.decay,
                "speed_D1_power": str(p1), "speed_D2_power": str(p2)}


def overlap_limit(problem) -> OverlapLimit:
    """The overlap rule's small-Omega law for gamma <= alpha < 2 gamma + 1 (alpha < gamma: the rules coincide,
    use asymptotics.viscous_limit).

    Parameters
    ----------
    problem : Problem, Exponents or (alpha, gamma)
        The exponents, gamma <= alpha < 2 gamma + 1.

    Returns
    -------
    OverlapLimit
        eps ~ C Omega^k as Omega -> 0: ``C`` (with its error ``C_error``), ``k`` and ``eps(omega)``.

    Raises
    ------
    ParameterError
        Outside gamma <= alpha < 2 gamma + 1.

    Examples
    --------
    >>> from restitution.core.collision import collide
    >>> from restitution.core.problem import Problem
    >>> lim = overlap_limit(("3/2", "1/2"))
    >>> lim.k, round(lim.C, 6)                        # eps ~ C Omega^3
    (3.0, 5.158382)
    >>> ref = collide(Problem.of("3/2", "1/2", "overlap"), 1e-2).eps   # the reference integrator
    >>> abs(float(lim.eps(1e-2)) / ref - 1) < 0.05    # the law's leading term, 1 % off at 1e-2
    True
    """
    ex = as_exponents(problem)
    a, g = ex.alpha, ex.gamma
    if not g <= a < 2 * g + 1:
        raise ParameterError("alpha, gamma", f"{a}, {g}",
                             "the overlap-rule creep law is for gamma <= alpha < 2 gamma + 1 (alpha < gamma: "
                             "both end rules coincide, see viscous_limit; alpha >= 2 gamma + 1: the bodies "
                             "can stick)")
    C, err = inner_rebound_speed((a, g))
    af, gf = float(a), float(g)
    X = (gf + 1.0) ** (1.0 / (gf + 1.0))
    m = 2.0 * gf + 1.0 - af
    return OverlapLimit(a, g, float((g + 1) / (2 * g + 1 - a)), C, err, X ** (af - gf), X ** m / m)

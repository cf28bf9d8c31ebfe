"""Limits of eps(Omega) for x'' + Omega x^alpha + x^gamma x' = 0, x(0) = 0, x'(0) = 1, derived here.

Notation: G(x) = x^(gamma+1)/(gamma+1), X = (gamma+1)^(1/(gamma+1)) (so G(X) = 1), lambda = X^gamma,
f = Omega x^(alpha-gamma) + x' (the total force is -x^gamma f; contact ends at f = 0 or x = 0).

Viscous limit, Omega -> 0
=========================
Two exact identities hold along every collision:

  (I1)  Phi = x' + G(x) obeys Phi' = -Omega x^alpha, so Phi(tau) = 1 - Omega J(tau),
        J(tau) = int_0^tau x^alpha.
  (I2)  f' = -x^gamma f + Omega (alpha - gamma) x^(alpha-gamma-1) x'.

At Omega = 0 the motion x0' = 1 - G(x0) creeps up to X: X - x0 ~ B exp(-lambda tau).

alpha > gamma. Contact ends by the force: at tau_c, x' = -eps = -Omega x_c^(alpha-gamma), so (I1)
gives the exact relation

    eps / Omega = x_c^(alpha-gamma) = X^(alpha-gamma) [1 - Omega (J(tau_c) - x_c^(alpha-gamma))]^r,
    r = (alpha - gamma)/(gamma + 1),

and as Omega -> 0, x_c -> X:

    eps / Omega -> k = X^(alpha-gamma) = (gamma+1)^((alpha-gamma)/(gamma+1)).

First correction. After maximum compression x creeps back along x' ~ -Omega x^(alpha-gamma); by
(I2) f relaxes (rate lambda) from its fast part ~ x0' ~ lambda B exp(-lambda tau) to the
quasi-static value -Omega^2 (alpha-gamma) X^(2 alpha - 3 gamma - 1), so f = 0 at

    tau_c = [2 ln(1/Omega) + L] / lambda,   L = ln(lambda B / ((alpha-gamma) X^(2alpha-3gamma-1))),

and J(tau_c) = X^alpha tau_c - K0 + O(Omega tau_c^2), K0 = int_0^inf (X^alpha - x0^alpha) dtau. Hence

    eps = k Omega [1 - Omega (c_log ln(1/Omega) + c_const)] + O(Omega^3 ln^2 Omega),
    c_log = 2 r k,   c_const = r (k L - K0 - k),

with B and K0 in closed form (psi = digamma, n = gamma + 1; derived in _damped_constants):

    ln B = ln X - gamma_E - psi(1/n) - ln n,   K0 = X^(alpha+1) [psi((alpha+1)/n) - psi(1/n)] / n.

gamma = 0 gives X = B = 1, K0 = H_alpha (harmonic number); gamma = 1 gives X = lambda = sqrt 2,
B = 2 sqrt 2. For the paper's alpha = 3/2, gamma = 1 everything is elementary:
k = 2^(1/4), c_log = 2^(1/4)/2, L = (7/2) ln 2, K0 = 2^(1/4) (4 - pi/2 - ln 2) and
c_const = (2^(1/4)/4) ((9/2) ln 2 + pi/2 - 5).

alpha = gamma. Then f = Omega + x' and f' = -x^gamma f exactly: the force never vanishes and contact
ends at x = 0. Over the whole contact, with J = int_0^tau_c x^gamma = int_0^tau_c x^alpha,
integrating f gives eps = Omega - (1 + Omega) exp(-J), and (I1) at x = 0 gives eps = Omega J - 1.
Writing u = J = (1 + eps)/Omega and eliminating Omega gives the parametric closed form, valid for
every Omega > 0 and any gamma = alpha:

    eps(u) = (1 - (1 + u) e^-u) / (u - 1 + e^-u),   Omega = (1 + eps(u)) / u,   u > 0,

so eps = Omega - (1 + Omega) exp(-(1 + eps)/Omega): eps/Omega -> 1 with exponentially small
corrections as Omega -> 0, and eps = 1 - 2/(3 Omega) + ... as Omega -> infinity.

alpha < gamma. The creeping return speeds up as x decreases (x' ~ -Omega x^(alpha-gamma)) and inertia
comes back at x ~ Omega^(1/(2gamma+1-alpha)). With x = Omega^a y, x' = Omega^b w,
a = 1/(2 gamma + 1 - alpha), b = (gamma + 1)/(2 gamma + 1 - alpha), the inner problem is
Omega-free, w dw/dy = -y^alpha - y^gamma w, matched to w ~ -y^(alpha-gamma) as y -> infinity; contact
ends by separation (y = 0) and

    eps ~ K Omega^b,   K = -w(0)   (b < 1: eps/Omega diverges),

with K a number computed here by integrating the inner problem.

Elastic limit, Omega -> infinity
================================
With x = Omega^(-1/(alpha+1)) y, tau = Omega^(-1/(alpha+1)) s the equation becomes
y'' + y^alpha + delta y^gamma y' = 0, y'(0) = 1, with delta = Omega^(-(gamma+1)/(alpha+1)).
Energy e = y'^2/2 + y^(alpha+1)/(alpha+1) on the way in (+) and out (-), as functions of y:
de/dy = -/+ delta y^gamma |y'|. To first order e_+ = e0 - delta F(y), e_- = e0 - delta (2 F(y_m) - F(y)),
F(y) = int_0^y t^gamma sqrt(2 e0), e0 = 1/2 - y^(alpha+1)/(alpha+1); the final energy
1/2 - delta int_0^{y_m} y^gamma (|y'_+| + |y'_-|) dy then gives, with I_{+-1} = int y^gamma (2e0)^{+-1/2}
and the Beta-function ratio I_{-1} = (2A + 1) I_1 (A = (gamma+1)/(alpha+1)):

    eps = 1 - C1 delta + C2 delta^2 + E delta^(1 + (gamma+1)/(alpha-gamma)) + O(delta^3),
    C1 = ((alpha+1)/2)^(A-1) B(A, 3/2),   C2 = A C1^2,
    E  = (alpha - gamma) / ((gamma+1)(alpha+1))        (alpha > gamma; 0 otherwise),

where the E term is the end of contact at f = 0, y_c = delta^(1/(alpha-gamma)), instead of y = 0.
For alpha = 3/2, gamma = 1/2 (Hertz contact with the Kuwabara-Kono dissipation): delta = Omega^(-3/5),
C1 = Gamma(3/5) sqrt(pi) / (2^(1/5) 5^(2/5) Gamma(21/10)) = 1.1534489..., C2 = (3/5) C1^2 = 0.79826...,
which are the constants of Ramirez et al., PRE 60, 4465 (1999) and Schwager & Poeschel, PRE 78,
051304 (2008): their expansion variable (3/2) A rho^(2/5) g^(1/5) (force rho xi^(3/2) + (3/2) A rho
xi^(1/2) xi') is exactly Omega^(-3/5) in our scaling (D1 = rho, D2 = (3/2) A rho), so X^2 = Omega^(-3/5)
with no extra factor. The end term adds (4/15) Omega^(-3/2).

Contact time: tau_c = Omega^(-1/(alpha+1)) [T0 + O(delta)], T0 = ((alpha+1)/2)^(1/(alpha+1)) (2/(alpha+1))
B(1/(alpha+1), 1/2); T0 = 3.2180655... for alpha = 3/2.

Every constant is checked against the integrators in tests/library/test_asymptotics.py.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache

import numpy as np

from .errors import ParameterError
from .exponents import as_exponents

__all__ = ["ViscousLimit", "ElasticLimit", "viscous_limit", "elastic_limit", "equal_exponents_eps",
           "inner_constant", "RAMIREZ_C1", "RAMIREZ_C2", "HERTZ_CONTACT_TIME"]


def _beta(a: float, b: float) -> float:
    # scipy is imported where used: it costs more than a command-line call (restitution eps) itself
    from scipy import special

    return math.exp(special.betaln(a, b))


#: Gamma(3/5) sqrt(pi) / (2^(1/5) 5^(2/5) Gamma(21/10)), Ramirez et al. 1999 (alpha = 3/2, gamma = 1/2).
RAMIREZ_C1 = math.gamma(0.6) * math.sqrt(math.pi) / (2 ** 0.2 * 5 ** 0.4 * math.gamma(2.1))
#: (3/5) C1^2, Schwager & Poeschel 2008.
RAMIREZ_C2 = 0.6 * RAMIREZ_C1 ** 2


def __getattr__(name):
    # HERTZ_CONTACT_TIME, the elastic contact time constant for alpha = 3/2 (tau_c ~ T0 Omega^(-2/5)),
    # is computed on first use: its Beta function needs scipy, which an import should not pay for.
    if name == "HERTZ_CONTACT_TIME":
        return (1.25 ** 0.4) * 0.8 * _beta(0.4, 0.5)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


# ------------------------------------------------------------------------------------- viscous
@dataclass(frozen=True)
class ViscousLimit:
    """Small-Omega behaviour of eps for given exponents (see the module docstring).

    kind: "force" (alpha > gamma), "closed" (alpha = gamma, exact closed form), "inner" (alpha < gamma).
    k: eps/Omega as Omega -> 0 ("force", "closed"), or the K of eps ~ K Omega^power ("inner").
    power: 1 for "force" and "closed", (gamma+1)/(2gamma+1-alpha) for "inner".
    c_log, c_const: first correction, eps = k Omega [1 - Omega (c_log ln(1/Omega) + c_const)]
    ("force" only; zero otherwise). X, lam, B, K0, L: the ingredients ("force" only for B, K0, L).
    """

    alpha: Fraction
    gamma: Fraction
    kind: str
    k: float
    power: float
    c_log: float = 0.0
    c_const: float = 0.0
    X: float = math.nan
    lam: float = math.nan
    B: float = math.nan
    K0: float = math.nan
    L: float = math.nan

    def eps(self, omega, order: int = 1) -> np.ndarray:
        """The expansion at Omega: order 0 = leading term, 1 = with the first correction."""
        om = np.asarray(omega, dtype=float)
        if self.kind == "closed":
            return equal_exponents_eps(om)
        if self.kind == "inner":
            return self.k * om ** self.power
        lead = self.k * om
        if order == 0:
            return lead
        return lead * (1.0 - om * (self.c_log * np.log(1.0 / om) + self.c_const))

    def tau_c(self, omega) -> np.ndarray:
        """Leading contact time for alpha > gamma: (2 ln(1/Omega) + L) / lambda."""
        if self.kind != "force":
            raise ParameterError("alpha, gamma", f"{self.alpha}, {self.gamma}",
                                 "the viscous contact-time formula needs alpha > gamma")
        om = np.asarray(omega, dtype=float)
        return (2.0 * np.log(1.0 / om) + self.L) / self.lam

    def kernel_params(self) -> np.ndarray:
        """(kind, k, c_log, c_const, power) as read by fast.panels._viscous_eval ("closed" has no kernel form)."""
        return np.array([0.0 if self.kind == "force" else 1.0, self.k, self.c_log, self.c_const,
                         self.power])

    def as_dict(self) -> dict:
        return {"alpha": str(self.alpha), "gamma": str(self.gamma), "kind": self.kind, "k": self.k,
                "power": self.power, "c_log": self.c_log, "c_const": self.c_const, "X": self.X,
                "lambda": self.lam, "B": self.B, "K0": self.K0, "L": self.L}


@lru_cache(maxsize=64)
def _damped_constants(alpha: Fraction, gamma: Fraction) -> tuple[float, float, float, float]:
    """X, lambda, B, K0 of the damped-only motion x0' = 1 - G(x0), in closed form.

    With x = X s and t = s^(gamma+1) both defining quadratures become Euler integrals
    int_0^1 (t^(p-1) - t^(q-1))/(1 - t) dt = psi(q) - psi(p) (n = gamma + 1, psi = digamma):

        ln B = ln X + int_0^1 [n/(1 - s^n) - 1/(1 - s)] ds = ln X - gamma_E - psi(1/n) - ln n,
        K0   = X^(alpha+1) int_0^1 (1 - s^alpha)/(1 - s^n) ds = X^(alpha+1) [psi((alpha+1)/n) - psi(1/n)] / n.

    (tests/library/test_asymptotics.py checks both against the quadratures to 1e-13.)
    """
    n = float(gamma) + 1.0
    a = float(alpha)
    X = n ** (1.0 / n)
    lam = X ** float(gamma)
    from scipy import special

    B = X * math.exp(-np.euler_gamma - special.digamma(1.0 / n) - math.log(n))
    K0 = X ** (a + 1.0) * (special.digamma((a + 1.0) / n) - special.digamma(1.0 / n)) / n
    return X, lam, float(B), float(K0)


@lru_cache(maxsize=64)
def inner_constant(problem, *, y_start: float | None = None) -> float:
    """K = -w(0) of the inner problem w dw/dy = -y^alpha - y^gamma w (alpha < gamma), w ~ -y^(alpha-gamma).

    Integrated (Radau, rtol 1e-12) from y_start, where w starts on the slow manifold to first order,
    w = -y^(alpha-gamma) (1 + (alpha-gamma) y^(alpha-2gamma-1)); deviations from the manifold die out
    on the way in, and the result is independent of y_start to the integration accuracy (tested).
    """
    ex = as_exponents(problem)
    a, g = float(ex.alpha), float(ex.gamma)
    if not a < g:
        raise ParameterError("alpha, gamma", f"{ex.alpha}, {ex.gamma}", "the inner problem needs alpha < gamma")
    e = a - 2.0 * g - 1.0  # < 0
    Y = y_start if y_start is not None else 1e-4 ** (1.0 / e)  # manifold correction ~ 1e-4 there

    def rhs(y, w):
        return [(-y ** a - y ** g * w[0]) / w[0]]

    def jac(y, w):
        return [[y ** a / w[0] ** 2]]

    w0 = -Y ** (a - g) * (1.0 + (a - g) * Y ** e)
    from scipy import integrate

    from .radau import Radau

    sol = integrate.solve_ivp(rhs, (Y, 0.0), [w0], method=Radau, jac=jac, rtol=1e-12,
                              atol=1e-14)
    if sol.status != 0:
        raise ArithmeticError(f"inner problem failed: {sol.message}")
    return float(-sol.y[0, -1])


def viscous_limit(problem) -> ViscousLimit:
    """The small-Omega expansion for these exponents (see the module docstring).

    Parameters
    ----------
    problem : Problem, Exponents or (alpha, gamma)
        The exponents (the small-Omega behaviour does not depend on the end rule where the rules
        coincide; the overlap rule's own law is :func:`restitution.core.overlap_limit.overlap_limit`).

    Returns
    -------
    ViscousLimit
        Its ``kind`` ("force", "closed" or "inner"), the leading constant ``k`` and power, the
        first correction, and ``eps(omega, order)``.

    Raises
    ------
    ParameterError
        For exponents out of range.

    See Also
    --------
    elastic_limit : The large-Omega expansion.

    Examples
    --------
    >>> from restitution.core.collision import collide
    >>> v = viscous_limit(("3/2", 1))
    >>> v.kind, round(v.k, 6)                       # eps ~ 2^(1/4) Omega as Omega -> 0
    ('force', 1.189207)
    >>> ref = collide(("3/2", 1), 1e-6).eps          # the reference integrator, a second method
    >>> abs(float(v.eps(1e-6)) / ref - 1) < 1e-9
    True
    """
    ex = as_exponents(problem)
    a, g = ex.alpha, ex.gamma
    if a == g:
        return ViscousLimit(a, g, "closed", 1.0, 1.0, X=float(g + 1) ** (1.0 / float(g + 1)))
    if a < g:
        K = inner_constant((a, g))
        return ViscousLimit(a, g, "inner", K, float((g + 1) / (2 * g + 1 - a)),
                            X=float(g + 1) ** (1.0 / float(g + 1)))
    X, lam, B, K0 = _damped_constants(a, g)
    af, gf = float(a), float(g)
    d = af - gf
    r = d / (gf + 1.0)
    k = X ** d
    L = math.log(lam * B / (d * X ** (2.0 * af - 3.0 * gf - 1.0)))
    return ViscousLimit(a, g, "force", k, 1.0, c_log=2.0 * r * k, c_const=r * (k * L - K0 - k),
                        X=X, lam=lam, B=B, K0=K0, L=L)


# ------------------------------------------------------------------------------- alpha = gamma
def _eps_of_u(u: np.ndarray) -> np.ndarray:
    """eps(u) = (1 - (1+u) e^-u) / (u - 1 + e^-u), stable for all u > 0 (series for small u)."""
    u = np.asarray(u, dtype=float)
    out = np.empty_like(u)
    small = u < 0.5
    if np.any(small):
        us = u[small]
        # numerator sum_{n>=2} (-1)^n (n-1) u^n / n!, denominator sum_{n>=2} (-1)^n u^n / n!,
        # both divided by u^2 / 2
        num = np.zeros_like(us)
        den = np.zeros_like(us)
        term = np.ones_like(us)  # (-u)^(n-2) * 2 / n!  at n = 2
        for n in range(2, 30):
            num += (n - 1) * term
            den += term
            term = term * (-us) / (n + 1)
        out[small] = num / den
    big = ~small
    if np.any(big):
        ub = u[big]
        em = np.exp(-ub)
        out[big] = (-np.expm1(-ub) - ub * em) / (ub + np.expm1(-ub))
    return out


def _deps_du(u: np.ndarray, e: np.ndarray) -> np.ndarray:
    """d eps / du = (N' D - N D') / D^2 with N' = u e^-u, D' = 1 - e^-u (used for Newton only).
    For small u, D = u - 1 + e^-u cancels to nothing (0/0 from u ~ 1e-16, Omega ~ 2e16): there a
    central difference of the stable eps(u) instead (Newton needs only an approximate slope)."""
    em = np.exp(-u)
    D = u + np.expm1(-u)
    N = e * D
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):   # replaced where it matters
        exact = (u * em * D - N * (-np.expm1(-u))) / (D * D)
    small = u < 0.5
    if np.any(small):
        h = 1e-4 * u[small]
        exact[small] = (_eps_of_u(u[small] + h) - _eps_of_u(u[small] - h)) / (2.0 * h)
    return exact


def equal_exponents_eps(omega) -> np.ndarray:
    """Exact eps for alpha = gamma (any gamma >= 0): the root of Omega u = 1 + eps(u), eps = eps(u).

    Newton in u from u = 2/Omega (elastic side) or 1/Omega (viscous side); converges to rounding
    in a few iterations (tested against the integrators).

    Parameters
    ----------
    omega : float or array_like
        Omega > 0.

    Returns
    -------
    numpy.ndarray
        eps, shaped as ``omega``, to rounding.

    Examples
    --------
    >>> from restitution.core.collision import collide
    >>> e = equal_exponents_eps([0.5, 2.0])
    >>> e.round(8)
    array([0.41071969, 0.74843493])
    >>> abs(float(e[0]) / collide((1, 1), 0.5).eps - 1) < 1e-10     # the reference integrator
    True
    """
    om = np.asarray(omega, dtype=float)
    flat = om.ravel()
    u = np.where(flat > 1.0, 2.0 / flat, (1.0 + flat) / flat)
    for _ in range(60):
        e = _eps_of_u(u)
        h = flat * u - 1.0 - e
        dh = flat - _deps_du(u, e)
        step = h / dh
        u_new = u - step
        u_new = np.where(u_new <= 0, 0.5 * u, u_new)
        done = np.abs(u_new - u) <= 1e-15 * u
        u = u_new
        if np.all(done):
            break
    out = _eps_of_u(u)
    # tiny Omega: eps = Omega - (1 + Omega) exp(-(1 + eps)/Omega) = Omega to double precision
    out = np.where(flat < 1e-2, flat - (1.0 + flat) * np.exp(-(1.0 + out) / flat), out)
    return out.reshape(om.shape)


# ------------------------------------------------------------------------------------- elastic
@dataclass(frozen=True)
class ElasticLimit:
    """Large-Omega expansion eps = 1 - C1 delta + C2 delta^2 + E delta^end_power, delta = Omega^-A."""

    alpha: Fraction
    gamma: Fraction
    A: float
    C1: float
    C2: float
    E: float
    end_power: float
    T0: float

    def delta(self, omega) -> np.ndarray:
        return np.asarray(omega, dtype=float) ** (-self.A)

    def eps(self, omega, order: int = 2, *, end_term: bool = True) -> np.ndarray:
        """order 1: 1 - C1 delta; 2: + C2 delta^2 and (``end_term``) the end-of-contact term, which
        the two-term series of Ramirez et al. does not have."""
        d = self.delta(omega)
        out = 1.0 - self.C1 * d
        if order >= 2:
            out = out + self.C2 * d * d
            if self.E and end_term:
                out = out + self.E * d ** self.end_power
        return out

    def tau_c(self, omega) -> np.ndarray:
        """Leading contact time T0 Omega^(-1/(alpha+1))."""
        return self.T0 * np.asarray(omega, dtype=float) ** (-1.0 / (float(self.alpha) + 1.0))

    def kernel_params(self) -> np.ndarray:
        return np.array([self.A, self.C1, self.C2, self.end_power, self.E])

    def as_dict(self) -> dict:
        return {"alpha": str(self.alpha), "gamma": str(self.gamma), "A": self.A, "C1": self.C1,
                "C2": self.C2, "E": self.E, "end_power": self.end_power, "T0": self.T0}


def elastic_limit(problem) -> ElasticLimit:
    """The large-Omega expansion eps = 1 - C1 delta + C2 delta^2 + E delta^end_power, delta = Omega^-A.

    Parameters
    ----------
    problem : Problem, Exponents or (alpha, gamma)
        The exponents (an end rule is not read: the end term E is the force rule's).

    Returns
    -------
    ElasticLimit
        A = (gamma+1)/(alpha+1), the constants C1, C2, E and the power of the end term, and
        ``eps(omega, order)``.

    See Also
    --------
    viscous_limit : The small-Omega expansion.

    Examples
    --------
    >>> import restitution
    >>> e = elastic_limit(("3/2", 1))
    >>> e.A
    0.8
    >>> abs(float(e.eps(1e6)) / restitution.collide("3/2", 1, 1e6).eps - 1) < 1e-9   # the reference integrator
    True
    """
    ex = as_exponents(problem)
    a, g = float(ex.alpha), float(ex.gamma)
    A = (g + 1.0) / (a + 1.0)
    C1 = ((a + 1.0) / 2.0) ** (A - 1.0) * _beta(A, 1.5)
    C2 = A * C1 * C1
    if ex.alpha > ex.gamma:
        E = (a - g) / ((g + 1.0) * (a + 1.0))
        end_power = 1.0 + (g + 1.0) / (a - g)
    else:
        E, end_power = 0.0, math.inf
    T0 = ((a + 1.0) / 2.0) ** (1.0 / (a + 1.0)) * (2.0 / (a + 1.0)) * _beta(1.0 / (a + 1.0), 0.5)
    return ElasticLimit(ex.alpha, ex.gamma, A, C1, C2, E, end_power, T0)

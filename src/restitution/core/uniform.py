"""eps(Omega) in one closed form, exact to leading and first order in both limits (alpha > gamma).

With eta = 1/eps, x = b Omega and u = tanh((sigma/2) ln x) = (x^sigma - 1)/(x^sigma + 1):

    eta - 1 = [ b (1 + x)^(1-A) / x  +  (c_log ln(1 + 1/x) + c3) / (1 + x)^2 ] / k
              + (1 + u)^m0 (1 - u)^m1 (a_0 + a_1 u + ... + a_n u^n),   n = 11 (more for small A),
    eps = 1 / eta,   1 - eps = (eta - 1) / eta.

The first line (the skeleton) has no free number. Its constants come from the limits of
:mod:`restitution.core.asymptotics`: k = (gamma+1)^((alpha-gamma)/(gamma+1)), A = (gamma+1)/(alpha+1),
b = (k C1)^(1/(1-A)), c3 = c_const + c_log ln b - (1-A) b - k. By construction

* Omega -> 0:   eps = k Omega [1 - Omega (c_log ln(1/Omega) + c_const)] + O(Omega^2 ...): the skeleton's
  eta is 1/(k Omega) + (c_log ln(1/Omega) + c_const)/k + o(1), and the fitted term vanishes
  like Omega^(sigma m0) (1 + u ~ 2 x^sigma);
* Omega -> inf: 1 - eps = C1 Omega^(-A) (1 + o(1)): the skeleton gives C1 Omega^(-A) + O(Omega^(-1-A), Omega^(-2)),
  the fitted term is O(Omega^(-sigma m1)) with sigma m1 >= 3A/2.

The second line is fitted in Chebyshev polynomials of u (well conditioned) and stored in powers of
u (u lies in (-1, 1), so 12 significant digits of each a_j are plenty; the pipeline checks the
printed digits). It is fitted (linear least squares, made minimax by Lawson's reweighting) to the
relative error of eta - 1, which bounds the relative error of eps and at most twice that of
1 - eps. The shape (sigma, m0, m1) is chosen from a fixed small set by the error on points not
used in the fit; the bound is stated from points used neither in the fit nor in that choice
(:func:`restitution.fast.uniform_build.build_uniform`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np
from numpy.polynomial import chebyshev as cheb

from . import asymptotics as asy
from .errors import ParameterError
from .exponents import as_exponents

__all__ = ["UniformForm", "Skeleton", "skeleton", "fit_uniform", "SHAPES", "DEGREE", "FORM_RANGE",
           "UNIFORM_VERSION"]

#: Bumped whenever the form or its fit changes (cached forms of an older kind are rebuilt).
UNIFORM_VERSION = 1
#: Polynomial degree of the fitted term: DEGREE + 1 fitted coefficients, raised in steps of
#: DEGREE_STEP (up to MAX_DEGREE) only while the error on the choice points stays above
#: SELECTION_TARGET; which is the case only for small A (e.g. gamma = 0, alpha >= 2), where the
#: crossover between the limits spans more decades of Omega.
DEGREE = 11
DEGREE_STEP = 4
MAX_DEGREE = 23
SELECTION_TARGET = 4e-4
#: Omega range over which a form is fitted and its bound measured.
FORM_RANGE = (1e-8, 1e8)
#: Candidate sigma values (A itself is added per pair) and powers m0, m1.
SIGMAS = (0.25, 1 / 3, 0.4, 0.5, 0.6, 0.75, 1.0)
POWERS_M0 = (1, 2, 3, 4)
POWERS_M1 = (1, 2, 3)
#: The fitted term must fall at least like Omega^(-MARGIN A) on the elastic side.
MARGIN = 1.5
#: Lawson iterations (weights of the least-squares fit made minimax).
LAWSON_STEPS = 60


def SHAPES(A: float) -> list[tuple[float, int, int]]:
    """(sigma, m0, m1) candidates for this A: every combination with sigma m1 >= MARGIN A."""
    sig = sorted(set(SIGMAS) | {A})
    return [(s, m0, m1) for s in sig for m0 in POWERS_M0 for m1 in POWERS_M1 if s * m1 >= MARGIN * A - 1e-12]


@dataclass(frozen=True)
class Skeleton:
    """The fit-free part: constants from the two limits."""

    A: float
    k: float
    b: float
    c_log: float
    c3: float

    def eta_minus_one(self, omega) -> np.ndarray:
        x = self.b * np.asarray(omega, dtype=float)
        with np.errstate(over="ignore"):
            return (self.b * (1.0 + x) ** (1.0 - self.A) / x
                    + (self.c_log * np.log1p(1.0 / x) + self.c3) / (1.0 + x) ** 2) / self.k


def skeleton(alpha, gamma) -> Skeleton:
    ex = as_exponents(alpha, gamma)
    if not ex.alpha > ex.gamma:
        why = ("alpha = gamma has an exact closed form (restitution.core.asymptotics.equal_exponents_eps)"
               if ex.alpha == ex.gamma else
               "for alpha < gamma the viscous limit's first correction is not known in closed form")
        raise ParameterError("alpha, gamma", f"{ex.alpha}, {ex.gamma}", f"the uniform form needs alpha > gamma: {why}")
    v = asy.viscous_limit(ex.alpha, ex.gamma)
    e = asy.elastic_limit(ex.alpha, ex.gamma)
    A, k = e.A, v.k
    b = (k * e.C1) ** (1.0 / (1.0 - A))
    c3 = v.c_const + v.c_log * math.log(b) - (1.0 - A) * b - k
    return Skeleton(A, k, b, v.c_log, c3)


def _u(sk: Skeleton, sigma: float, omega) -> np.ndarray:
    return np.tanh(0.5 * sigma * np.log(sk.b * np.asarray(omega, dtype=float)))


def _envelope(u: np.ndarray, m0: int, m1: int) -> np.ndarray:
    return (1.0 + u) ** m0 * (1.0 - u) ** m1


def _basis(sk: Skeleton, sigma: float, m0: int, m1: int, omega, degree: int = DEGREE) -> np.ndarray:
    u = _u(sk, sigma, omega)
    return _envelope(u, m0, m1)[:, None] * cheb.chebvander(u, degree)


@dataclass(frozen=True)
class UniformForm:
    """A fitted uniform form and its measured accuracy (relative errors, on held-out points)."""

    alpha: Fraction
    gamma: Fraction
    skel: Skeleton
    sigma: float
    m0: int
    m1: int
    coef: tuple
    bound_eps: float = math.nan            # over FORM_RANGE
    bound_one_minus_eps: float = math.nan  # over [1, FORM_RANGE[1]]
    measured: dict = field(default_factory=dict)

    def eta_minus_one(self, omega) -> np.ndarray:
        om = np.asarray(omega, dtype=float)
        u = _u(self.skel, self.sigma, om)
        poly = np.zeros_like(u)
        for a in reversed(self.coef):
            poly = poly * u + a
        return self.skel.eta_minus_one(om) + _envelope(u, self.m0, self.m1) * poly

    def eps(self, omega) -> np.ndarray:
        return 1.0 / (1.0 + self.eta_minus_one(omega))

    def one_minus_eps(self, omega) -> np.ndarray:
        h = self.eta_minus_one(omega)
        return h / (1.0 + h)

    def coefficients(self) -> dict:
        """Every number of the form, by name (what a user types into their own code)."""
        s = self.skel
        return {"k": s.k, "A": s.A, "b": s.b, "c_log": s.c_log, "c3": s.c3, "sigma": self.sigma,
                "m0": self.m0, "m1": self.m1, "a": list(self.coef)}

    def formula(self) -> str:
        """The form as one line of C/Python (W = Omega), with every constant written out."""
        s = self.skel
        poly = ""
        for a in reversed(self.coef):
            poly = f"({poly})*u{a:+.17g}" if poly else f"{a:.17g}"
        return (f"x={s.b!r}*W; u=tanh({0.5 * self.sigma!r}*log(x)); "
                f"eps=1/(1+({s.b!r}*pow(1+x,{1 - s.A!r})/x+({s.c_log!r}*log(1+1/x){s.c3:+.17g})/((1+x)*(1+x)))/{s.k!r}"
                f"+pow(1+u,{self.m0})*pow(1-u,{self.m1})*({poly}));")

    def rounded(self, digits: int) -> "UniformForm":
        """The form with every number as printed to ``digits`` significant digits (what a reader types)."""
        r = lambda v: float(f"{v:.{digits - 1}e}")  # noqa: E731
        s = self.skel
        return UniformForm(self.alpha, self.gamma, Skeleton(r(s.A), r(s.k), r(s.b), r(s.c_log), r(s.c3)),
                           r(self.sigma), self.m0, self.m1, tuple(r(a) for a in self.coef),
                           self.bound_eps, self.bound_one_minus_eps, self.measured)

    def as_dict(self) -> dict:
        return {"version": UNIFORM_VERSION, "alpha": str(self.alpha), "gamma": str(self.gamma),
                **self.coefficients(), "bound_eps": self.bound_eps,
                "bound_one_minus_eps": self.bound_one_minus_eps, "omega_range": list(FORM_RANGE),
                "measured": self.measured}

    @classmethod
    def from_dict(cls, d: dict) -> "UniformForm":
        if d.get("version") != UNIFORM_VERSION:
            raise ValueError("uniform form version mismatch")
        ex = as_exponents(d["alpha"], d["gamma"])
        sk = skeleton(ex.alpha, ex.gamma)
        stored = Skeleton(float(d["A"]), float(d["k"]), float(d["b"]), float(d["c_log"]), float(d["c3"]))
        if stored != sk:   # the skeleton is derived, never read: a stored one must agree with it
            raise ValueError("stored skeleton constants differ from the derived ones")
        return cls(ex.alpha, ex.gamma, sk, float(d["sigma"]), int(d["m0"]), int(d["m1"]),
                   tuple(float(a) for a in d["a"]), float(d["bound_eps"]), float(d["bound_one_minus_eps"]),
                   dict(d.get("measured", {})))


def _lawson(M: np.ndarray, y: np.ndarray, steps: int = LAWSON_STEPS) -> np.ndarray:
    """Least squares of M c ~ y, reweighted towards the minimax solution (Lawson's algorithm)."""
    w = np.full(y.size, 1.0 / y.size)
    c = np.linalg.lstsq(M, y, rcond=None)[0]
    for _ in range(steps):
        sw = np.sqrt(w)
        c = np.linalg.lstsq(M * sw[:, None], y * sw, rcond=None)[0]
        e = np.abs(M @ c - y)
        if not np.all(np.isfinite(e)) or e.sum() == 0:
            break
        w = w * e
        w = w / w.sum()
    return c


def rel_errors(form: UniformForm, omega, eps, one_minus_eps) -> tuple[float, float]:
    """Largest relative error in eps over ``omega`` and in 1 - eps over those >= 1."""
    om = np.asarray(omega, dtype=float)
    e_eps = np.abs(form.eps(om) / eps - 1.0)
    elastic = om >= 1.0
    e_ome = np.abs(form.one_minus_eps(om[elastic]) / np.asarray(one_minus_eps)[elastic] - 1.0)
    return float(np.max(e_eps)), float(np.max(e_ome)) if e_ome.size else 0.0


def fit_uniform(alpha, gamma, omega, eps, one_minus_eps, train, select) -> UniformForm:
    """Fit the form to reference values: coefficients on ``train`` (a boolean mask), the shape
    chosen by the largest relative error (eps, and 1 - eps for Omega >= 1) on ``select``. The
    returned form's bounds are still unset (they come from a third set of points)."""
    ex = as_exponents(alpha, gamma)
    sk = skeleton(ex.alpha, ex.gamma)
    om = np.asarray(omega, dtype=float)
    eps = np.asarray(eps, dtype=float)
    ome = np.asarray(one_minus_eps, dtype=float)
    target = ome / eps                          # eta - 1, relative accuracy kept near eps = 1
    resid = (target - sk.eta_minus_one(om)) / target
    best = None
    for degree in range(DEGREE, MAX_DEGREE + 1, DEGREE_STEP):
        for sigma, m0, m1 in SHAPES(sk.A):
            M = _basis(sk, sigma, m0, m1, om, degree) / target[:, None]
            c = cheb.cheb2poly(_lawson(M[train], resid[train]))
            form = UniformForm(ex.alpha, ex.gamma, sk, float(sigma), m0, m1, tuple(float(x) for x in c))
            with np.errstate(all="ignore"):
                err = max(rel_errors(form, om[select], eps[select], ome[select]))
            if math.isfinite(err) and (best is None or err < best[0]):
                best = (err, form)
        if best is not None and best[0] <= SELECTION_TARGET:
            break
    if best is None:
        raise ArithmeticError(f"no uniform form could be fitted for alpha={ex.alpha}, gamma={ex.gamma}")
    return best[1]

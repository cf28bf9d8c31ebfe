"""eps(Omega) by one uniform approximation, exact to leading and first order in both limits
(alpha > gamma), and one for the overlap end rule (gamma < alpha < 2 gamma + 1), exact to leading
order in both; in between it is fitted (12 numbers), so its error is measured, not proved.

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
used in the fit; the error (``bound_eps``, ``bound_one_minus_eps``: an estimate with a margin,
not a proven bound) is stated from points used neither in the fit nor in that choice
(:func:`restitution.fast.uniform_build.build_uniform`).

Under the overlap rule (contact ends at x = 0, :mod:`restitution.core.overlap_limit`) fast impacts
obey eps = C Omega^kv (kv = (gamma+1)/(2 gamma+1-alpha)) up to a correction ~ exp(-c/Omega), below
1e-12 for Omega < 0.03 on the pairs measured, and the elastic limit 1 - eps ~ C1 Omega^(-A) is the
force rule's. Hence another form (eta spans 40 decades, the correction is relative in both limits,
and 1/eps = Omega^(-kv)/C has no "1 +" at small Omega):

    eta = x^P/(1 + x^P) + K x^(-kv) (1 + x^P)^((kv - A)/P) exp[e^(-r/x) (1 - u)^m1 (a_0 T_0(u) + ... + a_n T_n(u))],

P = OVERLAP_P, b = (C C1)^(1/(kv - A)) and K = b^kv / C fixed by the two limits (kv > A exactly when
alpha > gamma), so that eps -> C Omega^kv (1 + O(Omega^(P+kv))) and 1 - eps -> C1 Omega^(-A); the
envelope e^(-r/x) vanishes like the true correction, and eps > 0 for any coefficients. The shape is
(sigma, r, m1). Its degree reaches 39: in powers of u, or fitted without a penalty on their size,
the coefficients reached 1e8 to 1e11 and 12 printed digits moved eps by up to 1e-4, so it is stored
in Chebyshev polynomials T_j(u) = cos(j arccos u) and fitted with a small ridge (OVERLAP_RIDGE).
Where alpha >= 2 gamma + 1 the bodies can stick at small Omega and there is no such form.
"""

from __future__ import annotations

import math
from dataclasses import astuple, dataclass, field, fields, replace
from fractions import Fraction

import numpy as np
from numpy.polynomial import chebyshev as cheb

from . import asymptotics as asy
from .errors import ParameterError
from .exponents import as_exponents
from .problem import Problem, as_problem
from .overlap_limit import overlap_limit

__all__ = ["UniformForm", "Skeleton", "OverlapSkeleton", "skeleton", "fit_uniform", "SHAPES", "DEGREE",
           "FORM_RANGE", "UNIFORM_VERSION"]

#: Bumped whenever the form, its fit or its measured bound changes (cached forms of an older kind are
#: rebuilt; 2: the bound includes a dense scan of held-out points).
UNIFORM_VERSION = 2
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
#: The overlap form: its power P, the envelope's rates r (times the creep law's decay rate in x,
#: core.overlap_limit), its powers m1, and its degrees (more than the force form's: the onset
#: exp(-c/Omega) is steep: bound 2.4e-5 at degree 31 for (3/2, 1/2), 6.5e-5 at 39 for (5/2, 1)), and
#: a ridge on the coefficients: without it the envelope's dead zone at small x lets them grow to
#: 1e8 (12 printed digits then moved eps by 2e-5); with it they stay below 1 and move it by 1e-12.
OVERLAP_P = 4
OVERLAP_RATES = (0.125, 0.25, 0.5)
OVERLAP_M1 = (1, 2)
OVERLAP_MAX_DEGREE = 39
OVERLAP_SELECTION_TARGET = 3e-5
OVERLAP_RIDGE = 1e-4
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


@dataclass(frozen=True)
class OverlapSkeleton:
    """The overlap rule's fit-free parts, x = b Omega: w = x^P/(1 + x^P) and the factor
    S = K x^(-kv) (1 + x^P)^((kv - A)/P) of the exponential; eta = w + S exp(fitted)."""

    A: float
    kv: float
    b: float
    K: float
    decay: float   # the creep law's rate c (relative correction ~ exp(-c/Omega)), in x = b Omega

    def parts(self, omega) -> tuple[np.ndarray, np.ndarray]:
        x = self.b * np.asarray(omega, dtype=float)
        with np.errstate(over="ignore", divide="ignore"):
            lp = np.log1p(x ** OVERLAP_P)
            w = np.exp(OVERLAP_P * np.log(x) - lp)
            return w, np.exp(math.log(self.K) - self.kv * np.log(x) + (self.kv - self.A) / OVERLAP_P * lp)


def _no_form(ex, why: str) -> ParameterError:
    return ParameterError("alpha, gamma", f"{ex.alpha}, {ex.gamma}", why)


def skeleton(problem: Problem) -> Skeleton | OverlapSkeleton:
    """The fit-free part of the form for the problem's exponents and end rule; ParameterError
    (saying why) where there is no form."""
    problem = as_problem(problem)
    ex, end = problem.ex, problem.end
    if not ex.alpha > ex.gamma:
        why = ("alpha = gamma has an exact closed form (restitution.core.asymptotics.equal_exponents_eps)"
               if ex.alpha == ex.gamma else
               "for alpha < gamma the viscous limit's first correction is not known in closed form")
        raise _no_form(ex, f"the uniform form needs alpha > gamma: {why}")
    e = asy.elastic_limit(ex)
    A = e.A
    if end == "overlap":
        if not ex.alpha < 2 * ex.gamma + 1:
            raise _no_form(ex, "the overlap rule's uniform form needs alpha < 2 gamma + 1 (otherwise the bodies "
                               "stick at small Omega)")
        lim = overlap_limit(ex)
        lnb = (math.log(lim.C) + math.log(e.C1)) / (lim.k - A)
        b = math.exp(lnb)
        return OverlapSkeleton(A, lim.k, b, math.exp(lim.k * lnb - math.log(lim.C)), lim.decay * b)
    v = asy.viscous_limit(ex)
    k = v.k
    b = (k * e.C1) ** (1.0 / (1.0 - A))
    c3 = v.c_const + v.c_log * math.log(b) - (1.0 - A) * b - k
    return Skeleton(A, k, b, v.c_log, c3)


def _u(sk, sigma: float, omega) -> np.ndarray:
    return np.tanh(0.5 * sigma * np.log(sk.b * np.asarray(omega, dtype=float)))


def _envelope(sk, u: np.ndarray, m0: int, m1: int, rate: float, omega) -> np.ndarray:
    env = (1.0 + u) ** m0 * (1.0 - u) ** m1
    if rate:
        with np.errstate(divide="ignore"):
            env = env * np.exp(-rate / (sk.b * np.asarray(omega, dtype=float)))
    return env


def _basis(sk, sigma: float, m0: int, m1: int, rate: float, omega, degree: int = DEGREE) -> np.ndarray:
    u = _u(sk, sigma, omega)
    return _envelope(sk, u, m0, m1, rate, omega)[:, None] * cheb.chebvander(u, degree)


@dataclass(frozen=True)
class UniformForm:
    """A fitted uniform form and its measured accuracy (relative errors, on held-out points)."""

    alpha: Fraction
    gamma: Fraction
    skel: Skeleton | OverlapSkeleton
    sigma: float
    m0: int
    m1: int
    coef: tuple
    bound_eps: float = math.nan            # over FORM_RANGE
    bound_one_minus_eps: float = math.nan  # over [1, FORM_RANGE[1]]
    measured: dict = field(default_factory=dict)
    end: str = "force"
    rate: float = 0.0   # the overlap form's envelope e^(-rate/x) (0: none)

    def _fitted(self, om: np.ndarray) -> np.ndarray:
        u = _u(self.skel, self.sigma, om)
        if self.end == "overlap":
            return _envelope(self.skel, u, self.m0, self.m1, self.rate, om) * cheb.chebval(u, self.coef)
        poly = np.zeros_like(u)
        for a in reversed(self.coef):
            poly = poly * u + a
        return _envelope(self.skel, u, self.m0, self.m1, self.rate, om) * poly

    def _eta_parts(self, omega) -> tuple[np.ndarray, np.ndarray]:
        """eta as 1 + h (force) or w + S e^F (overlap): (the first term, the rest)."""
        om = np.asarray(omega, dtype=float)
        if self.end == "overlap":
            w, S = self.skel.parts(om)
            with np.errstate(over="ignore"):
                return w, S * np.exp(self._fitted(om))
        return np.ones_like(om), self.skel.eta_minus_one(om) + self._fitted(om)

    def eta_minus_one(self, omega) -> np.ndarray:
        first, rest = self._eta_parts(omega)
        return rest - (1.0 - first)

    def eps(self, omega) -> np.ndarray:
        first, rest = self._eta_parts(omega)
        return 1.0 / (first + rest)

    def one_minus_eps(self, omega) -> np.ndarray:
        first, rest = self._eta_parts(omega)
        return (rest - (1.0 - first)) / (first + rest)

    def coefficients(self) -> dict:
        """Every number of the form, by name (what a user types into their own code)."""
        s = self.skel
        if self.end == "overlap":
            return {"end": "overlap", "kv": s.kv, "A": s.A, "b": s.b, "K": s.K, "decay": s.decay, "P": OVERLAP_P,
                    "sigma": self.sigma, "r": self.rate, "m1": self.m1, "a": list(self.coef)}
        return {"k": s.k, "A": s.A, "b": s.b, "c_log": s.c_log, "c3": s.c3, "sigma": self.sigma, "m0": self.m0,
                "m1": self.m1, "a": list(self.coef)}

    def formula(self) -> str:
        """The form as one line of C/Python (W = Omega), with every constant written out."""
        s = self.skel
        head = f"x={s.b!r}*W; u=tanh({0.5 * self.sigma!r}*log(x)); "
        if self.end == "overlap":
            P = OVERLAP_P
            series = "+".join(f"{a!r}*cos({j}*t)" for j, a in enumerate(self.coef)).replace("+-", "-")
            return head + (f"t=acos(u); eps=1/(pow(x,{P})/(1+pow(x,{P}))+{s.K!r}*pow(x,{-s.kv!r})"
                           f"*pow(1+pow(x,{P}),{(s.kv - s.A) / P!r})*exp(exp({-self.rate!r}/x)*pow(1-u,{self.m1})*({series})));")
        poly = ""
        for a in reversed(self.coef):
            poly = f"({poly})*u{a:+.17g}" if poly else f"{a:.17g}"
        fitted = f"pow(1+u,{self.m0})*pow(1-u,{self.m1})*({poly})"
        return head + (f"eps=1/(1+({s.b!r}*pow(1+x,{1 - s.A!r})/x+({s.c_log!r}*log(1+1/x){s.c3:+.17g})/((1+x)*(1+x)))/{s.k!r}"
                       f"+{fitted});")

    def rounded(self, digits: int) -> "UniformForm":
        """The form with every number as printed to ``digits`` significant digits (what a reader types)."""
        r = lambda v: float(f"{v:.{digits - 1}e}")  # noqa: E731
        s = self.skel
        return replace(self, skel=type(s)(*(r(v) for v in astuple(s))), sigma=r(self.sigma), rate=r(self.rate),
                       coef=tuple(r(a) for a in self.coef))

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
        end = d.get("end", "force")
        sk = skeleton(Problem(ex, end))
        stored = type(sk)(*(float(d[f.name]) for f in fields(sk)))
        if stored != sk:   # the skeleton is derived, never read: a stored one must agree with it
            raise ValueError("stored skeleton constants differ from the derived ones")
        if end == "overlap" and int(d["P"]) != OVERLAP_P:
            raise ValueError("overlap form with another power P")
        return cls(ex.alpha, ex.gamma, sk, float(d["sigma"]), int(d.get("m0", 0)), int(d["m1"]),
                   tuple(float(a) for a in d["a"]), float(d["bound_eps"]), float(d["bound_one_minus_eps"]),
                   dict(d.get("measured", {})), end, float(d.get("r", 0.0)))


def _lawson(M: np.ndarray, y: np.ndarray, steps: int = LAWSON_STEPS, ridge: float = 0.0) -> np.ndarray:
    """Least squares of M c ~ y, reweighted towards the minimax solution (Lawson's algorithm); with
    ``ridge`` > 0 the coefficients' norm is penalised (ridge^2 |c|^2 against the mean squared error)."""
    w = np.full(y.size, 1.0 / y.size)
    damp = ridge * math.sqrt(1.0 / y.size) * np.eye(M.shape[1]) if ridge else np.empty((0, M.shape[1]))

    def solve(w):
        sw = np.sqrt(w)
        return np.linalg.lstsq(np.vstack([M * sw[:, None], damp]), np.concatenate([y * sw, np.zeros(len(damp))]),
                               rcond=None)[0]

    for _ in range(max(steps, 1)):   # the first pass, with equal weights, is plain least squares
        c = solve(w)
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


def _shapes(sk, end: str) -> list[tuple[float, int, int, float]]:
    """(sigma, m0, m1, rate) candidates."""
    if end == "overlap":
        sig = sorted(set(SIGMAS) | {sk.A})
        return [(s, 0, m1, r * sk.decay) for s in sig for m1 in OVERLAP_M1 for r in OVERLAP_RATES]
    return [(s, m0, m1, 0.0) for s, m0, m1 in SHAPES(sk.A)]


def fit_uniform(problem: Problem, omega, eps, one_minus_eps, train, select) -> UniformForm:
    """Fit the form for the problem's end rule to reference values: coefficients on ``train`` (a boolean mask), the
    shape chosen by the largest relative error (eps, and 1 - eps for Omega >= 1) on ``select``. The
    returned form's bounds are still unset (they come from a third set of points)."""
    problem = as_problem(problem)
    ex, end = problem.ex, problem.end
    sk = skeleton(problem)
    om = np.asarray(omega, dtype=float)
    eps = np.asarray(eps, dtype=float)
    ome = np.asarray(one_minus_eps, dtype=float)
    if end == "overlap":
        # the log of what the exponential must be: linear in the coefficients, relative in eta
        w, S = sk.parts(om)
        resid, weight = np.log((1.0 / eps - w) / S), np.ones_like(om)
        top, target_err, ridge = OVERLAP_MAX_DEGREE, OVERLAP_SELECTION_TARGET, OVERLAP_RIDGE
    else:
        weight = ome / eps                      # eta - 1, relative accuracy kept near eps = 1
        resid = (weight - sk.eta_minus_one(om)) / weight
        top, target_err, ridge = MAX_DEGREE, SELECTION_TARGET, 0.0
    best = None
    for degree in range(DEGREE, top + 1, DEGREE_STEP):
        for sigma, m0, m1, rate in _shapes(sk, end):
            M = _basis(sk, sigma, m0, m1, rate, om, degree) / weight[:, None]
            c = _lawson(M[train], resid[train], ridge=ridge)
            c = c if end == "overlap" else cheb.cheb2poly(c)
            form = UniformForm(ex.alpha, ex.gamma, sk, float(sigma), m0, m1, tuple(float(x) for x in c),
                               end=end, rate=float(rate))
            with np.errstate(all="ignore"):
                err = max(rel_errors(form, om[select], eps[select], ome[select]))
            if math.isfinite(err) and (best is None or err < best[0]):
                best = (err, form)
        if best is not None and best[0] <= target_err:
            break
    if best is None:
        raise ArithmeticError(f"no uniform form could be fitted for alpha={ex.alpha}, gamma={ex.gamma}")
    return best[1]

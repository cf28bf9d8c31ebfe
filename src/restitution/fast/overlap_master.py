"""The master curve of the overlap end rule (alpha > gamma, where it differs from the force rule):
Chebyshev panels of ln eps in s = ln Omega over [OMEGA_LO, OMEGA_HI], from the compiled integrator
under that rule, built in 1-2 s and evaluated by the force rule's compiled loop
(:func:`restitution.fast.panels.chebyshev_panels_eval`).

Beyond its panels the curve joins the two ends of the overlap rule, evaluated by the same loop:

* below OMEGA_LO, where the bodies cannot stick (alpha < 2 gamma + 1), the viscous limit law
  eps = C Omega^k (:mod:`restitution.core.overlap_limit`), whose correction decays like
  exp(-c/Omega) as Omega falls: already at the panels' first nodes (Omega 1e-4..1e-3) it agrees
  with the integrator to C's own accuracy. Its bound is twice the largest deviation measured at
  those nodes plus the nodes' own accuracy, at least twice C's estimated error, plus the rounding
  of C exp(k ln Omega); it answers down to where C Omega^k leaves the normal doubles (LAW_EPS_MIN);
* above OMEGA_HI the elastic expansion 1 - C1 delta + C2 delta^2, delta = Omega^(-(gamma+1)/(alpha+1))
  (:func:`restitution.core.asymptotics.elastic_limit` without the force rule's end-of-contact term:
  under the overlap rule contact lasts the whole oscillation, and the remainder is measured to fall
  like delta^3). Its bound is SAFETY x R delta^3 plus the nodes' accuracy, with R the largest
  (deviation - node accuracy) / delta^3 measured against the integrator at ELASTIC_CHECKS.

Where the bodies can stick (alpha >= 2 gamma + 1) the build first finds the sticking boundary
(bisection on the integrator's proof of sticking, stored with the curve) and starts the curve at
STICK_MARGIN times it, where ln eps is smooth again.

Bound: twice the largest error at random points of every panel (not nodes) against the integrator
at rtol NODE_RTOL, plus that integrator's own bound under the overlap rule.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np
from numpy.polynomial import chebyshev as cheb

from ..core import asymptotics as asy
from ..core.collision import StickError, stick_bound
from ..core.exponents import as_exponents
from ..core.problem import Problem
from ..core.overlap_limit import overlap_limit
from .master import reference_eps
from .panels import PanelRange, chebyshev_panels_eval
from .rung import TOL_FLOOR, integrator_bound

__all__ = ["OverlapCurve", "build_overlap_curve", "sticking_boundary", "least_bound", "OVERLAP_CURVE_VERSION",
           "OMEGA_LO", "OMEGA_HI", "NODE_RTOL"]

OVERLAP_CURVE_VERSION = 4
#: The panels' widest range (below 1e-4 the creeping return makes each node cost milliseconds).
OMEGA_LO, OMEGA_HI = 1e-4, 1e8
#: The viscous law answers down to where eps = C Omega^k is this small (normal doubles, with room).
LAW_EPS_MIN = 1e-290
#: Nodes at or below this Omega measure the viscous law's deviation.
LAW_CHECK_MAX = 1e-3
#: Where the elastic expansion is measured against the integrator (its validated range ends at 1e14).
ELASTIC_CHECKS = (1e8, 1e9, 1e10, 1e11, 1e12)
#: The elastic expansion's bound is this times its fitted remainder.
SAFETY = 3.0
#: Degree 10 on panels of 0.25 in ln Omega: 3e-12 for 3/2, 1/2 (0.5 left 3.6e-10 near Omega = 0.17),
#: and the force rule's cost per evaluation (degree 14 on 0.5 reached the bound too, 25 % slower).
DEGREE, WIDTH, NODE_RTOL, HELDOUT_PER_PANEL = 10, 0.25, 1e-13, 3
#: Where in each panel a loaded curve is checked against the integrator (not a node).
SPOT_CHECK_AT = 0.37
#: The curve starts this far above a sticking boundary (eps -> 0 there: ln eps is not smooth).
STICK_MARGIN = 4.0
SEED = 20261125


def _sticks(over: Problem, w: float) -> bool:
    try:
        reference_eps(over, [w], 1e-10)
    except (StickError, ArithmeticError):   # the integrator gives up within ~1e-8 of the boundary
        return True
    return False


def _overlap(problem) -> Problem:
    """The overlap rule's problem for these exponents (the only rule this curve is for)."""
    return Problem(as_exponents(problem), "overlap")


def sticking_boundary(problem, lo: float = OMEGA_LO, hi: float = OMEGA_HI) -> float:
    """The Omega below which the bodies stick under the overlap rule, to 1e-6 relative, searched in
    [lo, hi]: 0 where they never stick (alpha < 2 gamma + 1), ``lo`` when they separate at lo
    already (the boundary, if any, lies below). Sticking is the integrator's proof (END_STUCK)."""
    over = _overlap(problem)
    ex = over.ex
    if ex.alpha < 2 * ex.gamma + 1:
        return 0.0
    if ex.alpha == 2 * ex.gamma + 1:
        return stick_bound(ex)   # the whole boundary there, proved in core.collision
    if not _sticks(over, lo):
        return lo
    if _sticks(over, hi):
        raise ArithmeticError(f"alpha={ex.alpha}, gamma={ex.gamma} stick up to Omega = {hi:g}")
    a, b = math.log(lo), math.log(hi)   # sticks at a, separates at b
    while b - a > 1e-6:
        m = 0.5 * (a + b)
        a, b = (m, b) if _sticks(over, math.exp(m)) else (a, m)
    return math.exp(b)


@dataclass
class OverlapCurve(PanelRange):
    alpha: Fraction
    gamma: Fraction
    s0: float
    width: float
    coef: np.ndarray
    bound_inside: float
    stick_below: float = 0.0
    checks: dict = field(default_factory=dict)
    #: The viscous law below the panels: (C, k), or None where the bodies can stick.
    law: tuple | None = None
    law_bound: float = math.nan
    #: The elastic expansion above them: (A, C1, C2), and its fitted remainder coefficient.
    elastic: tuple = (0.0, 0.0, 0.0)
    elastic_remainder: float = math.nan

    @property
    def lowest(self) -> float:
        """The smallest Omega the curve answers for: where the law leaves the normal doubles, or
        the panels' start."""
        if self.law is None:
            return self.omega_lo
        C, k = self.law
        return max(1e-300, (LAW_EPS_MIN / C) ** (1.0 / k))

    def covers(self, lo: float, hi: float) -> bool:
        return self.lowest <= lo and math.isfinite(hi)

    def bound(self, lo: float, hi: float) -> float:
        """The relative bound over Omega in [lo, hi] (inside ``covers``). Within JOIN_SLACK of a
        join either side may answer (the loop decides in ln Omega), so there both sides' bounds hold."""
        slack = 1e-11
        b = 0.0
        if hi >= self.omega_lo * (1 - slack) and lo <= self.omega_hi * (1 + slack):
            b = self.bound_inside
        if lo < self.omega_lo * (1 + slack) and self.law is not None:
            # C exp(k ln Omega): the exponent's rounding, |k ln Omega| ulps (a curve without a law
            # answers from its panels alone, down to its first node)
            b = max(b, self.law_bound + TOL_FLOOR * (1.0 + self.law[1] * abs(math.log(lo))))
        if hi > self.omega_hi * (1 - slack):
            b = max(b, self.elastic_bound(max(lo, self.omega_hi * (1 - slack))))
        return b

    def elastic_bound(self, omega: float) -> float:
        """The elastic expansion's bound at ``omega`` (it falls as Omega grows)."""
        delta = omega ** (-self.elastic[0])
        return SAFETY * self.elastic_remainder * delta ** 3 + least_bound((self.alpha, self.gamma))

    def _kernel_params(self) -> tuple[np.ndarray, np.ndarray]:
        # the loop's "kind 1" viscous form is k Omega^power: here C Omega^k; its elastic form
        # without the end-of-contact term
        vis = np.zeros(5) if self.law is None else np.array([1.0, self.law[0], 0.0, 0.0, self.law[1]])
        A, C1, C2 = self.elastic
        return vis, np.array([A, C1, C2, 0.0, 0.0])

    def eps(self, omega) -> np.ndarray:
        """eps at Omega inside ``covers`` (the caller checks)."""
        om = np.asarray(omega, dtype=float)
        vis, el = self._kernel_params()
        return chebyshev_panels_eval(om, self.s0, self.width, self.coef, vis, el).reshape(om.shape)

    def spot_checks_pass(self) -> bool:
        """Every panel agrees with a fresh integration at one point to its bound (plus the
        integrator's): the cache's digest catches a damaged file, this a wrong curve."""
        over = _overlap((self.alpha, self.gamma))
        nodes = integrator_bound(NODE_RTOL, over)
        least = least_bound(over)
        if not (np.all(np.isfinite(self.coef)) and least <= self.bound_inside < 1e-6):
            return False
        if self.law is not None and not least <= self.law_bound < 1e-6:
            return False
        if not (self.elastic_remainder >= 0.0 and np.all(np.isfinite(self.elastic))):
            return False
        om = np.exp(self.s0 + (np.arange(self.coef.shape[0]) + SPOT_CHECK_AT) * self.width)
        ref = reference_eps(over, om, NODE_RTOL)
        return bool(np.all(np.abs(self.eps(om) / ref - 1) <= 10.0 * (self.bound_inside + nodes)))

    def as_dict(self) -> dict:
        return {"version": OVERLAP_CURVE_VERSION, "alpha": str(self.alpha), "gamma": str(self.gamma),
                "s0": self.s0, "width": self.width, "coef": self.coef.tolist(), "bound_inside": self.bound_inside,
                "stick_below": self.stick_below, "checks": self.checks,
                "law": None if self.law is None else list(self.law),
                "law_bound": None if self.law is None else self.law_bound,
                "elastic": list(self.elastic), "elastic_remainder": self.elastic_remainder}

    @classmethod
    def from_dict(cls, d: dict) -> "OverlapCurve":
        if d.get("version") != OVERLAP_CURVE_VERSION:
            raise ValueError(f"overlap curve version {d.get('version')} != {OVERLAP_CURVE_VERSION}")
        ex = as_exponents(d["alpha"], d["gamma"])
        law = None if d["law"] is None else (float(d["law"][0]), float(d["law"][1]))
        return cls(ex.alpha, ex.gamma, float(d["s0"]), float(d["width"]), np.asarray(d["coef"], dtype=float),
                   float(d["bound_inside"]), float(d["stick_below"]), d.get("checks", {}), law,
                   math.nan if d["law_bound"] is None else float(d["law_bound"]),
                   tuple(float(x) for x in d["elastic"]), float(d["elastic_remainder"]))


def least_bound(problem) -> float:
    """The smallest bound a curve for these exponents states: twice its nodes' own accuracy (the
    build adds twice its measured fit error to it, and a loaded curve stating less was edited).

    Parameters
    ----------
    problem : Problem, Exponents or (alpha, gamma)
        The exponents (the curve is the overlap rule's, whatever rule a Problem names).

    Returns
    -------
    float
        2 x the compiled integrator's bound under the overlap rule at NODE_RTOL.

    Examples
    --------
    >>> least_bound(("3/2", "1/2"))
    1.0000000000000001e-11
    """
    return 2.0 * integrator_bound(NODE_RTOL, _overlap(problem))


def build_overlap_curve(problem, progress=None) -> OverlapCurve:
    """Fit and measure the curve and its two ends (see the module docstring); 1-2 s for the paper's pair."""
    over = _overlap(problem)
    ex = over.ex
    if not ex.alpha > ex.gamma:
        raise ValueError("for alpha <= gamma the overlap rule is the force rule: use the force rule's master curve")
    say = progress or (lambda m: None)
    stick = sticking_boundary(over)
    lo = OMEGA_LO if stick <= OMEGA_LO else STICK_MARGIN * stick
    s0, s1 = math.log(lo), math.log(OMEGA_HI)
    npan = int(math.ceil((s1 - s0) / WIDTH - 1e-9))
    k = np.arange(DEGREE + 1)
    x = np.cos(np.pi * (k + 0.5) / (DEGREE + 1))
    nodes = s0 + (np.arange(npan)[:, None] + (x[None, :] + 1.0) / 2.0) * WIDTH
    say(f"overlap rule: {npan} panels x {DEGREE + 1} nodes on Omega in [{lo:.3g}, {math.exp(s0 + npan * WIDTH):.3g}]")
    vals = np.log(reference_eps(over, np.exp(nodes.ravel()), NODE_RTOL)).reshape(npan, DEGREE + 1)
    coef = np.array([cheb.chebfit(x, v, DEGREE) for v in vals])
    curve = OverlapCurve(ex.alpha, ex.gamma, s0, WIDTH, coef, math.nan, stick)
    rng = np.random.default_rng(SEED)
    held = np.exp(s0 + (np.arange(npan)[:, None] + rng.uniform(0, 1, (npan, HELDOUT_PER_PANEL))) * WIDTH).ravel()
    ref = reference_eps(over, held, NODE_RTOL)
    fit_err = float(np.max(np.abs(curve.eps(held) / ref - 1.0)))
    curve.bound_inside = float(max(2.0 * fit_err + least_bound(over), 2e-14))
    curve.checks = {"fit_err_heldout": fit_err, "n_heldout": int(held.size), "n_nodes": int(nodes.size),
                    "node_rtol": NODE_RTOL}
    if ex.alpha < 2 * ex.gamma + 1:
        lim = overlap_limit(ex)
        low = nodes.ravel() <= math.log(LAW_CHECK_MAX)
        dev = float(np.max(np.abs(lim.eps(np.exp(nodes.ravel()[low])) / np.exp(vals.ravel()[low]) - 1.0)))
        curve.law = (lim.C, lim.k)
        curve.law_bound = float(max(2.0 * dev + least_bound(over), 2.0 * lim.C_error / lim.C + 4.0 * TOL_FLOOR))
        curve.checks.update(law_deviation=dev, law_nodes=int(np.count_nonzero(low)))
    E = asy.elastic_limit(ex)
    curve.elastic = (E.A, E.C1, E.C2)
    top = np.array(ELASTIC_CHECKS)
    dev = np.abs(E.eps(top, 2, end_term=False) / reference_eps(over, top, NODE_RTOL) - 1.0)
    node = integrator_bound(NODE_RTOL, over)
    curve.elastic_remainder = float(np.max(np.maximum(dev - node, 0.0) / top ** (-3.0 * E.A)))
    curve.checks.update(elastic_deviation=[float(x) for x in dev])
    return curve

"""The choice of contact model a scene makes for each contact: the engine's candidate models,
cheapest first, each calibrated to the target over the scene's speed range and accepted when its
eps(v) stays within the tolerance.

Every candidate is a damping law of the engine (its conventions in the engine's contact module,
restitution.dem.engines) with the scene's normal model. Its eps depends on one scaled parameter,
Omega(v) = C v^k with k = (alpha-1-2gamma)/(gamma+1) and C = D1 D2^(-(alpha+1)/(gamma+1)); so a fit is a search over
the one number log C, the same for every pair of particles with one target (the radii and masses
only turn C into each pair's damping afterwards). k = 0 is a constant-e law: eps is the same at
every speed.

A fit is least squares in eps (over the target's measured points, or over FIT_POINTS speeds of the
range for a constant target; a constant-e law's least squares is eps = the mean target, solved as a
root), and
the check is the largest |eps - target| over the scene's check grid plus the evaluation's own
error bound (restitution.fast.ladder.epsilon at relative EVAL_TOL; see scaled_eps for eps below
SMALL_EPS where the bodies can stick).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from fractions import Fraction

import numpy as np

from ..core.collision import StickError
from ..core.errors import ParameterError
from ..core.problem import Problem
from ..fast.ladder import epsilon
from .contact import Contact

__all__ = ["ContactModel", "Fit", "fit_model", "scaled_eps", "EVAL_TOL", "SMALL_EPS"]

#: Relative tolerance of every eps the scene states (far below any scene tolerance, and what the
#: 1e-9 round trip of a calibration needs).
EVAL_TOL = 1e-10
#: Where the bodies can stick, eps below SMALL_EPS is asked to the absolute EVAL_TOL * SMALL_EPS
#: (see scaled_eps), at most SMALL_EPS_DECADES decades looser than EVAL_TOL; ESTIMATE_TOL is the
#: relative accuracy of the estimate that sorts the points into decades.
SMALL_EPS = 0.1
SMALL_EPS_DECADES = 6
ESTIMATE_TOL = 1e-3
#: log Omega is searched in [1e-4, 1e8]: eps there spans what a scene asks for (eps(1e8) > 0.99
#: for every law here), and the master curves of both end rules and the compiled integrator meet
#: EVAL_TOL all over it (beyond, the ladder may have to fall back on mpmath: minutes).
LOG_OMEGA_RANGE = (math.log(1.01e-4), math.log(0.99e8))   # inside, not on, the curves' ends


@dataclass(frozen=True)
class ContactModel:
    """One candidate: the engine's normal model and damping option, with the model's exponents."""

    name: str
    normal: str
    damping: str
    alpha: Fraction
    gamma: Fraction

    @cached_property
    def k(self) -> Fraction:
        return (self.alpha - 1 - 2 * self.gamma) / (self.gamma + 1)

    @cached_property
    def constant_e(self) -> bool:
        return self.k == 0


def scaled_eps(model: ContactModel, end: str, omega, build: bool | None = None) -> tuple[np.ndarray, float]:
    """eps at each Omega (0 where the overlap rule's attraction keeps the bodies together) and a
    relative error bound r such that r max(eps) bounds every point's absolute error. ``build``: as
    epsilon's (True for a caller that will ask for many more points than this call holds, so that
    the master curves are built once).

    Relative EVAL_TOL, except below SMALL_EPS where the bodies can stick (overlap rule, alpha >=
    2 gamma + 1): there the absolute error EVAL_TOL SMALL_EPS is asked, decade by decade of an
    estimate. Near the sticking boundary eps falls towards 0 and the double-precision integrators
    lose relative accuracy (core.conditioning), so a relative 1e-10 sent the ladder to mpmath: a
    random scene's fit (hertz, velocity damping, e = 0.091) took over 20 minutes for eps that a
    scene only needs to an absolute 1e-8 or worse."""
    om = np.asarray(omega, float)
    if not (end == "overlap" and Fraction(model.alpha) >= 2 * Fraction(model.gamma) + 1):
        return _eps_at(model, end, om, EVAL_TOL, build)
    est, _ = _eps_at(model, end, om, ESTIMATE_TOL, build)
    with np.errstate(divide="ignore"):
        decade = np.clip(np.floor(np.log10(SMALL_EPS / est)), 0, SMALL_EPS_DECADES).astype(int)
    eps, worst = np.zeros(om.shape), 0.0
    for j in np.unique(decade[est > 0]):
        where = (decade == j) & (est > 0)
        e, r = _eps_at(model, end, om[where], EVAL_TOL * 10.0 ** j, build)
        eps[where] = e
        worst = max(worst, r * float(np.max(e, initial=0.0)))
    top = float(np.max(eps, initial=0.0))
    return eps, (worst / top if top > 0 else 0.0)


def _epsilon(model: ContactModel, end: str, om, tol: float, build: bool | None):
    """epsilon() for a scene. With build None (a scene too small to build curves for) by the cheapest
    method that reads no build wherever one meets ``tol`` (``cached=False``, as with an empty cache:
    the exact family's closed form for alpha = 2 gamma + 1, such as Hertz with tsuji damping,
    otherwise the compiled integrator): a master curve cached by some earlier run agrees with it
    within the bound but not bit for bit, and a least-squares fit's damping moved in its 8th digit
    with the cache's state (the small scene's glass-steel line: 1212924442.54 with an empty cache,
    1212924487.03 with curves cached)."""
    problem = Problem.of(model.alpha, model.gamma, end)
    if build is None:
        try:
            return epsilon(problem, omega=om, tol=tol, build=False, cached=False)
        except StickError:
            raise
        except ParameterError:
            pass    # the integrator does not reach tol here: the cheapest method that does
    return epsilon(problem, omega=om, tol=tol, build=build)


def _eps_at(model: ContactModel, end: str, om: np.ndarray, tol: float, build: bool | None) -> tuple[np.ndarray, float]:
    """eps at each Omega to relative ``tol`` (0 where the bodies stick) and the relative bound."""
    try:
        r = _epsilon(model, end, om, tol, build)
        return np.asarray(r.eps, float), float(r.error_bound)
    except StickError:
        pass
    # the bodies stick below some Omega (the attraction wins where damping is strong): find where
    # by bisection over the sorted Omegas, one point a call, then evaluate the rest at once
    flat = om.ravel()
    order = np.argsort(flat)
    lo, hi = 0, flat.size
    while lo < hi:
        mid = (lo + hi) // 2
        try:
            _epsilon(model, end, [flat[order[mid]]], tol, build)
            hi = mid
        except StickError:
            lo = mid + 1
    out, bound = np.zeros(flat.size), 0.0
    if lo < flat.size:
        try:
            r = _epsilon(model, end, flat[order[lo:]], tol, build)
        except StickError:   # not one boundary after all: point by point
            for i in order[lo:]:
                try:
                    one = _epsilon(model, end, [flat[i]], tol, build)
                except StickError:
                    continue
                out[i], bound = float(one.eps[0]), max(bound, float(one.error_bound))
            return out.reshape(om.shape), bound
        out[order[lo:]], bound = np.asarray(r.eps, float), float(r.error_bound)
    return out.reshape(om.shape), bound


@dataclass(frozen=True)
class Fit:
    """A model fitted to a target over the scene's speeds: log C, eps on the check grid, the worst
    deviation (absolute, evaluation bound included) and where, and whether it meets the tolerance.
    ``reason`` says why a model could not be fitted at all (then log_c is None)."""

    model: ContactModel
    log_c: float | None
    max_deviation: float
    at_speed: float | None
    accepted: bool
    error_bound: float = math.inf
    grid: tuple = ()
    eps: tuple = ()
    reason: str = ""

    def omega(self, speeds) -> np.ndarray:
        return np.exp(self.log_c) * np.asarray(speeds, float) ** float(self.model.k)

    def damped(self, base: Contact) -> Contact:
        """``base`` with the damping D2 that puts its Omega(v) on the fitted C v^k."""
        p = float((self.model.alpha + 1) / (self.model.gamma + 1))
        return Contact(base.alpha, base.gamma, base.D1, math.exp((math.log(base.D1) - self.log_c) / p), base.end)

    def as_dict(self) -> dict:
        return {"name": self.model.name, "damping": self.model.damping, "alpha": str(self.model.alpha),
                "gamma": str(self.model.gamma), "constant_e": self.model.constant_e,
                "max_deviation": self.max_deviation, "at_speed": self.at_speed, "accepted": self.accepted,
                **({"reason": self.reason} if self.reason else {})}


#: Points per round of the vectorised searches below: one evaluation of many Omegas costs about
#: what one of a single Omega does (the ladder's overhead), so each round narrows by this factor.
SEARCH_POINTS = 64
SEARCH_ROUNDS = 12


def _root(model: ContactModel, end: str, target: float, build: bool | None) -> float:
    """log Omega with eps(Omega) = target over LOG_OMEGA_RANGE (eps grows with Omega), by rounds
    of SEARCH_POINTS evaluations that each keep the cell where eps crosses the target. Omega >= 1
    first: below it the overlap rule comes near sticking, where only the integrator serves and
    slowly, and few scenes ask for such eps."""
    lo, hi = LOG_OMEGA_RANGE
    for a, b in ((0.0, hi), (lo, 0.0)):
        s = np.linspace(a, b, SEARCH_POINTS + 1)
        e = scaled_eps(model, end, np.exp(s), build)[0] - target
        if e[0] < 0.0 <= e[-1]:
            break
    else:
        raise ParameterError("e", target, f"{model.name} cannot reach it (its eps over Omega in [1e-4, 1e8] "
                                          f"is {e[0] + target:.6g} to {e[-1] + target:.6g})")
    for _ in range(SEARCH_ROUNDS):
        i = int(np.argmax(e >= 0.0))
        a, b = s[i - 1], s[i]
        if b - a <= 1e-13 * max(1.0, abs(a)):
            break
        s = np.linspace(a, b, SEARCH_POINTS + 1)
        e = scaled_eps(model, end, np.exp(s), build)[0] - target
    i = int(np.argmax(e >= 0.0))
    a, b, ea, eb = s[i - 1], s[i], e[i - 1], e[i]
    return float(a + (b - a) * (-ea / (eb - ea))) if eb > ea else float(a)


def _least_squares(model: ContactModel, end: str, fv, fe, s0: float, width: float, build) -> float:
    """log C minimising sum (eps(C v^k) - e)^2, by rounds of SEARCH_POINTS trial values around the
    best so far (all points of a round in one evaluation)."""
    k = float(model.k)
    logs = k * np.log(fv)
    a = max(s0 - width, LOG_OMEGA_RANGE[0] - float(np.min(logs)))   # every trial Omega in the range
    b = min(s0 + width, LOG_OMEGA_RANGE[1] - float(np.max(logs)))
    best = s0
    for _ in range(SEARCH_ROUNDS):
        s = np.linspace(a, b, SEARCH_POINTS + 1)
        om = np.exp(s)[:, None] * (fv ** k)[None, :]
        e = scaled_eps(model, end, om.ravel(), build)[0].reshape(om.shape)
        j = int(np.argmin(np.sum((e - fe[None, :]) ** 2, axis=1)))
        best, h = s[j], s[1] - s[0]
        a, b = best - h, best + h
        if h <= 1e-11 * max(1.0, abs(best)):
            break
    return float(best)


def fit_model(model: ContactModel, end: str, target, grid, tolerance: float, build: bool | None = None) -> Fit:
    """Calibrate ``model`` to ``target`` (a scene.file.Target) and check it on ``grid`` (speeds);
    ``build`` as :func:`scaled_eps`'s."""
    fv, fe = target.fit_points(grid)
    k = float(model.k)
    try:
        # the constant-e law's least squares, and the speed-dependent laws' starting point
        v_mid = math.exp(float(np.mean(np.log(fv))))
        s0 = _root(model, end, float(np.mean(fe)), build) - k * math.log(v_mid)
    except ParameterError as err:
        return Fit(model, None, math.inf, None, False, reason=err.allowed)
    if k != 0.0:
        width = abs(k) * math.log(grid[-1] / grid[0]) + math.log(10.0)
        s0 = _least_squares(model, end, np.asarray(fv, float), np.asarray(fe, float), s0, width, build)
    eps, bound = scaled_eps(model, end, np.exp(s0) * np.asarray(grid) ** k, build)
    dev = np.abs(eps - target.at(grid))
    i = int(np.argmax(dev))
    worst = float(dev[i] + bound * np.max(eps))
    return Fit(model, float(s0), worst, float(grid[i]), worst <= tolerance, float(bound * np.max(eps)),
               tuple(float(v) for v in grid), tuple(float(e) for e in eps))

"""The method ladder for eps(Omega) and ``epsilon()``, which picks the cheapest rung that meets a tolerance.

Rungs (cheapest first; bounds are relative errors in eps, measured against the references on points
not used to build the rung; "cal" = needs the calibration bundle, built once per exponents and cached):

======================  =========================================  ============================  ========
rung                    what                                       domain                        cost/pt
======================  =========================================  ============================  ========
paper-c          (cal)  Omega~ = c0 + c1 Omega + c2 Omega^2 with    alpha=3/2, gamma=1 where the   ~2e-8 s
                        the paper's printed c0-c2, eps =            measured error is finite
                        (Omega~/Omega)^((gamma+1)/(alpha-1-2gamma))
fitted-c         (cal)  the same with c0-c2 fitted (least squares)  alpha-1-2gamma != 0            ~2e-8 s
                        to the exact connection, Omega in [0.1, 3]
perturbation-N<n>(cal)  the same with c0-c2 from the paper's        where the reading is defined   ~2e-8 s
                        procedure on the exact series to Omega^n
                        (n = 1..4, reading "converged, linear Delta")
pade-mp2011      (cal)  Mueller & Poeschel's Pade form in           alpha=3/2, gamma=1/2           ~2e-8 s
                        v = Omega^(-3/10)
viscous          (cal)  small-Omega expansion (asymptotics)         Omega <= 1e-3                  ~2e-8 s
elastic          (cal)  large-Omega expansion (asymptotics)         Omega >= 1e2                   ~3e-8 s
closed-form             exact: alpha = gamma (asymptotics) or the   alpha=gamma; alpha=1,gamma=0   5e-7 s
                        linear spring-dashpot (core.dashpot);                                      5e-6 s
                 (cal)  otherwise the uniform form (core.uniform)   alpha>gamma, Omega in          ~1e-7 s
                                                                    [1e-8, 1e8]
master           (cal)  Chebyshev master curve + expansions         all Omega > 0                  ~4e-8 s
integrator              compiled DOP853 (fast.integrator), rtol     Omega in [1e-12, 1e14]         2e-5 to
                        from tol                                    (alpha<=gamma: >= 1e-5)        7e-5 s
reference               core.collision.collide (scipy)              all                            ~1e-2 s
highprec                core.highprec (mpmath Taylor)               all (alpha<=gamma: >= 1e-3)    0.15 s and
                                                                                                   more at small
                                                                                                   Omega
======================  =========================================  ============================  ========

Bounds:

* relation rungs, Pade, expansions inside the calibration grid (Omega 1e-12..1e14 in steps of
  0.1 decade): SAFETY x the largest error at the grid points bracketing the inputs + the grid's own
  accuracy; expansions beyond the grid: the fitted remainder model of :mod:`restitution.fast.master`;
* master: measured held-out error inside its range (x2), expansion bounds outside;
* integrator: INTEGRATOR_BOUND_FACTOR rtol + INTEGRATOR_BOUND_FLOOR (validated against mpmath);
* reference: 10 rtol + 1e-13 (validated against mpmath); highprec: 10^(1 - digits), at least the
  2.3e-16 of rounding to a double (and its own two-run error estimate must agree, else it raises);
* closed-form: 2e-14 (validated against mpmath) where exact; the uniform form: its stated bound
  (twice the largest error on points used neither in its fit nor in the choice of its shape).

End rule: every rung above computes the "force" rule; an ``end="overlap"`` request goes to the rungs
of :mod:`restitution.fast.overlap` instead (for alpha <= gamma the rules coincide and all serve).

Choice: among rungs whose domain holds every input and whose bound over the inputs is <= tol, the
least expected time (setup + n x cost). The calibration bundle is built (seconds, cached on disk) only
when that is cheaper than the best rung that does not need it, or when nothing else meets tol.
A tolerance no rung meets raises ParameterError naming the best bound available.
"""

from __future__ import annotations

import hashlib
import math
import sys
from dataclasses import dataclass
from fractions import Fraction
from typing import Callable

import numpy as np

from ..core import asymptotics as asy
from . import cache as _cache
from ..core.errors import ParameterError, number_in, real_array
from ..core.model import OMEGA_REPRESENTABLE, at_most_one
from ..core.results import end_rule
from ..core.exponents import Exponents, as_exponents
from ..core.connection import eps_from_connection
from .calibration import (CALIBRATION_VERSION, FITTED_C, MUELLER_POESCHEL_PADE, Calibration, Relation,
                          _viscous_eval, build_calibration, pade_mp2011)
from .master import MASTER_VERSION, MasterCurve, MasterSettings, integrator_bound, reference_eps, stiff_omega_min
from .uniform_eval import uniform_eps
from .slow_rungs import HIGHPREC_COST, _dashpot_eps, _highprec_cost, _highprec_eps, _scipy_eps

__all__ = ["EpsResult", "Ladder", "epsilon", "rung_names", "SAFETY", "MUELLER_POESCHEL_PADE"]

#: Profile bounds are SAFETY times the largest measured error at the bracketing grid points.
SAFETY = 3.0
#: Rough seconds per point (measured by benchmarks/speed_accuracy.py on one core).
COST = {"relation": 2e-8, "pade": 2e-8, "viscous": 2e-8, "elastic": 3e-8, "closed-equal": 5e-7, "uniform": 1e-7,
        "closed-dashpot": 5e-6, "master": 4e-8, "integrator": 6e-5, "reference": 1e-2, "highprec": HIGHPREC_COST}
#: Rough seconds to build a calibration bundle that is not cached.
BUILD_COST = {"alpha>gamma": 15.0, "alpha<=gamma": 30.0}


# ------------------------------------------------------------------------------------------ result
@dataclass(frozen=True)
class EpsResult:
    """What ``epsilon`` returns: eps (numpy array, same shape as the input), the rung used and its bound.

    ``setting`` describes the rung's parameter (e.g. "rtol=1e-10"); ``candidates`` is the chooser's
    table: one dict per rung with its bound over these inputs (inf when outside its domain), the
    expected cost and why it was or was not eligible.
    """

    eps: np.ndarray
    method: str
    error_bound: float
    omega: np.ndarray
    alpha: Fraction
    gamma: Fraction
    tol: float
    setting: str = ""
    candidates: tuple = ()
    coefficients: dict | None = None   # the closed form's numbers, when that rung answered

    def __array__(self, dtype=None, copy=None):
        return np.asarray(self.eps, dtype=dtype)

    def as_dict(self) -> dict:
        return {"eps": np.asarray(self.eps, float).ravel().tolist(), "method": self.method,
                "error_bound": float(self.error_bound), "alpha": str(self.alpha), "gamma": str(self.gamma),
                "tol": self.tol, "setting": self.setting,
                **({} if self.coefficients is None else {"coefficients": self.coefficients})}


# ------------------------------------------------------------------------------------------ helpers
def _omega_array(omega, field_name: str = "omega") -> np.ndarray:
    lo, hi = OMEGA_REPRESENTABLE
    allowed = f"must be numbers in [{lo:g}, {hi:g}] (at least one)"
    arr = real_array(field_name, omega, allowed)
    if arr.size == 0:
        raise ParameterError(field_name, omega, allowed)
    # Subnormal or near-overflow Omega leaves no headroom for the expansions' powers of Omega.
    bad = ~(np.isfinite(arr) & (arr >= lo) & (arr <= hi))
    if np.any(bad):
        raise ParameterError(field_name, float(arr[bad].flat[0]), allowed)
    return arr


#: Tolerance when none is given (and no method is forced).
DEFAULT_TOL = 1e-9
#: No method returns a double closer than this to the true eps (rounding of the result itself).
TOL_FLOOR = 2.3e-16


def _check_tol(tol) -> float:
    # Refuse an unreachable tolerance at once, before any master curve is built for nothing.
    return number_in("tol", tol, TOL_FLOOR, 1.0, hi_open=True, why="no method returns a double closer than that")


# ------------------------------------------------------------------------------------------ rungs
@dataclass
class _Quote:
    name: str
    bound: float
    cost: float
    setting: str = ""
    reason: str = ""
    needs_cal: bool = False
    run: Callable | None = None
    coefficients: dict | None = None


def _calibrated_names(relations) -> list[str]:
    return [*(r.name for r in relations), "pade-mp2011", "viscous", "elastic", "master"]


def rung_names(relations=(FITTED_C,)) -> tuple[str, ...]:
    """The ladder's rungs, cheapest kinds first, for these relation rungs."""
    *cal, master = _calibrated_names(relations)
    return (*cal, "closed-form", master, "integrator", "reference", "highprec")


#: Where in each Chebyshev panel a loaded master curve is checked against the integrator (a
#: fraction of the panel's width, away from the nodes the curve was fitted on).
SPOT_CHECK_AT = 0.37


def _spot_checks_pass(ex: Exponents, m: MasterCurve) -> bool:
    """Every panel of the curve agrees with a fresh integration at one point, to its own bound (plus
    the integrator's): the sealed digest catches a damaged file, this a wrong curve (a few ms)."""
    om = np.exp(m.s0 + (np.arange(m.coef.shape[0]) + SPOT_CHECK_AT) * m.width)
    ref = reference_eps(ex, None, om, 1e-13)
    err = np.abs(m.eps(om) - ref) / ref
    return bool(np.all(err <= 10.0 * (m.bound_at(om) + integrator_bound(1e-13))))


def _uniform_checks_pass(ex: Exponents, u) -> bool:
    """The stored uniform form is there exactly when it should be and meets its bound at a few points."""
    if u is None:
        return not ex.alpha > ex.gamma
    if (u.alpha, u.gamma) != (ex.alpha, ex.gamma) or not 0 < u.bound_eps < 1:
        return False
    om = np.geomspace(1e-7, 1e7, 8) * 1.37
    ref = reference_eps(ex, None, om, 1e-13)
    return bool(np.all(np.abs(u.eps(om) / ref - 1) <= u.bound_eps))


def _viscous_domain(ex: Exponents, omega_max: float) -> str | None:
    """Why the viscous expansion does not serve up to ``omega_max`` (None if it does)."""
    limit = 1e-3 if ex.alpha > ex.gamma else 1e-2   # the "force" kind of asy.viscous_limit
    return f"Omega > {limit:g}" if omega_max > limit else None


class Ladder:
    """The ladder for one pair of exponents (and one calibration setting / cache directory)."""

    def __init__(self, alpha, gamma, *, settings: MasterSettings | None = None, cache_dir=None,
                 stream=None, relations: tuple[Relation, ...] = (FITTED_C,)):
        self.ex = as_exponents(alpha, gamma)
        self.relations = tuple(relations)
        self.rung_names = rung_names(self.relations)
        self.settings = settings or MasterSettings()
        self.cache_dir = cache_dir
        self.stream = stream
        self._cal: Calibration | None = None

    # -- calibration bundle
    @property
    def cache_key(self) -> str:
        # the relation rungs are part of the bundle: a ladder with other ones builds its own
        key = self.settings.key() + "|" + ",".join(r.name for r in self.relations)
        return (f"calibration-a{self.ex.alpha}-g{self.ex.gamma}-v{CALIBRATION_VERSION}.{MASTER_VERSION}"
                f"-{hashlib.sha256(key.encode()).hexdigest()[:12]}")

    def _valid(self, d: dict) -> bool:
        try:
            cal = Calibration.from_dict(d)
        except Exception:  # noqa: BLE001 - anything unreadable is rebuilt
            return False
        m = cal.master
        return (m.alpha == self.ex.alpha and m.gamma == self.ex.gamma and m.settings == self.settings
                and bool(np.all(np.isfinite(m.coef))) and _spot_checks_pass(self.ex, m)
                and _uniform_checks_pass(self.ex, cal.uniform))

    def cached_calibration(self) -> Calibration | None:
        if self._cal is None:
            from pathlib import Path
            stream = sys.stderr if self.stream is None else self.stream
            path = _cache.cache_path(self.cache_key, Path(self.cache_dir) if self.cache_dir else None)
            # a bad entry is removed with one note: read, refused and reported on every call
            # otherwise, and never replaced when the request is served without building
            d = _cache.load_or_discard(path, stream, self._valid,
                                       "does not pass its checks against the integrator")
            if d is not None:
                self._cal = Calibration.from_dict(d)
        return self._cal

    def calibration(self) -> Calibration:
        if self.cached_calibration() is None:
            from pathlib import Path
            stream = sys.stderr if self.stream is None else self.stream

            def progress(msg):
                print(f"restitution:   {msg}", file=stream, flush=True)

            d = _cache.get_or_build(
                self.cache_key, lambda: build_calibration(self.ex, None, self.settings, progress, self.relations).as_dict(),
                valid=self._valid, what=f"the master curve for alpha={self.ex.alpha}, gamma={self.ex.gamma}",
                directory=Path(self.cache_dir) if self.cache_dir else None, stream=stream)
            self._cal = Calibration.from_dict(d)
        return self._cal

    @property
    def master(self) -> MasterCurve:
        return self.calibration().master

    # -- quotes
    def _profile_bound(self, cal: Calibration, name: str, lo10: float, hi10: float) -> float:
        g = cal.master.grid_log10_omega
        e = cal.profiles[name]
        if lo10 < g[0] - 1e-9 or hi10 > g[-1] + 1e-9:
            return math.inf
        i0 = max(0, int(np.searchsorted(g, lo10, side="right")) - 1)
        i1 = min(g.size - 1, int(np.searchsorted(g, hi10, side="left")))
        worst = float(np.max(e[i0:i1 + 1]))
        return SAFETY * worst + integrator_bound(cal.master.settings.rtol)

    def quotes(self, omega: np.ndarray, tol: float) -> list[_Quote]:
        """Every rung with its bound over ``omega``, cost and a runner (None when not applicable)."""
        ex = self.ex
        n = omega.size
        lo, hi = float(omega.min()), float(omega.max())
        lo10, hi10 = math.log10(lo), math.log10(hi)
        cal = self.cached_calibration()
        out: list[_Quote] = []
        big = ex.alpha > ex.gamma

        # calibrated rungs
        cal_names = _calibrated_names(self.relations)
        if cal is None:
            for name in cal_names:
                cost = COST["master"] if name == "master" else COST["relation"]
                # a rung's domain does not depend on the cache: say it first, so the answer is the
                # same on a fresh machine and on one that built the bundle
                outside = _viscous_domain(ex, hi) if name == "viscous" else None
                out.append(_Quote(name, math.inf, 0.0, reason=outside) if outside else
                           _Quote(name, math.nan, cost * n, reason="needs the calibration bundle (not built yet)",
                                  needs_cal=True))
        else:
            for name in cal_names:
                out.append(self._cal_quote(cal, name, omega, lo10, hi10, n))

        # closed forms
        if ex.alpha == ex.gamma:
            out.append(_Quote("closed-form", 2e-14, COST["closed-equal"] * n, "alpha = gamma",
                              run=lambda om: asy.equal_exponents_eps(om),
                              coefficients={"exact": "alpha = gamma (restitution.core.asymptotics.equal_exponents_eps)"}))
        elif ex.alpha == 1 and ex.gamma == 0:
            out.append(_Quote("closed-form", 2e-14, COST["closed-dashpot"] * n, "spring-dashpot",
                              run=_dashpot_eps, coefficients={"exact": "linear spring-dashpot (restitution.core.dashpot)"}))
        elif not big:
            out.append(_Quote("closed-form", math.inf, 0.0, reason="alpha < gamma: the viscous limit's first "
                              "correction, which the uniform form needs, is not known in closed form"))
        else:
            out.append(self._uniform_quote(cal, lo, hi, n))

        # compiled integrator
        wmin = stiff_omega_min(ex, None)
        if lo < wmin or hi > 1e14:
            out.append(_Quote("integrator", math.inf, math.inf,
                              reason=f"Omega outside [{wmin:g}, 1e14] (explicit method; stiff below)"))
        else:
            rtol = min(1e-6, max(1e-14, (tol - integrator_bound(0.0)) / (2 * 10.0)))
            cost = COST["integrator"] * n * (1.0 if big else (1.0 + 1e-3 / lo))
            out.append(_Quote("integrator", integrator_bound(rtol), cost, f"rtol={rtol:.3g}",
                              run=lambda om, r=rtol: reference_eps(ex, None, om, r)))

        # scipy reference, only where its accuracy was verified (collision.OMEGA_RANGE)
        from ..core.collision import OMEGA_RANGE

        rtol_s = min(1e-6, max(1e-14, (tol - 1e-13) / 20.0))
        if lo < OMEGA_RANGE[0] or hi > OMEGA_RANGE[1]:
            out.append(_Quote("reference", math.inf, math.inf,
                              reason=f"Omega outside [{OMEGA_RANGE[0]:g}, {OMEGA_RANGE[1]:g}] (its verified range)"))
        else:
            out.append(_Quote("reference", 10.0 * rtol_s + 1e-13, COST["reference"] * n, f"rtol={rtol_s:.3g}",
                              run=lambda om, r=rtol_s: _scipy_eps(ex, om, r)))

        # mpmath reference
        if not big and lo < 1e-3:
            out.append(_Quote("highprec", math.inf, math.inf, reason="Omega < 1e-3 with alpha <= gamma (creeping)"))
        else:
            digits = int(min(60, max(15, math.ceil(-math.log10(tol)) + 3)))
            out.append(_Quote("highprec", max(10.0 ** (1 - digits), TOL_FLOOR), _highprec_cost(omega, digits),
                              f"digits={digits}", run=lambda om, d=digits: _highprec_eps(ex, om, d, self.stream)))
        return out

    def _uniform_quote(self, cal: Calibration | None, lo: float, hi: float, n: int) -> _Quote:
        from ..core.uniform import FORM_RANGE
        if lo < FORM_RANGE[0] or hi > FORM_RANGE[1]:
            return _Quote("closed-form", math.inf, 0.0,
                          reason=f"Omega outside [{FORM_RANGE[0]:g}, {FORM_RANGE[1]:g}] (where its bound was measured)")
        if cal is None:
            return _Quote("closed-form", math.nan, COST["uniform"] * n,
                          reason="needs the calibration bundle (not built yet)", needs_cal=True)
        u = cal.uniform
        return _Quote("closed-form", u.bound_eps, COST["uniform"] * n, "uniform form",
                      run=lambda om: uniform_eps(u, om),
                      coefficients={**u.coefficients(), "bound_one_minus_eps": u.bound_one_minus_eps})

    def _cal_quote(self, cal: Calibration, name: str, omega, lo10, hi10, n) -> _Quote:
        ex = self.ex
        m = cal.master
        if name == "master":
            return _Quote(name, m.bound(omega), COST["master"] * n, f"{m.coef.shape[0]} panels",
                          run=lambda om: m.eps(om))
        if name in cal.unavailable:
            return _Quote(name, math.inf, 0.0, reason=cal.unavailable[name])
        if name in ("viscous", "elastic"):
            if name == "viscous":
                outside = _viscous_domain(ex, 10 ** hi10)
                if outside:
                    return _Quote(name, math.inf, 0.0, reason=outside)
                model = m.viscous_bound
                run = lambda om: _viscous_eval(m, om)  # noqa: E731
            else:
                if 10 ** lo10 < 1e2:
                    return _Quote(name, math.inf, 0.0, reason="Omega < 100")
                model = m.elastic_bound
                run = lambda om: m.elastic.eps(om, 2)  # noqa: E731
            g = m.grid_log10_omega
            b = 0.0
            if hi10 >= g[0] and lo10 <= g[-1]:
                b = self._profile_bound(cal, name, max(lo10, g[0]), min(hi10, g[-1]))
            ends = np.array([10 ** lo10, 10 ** hi10])
            outside = ends[(np.log10(ends) < g[0]) | (np.log10(ends) > g[-1])]
            if outside.size:
                b = max(b, float(np.max(SAFETY * model(outside))))
            return _Quote(name, b, COST[name] * n, "expansion", run=run)
        if name not in cal.profiles:
            return _Quote(name, math.inf, 0.0, reason="not calibrated")
        b = self._profile_bound(cal, name, lo10, hi10)
        if name == "pade-mp2011":
            run = pade_mp2011
            cost = COST["pade"]
        else:
            c = cal.relations[name]["c"]
            run = lambda om, c=c: eps_from_connection(ex, None, om, c)  # noqa: E731
            cost = COST["relation"]
        reason = "" if math.isfinite(b) else "no finite measured error over these Omegas (outside the grid or the relation breaks down)"
        return _Quote(name, b, cost * n, "c0-c2" if name != "pade-mp2011" else "", reason=reason, run=run)

    # -- the choice
    def evaluate(self, omega, *, tol: float | None = DEFAULT_TOL, method: str | None = None,
                 build: bool | None = None, end: str = "force") -> EpsResult:
        om = _omega_array(omega)
        # A forced method without a tolerance answers with its own bound (tol only sets the
        # integrators' settings then); otherwise the default tolerance applies.
        checked = tol is not None or method is None
        tol = _check_tol(DEFAULT_TOL if tol is None else tol)
        if build is not None and not isinstance(build, bool):   # build="no" is truthy: it would build
            raise ParameterError("build", build, "must be True, False or None")
        if method is not None and method not in self.rung_names:
            raise ParameterError("method", method, f"must be one of {', '.join(self.rung_names)}")
        flat = om.ravel()
        if end_rule(end) == "overlap" and self.ex.alpha > self.ex.gamma:
            # only the rungs that know the overlap rule (its docstring); none of them is built
            from .overlap import overlap_quotes
            quotes, build = overlap_quotes(self.ex, flat, tol), False
        else:
            quotes = self.quotes(flat, tol)
        if build is not False and self.cached_calibration() is None:
            need = method is not None and any(q.name == method and q.needs_cal for q in quotes)
            if build or need or self._building_pays(quotes, tol, flat.size):
                self.calibration()
                quotes = self.quotes(flat, tol)
        if method is not None:
            q = next((q for q in quotes if q.name == method), None)
            if q is None:   # a rung that is not quoted for this end rule at all (the relation rungs)
                raise ParameterError("method", method, f"does not serve end = {end}; the rungs that do: "
                                     + ", ".join(q.name for q in quotes if q.run is not None))
            if q.run is None:
                raise ParameterError("method", method, f"not available here: {q.reason or 'needs the calibration'}")
            if checked and not q.bound <= tol:
                raise ParameterError("tol", tol, f"method {method} has bound {q.bound:.3g} over these Omegas")
            chosen = q
        else:
            ok = [q for q in quotes if q.run is not None and q.bound <= tol]
            if not ok:
                finite = [q for q in quotes if q.run is not None and math.isfinite(q.bound)]
                best = min(finite, key=lambda q: q.bound) if finite else None
                hint = (f"the smallest bound over these Omegas is {best.bound:.3g} ({best.name})" if best
                        else "no method covers these Omegas")
                raise ParameterError("tol", tol, f"no method reaches it: {hint}")
            chosen = min(ok, key=lambda q: (q.cost, q.bound))
        eps = np.asarray(chosen.run(flat), dtype=float)
        if not np.all(np.isfinite(eps)):
            raise ArithmeticError(f"method {chosen.name} returned non-finite eps")
        eps = at_most_one(eps)
        table = tuple({"method": q.name, "bound": q.bound, "cost": q.cost, "setting": q.setting,
                       "available": q.run is not None, "reason": q.reason} for q in quotes)
        return EpsResult(eps.reshape(om.shape), chosen.name, float(chosen.bound), om, self.ex.alpha,
                         self.ex.gamma, tol if checked else None, chosen.setting, table, chosen.coefficients)

    def _building_pays(self, quotes, tol: float, n: int) -> bool:
        """Build the calibration when nothing else meets tol, or when it is cheaper overall."""
        plain = [q.cost for q in quotes if not q.needs_cal and q.run is not None and q.bound <= tol]
        setup = BUILD_COST["alpha>gamma" if self.ex.alpha > self.ex.gamma else "alpha<=gamma"]
        return not plain or setup + COST["master"] * n < min(plain)


# --------------------------------------------------------------------------------- the public call
_LADDERS: dict = {}


def _ladder(ex: Exponents, relations) -> Ladder:
    key = (ex.alpha, ex.gamma, _cache.cache_dir(), tuple(relations))
    if key not in _LADDERS:
        _LADDERS[key] = Ladder(ex, None, relations=relations)
    return _LADDERS[key]


def epsilon(*, alpha, gamma, omega=None, g=None, D1=None, D2=None, tol: float | None = DEFAULT_TOL,
            method: str | None = None, build: bool | None = None,
            relations: tuple[Relation, ...] = (FITTED_C,), end: str = "force") -> EpsResult:
    """Coefficient of restitution to a relative tolerance ``tol``, by the cheapest adequate method.

    Give either ``omega`` (scaled parameter, scalar or array) or the impact speeds ``g`` with the
    material constants ``D1``, ``D2`` (Omega = D1 g^((alpha-1-2gamma)/(gamma+1)) D2^(-(alpha+1)/(gamma+1))).
    Returns an :class:`EpsResult`: ``.eps`` (numpy array shaped like the input), ``.method``,
    ``.error_bound`` (relative, over all inputs), ``.candidates`` (the chooser's table).
    ``method`` forces a rung (it must still meet ``tol``, unless ``tol`` is None: then it answers
    with whatever bound it has); ``build`` = False never builds the
    calibration bundle, True always does, None (default) builds it when that pays.
    ``relations`` are the relation rungs (:mod:`restitution.api` adds the paper's). ``end``: the
    end-of-contact rule; "overlap" is served only by the rungs of :mod:`restitution.fast.overlap`.
    Raises ParameterError for bad input and for a tolerance no rung meets.
    """
    ex = as_exponents(alpha, gamma)
    if omega is not None:
        if g is not None or D1 is not None or D2 is not None:
            raise ParameterError("omega", omega, "give either omega or all of g, D1, D2, not both")
        om = _omega_array(omega, "omega")
    else:
        if g is None or D1 is None or D2 is None:
            missing = [n for n, v in (("g", g), ("D1", D1), ("D2", D2)) if v is None]
            raise ParameterError(missing[0], None, "give omega, or all of g, D1, D2")
        from ..core.model import Material
        gs = _omega_array(g, "g")
        with np.errstate(over="ignore", under="ignore"):
            om = np.asarray(Material(ex, None, D1, D2).omega(gs), dtype=float).reshape(gs.shape)
        om = _omega_array(om, "omega")  # Omega itself may over/underflow for extreme inputs
    return _ladder(ex, relations).evaluate(om, tol=tol, method=method, build=build, end=end)

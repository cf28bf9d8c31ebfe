"""The method ladder for eps(Omega) and ``epsilon()``, which picks the cheapest rung that meets a tolerance.

Rungs (cheapest first; bounds are relative errors in eps, measured against the references on points
not used to build the rung; "cal" = needs the calibration bundle, built once per exponents and cached;
"ovl" = needs the overlap rule's own curve, built alone in seconds and cached):

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
                 (ovl)  overlap rule: its own curve, Chebyshev      Omega in [1e-4, 1e8], above    ~4e-8 s
                        only (fast.overlap_master), built alone     a sticking boundary
                        in 1-2 s
integrator              compiled DOP853 (fast.integrator), rtol     Omega in [1e-12, 1e14]         2e-5 to
                        from tol; both end rules                    (alpha<=gamma, overlap rule:   7e-5 s
                                                                    >= 1e-5)
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

End rule: each rung declares the rules it serves where they differ (alpha > gamma): closed-form
(the dashpot only), master, integrator, reference and highprec serve both (each with a rung of
its own per rule where needed); the others the "force" rule (for
alpha <= gamma the rules coincide and all serve).

Each rung is an object of :mod:`restitution.fast.rungs` (interface: :mod:`restitution.fast.rung`);
this module only compares their quotes and loads or builds what they read.

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

import numpy as np

from . import cache as _cache
from ..core.errors import ParameterError, number_in, real_array
from ..core.model import OMEGA_REPRESENTABLE, at_most_one
from ..core.results import end_rule
from ..core.exponents import Exponents, as_exponents
from .calibration import (CALIBRATION_VERSION, FITTED_C, MUELLER_POESCHEL_PADE, Calibration, Relation,
                          build_calibration)
from .master import MASTER_VERSION, MasterCurve, MasterSettings, reference_eps
from .rung import DEFAULT_TOL, TOL_FLOOR, Quote, Request, integrator_bound
from .rungs import ladder_rungs, rung_names
from .rungs.calibrated import CALIBRATION, SAFETY
from .rungs.overlap_master import OVERLAP_CURVE
from .overlap_master import OVERLAP_CURVE_VERSION, OverlapCurve, build_overlap_curve

__all__ = ["EpsResult", "Ladder", "epsilon", "rung_names", "SAFETY", "MUELLER_POESCHEL_PADE", "BUILD_COST",
           "DEFAULT_TOL", "TOL_FLOOR"]

#: Rough seconds to build a calibration bundle that is not cached.
BUILD_COST = {"alpha>gamma": 15.0, "alpha<=gamma": 30.0}
#: Rough seconds to build the overlap rule's master curve (1-2 s measured on the 2-core machine).
OVERLAP_CURVE_COST = 3.0


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


def _check_tol(tol) -> float:
    # Refuse an unreachable tolerance at once, before any master curve is built for nothing.
    return number_in("tol", tol, TOL_FLOOR, 1.0, hi_open=True, why="no method returns a double closer than that")


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


class Ladder:
    """The ladder for one pair of exponents (and one calibration setting / cache directory)."""

    def __init__(self, alpha, gamma, *, settings: MasterSettings | None = None, cache_dir=None,
                 stream=None, relations: tuple[Relation, ...] = (FITTED_C,)):
        self.ex = as_exponents(alpha, gamma)
        self.relations = tuple(relations)
        self.rungs = ladder_rungs(self.relations)
        self.rung_names = rung_names(self.relations)
        self.settings = settings or MasterSettings()
        self.cache_dir = cache_dir
        self.stream = stream
        #: What is built and loaded, by build name (what the rungs' ``needs`` name).
        self.built: dict = {}

    @property
    def _stream(self):
        return sys.stderr if self.stream is None else self.stream

    def _directory(self):
        from pathlib import Path
        return Path(self.cache_dir) if self.cache_dir else None

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

    def _load(self, name: str, key: str, valid, from_dict):
        """The build ``name`` from its cache entry, once per ladder (None if absent). A bad entry is
        removed with one note: otherwise it would be read, refused and reported on every call, and
        never replaced when a request is served without building."""
        if name not in self.built:
            path = _cache.cache_path(key, self._directory())
            d = _cache.load_or_discard(path, self._stream, valid, "does not pass its checks against the integrator")
            if d is not None:
                self.built[name] = from_dict(d)
        return self.built.get(name)

    def cached_calibration(self) -> Calibration | None:
        return self._load(CALIBRATION, self.cache_key, self._valid, Calibration.from_dict)

    def calibration(self) -> Calibration:
        if self.cached_calibration() is None:
            stream = self._stream

            def progress(msg):
                print(f"restitution:   {msg}", file=stream, flush=True)

            d = _cache.get_or_build(
                self.cache_key, lambda: build_calibration(self.ex, None, self.settings, progress, self.relations).as_dict(),
                valid=self._valid, what=f"the master curve for alpha={self.ex.alpha}, gamma={self.ex.gamma}",
                directory=self._directory(), stream=stream)
            self.built[CALIBRATION] = Calibration.from_dict(d)
        return self.built[CALIBRATION]

    @property
    def master(self) -> MasterCurve:
        return self.calibration().master

    # -- the overlap rule's master curve (its own cache file: built on its own, in seconds)
    @property
    def overlap_key(self) -> str:
        return f"overlap-curve-a{self.ex.alpha}-g{self.ex.gamma}-v{OVERLAP_CURVE_VERSION}"

    def _overlap_valid(self, d: dict) -> bool:
        try:
            c = OverlapCurve.from_dict(d)
        except Exception:  # noqa: BLE001 - anything unreadable is rebuilt
            return False
        return (c.alpha, c.gamma) == (self.ex.alpha, self.ex.gamma) and c.spot_checks_pass()

    def cached_overlap_curve(self) -> OverlapCurve | None:
        return self._load(OVERLAP_CURVE, self.overlap_key, self._overlap_valid, OverlapCurve.from_dict)

    def overlap_curve(self) -> OverlapCurve:
        if self.cached_overlap_curve() is None:
            d = _cache.get_or_build(
                self.overlap_key, lambda: build_overlap_curve(self.ex, None).as_dict(), valid=self._overlap_valid,
                what=f"the overlap rule's master curve for alpha={self.ex.alpha}, gamma={self.ex.gamma}",
                directory=self._directory(), stream=self._stream)
            self.built[OVERLAP_CURVE] = OverlapCurve.from_dict(d)
        return self.built[OVERLAP_CURVE]

    # -- builds, by the name a rung's ``needs`` gives
    def _cached(self, name: str):
        return {CALIBRATION: self.cached_calibration, OVERLAP_CURVE: self.cached_overlap_curve}[name]()

    def _build(self, name: str):
        return {CALIBRATION: self.calibration, OVERLAP_CURVE: self.overlap_curve}[name]()

    def _build_cost(self, name: str) -> float:
        if name == OVERLAP_CURVE:
            return OVERLAP_CURVE_COST
        return BUILD_COST["alpha>gamma" if self.ex.alpha > self.ex.gamma else "alpha<=gamma"]

    # -- quotes
    def quotes(self, omega: np.ndarray, tol: float, end: str = "force") -> list[Quote]:
        """Every rung with its bound over ``omega``, cost and a runner (None when not applicable)."""
        req = Request(self.ex, np.asarray(omega, float).ravel(), tol, end, self._loaded(end), self.stream)
        return [r.quote(req) for r in self.rungs]

    def _loaded(self, end: str) -> dict:
        probe = Request(self.ex, np.ones(1), 1.0, end)
        for name in {r.needs(probe) for r in self.rungs if r.serves(probe)} - {None}:
            self._cached(name)
        return dict(self.built)

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
        end = end_rule(end)
        flat = om.ravel()
        quotes = self.quotes(flat, tol, end)
        if build is not False:
            wanted = {q.needs_build for q in quotes if q.needs_build}
            if method is not None:
                wanted &= {q.needs_build for q in quotes if q.name == method}
            if not build:
                wanted &= self._building_pays(quotes, tol, flat.size) if method is None else wanted
            if wanted:
                for name in sorted(wanted):
                    self._build(name)
                quotes = self.quotes(flat, tol, end)
        if method is not None:
            mine = [q for q in quotes if q.name == method]
            if not mine:   # a rung that is not quoted for this end rule at all
                raise ParameterError("method", method, f"does not serve end = {end}; the rungs that do: "
                                     + ", ".join(q.name for q in quotes if q.run is not None))
            q = next((q for q in mine if q.run is not None), mine[0])
            if q.run is None:
                raise ParameterError("method", method, f"not available here: {q.reason or 'needs a build'}")
            if checked and not q.bound <= tol:
                raise ParameterError("tol", tol, f"method {method} has bound {q.bound:.3g} over these Omegas")
            order = [q]
        else:
            ok = [q for q in quotes if q.run is not None and q.bound <= tol]
            if not ok:
                finite = [q for q in quotes if q.run is not None and math.isfinite(q.bound)]
                best = min(finite, key=lambda q: q.bound) if finite else None
                hint = (f"the smallest bound over these Omegas is {best.bound:.3g} ({best.name})" if best
                        else "no method covers these Omegas")
                raise ParameterError("tol", tol, f"no method reaches it: {hint}")
            order = sorted(ok, key=lambda q: (q.cost, q.bound))
        chosen, eps, bound = self._first_within(order, flat, tol if checked else math.inf, end)
        table = tuple({"method": q.name, "bound": q.bound, "cost": q.cost, "setting": q.setting,
                       "available": q.run is not None, "reason": q.reason} for q in quotes)
        return EpsResult(eps.reshape(om.shape), chosen.name, float(bound), om, self.ex.alpha,
                         self.ex.gamma, tol if checked else None, chosen.setting, table, chosen.coefficients)

    def _first_within(self, order, flat: np.ndarray, tol: float, end: str):
        """The first quote, cheapest first, whose bound still holds once widened by its answer
        (a double-precision integration near the overlap rule's sticking boundary loses relative
        accuracy as eps falls: core.conditioning), run once more at a tolerance tightened by that
        factor where it falls short; then (quote, eps, widened bound)."""
        widened, failed = [], []
        for q in order:
            for attempt in range(2):
                try:
                    eps = np.asarray(q.run(flat), dtype=float)
                except ArithmeticError as exc:
                    # a compiled integrator that gives up (at the edge of sticking): the next rung
                    # answers, or refuses in one line
                    failed.append(f"{q.name}: {exc}")
                    break
                if not np.all(np.isfinite(eps)):
                    raise ArithmeticError(f"method {q.name} returned non-finite eps")
                eps = at_most_one(eps)
                factor = q.widen(eps) if q.widen is not None else 1.0
                bound = q.bound * factor
                if bound <= tol:
                    return q, eps, bound
                widened.append((q, eps, bound))
                tighter = [t for t in self.quotes(flat, max(TOL_FLOOR, min(tol, q.bound) / (2.0 * factor)), end)
                           if t.name == q.name and t.run is not None and t.bound < q.bound]
                if attempt or not tighter:
                    break
                q = tighter[0]
        if not widened:
            raise ParameterError("omega", float(flat[0]) if flat.size == 1 else "these Omegas",
                                 "no method that reaches tol could integrate here (" + "; ".join(failed) + ")")
        q, eps, bound = min(widened, key=lambda w: w[2])
        raise ParameterError("tol", tol, f"eps = {float(np.min(eps)):.3g} lies near the sticking boundary of the "
                             f"overlap rule, where the integrators' relative error grows like 1/eps: the "
                             f"smallest bound reached here is {bound:.3g} ({q.name}); ask for a larger tol")

    def _building_pays(self, quotes, tol: float, n: int) -> set[str]:
        """The builds worth making: all the quoted ones when nothing else meets tol; otherwise those
        whose cost plus their cheapest rung's undercuts the best rung that needs no build."""
        plain = [q.cost for q in quotes if q.run is not None and q.bound <= tol]
        pending = {q.needs_build for q in quotes if q.needs_build}
        if not plain:
            return pending
        best = min(plain)
        return {b for b in pending
                if self._build_cost(b) + min(q.cost for q in quotes if q.needs_build == b) < best}


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
    end-of-contact rule; "overlap" is served only by the rungs that declare it (``Rung.ends``).
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

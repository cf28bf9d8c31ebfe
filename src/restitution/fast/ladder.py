"""The method ladder for eps(Omega) and ``epsilon()``, which picks the cheapest rung that meets a tolerance.

The rungs are the objects of the registry :data:`restitution.fast.rungs.RUNGS` (the contract:
:mod:`restitution.fast.rung`; each states its domain, cost and bound in its own docstring), listed
with their end rules and costs on the documentation's generated page "The rungs of the method
ladder" (``reference/_generated/rungs``, made from the registry by
``restitution_workflow.docs_pages.rungs_page``). What they read that is made once (a master curve,
a uniform form, a relation's c0-c2, a check against mpmath) are the builds of the registry
:data:`restitution.fast.builds.BUILDS` (the contract: :mod:`restitution.fast.build`). This module
only compares the rungs' quotes and loads or makes the builds they name; it knows neither kind by
name.

Choice: an exact rung (``Rung.exact``: the exact family alpha = 2 gamma + 1) wherever it serves
and meets tol, with no build made; otherwise, among rungs whose domain holds every input and whose
bound over the inputs is <= tol, the least expected time (setup + n x cost). A build is made
(cached on disk) only when its price (``Build.price``: what the last one of its kind took in this
process, else its declared ``Build.seconds``) plus its rung's cost undercuts the best rung that
needs no build, or when nothing else meets tol; builds are made cheapest first, quoting again after
each (the master curve may serve the request, and the perturbation route is then not built). One
expected to take more than a second is named on stderr with its price. The master curve's check
against mpmath (seconds) is built for the pipeline and the benchmark (``calibration()``), and can
only widen the curve's bound. A tolerance no rung meets raises ParameterError naming the best bound
available. Under the overlap rule an Omega at or below core.collision.stick_bound is refused before
any rung runs (StickError).

End rule: each rung declares the rules it serves where they differ (alpha > gamma, ``Rung.ends``);
for alpha <= gamma the rules coincide and all serve.
"""

from __future__ import annotations

import math
import sys
import time
from dataclasses import dataclass, field

import numpy as np

from . import cache as _cache
from ..core.collision import StickError, stick_bound, stick_reason
from ..core.conditioning import conditioning_cause
from ..core.errors import ParameterError, number_in, real_array
from ..core.model import OMEGA_REPRESENTABLE, at_most_one
from ..core.problem import Problem, as_problem
from ..core.exponents import read_through
from ..core.uniform import UniformForm
from .build import Site
from .builds import ladder_builds
from .builds.overlap_curve import OVERLAP_CURVE
from .calibration import FITTED_C, MASTER, MPMATH, MUELLER_POESCHEL_PADE, UNIFORM, Calibration, Relation, merged, relation_build
from .master import MasterCurve, MasterSettings
from .overlap_master import OverlapCurve
from .parts import part_ranges
from .rung import DEFAULT_TOL, TOL_FLOOR, Quote, Request, Setting
from .rungs import ladder_rungs, rung_names
from .rungs.calibrated import SAFETY

__all__ = ["EpsResult", "Part", "PartSettings", "Ladder", "epsilon", "rung_names", "SAFETY", "MUELLER_POESCHEL_PADE", "DEFAULT_TOL", "TOL_FLOOR",
           "RENAMED"]

#: Old method names still accepted, with a one-line note on stderr: scripts and command lines written
#: before the rename keep working, and say what to write instead. "closed-form" was the fitted uniform
#: approximation's name (alpha = gamma and the dashpot, answered exactly by the same rung, included).
RENAMED = {"closed-form": "uniform"}

# ------------------------------------------------------------------------------------------ result
@dataclass(frozen=True)
class Part:
    """The points of one request that one rung answered: its name, their Omega range and count,
    its bound over them and its setting (an :class:`EpsResult` has one per rung it used)."""

    method: str
    omega_min: float
    omega_max: float
    count: int
    bound: float
    setting: Setting = field(default_factory=Setting)

    def as_dict(self) -> dict:
        return {"method": self.method, "omega_min": self.omega_min, "omega_max": self.omega_max,
                "count": self.count, "error_bound": self.bound, "setting": str(self.setting)}


@dataclass(frozen=True)
class PartSettings:
    """The setting of an answer made part by part: each part's rung and its
    :class:`~restitution.fast.rung.Setting`, in increasing Omega. ``str()`` shows them as
    "rung: setting" joined by "; " (how tables and ``--json`` show it).

    Parameters
    ----------
    parts : tuple of (str, Setting)
        (rung name, its setting) per part.

    Examples
    --------
    >>> s = PartSettings((("master", Setting(label="61 panels")), ("integrator", Setting(rtol=5e-08))))
    >>> str(s), s.parts[1][1].rtol
    ('master: 61 panels; integrator: rtol=5e-08', 5e-08)
    """

    parts: tuple = ()

    def __str__(self) -> str:
        return "; ".join(f"{method}: {setting}" for method, setting in self.parts)

    def __bool__(self) -> bool:
        return bool(self.parts)


@dataclass(frozen=True)
class EpsResult:
    """What ``epsilon`` returns: eps (numpy array, same shape as the input), the rungs used and their bounds.

    ``setting`` is the rung's :class:`~restitution.fast.rung.Setting` (its ``str()`` e.g.
    "rtol=1e-10"), or for an answer made part by part a :class:`PartSettings` (each part's is also
    in ``parts``); ``candidates`` is the chooser's table: one dict per rung name with its bound
    over these inputs (inf when outside its domain), the expected cost, its Setting and why it was
    or was not eligible (of two rungs of one name, one per end rule, the one serving the rule asked). An array whose parts different rungs answer
    (each point by the cheapest rung that meets tol over its part) has one :class:`Part` per rung
    in ``parts``, ``methods`` counts the points each answered, ``bounds`` is the bound at each
    point, and ``method`` names them all joined by "+" (the candidates then carry their part's index).

    Parameters
    ----------
    eps : numpy.ndarray
        The coefficients of restitution, shaped as the Omega given.
    method : str
        The rung that answered (several: their names joined by "+", in increasing Omega).
    error_bound : float
        The relative error bound over all the inputs (the largest of the parts').
    omega : numpy.ndarray
        The Omegas.
    problem : Problem
        What was solved: the exponents and the end rule asked (``alpha``, ``gamma`` and ``end``
        read through it).
    tol : float or None
        The tolerance asked.
    setting : Setting or PartSettings, optional
        What the rung ran at (its ``str()`` is what tables and ``--json`` show).
    candidates : tuple of dict, optional
        The chooser's table (``method``, ``bound``, ``cost``, ``setting`` (a Setting), ``available``,
        ``reason``).
    coefficients : dict, optional
        The uniform approximation's numbers, when that rung answered.
    parts : tuple of Part, optional
        Which rung answered which points, with its bound over them.

    Examples
    --------
    >>> import numpy as np
    >>> from restitution import epsilon
    >>> r = epsilon(alpha=1, gamma=0, omega=0.5)
    >>> r.method, float(np.asarray(r).round(6))          # an EpsResult is array-like
    ('exact-family', 0.20788)
    >>> r.as_dict()["method"], r.as_dict()["eps"] == r.eps.ravel().tolist()   # what --json prints
    ('exact-family', True)
    >>> r.methods
    {'exact-family': 1}
    >>> r = epsilon(alpha="3/2", gamma=1, omega=0.3, method="integrator", tol=1e-6, build=False)
    >>> round(r.setting.rtol, 12), str(r.setting), r.as_dict()["setting"]
    (5e-08, 'rtol=5e-08', 'rtol=5e-08')
    """

    eps: np.ndarray
    method: str
    error_bound: float
    omega: np.ndarray
    problem: Problem
    tol: float
    setting: Setting | PartSettings = field(default_factory=Setting)
    candidates: tuple = ()
    coefficients: dict | None = None   # the uniform approximation's numbers, when that rung answered
    parts: tuple = ()

    alpha = read_through("problem", "alpha")
    gamma = read_through("problem", "gamma")
    end = read_through("problem", "end", "The end-of-contact rule asked for.")

    def __array__(self, dtype=None, copy=None):
        return np.asarray(self.eps, dtype=dtype)

    @property
    def methods(self) -> dict:
        """How many points each rung answered, in increasing Omega."""
        out: dict = {}
        for p in self.parts:
            out[p.method] = out.get(p.method, 0) + p.count
        return out

    @property
    def bounds(self) -> np.ndarray:
        """The relative error bound at each point (shaped as ``eps``): its part's."""
        om = np.asarray(self.omega, dtype=float)
        out = np.full(om.shape, float(self.error_bound))
        if len(self.parts) > 1:
            for p in self.parts:
                out[(om >= p.omega_min) & (om <= p.omega_max)] = p.bound
        return out

    def as_dict(self) -> dict:
        return {"eps": np.asarray(self.eps, float).ravel().tolist(), "method": self.method,
                "error_bound": float(self.error_bound), "alpha": str(self.alpha), "gamma": str(self.gamma),
                "tol": self.tol, "setting": str(self.setting), "methods": self.methods,
                "parts": [p.as_dict() for p in self.parts],
                **({} if self.coefficients is None else {"coefficients": self.coefficients})}


# ------------------------------------------------------------------------------------------ helpers
def _omega_array(omega, field_name: str = "omega") -> np.ndarray:
    return _omega_checked(omega, field_name)[0]


def _omega_checked(omega, field_name: str = "omega") -> tuple[np.ndarray, float, float]:
    """The Omegas as an array, with their smallest and largest (which the chooser reuses)."""
    lo, hi = OMEGA_REPRESENTABLE
    allowed = f"must be numbers in [{lo:g}, {hi:g}] (at least one)"
    arr = real_array(field_name, omega, allowed)
    if arr.size == 0:
        raise ParameterError(field_name, omega, allowed)
    # Subnormal or near-overflow Omega leaves no headroom for the expansions' powers of Omega.
    # Two reductions decide it for the whole array (a NaN makes both comparisons fail); the
    # elementwise search for the first bad value runs only when there is one.
    least, most = float(np.min(arr)), float(np.max(arr))
    if not (least >= lo and most <= hi):
        bad = ~(np.isfinite(arr) & (arr >= lo) & (arr <= hi))
        raise ParameterError(field_name, float(arr[bad].flat[0]), allowed)
    return arr, least, most


def _one_per_name(quotes: list) -> list:
    """The quotes a table shows: of two rungs of one name (one per end rule, as master and
    integrator are), the one that serves the rule asked; a rung serving neither, once."""
    served = {q.name for q in quotes if q.serves}
    first: dict = {}
    for q in quotes:
        if q.serves or q.name not in served:
            first.setdefault(q.name, q)
    return list(first.values())


def _check_tol(tol) -> float:
    # Refuse an unreachable tolerance at once, before any master curve is built for nothing.
    return number_in("tol", tol, TOL_FLOOR, 1.0, hi_open=True, why="no method returns a double closer than that")


class Ladder:
    """The ladder for one problem, its exponents and end rule (and one calibration setting / cache
    directory). ``problem``: a Problem (an Exponents or an (alpha, gamma) pair: the force rule)."""

    def __init__(self, problem, *, settings: MasterSettings | None = None, cache_dir=None,
                 stream=None, relations: tuple[Relation, ...] = (FITTED_C,)):
        self.problem = as_problem(problem)
        self.ex = self.problem.ex
        self.relations = tuple(relations)
        self.rungs = ladder_rungs(self.relations)
        self.rung_names = rung_names(self.relations)
        self.settings = settings or MasterSettings()
        self.cache_dir = cache_dir
        self.stream = stream
        #: The builds it may make, by name (restitution.fast.builds).
        self.builds = ladder_builds(self.relations)
        #: What is built and loaded, by build name (what the rungs' ``needs`` name).
        self.built: dict = {}
        self.site = Site(self.ex, self.settings, self._progress, self.built)
        self._announce = False

    def with_end(self, end: str) -> "Ladder":
        """The ladder for the same exponents under the end rule ``end``, sharing what this one has
        built and loaded (a build belongs to the exponents; each rule's rungs name the ones they read)."""
        other = type(self)(self.problem.with_end(end), settings=self.settings, cache_dir=self.cache_dir,
                       stream=self.stream, relations=self.relations)
        other.rungs, other.rung_names, other.builds, other.built = self.rungs, self.rung_names, self.builds, self.built
        other.site = Site(self.ex, self.settings, other._progress, other.built)
        return other

    @property
    def _stream(self):
        return sys.stderr if self.stream is None else self.stream

    def _directory(self):
        from pathlib import Path
        return Path(self.cache_dir) if self.cache_dir else None

    @property
    def master_settings(self) -> MasterSettings:
        """The curve's settings: its mpmath check is a build of its own (MPMATH)."""
        return self.site.master_settings

    # -- the builds, by the name a rung's ``needs`` gives (the registry: restitution.fast.builds)
    def _progress(self, msg: str) -> None:
        if self._announce:
            print(f"restitution:   {msg}", file=self._stream, flush=True)

    def _cached(self, name: str):
        """The build ``name`` from its cache entry, once per ladder (None if absent, or if a build it
        reads is absent). A bad entry is removed with one note: otherwise it would be read, refused
        and reported on every call, and never replaced when a request is served without building."""
        if name not in self.built:
            build = self.builds[name]
            if any(self._cached(a) is None for a in build.after):
                return None
            path = _cache.cache_path(build.key(self.site), self._directory())
            # every check of a build depends on its key, content and the library only: remembered
            d = _cache.load_or_discard(path, self._stream, lambda d: build.valid(self.site, d),
                                       "does not pass its checks against the integrator", remember=True)
            if d is not None:
                self.built[name] = build.load(self.site, d)
        return self.built.get(name)

    def _build(self, name: str):
        """The build ``name``, made (with what it reads) and cached if it is not; announced on stderr
        when it is expected to take more than a second."""
        if self._cached(name) is None:
            build = self.builds[name]
            for a in build.after:
                self._build(a)
            seconds = build.price(self.site)
            timing = {}

            def make():
                t0 = time.perf_counter()
                out = build.make(self.site)
                timing["s"] = time.perf_counter() - t0
                return out

            self._announce = seconds > _cache.ANNOUNCE_SECONDS
            try:
                d = _cache.get_or_build(build.key(self.site), make, valid=lambda d: build.valid(self.site, d),
                                        directory=self._directory(), what=build.what(self.site),
                                        stream=self._stream, announce=self._announce, estimate=seconds,
                                        remember=True)
            finally:
                self._announce = False
            if "s" in timing:
                build.timed(self.site, timing["s"])
            self.built[name] = build.load(self.site, d)
        return self.built[name]

    def _build_cost(self, name: str) -> float:
        """Expected seconds to have ``name``: its own and those of the unbuilt builds it reads."""
        if name in self.built:
            return 0.0
        build = self.builds[name]
        return build.price(self.site) + sum(self._build_cost(a) for a in build.after)

    # -- the pieces by name (tests, the benchmark, the pipeline)
    def cached_calibration(self) -> Calibration | None:
        """The master curve with the rungs it measures, if cached."""
        return self._cached(MASTER)

    @property
    def master(self) -> MasterCurve:
        return self._build(MASTER).master

    def overlap_curve(self) -> OverlapCurve:
        return self._build(OVERLAP_CURVE)

    def cached_overlap_curve(self) -> OverlapCurve | None:
        return self._cached(OVERLAP_CURVE)

    @property
    def overlap_key(self) -> str:
        return self.builds[OVERLAP_CURVE].key(self.site)

    def uniform(self) -> UniformForm | None:
        """The force rule's uniform form (None where alpha <= gamma, and for alpha = 2 gamma + 1,
        whose exact-family rung makes a fitted form unnecessary)."""
        if not self.ex.alpha > self.ex.gamma or self.ex.alpha == 2 * self.ex.gamma + 1:
            return None
        return self._build(UNIFORM)

    def calibration(self) -> Calibration:
        """Everything: the master curve checked against mpmath, every relation rung and the uniform
        form (what the pipeline and the benchmark want; an eps request builds only what it reads)."""
        parts = [self._build(MASTER), *(self._build(relation_build(r.name)) for r in self.relations)]
        if self.settings.n_highprec > 0:
            self._build(MPMATH)
        cal = merged(parts)
        cal.uniform = self.uniform()
        return cal

    # -- quotes
    def quotes(self, omega: np.ndarray, tol: float, cached: bool = True,
               size: int | None = None, builds: dict | None = None, extremes=None) -> list[Quote]:
        """Every rung with its bound over ``omega``, cost and a runner (None when not applicable);
        ``cached`` False: as with an empty cache (no rung that reads a build can run); ``size``: the
        number of points when ``omega`` is only their range's two ends; ``builds``: what is loaded,
        when the caller has just looked (the cache is not asked again); ``extremes``: the smallest
        and largest of ``omega``, when the caller has them."""
        if builds is None:
            builds = self._loaded() if cached else {}
        req = Request(self.problem, np.asarray(omega, float).ravel(), tol, builds, self.stream, size, extremes)
        return [r.quote(req) for r in self.rungs]

    def _loaded(self) -> dict:
        probe = Request(self.problem, np.ones(1), 1.0)
        for name in {r.needs(probe) for r in self.rungs if r.serves(probe)} - {None}:
            self._cached(name)
        return dict(self.built)

    # -- the choice
    def evaluate(self, omega, *, tol: float | None = DEFAULT_TOL, method: str | None = None,
                 build: bool | None = None, cached: bool = True) -> EpsResult:
        om, lo, hi = _omega_checked(omega)
        if not cached and build:
            raise ParameterError("build", build, "must be False or None with cached=False (nothing is read or built)")
        # A forced method without a tolerance answers with its own bound (tol only sets the
        # integrators' settings then); otherwise the default tolerance applies.
        checked = tol is not None or method is None
        tol = _check_tol(DEFAULT_TOL if tol is None else tol)
        if build is not None and not isinstance(build, bool):   # build="no" is truthy: it would build
            raise ParameterError("build", build, "must be True, False or None")
        if isinstance(method, str) and method in RENAMED:
            print(f'restitution: note: eps method "{method}" is now called "{RENAMED[method]}" (a fitted approximation '
                  f'with a measured error, not a closed form); "{method}" will go', file=sys.stderr, flush=True)
            method = RENAMED[method]
        if method is not None and method not in self.rung_names:
            raise ParameterError("method", method, f"must be one of {', '.join(self.rung_names)}")
        flat = om.ravel()
        if self.problem.end == "overlap":
            self._refuse_sticking(flat)
        if method is None and flat.size > 1:
            groups = self._groups(flat, lo, hi, tol, build, cached)
            if len(groups) > 1:
                return self._joined(om, flat, groups, tol, build, cached)
        return self._answer(om, flat, tol, checked, method, build, cached, (lo, hi))

    def _answer(self, om, flat, tol: float, checked: bool, method, build, cached: bool,
                extremes=None) -> EpsResult:
        """The whole of ``flat`` by one rung: the forced one, else the cheapest that meets tol
        (``extremes``: the smallest and largest of ``flat``, when known)."""
        quotes = self.quotes(flat, tol, cached, extremes=extremes)
        if build is not False and cached:
            quotes = self._make_builds(quotes, flat, tol, method, build)
        if method is not None:
            # the rungs of that name that serve this end rule: of two (one per rule) the refusal is
            # the one whose rule was asked, not the other's "serves the force rule only"
            mine = [q for q in quotes if q.name == method and q.serves]
            if not mine:
                raise ParameterError("method", method, f"does not serve end = {self.problem.end}; the rungs that do: "
                                     + ", ".join(q.name for q in quotes if q.run is not None))
            q = next((q for q in mine if q.run is not None), mine[0])
            if q.run is None:
                raise ParameterError("method", method, f"not available here: {q.reason or 'needs a build'}")
            if not math.isfinite(q.bound):   # an answer without a bound is no answer (even with no tol)
                raise ParameterError("method", method, f"states no bound over these Omegas: {q.setting or q.reason}")
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
            # an exact rung first (Rung.exact): none is more accurate, and it reads no cache
            order = sorted(ok, key=lambda q: (not q.exact, q.cost, q.bound))
        chosen, eps, bound = self._first_within(order, flat, tol if checked else math.inf, cached)
        table = tuple({"method": q.name, "bound": q.bound, "cost": q.cost, "setting": q.setting,
                       "available": q.run is not None, "reason": q.reason} for q in _one_per_name(quotes))
        lo, hi = extremes if extremes is not None else (float(np.min(flat)), float(np.max(flat)))
        part = Part(chosen.name, lo, hi, int(flat.size), float(bound), chosen.setting)
        return EpsResult(eps.reshape(om.shape), chosen.name, float(bound), om, self.problem,
                         tol if checked else None, chosen.setting, table, chosen.coefficients,
                         (part,))

    # -- each part of an array its own rung
    def _groups(self, flat: np.ndarray, lo: float, hi: float, tol: float, build,
                cached: bool) -> list[tuple[float, float, float, float]]:
        """The Omega intervals [a, b) (open ends: -inf, inf) that ``flat`` is answered by in turn,
        each with the smallest and largest of its points.

        The array is cut at every rung's domain edges (``Rung.edges``) inside its range; each part
        that holds points is quoted over the range of its points with its count (what ``epsilon``
        would quote for them alone) and makes the builds its quotes say pay for it; adjacent parts
        whose cheapest adequate rung is the same form one interval. One interval: the whole array
        is answered as one (no copy), as it was before arrays were cut. ``lo``, ``hi``: the
        smallest and largest of ``flat``."""
        builds = self._loaded() if cached else {}
        probe = Request(self.problem, np.array([lo, hi]), tol, builds, self.stream)
        cuts = sorted({float(e) for r in self.rungs if r.serves(probe) for e in r.edges(probe) if lo < e <= hi})
        if not cuts:
            return [(-math.inf, math.inf, lo, hi)]
        counts, lows, highs = part_ranges(flat, cuts)
        starts, stops = [-math.inf, *cuts], [*cuts, math.inf]
        groups: list[tuple[float, float, float, float]] = []
        last = object()
        for a, b, n, p_lo, p_hi in zip(starts, stops, counts, lows, highs):
            if n == 0:
                continue
            ends = np.array([p_lo, p_hi])
            # what the probe loaded, and what an earlier part built since
            quotes = self.quotes(ends, tol, cached, size=int(n), builds=dict(self.built) if cached else {})
            if build is not False and cached:
                quotes = self._make_builds(quotes, ends, tol, None, build, size=int(n))
            ok = [q for q in quotes if q.run is not None and q.bound <= tol]
            key = min(ok, key=lambda q: (not q.exact, q.cost, q.bound)).name if ok else None
            if groups and key == last:
                groups[-1] = (groups[-1][0], b, groups[-1][2], float(p_hi))
            else:
                groups.append((a, b, float(p_lo), float(p_hi)))
            last = key
        return groups

    def _joined(self, om, flat, groups, tol: float, build, cached: bool) -> EpsResult:
        """Each interval's points answered as ``epsilon`` answers them alone, put back in place."""
        eps = np.empty(flat.size)
        results = []
        for a, b, lo, hi in groups:
            # an open end needs no comparison (a pass over the array each)
            where = flat < b if a == -math.inf else (flat >= a if b == math.inf else (flat >= a) & (flat < b))
            sub = flat[where]
            r = self._answer(sub, sub, tol, True, None, build, cached, (lo, hi))
            eps[where] = r.eps
            results.append(r)
        names = list(dict.fromkeys(r.method for r in results))
        parts = tuple(p for r in results for p in r.parts)
        table = tuple({**row, "part": i} for i, r in enumerate(results) for row in r.candidates)
        return EpsResult(eps.reshape(om.shape), "+".join(names), max(p.bound for p in parts), om,
                         self.problem, tol, PartSettings(tuple((p.method, p.setting) for p in parts)),
                         table, None, parts)

    def _refuse_sticking(self, flat: np.ndarray) -> None:
        """Where sticking is proved without integrating (core.collision.stick_bound) no method runs:
        the integrators would refuse as well, but below the reference's range only the mpmath rung is
        left, which cannot prove sticking and would follow the creep for hours."""
        stuck = flat[flat <= stick_bound(self.ex)]
        if stuck.size:
            raise StickError.at(float(stuck[0]), stick_reason(self.ex))

    def _make_builds(self, quotes, flat, tol: float, method, build, size: int | None = None) -> list[Quote]:
        """Make the builds the request wants, cheapest first, quoting again after each: the first
        one built may serve the request already, so the next ones no longer pay."""
        tried: set = set()
        while True:
            pending = {q.needs_build for q in quotes if q.needs_build and (method is None or q.name == method)}
            if method is None and not build:
                pending = self._building_pays(quotes, tol, flat.size if size is None else size)
            pending -= tried
            if not pending:
                return quotes
            name = min(pending, key=lambda b: (self._build_cost(b), b))
            tried.add(name)
            self._build(name)
            quotes = self.quotes(flat, tol, size=size)

    def _first_within(self, order, flat: np.ndarray, tol: float, cached: bool = True):
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
                # two reductions and no temporary array: a NaN or inf makes its extreme non-finite
                low, high = (float(np.min(eps)), float(np.max(eps))) if eps.size else (0.0, 0.0)
                if not (math.isfinite(low) and math.isfinite(high)):
                    raise ArithmeticError(f"method {q.name} returned non-finite eps")
                if high > 1.0:
                    eps = at_most_one(eps)
                factor = q.widen(eps) if q.widen is not None else 1.0
                bound = q.bound * factor
                if bound <= tol:
                    return q, eps, bound
                widened.append((q, eps, bound))
                tighter = [t for t in self.quotes(flat, max(TOL_FLOOR, min(tol, q.bound) / (2.0 * factor)), cached)
                           if t.name == q.name and t.run is not None and t.bound < q.bound]
                if attempt or not tighter:
                    break
                q = tighter[0]
        if not widened:
            raise ParameterError("omega", float(flat[0]) if flat.size == 1 else "these Omegas",
                                 "no method that reaches tol could integrate here (" + "; ".join(failed) + ")")
        q, eps, bound = min(widened, key=lambda w: w[2])
        raise ParameterError("tol", tol, f"{conditioning_cause(self.problem, eps, flat)}: the "
                             f"smallest bound reached here is {bound:.3g} ({q.name}); ask for a larger tol")

    def _building_pays(self, quotes, tol: float, n: int) -> set[str]:
        """The builds worth making, among those a rung that can meet tol reads (Rung.floor): all of
        them when nothing else meets tol; otherwise those whose cost plus their cheapest rung's
        undercuts the best rung that needs no build."""
        plain = [q.cost for q in quotes if q.run is not None and q.bound <= tol]
        waiting = [q for q in quotes if q.needs_build and q.floor <= tol]
        pending = {q.needs_build for q in waiting}
        if any(q.exact and q.run is not None and q.bound <= tol for q in quotes):
            return set()   # the exact rung answers whatever is built (Ladder.evaluate's order)
        if not plain:
            return pending
        best = min(plain)
        return {b for b in pending
                if self._build_cost(b) + min(q.cost for q in waiting if q.needs_build == b) < best}


# --------------------------------------------------------------------------------- the public call
_LADDERS: dict = {}


def _ladder(problem: Problem, relations) -> Ladder:
    key = (problem, _cache.cache_dir(), tuple(relations))
    if key not in _LADDERS:
        _LADDERS[key] = Ladder(problem, relations=relations)
    return _LADDERS[key]


def epsilon(problem: Problem, *, omega=None, g=None, D1=None, D2=None, tol: float | None = DEFAULT_TOL,
            method: str | None = None, build: bool | None = None,
            relations: tuple[Relation, ...] = (FITTED_C,), cached: bool = True) -> EpsResult:
    """Coefficient of restitution to a relative tolerance ``tol``, by the cheapest adequate method.

    ``problem``: the exponents and the end-of-contact rule (a :class:`~restitution.core.problem.Problem`;
    "overlap" is served only by the rungs that declare it, ``Rung.ends``). Give either ``omega``
    (scaled parameter, scalar or array) or the impact speeds ``g`` with the material constants
    ``D1``, ``D2`` (Omega = D1 g^((alpha-1-2gamma)/(gamma+1)) D2^(-(alpha+1)/(gamma+1))).
    Returns an :class:`EpsResult`: ``.eps`` (numpy array shaped like the input), ``.method``,
    ``.error_bound`` (relative, over all inputs), ``.candidates`` (the chooser's table).
    ``method`` forces a rung (it must still meet ``tol``, unless ``tol`` is None: then it answers
    with whatever bound it has); ``build`` = False never builds
    anything, True builds everything the quoted rungs read, None (default) what pays.
    ``relations`` are the relation rungs (:mod:`restitution.api` adds the paper's).
    ``cached`` = False answers as with an empty cache: no build is read or made, so the answer does
    not depend on what earlier runs cached (a DEM scene's fit must not; build must not be True).
    Raises ParameterError for bad input and for a tolerance no rung meets.
    """
    if not isinstance(problem, Problem):
        raise ParameterError("problem", problem, "must be a Problem (restitution.epsilon reads alpha, gamma, end)")
    ex = problem.ex
    if omega is not None:
        if g is not None or D1 is not None or D2 is not None:
            raise ParameterError("omega", omega, "give either omega or all of g, D1, D2, not both")
        om = omega   # Ladder.evaluate checks it (a second check would be two more passes over it)
    else:
        if g is None or D1 is None or D2 is None:
            missing = [n for n, v in (("g", g), ("D1", D1), ("D2", D2)) if v is None]
            raise ParameterError(missing[0], None, "give omega, or all of g, D1, D2")
        from ..core.model import Material
        gs = _omega_array(g, "g")
        with np.errstate(over="ignore", under="ignore"):
            om = np.asarray(Material.of(ex, D1, D2).omega(gs), dtype=float).reshape(gs.shape)
        om = _omega_array(om, "omega")  # Omega itself may over/underflow for extreme inputs
    return _ladder(problem, relations).evaluate(om, tol=tol, method=method, build=build, cached=cached)

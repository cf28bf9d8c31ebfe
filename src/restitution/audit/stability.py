"""The stability atlas: the reference integrator swept over Omega and the exponents, and its invariants.

For every (alpha, gamma) of a grid and every Omega of a log-spaced grid (1e-8 to 1e8 by default),
``restitution.core.collision.collide`` is run at the atlas tolerance and the result is checked:

* ``finite``      eps, tau_b, x_b, tau_c, x_c are finite (and the integrator did not fail);
* ``eps_range``   0 < eps < 1;
* ``order``       0 < tau_b < tau_c, 0 <= x_c < x_b;
* ``x_c``         x_c > 0 where contact ends by the force;
* ``ended_by``    contact ends by the force when alpha > gamma and by separation when alpha <= gamma
                  (for alpha = gamma the force Omega + x' never vanishes while x > 0; for alpha < gamma
                  it stays positive, see restitution.core.collision);
* ``monotone``    eps increases with Omega: a step down by more than twice the stated accuracy is a
                  violation; smaller ones are counted as "unresolved", not as violations;
* ``tight``       on a subset of Omega, every quantity agrees with a run at ``tight_rtol`` within the
                  stated accuracy (relative);
* ``reference``   on a sparse subset, every quantity agrees with the independent mpmath integrator
                  ``restitution.core.highprec.reference_collision`` within the stated accuracy;
* ``exact``       where a closed form exists, the quantities it gives agree within the stated accuracy:
                  eps for alpha = gamma (``asymptotics.equal_exponents_eps``), everything for the linear
                  spring-dashpot alpha = 1, gamma = 0 (``restitution.core.dashpot``).

"Stated accuracy" is the relative error claimed for every quantity at ``AtlasSpec.rtol``: by default
10 rtol + 1e-13, the bound ``restitution.fast.ladder`` states for its "reference" rung (collide); set
``AtlasSpec.accuracy`` to claim something else.

The high-precision reference costs 0.1-1 s per point when alpha > gamma at any Omega, but for
alpha <= gamma its cost grows like 1/Omega (the creeping return must be resolved by an explicit
method): there it is run at ``reference_min_omega_creep`` instead of below it, and the exact closed
forms and the tight runs cover the rest.

The checks, the summary and the limits' agreement are :mod:`restitution.audit.stability_checks`.
Everything here is pure computation (no file I/O); the workflow's scripts write the tables.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace
from fractions import Fraction
from typing import Iterable, Sequence

import numpy as np

from ..core import conditioning
from ..core.errors import ParameterError, integer_in, number_in, require_positive_finite
from ..core.exponents import Exponents, as_exponents

__all__ = ["AtlasSpec", "AtlasPoint", "CHECKS", "QUANTITIES", "omega_grid", "plan", "shard", "estimated_cost",
           "run_point", "run_atlas", "pair_label", "DEFAULT_ALPHAS", "DEFAULT_GAMMAS"]

DEFAULT_ALPHAS = ("1", "5/4", "3/2", "2", "5/2")
DEFAULT_GAMMAS = ("0", "1/2", "1", "3/2")
#: Quantities compared between runs (x_c only where contact ends by the force: it is 0 otherwise).
QUANTITIES = ("eps", "tau_b", "x_b", "tau_c", "x_c")
#: The invariants, in the order they are reported.
CHECKS = ("finite", "eps_range", "order", "x_c", "ended_by", "monotone", "tight", "reference", "exact")
#: Largest Omega range the atlas accepts (collide itself takes any finite Omega > 0). Measured at
#: rtol 1e-10 beyond the default 1e-8..1e8: for alpha <= gamma, 1 - eps falls below the absolute
#: accuracy of eps from Omega ~ 3e10 on and eps comes out > 1 (e.g. 1 + 5.9e-11 for alpha = gamma = 1
#: at 1e11); alpha = 5/2, gamma = 1/2 misses tau_c by 1.8e-9 at 1e12. The atlas reports both.
OMEGA_LIMITS = (1e-12, 1e12)
#: Default stated accuracy: ACCURACY_FACTOR rtol + ACCURACY_FLOOR (collide's, and the ladder's, bound),
#: times core.conditioning.exponent_factor for a pair with alpha + gamma > 4.
ACCURACY_FACTOR, ACCURACY_FLOOR = conditioning.ACCURACY_FACTOR, conditioning.ACCURACY_FLOOR


# ------------------------------------------------------------------------------------------ spec
def _positive(name: str, value, lo: float | None = None, hi: float | None = None) -> float:
    return require_positive_finite(name, value) if lo is None else number_in(name, value, lo, hi)


_count = integer_in


@dataclass(frozen=True)
class AtlasSpec:
    """What the atlas computes. Build it with :meth:`from_config` (validates every field).

    alphas, gammas: exponent grid (exact rationals as strings). omega_min, omega_max, per_decade:
    Omega = 10^(k / per_decade) for integer k from log10(omega_min) to log10(omega_max) (both must be
    powers of ten). rtol: tolerance of the atlas runs; accuracy: the relative error claimed at rtol.
    tight_rtol, tight_decades: the grid points every ``tight_decades`` decades from omega_min (and the
    last one) are rerun at tight_rtol. reference_omegas: Omega values (on the grid) where the mpmath reference is run at
    ``reference_digits`` digits (for alpha <= gamma none below reference_min_omega_creep: see plan).
    """

    alphas: tuple[str, ...] = DEFAULT_ALPHAS
    gammas: tuple[str, ...] = DEFAULT_GAMMAS
    omega_min: float = 1e-8
    omega_max: float = 1e8
    per_decade: int = 2
    rtol: float = 1e-10
    accuracy: float | None = None
    tight_rtol: float = 1e-14
    tight_decades: int = 4
    reference_omegas: tuple[float, ...] = (1e-8, 1e8)
    reference_digits: int = 16
    reference_min_omega_creep: float = 1e-2

    @classmethod
    def from_config(cls, cfg: dict | None = None, also_allowed: Sequence[str] = ()) -> "AtlasSpec":
        """The spec from a config mapping (keys as the fields; missing keys take the defaults).

        Raises ParameterError (one line naming the field and the allowed range) on any bad value.
        ``also_allowed``: keys the caller handles itself (named in the unknown-field message only).
        """
        if cfg is not None and not isinstance(cfg, dict):
            raise ParameterError("stability", cfg, "must be a mapping of atlas settings")
        cfg = dict(cfg or {})
        known = set(cls.__dataclass_fields__)
        unknown = sorted(set(cfg) - known)
        if unknown:
            allowed = ", ".join(sorted(known | set(also_allowed)))
            raise ParameterError(unknown[0], cfg[unknown[0]], f"unknown field; allowed: {allowed}")
        spec = replace(cls(), **cfg)
        return spec.validated()

    def validated(self) -> "AtlasSpec":
        alphas = self._exponents("alphas", self.alphas, "alpha")
        gammas = self._exponents("gammas", self.gammas, "gamma")
        lo, hi = OMEGA_LIMITS
        omin = _positive("omega_min", self.omega_min, lo, hi)
        omax = _positive("omega_max", self.omega_max, lo, hi)
        for name, w in (("omega_min", omin), ("omega_max", omax)):
            if not _is_power_of_ten(w):
                raise ParameterError(name, w, f"must be a power of ten in [{lo:g}, {hi:g}]")
        if not omin < omax:
            raise ParameterError("omega_max", self.omega_max, f"must be > omega_min = {omin:g}")
        per_decade = _count("per_decade", self.per_decade, 1, 1000)
        rtol = _positive("rtol", self.rtol, 1e-14, 1e-3)
        accuracy = None if self.accuracy is None else _positive("accuracy", self.accuracy, rtol, 1e-1)
        tight_rtol = _positive("tight_rtol", self.tight_rtol, 1e-14, rtol)
        tight_decades = _count("tight_decades", self.tight_decades, 1, 100)
        refs = self.reference_omegas
        if isinstance(refs, (str, bytes)) or not isinstance(refs, Iterable):
            raise ParameterError("reference_omegas", refs, "must be a list of Omega values on the grid")
        refs = tuple(sorted({_positive("reference_omegas", w, omin, omax) for w in refs}))
        grid = omega_grid(omin, omax, per_decade)
        for w in refs:
            if not np.any(np.isclose(grid, w, rtol=1e-12, atol=0)):
                raise ParameterError("reference_omegas", w,
                                     f"must lie on the Omega grid (10^(k/{per_decade}) in [{omin:g}, {omax:g}])")
        digits = _count("reference_digits", self.reference_digits, 8, 60)
        creep = _positive("reference_min_omega_creep", self.reference_min_omega_creep, lo, hi)
        return replace(self, alphas=alphas, gammas=gammas, omega_min=omin, omega_max=omax,
                       per_decade=per_decade, rtol=rtol, accuracy=accuracy, tight_rtol=tight_rtol,
                       tight_decades=tight_decades, reference_omegas=refs, reference_digits=digits,
                       reference_min_omega_creep=creep)

    @staticmethod
    def _exponents(name: str, values, which: str) -> tuple[str, ...]:
        if isinstance(values, (str, bytes)) or not isinstance(values, Iterable):
            raise ParameterError(name, values, f"must be a non-empty list of {which} exponents")
        values = list(values)
        if not values:
            raise ParameterError(name, values, f"must be a non-empty list of {which} exponents")
        out = []
        for v in values:
            try:
                ex = Exponents.parse(v, 0) if which == "alpha" else Exponents.parse(1, v)
            except ParameterError as err:
                raise ParameterError(f"{name}[{v!r}]", v, err.allowed) from None
            exact = ex.alpha if which == "alpha" else ex.gamma
            out.append(str(exact))
        if len(set(out)) != len(out):
            raise ParameterError(name, values, "must not repeat an exponent")
        return tuple(out)

    @property
    def stated_accuracy(self) -> float:
        """Relative error claimed for every quantity of every atlas point whose alpha + gamma <= 4."""
        return ACCURACY_FACTOR * self.rtol + ACCURACY_FLOOR if self.accuracy is None else self.accuracy

    def accuracy_for(self, alpha, gamma) -> float:
        """Relative error claimed for the pair's points: the one set in the config, or collide's."""
        if self.accuracy is not None:
            return self.accuracy
        return conditioning.plain_accuracy((alpha, gamma), self.rtol)

    @property
    def pairs(self) -> list[tuple[str, str]]:
        return [(a, g) for a in self.alphas for g in self.gammas]

    def omegas(self) -> np.ndarray:
        return omega_grid(self.omega_min, self.omega_max, self.per_decade)

    def as_dict(self) -> dict:
        return {k: (list(v) if isinstance(v, tuple) else v) for k, v in self.__dict__.items()}


def _is_power_of_ten(w: float) -> bool:
    k = round(math.log10(w))
    return math.isclose(w, 10.0 ** k, rel_tol=1e-12)


def omega_grid(omega_min: float = 1e-8, omega_max: float = 1e8, per_decade: int = 4) -> np.ndarray:
    """10^(k / per_decade) for k = per_decade log10(omega_min) .. per_decade log10(omega_max).

    Exact decades (10.0 ** -8 is the double nearest 1e-8) and the same floats on every machine.
    """
    k0 = round(math.log10(omega_min) * per_decade)
    k1 = round(math.log10(omega_max) * per_decade)
    return np.array([10.0 ** (k / per_decade) if k % per_decade else 10.0 ** (k // per_decade)
                     for k in range(k0, k1 + 1)])


def pair_label(alpha, gamma) -> str:
    """A file-name-safe label of an exponent pair: a3_2-g1 for alpha = 3/2, gamma = 1."""
    return f"a{str(Fraction(str(alpha))).replace('/', '_')}-g{str(Fraction(str(gamma))).replace('/', '_')}"


# ------------------------------------------------------------------------------------------ plan
@dataclass(frozen=True)
class AtlasPoint:
    """One point of the atlas and which comparisons it gets."""

    alpha: str
    gamma: str
    omega: float
    index: int          # position on the Omega grid
    tight: bool
    reference: bool


def plan(spec: AtlasSpec) -> list[AtlasPoint]:
    """Every point of the atlas, pair by pair, Omega increasing.

    Tight runs: every ``tight_decades`` decades from omega_min, and the last point. Reference runs:
    at ``reference_omegas``; for alpha <= gamma a reference Omega below reference_min_omega_creep is
    moved up to the first grid point at or above it (the mpmath cost grows like 1/Omega there).
    """
    omegas = spec.omegas()
    last = len(omegas) - 1
    tight = {i for i in range(len(omegas)) if i % (spec.per_decade * spec.tight_decades) == 0} | {last}
    ref_at = [int(np.argmin(np.abs(np.log(omegas / w)))) for w in spec.reference_omegas]
    floor = next((i for i, w in enumerate(omegas) if w >= spec.reference_min_omega_creep * (1 - 1e-12)), last)
    out = []
    for a, g in spec.pairs:
        creeps = Fraction(a) <= Fraction(g)
        refs = {max(i, floor) for i in ref_at} if creeps else set(ref_at)
        for i, w in enumerate(omegas):
            out.append(AtlasPoint(a, g, float(w), i, i in tight, i in refs))
    return out


def estimated_cost(point: AtlasPoint, spec: AtlasSpec) -> float:
    """Rough seconds one point costs (measured on one core; only used to balance shards).

    collide: ~0.02 s, but ~0.5 s where alpha < gamma and Omega < 1e-2 (stiff creeping return,
    Radau), ~0.08 s there for alpha = gamma; the tight run about 2x that (10x in the stiff case at
    rtol 1e-14); the mpmath reference 0.2-0.6 s, growing like 1/Omega when alpha <= gamma.
    """
    a, g, w = Fraction(point.alpha), Fraction(point.gamma), point.omega
    creep = w < 1e-2
    base = 0.5 if (a < g and creep) else 0.08 if (a == g and creep) else 0.02
    cost = base
    if point.tight:
        cost += base * (10.0 if (a < g and creep) else 2.0)
    if point.reference:
        cost += (0.6 if w < 1e-2 else 0.3) * (max(1.0, 1e-2 / w) if a <= g else 1.0)
    return cost


def shard(points: Sequence[AtlasPoint], k: int, n: int, spec: AtlasSpec | None = None) -> list[AtlasPoint]:
    """The k-th of n shards (k = 0..n-1), balanced by estimated cost (largest first onto the least
    loaded shard; deterministic). Returned in the order of ``points``."""
    n = _count("shards", n, 1, 10**6)
    if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or not 0 <= k < n:
        raise ParameterError("shard", k, f"must be an integer in [0, {n - 1}]")
    spec = spec or AtlasSpec()
    costs = [estimated_cost(p, spec) for p in points]
    order = sorted(range(len(points)), key=lambda i: (-costs[i], i))
    load = [0.0] * n
    owner = [0] * len(points)
    for i in order:
        j = min(range(n), key=lambda s: (load[s], s))
        owner[i] = j
        load[j] += costs[i]
    return [p for i, p in enumerate(points) if owner[i] == k]


# ------------------------------------------------------------------------------------------ runs
def _values(hit) -> dict:
    return {q: float(getattr(hit, q)) for q in QUANTITIES}


def rel_error(a: float, b: float) -> float:
    """|a - b| / |b| (|a| where b = 0): the atlas' measure of every deviation."""
    if b == 0.0:
        return abs(a)
    return abs(a - b) / abs(b)


def _worst(got: dict, truth: dict, with_xc: bool) -> tuple[float, str]:
    names = [q for q in QUANTITIES if with_xc or q != "x_c"]
    errs = {q: rel_error(got[q], truth[q]) for q in names}
    if not all(math.isfinite(v) for v in errs.values()):
        return math.inf, next(q for q, v in errs.items() if not math.isfinite(v))
    q = max(errs, key=errs.get)
    return errs[q], q


def _exact(alpha: Fraction, gamma: Fraction, omega: float) -> dict | None:
    """Closed-form values where they exist (eps only for alpha = gamma)."""
    if alpha == 1 and gamma == 0:
        from ..core.dashpot import dashpot_collision
        return _values(dashpot_collision(omega))
    if alpha == gamma:
        from ..core.asymptotics import equal_exponents_eps
        return {"eps": float(equal_exponents_eps(np.array([omega]))[0])}
    return None


def run_point(point: AtlasPoint, spec: AtlasSpec, timings: dict | None = None) -> dict:
    """Integrate one atlas point (and its comparisons); a failure of the integrator is recorded.

    Returns a flat record: alpha, gamma, omega, the five quantities, ended_by, status ("ok" or the
    exception's one-line message), and the comparisons err_tight / worst_tight (atlas run against
    tight_rtol), err_ref / worst_ref (against the mpmath reference), tight_ref (tight run against the
    reference), ref_estimate (the reference's own error estimate), err_exact / worst_exact (against a
    closed form). Comparisons not made are NaN (worst_*: ""). ``timings`` (optional dict) receives
    the seconds spent per kind of run; they are never part of the record, so records are reproducible.
    """
    from ..core.collision import collide

    ex = as_exponents(point.alpha, point.gamma)
    rec = {"alpha": str(ex.alpha), "gamma": str(ex.gamma), "omega": point.omega, "index": point.index}
    rec.update({q: math.nan for q in QUANTITIES})
    rec.update(ended_by="", status="ok", err_tight=math.nan, worst_tight="", err_ref=math.nan, worst_ref="",
               tight_ref=math.nan, ref_estimate=math.nan, err_exact=math.nan, worst_exact="")
    clock = _Clock(timings)
    try:
        with clock("atlas"):
            hit = collide(ex, point.omega, rtol=spec.rtol)
    except Exception as err:  # noqa: BLE001 - the atlas records what broke and carries on
        rec["status"] = f"{type(err).__name__}: {err}".replace("\n", " ")
        return rec
    got = _values(hit)
    rec.update(got, ended_by=hit.ended_by)
    with_xc = hit.ended_by == "force"

    tight = None
    if point.tight:
        try:
            with clock("tight"):
                tight = _values(collide(ex, point.omega, rtol=spec.tight_rtol))
            rec["err_tight"], rec["worst_tight"] = _worst(got, tight, with_xc)
        except Exception as err:  # noqa: BLE001
            rec["status"] = f"tight run failed: {type(err).__name__}: {err}".replace("\n", " ")
    if point.reference:
        from ..core.highprec import reference_collision
        try:
            with clock("reference"):
                ref = reference_collision(ex, point.omega, digits=spec.reference_digits)
        except Exception as err:  # noqa: BLE001
            rec["status"] = f"reference failed: {type(err).__name__}: {err}".replace("\n", " ")
        else:
            truth = {q: float(getattr(ref, q)) for q in QUANTITIES}
            both_force = with_xc and ref.ended_by == "force"
            rec["err_ref"], rec["worst_ref"] = _worst(got, truth, both_force)
            if ref.ended_by != hit.ended_by:
                rec["err_ref"], rec["worst_ref"] = math.inf, "ended_by"
            rec["ref_estimate"] = float(ref.error_estimate)
            if tight is not None:
                rec["tight_ref"] = _worst(tight, truth, both_force)[0]
    exact = _exact(ex.alpha, ex.gamma, point.omega)
    if exact is not None:
        errs = {q: rel_error(got[q], v) for q, v in exact.items() if q != "x_c" or with_xc}
        q = max(errs, key=errs.get)
        rec["err_exact"], rec["worst_exact"] = errs[q], q
    return rec


class _Clock:
    def __init__(self, sink: dict | None):
        self.sink = sink

    def __call__(self, kind: str):
        return _Timed(self.sink, kind)


class _Timed:
    def __init__(self, sink, kind):
        self.sink, self.kind = sink, kind

    def __enter__(self):
        self.t0 = time.perf_counter()

    def __exit__(self, *exc):
        if self.sink is not None:
            self.sink[self.kind] = self.sink.get(self.kind, 0.0) + time.perf_counter() - self.t0
        return False


def run_atlas(spec: AtlasSpec, points: Sequence[AtlasPoint] | None = None, timings: dict | None = None,
              progress=None) -> list[dict]:
    """Records of ``points`` (default: the whole plan of ``spec``), in the order given."""
    spec = spec.validated()
    points = plan(spec) if points is None else points
    out = []
    for i, p in enumerate(points):
        out.append(run_point(p, spec, timings))
        if progress is not None:
            progress(i + 1, len(points), p)
    return out

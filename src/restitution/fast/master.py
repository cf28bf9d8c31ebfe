"""Master curve eps(Omega) for given exponents: built once, evaluated at ~1e7 points per second.

Construction (``build_master``):

1. Reference values on a calibration grid (log10 Omega in steps of 0.1) from the compiled
   integrator at rtol = 1e-14 (:func:`restitution.fast.integrator.collide_fast`), or from the exact closed form
   when alpha = gamma.
2. The asymptotic expansions of :mod:`restitution.core.asymptotics` are compared with the grid; their
   remainders are fitted by the form the derivation predicts (viscous, alpha > gamma:
   Omega^2 (a L^2 + b L + c), L = ln 1/Omega; elastic: delta^q, q = min(3, end_power + 1)), which
   gives an error bound for each expansion that extends beyond the grid.
3. The join points Omega_lo, Omega_hi are the grid points beyond which the expansion bounds stay
   below ``join_tol``; between them ln eps is interpolated by Chebyshev series of degree ``degree``
   on uniform panels of width ``width`` in s = ln Omega (values from the integrator at the nodes).
4. Errors are measured on points that were not nodes: random points in every panel and the whole
   calibration grid against the integrator, and ``n_highprec`` random points against the mpmath
   reference (:mod:`restitution.core.highprec`). The bound claimed inside [Omega_lo, Omega_hi] is twice
   the larger of (fit error + integrator error) and the error against the mpmath reference.

Evaluation (``MasterCurve.eps``) runs one compiled loop (:func:`restitution.fast.panels.chebyshev_panels_eval`):
Chebyshev inside, the expansions outside. ``MasterCurve.bound(omega)`` is the largest bound over the
given Omegas. A curve serialises to a plain dict (``as_dict``/``from_dict``) for JSON.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np
from numpy.polynomial import chebyshev as cheb

from ..core import asymptotics as asy
from ..core.errors import ParameterError
from ..core.exponents import as_exponents
from .integrator import END_FAILED, END_STUCK, collide_fast
from .panels import PanelRange, chebyshev_panels_eval
from .rung import INTEGRATOR_BOUND_FACTOR, INTEGRATOR_BOUND_FLOOR, integrator_bound
from ..core.problem import as_problem

__all__ = ["MASTER_VERSION", "MasterSettings", "MasterCurve", "build_master", "reference_eps", "mpmath_check",
           "widen_by_check",
           "INTEGRATOR_BOUND_FACTOR", "INTEGRATOR_BOUND_FLOOR", "integrator_bound", "stiff_omega_min",
           "TIMES_OMEGA_MIN"]

#: Bumped whenever the construction changes, so cached curves of an older kind are rebuilt.
MASTER_VERSION = 2

def stiff_omega_min(problem) -> float:
    """Smallest Omega the explicit compiled integrator's eps is used for.

    For alpha > gamma contact ends a few relaxation times after maximum compression and nothing is
    stiff: the run takes about ln(1/Omega) relaxation times (3 ms at 1e-300, 0.1 ms at 1e-3), and
    eps was checked against the mpmath reference below 1e-12 (at 3e-15 and 1e-40 in tests/library/
    test_integrator_bound.py, down to 1e-292 in a sweep of random pairs; beyond about 1e-18 eps is
    the viscous limit k Omega to double precision). Its contact times hold to TIMES_OMEGA_MIN only.
    For alpha <= gamma the return creeps for a time ~ 1/Omega while the fast relaxation stays O(1):
    the step count grows like 1/Omega (~1.6e5 steps at 1e-6). Under the overlap rule the return
    creeps for every pair (about 0.4/Omega steps for alpha = 3/2, gamma = 1/2: 14 ms at 1e-5, 0.2 s
    at 1e-6).
    """
    problem = as_problem(problem)
    return 1e-300 if problem.rules_differ and problem.end == "force" else 1e-5


#: Below this the compiled integrator's contact times are not to be trusted though its eps is: after
#: the turn the force decays from Omega x^(alpha-gamma) towards Omega^2, which leaves double precision
#: below about 1e-154 and moves the force's zero. Against mpmath, tau_c was within its bound at 1e-150
#: (5/2, 3/2) and off by 2 % at 1e-160 (3/2, 1), eps right at both.
TIMES_OMEGA_MIN = 1e-100


@dataclass(frozen=True)
class MasterSettings:
    """How a master curve is built (all part of its cache key)."""

    log10_omega_min: float = -12.0   # calibration grid and largest possible range
    log10_omega_max: float = 14.0
    grid_step: float = 0.1           # calibration grid spacing in log10 Omega
    degree: int = 10                 # Chebyshev degree per panel
    width: float = 0.5               # panel width in ln Omega
    rtol: float = 1e-14              # integrator tolerance for nodes and grid
    join_tol: float = 1e-13          # bound the expansions must meet beyond the joins
    heldout_per_panel: int = 3
    n_highprec: int = 12
    highprec_digits: int = 20
    seed: int = 20240601

    def as_dict(self) -> dict:
        return dict(self.__dict__)

    @classmethod
    def from_dict(cls, d: dict) -> "MasterSettings":
        return cls(**{k: d[k] for k in cls.__dataclass_fields__ if k in d})

    def key(self) -> str:
        items = sorted(self.as_dict().items())
        return "_".join(f"{v:g}" if isinstance(v, float) else str(v) for _, v in items)


# ------------------------------------------------------------------------------ reference values
def reference_eps(problem, omegas, rtol: float = 1e-14) -> np.ndarray:
    """eps from the exact closed form (alpha = gamma) or the compiled integrator (otherwise), for
    the problem's end rule; under "overlap" a proved sticking raises core.collision.StickError."""
    problem = as_problem(problem)
    ex = problem.ex
    om = np.asarray(omegas, dtype=float)
    if ex.alpha == ex.gamma:
        return asy.equal_exponents_eps(om)
    res = collide_fast(ex.p, ex.q_alpha, ex.q_gamma, om, rtol, problem.effective_end)
    if np.any(res[:, 5] == END_STUCK):
        from ..core.collision import StickError
        w = float(om.ravel()[res[:, 5] == END_STUCK][0])
        raise StickError.at(w, "proved as in core.collision")
    if np.any(res[:, 5] == END_FAILED):
        bad = om[res[:, 5] == END_FAILED]
        raise ArithmeticError(f"compiled integrator failed at Omega = {bad[:3]} (alpha={ex.alpha}, "
                              f"gamma={ex.gamma})")
    return res[:, 0].reshape(om.shape)


# ------------------------------------------------------------------------------ remainder models
@dataclass(frozen=True)
class ViscousBound:
    """Bound on |expansion/eps - 1| for Omega below the grid's top (see build_master)."""

    kind: str                 # "force": 2 s Omega^2 (|a| L^2 + |b| L + |c|); "envelope"; "closed"
    coeffs: tuple = ()        # (a, b, c) for "force"
    scale: float = 1.0
    env_omega: tuple = ()     # "envelope": grid Omegas and running max of |residual|
    env_value: tuple = ()
    floor: float = 1e-15

    def __call__(self, omega) -> np.ndarray:
        om = np.asarray(omega, dtype=float)
        if self.kind == "closed":
            return np.full(om.shape, self.floor)
        if self.kind == "force":
            a, b, c = self.coeffs
            L = np.log(1.0 / om)
            return 2.0 * self.scale * om * om * (abs(a) * L * L + abs(b) * np.abs(L) + abs(c)) + self.floor
        # envelope: running max from small Omega upwards, x3; below the grid its first value
        w = np.asarray(self.env_omega)
        v = np.asarray(self.env_value)
        idx = np.searchsorted(w, om * 10 ** 0.1, side="right") - 1
        idx = np.clip(idx, 0, w.size - 1)
        return 3.0 * v[idx] + self.floor

    def as_dict(self) -> dict:
        return {"kind": self.kind, "coeffs": list(self.coeffs), "scale": self.scale,
                "env_omega": list(self.env_omega), "env_value": list(self.env_value), "floor": self.floor}

    @classmethod
    def from_dict(cls, d: dict) -> "ViscousBound":
        return cls(d["kind"], tuple(d["coeffs"]), d["scale"], tuple(d["env_omega"]),
                   tuple(d["env_value"]), d["floor"])


@dataclass(frozen=True)
class ElasticBound:
    """Bound 2 s delta^q + floor on |expansion/eps - 1| (delta = Omega^-A)."""

    A: float
    q: float
    scale: float
    floor: float = 1e-15

    def __call__(self, omega) -> np.ndarray:
        d = np.asarray(omega, dtype=float) ** (-self.A)
        return 2.0 * self.scale * d ** self.q + self.floor

    def as_dict(self) -> dict:
        return dict(self.__dict__)

    @classmethod
    def from_dict(cls, d: dict) -> "ElasticBound":
        return cls(**d)


_NOISE = 1e-13  # residuals below this are integrator noise, not expansion error


def _fit_viscous_bound(V: asy.ViscousLimit, om: np.ndarray, ref: np.ndarray) -> ViscousBound:
    if V.kind == "closed":
        return ViscousBound("closed", floor=2e-15)
    sel = om <= 1e-2
    r = V.eps(om[sel], 1) / ref[sel] - 1.0
    w = om[sel]
    if V.kind == "force":
        use = (np.abs(r) > _NOISE) & (w <= 1e-3)
        if use.sum() < 3:
            use = np.argsort(-np.abs(r))[:3]
        L = np.log(1.0 / w[use])
        X = np.stack([np.ones_like(L), 1.0 / L, 1.0 / L ** 2], axis=1)
        y = r[use] / (w[use] ** 2 * L ** 2)
        coeffs, *_ = np.linalg.lstsq(X, y, rcond=None)
        a, b, c = (float(x) for x in coeffs)
        # the model must cover every residual that is measurable (above the integrator's noise)
        meas = np.abs(r) > _NOISE
        Lm = np.log(1.0 / w[meas])
        model = w[meas] ** 2 * (abs(a) * Lm ** 2 + abs(b) * Lm + abs(c))
        scale = float(max(1.0, np.max(np.abs(r[meas]) / model))) if np.any(meas) else 1.0
        return ViscousBound("force", (a, b, c), scale, floor=1e-15)
    order = np.argsort(w)
    env = np.maximum.accumulate(np.abs(r[order]))
    return ViscousBound("envelope", env_omega=tuple(float(x) for x in w[order]),
                        env_value=tuple(float(x) for x in env), floor=1e-15)


def _fit_elastic_bound(E: asy.ElasticLimit, om: np.ndarray, ref: np.ndarray) -> ElasticBound:
    q = min(3.0, E.end_power + 1.0) if math.isfinite(E.end_power) else 3.0
    sel = om >= 1e2
    r = np.abs(E.eps(om[sel], 2) / ref[sel] - 1.0)
    d = E.delta(om[sel])
    use = r > _NOISE
    if not np.any(use):
        use = np.argsort(-r)[:3]
    scale = float(np.max(r[use] / d[use] ** q))
    return ElasticBound(E.A, q, scale, 1e-15)


# ------------------------------------------------------------------------------ the curve
#: Relative distance from a join within which the evaluator's side (decided in ln Omega, whose
#: rounding grows with |ln Omega|) may differ from a comparison of Omega with exp(s0): both bounds
#: hold there.
JOIN_SLACK = 1e-11


@dataclass
class MasterCurve(PanelRange):
    """Chebyshev panels of ln eps on [exp(s0), exp(s0 + npan width)], expansions beyond."""

    alpha: Fraction
    gamma: Fraction
    s0: float
    width: float
    coef: np.ndarray
    viscous: asy.ViscousLimit
    elastic: asy.ElasticLimit
    viscous_bound: ViscousBound
    elastic_bound: ElasticBound
    bound_inside: float
    settings: MasterSettings
    checks: dict = field(default_factory=dict)
    grid_log10_omega: np.ndarray = field(default_factory=lambda: np.empty(0))
    grid_eps: np.ndarray = field(default_factory=lambda: np.empty(0))

    def _kernel_viscous(self) -> np.ndarray:
        if self.viscous.kind == "closed":
            # eps = Omega (exponentially small error), as the force form with no correction term:
            # k Omega (1 - 0) is Omega to the last bit, where the power form's exp(ln Omega) lost
            # |ln Omega| ulps (2e-14 at Omega = 1e-300 against the 2e-15 bound)
            return np.array([0.0, 1.0, 0.0, 0.0, 1.0])
        return self.viscous.kernel_params()

    def _kernel_elastic(self) -> np.ndarray:
        p = self.elastic.kernel_params()
        if not math.isfinite(p[3]):
            p[3] = 0.0
        return p

    def eps(self, omega) -> np.ndarray:
        """eps at Omega (any shape; validated by the caller: finite and > 0)."""
        om = np.asarray(omega, dtype=float)
        out = chebyshev_panels_eval(om, self.s0, self.width, self.coef, self._kernel_viscous(),
                                    self._kernel_elastic())
        return out.reshape(om.shape)

    def viscous_eps(self, omega) -> np.ndarray:
        """The viscous expansion alone (the ladder's viscous rung)."""
        if self.viscous.kind == "closed":
            return np.asarray(omega, dtype=float).copy()  # eps = Omega, exponentially small error
        return self.viscous.eps(omega, 1)

    def bound_at(self, omega) -> np.ndarray:
        """Pointwise error bound (relative). Within JOIN_SLACK of a join either side may answer
        (the evaluator decides in ln Omega), so there both sides' bounds hold."""
        om = np.asarray(omega, dtype=float)
        lo_join, hi_join = self.omega_lo, self.omega_hi
        inside = (om >= lo_join * (1.0 - JOIN_SLACK)) & (om <= hi_join * (1.0 + JOIN_SLACK))
        out = np.where(inside, self.bound_inside, 0.0)
        lo = om < lo_join * (1.0 + JOIN_SLACK)
        hi = om > hi_join * (1.0 - JOIN_SLACK)
        if np.any(lo):
            out[lo] = np.maximum(out[lo], self.viscous_bound(om[lo]))
        if np.any(hi):
            out[hi] = np.maximum(out[hi], self.elastic_bound(om[hi]))
        return out

    def bound(self, omega) -> float:
        """Largest bound over the given Omegas (the expansion bounds are monotone, so only the
        extreme Omegas on each side are evaluated)."""
        om = np.asarray(omega, dtype=float).ravel()
        lo, hi = float(om.min()), float(om.max())
        lo_join, hi_join = self.omega_lo, self.omega_hi
        b = self.bound_inside if (hi >= lo_join * (1.0 - JOIN_SLACK) and lo <= hi_join * (1.0 + JOIN_SLACK)) else 0.0
        # the extremes of the Omegas beyond each join: one masked reduction each, no copy of them
        if lo < lo_join * (1.0 + JOIN_SLACK):
            top = hi if hi < lo_join * (1.0 + JOIN_SLACK) else float(
                np.max(om, where=om < lo_join * (1.0 + JOIN_SLACK), initial=-np.inf))
            b = max(b, float(np.max(self.viscous_bound(np.array([lo, top])))))
        if hi > hi_join * (1.0 - JOIN_SLACK):
            bottom = lo if lo > hi_join * (1.0 - JOIN_SLACK) else float(
                np.min(om, where=om > hi_join * (1.0 - JOIN_SLACK), initial=np.inf))
            b = max(b, float(np.max(self.elastic_bound(np.array([bottom, hi])))))
        return b

    # -- serialisation
    def as_dict(self) -> dict:
        return {
            "version": MASTER_VERSION,
            "alpha": str(self.alpha), "gamma": str(self.gamma),
            "s0": self.s0, "width": self.width, "coef": self.coef.tolist(),
            "omega_lo": self.omega_lo, "omega_hi": self.omega_hi,
            "viscous": {k: _nan_to_none(v) for k, v in self.viscous.as_dict().items()},
            "elastic": {k: (None if isinstance(v, float) and not math.isfinite(v) else v)
                        for k, v in self.elastic.as_dict().items()},
            "viscous_bound": self.viscous_bound.as_dict(),
            "elastic_bound": self.elastic_bound.as_dict(),
            "bound_inside": self.bound_inside,
            "settings": self.settings.as_dict(),
            "checks": self.checks,
            "grid": {"log10_omega": self.grid_log10_omega.tolist(), "eps": self.grid_eps.tolist()},
        }

    @classmethod
    def from_dict(cls, d: dict) -> "MasterCurve":
        if d.get("version") != MASTER_VERSION:
            raise ValueError(f"master curve version {d.get('version')} != {MASTER_VERSION}")
        ex = as_exponents(d["alpha"], d["gamma"])
        v = {k: (math.nan if x is None else x) for k, x in d["viscous"].items()}
        V = asy.ViscousLimit(ex.alpha, ex.gamma, v["kind"], v["k"], v["power"], v["c_log"], v["c_const"],
                             v["X"], v["lambda"], v["B"], v["K0"], v["L"])
        e = d["elastic"]
        E = asy.ElasticLimit(ex.alpha, ex.gamma, e["A"], e["C1"], e["C2"], e["E"],
                             math.inf if e["end_power"] is None else e["end_power"], e["T0"])
        return cls(ex.alpha, ex.gamma, float(d["s0"]), float(d["width"]),
                   np.asarray(d["coef"], dtype=float), V, E,
                   ViscousBound.from_dict(d["viscous_bound"]), ElasticBound.from_dict(d["elastic_bound"]),
                   float(d["bound_inside"]), MasterSettings.from_dict(d["settings"]), d.get("checks", {}),
                   np.asarray(d["grid"]["log10_omega"], dtype=float), np.asarray(d["grid"]["eps"], dtype=float))


def _nan_to_none(x):
    return None if (isinstance(x, float) and not math.isfinite(x)) else x


def build_master(problem, settings: MasterSettings | None = None, *, progress=None) -> MasterCurve:
    """Build the master curve (see the module docstring). ``progress``: callable(str) or None."""
    s = settings or MasterSettings()
    ex = as_exponents(problem)
    say = progress or (lambda msg: None)
    rng = np.random.default_rng(s.seed)

    lo10 = max(s.log10_omega_min, math.log10(stiff_omega_min(ex)))
    hi10 = s.log10_omega_max
    if not lo10 < hi10 - 1:
        raise ParameterError("log10_omega_min", s.log10_omega_min, "must be below log10_omega_max - 1")
    grid10 = np.round(np.arange(lo10, hi10 + 1e-9, s.grid_step), 10)
    grid = 10.0 ** grid10
    say(f"reference values on {grid.size} grid points")
    ref = reference_eps(ex, grid, s.rtol)

    V = asy.viscous_limit(ex)
    E = asy.elastic_limit(ex)
    vb = _fit_viscous_bound(V, grid, ref)
    eb = _fit_elastic_bound(E, grid, ref)

    # joins: the largest grid Omega below which the viscous bound stays <= join_tol, etc.
    vbg = vb(grid)
    ok_lo = np.flatnonzero(np.minimum.accumulate(vbg <= s.join_tol)) if vbg[0] <= s.join_tol else []
    omega_lo = grid[ok_lo[-1]] if len(ok_lo) else grid[0]
    omega_lo = min(omega_lo, 1e-2)
    ebg = eb(grid)
    ok_hi = np.flatnonzero(np.minimum.accumulate((ebg <= s.join_tol)[::-1])[::-1]) if ebg[-1] <= s.join_tol else []
    omega_hi = grid[ok_hi[0]] if len(ok_hi) else grid[-1]
    omega_hi = max(omega_hi, 1e2)

    s0 = math.log(omega_lo)
    npan = int(math.ceil((math.log(omega_hi) - s0) / s.width - 1e-9))
    n = s.degree
    k = np.arange(n + 1)
    x = np.cos(np.pi * (k + 0.5) / (n + 1))  # Chebyshev points of the first kind
    nodes = s0 + (np.arange(npan)[:, None] + (x[None, :] + 1.0) / 2.0) * s.width
    say(f"{npan} panels x {n + 1} nodes on Omega in [{omega_lo:.3g}, {math.exp(s0 + npan * s.width):.3g}]")
    vals = np.log(reference_eps(ex, np.exp(nodes.ravel()), s.rtol)).reshape(npan, n + 1)
    coef = np.array([cheb.chebfit(x, v, n) for v in vals])

    curve = MasterCurve(ex.alpha, ex.gamma, s0, s.width, coef, V, E, vb, eb, math.nan, s, {},
                        grid10, ref)

    # ---- held-out errors against the integrator
    held = np.exp(s0 + (np.arange(npan)[:, None] + rng.uniform(0, 1, (npan, s.heldout_per_panel))) * s.width).ravel()
    held_ref = reference_eps(ex, held, s.rtol)
    fit_err = float(np.max(np.abs(curve.eps(held) / held_ref - 1.0)))
    inside = (grid >= curve.omega_lo) & (grid <= curve.omega_hi)
    grid_err_inside = float(np.max(np.abs(curve.eps(grid[inside]) / ref[inside] - 1.0)))
    fit_err = max(fit_err, grid_err_inside)
    out = ~inside
    noise = integrator_bound(s.rtol, ex) if ex.alpha != ex.gamma else 2e-15
    # set before the bounds beyond the joins are read: a grid point at a join takes both sides' bounds
    curve.bound_inside = float(max(2.0 * (fit_err + noise), 2e-14))
    # beyond the joins: error against the grid, in units of (expansion bound + integrator noise)
    grid_err_outside = float(np.max(np.abs(curve.eps(grid[out]) / ref[out] - 1.0)
                                    / (curve.bound_at(grid[out]) + noise))) if np.any(out) else 0.0

    curve.checks = {
        "fit_err_heldout": fit_err,
        "n_heldout": int(held.size + inside.sum()),
        "grid_err_outside_over_bound": grid_err_outside,
        "n_nodes": int(npan * (n + 1)),
        "join_tol": s.join_tol,
    }
    if s.n_highprec > 0:
        widen_by_check(curve, mpmath_check(curve, s.n_highprec, s.highprec_digits, s.seed, say))
    return curve


def mpmath_check(curve: MasterCurve, n: int, digits: int, seed: int, progress=None) -> dict:
    """The mpmath reference at ``n`` log-random points (not nodes) from a hundredth of the curve's
    lower join to a hundred times its upper one: seconds, so built apart from the curve (the
    ladder's "mpmath check") and applied by :func:`widen_by_check`."""
    from ..core.highprec import reference_collision
    ex = as_exponents(curve.alpha, curve.gamma)
    g = 10.0 ** curve.grid_log10_omega
    rng = np.random.default_rng([seed, 1])
    lo, hi = math.log(max(g[0], curve.omega_lo / 100)), math.log(min(g[-1], curve.omega_hi * 100))
    pts = np.exp(rng.uniform(lo, hi, n))
    if ex.alpha <= ex.gamma:
        pts = np.maximum(pts, 1e-3)  # the mpmath reference is explicit too: keep it cheap
    (progress or (lambda m: None))(f"checking against the mpmath reference at {pts.size} points")
    hp = [float(reference_collision(ex, float(w), digits=digits).eps) for w in pts]
    return {"alpha": str(ex.alpha), "gamma": str(ex.gamma), "digits": digits, "omega": pts.tolist(), "eps": hp}


def widen_by_check(curve: MasterCurve, check: dict) -> None:
    """Apply an mpmath check to its curve. It can only widen the bound inside the joins: to twice
    the curve's error found there, or twice (held-out fit error + the integrator's error found), if
    either is larger; the errors beyond the joins are recorded in units of the local bound."""
    ex = as_exponents(curve.alpha, curve.gamma)
    pts, hp = np.asarray(check["omega"], float), np.asarray(check["eps"], float)
    err = np.abs(curve.eps(pts) / hp - 1.0)
    inside = (pts >= curve.omega_lo) & (pts <= curve.omega_hi)
    worst = float(np.max(err[inside])) if np.any(inside) else 0.0
    i_err = float(np.max(np.abs(reference_eps(ex, pts, curve.settings.rtol) / hp - 1.0)))
    if ex.alpha != ex.gamma:
        curve.bound_inside = max(curve.bound_inside, 2.0 * (curve.checks.get("fit_err_heldout", 0.0) + i_err))
    curve.bound_inside = float(max(curve.bound_inside, 2.0 * worst))
    curve.checks["highprec"] = {
        "n": int(pts.size), "omega": pts.tolist(), "eps": hp.tolist(), "max_rel_err_master": worst,
        "max_rel_err_integrator": i_err,
        "max_err_over_bound_outside": float(np.max(err[~inside] / curve.bound_at(pts[~inside]))) if np.any(~inside) else 0.0}

"""What a rung of the method ladder is, and the tolerance formulas every rung shares.

A rung (:class:`Rung`) is one way to compute eps(Omega). It declares, for a :class:`Request`
(exponents, Omegas, tolerance, end rule, what is built):

* ``ends``: the end-of-contact rules it serves where they differ (alpha > gamma; where
  alpha <= gamma the force never pulls, both rules give the same collision and every rung serves,
  except one of ``ends = ("overlap",)``: the overlap rule's own numbers exist only where they differ);
* ``outside(req)``: why the Omegas are outside its domain (None when inside);
* ``edges(req)``: the Omegas where its domain begins or ends (or its quote changes kind): the
  chooser cuts an array there and gives each part its own rung (a point at an edge goes above it);
* ``needs(req)``: the build it reads (a key of the ladder's builds, e.g. "calibration"), or None;
* ``floor(req)``: the smallest bound it can state once that build is made (0 when not known): the
  chooser makes no build for a request whose tolerance is below the floor of every rung reading it;
* ``cost`` (seconds per point) and ``price(req)`` (expected seconds for the request);
* ``bound(req, built)``: its relative error bound over the request and the :class:`Setting` that
  meets it (the rtol or digits it runs at, as numbers: ``evaluate`` reads them back, never derives
  them again);
* ``evaluate(req, built, setting, omega)``: eps;
* ``exact``: True for a closed form whose bound is at rounding level over its whole domain (the
  exact family alpha = 2 gamma + 1): the chooser takes it first wherever it serves and meets the
  tolerance, whatever the other rungs cost, and makes no build for such a request (no rung can
  be more accurate, and a cached curve would make the answer depend on the cache's state);
* ``conditioned``: True for the double-precision integrations, whose bound grows near the overlap
  rule's sticking boundary (core.collision.conditioning): the quote's ``widen`` gives the factor
  from the answer, and the chooser checks the widened bound after the evaluation;
* ``collision(problem, omega, rtol=, digits=, t_eval=)``: one whole collision (a
  :class:`~restitution.core.results.Collision`), for the rungs that integrate or solve one
  (``collides``; ``trajectories`` where it samples ``t_eval``): ``restitution.collide`` runs these
  by the same names as ``epsilon`` (:mod:`restitution.fast.collide`).

``quote(req)`` turns these into a :class:`Quote`, the one thing the chooser
(:mod:`restitution.fast.ladder`) compares, as scipy's ``solve_ivp`` compares nothing but picks an
``OdeSolver`` from ``METHODS``. The registry is :mod:`restitution.fast.rungs`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any, Callable, Mapping

import numpy as np

from ..core.conditioning import conditioning, plain_accuracy, plain_factor_floor
from ..core.exponents import read_through
from ..core.problem import Problem

__all__ = ["Quote", "Request", "Rung", "Setting", "TOL_FLOOR", "DEFAULT_TOL", "INTEGRATOR_BOUND_FACTOR",
           "INTEGRATOR_BOUND_FLOOR", "integrator_bound", "integrator_rtol", "reference_rtol", "reference_bound",
           "highprec_digits", "highprec_bound"]

#: Tolerance when none is given (and no method is forced).
DEFAULT_TOL = 1e-9
#: No method returns a double closer than this to the true eps (rounding of the result itself).
TOL_FLOOR = 2.3e-16

#: Validated accuracy of the compiled integrator under the force rule: |error| <= FACTOR * rtol + FLOOR
#: (relative), times core.conditioning.exponent_factor (alpha + gamma > 4, measured there); under the
#: overlap rule collide's (core.conditioning.plain_factor_floor). Measured against the mpmath
#: reference in tests/library/test_epsilon.py and the benchmark (observed: <= 1.6 rtol for rtol >=
#: 1e-12 and <= 6e-15 at rtol = 1e-14 over Omega 1e-8..1e12 for the common pairs).
INTEGRATOR_BOUND_FACTOR = 10.0
INTEGRATOR_BOUND_FLOOR = 5e-14


def _integrator_factor_floor(problem) -> tuple[float, float]:
    return plain_factor_floor(problem, INTEGRATOR_BOUND_FACTOR, INTEGRATOR_BOUND_FLOOR)


def _rtol_for(tol: float, factor: float, floor: float) -> float:
    """The rtol whose bound factor rtol + floor is half of what tol leaves above the floor (the
    other half is the margin)."""
    return min(1e-6, max(1e-14, (tol - floor) / (2 * factor)))


# ``problem`` below: a Problem, whose rule applies (an Exponents or a pair: the force rule).
def integrator_bound(rtol: float, problem) -> float:
    """Relative bound of the compiled integrator at ``rtol`` for ``problem``."""
    factor, floor = _integrator_factor_floor(problem)
    return factor * rtol + floor


def integrator_rtol(tol: float, problem) -> float:
    return _rtol_for(tol, *_integrator_factor_floor(problem))


def reference_bound(rtol: float, problem) -> float:
    """The scipy reference's (core.collision.collide) bound: what collide states before conditioning."""
    return plain_accuracy(problem, rtol)


def reference_rtol(tol: float, problem) -> float:
    return _rtol_for(tol, *plain_factor_floor(problem))


def highprec_digits(tol: float) -> int:
    """Digits of the mpmath reference for a tolerance (three to spare, 15 to 60)."""
    return int(min(60, max(15, math.ceil(-math.log10(tol)) + 3)))


def highprec_bound(digits: int) -> float:
    """10^(1 - digits), at least the rounding of the result to a double."""
    return max(10.0 ** (1 - digits), TOL_FLOOR)


@dataclass(frozen=True)
class Setting:
    """What a rung runs at for one request, as a value: ``rtol`` (the integrators'), ``digits`` (the
    mpmath reference's), ``label`` (whatever else names it: "c0-c2", "uniform form", why no bound
    is stated) and ``end`` (the rule it runs under). ``str()`` is how tables and ``--json`` show it,
    e.g. "rtol=1e-10, overlap"; an empty setting shows as "".

    Examples
    --------
    >>> str(Setting(rtol=1.25e-10, end="overlap")), str(Setting(digits=20)), str(Setting(label="c0-c2"))
    ('rtol=1.25e-10, overlap', 'digits=20', 'c0-c2')
    >>> bool(Setting())
    False
    """

    rtol: float | None = None
    digits: int | None = None
    label: str = ""
    end: str = "force"

    def __str__(self) -> str:
        parts = [] if self.rtol is None else [f"rtol={self.rtol:.3g}"]
        if self.digits is not None:
            parts.append(f"digits={self.digits}")
        if self.label:
            parts.append(self.label)
        if self.end == "overlap":
            parts.append("overlap")
        return ", ".join(parts)

    def __bool__(self) -> bool:
        return bool(str(self))


@dataclass
class Quote:
    """One rung's offer for one request: its bound over the Omegas, expected seconds, and a runner
    (None when it cannot serve; then ``reason`` says why)."""

    name: str
    bound: float
    cost: float
    setting: Setting = field(default_factory=Setting)
    reason: str = ""
    needs_build: str | None = None   # the build it waits for (not built yet)
    floor: float = 0.0               # with needs_build: the smallest bound it can state once built
    run: Callable | None = None
    coefficients: dict | None = None
    widen: Callable | None = None   # eps -> factor on ``bound`` (None: the bound holds as quoted)
    exact: bool = False             # taken first where it meets tol (Rung.exact)
    serves: bool = True             # False: the rung does not serve this end rule at all


@dataclass(frozen=True)
class Request:
    """What is asked (the problem: exponents and end rule; flat Omegas, tolerance) and what is built."""

    problem: Problem
    omega: np.ndarray
    tol: float
    builds: Mapping[str, Any] = field(default_factory=dict)
    stream: Any = None
    #: How many points the request stands for, when ``omega`` is only its range's two ends (the
    #: chooser quoting a part of an array: every bound depends on the range, every price on n).
    size: int | None = None

    # Every rung's quote asks for the range: one pass over the Omegas per request, not per rung.
    @cached_property
    def lo(self) -> float:
        return float(np.min(self.omega))

    @cached_property
    def hi(self) -> float:
        return float(np.max(self.omega))

    @property
    def n(self) -> int:
        return int(self.omega.size if self.size is None else self.size)

    ex = read_through("problem", "ex")
    end = read_through("problem", "end", "The end rule asked for.")
    rules_differ = read_through("problem", "rules_differ",
                                "The force can vanish during contact (alpha > gamma): the two end rules differ.")
    effective_end = read_through("problem", "effective_end",
                        'The end rule whose numbers apply: "overlap" only where it differs from the force rule.')


class Rung:
    """Base of every rung (see the module docstring); subclasses set ``name``, ``cost`` and override
    what differs from the defaults (force rule only, whole Omega range, no build)."""

    name: str = ""
    ends: tuple[str, ...] = ("force",)
    cost: float = 0.0
    conditioned: bool = False
    exact: bool = False
    collides: bool = False
    trajectories: bool = False

    def serves(self, req: Request) -> bool:
        return self.serves_rule(req.end, req.rules_differ)

    def serves_rule(self, end: str, rules_differ: bool) -> bool:
        """Whether it serves the end rule ``end`` for exponents where the rules differ or not."""
        if "force" not in self.ends:   # the overlap rule's own numbers, which exist only where the rules differ
            return end == "overlap" and rules_differ
        return end in self.ends or not rules_differ

    def collision(self, problem, omega: float, *, rtol: float, digits: int, t_eval=None):
        """One collision for the Problem ``problem`` at ``omega`` (rungs with ``collides``)."""
        raise NotImplementedError

    def outside(self, req: Request) -> str | None:
        return None

    def edges(self, req: Request) -> tuple[float, ...]:
        return ()

    def needs(self, req: Request) -> str | None:
        return None

    def floor(self, req: Request) -> float:
        return 0.0

    def price(self, req: Request) -> float:
        return self.cost * req.n

    def bound(self, req: Request, built) -> tuple[float, Setting]:
        raise NotImplementedError

    def evaluate(self, req: Request, built, setting: Setting, omega: np.ndarray) -> np.ndarray:
        raise NotImplementedError

    def coefficients(self, req: Request, built) -> dict | None:
        return None

    def quote(self, req: Request) -> Quote:
        if not self.serves(req):
            return Quote(self.name, math.inf, math.inf, reason=f"serves the {' and '.join(self.ends)} rule only",
                         serves=False)
        why = self.outside(req)
        if why:
            return Quote(self.name, math.inf, math.inf, reason=why)
        need = self.needs(req)
        if need is not None and need not in req.builds:
            return Quote(self.name, math.nan, self.price(req), reason=f"needs the {need} (not built yet)",
                         needs_build=need, floor=self.floor(req))
        built = req.builds.get(need) if need is not None else None
        b, setting = self.bound(req, built)
        if isinstance(setting, str):   # a rung with nothing to run at names itself in words
            setting = Setting(label=setting)
        reason = "" if math.isfinite(b) else "no finite measured error over these Omegas"
        widen = None
        if self.conditioned:
            widen = lambda eps: float(np.max(conditioning(req.problem, eps, req.omega)))  # noqa: E731
        return Quote(self.name, b, self.price(req), setting, reason,
                     run=lambda om: self.evaluate(req, built, setting, om),
                     coefficients=self.coefficients(req, built), widen=widen, exact=self.exact)

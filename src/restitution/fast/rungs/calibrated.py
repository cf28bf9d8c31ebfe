"""The rungs read from the master curve's build (:mod:`restitution.fast.calibration`): Mueller &
Poeschel's Pade form, the two expansions and the curve itself; and the relation rungs, each from
its own build, measured on the curve's grid. Each one's bound
is SAFETY times its largest measured error at the grid points bracketing the request (the
expansions beyond the grid: their fitted remainder models; the master curve: its own bound)."""

from __future__ import annotations

import math

import numpy as np

from ...core.connection import eps_from_connection
from ...core.exponents import as_exponents
from ..calibration import MASTER, Calibration, Relation, pade_mp2011, relation_build
from ..rung import Request, Rung, Setting, integrator_bound

__all__ = ["SAFETY", "RelationRung", "PadeRung", "ViscousRung", "ElasticRung", "MasterRung"]

#: Profile bounds are SAFETY times the largest measured error at the bracketing grid points.
SAFETY = 3.0


def profile_bound(cal: Calibration, name: str, lo10: float, hi10: float) -> float:
    g = cal.master.grid_log10_omega
    e = cal.profiles[name]
    if lo10 < g[0] - 1e-9 or hi10 > g[-1] + 1e-9:
        return math.inf
    i0 = max(0, int(np.searchsorted(g, lo10, side="right")) - 1)
    i1 = min(g.size - 1, int(np.searchsorted(g, hi10, side="left")))
    grid = integrator_bound(cal.master.settings.rtol, as_exponents(cal.master.alpha, cal.master.gamma))
    return SAFETY * float(np.max(e[i0:i1 + 1])) + grid


class _Calibrated(Rung):
    cost = 2e-8

    def needs(self, req: Request) -> str | None:
        return MASTER

    def bound(self, req: Request, cal: Calibration) -> tuple[float, Setting]:
        if self.name in cal.unavailable:
            return math.inf, Setting(label=cal.unavailable[self.name])
        if self.name not in cal.profiles:
            return math.inf, Setting(label="not calibrated")
        b = profile_bound(cal, self.name, math.log10(req.lo), math.log10(req.hi))
        return b, Setting(label=self.setting)


    def edges(self, req):
        # the calibration grid's ends: a profile bound exists only inside it
        cal = req.builds.get(MASTER)
        if cal is None or cal.master.grid_log10_omega.size == 0:
            return ()
        g = cal.master.grid_log10_omega
        return (10.0 ** float(g[0]), 10.0 ** float(g[-1]))


class RelationRung(_Calibrated):
    """Omega~ = c0 + c1 Omega + c2 Omega^2 with the c's of one :class:`Relation` (a build of its own),
    eps = (Omega~/Omega)^((gamma+1)/(alpha-1-2gamma)); bound: SAFETY x its largest error measured on the master curve's calibration grid (Omega 1e-12..1e14
    in steps of 0.1 decade) at the grid points bracketing the request, plus the grid's own accuracy."""

    setting = "c0-c2"

    def __init__(self, relation: Relation):
        self.name = relation.name

    def needs(self, req):
        return relation_build(self.name)

    def evaluate(self, req, cal, setting, omega):
        return eps_from_connection(req.ex, omega, cal.relations[self.name]["c"])


class PadeRung(_Calibrated):
    """Mueller & Poeschel's Pade form in v = Omega^(-3/10), alpha = 3/2, gamma = 1/2 only; bound:
    SAFETY x its largest error measured on the master curve's calibration grid (Omega 1e-12..1e14
    in steps of 0.1 decade) at the grid points bracketing the request, plus the grid's own accuracy."""

    name, setting = "pade-mp2011", ""

    def evaluate(self, req, cal, setting, omega):
        return pade_mp2011(omega)


class _Expansion(_Calibrated):
    setting = "expansion"

    def model(self, cal: Calibration):
        raise NotImplementedError

    def bound(self, req, cal):
        if self.name in cal.unavailable:
            return math.inf, Setting(label=cal.unavailable[self.name])
        g = cal.master.grid_log10_omega
        lo10, hi10 = math.log10(req.lo), math.log10(req.hi)
        b = 0.0
        if hi10 >= g[0] and lo10 <= g[-1]:
            b = profile_bound(cal, self.name, max(lo10, g[0]), min(hi10, g[-1]))
        ends = np.array([req.lo, req.hi])
        beyond = ends[(np.log10(ends) < g[0]) | (np.log10(ends) > g[-1])]
        if beyond.size:
            b = max(b, float(np.max(SAFETY * self.model(cal)(beyond))))
        return b, Setting(label=self.setting)


class ViscousRung(_Expansion):
    """The small-Omega expansion (:mod:`restitution.core.asymptotics`), Omega <= 1e-3 (1e-2 where
    alpha <= gamma); bound: inside the calibration grid as the Pade rung's, beyond it SAFETY x the
    fitted remainder model of :mod:`restitution.fast.master`."""

    name, cost = "viscous", 2e-8

    def outside(self, req):
        limit = self._limit(req)
        return f"Omega > {limit:g}" if req.hi > limit else None

    @staticmethod
    def _limit(req) -> float:
        return 1e-3 if req.ex.alpha > req.ex.gamma else 1e-2   # the "force" kind of asy.viscous_limit

    def edges(self, req):
        return (self._limit(req),)

    def model(self, cal):
        return cal.master.viscous_bound

    def evaluate(self, req, cal, setting, omega):
        return cal.master.viscous_eps(omega)


class ElasticRung(_Expansion):
    """The large-Omega expansion (:mod:`restitution.core.asymptotics`), Omega >= 1e2; bound: inside
    the calibration grid as the Pade rung's, beyond it SAFETY x the fitted remainder model of
    :mod:`restitution.fast.master`."""

    name, cost = "elastic", 3e-8

    def outside(self, req):
        return "Omega < 100" if req.lo < 1e2 else None

    def edges(self, req):
        return (1e2,)

    def model(self, cal):
        return cal.master.elastic_bound

    def evaluate(self, req, cal, setting, omega):
        return cal.master.elastic.eps(omega, 2)


class MasterRung(_Calibrated):
    """The Chebyshev master curve with the expansions beyond its joins (:mod:`restitution.fast.master`),
    every Omega > 0; bound: its measured held-out error inside its range (x2), the expansions'
    bounds outside."""

    name, cost = "master", 4e-8

    def edges(self, req):
        return ()   # every Omega

    def bound(self, req, cal):
        m = cal.master
        return m.bound(req.omega), Setting(label=f"{m.coef.shape[0]} panels")

    def evaluate(self, req, cal, setting, omega):
        return cal.master.eps(omega)

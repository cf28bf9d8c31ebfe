"""The uniform rung: the uniform approximation of :mod:`restitution.core.uniform`, fitted and built
on its own (alpha > gamma under the force rule, gamma < alpha < 2 gamma + 1 under the overlap rule;
Omega in FORM_RANGE), its error estimate the build's measured one (twice the largest error on
held-out points plus the references' accuracy: a measurement, not a proof). Where the problem is
solvable it answers with the exact closed form instead (alpha = gamma; the linear spring-dashpot,
both end rules). Not for alpha = 2 gamma + 1 other than the dashpot: the exact-family rung
(:mod:`restitution.fast.rungs.exact_family`) answers those exactly.

It was called "closed-form" until the fitted formula was named for what it is; the ladder still
accepts that name, with a note (:data:`restitution.fast.ladder.RENAMED`)."""

from __future__ import annotations


import numpy as np

from ...core import asymptotics as asy
from ...core.uniform import FORM_RANGE
from ..uniform_build import REFERENCE_ACCURACY
from ..uniform_eval import uniform_eps
from ..calibration import UNIFORM, UNIFORM_OVERLAP
from ..rung import Request, Rung, Setting

__all__ = ["Uniform", "EXACT_BOUND"]

#: Bound of the exact forms (validated against mpmath).
EXACT_BOUND = 2e-14
#: Seconds per point: alpha = gamma, the dashpot (a few special functions in Python), the uniform form.
COSTS = {"equal": 5e-7, "dashpot": 5e-6, "uniform": 1e-7}


def _kind(req: Request) -> str:
    ex = req.ex
    if ex.alpha == ex.gamma:
        return "equal"
    if (ex.alpha, ex.gamma) == (1, 0):
        return "dashpot"
    if not ex.alpha > ex.gamma:
        return "none"
    if ex.alpha == 2 * ex.gamma + 1:
        return "family"
    if req.end == "overlap" and not ex.alpha < 2 * ex.gamma + 1:
        return "sticks"
    return "uniform"


def dashpot_eps(omega: np.ndarray, end: str = "force") -> np.ndarray:
    from ...core.dashpot import dashpot_collision
    return np.array([dashpot_collision(float(w), end=end).eps for w in np.ravel(omega)])


class Uniform(Rung):
    """The uniform approximation (:mod:`restitution.core.uniform`, a build of its own per end rule),
    Omega in FORM_RANGE, its error the build's estimate: twice its largest error measured on points
    used neither in its fit nor in the choice of its shape, plus the references' accuracy. Where the
    problem is solvable, the exact closed form instead (alpha = gamma by
    :mod:`restitution.core.asymptotics`; the linear spring-dashpot by :mod:`restitution.core.dashpot`),
    bound EXACT_BOUND (validated against mpmath)."""

    name = "uniform"
    ends = ("force", "overlap")
    # no collision: the approximation gives eps alone (collide's "closed-form", the exact family's
    # whole collision, is an alias of "exact-family": restitution.fast.collide.ALIASES)

    def outside(self, req):
        kind = _kind(req)
        if kind == "none":
            return ("alpha < gamma: the viscous limit's first correction, which the uniform approximation needs, "
                    "is not known in closed form")
        if kind == "family":
            return "alpha = 2 gamma + 1: the exact-family rung answers exactly, no uniform approximation is fitted"
        if kind == "sticks":
            return "alpha >= 2 gamma + 1: the bodies can stick under the overlap rule, no uniform approximation"
        if kind == "dashpot" and req.end == "overlap" and req.lo <= 0.25:
            return "Omega <= 1/4: the overdamped dashpot sticks under the overlap rule"
        if kind == "uniform" and (req.lo < FORM_RANGE[0] or req.hi > FORM_RANGE[1]):
            return f"Omega outside [{FORM_RANGE[0]:g}, {FORM_RANGE[1]:g}] (where its error was measured)"
        return None

    def edges(self, req):
        kind = _kind(req)
        if kind == "dashpot" and req.end == "overlap":
            return (0.25,)
        return FORM_RANGE if kind == "uniform" else ()

    def needs(self, req):
        if _kind(req) != "uniform":
            return None
        return UNIFORM_OVERLAP if req.end == "overlap" else UNIFORM

    def floor(self, req):
        # a form's error estimate adds its references' accuracy to what it measured (uniform_build)
        return REFERENCE_ACCURACY

    def price(self, req):
        return COSTS[_kind(req)] * req.n

    def bound(self, req, form):
        kind = _kind(req)
        if kind == "equal":
            return EXACT_BOUND, Setting(label="alpha = gamma")
        if kind == "dashpot":
            return EXACT_BOUND, Setting(label="spring-dashpot", end=req.end)
        return form.bound_eps, Setting(label="uniform approximation", end=req.end)

    def coefficients(self, req, form):
        kind = _kind(req)
        if kind == "equal":
            return {"exact": "alpha = gamma (restitution.core.asymptotics.equal_exponents_eps)"}
        if kind == "dashpot":
            return {"exact": "linear spring-dashpot (restitution.core.dashpot)"}
        return {**form.coefficients(), "bound_one_minus_eps": form.bound_one_minus_eps}

    def evaluate(self, req, form, setting, omega):
        kind = _kind(req)
        if kind == "equal":
            return asy.equal_exponents_eps(omega)
        if kind == "dashpot":
            return dashpot_eps(omega, req.end)
        return uniform_eps(form, omega)



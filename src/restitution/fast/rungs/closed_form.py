"""The closed-form rung: exact where the problem is solvable (alpha = gamma; the linear
spring-dashpot, both end rules), otherwise the uniform form of :mod:`restitution.core.uniform`
built on its own (alpha > gamma under the force rule, gamma < alpha < 2 gamma + 1 under the overlap
rule; Omega in FORM_RANGE, its stated bound). Not for alpha = 2 gamma + 1 other than the dashpot:
the exact-family rung (:mod:`restitution.fast.rungs.exact_family`) answers those exactly."""

from __future__ import annotations


import numpy as np

from ...core import asymptotics as asy
from ...core.uniform import FORM_RANGE
from ..uniform_build import REFERENCE_ACCURACY
from ..uniform_eval import uniform_eps
from ..calibration import UNIFORM, UNIFORM_OVERLAP
from ..rung import Request, Rung, Setting
from .exact_family import family_collision

__all__ = ["ClosedForm", "EXACT_BOUND"]

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


class ClosedForm(Rung):
    """Exact where the problem is solvable (alpha = gamma by :mod:`restitution.core.asymptotics`;
    the linear spring-dashpot by :mod:`restitution.core.dashpot`), bound EXACT_BOUND (validated
    against mpmath); otherwise the uniform form (:mod:`restitution.core.uniform`, a build of its own
    per end rule), Omega in FORM_RANGE, bound the form's stated one: twice its largest error on
    points used neither in its fit nor in the choice of its shape."""

    name = "closed-form"
    ends = ("force", "overlap")
    # one collision in closed form, trajectory quantities included, exists for the linear dashpot
    # and the family that maps onto it (what collide's "closed-form" has always covered)
    collides = True

    def collision(self, problem, omega, *, rtol, digits, t_eval=None):
        return family_collision(problem, omega, self.name)

    def outside(self, req):
        kind = _kind(req)
        if kind == "none":
            return ("alpha < gamma: the viscous limit's first correction, which the uniform form needs, "
                    "is not known in closed form")
        if kind == "family":
            return "alpha = 2 gamma + 1: the exact-family rung answers exactly, no uniform form is fitted"
        if kind == "sticks":
            return "alpha >= 2 gamma + 1: the bodies can stick under the overlap rule, no uniform form"
        if kind == "dashpot" and req.end == "overlap" and req.lo <= 0.25:
            return "Omega <= 1/4: the overdamped dashpot sticks under the overlap rule"
        if kind == "uniform" and (req.lo < FORM_RANGE[0] or req.hi > FORM_RANGE[1]):
            return f"Omega outside [{FORM_RANGE[0]:g}, {FORM_RANGE[1]:g}] (where its bound was measured)"
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
        # a form's stated bound adds its references' accuracy to what it measured (uniform_build)
        return REFERENCE_ACCURACY

    def price(self, req):
        return COSTS[_kind(req)] * req.n

    def bound(self, req, form):
        kind = _kind(req)
        if kind == "equal":
            return EXACT_BOUND, Setting(label="alpha = gamma")
        if kind == "dashpot":
            return EXACT_BOUND, Setting(label="spring-dashpot", end=req.end)
        return form.bound_eps, Setting(label="uniform form", end=req.end)

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



"""The compiled integrator as a rung (:mod:`restitution.fast.integrator`), force rule: rtol from
the tolerance, bound integrator_bound(rtol) (validated against the mpmath reference)."""

from __future__ import annotations

import math

from ..master import reference_eps, stiff_omega_min
from ..rung import Rung, Setting, integrator_bound, integrator_rtol

__all__ = ["Integrator", "OMEGA_MAX", "printed", "integrator_collision"]

#: Largest Omega the compiled integrator is validated at (as messages print it: 1e14, not 1e+14).
OMEGA_MAX = 1e14


def printed(x: float) -> str:
    return f"{x:g}".replace("e+", "e")


def integrator_collision(problem, omega, rtol):
    """One collision by the compiled integrator under the problem's end rule (both rungs named
    "integrator" run it): eps, tau_b, x_b, tau_c, x_c, no ``one_minus_eps``; Omega from the stiff
    limit (the overlap rule: 1e-5) to OMEGA_MAX."""
    from ...core.collision import RTOL_MIN, StickError
    from ...core.errors import number_in
    from ...core.model import at_most_one
    from ...core.results import Collision
    from ..integrator import COLUMNS, END_FORCE, END_SEPARATION, END_STUCK, collide_fast
    from ..master import TIMES_OMEGA_MIN

    ex = problem.ex
    lo = max(stiff_omega_min(problem), TIMES_OMEGA_MIN)
    omega = number_in("omega", omega, lo, OMEGA_MAX, why="the compiled integrator's range (method reference "
                      "or epsilon() cover the rest)")
    rtol = number_in("rtol", rtol, RTOL_MIN, 1e-6)
    row = dict(zip(COLUMNS, collide_fast(ex.p, ex.q_alpha, ex.q_gamma, [omega], rtol, problem.effective_end)[0]))
    if int(row["ended_by"]) == END_STUCK:
        raise StickError("omega", omega, "under the overlap rule contact never ends here: the "
                                         "attractive phase stops the return and the bodies stay together "
                                         "(eps = 0); use end=force")
    ends = {END_FORCE: "force", END_SEPARATION: "separation"}
    if int(row["ended_by"]) not in ends:
        raise ArithmeticError(f"the compiled integrator failed at Omega = {omega:g}")
    return Collision(problem, omega, "forward", float(at_most_one(row["eps"])), float(row["tau_b"]),
                     float(row["x_b"]), float(row["tau_c"]), float(row["x_c"]), ends[int(row["ended_by"])], rtol)


class Integrator(Rung):
    """The compiled DOP853 integrator (:mod:`restitution.fast.integrator`) at an rtol from the
    tolerance, Omega in [1e-300, OMEGA_MAX] (alpha <= gamma: from the stiff limit); bound
    INTEGRATOR_BOUND_FACTOR rtol + INTEGRATOR_BOUND_FLOOR, times ((alpha + gamma) / 4)^3 where
    alpha + gamma > 4 (:func:`restitution.core.conditioning.exponent_factor`), validated against
    mpmath."""

    name, cost = "integrator", 6e-5
    conditioned = True
    collides = True
    #: What makes the explicit method slow below its range, for the refusal.
    stiff_below = "stiff below"

    def collision(self, problem, omega, *, rtol, digits, t_eval=None):
        return integrator_collision(problem, omega, rtol)

    def outside(self, req):
        wmin = stiff_omega_min(req.problem)
        if req.lo < wmin or req.hi > OMEGA_MAX:
            return f"Omega outside [{printed(wmin)}, {printed(OMEGA_MAX)}] (explicit method; {self.stiff_below})"
        return None

    def edges(self, req):
        return (stiff_omega_min(req.problem), OMEGA_MAX)

    def price(self, req):
        # alpha <= gamma: the creeping return takes ~1/Omega steps; alpha > gamma: the force's zero
        # comes ~ln(1/Omega) relaxation times after the turn (25 times the cost at 1e-300)
        if req.rules_differ:
            return self.cost * req.n * (1.0 + max(0.0, -math.log(req.lo)) / 28.0)
        return self.cost * req.n * (1.0 + 1e-3 / req.lo)

    def bound(self, req, built):
        rtol = integrator_rtol(req.tol, req.problem)
        return integrator_bound(rtol, req.problem), Setting(rtol=rtol)

    def evaluate(self, req, built, setting, omega):
        return reference_eps(req.problem, omega, setting.rtol)

"""The public calls, on top of the four layers: ``epsilon`` with every rung of the ladder (the fast
layer's, and the paper's relations from the audit layer), and ``collide``: one collision by any of
the integrators, as one result type.

``Ladder`` and ``RUNG_NAMES`` here are the full ladder; :mod:`restitution.fast.ladder` alone knows
only the rungs that do not need the paper.
"""

from __future__ import annotations

from .audit.relations import PAPER_C, PERTURBATION
from .core import collision as _collision
from .core.errors import ParameterError, number_in
from .core.exponents import as_exponents
from .core.results import Collision, end_rule
from .fast import ladder as _ladder
from .fast.calibration import FITTED_C
from .fast.ladder import EpsResult

__all__ = ["epsilon", "EpsResult", "Ladder", "RUNG_NAMES", "RELATIONS", "collide", "Collision", "METHODS",
           "inverse_collide", "collide_many"]

#: The relation rungs of the full ladder, in the order the chooser lists them.
RELATIONS = (PAPER_C, FITTED_C, *PERTURBATION)
RUNG_NAMES = _ladder.rung_names(RELATIONS)


class Ladder(_ladder.Ladder):
    """:class:`restitution.fast.ladder.Ladder` with the paper's relation rungs."""

    def __init__(self, problem, **kwargs):
        kwargs.setdefault("relations", RELATIONS)
        super().__init__(problem, **kwargs)


def epsilon(*, alpha, gamma, omega=None, g=None, D1=None, D2=None, tol: float | None = 1e-9,
            method: str | None = None, build: bool | None = None, end: str = "force") -> EpsResult:
    """Coefficient of restitution to a relative tolerance ``tol`` by the cheapest adequate rung of
    the full ladder (see :func:`restitution.fast.ladder.epsilon` for the arguments and result).

    ``end="overlap"`` (contact lasts until the overlap returns to 0, as in LAMMPS without
    limit_damping) is served only by the rungs that declare that rule (``Rung.ends``,
    :mod:`restitution.fast.rung`): the compiled integrator, that rule's own master curve, the exact
    family alpha = 2 gamma + 1 (the linear dashpot at (gamma+1) Omega, taken first for those pairs),
    the reference and the mpmath integrators; for alpha <= gamma both rules give the same eps and
    every rung serves."""
    return _ladder.epsilon(alpha=alpha, gamma=gamma, omega=omega, g=g, D1=D1, D2=D2, tol=tol,
                           method=method, build=build, relations=RELATIONS, end=end)


#: The integrators ``collide`` can run.
METHODS = ("reference", "fast", "highprec", "closed-form")


def collide(alpha, gamma, omega, *, method: str = "reference", rtol: float = 1e-12, t_eval=None,
            digits: int = 30, end: str = "force") -> Collision:
    """One forward collision x'' + Omega x^alpha + x^gamma x' = 0, x(0) = 0, x'(0) = 1, to the end of
    contact; every method returns a :class:`~restitution.core.results.Collision`.

    ``method``:

    * ``"reference"`` (default): scipy's DOP853/Radau in smooth variables
      (:func:`restitution.core.collision.collide`), Omega in [1e-12, 1e10], ``t_eval`` samples the
      trajectory; relative accuracy 10 rtol + 1e-13, for ``one_minus_eps`` too (from the dissipated
      energy; by subtraction where it is 1/4 or more), as ``error_bound`` and ``one_minus_eps_bound``
      state them (the first widened near the overlap rule's sticking boundary).
    * ``"fast"``: the compiled integrator (:mod:`restitution.fast.integrator`), tens of
      microseconds; Omega in [1e-100, 1e14] (alpha <= gamma, and the overlap rule: from 1e-5, where
      the return is not stiff); no ``one_minus_eps``.
    * ``"highprec"``: mpmath Taylor series at ``digits`` digits (:mod:`restitution.core.highprec`),
      rounded to doubles; ``rtol`` of the result is 10^(1 - digits).
    * ``"closed-form"``: exact, for alpha = 2 gamma + 1 only: the linear spring-dashpot (alpha = 1,
      gamma = 0) and the family that maps onto it at (gamma+1) Omega
      (:func:`restitution.core.exact_family.exact_collision`; tau_b, tau_c by quadrature to about
      1e-14), every Omega > 0; eps within 8 u (1 + ln(1/eps)) as ``error_bound`` states.

    ``end``: the end-of-contact rule, "force" (default) or "overlap" (see
    :data:`restitution.core.results.END_RULES`); every method serves both.
    """
    if method not in METHODS:
        raise ParameterError("method", method, f"must be one of {', '.join(METHODS)}")
    if t_eval is not None and method != "reference":
        raise ParameterError("t_eval", "...", 'trajectories come from method "reference" only')
    ex = as_exponents(alpha, gamma)
    end = end_rule(end)
    if method == "reference":
        return _collision.collide(ex, omega, rtol=rtol, t_eval=t_eval, end=end)
    if method == "closed-form":
        from .core.exact_family import exact_collision, in_family
        if not in_family(ex):
            raise ParameterError("method", method, "the closed form is for alpha = 2 gamma + 1 only (alpha = 1, "
                                                   "gamma = 0, the linear dashpot, and the family that maps onto it)")
        return exact_collision(ex, omega, end=end)
    if method == "highprec":
        from .core.highprec import reference_collision
        r = reference_collision(ex, omega, digits=digits, end=end)
        return Collision(ex.alpha, ex.gamma, float(r.omega), "forward", float(r.eps), float(r.tau_b),
                         float(r.x_b), float(r.tau_c), float(r.x_c), r.end, 10.0 ** (1 - r.digits),
                         one_minus_eps=float(1 - r.eps), rule=end)
    return _fast_collision(ex, omega, rtol, end)


def _fast_collision(ex, omega, rtol, end: str = "force") -> Collision:
    from .fast.integrator import COLUMNS, END_FORCE, END_SEPARATION, END_STUCK, collide_fast
    from .core.model import at_most_one
    from .fast.master import TIMES_OMEGA_MIN, stiff_omega_min

    lo = max(stiff_omega_min(ex, end), TIMES_OMEGA_MIN)
    omega = number_in("omega", omega, lo, 1e14, why="the compiled integrator's range (method reference "
                      "or epsilon() cover the rest)")
    rtol = number_in("rtol", rtol, _collision.RTOL_MIN, 1e-6)
    overlap = end == "overlap" and ex.alpha > ex.gamma
    row = dict(zip(COLUMNS, collide_fast(ex.p, ex.q_alpha, ex.q_gamma, [omega], rtol, overlap)[0]))
    if int(row["end"]) == END_STUCK:
        raise _collision.StickError("omega", omega, "under the overlap rule contact never ends here: the "
                                    "attractive phase stops the return and the bodies stay together "
                                    "(eps = 0); use end=force")
    ends = {END_FORCE: "force", END_SEPARATION: "separation"}
    if int(row["end"]) not in ends:
        raise ArithmeticError(f"the compiled integrator failed at Omega = {omega:g}")
    return Collision(ex.alpha, ex.gamma, omega, "forward", float(at_most_one(row["eps"])), float(row["tau_b"]),
                     float(row["x_b"]), float(row["tau_c"]), float(row["x_c"]), ends[int(row["end"])], rtol,
                     rule=end)


# The public spellings keep the exponents as two numbers; the core takes one problem value.
def inverse_collide(alpha, gamma, omega_tilde, x_start: float = 0.0, *, rtol: float = 1e-12, t_eval=None):
    """The paper's inverse collision (:func:`restitution.core.collision.inverse_collide`) for the
    exponents ``alpha``, ``gamma``."""
    return _collision.inverse_collide((alpha, gamma), omega_tilde, x_start, rtol=rtol, t_eval=t_eval)


def collide_many(alpha, gamma, omegas, *, rtol: float = 1e-12) -> dict:
    """:func:`restitution.core.collision.collide_many` for the exponents ``alpha``, ``gamma``."""
    return _collision.collide_many((alpha, gamma), omegas, rtol=rtol)

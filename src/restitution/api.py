"""The public calls, on top of the four layers: ``epsilon`` with every rung of the ladder (the fast
layer's, and the paper's relations from the audit layer), and ``collide``: one collision by any of
the integrators, as one result type.

``Ladder`` and ``RUNG_NAMES`` here are the full ladder; :mod:`restitution.fast.ladder` alone knows
only the rungs that do not need the paper.
"""

from __future__ import annotations

from .audit.relations import PAPER_C, PERTURBATION
from .core import collision as _collision
from .core.errors import ParameterError
from .core.problem import Problem
from .core.exponents import as_exponents
from .core.results import Collision, InverseCollision, end_rule
from .fast import ladder as _ladder
from .fast.collide import METHODS, collide as _fast_collide
from .fast.calibration import FITTED_C
from .fast.ladder import EpsResult

__all__ = ["epsilon", "EpsResult", "Ladder", "RUNG_NAMES", "RELATIONS", "collide", "Collision", "METHODS",
           "inverse_collide", "collide_many", "Problem"]

#: The relation rungs of the full ladder, in the order the chooser lists them.
RELATIONS = (PAPER_C, FITTED_C, *PERTURBATION)
RUNG_NAMES = _ladder.rung_names(RELATIONS)


class Ladder(_ladder.Ladder):
    """:class:`restitution.fast.ladder.Ladder` with the paper's relation rungs."""

    def __init__(self, problem, **kwargs):
        kwargs.setdefault("relations", RELATIONS)
        super().__init__(problem, **kwargs)


def epsilon(*, alpha=None, gamma=None, omega=None, g=None, D1=None, D2=None, tol: float | None = 1e-9,
            method: str | None = None, build: bool | None = None, end: str | None = None,
            problem=None) -> EpsResult:
    """Coefficient of restitution to a relative tolerance ``tol`` by the cheapest adequate rung of
    the full ladder (see :func:`restitution.fast.ladder.epsilon` for the arguments and result).

    ``end="overlap"`` (contact lasts until the overlap returns to 0, as in LAMMPS without
    limit_damping) is served only by the rungs that declare that rule (``Rung.ends``,
    :mod:`restitution.fast.rung`): the compiled integrator, that rule's own master curve, the exact
    family alpha = 2 gamma + 1 (the linear dashpot at (gamma+1) Omega, taken first for those pairs),
    the reference and the mpmath integrators; for alpha <= gamma both rules give the same eps and
    every rung serves. ``problem=`` (a :class:`~restitution.core.problem.Problem`) gives the
    exponents and the rule in one value instead of ``alpha``, ``gamma`` and ``end``.

    Parameters
    ----------
    alpha, gamma : str, int, Fraction or float
        The exponents (:meth:`restitution.Exponents.parse`).
    omega : float or array_like, optional
        Omega, one or many (> 0). Give either ``omega`` or all of ``g``, ``D1`` and ``D2``.
    g, D1, D2 : float or array_like, optional
        Impact speed(s) and the material constants, from which Omega is computed
        (:meth:`restitution.Material.omega`).
    tol : float or None, optional
        Relative tolerance on eps, at least 2.3e-16 (rounding of a double). ``None`` with a forced
        ``method`` takes that method's bound as it comes.
    method : str, optional
        Force one rung by name (see the table of rungs); by default the cheapest that meets ``tol``.
        ``"uniform"`` is the fitted uniform approximation (exact where a closed form exists:
        alpha = gamma, the linear dashpot); its former name ``"closed-form"`` still works, with a
        note on stderr.
    build : bool, optional
        ``False``: use only what needs no build (no master curve or fit is made or read from a
        build this call would start).
    end : {"force", "overlap"}, optional
        The end-of-contact rule (default "force").
    problem : Problem, optional
        The exponents and the end rule in one value (then ``alpha``, ``gamma`` and ``end`` are
        not needed; an ``end`` given too must agree).

    Returns
    -------
    EpsResult
        ``eps`` (an array shaped as the input), ``method``, ``error_bound`` (relative, over all
        inputs), ``setting`` and ``candidates`` (the chooser's table).

    Raises
    ------
    ParameterError
        For an argument out of range, a tolerance no rung meets (naming the best bound available),
        or, under the overlap rule, an Omega at which the bodies stick (StickError).

    See Also
    --------
    collide : One whole collision (times, deformations, how contact ended) by a named method.
    Material.omega : Omega from the material constants and the impact speed.
    restitution.dem.calibrate : The damping D2 that gives a target eps.

    Examples
    --------
    >>> from restitution import epsilon
    >>> r = epsilon(alpha=1, gamma=0, omega=[0.5, 2.0], tol=1e-12)   # the linear dashpot: exact
    >>> r.method, r.error_bound < 1e-12
    ('exact-family', True)
    >>> r.eps.round(8)
    array([0.20787958, 0.40082012])
    """
    return _ladder.epsilon(_problem(alpha, gamma, end, problem), omega=omega, g=g, D1=D1, D2=D2, tol=tol,
                           method=method, build=build, relations=RELATIONS)


def collide(alpha=None, gamma=None, omega=None, *, method: str = "reference", rtol: float = 1e-12, t_eval=None,
            digits: int = 30, end: str | None = None, problem=None) -> Collision:
    """One forward collision x'' + Omega x^alpha + x^gamma x' = 0, x(0) = 0, x'(0) = 1, to the end of
    contact; every method returns a :class:`~restitution.core.results.Collision`.

    The exponents as ``alpha``, ``gamma``, or the whole problem as ``problem=`` (a
    :class:`~restitution.core.problem.Problem`, its end rule included). ``method``: one of
    :data:`METHODS`, the names :func:`epsilon` gives the same rungs (:mod:`restitution.fast.collide`):

    * ``"reference"`` (default): scipy's DOP853/Radau in smooth variables
      (:func:`restitution.core.collision.collide`), Omega in [1e-12, 1e10], ``t_eval`` samples the
      trajectory; relative accuracy 10 rtol + 1e-13, for ``one_minus_eps`` too (from the dissipated
      energy; by subtraction where it is 1/4 or more), as ``error_bound`` and ``one_minus_eps_bound``
      state them (the first widened near the overlap rule's sticking boundary).
    * ``"integrator"``: the compiled integrator (:mod:`restitution.fast.integrator`), far cheaper
      than the reference; Omega in [1e-100, 1e14] (alpha <= gamma, and the overlap rule: from 1e-5,
      where the return is not stiff); no ``one_minus_eps``. Its old name here, ``"fast"``, still
      works and says so on stderr.
    * ``"highprec"``: mpmath Taylor series at ``digits`` digits (:mod:`restitution.core.highprec`),
      rounded to doubles; ``rtol`` of the result is 10^(1 - digits).
    * ``"exact-family"`` and its alias ``"closed-form"``: exact, for alpha = 2 gamma + 1 only: the linear
      spring-dashpot (alpha = 1, gamma = 0) and the family that maps onto it at (gamma+1) Omega
      (:func:`restitution.core.exact_family.exact_collision`; tau_b, tau_c by quadrature to about
      1e-14), every Omega > 0; eps within 8 u (1 + ln(1/eps)) as ``error_bound`` states. (For
      :func:`epsilon`, ``"closed-form"`` is the old name of ``"uniform"``, the fitted approximation.)

    ``end``: the end-of-contact rule, "force" (default) or "overlap" (see
    :data:`restitution.core.results.END_RULES`); every method serves both. With ``problem=`` the
    problem's own rule applies (an ``end`` given too must agree).

    Parameters
    ----------
    alpha, gamma : str, int, Fraction or float
        The exponents (:meth:`restitution.Exponents.parse`).
    omega : float
        Omega > 0 (its range depends on ``method``, above).
    method : {"reference", "integrator", "highprec", "exact-family", "closed-form"}, optional
        The method, by the names :func:`epsilon` gives its rungs ("fast", the compiled
        integrator's former name, still runs, with a note on stderr).
    rtol : float, optional
        Relative tolerance of the integration (``reference``, ``integrator``).
    t_eval : array_like, optional
        Times at which to sample the trajectory (``reference`` only).
    digits : int, optional
        Working digits of ``highprec``.
    end : {"force", "overlap"}, optional
        The end-of-contact rule (default "force").
    problem : Problem, optional
        The exponents and the end rule in one value, instead of ``alpha``, ``gamma`` and ``end``.

    Returns
    -------
    Collision
        ``eps``, ``tau_b``, ``x_b`` (maximum compression), ``tau_c``, ``x_c`` (end of contact),
        ``ended_by`` ("force" or "separation": how contact ended), ``end`` (the rule asked),
        ``error_bound``, ``one_minus_eps``.

    Raises
    ------
    ParameterError
        For an unknown method, an argument out of the method's range, or a closed form asked
        outside alpha = 2 gamma + 1; StickError (a ParameterError) when under the overlap rule the
        bodies never separate.

    See Also
    --------
    epsilon : eps alone, for many Omega, by the cheapest method that meets a tolerance.
    inverse_collide : The inverse collision, time run backwards from the end of contact.
    restitution.core.results.Collision : What it returns.

    Examples
    --------
    >>> from restitution import collide
    >>> c = collide("3/2", 1, 0.47)
    >>> round(c.eps, 8), round(c.tau_b, 6), c.ended_by
    (0.33067437, 1.784529, 'force')
    >>> round(collide("3/2", 1, 0.47, method="integrator").eps, 8)
    0.33067437
    """
    problem = _problem(alpha, gamma, end, problem)
    return _fast_collide(problem, omega, method=method, rtol=rtol, t_eval=t_eval, digits=digits)


def _problem(alpha, gamma, end, problem) -> Problem:
    """The problem of a public call, made once here: ``alpha`` and ``gamma`` with ``end``, or
    ``problem=`` (a Problem, an Exponents or a pair; an ``end`` given too must agree with a
    Problem's own rule, so that a rule never travels two ways at once and silently disagrees)."""
    if problem is None:
        return Problem(as_exponents(alpha, gamma), "force" if end is None else end)
    if alpha is not None or gamma is not None:
        raise ParameterError("problem", problem, "give either alpha and gamma or problem, not both")
    if isinstance(problem, Problem):
        if end is not None and end_rule(end) != problem.end:
            raise ParameterError("end", end, f"disagrees with the problem's own rule, {problem.end!r}")
        return problem
    return Problem(as_exponents(problem), "force" if end is None else end)


# The public spellings keep the exponents as two numbers; the core takes one problem value.
def inverse_collide(alpha, gamma, omega_tilde, x_start: float = 0.0, *, rtol: float = 1e-12,
                    t_eval=None) -> InverseCollision:
    """Inverse collision x~'' + Omega~ x~^alpha - x~^gamma x~' = 0, x~(0) = x_start, x~'(0) = 1.

    Integrated until x~ returns to 0. Once x~' < 0 both force terms accelerate the return, so it
    always comes back after turning around; but the negative damping can outgrow the elastic
    force before the turn (e.g. alpha = 1, gamma = 0, Omega~ < 1/4 from x_start = 0), and then
    RunawayError (a ParameterError) is raised.

    Parameters
    ----------
    alpha, gamma : str, int, Fraction or float
        The exponents (:meth:`Exponents.parse`).
    omega_tilde : float
        The inverse collision's parameter Omega~ > 0.
    x_start : float, optional
        The starting deformation x~(0) >= 0.
    rtol : float, optional
        Relative tolerance of the scipy integration.
    t_eval : array_like, optional
        Times at which to sample the trajectory (``.trajectory``).

    Returns
    -------
    InverseCollision
        ``tau_b``, ``x_b`` (the turning point), ``tau_end`` and ``v_end`` (time and speed when x~
        is back to 0), with the inputs.

    Raises
    ------
    ParameterError
        For an argument out of range; RunawayError (a ParameterError) when the motion never turns.

    See Also
    --------
    collide : The forward collision.
    restitution.core.results.InverseCollision : What it returns.

    Examples
    --------
    >>> from restitution import inverse_collide
    >>> r = inverse_collide("3/2", 1, 3.0)
    >>> round(r.tau_b, 6), round(r.v_end, 6)
    (1.128686, -1.491971)
    """
    return _collision.inverse_collide(_problem(alpha, gamma, None, None), omega_tilde, x_start, rtol=rtol,
                                      t_eval=t_eval)


def collide_many(alpha, gamma, omegas, *, rtol: float = 1e-12) -> dict:
    """:func:`restitution.core.collision.collide_many` for the exponents ``alpha``, ``gamma``."""
    return _collision.collide_many(_problem(alpha, gamma, None, None), omegas, rtol=rtol)

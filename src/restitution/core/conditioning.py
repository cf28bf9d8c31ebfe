"""How accurate a double-precision integration of a collision is: collide's stated bound, and
the factor by which it grows near the overlap rule's sticking boundary."""

from __future__ import annotations

import numpy as np

from .exponents import as_exponents
from .problem import as_problem

__all__ = ["ACCURACY_FACTOR", "ACCURACY_FLOOR", "OVERLAP_ACCURACY_FACTOR", "OVERLAP_ACCURACY_FLOOR",
           "EXPONENT_SCALE", "STICK_CONDITION", "SELF_SIMILAR_CONDITION", "SELF_SIMILAR_POWER", "ELASTIC_START",
           "exponent_factor", "plain_factor_floor", "plain_accuracy", "conditioning", "conditioning_cause"]

#: collide's stated accuracy, relative, in eps and in 1 - eps: ACCURACY_FACTOR * rtol + ACCURACY_FLOOR,
#: times conditioning(...) under the overlap rule near a sticking boundary.
ACCURACY_FACTOR, ACCURACY_FLOOR = 10.0, 1e-13
#: Under the overlap rule (alpha > gamma) both double-precision integrators need more before any
#: conditioning: for large alpha in the elastic regime their error against the mpmath reference (24
#: digits, the same at 40) is 10-15 rtol down to rtol 1e-13 and about 1e-12 below, whatever rtol
#: ((17/3, 4/3) at Omega = 1.9e6: the compiled one 12.7 rtol at 1e-12, 15 rtol at 1e-13, 2.7e-13 at
#: 1e-14; collide 12.6 rtol at 1e-13 and 3.4e-13 at 1e-14, where 10 rtol + 1e-13 times the
#: elastic factor below stated 2.5e-13; 3,700 random cases, alpha up to 6, Omega 1e-3..1e8: up to
#: 1.4e-12 at rtol 1e-13). Twice what was seen.
OVERLAP_ACCURACY_FACTOR, OVERLAP_ACCURACY_FLOOR = 20.0, 3e-12
#: Under the force rule both double-precision integrators lose accuracy as the exponents grow. Against
#: the mpmath reference (22 digits), 500 random pairs (alpha, gamma up to 8, denominators up to 12,
#: Omega 1e-12..1e10), the compiled integrator's error at rtol 1e-14 was at most 2e-15 for alpha +
#: gamma < 2, 4.3e-14 for 4..6, 1.6e-13 for 6..8, 3e-13 for 10..12 and 1.1e-12 for 14..16 (7.3 times
#: 10 rtol + 5e-14 at (38/5, 7), Omega = 2.1e3); 2.7e-12 at rtol 1e-13 (32/5, 27/5) and 1.4e-11 at
#: 1e-12 (41/6, 13/2); the scipy reference's 3.6e-13 at 1e-14 (32/5, 5). It grows about as the cube
#: of alpha + gamma: both plain bounds are multiplied by ((alpha + gamma) / EXPONENT_SCALE)^3 where
#: that exceeds 1, which covers every case by 3 or more (every pair measured before, and every pair
#: the paper uses, has alpha + gamma <= 4). The overlap rule's wider bound above holds there without
#: it (160 pairs with alpha > 4: at most 0.55 of it).
EXPONENT_SCALE = 4.0
#: Near a sticking boundary (overlap rule, alpha > 2 gamma + 1) the bodies leave with a speed eps
#: that is a small remainder of O(1) speeds, so the integration's O(rtol) error in those speeds
#: becomes a relative error ~ rtol / eps in eps. Measured against the mpmath reference for ten
#: pairs ((5/2,1/2), (3,1/2), (9/2,1/2), (3,0), (4,1), (6,1), (8,2), (67/9,0), (13/2,1/4),
#: (7,1/3)) at Omega = (1 + d) Omega_stick, d = 10..0.003, rtol 1e-9..3e-14, both double-precision
#: integrators: error / (10 rtol + 1e-13) <= 0.021 / eps wherever it exceeds 1 (0.007 / eps for
#: denominators up to 2; the fuzz found the larger ones with alpha = 67/9); stated with a factor
#: of three to spare.
STICK_CONDITION = 0.06
#: At alpha = 2 gamma + 1 eps falls faster than any power towards 1/(4 (gamma+1)) and the error
#: grows with the logarithm instead: measured <= 64 at ln(1/eps) = 58, 9 at 31, 2.4 at 18 for
#: (1, 0) and (2, 1/2). Larger denominators grow faster (the fuzz found (12/5, 7/10) off by 2.5
#: times (ln(1/eps) / 10)^3): against mpmath, seven pairs ((1, 0), (2, 1/2), (5/2, 3/4), (11/5, 3/5),
#: (12/5, 7/10), (8/3, 5/6), (17/5, 6/5)) at Omega = (1 + d) / (4 (gamma + 1)), d = 0.003..0.3, rtol
#: 1e-6..1e-12, both double-precision integrators: error / plain bound <= 4,448 at ln(1/eps) = 57,
#: 742 at 39, 121 at 27, 14 at 18, 0.5 at 12 ((11/5, 3/5) and (8/3, 5/6) the largest).
#: (ln(1/eps) / SELF_SIMILAR_CONDITION)^SELF_SIMILAR_POWER covers every one by 3.9 or more, and
#: (11/5, 3/5) and (8/3, 5/6) further in by 3.7 or more (d = 1e-3, 3e-4, 1e-4: ln(1/eps) = 99, 181, 314).
SELF_SIMILAR_CONDITION, SELF_SIMILAR_POWER = 5.0, 4
#: Under the overlap rule near the elastic limit (alpha > gamma, large Omega) both double-precision
#: integrators lose relative accuracy with Omega for large alpha: measured against mpmath, error /
#: (10 rtol + floor) up to 2.0 at Omega = 1e8, 3.3 at 1e10 (collide, alpha = 8, gamma = 1), 7.7 at
#: 1.9e10 and 7.5 at 1e12 (the compiled integrator), 0.46 at 1e6; (5, 0), (6, 1/2), (3, 1/3) and
#: (3/2, 1/2) stay lower. (Omega / ELASTIC_START)^(1/3) covers every one by 2.3 or more.
ELASTIC_START = 1e6
#: Below this eps counts as this (the factor stays finite for an eps that underflowed).
TINY = 1e-300


def exponent_factor(problem) -> float:
    """The factor on the force rule's plain bounds for large exponents (EXPONENT_SCALE)."""
    ex = as_exponents(problem)
    return max(1.0, float(ex.alpha + ex.gamma) / EXPONENT_SCALE) ** 3


def plain_factor_floor(problem, factor: float = ACCURACY_FACTOR,
                       floor: float = ACCURACY_FLOOR) -> tuple[float, float]:
    """(factor, floor) of a double-precision integration's plain bound factor rtol + floor: the
    given force-rule ones (collide's by default) times exponent_factor; where the rules differ
    (alpha > gamma) under the overlap rule at least its own as well. The overlap rule shares the
    force rule's legs up to the force's zero, and with them their growth with the exponents: make
    fuzz found 1 - eps of (15/2, 29/6) at Omega = 7.6e4 1.12 times over the overlap rule's own
    bound (an error equal to the force rule's, which states 11 times more). ``problem``: a Problem
    (an Exponents or a pair: the force rule)."""
    problem = as_problem(problem)
    ex = problem.ex
    scale = exponent_factor(ex)
    if problem.effective_end == "overlap":
        return max(OVERLAP_ACCURACY_FACTOR, factor * scale), max(OVERLAP_ACCURACY_FLOOR, floor * scale)
    return factor * scale, floor * scale


def plain_accuracy(problem, rtol: float) -> float:
    """collide's stated relative accuracy at ``rtol`` before conditioning.

    Parameters
    ----------
    problem : Problem, Exponents or (alpha, gamma)
        The exponents and end rule (plain exponents: the force rule).
    rtol : float
        The integration's relative tolerance.

    Returns
    -------
    float
        factor x rtol + floor (:func:`plain_factor_floor`).

    Examples
    --------
    >>> from restitution.core.problem import Problem
    >>> plain_accuracy(Problem.of("3/2", 1), 1e-12)     # 10 rtol + 1e-13
    1.01e-11
    >>> plain_accuracy(Problem.of("38/5", 7), 1e-12) > 1.01e-11     # large exponents state more
    True
    """
    factor, floor = plain_factor_floor(problem)
    return factor * rtol + floor


def conditioning(problem, eps, omega) -> np.ndarray:
    """The factor by which a double-precision integration's relative error in eps grows under the
    overlap rule near a sticking boundary (STICK_CONDITION) and near the elastic limit
    (ELASTIC_START); 1 elsewhere. It depends on the answer, so a bound stated with it is known
    after the evaluation (fast.ladder checks it then; collide states it).

    Parameters
    ----------
    problem : Problem, Exponents or (alpha, gamma)
        The exponents and end rule (plain exponents: the force rule, where the factor is 1).
    eps, omega : array_like
        The answers and their Omegas.

    Returns
    -------
    numpy.ndarray
        The factor at each point, >= 1.

    Examples
    --------
    >>> from restitution.core.problem import Problem
    >>> conditioning(Problem.of(1, 0), [1e-20], [0.2512])
    array([1.])
    >>> float(conditioning(Problem.of(1, 0, "overlap"), [1e-20], [0.2512])[0]) > 1.0   # near sticking
    True
    """
    problem = as_problem(problem)
    e = np.maximum(np.asarray(eps, dtype=float), TINY)
    if problem.effective_end != "overlap":
        return np.ones_like(e)
    return _elastic_factor(omega) * _stick_factor(problem.ex, e)


def _elastic_factor(omega) -> np.ndarray:
    return np.maximum(1.0, np.asarray(omega, dtype=float) / ELASTIC_START) ** (1.0 / 3.0)


def _stick_factor(ex, e: np.ndarray) -> np.ndarray:
    if ex.alpha < 2 * ex.gamma + 1:   # the bodies never stick
        return np.ones_like(e)
    if ex.alpha > 2 * ex.gamma + 1:
        return np.maximum(1.0, STICK_CONDITION / e)
    return np.maximum(1.0, (np.log(1.0 / e) / SELF_SIMILAR_CONDITION) ** SELF_SIMILAR_POWER)


def conditioning_cause(problem, eps, omega) -> str:
    """Where :func:`conditioning` widens a bound, why, in words a refusal can give: the sticking
    boundary (with how the error grows in this class of exponents) or the elastic limit, whichever
    contributes more.

    Parameters
    ----------
    problem : Problem or (alpha, gamma)
        The exponents and end rule.
    eps, omega : array_like
        The answers and their Omegas.

    Returns
    -------
    str
        A clause such as ``"eps = 2.1e-13 lies near the sticking boundary of the overlap rule, where
        the integrators' relative error grows like ln(1/eps)^4"``.

    Examples
    --------
    >>> from restitution.core.problem import Problem
    >>> conditioning_cause(Problem.of(1, 0, "overlap"), [1e-20], [0.2512]).split(", where ")[1]
    "the integrators' relative error grows like ln(1/eps)^4"
    >>> conditioning_cause(Problem.of(3, 0, "overlap"), [1e-6], [2.0]).split(", where ")[1]
    "the integrators' relative error grows like 1/eps"
    >>> conditioning_cause(Problem.of("3/2", "1/2", "overlap"), [0.99], [1e9]).split(", where ")[0]
    "Omega = 1e+09 lies far into the overlap rule's elastic limit"
    """
    ex = as_problem(problem).ex
    e = np.maximum(np.asarray(eps, dtype=float), TINY)
    om = np.asarray(omega, dtype=float)
    if ex.alpha < 2 * ex.gamma + 1 or np.max(_stick_factor(ex, e)) < np.max(_elastic_factor(om)):
        return (f"Omega = {float(np.max(om)):.3g} lies far into the overlap rule's elastic limit, where the "
                f"integrators' relative error grows like Omega^(1/3)")
    growth = "1/eps" if ex.alpha > 2 * ex.gamma + 1 else f"ln(1/eps)^{SELF_SIMILAR_POWER}"
    return (f"eps = {float(np.min(e)):.3g} lies near the sticking boundary of the overlap rule, where the "
            f"integrators' relative error grows like {growth}")

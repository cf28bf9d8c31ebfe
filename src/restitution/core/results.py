"""What a collision returns: end-of-contact quantities and, on request, sampled trajectories.

The scipy reference (:mod:`restitution.core.collision`), the mpmath one
(:mod:`restitution.core.highprec`) and the closed forms (:mod:`restitution.core.dashpot`) all return
:class:`Collision`; the paper's inverse collision returns :class:`InverseCollision`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from .errors import one_of
from .exponents import read_through

if TYPE_CHECKING:   # problem.py reads end_rule from here
    from .problem import Problem

__all__ = ["Trajectory", "Collision", "InverseCollision", "END_RULES", "end_rule"]

#: The end-of-contact rules a forward collision can be computed with. "force": contact ends where
#: the total force Omega x^alpha + x^gamma x' first vanishes (or at x = 0 if that comes first), the
#: contact law never pulls (LAMMPS' limit_damping, LIGGGHTS' limitForce). "overlap": contact ends
#: only when x returns to 0, the force turning attractive on the way (LAMMPS' and LIGGGHTS' default).
END_RULES = ("force", "overlap")


def end_rule(value) -> str:
    """The end-of-contact rule ``value``, or ParameterError naming the allowed ones.

    Parameters
    ----------
    value : str
        A rule asked for.

    Returns
    -------
    str
        ``value``, one of :data:`END_RULES`.

    Raises
    ------
    ParameterError
        For anything else, naming the field ``end`` and the allowed rules.

    Examples
    --------
    >>> end_rule("overlap")
    'overlap'
    >>> end_rule("both")
    Traceback (most recent call last):
    ...
    restitution.core.errors.ParameterError: end = 'both': must be one of force, overlap
    """
    return one_of("end", value, END_RULES)


@dataclass(frozen=True)
class Trajectory:
    """Samples of the solution at requested tau (samples beyond the end of contact are dropped).

    Parameters
    ----------
    tau : numpy.ndarray
        The scaled times asked for, up to the end of contact.
    x, v : numpy.ndarray
        The deformation and its rate there.

    Examples
    --------
    >>> from restitution.core.collision import collide
    >>> t = collide(("3/2", 1), 0.5, t_eval=[0.5, 1.0, 100.0]).trajectory
    >>> t.tau, t.x.round(6)                          # tau = 100 lies after the end of contact
    (array([0.5, 1. ]), array([0.475448, 0.817126]))
    """

    tau: np.ndarray
    x: np.ndarray
    v: np.ndarray


@dataclass(frozen=True)
class Collision:
    """End-of-contact quantities of one forward collision in scaled variables.

    ``ended_by`` is how contact ended: "force" where the total force vanished
    (Omega x^(alpha-gamma) + x' = 0), "separation" where x returned to 0. ``end`` is the
    end-of-contact rule asked for (END_RULES): under "overlap" ``ended_by`` is always "separation".
    ``problem`` is what was solved (its exponents and ``end``). ``rtol`` is the
    tolerance the integration ran at (0.0 for a closed form). ``one_minus_eps`` is 1 - eps to
    relative accuracy (from the dissipated energy, not by subtraction), None where the method does
    not provide it. ``error_bound`` and ``one_minus_eps_bound`` are the stated relative accuracies
    of eps and 1 - eps (None where the method states none).

    Parameters
    ----------
    problem : Problem
        The exponents and the end-of-contact rule asked (``alpha``, ``gamma`` and ``end`` read
        through it).
    omega : float
        Omega.
    direction : str
        "forward".
    eps : float
        The coefficient of restitution, -x'(tau_c).
    tau_b, x_b : float
        Time and deformation at maximum compression.
    tau_c, x_c : float
        Time and deformation at the end of contact.
    ended_by : {"force", "separation"}
        How contact ended.
    rtol : float
        The integration's relative tolerance (0.0 for a closed form).
    trajectory : Trajectory, optional
        Samples at the times asked for.
    one_minus_eps : float, optional
        1 - eps to relative accuracy.
    error_bound, one_minus_eps_bound : float, optional
        The stated relative accuracies of ``eps`` and ``one_minus_eps``.

    Examples
    --------
    >>> from restitution.core.collision import collide
    >>> from restitution.core.problem import Problem
    >>> c = collide(Problem.of("3/2", 1, "overlap"), 0.5)
    >>> c.end, c.ended_by, c.x_c, c.alpha
    ('overlap', 'separation', 0.0, Fraction(3, 2))
    >>> sorted(c.as_dict())[:4]
    ['alpha', 'end', 'ended_by', 'eps']
    """

    problem: Problem
    omega: float
    direction: str
    eps: float
    tau_b: float
    x_b: float
    tau_c: float
    x_c: float
    ended_by: str
    rtol: float
    trajectory: Trajectory | None = None
    one_minus_eps: float | None = None
    error_bound: float | None = None
    one_minus_eps_bound: float | None = None

    alpha = read_through("problem", "alpha")
    gamma = read_through("problem", "gamma")
    end = read_through("problem", "end", "The end-of-contact rule asked for.")

    def as_dict(self) -> dict:
        out = {**_json_numbers(self, ("omega", "eps", "tau_b", "x_b", "tau_c", "x_c")), "end": self.end,
               "ended_by": self.ended_by}
        if self.one_minus_eps is not None:
            out["one_minus_eps"] = float(self.one_minus_eps)
        if self.error_bound is not None:
            out["error_bound"] = float(self.error_bound)
        if self.one_minus_eps_bound is not None:
            out["one_minus_eps_bound"] = float(self.one_minus_eps_bound)
        return out


def _json_numbers(result, names) -> dict:
    """JSON-ready fields: exponents as exact rational strings, then the named numbers as floats."""
    return {"alpha": str(result.alpha), "gamma": str(result.gamma),
            **{name: float(getattr(result, name)) for name in names}}


@dataclass(frozen=True)
class InverseCollision:
    """x~'' + Omega~ x~^alpha - x~^gamma x~' = 0 from x~(0) = x_start, x~'(0) = 1 back to x~ = 0
    (``problem``: the exponents; no end rule applies).

    Parameters
    ----------
    problem : Problem
        The exponents (``alpha`` and ``gamma`` read through it).
    omega : float
        Omega~.
    x_start : float
        x~(0).
    tau_b, x_b : float
        The turning point.
    tau_end, v_end : float
        Time and speed when x~ is back to 0.
    rtol : float
        The integration's relative tolerance.
    trajectory : Trajectory, optional
        Samples at the times asked for.

    Examples
    --------
    >>> from restitution.core.collision import inverse_collide
    >>> r = inverse_collide(("3/2", 1), 3.0)
    >>> r.alpha, round(r.tau_b, 6), round(r.v_end, 6)
    (Fraction(3, 2), 1.128686, -1.491971)
    """

    problem: Problem
    omega: float
    x_start: float
    tau_b: float
    x_b: float
    tau_end: float
    v_end: float
    rtol: float
    trajectory: Trajectory | None = None

    alpha = read_through("problem", "alpha")
    gamma = read_through("problem", "gamma")

    def as_dict(self) -> dict:
        return _json_numbers(self, ("omega", "x_start", "tau_b", "x_b", "tau_end", "v_end"))

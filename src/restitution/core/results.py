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
    """The end-of-contact rule ``value``, or ParameterError naming the allowed ones."""
    return one_of("end", value, END_RULES)


@dataclass(frozen=True)
class Trajectory:
    """Samples of the solution at requested tau (samples beyond the end of contact are dropped)."""

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
    (``problem``: the exponents; no end rule applies)."""

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

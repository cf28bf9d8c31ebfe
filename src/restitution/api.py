"""The public calls, on top of the three layers: ``epsilon`` with every rung of the ladder (the fast
layer's, and the paper's relations from the audit layer), and ``collide``.

``Ladder`` and ``RUNG_NAMES`` here are the full ladder; :mod:`restitution.fast.ladder` alone knows
only the rungs that do not need the paper.
"""

from __future__ import annotations

from .audit.relations import PAPER_C, PERTURBATION
from .core.collision import collide, collide_many, inverse_collide
from .fast import ladder as _ladder
from .fast.calibration import FITTED_C
from .fast.ladder import EpsResult

__all__ = ["epsilon", "EpsResult", "Ladder", "RUNG_NAMES", "RELATIONS", "collide", "inverse_collide",
           "collide_many"]

#: The relation rungs of the full ladder, in the order the chooser lists them.
RELATIONS = (PAPER_C, FITTED_C, *PERTURBATION)
RUNG_NAMES = _ladder.rung_names(RELATIONS)


class Ladder(_ladder.Ladder):
    """:class:`restitution.fast.ladder.Ladder` with the paper's relation rungs."""

    def __init__(self, alpha, gamma, **kwargs):
        kwargs.setdefault("relations", RELATIONS)
        super().__init__(alpha, gamma, **kwargs)


def epsilon(*, alpha, gamma, omega=None, g=None, D1=None, D2=None, tol: float = 1e-9,
            method: str | None = None, build: bool | None = None) -> EpsResult:
    """Coefficient of restitution to a relative tolerance ``tol`` by the cheapest adequate rung of
    the full ladder (see :func:`restitution.fast.ladder.epsilon` for the arguments and result)."""
    return _ladder.epsilon(alpha=alpha, gamma=gamma, omega=omega, g=g, D1=D1, D2=D2, tol=tol,
                           method=method, build=build, relations=RELATIONS)

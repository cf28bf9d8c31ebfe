"""The paper's relations as rungs of the fast ladder: its printed c0-c2 ("paper-c") and its
matching procedure carried to order Omega^n on the converged exact series ("perturbation-N<n>").
:mod:`restitution.api` hands them to :class:`restitution.fast.ladder.Ladder`, whose error profiles
then say how good each is as an eps evaluator.
"""

from __future__ import annotations

import math
from fractions import Fraction

from ..fast.calibration import Relation, RelationUnavailable
from . import printed

__all__ = ["PAPER_C", "PERTURBATION", "PERTURBATION_ORDERS", "PERTURBATION_READING"]

#: Orders of the perturbation route: the paper's procedure on the converged exact series, with
#: Delta, Delta~ from x' expanded to first order in Delta and solved exactly (readings.Reading
#: delta="linear"). That reading is fixed in advance because it is defined at every order; the
#: printed lowest-order Delta formulas give no root c0 at odd orders for the paper's exponents.
PERTURBATION_ORDERS = (1, 2, 3, 4)
PERTURBATION_READING = {"truncation": "converged", "delta": "linear"}


def _printed_c(ex, progress) -> tuple:
    if not (ex.alpha == Fraction(3, 2) and ex.gamma == 1):
        raise RelationUnavailable("the printed c0-c2 belong to alpha = 3/2, gamma = 1")
    return printed.PRINTED_C, "printed in the paper"


def _perturbation_c(order: int):
    def coefficients(ex, progress) -> tuple:
        from .matching import paper_procedure
        from .readings import Reading
        try:
            progress(f"perturbation route, order {order}")
            cc = paper_procedure(ex, Reading(omega_orders=order, **PERTURBATION_READING))
        except Exception as exc:  # noqa: BLE001 - a rung that cannot be built is reported, not fatal
            raise RelationUnavailable(f"paper's procedure failed: {type(exc).__name__}: {exc}") from exc
        if not (cc.defined and all(math.isfinite(x) for x in cc.c)):
            raise RelationUnavailable(f"paper's procedure undefined: {cc.reason}")
        return cc.c, f"paper's procedure, reading {cc.reading.label}"
    return coefficients


#: Seconds to derive one order's c0-c2 on the 2-core machine: 11 s for the first order asked (the
#: exact series is derived then), 1-2 s for each further one (3/2, 1/2).
PERTURBATION_SECONDS = 10.0
PAPER_C = Relation("paper-c", _printed_c, build_seconds=0.0)
PERTURBATION = tuple(Relation(f"perturbation-N{n}", _perturbation_c(n), PERTURBATION_SECONDS)
                     for n in PERTURBATION_ORDERS)

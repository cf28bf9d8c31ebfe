"""The registry of the method ladder's rungs (each a :class:`restitution.fast.rung.Rung`).

Adding a rung is one module in this package and one line in RUNGS. The chooser
(:mod:`restitution.fast.ladder`) lists them in this order, the relation rungs first, and takes an
exact rung (``Rung.exact``) first wherever it serves.
"""

from __future__ import annotations

from ..rung import Rung
from .calibrated import ElasticRung, MasterRung, PadeRung, RelationRung, ViscousRung
from .exact_family import ExactFamily
from .highprec import Highprec
from .integrator import Integrator
from .overlap_integrator import OverlapIntegrator
from .overlap_law import OverlapLaw
from .overlap_master import OverlapMaster
from .reference import Reference
from .uniform import Uniform

__all__ = ["RUNGS", "ladder_rungs", "rung_names"]

#: Every rung but the relation rungs (which come from the Relations a ladder is given), cheapest kinds first.
RUNGS: tuple[Rung, ...] = (
    ExactFamily(),
    PadeRung(),
    ViscousRung(),
    ElasticRung(),
    Uniform(),
    MasterRung(),
    OverlapMaster(),
    OverlapLaw(),
    Integrator(),
    OverlapIntegrator(),
    Reference(),
    Highprec(),
)


def ladder_rungs(relations=()) -> tuple[Rung, ...]:
    """The relation rungs for ``relations``, then RUNGS."""
    return (*(RelationRung(r) for r in relations), *RUNGS)


def rung_names(relations=()) -> tuple[str, ...]:
    """The method names a ladder with these relation rungs offers (a name served by several rungs,
    one per end rule, once)."""
    return tuple(dict.fromkeys(r.name for r in ladder_rungs(relations)))

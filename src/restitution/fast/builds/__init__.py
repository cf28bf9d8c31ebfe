"""The registry of the method ladder's builds (each a :class:`restitution.fast.build.Build`): what
rungs read that is made once, cached and checked on load.

Adding a build is one module in this package and one line in BUILDS; a rung asks for it by its
``name`` (``Rung.needs``). The chooser (:mod:`restitution.fast.ladder`) looks builds up here by name.
"""

from __future__ import annotations

from ..build import Build
from .master_curve import MasterCurveBuild
from .mpmath_check import MpmathCheck
from .overlap_curve import OverlapCurveBuild
from .relation import RelationBuild
from .uniform_form import UniformFormBuild

__all__ = ["BUILDS", "ladder_builds"]

#: Every build but the relation builds (which come from the Relations a ladder is given).
BUILDS: tuple[Build, ...] = (
    MasterCurveBuild(),
    OverlapCurveBuild(),
    UniformFormBuild("force"),
    UniformFormBuild("overlap"),
    MpmathCheck(),
)


def ladder_builds(relations=()) -> dict[str, Build]:
    """The builds of a ladder with the relation rungs of ``relations``, by name.

    Parameters
    ----------
    relations : iterable of Relation
        The ladder's relations (each brings the build of its c0-c2).

    Returns
    -------
    dict
        Build name -> :class:`restitution.fast.build.Build`.

    Examples
    --------
    >>> from restitution.fast.calibration import FITTED_C
    >>> sorted(ladder_builds((FITTED_C,)))[:2]
    ['fitted-c relation', 'master curve']
    """
    return {b.name: b for b in (*BUILDS, *(RelationBuild(r) for r in relations))}

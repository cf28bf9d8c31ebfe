"""Coefficient of restitution for viscoelastic collisions (a rebuild and audit of S. Kim's paper).

Heavier modules (the integrators) load on first use so that `import restitution` stays cheap
for the command line and for workflow scripts that need only the series.
"""

from .core.errors import ParameterError
from .core.exponents import Exponents
from .core.model import Material
from .core.series import perturbation_series

__all__ = ["ParameterError", "Exponents", "Material", "perturbation_series", "collide", "inverse_collide",
           "epsilon", "EpsResult"]
__version__ = "0.1.0"


def __getattr__(name):
    if name in ("collide", "inverse_collide", "collide_many", "epsilon", "EpsResult"):
        from . import api
        return getattr(api, name)
    raise AttributeError(f"module 'restitution' has no attribute {name!r}")

"""Coefficient of restitution for viscoelastic collisions (a rebuild and audit of S. Kim's paper).

Heavier modules (the integrators) load on first use so that `import restitution` stays cheap
for the command line and for workflow scripts that need only the series.
"""

from .errors import ParameterError
from .exponents import Exponents
from .model import Material
from .series import perturbation_series

__all__ = ["ParameterError", "Exponents", "Material", "perturbation_series", "collide", "inverse_collide",
           "epsilon", "EpsResult"]
__version__ = "0.1.0"


def __getattr__(name):
    if name in ("collide", "inverse_collide", "collide_many"):
        from . import collision
        return getattr(collision, name)
    if name in ("epsilon", "EpsResult"):
        from . import ladder
        return getattr(ladder, name)
    raise AttributeError(f"module 'restitution' has no attribute {name!r}")

"""Coefficient of restitution for viscoelastic collisions: a rebuild and audit of S. Kim's paper.

The contact law x'' + Omega x^alpha + x^gamma x' = 0 (scaled), in four layers; imports point down
only (checked by tests/library/test_layers.py):

====================  ===================================================================
``restitution.core``  the physics: exponents, materials and Omega, the exact perturbation
                      series, closed forms, the scipy and mpmath reference collisions, the
                      small- and large-Omega expansions, the exact Omega~(Omega) connection
``restitution.fast``  eps(Omega) fast and to a stated accuracy: compiled integrator, master
                      curve, the calibrated method ladder, the sealed disk cache (uses core)
``restitution.audit`` the paper: its printed numbers, its matching procedure for c0-c2 as
                      its text can be read, the claims ledger, the stability atlas (uses core)
``restitution.dem``   DEM codes' contact options <-> the model, calibration of the damping,
                      contact time and time step, the real LAMMPS engine (uses core)
``api``, ``cli``      on top: ``epsilon`` with every rung (the paper's c's included) and the
                      ``restitution`` command
====================  ===================================================================

The names below are the everyday entry points. Heavier modules (the integrators) load on first
use, so ``import restitution`` stays cheap for the command line and for scripts that need only
the series.
"""

from .core.errors import ParameterError
from .core.exponents import Exponents
from .core.model import Material
from .core.problem import Problem
from .core.series import perturbation_series

__all__ = ["ParameterError", "Exponents", "Problem", "Material", "perturbation_series", "collide", "inverse_collide",
           "epsilon", "EpsResult"]


def __getattr__(name):
    if name in ("collide", "inverse_collide", "collide_many", "epsilon", "EpsResult"):
        from . import api
        return getattr(api, name)
    if name == "__version__":
        # the installed distribution's, written once in pyproject.toml; read on first use, as
        # importlib.metadata would add to every start-up of the command
        from importlib.metadata import version
        return version("restitution")
    raise AttributeError(f"module 'restitution' has no attribute {name!r}")

"""scipy's Dormand-Prince 8(5,3) tableau (DOP853) for the compiled integrator
(:mod:`restitution.fast.collision_kernels`), taken from scipy so the two cannot drift apart."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np

__all__ = ["N_STAGES", "A", "B", "C", "E3", "E5"]


def _scipy_dop853():
    """scipy's DOP853 coefficients module, executed from its own file: importing it by name imports
    the whole of scipy.integrate first (about 0.3 s, most of a one-point ``restitution eps`` call)
    for a few hundred numbers that need only numpy."""
    spec = importlib.util.find_spec("scipy")   # locates the package without importing it
    path = Path(spec.origin).parent / "integrate" / "_ivp" / "dop853_coefficients.py"
    if not path.is_file():   # another scipy layout: the ordinary import
        from scipy.integrate._ivp import dop853_coefficients
        return dop853_coefficients
    own = importlib.util.spec_from_file_location("restitution_scipy_dop853_coefficients", path)
    module = importlib.util.module_from_spec(own)
    own.loader.exec_module(module)
    return module


_dop = _scipy_dop853()
#: Stages of the method (12); the arrays below as the kernels read them (C-contiguous float64).
N_STAGES = _dop.N_STAGES
A = np.ascontiguousarray(_dop.A[:N_STAGES, :N_STAGES], dtype=np.float64)
B = np.ascontiguousarray(_dop.B, dtype=np.float64)
C = np.ascontiguousarray(_dop.C[:N_STAGES], dtype=np.float64)
E3 = np.ascontiguousarray(_dop.E3, dtype=np.float64)
E5 = np.ascontiguousarray(_dop.E5, dtype=np.float64)

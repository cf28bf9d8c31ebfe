"""eps at dt = 0 from three runs of a DEM engine at dt, dt/2, dt/4.

The engines (LAMMPS, LIGGGHTS, Yade) advance a contact with velocity Verlet or leapfrog, the
damping seen with the half-step velocity: eps(dt) = eps0 + a dt + ... The next term depends on
the damping law. With a damping force c delta^gamma delta' and 0 < gamma < 1, the force at the
start of contact grows like t^gamma, which no fixed step integrates to better than dt^(1+gamma):
measured in Yade (Hertz-Mindlin, gamma = 1/4), the error of a (dt, dt^2) extrapolation shrinks
only like dt^1.3 and stays near 1e-6 at 4000 steps per contact, while removing (dt, dt^(5/4))
leaves a dt^2 residual of 2e-8 at 1000 steps. For gamma = 0 or 1 the next term is dt^2.
A fourth run at dt/8 tests that model: :func:`observed_order` measures the second order, and
:func:`fit_residual` is what a fit of either model leaves of the four runs.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

__all__ = ["orders", "richardson", "observed_order", "fit_residual", "eps_extrapolated"]


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


def observed_order(e1: float, e2: float, e4: float, e8: float) -> float:
    """The order in dt of the error term after the first-order one, measured in four runs.

    The first-order term is removed from each pair of successive runs (r = 2 e(dt/2) - e(dt)); the
    three differences that remain fall by 2^q per halving if the next term is in dt^q.

    Parameters
    ----------
    e1, e2, e4, e8 : float
        eps measured at dt, dt/2, dt/4 and dt/8.

    Returns
    -------
    float
        q, e.g. near 1 + gamma where :func:`orders` removes dt^(1 + gamma), near 2 for a dt^2 term.

    Examples
    --------
    >>> f = lambda dt: 0.6 + 0.1 * dt + 0.05 * dt ** 1.5
    >>> round(observed_order(f(0.1), f(0.05), f(0.025), f(0.0125)), 9)
    1.5
    """
    r1, r2, r3 = 2.0 * e2 - e1, 2.0 * e4 - e2, 2.0 * e8 - e4
    return math.log2((r1 - r2) / (r2 - r3))


def fit_residual(eps, order: float) -> float:
    """The largest residual of the least-squares fit eps(dt) = eps0 + a dt + b dt^order to runs at
    dt, dt/2, dt/4, ...: with four runs or more, how well that model of the error describes them.

    Parameters
    ----------
    eps : sequence of float
        eps measured at dt, dt/2, dt/4, ... (at least four for a residual that can differ from 0).
    order : float
        The order of the second term of the model (the first is dt).

    Returns
    -------
    float
        max |fit - eps| over the runs.

    Examples
    --------
    Runs whose error is in dt and dt^1.5 are fitted exactly by that model, not by one with dt^2:

    >>> e = [0.6 + 0.1 * dt + 0.05 * dt ** 1.5 for dt in (0.1, 0.05, 0.025, 0.0125)]
    >>> fit_residual(e, 1.5) < 1e-15, fit_residual(e, 2.0) > 1e-6
    (True, True)
    """
    eps = np.asarray(eps, dtype=float)
    dt = 0.5 ** np.arange(len(eps))          # in units of the coarsest step: the residual does not depend on it
    basis = np.column_stack([np.ones_like(dt), dt, dt ** order])
    coef, *_ = np.linalg.lstsq(basis, eps, rcond=None)
    return float(np.max(np.abs(basis @ coef - eps)))


def eps_extrapolated(eps_runs, pair, setting, speeds, t_c: dict, gamma, steps: int,
                     t_run: dict | None = None) -> dict:
    """{g: (eps extrapolated to dt = 0, eps at t_c/steps, /2, /4)} for one setting of an engine at
    each speed, all the runs in one call of its runner (one engine process where it batches them).

    Parameters
    ----------
    eps_runs : callable
        The engine's runner, ``eps_runs(pair, [(setting, g, dt, t_run), ...])`` -> eps of each
        (the form of :attr:`restitution.dem.engine.Engine.runner`).
    pair : Pair
        The two spheres.
    setting
        The engine's setting, as ``eps_runs`` takes it.
    speeds : iterable of float
        Approach speeds.
    t_c : dict
        {g: contact time}: the runs' steps are t_c / steps, / 2 steps and / 4 steps.
    gamma : rational or str
        The damping exponent (:func:`richardson`'s orders).
    steps : int
        Steps per contact of the coarsest run.
    t_run : dict, optional
        {g: length of the run}; 1.5 t_c where not given.

    Returns
    -------
    dict
        {g: (eps at dt = 0, the engine's eps at the three steps)}.

    Examples
    --------
    A stand-in runner whose eps(dt) = 0.6 + 10 dt + 1e4 dt^2 is extrapolated to 0.6 at each speed:

    >>> def runs(pair, cases):
    ...     return [0.6 + 10 * dt + 1e4 * dt ** 2 for setting, g, dt, t in cases]
    >>> out = eps_extrapolated(runs, None, "lines", [1.0, 2.0], {1.0: 1e-3, 2.0: 8e-4}, 1, steps=100)
    >>> [round(out[g][0], 12) for g in (1.0, 2.0)]
    [0.6, 0.6]
    """
    speeds = list(speeds)
    length = t_run if t_run is not None else {g: 1.5 * t_c[g] for g in speeds}
    eps = eps_runs(pair, [(setting, g, t_c[g] / steps / k, length[g]) for g in speeds for k in (1, 2, 4)])
    return {g: (richardson(*eps[3 * i: 3 * i + 3], gamma), *eps[3 * i: 3 * i + 3]) for i, g in enumerate(speeds)}

"""A DEM time step for a target accuracy in eps, from a measured convergence study.

DEM codes (LAMMPS' fix nve/sphere, LIGGGHTS, MercuryDPM) advance contacts with velocity Verlet, the
damping force evaluated with the half-step velocity. That makes eps first order in dt (measured
below, and against LAMMPS in tests/library/test_dem_lammps.py): eps(dt) = eps + C dt / t_c + O(dt^2). The
study runs the same scheme on the contact at a few steps per contact, fits C, and recommends
dt = t_c / N with N = C / tol (at least 10): the step that keeps eps within a relative ``tol``;
up to VERIFY_STEPS steps per contact that N is run and refined until its error is within ``tol``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..core.errors import number_in
from .contact import Contact

__all__ = ["verlet_eps", "recommended_dt", "TimeStep", "VERIFY_STEPS", "REFINE"]

#: Steps per contact of the study; the coarsest is already in the asymptotic first-order regime
#: for every contact law tried (the ratio of successive errors is 2 within a few per cent).
STUDY_STEPS = (100, 200, 400)
#: Steps per contact sampled for the force rule's wobble of N |error| (see recommended_dt).
PHASE_STEPS = tuple(range(101, 117))
#: A recommended step of at most this many steps per contact is run before it is returned
#: (milliseconds), and refined by REFINE until its own error is within the tolerance.
VERIFY_STEPS = 20_000
REFINE = 1.25


def verlet_eps(contact: Contact, g: float, dt: float, max_steps: int = 10_000_000, phase: float = 0.0) -> float:
    """eps of one head-on collision advanced the way DEM codes do it (velocity Verlet, force from
    the half-step velocity; the force clipped at zero under the force rule, as LAMMPS'
    limit_damping does; no force once the overlap is gone). ``phase`` in [0, 1): where in a step
    the contact starts (the bodies ``phase * g * dt`` apart at the first step; 0: touching)."""
    a, c = float(contact.alpha), float(contact.gamma)
    D1, D2, clip = contact.D1, contact.D2, contact.end == "force"

    def accel(x, v):
        if x <= 0.0:
            return 0.0
        f = D1 * x ** a + D2 * x ** c * v
        return -max(f, 0.0) if clip else -f

    x, v = -phase * g * dt, g
    acc = 0.0
    for _ in range(max_steps):
        v_half = v + 0.5 * dt * acc
        x += dt * v_half
        acc = accel(x, v_half)
        v = v_half + 0.5 * dt * acc
        if x < 0.0 and v < 0.0:
            return -v / g
        if x > 0.0 and v < 0.0 and acc == 0.0 and clip:
            return -v / g    # force rule: no force left, the bodies drift apart at this speed
    raise ArithmeticError(f"no separation within {max_steps} steps of dt = {dt:g}")


@dataclass(frozen=True)
class TimeStep:
    """The recommendation and the study behind it."""

    dt: float
    contact_time: float
    steps_per_contact: float
    first_order_coefficient: float
    tol: float
    study: tuple            # (N, relative error of eps) for N in STUDY_STEPS

    def as_dict(self) -> dict:
        return {"dt": self.dt, "contact_time": self.contact_time, "steps_per_contact": self.steps_per_contact,
                "first_order_coefficient": self.first_order_coefficient, "tol": self.tol,
                "study": [list(row) for row in self.study]}


def recommended_dt(contact: Contact, g: float, tol: float = 1e-3, *, eps: float | None = None,
                   contact_time: float | None = None) -> TimeStep:
    """dt = t_c / N that keeps the velocity-Verlet eps within relative ``tol`` of the exact eps.
    ``eps`` and ``contact_time``, when the caller has them already (from a faster rung than the
    reference integrator this would run), are taken as the exact values.

    Velocity Verlet with the damping on the half-step velocity is the scheme DEM codes use
    (LAMMPS' among them); its eps converges at first order in dt. The study runs it at 100, 200
    and 400 steps per contact, takes the largest N times the error as the first-order coefficient, and
    checks the step it recommends.

    Parameters
    ----------
    contact : Contact
        The contact.
    g : float
        Impact speed.
    tol : float, optional
        Relative error allowed in eps, in [1e-8, 0.5].
    eps, contact_time : float, optional
        The exact eps and contact time, if already known.

    Returns
    -------
    TimeStep
        ``dt``, ``contact_time``, ``steps_per_contact``, ``first_order_coefficient``, ``tol`` and
        the ``study`` (steps per contact, relative error).

    Raises
    ------
    ParameterError
        For a ``tol`` out of range.

    Examples
    --------
    >>> from restitution.dem import Contact, recommended_dt
    >>> c = Contact("3/2", "1/2", D1=1.5e8, D2=2.0e4, end="overlap")
    >>> step = recommended_dt(c, 1.0, tol=1e-3)
    >>> step.steps_per_contact > 10, step.dt < step.contact_time
    (True, True)
    """
    tol = number_in("tol", tol, 1e-8, 0.5)
    t_c = contact.contact_time(g) if contact_time is None else contact_time
    exact = contact.eps(g) if eps is None else eps

    def error(n: float) -> float:
        return verlet_eps(contact, g, t_c / n) / exact - 1.0

    errors = [(n, error(n)) for n in STUDY_STEPS]
    # first order: |err| <= C / N; the largest N |err| of the study is a C that holds at every N
    # studied (it overestimates where the error falls faster than 1/N, as for tsuji damping). Under
    # the force rule N |err| also wobbles with where the last step falls (hooke with velocity
    # damping: 0.142 at 100 steps, 0.147 at 122.45, 0.141 at 130), so PHASE_STEPS sample that too.
    coefficient = max([n * abs(err) for n, err in errors] + [n * abs(error(n)) for n in PHASE_STEPS])
    n_needed = max(10.0, coefficient / tol)
    # The step is run, and refined until its own error is within tol, wherever that costs little:
    # below the study's steps the first-order model is an extrapolation (at 10 steps per contact a
    # Hertz-tsuji contact's error in LAMMPS was 0.0106 where 0.01 was asked), and above them the
    # wobble may still peak between the samples (found in LAMMPS on a random scene: 1.2e-3 at the
    # step recommended for 1.16e-3).
    while n_needed <= VERIFY_STEPS and abs(error(n_needed)) > tol:
        n_needed *= REFINE
    from ..core.errors import derived_in_range
    dt = derived_in_range("the time step", t_c / n_needed, {"D1": contact.D1, "D2": contact.D2, "g": float(g),
                                                             "tol": tol})
    return TimeStep(dt, t_c, n_needed, coefficient, tol, tuple(errors))


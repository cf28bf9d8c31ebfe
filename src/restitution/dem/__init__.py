"""For DEM modellers: the model in physical units of one contact (alpha, gamma, D1, D2, end rule),
calibration of the damping from a target eps, the contact duration and a time step, and the
dictionary between DEM codes' contact options and the model (LAMMPS, LIGGGHTS, MercuryDPM).

Sits above ``core`` (its only import); :mod:`restitution.dem.lammps` drives the real LAMMPS engine when
the optional dependency group ``restitution[dem]`` is installed.
"""

from .calibrate import Calibrated, calibrate
from .contact import Contact
from .timestep import recommended_dt

__all__ = ["Contact", "calibrate", "Calibrated", "recommended_dt"]

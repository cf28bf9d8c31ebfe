"""For DEM modellers: the model in physical units of one contact (alpha, gamma, D1, D2, end rule),
calibration of the damping from a target eps, the contact duration and a time step, and the
dictionary between DEM codes' contact options and the model, one engine object each (LAMMPS,
LIGGGHTS, Yade, MercuryDPM) in the registry :data:`restitution.dem.engines.ENGINES`.

Sits above ``core`` and ``fast``; an engine's runner (restitution.dem.engines.lammps.run for LAMMPS,
with the optional dependency group ``restitution[dem]``) drives the real engine where it is installed.
"""

from .calibrate import Calibrated, calibrate
from .contact import Contact
from .timestep import recommended_dt

__all__ = ["Contact", "calibrate", "Calibrated", "recommended_dt"]

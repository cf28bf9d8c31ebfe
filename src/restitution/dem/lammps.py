"""The LAMMPS runner's former address: it lives with its engine, in
restitution.dem.engines.lammps.run; scripts and notebooks that import it from here keep working."""

from .engines.lammps.run import available, lammps_eps, lammps_eps_extrapolated, lammps_wall_eps

__all__ = ["available", "lammps_eps", "lammps_eps_extrapolated", "lammps_wall_eps"]

"""The Yade runner's former address: it lives with its engine, in
restitution.dem.engines.yade.run; scripts and notebooks that import it from here keep working."""

from .engines.yade.run import (available, yade_eps_runs, yade_states, yade_eps_extrapolated, viscel_material,
                               mindlin_material)

__all__ = ["available", "yade_eps_runs", "yade_states", "yade_eps_extrapolated", "viscel_material", "mindlin_material"]

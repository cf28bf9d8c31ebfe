"""The LIGGGHTS runner's former address: it lives with its engine, in
restitution.dem.engines.liggghts.run; scripts and notebooks that import it from here keep working."""

from .engines.liggghts.run import (available, liggghts_pair_style, liggghts_eps_runs, liggghts_states,
                                   liggghts_eps_extrapolated, liggghts_wall_eps_runs)

__all__ = ["available", "liggghts_pair_style", "liggghts_eps_runs", "liggghts_states", "liggghts_eps_extrapolated",
           "liggghts_wall_eps_runs"]

"""The collision the DEM engine tests share: two spheres of glass on steel (unlike radii and
densities, so the effective mass and radius matter), SI units, and the impact speeds (two decades)
and material that the LIGGGHTS and Yade runs use."""

from __future__ import annotations

from restitution.dem.pair import Pair

PAIR = Pair.spheres(1e-3, 1.5e-3, 2500.0, 7800.0)
SPEEDS = (0.01, 0.1, 1.0)
MATERIAL = {"E": 5e7, "nu": 0.3}

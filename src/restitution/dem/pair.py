"""Two particles of a DEM contact, as every engine's contact law reads them: radii, masses, and the
effective mass m = m1 m2 / (m1 + m2) and radius R = R1 R2 / (R1 + R2) that divide its force."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..core.errors import derived_in_range, require_positive_finite

__all__ = ["Pair", "WALL_SIZE", "pair_inputs"]

#: A flat wall's radius and mass in a Pair (see Pair.wall).
WALL_SIZE = 1e300


@dataclass(frozen=True)
class Pair:
    """Two particles: radii and masses (SI or any consistent units)."""

    R1: float
    R2: float
    m1: float
    m2: float
    #: the densities when built by :meth:`spheres`: named in messages instead of masses nobody typed
    densities: tuple | None = field(default=None, compare=False, repr=False)

    def __post_init__(self):
        for name in ("R1", "R2", "m1", "m2"):
            require_positive_finite(name, getattr(self, name))

    @classmethod
    def spheres(cls, R1: float, R2: float, density1: float, density2: float | None = None) -> "Pair":
        d2 = density1 if density2 is None else density2
        for name, v in (("R1", R1), ("R2", R2), ("density1", density1), ("density2", d2)):
            require_positive_finite(name, v)
        vol = lambda r: 4.0 / 3.0 * math.pi * _pow(r, 3)   # noqa: E731
        # the masses are ours, not the user's: out of range, the message names radius and density
        m1, m2 = density1 * vol(R1), d2 * vol(R2)
        m1 = derived_in_range("the mass m1", m1, {"radius R1": R1, "density1": density1})
        m2 = derived_in_range("the mass m2", m2, {"radius R2": R2, "density2": d2})
        pair = cls(R1, R2, m1, m2, (density1, d2))
        derived_in_range("the effective mass", pair.m, {"radii": (R1, R2), "densities": (density1, d2)})
        derived_in_range("the effective radius", pair.R, {"radii": (R1, R2)})
        return pair

    @classmethod
    def wall(cls, R: float, density: float) -> "Pair":
        """A sphere of radius R and density ``density`` against a flat wall: the wall's radius and
        mass are WALL_SIZE, so large that the effective ones are the sphere's to rounding
        (R R_w / (R + R_w) = R (1 + R / R_w)^-1)."""
        for name, v in (("R", R), ("density", density)):
            require_positive_finite(name, v)
        m = derived_in_range("the mass", density * 4.0 / 3.0 * math.pi * _pow(R, 3), {"radius": R, "density": density})
        return cls(R, WALL_SIZE, m, WALL_SIZE)

    @property
    def m(self) -> float:
        return _harmonic(self.m1, self.m2)

    @property
    def R(self) -> float:
        return _harmonic(self.R1, self.R2)


def _harmonic(a: float, b: float) -> float:
    """a b / (a + b); where the product leaves doubles (tiny or huge particles), a / (1 + a / b),
    which stays in range whenever the result does (the usual form kept for unchanged digits)."""
    prod = a * b
    if 2.2250738585072014e-308 <= prod < math.inf:
        return prod / (a + b)
    return a / (1.0 + a / b)


def _pow(a: float, b: float) -> float:
    """a ** b without OverflowError: inf instead (then named by derived_in_range)."""
    try:
        return a ** b
    except OverflowError:
        return math.inf


def pair_inputs(pair: Pair) -> dict:
    """The pair as the user gave it, for messages (radii; masses stand for radius and density)."""
    if pair.densities is not None:
        return {"radii": (pair.R1, pair.R2), "densities": pair.densities}
    return {"radii": (pair.R1, pair.R2), "masses": (pair.m1, pair.m2)}

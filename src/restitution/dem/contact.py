"""One contact in physical units: delta'' + D1 delta^alpha + D2 delta^gamma delta' = 0 with an
end-of-contact rule, and what a DEM modeller asks of it: eps at an impact speed, the contact
duration t_c, and the scaled parameter Omega behind both.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from ..core.collision import collide
from ..core.exponents import as_exponents
from ..core.model import Material
from ..core.results import end_rule

__all__ = ["Contact"]


@dataclass(frozen=True)
class Contact:
    """delta'' + D1 delta^alpha + D2 delta^gamma delta' = 0 (per unit effective mass) ended by ``end``
    ("force": contact ends where the normal force vanishes, "overlap": where delta returns to 0)."""

    alpha: Fraction
    gamma: Fraction
    D1: float
    D2: float
    end: str = "force"

    def __post_init__(self):
        ex = as_exponents(self.alpha, self.gamma)
        Material(ex, None, self.D1, self.D2)          # validates D1, D2 (one line each)
        object.__setattr__(self, "alpha", ex.alpha)
        object.__setattr__(self, "gamma", ex.gamma)
        object.__setattr__(self, "D1", float(self.D1))
        object.__setattr__(self, "D2", float(self.D2))
        object.__setattr__(self, "end", end_rule(self.end))

    @property
    def material(self) -> Material:
        return Material(self.alpha, self.gamma, self.D1, self.D2)

    def omega(self, g: float) -> float:
        return float(self.material.omega(g))

    def collision(self, g: float, rtol: float = 1e-12):
        """The scaled collision at impact speed g (core.collision.collide with this end rule)."""
        return collide(self.alpha, self.gamma, self.omega(g), rtol=rtol, end=self.end)

    def eps(self, g: float, rtol: float = 1e-12) -> float:
        return self.collision(g, rtol).eps

    def contact_time(self, g: float, rtol: float = 1e-12) -> float:
        """t_c in the units of D1, D2, g: the scaled tau_c times the time scale B(g)."""
        from ..core.errors import derived_in_range
        inputs = {"D1": self.D1, "D2": self.D2, "g": float(g)}
        with np.errstate(all="ignore"):
            t_c = self.collision(g, rtol).tau_c * float(self.material.time_scale(g))
        return derived_in_range("the contact time", t_c, inputs)

    def as_dict(self) -> dict:
        return {"alpha": str(self.alpha), "gamma": str(self.gamma), "D1": self.D1, "D2": self.D2,
                "end": self.end}

"""What every engine's designer does between a target eps and a setting: calibrate the damping of
a contact whose stiffness is given, and refuse a design the engine's geometry cannot run."""

from __future__ import annotations

from ..core.errors import ParameterError
from .calibrate import calibrate
from .contact import Contact
from .pair import Pair

__all__ = ["calibrated", "refuse_passing_through"]


def calibrated(base: Contact, eps: float, g: float) -> Contact:
    """``base`` with the damping D2 that gives ``eps`` at impact speed ``g``."""
    return calibrate(base.alpha, base.gamma, D1=base.D1, eps=eps, g=g, end=base.end).contact


def refuse_passing_through(contact: Contact, pair: Pair, eps: float, g: float, code: str) -> None:
    """A design whose contact overlaps past R1 + R2 at g gives another eps there: the engine pushes
    the spheres through each other (measured with LAMMPS: 2.7e-4 off at 1.05 times that speed)."""
    if contact.reaches(g, pair.R1 + pair.R2):
        raise ParameterError("g", g, f"at this speed the contact that gives eps = {eps:g} overlaps past R1 + R2 = "
                                     f"{pair.R1 + pair.R2:.4g}: {code} pushes the spheres through each other; a "
                                     "stiffer contact or a lower speed")

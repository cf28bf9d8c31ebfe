"""What every engine's designer does between a target eps and a setting: calibrate the damping of
a contact whose stiffness is given, and refuse a design the engine's geometry cannot run."""

from __future__ import annotations

from ..core.errors import ParameterError
from .calibrate import calibrate
from .contact import Contact
from .pair import Pair

__all__ = ["calibrated", "refuse_passing_through"]


def calibrated(base: Contact, eps: float, g: float) -> Contact:
    """``base`` with the damping D2 that gives ``eps`` at impact speed ``g``.

    Parameters
    ----------
    base : Contact
        The law, its stiffness D1 and end rule; its D2 is replaced.
    eps : float
        The target coefficient of restitution.
    g : float
        Impact speed.

    Returns
    -------
    Contact

    Examples
    --------
    >>> from restitution.dem import Contact
    >>> c = calibrated(Contact("3/2", "1", 1e12, 1.0, "force"), 0.6, 1.0)
    >>> round(c.eps(1.0), 9)
    0.6
    """
    return calibrate(base.alpha, base.gamma, D1=base.D1, eps=eps, g=g, end=base.end).contact


def refuse_passing_through(contact: Contact, pair: Pair, eps: float, g: float, code: str) -> None:
    """A design whose contact overlaps past R1 + R2 at g gives another eps there: the engine pushes
    the spheres through each other (measured with LAMMPS: 2.7e-4 off at 1.05 times that speed).

    Parameters
    ----------
    contact : Contact
        The designed contact.
    pair : Pair
        The two particles (their radii R1, R2).
    eps : float
        The target eps, as the refusal states it.
    g : float
        Impact speed.
    code : str
        The engine, as the refusal names it.

    Returns
    -------
    None

    Raises
    ------
    ParameterError
        Where the overlap at ``g`` reaches R1 + R2.

    Examples
    --------
    >>> from restitution.dem import Contact
    >>> from restitution.dem.pair import Pair
    >>> soft = Contact("3/2", "1", 1.0, 1e-3, "force")
    >>> refuse_passing_through(soft, Pair.spheres(0.001, 0.001, 2500.0, 2500.0), 0.6, 1.0, "LAMMPS")
    Traceback (most recent call last):
    ...
    restitution.core.errors.ParameterError: g = 1.0: at this speed ... overlaps past R1 + R2 = 0.002: LAMMPS ...
    """
    if contact.reaches(g, pair.R1 + pair.R2):
        raise ParameterError("g", g, f"at this speed the contact that gives eps = {eps:g} overlaps past R1 + R2 = "
                                     f"{pair.R1 + pair.R2:.4g}: {code} pushes the spheres through each other; a "
                                     "stiffer contact or a lower speed")

"""One contact in physical units: delta'' + D1 delta^alpha + D2 delta^gamma delta' = 0 with an
end-of-contact rule, and what a DEM modeller asks of it: eps at an impact speed, the contact
duration t_c, and the scaled parameter Omega behind both.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from functools import lru_cache

import numpy as np

from ..core.collision import collide
from ..core.exponents import as_exponents
from ..core.model import Material
from ..core.problem import Problem, as_problem
from ..core.results import end_rule

__all__ = ["Contact", "ElasticContact", "contact_eps", "scaled_collision", "TIMES_OMEGA_MAX"]

#: Above the scipy reference's range (core.collision.OMEGA_RANGE: a contact all but undamped, whose
#: 1 - eps that integration no longer resolves) contact times come from the compiled integrator, up
#: to here: against mpmath (20 digits) its tau_c at rtol 1e-12 held to 1.7e-12 (relative) at Omega =
#: 1e11..1e15 for (3/2, 1/4), (1, 0), (3/2, 1/2), (3/2, 1), (1, 1), (1, 3/2), (2, 1), (5/2, 0)
#: under both end rules (tests/library/test_contact_time.py checks four of them).
TIMES_OMEGA_MAX = 1e15


def contact_eps(problem, omega: float, rtol: float = 1e-12) -> float:
    """eps at one Omega, to the scipy reference's bound at ``rtol``, from the cheapest rung that meets it.

    Under the overlap rule this is the compiled integrator (tens of microseconds) instead of the
    reference (20-200 ms), which calibrations call dozens of times. Near the overlap rule's sticking
    boundary, where no fast rung meets that bound, the reference answers. Nothing cached on disk is
    read: a master curve some earlier run left in the cache answers within the same bound but not to
    the same bits, and a calibration (the pipeline's calibration table, a DEM designer's D2) must
    not depend on what the user's cache holds. Answers are kept in memory for the process, keyed
    by (problem, Omega, rtol): a deck's walls of one law, its stages, sizes and speeds ask the same
    Omega again (a LIGGGHTS tutorial's six walls of one law, each at nine sizes and five speeds),
    and each ask of the ladder quotes its every rung in exact fractions.

    Parameters
    ----------
    problem : Problem
        The exponents and end rule (an Exponents or an (alpha, gamma) pair: the force rule).
    omega : float
        The scaled parameter Omega > 0.
    rtol : float
        The tolerance of the scipy reference whose bound (10 rtol + 1e-13, more for large
        exponents) the answer meets.

    Returns
    -------
    float
        eps at ``omega``.

    Raises
    ------
    ParameterError
        For bad input; StickError (a ParameterError) where the bodies stick under the overlap rule.

    Examples
    --------
    >>> round(contact_eps(("3/2", "1/2"), 1.0), 9)
    0.393930603
    >>> contact_eps(("3/2", "1/2"), 1.0) == contact_eps(Problem.of("3/2", "1/2"), 1)
    True
    """
    return _contact_eps(as_problem(problem), float(omega), float(rtol))


@lru_cache(maxsize=4096)
def _contact_eps(problem: Problem, omega: float, rtol: float) -> float:
    from ..core.collision import StickError
    from ..core.errors import ParameterError
    from ..fast.ladder import epsilon
    from ..fast.rung import reference_bound
    try:
        tol = reference_bound(rtol, problem.ex)   # the force rule's, as the reference states it
        return float(epsilon(problem, omega=[omega], tol=tol, build=False, cached=False).eps[0])
    except StickError:
        raise
    except ParameterError:
        return collide(problem, omega, rtol=rtol).eps


def scaled_collision(problem, omega: float, rtol: float = 1e-12):
    """The scaled collision at one Omega, by the most accurate means that exists for the law.

    In closed form for alpha = 2 gamma + 1 (:func:`restitution.core.exact_family.exact_collision`:
    eps to rounding, tau_b and tau_c to about 1e-14, any Omega, under a millisecond): Hertz with
    delta^(1/4) damping (LAMMPS tsuji and coeff_restitution, LIGGGHTS hertz) and hooke with linear
    damping are in it. Otherwise the scipy reference at ``rtol``
    (:func:`restitution.core.collision.collide`: its Omega range, 20-200 ms).

    Parameters
    ----------
    problem : Problem
        The exponents and the end-of-contact rule (an Exponents or an (alpha, gamma) pair: the
        force rule).
    omega : float
        The scaled parameter Omega > 0.
    rtol : float
        The reference integrator's tolerance (not read by the closed form).

    Returns
    -------
    Collision
        eps, tau_b, x_b, tau_c, x_c and their stated bounds.

    Raises
    ------
    ParameterError
        For bad input or an Omega outside the reference's range; StickError (a ParameterError)
        where the bodies stick under the overlap rule.

    Examples
    --------
    >>> c = scaled_collision(Problem.of("3/2", "1/4", end="overlap"), 0.7)
    >>> c.rtol, round(c.eps, 10), c.ended_by
    (0.0, 0.1371174182, 'separation')
    >>> scaled_collision(("3/2", "1/2"), 0.7).rtol
    1e-12
    """
    from ..core.exact_family import in_family
    if in_family(problem):
        return _exact_collision(as_problem(problem), float(omega))
    return collide(problem, omega, rtol=rtol)


@lru_cache(maxsize=1024)
def _exact_collision(problem, omega: float):
    """The closed form's collision, kept: a deck's pairs, walls, sizes and speeds share Omega where
    eps does not depend on size or speed (its contact time's quadratures are the audit's costliest step)."""
    from ..core.exact_family import exact_collision
    return exact_collision(problem, omega)


def _fast_tau_c(problem, omega: float, rtol: float) -> float:
    """tau_c of the compiled integrator (all but undamped contacts: no sticking, no creep)."""
    from ..fast.integrator import END_FAILED, collide_fast
    problem = as_problem(problem)
    ex = problem.ex
    row = collide_fast(ex.p, ex.q_alpha, ex.q_gamma, [omega], rtol, problem.effective_end)[0]
    if row[5] == END_FAILED:
        raise ArithmeticError(f"compiled integrator failed at Omega = {omega:g} (alpha={ex.alpha}, gamma={ex.gamma})")
    return float(row[3])


@dataclass(frozen=True)
class Contact:
    """delta'' + D1 delta^alpha + D2 delta^gamma delta' = 0 (per unit effective mass) ended by ``end``
    ("force": contact ends where the normal force vanishes, "overlap": where delta returns to 0).

    One contact of a DEM simulation in physical units; the functions of
    each engine's contact module (:mod:`restitution.dem.engines`) builds one from a code's options.

    Parameters
    ----------
    alpha, gamma : str, int, Fraction or float
        The exponents (:meth:`restitution.Exponents.parse`).
    D1, D2 : float
        Elastic and dissipative constants per unit effective mass (> 0).
    end : {"force", "overlap"}, optional
        The end-of-contact rule.

    Raises
    ------
    ParameterError
        For an exponent, constant or end rule out of range.

    Examples
    --------
    >>> from restitution.dem import Contact
    >>> c = Contact("3/2", "1/2", D1=1.5e8, D2=2.0e4, end="overlap")
    >>> round(c.eps(1.0), 5)                       # eps at an impact speed of 1 (m/s)
    0.75576
    >>> round(c.contact_time(1.0) * 1e3, 4)        # contact time (ms)
    1.783
    """

    alpha: Fraction
    gamma: Fraction
    D1: float
    D2: float
    end: str = "force"

    def __post_init__(self):
        ex = as_exponents(self.alpha, self.gamma)
        Material.of(ex, self.D1, self.D2)          # validates D1, D2 (one line each)
        object.__setattr__(self, "alpha", ex.alpha)
        object.__setattr__(self, "gamma", ex.gamma)
        object.__setattr__(self, "D1", float(self.D1))
        object.__setattr__(self, "D2", float(self.D2))
        object.__setattr__(self, "end", end_rule(self.end))

    @property
    def problem(self) -> Problem:
        """The exponents and this contact's end rule."""
        return Problem.of(self.alpha, self.gamma, self.end)

    @property
    def material(self) -> Material:
        return Material(self.alpha, self.gamma, self.D1, self.D2)

    def omega(self, g: float) -> float:
        return float(self.material.omega(g))

    def collision(self, g: float, rtol: float = 1e-12):
        """The scaled collision at impact speed g with this end rule (:func:`scaled_collision`)."""
        return scaled_collision(self.problem, self.omega(g), rtol)

    def eps(self, g: float, rtol: float = 1e-12) -> float:
        """eps at impact speed g, to the reference's bound at rtol (:func:`contact_eps`)."""
        return contact_eps(self.problem, self.omega(g), rtol)

    def contact_time(self, g: float, rtol: float = 1e-12, compiled: bool = False) -> float:
        """t_c in the units of D1, D2, g: the scaled tau_c times the time scale B(g) (the scipy
        reference's tau_c; above its Omega range, up to TIMES_OMEGA_MAX, the compiled integrator's;
        for alpha = 2 gamma + 1 the closed form's at every Omega, :func:`scaled_collision`).
        ``compiled``: the compiled integrator's within the reference's range too (within 3.3e-13 of
        the reference's there, measured for alpha, gamma = 3/2, 1/2; 1, 1/2; 3/2, 1; 3/2, 0, both end
        rules, Omega 1e-3 to 1e3), for a caller that needs many and not scipy's import."""
        from ..core.collision import OMEGA_RANGE
        from ..core.errors import derived_in_range
        from ..core.exact_family import in_family
        inputs = {"D1": self.D1, "D2": self.D2, "g": float(g)}
        om = self.omega(g)
        numeric = not in_family((self.alpha, self.gamma))
        with np.errstate(all="ignore"):
            low = OMEGA_RANGE[0] if compiled else OMEGA_RANGE[1]
            try:
                tau_c = (_fast_tau_c(self.problem, om, rtol)
                         if numeric and low < om <= TIMES_OMEGA_MAX else self.collision(g, rtol).tau_c)
            except ArithmeticError:
                if not compiled:
                    raise
                tau_c = self.collision(g, rtol).tau_c
            t_c = tau_c * float(self.material.time_scale(g))
        return derived_in_range("the contact time", t_c, inputs)

    def reaches(self, g: float, limit: float) -> bool:
        """Whether the largest overlap at impact speed g reaches ``limit`` (for two spheres R1 + R2,
        where their centres meet). Beyond it a DEM engine pushes the bodies through each other and
        the contact law's eps is not what it gives (found running random decks in LAMMPS: eps off,
        then atoms lost from the box). The undamped contact's largest overlap,
        (g^2 (alpha + 1) / (2 D1))^(1/(alpha + 1)), bounds the damped one's; only where it reaches
        the limit is the compression integrated (the same under both end rules, so the force
        rule's, which never sticks). Outside the reference's range of Omega (alpha = 2 gamma + 1 has
        none: its closed form) the bound is kept: a flag where the bodies may still part, never an
        eps where they do not."""
        from ..core.errors import ParameterError
        a = float(self.alpha)
        if (g * g * (a + 1.0) / (2.0 * self.D1)) ** (1.0 / (a + 1.0)) < limit:
            return False
        try:
            reach = scaled_collision(self.problem.with_end("force"), self.omega(g)).x_b
        except ParameterError:
            return True
        return reach * float(self.material.length_scale(g)) >= limit

    def as_dict(self) -> dict:
        return {"alpha": str(self.alpha), "gamma": str(self.gamma), "D1": self.D1, "D2": self.D2,
                "end": self.end}


@dataclass(frozen=True)
class ElasticContact:
    """delta'' + D1 delta^alpha = 0: a contact without damping (an engine's e = 1), which gives
    eps = 1 exactly at every speed under either end rule (energy is conserved, and the force
    vanishes where the overlap does). Its contact time and largest overlap are closed forms.

    Parameters
    ----------
    alpha : str, int, Fraction or float
        The elastic exponent.
    D1 : float
        The elastic constant per unit effective mass (> 0).
    end : {"force", "overlap"}, optional
        The engine's end rule (the same contact under both).

    Examples
    --------
    >>> c = ElasticContact("3/2", D1=1.0e8)
    >>> c.eps(1.0), round(c.contact_time(1.0) / c.largest_overlap(1.0), 4)   # Hertz: t_c = 2.9433 delta_max / g
    (1.0, 2.9433)
    """

    alpha: Fraction
    D1: float
    end: str = "overlap"
    gamma: Fraction = Fraction(0)
    D2: float = 0.0

    def __post_init__(self):
        ex = as_exponents(self.alpha, self.gamma)
        Material.of(ex, self.D1, 1.0)               # validates D1 (one line)
        object.__setattr__(self, "alpha", ex.alpha)
        object.__setattr__(self, "D1", float(self.D1))
        object.__setattr__(self, "end", end_rule(self.end))

    def largest_overlap(self, g: float) -> float:
        """(g^2 (alpha + 1) / (2 D1))^(1/(alpha + 1)), from the conserved energy."""
        a = float(self.alpha)
        return (g * g * (a + 1.0) / (2.0 * self.D1)) ** (1.0 / (a + 1.0))

    def eps(self, g: float, rtol: float = 1e-12) -> float:
        """1, exactly."""
        return 1.0

    def contact_time(self, g: float, rtol: float = 1e-12, compiled: bool = False) -> float:
        """t_c = (2 delta_max / g) int_0^1 du / sqrt(1 - u^(alpha+1))
        = (2 delta_max / g) sqrt(pi) Gamma(1 + b) / Gamma(1/2 + b), b = 1/(alpha + 1) (a closed form:
        ``rtol`` and ``compiled``, as :meth:`Contact.contact_time` takes them, change nothing)."""
        b = 1.0 / (float(self.alpha) + 1.0)
        return 2.0 * self.largest_overlap(g) / g * math.sqrt(math.pi) * math.gamma(1.0 + b) / math.gamma(0.5 + b)

    def reaches(self, g: float, limit: float) -> bool:
        """Whether the largest overlap at impact speed g reaches ``limit`` (as :meth:`Contact.reaches`)."""
        return self.largest_overlap(g) >= limit

    def as_dict(self) -> dict:
        return {"alpha": str(self.alpha), "gamma": None, "D1": self.D1, "D2": 0.0, "end": self.end}

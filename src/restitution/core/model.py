"""Material parameters and the scaling that reduces the collision to one parameter Omega.

    xi'' + D1 xi^alpha + D2 xi^gamma xi' = 0,  xi(0) = 0, xi'(0) = g

becomes x'' + Omega x^alpha + x^gamma x' = 0, x(0) = 0, x'(0) = 1 with xi = A x,
t = B tau, A = (g / D2)^(1/(gamma+1)), B = (D2 g^gamma)^(-1/(gamma+1)) and

    Omega = D1 g^((alpha-1-2 gamma)/(gamma+1)) D2^(-(alpha+1)/(gamma+1)).

This form is the paper's D* v^((alpha-1-2gamma)/(gamma+1)) with v = D2^(1/gamma) g
rewritten so that it also holds for gamma = 0, where D* is undefined.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import ParameterError, real_array, require_positive_finite
from .exponents import Exponents, as_exponents, read_through

#: Omega outside this range is refused here: no method in the package works with it in doubles.
OMEGA_REPRESENTABLE = (1e-300, 1e300)

VISCOUS = "viscous-dominant"
ELASTIC = "elastic-dominant"


def positive_speeds(g, field: str = "g") -> np.ndarray:
    """Impact speeds as a float array, every entry finite and > 0."""
    arr = real_array(field, g, "must be finite numbers > 0")
    if arr.size == 0 or not np.all(np.isfinite(arr)) or not np.all(arr > 0):
        bad = arr[~(np.isfinite(arr) & (arr > 0))] if arr.size else arr
        shown = bad.flat[0] if bad.size else g
        raise ParameterError(field, float(shown) if bad.size else shown, "must be finite numbers > 0")
    return arr


@dataclass(frozen=True)
class Material:
    """A viscoelastic pair: force-law exponents and the constants D1 (elastic), D2 (dissipative).

    The contact law is xi'' + D1 xi^alpha + D2 xi^gamma xi' = 0 with xi'(0) = g; :meth:`omega` gives
    the one parameter of the scaled problem, Omega = D1 g^((alpha-1-2 gamma)/(gamma+1))
    D2^(-(alpha+1)/(gamma+1)), on which eps depends.

    Parameters
    ----------
    alpha, gamma : str, int, Fraction or float
        The exponents, as :meth:`Exponents.parse` takes them (``"3/2"``, ``1``).
    D1, D2 : float
        Elastic and dissipative constants, finite and > 0, in any consistent units.

    Raises
    ------
    ParameterError
        For an exponent outside its range or a D1, D2 that is not a finite number > 0; and from
        :meth:`omega`, for speeds that are not > 0 or an Omega outside double precision.

    Examples
    --------
    >>> from restitution import Material
    >>> m = Material(alpha="3/2", gamma=1, D1=0.000296, D2=0.0109)    # the paper's material
    >>> round(m.omega(0.1), 6)
    0.472616
    >>> m.omega([0.01, 0.1]).round(4)                                 # vectorised over g
    array([2.6577, 0.4726])
    """

    exponents: Exponents
    D1: float
    D2: float

    def __init__(self, alpha, gamma, D1, D2):
        object.__setattr__(self, "exponents", as_exponents(alpha, gamma))
        object.__setattr__(self, "D1", require_positive_finite("D1", D1))
        object.__setattr__(self, "D2", require_positive_finite("D2", D2))

    @classmethod
    def of(cls, problem, D1, D2) -> "Material":
        """The material for a problem's exponents (a Problem, an Exponents or an (alpha, gamma) pair)."""
        ex = as_exponents(problem)
        out = cls.__new__(cls)
        object.__setattr__(out, "exponents", ex)
        object.__setattr__(out, "D1", require_positive_finite("D1", D1))
        object.__setattr__(out, "D2", require_positive_finite("D2", D2))
        return out

    alpha = read_through("exponents", "alpha")
    gamma = read_through("exponents", "gamma")

    def omega(self, g):
        """Omega = D1 g^((alpha-1-2 gamma)/(gamma+1)) D2^(-(alpha+1)/(gamma+1)) at impact speed(s) g.

        Parameters
        ----------
        g : float or array_like
            Impact speeds, > 0.

        Returns
        -------
        float or numpy.ndarray
            Omega, the same shape as ``g`` (a float for a scalar).

        Raises
        ------
        ParameterError
            For a speed that is not positive and finite, or where D1, D2 and g together give an
            Omega outside [1e-300, 1e300].

        See Also
        --------
        restitution.epsilon : eps at these Omega (or give it ``g``, ``D1``, ``D2`` directly).
        restitution.collide : One whole collision at one Omega.

        Examples
        --------
        >>> from restitution import Material
        >>> m = Material(alpha="3/2", gamma=1, D1=0.000296, D2=0.0109)
        >>> round(m.omega(0.1), 6)
        0.472616
        """
        speeds = positive_speeds(g)
        a, c = self.alpha, self.gamma
        # Work in logs: D2^(-(alpha+1)/(gamma+1)) overflows for tiny D2 long before Omega does.
        log_omega = (math.log(self.D1) + float((a - 1 - 2 * c) / (c + 1)) * np.log(speeds)
                     - float((a + 1) / (c + 1)) * math.log(self.D2))
        with np.errstate(over="ignore", under="ignore"):
            out = np.exp(log_omega)
        if not np.all((out >= OMEGA_REPRESENTABLE[0]) & (out <= OMEGA_REPRESENTABLE[1])):
            # The inputs are fine one by one; together they leave double precision.
            outside = ~((out >= OMEGA_REPRESENTABLE[0]) & (out <= OMEGA_REPRESENTABLE[1]))
            bad = float(np.asarray(speeds).flat[int(np.argmax(outside))])
            raise ParameterError("g", bad, f"with D1 = {self.D1:g}, D2 = {self.D2:g} gives Omega = "
                                           f"exp({float(np.max(np.abs(log_omega))):.4g}) in magnitude, "
                                           "outside double precision; choose D1, D2, g with Omega in "
                                           "[1e-300, 1e300]")
        return float(out) if np.ndim(out) == 0 else out

    @property
    def d_star(self) -> float | None:
        """The paper's D* = D1 / D2^((alpha-1)/gamma); None for gamma = 0, where it is undefined."""
        if self.gamma == 0:
            return None
        return math.exp(math.log(self.D1) - float((self.alpha - 1) / self.gamma) * math.log(self.D2))

    @property
    def regime(self) -> str | None:
        """'viscous-dominant' for D* < 1, 'elastic-dominant' otherwise (None when D* is undefined)."""
        d = self.d_star
        if d is None:
            return None
        return VISCOUS if d < 1 else ELASTIC

    def length_scale(self, g):
        """A with xi = A x."""
        speeds = positive_speeds(g)
        out = (speeds / self.D2) ** (1.0 / float(self.gamma + 1))
        return float(out) if np.ndim(out) == 0 else out

    def time_scale(self, g):
        """B with t = B tau."""
        speeds = positive_speeds(g)
        out = (self.D2 * speeds ** float(self.gamma)) ** (-1.0 / float(self.gamma + 1))
        return float(out) if np.ndim(out) == 0 else out

    def as_dict(self) -> dict:
        return {"alpha": str(self.alpha), "gamma": str(self.gamma), "D1": self.D1, "D2": self.D2,
                "d_star": self.d_star, "regime": self.regime}


def at_most_one(eps):
    """eps capped at 1. The collision only dissipates energy, so eps <= 1 exactly; a value computed
    above 1 (integrator tolerance or rounding where 1 - eps is below them) lies within its error
    bound of the truth, and 1 lies closer to the truth still: capping never widens the bound."""
    return np.minimum(eps, 1.0) if isinstance(eps, np.ndarray) else min(float(eps), 1.0)

"""Force-law exponents as exact rationals.

The series in tau^(1/p) only exists when alpha and gamma are rational; the paper
approximates them by q_alpha/p and q_gamma/p with a common denominator p. A float is read only
where it is such a rational to within one unit in its last place (1.5, 0.25, 1/3 as Python
computes it): every method answers at the rational, so a float farther from it (1.4999999) would be
answered for another exponent than the one given, beyond the error bound stated (2.75e-8 in eps
for alpha = 1.4999999, gamma = 1, Omega = 1, where the stated bound was 5e-13). It is refused, naming
the rational to pass exactly.
"""

from __future__ import annotations

import math
import re
import numbers
from dataclasses import dataclass
from fractions import Fraction

from .errors import ParameterError

#: Largest denominator accepted when a float must be turned into a rational.
MAX_DENOMINATOR = 12
#: Largest exponent accepted. The physics has no bound, but beyond this the force laws are so
#: steep that the integrator's stated accuracy has not been verified.
MAX_EXPONENT = Fraction(8)


#: How the README writes numbers and exponents: 3/2, 1, 1.5, 2.5e-3. No sign, spaces or digit
#: separators: Python would read " 3/2 ", "-0" or "1_0/4" (as 5/2), which nobody means.
NUMBER_TEXT = re.compile(r"(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?")
RATIONAL_TEXT = re.compile(r"\d+/[1-9]\d*")


def number_argument(text: str) -> float:
    """An argparse type: a float written as the README writes numbers (a sign is read here and
    judged by the physics, like NaN and inf, which then name the field); "1_000" or " 2" are not."""
    import argparse

    body = text[1:] if text[:1] in "+-" else text
    if not (NUMBER_TEXT.fullmatch(body) or body.lower() in ("nan", "inf", "infinity")):
        raise argparse.ArgumentTypeError(f"not a number: {text!r}")
    return float(text)


def parse_exponent(field: str, value, *, minimum: Fraction, inclusive: bool,
                   max_denominator: int = MAX_DENOMINATOR) -> Fraction:
    """Read an exponent given as "3/2", "1", 1.5, Fraction(3, 2) or a float that is a rational
    with denominator at most ``max_denominator`` to within one unit in its last place.

    Returns the rational; ParameterError (naming the nearest rational) for anything else.
    """
    given = value  # errors quote what the user typed, not our conversion of it
    bound = f"in {'[' if inclusive else '('}{minimum}, {MAX_EXPONENT}]"
    allowed = f"must be a rational number {bound} (e.g. 3/2), denominator <= {max_denominator}"
    if isinstance(value, (bool, np_bool_types())):
        raise ParameterError(field, given, allowed)
    if isinstance(value, Fraction):
        exact = value
    elif isinstance(value, numbers.Integral):
        exact = Fraction(int(value))
    elif isinstance(value, numbers.Real) and not isinstance(value, float):
        value = float(value)
        exact = None
        if not math.isfinite(value):
            raise ParameterError(field, given, allowed)
    elif isinstance(value, float):
        if not math.isfinite(value):
            raise ParameterError(field, given, allowed)
        exact = None
    elif isinstance(value, str):
        text = value
        if not (RATIONAL_TEXT.fullmatch(text) or NUMBER_TEXT.fullmatch(text)):
            raise ParameterError(field, given, allowed)
        try:
            exact = Fraction(text)
        except (ValueError, ZeroDivisionError):
            raise ParameterError(field, given, allowed) from None
        if abs(exact) > MAX_EXPONENT:
            raise ParameterError(field, given, allowed)
        if "/" not in text and ("." in text or "e" in text.lower()):
            # A decimal string is a float in disguise: treat it like one.
            value, exact = float(exact), None
    else:
        raise ParameterError(field, given, allowed)

    if exact is None:
        if abs(value) > MAX_EXPONENT:
            raise ParameterError(field, given, allowed)
        exact = Fraction(value).limit_denominator(max_denominator)
        off = abs(Fraction(value) - exact)
        if off > Fraction(math.ulp(value)):
            raise ParameterError(field, given, (
                f"{allowed}; a float is read only where it is such a rational to its last bit (1.5, "
                f"0.25, 1/3 as Python computes it), and the nearest such rational, {exact}, is "
                f"{float(off):.2g} away: eps would differ at about that level; pass it exactly, as "
                f"'{exact}' or Fraction({exact.numerator}, {exact.denominator})"))
    elif exact.denominator > max_denominator:
        raise ParameterError(field, given, allowed)

    if exact < minimum or (exact == minimum and not inclusive) or exact > MAX_EXPONENT:
        raise ParameterError(field, given, allowed)
    return exact


def np_bool_types() -> tuple:
    """numpy's bool type when numpy is loaded (a bool is not a number of anything here)."""
    import numpy as np
    return (np.bool_,)


@dataclass(frozen=True)
class Exponents:
    """alpha (elastic) and gamma (dissipative) as rationals q_alpha/p and q_gamma/p.

    Build one with :meth:`Exponents.parse`, which accepts what the rest of the package accepts:
    exact strings (``"3/2"``), integers, Fractions, or floats that are a rational with denominator
    at most 12 to their last bit (``1.5``, ``1/3``; ``1.4999999`` is refused).

    Parameters
    ----------
    alpha : Fraction
        Elastic exponent, in (0, 8].
    gamma : Fraction
        Dissipative exponent, in [0, 8].

    Attributes
    ----------
    p : int
        Least common denominator of alpha and gamma: the series are in powers of tau^(1/p).
    q_alpha, q_gamma : int
        The numerators over ``p``.

    Raises
    ------
    ParameterError
        From :meth:`parse`, for an exponent outside its range or a float that is no such rational.

    Examples
    --------
    >>> from restitution import Exponents
    >>> ex = Exponents.parse("3/2", 1)
    >>> ex.alpha, ex.gamma, ex.p, ex.q_alpha, ex.q_gamma
    (Fraction(3, 2), Fraction(1, 1), 2, 3, 2)
    >>> Exponents.parse(1.5, "1/2").gamma
    Fraction(1, 2)
    """

    alpha: Fraction
    gamma: Fraction

    @classmethod
    def parse(cls, alpha, gamma) -> "Exponents":
        return cls(parse_exponent("alpha", alpha, minimum=Fraction(0), inclusive=False),
                   parse_exponent("gamma", gamma, minimum=Fraction(0), inclusive=True))

    @property
    def p(self) -> int:
        """Least common denominator of alpha and gamma."""
        return math.lcm(self.alpha.denominator, self.gamma.denominator)

    @property
    def q_alpha(self) -> int:
        return int(self.alpha * self.p)

    @property
    def q_gamma(self) -> int:
        return int(self.gamma * self.p)

    @property
    def omega_exponent(self) -> Fraction:
        """Power of the impact speed g in Omega: (alpha - 1 - 2 gamma) / (gamma + 1)."""
        return (self.alpha - 1 - 2 * self.gamma) / (self.gamma + 1)

    def __str__(self) -> str:
        return f"alpha={self.alpha}, gamma={self.gamma}"


def as_exponents(alpha, gamma=None) -> Exponents:
    """The exponents of a problem: an Exponents, a Problem (its ``ex``; read by attribute, as this
    module sits below core.problem), an ``(alpha, gamma)`` pair, or alpha and gamma as parse()
    takes them."""
    if gamma is None:
        if isinstance(alpha, Exponents):
            return alpha
        if isinstance(getattr(alpha, "ex", None), Exponents):
            return alpha.ex
        if isinstance(alpha, tuple) and len(alpha) == 2:
            return Exponents.parse(*alpha)
    return Exponents.parse(alpha, gamma)


def read_through(holder: str, name: str, doc: str | None = None) -> property:
    """A read-only property that reads ``name`` from the attribute ``holder``: the one spelling of
    alpha, gamma and p for a value that holds its exponents (a Problem, a Series, a Material)
    rather than a copy of them.

    Parameters
    ----------
    holder : str
        The attribute that holds the exponents (or the problem), e.g. ``"ex"``.
    name : str
        What to read from it.
    doc : str, optional
        The property's docstring.

    Returns
    -------
    property

    Examples
    --------
    >>> class Pair:
    ...     def __init__(self, ex):
    ...         self.ex = ex
    ...     alpha = read_through("ex", "alpha")
    >>> Pair(Exponents.parse("3/2", 1)).alpha
    Fraction(3, 2)
    """
    return property(lambda self: getattr(getattr(self, holder), name), doc=doc or f"``{holder}.{name}``")

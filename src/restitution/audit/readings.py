"""How the paper's matching procedure can be read: the choices its text leaves open.

The paper (its Sec. V) joins the forward solution x(tau; Omega) and the inverse one
x~(tau~; Omega~) at maximum compression and writes Omega~ = c0 + c1 Omega + c2 Omega^2
(it prints c0 = 6.0203, c1 = -1.5257, c2 = 0.0256). Its text leaves several choices open; each is
a field of :class:`Reading`, and :func:`all_readings` is the documented set we report. The values
a reading matches are in :mod:`restitution.audit.reference_points`, its equations and their
solution in :mod:`restitution.audit.matching`.

This module imports neither sympy nor mpmath, so a configuration check can list the readings'
labels cheaply.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from fractions import Fraction

import numpy as np

from ..core.errors import ParameterError, integer_in

__all__ = ["Reading", "PRINTED_MAX_POWER", "CONVERGED_MAX_POWER", "all_readings", "reading_labels"]

#: The paper prints every series up to tau^11.
PRINTED_MAX_POWER = Fraction(11)
#: "Converged": the series at tau_0 ~ 1.25 (radius pi/sqrt 2 ~ 2.22) change by < 1e-14 beyond this.
CONVERGED_MAX_POWER = Fraction(120)

_TRUNCATIONS = ("printed", "converged")
_DELTAS = ("printed", "linear", "quadratic")
_CONVENTIONS = ("sum", "factorial")


# ----------------------------------------------------------------------------------------- readings
@dataclass(frozen=True)
class Reading:
    """One reading of the paper's (terse) connection procedure.

    truncation
        ``"printed"``: every x_n as printed, up to tau^11 (x0 too). ``"converged"``: x0 from the
        damped-only closed form / first integral, x_n (n >= 1) summed to tau^120 (converged to
        double precision at tau_0 and tau~_0).
    omega_orders
        Highest power of Omega (Omega~) kept in each series: 1 means x0 + Omega x1.
    match_order
        Order in Delta (Delta~) of the Taylor expansion of x (x~) in the matching condition.
    delta
        How Delta, Delta~ follow from x'(tau_b) = 0, x~'(tau~_b) = 0:
        ``"printed"`` the paper's lowest-order formulas Delta = 1 + 2 x1'(tau_0) Omega,
        Delta~ = -1 - (2/3) x~1'(tau~_0) Omega~ (general gamma: same derivation);
        ``"linear"`` x' expanded to first order in Delta with all kept Omega orders, solved exactly;
        ``"quadratic"`` x' expanded to second order in Delta, root nearest the linear one.
    rescale
        False: x(tau_b) = x~(tau~_b) as printed. True: x(tau_b) = s x~(tau~_b) with
        s = eps^(1/(gamma+1)) = (Omega~/Omega)^(1/(alpha-1-2gamma)), the ratio of the two length scales.
    x_tilde_c
        Where the inverse collision starts (x~(0)); the printed series assume 0. A value > 0 replaces
        the inverse series by the Taylor series of the inverse equation about tau~ = 0 from x~_c
        (always converged: nothing of that kind is printed).
    convention
        ``"sum"``: x = sum Omega^n x_n, the paper's Eq. (x), which its printed x_n satisfy.
        ``"factorial"``: x = sum Omega^n x_n / n!, the paper's Eq. (taylor) (the form it introduces
        first), with the printed x_n inserted; this halves x2, divides x3 by 6, x4 by 24.
    """

    truncation: str = "printed"
    omega_orders: int = 1
    match_order: int = 2
    delta: str = "printed"
    rescale: bool = False
    x_tilde_c: float = 0.0
    convention: str = "sum"

    def __post_init__(self):
        if self.convention not in _CONVENTIONS:
            raise ParameterError("convention", self.convention, f"must be one of {_CONVENTIONS}")
        if self.truncation not in _TRUNCATIONS:
            raise ParameterError("truncation", self.truncation, f"must be one of {_TRUNCATIONS}")
        integer_in("omega_orders", self.omega_orders, 1, 8)
        if self.match_order not in (1, 2):
            raise ParameterError("match_order", self.match_order, "must be 1 or 2")
        if self.delta not in _DELTAS:
            raise ParameterError("delta", self.delta, f"must be one of {_DELTAS}")
        if not isinstance(self.rescale, (bool, np.bool_)):
            raise ParameterError("rescale", self.rescale, "must be true or false")
        x = float(self.x_tilde_c)
        if not math.isfinite(x) or not 0.0 <= x < 1.0:
            raise ParameterError("x_tilde_c", self.x_tilde_c,
                                 "must be a number in [0, 1) (the reference point x~ = 1 must lie ahead)")

    @property
    def label(self) -> str:
        """Short stable identifier, e.g. ``P-N1-K2-Dprinted`` (+ ``-S`` rescaled, ``-xc0.85``)."""
        text = f"{self.truncation[0].upper()}-N{self.omega_orders}-K{self.match_order}-D{self.delta}"
        if self.rescale:
            text += "-S"
        if self.x_tilde_c:
            text += f"-xc{self.x_tilde_c:.4g}"
        if self.convention == "factorial":
            text += "-F"
        return text

    def describe(self) -> str:
        """One sentence for the manuscript."""
        trunc = ("series truncated at tau^11 as printed" if self.truncation == "printed"
                 else "converged series (x0 in closed form, x_n to tau^120)")
        if self.x_tilde_c:
            trunc += f"; inverse series started at x~_c = {self.x_tilde_c:.4g} (converged)"
        orders = "x0 + Omega x1" if self.omega_orders == 1 else f"x0 ... Omega^{self.omega_orders} x{self.omega_orders}"
        delta = {"printed": "Delta, Delta~ from the printed lowest-order formulas",
                 "linear": "Delta, Delta~ from x' expanded to first order in Delta, solved exactly",
                 "quadratic": "Delta, Delta~ from x' expanded to second order in Delta"}[self.delta]
        match = f"match expanded to order {self.match_order} in Delta"
        scale = ("match in common physical units, x = eps^(1/(gamma+1)) x~" if self.rescale
                 else "match x = x~ as printed (no change of scale)")
        conv = "" if self.convention == "sum" else " Series read as sum Omega^n x_n / n! (Eq. taylor)."
        return f"{trunc}; {orders} in each series; {delta}; {match}; {scale}.{conv}"


def all_readings(x_tilde_c: float | None = None) -> list[Reading]:
    """The documented set of readings whose c0-c2 we report (see Reading for the fields).

    1. ``P-N1-K2-Dprinted`` (plain): printed series, x0 + Omega x1, the printed Delta formulas, the
       match expanded to second order in Delta ("up to second order"), x = x~ as printed.
    2-3. the same with the Omega^2 terms and with every printed order (Omega^4).
    4-6. 1-3 with converged series instead of the tau^11 truncation.
    7. the match expanded to first order in Delta only.
    8. Delta, Delta~ from x' expanded to first order in Delta with all kept orders, solved exactly.
    9-10. "expand up to second order" applied to x'(tau_b) = 0 as well (printed / converged series).
    11. the series read with factorials, x = sum Omega^n x_n / n! (the paper's Eq. taylor).
    12-13. the change of scale between forward and inverse variables applied at the match.
    14. (only if ``x_tilde_c`` is given) the inverse series started at x~_c instead of 0.
    """
    plain = Reading()
    out = [
        plain,
        replace(plain, omega_orders=2),
        replace(plain, omega_orders=4),
        replace(plain, truncation="converged"),
        replace(plain, truncation="converged", omega_orders=2),
        replace(plain, truncation="converged", omega_orders=4),
        replace(plain, omega_orders=2, match_order=1),
        replace(plain, omega_orders=2, delta="linear"),
        replace(plain, omega_orders=2, delta="quadratic"),
        replace(plain, truncation="converged", omega_orders=2, delta="quadratic"),
        replace(plain, omega_orders=2, convention="factorial"),
        replace(plain, rescale=True),
        replace(plain, truncation="converged", omega_orders=2, rescale=True),
    ]
    if x_tilde_c:
        out.append(replace(plain, truncation="converged", omega_orders=2, x_tilde_c=float(x_tilde_c)))
    return out


#: Suffix of the reading whose inverse series start at x~_c (its label carries the number).
XC_SUFFIX = "-xc"


def reading_labels() -> list[str]:
    """Labels a study may name (the configuration's `readings`): every reading of
    :func:`all_readings`, the one started at x~_c by its suffix alone (its x~_c depends on g)."""
    out = [r.label for r in all_readings(None)]
    out += [r.label.split(XC_SUFFIX)[0] + XC_SUFFIX for r in all_readings(0.5) if r.x_tilde_c]
    return out

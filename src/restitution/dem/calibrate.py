"""The inverse problem: the damping constant D2 that gives a target eps at an impact speed g (or
the least-squares D2 for several (g, eps) pairs), for given exponents, D1 and end rule.

eps grows with Omega (from 0 in the viscous limit to 1 in the elastic one), and Omega falls with D2
like D2^(-(alpha+1)/(gamma+1)); so one pair has one D2, found by bracketing in log Omega over the
reference integrator's verified range and refining with Brent's method. A target the range cannot
reach (eps >= 1: only zero damping gives 1; or below eps at the smallest Omega; or inside the
overlap rule's sticking region, where the bodies never separate) is refused in one line.
"""

from __future__ import annotations

import math
from dataclasses import dataclass


from ..core.collision import OMEGA_RANGE, StickError
from ..core.errors import DerivedRangeError, ParameterError, derived_in_range, real_array, require_positive_finite
from ..core.exponents import as_exponents
from ..core.problem import Problem
from ..core.root import bracketed_root
from .contact import Contact, contact_eps

__all__ = ["calibrate", "Calibrated"]

#: Brent's method on log10 Omega stops at this width: eps moves by about eps * 2.3 * width there,
#: far below the 1e-9 round trip asked of calibrate.
_LOG_OMEGA_XTOL = 1e-13


@dataclass(frozen=True)
class Calibrated:
    """A calibration: the D2 found, the eps recomputed forward at it for every g, and the rms
    residual of eps against the targets (0 up to rounding for one pair).

    Parameters
    ----------
    contact : Contact
        The calibrated contact (its ``D2`` is the answer).
    g, target, eps : tuple of float
        The speeds, the eps asked and the eps the contact gives there.
    residual : float
        Root-mean-square of eps - target.

    Examples
    --------
    >>> from restitution.dem import calibrate
    >>> cal = calibrate("3/2", 1, D1=1e5, eps=0.6, g=0.3)
    >>> round(cal.D2, 3), cal.residual < 1e-12
    (14369.225, True)
    """

    contact: Contact
    g: tuple
    target: tuple
    eps: tuple
    residual: float

    @property
    def D2(self) -> float:
        return self.contact.D2

    def as_dict(self) -> dict:
        single = len(self.g) == 1
        return {"D2": self.D2, "eps": self.eps[0] if single else list(self.eps),
                "g": self.g[0] if single else list(self.g), "target": self.target[0] if single else list(self.target),
                "end": self.contact.end, "residual": self.residual, **{k: v for k, v in self.contact.as_dict().items()
                                                                      if k not in ("D2", "end")}}


def _eps_or_zero(problem, omega: float, rtol: float) -> float:
    try:
        return contact_eps(problem, omega, rtol)
    except StickError:
        return 0.0   # the bodies never separate: the limit of eps from above


def _eps_at(problem, log_omega: float, rtol: float) -> float:
    return _eps_or_zero(problem, 10.0 ** log_omega, rtol)


def _omega_for(problem, target: float, rtol: float) -> float:
    """Omega with eps(Omega) = target: bracketed decade by decade from Omega = 1 (the ends of the
    range are slow to integrate and rarely needed), then Brent's method on log10 Omega."""
    lo, hi = math.log10(OMEGA_RANGE[0]), math.log10(OMEGA_RANGE[1])
    s, e = 0.0, _eps_at(problem, 0.0, rtol)
    step = 1.0 if e < target else -1.0
    while True:
        s_next = min(max(s + step, lo), hi)
        e_next = _eps_at(problem, s_next, rtol)
        if (e_next - target) * (e - target) <= 0.0:
            break
        if s_next in (lo, hi):
            reach = (e_next, 1.0) if step < 0 else (0.0, e_next)
            raise ParameterError("eps", target, f"must be in ({reach[0]:.6g}, {reach[1]:.12g}) for alpha = "
                                                f"{problem.alpha}, gamma = {problem.gamma}, end = {problem.end}: the eps of "
                                                f"Omega in [{OMEGA_RANGE[0]:g}, {OMEGA_RANGE[1]:g}]")
        s, e = s_next, e_next
    a, b = sorted((s, s_next))
    return 10.0 ** bracketed_root(lambda t: _eps_at(problem, t, rtol) - target, a, b, _LOG_OMEGA_XTOL)


def _d2_for(ex, D1: float, g: float, omega: float, target: float) -> float:
    """Omega = D1 g^((alpha-1-2gamma)/(gamma+1)) D2^(-(alpha+1)/(gamma+1)), solved for D2 in logs.
    A D2 beyond doubles is the inputs' doing: the message names them, not D2."""
    a, c = ex.alpha, ex.gamma
    log_d2 = (math.log(D1) + float((a - 1 - 2 * c) / (c + 1)) * math.log(g) - math.log(omega)) * float((c + 1) / (a + 1))
    inputs = {"D1": D1, "g": g, "eps": target}
    if not math.log(1e-300) <= log_d2 <= math.log(1e300):   # Material refuses D2 outside [1e-300, 1e300]
        raise DerivedRangeError("the damping D2", inputs, log_d2 / math.log(10), 1e-300, 1e300)
    return derived_in_range("D2", math.exp(log_d2), inputs, log_d2 / math.log(10))


def calibrate(alpha, gamma, *, D1, eps, g, end: str = "force", rtol: float = 1e-12) -> Calibrated:
    """D2 with eps(g) = ``eps`` for the contact delta'' + D1 delta^alpha + D2 delta^gamma delta' = 0.

    ``eps`` and ``g``: one target at one speed, or equal-length sequences (least squares in eps over
    log D2, the rms residual reported). ``end``: "force" or "overlap". Raises ParameterError (one
    line) for targets outside (0, 1) or beyond the reachable range.

    Parameters
    ----------
    alpha, gamma : str, int, Fraction or float
        The exponents (:meth:`restitution.Exponents.parse`).
    D1 : float
        The elastic constant per unit effective mass (> 0).
    eps : float or sequence of float
        Target coefficient(s) of restitution, in (0, 1).
    g : float or sequence of float
        The impact speed of each target (> 0).
    end : {"force", "overlap"}, optional
        The end-of-contact rule.
    rtol : float, optional
        Tolerance of the integrations behind each eps.

    Returns
    -------
    Calibrated
        ``.D2``, ``.contact``, the eps it gives at each ``g`` and the residual.

    Raises
    ------
    ParameterError
        For targets outside (0, 1), targets no damping reaches, or mismatched ``eps`` and ``g``.

    Examples
    --------
    >>> from restitution.dem import calibrate
    >>> cal = calibrate("3/2", "1/2", D1=1.5e8, eps=0.6, g=1.0, end="overlap")
    >>> round(cal.eps[0], 12)
    0.6
    >>> cal.contact.end
    'overlap'
    """
    ex = as_exponents(alpha, gamma)
    D1 = require_positive_finite("D1", D1)
    gs = real_array("g", g, "must be finite numbers > 0").ravel()
    targets = real_array("eps", eps, "must be numbers in (0, 1)").ravel()
    if gs.size == 0 or gs.size != targets.size:
        raise ParameterError("g", g, f"give one speed per target eps ({targets.size} targets)")
    for v in gs:
        require_positive_finite("g", float(v))
    for t in targets:
        if not 0.0 < t < 1.0:
            raise ParameterError("eps", float(t), "must be in (0, 1): eps = 1 needs zero damping (D2 = 0), "
                                                  "eps = 0 infinite damping")
    end = Contact(ex.alpha, ex.gamma, D1, 1.0, end).end
    d2s = [_d2_for(ex, D1, float(v), _omega_for(Problem(ex, end), float(t), rtol), float(t)) for v, t in zip(gs, targets)]
    if len(d2s) == 1:
        best = d2s[0]
    else:
        from scipy.optimize import minimize_scalar     # here: one target, the common case, does not pay its import

        def misfit(log_d2):
            c = Contact(ex.alpha, ex.gamma, D1, math.exp(log_d2), end)
            return sum((_safe_eps(c, float(v), rtol) - t) ** 2 for v, t in zip(gs, targets))
        lo, hi = math.log(min(d2s)), math.log(max(d2s))
        best = math.exp(minimize_scalar(misfit, bounds=(lo, hi), method="bounded",
                                        options={"xatol": 1e-12 * max(1.0, abs(lo))}).x) if hi > lo else d2s[0]
    contact = Contact(ex.alpha, ex.gamma, D1, best, end)
    forward = tuple(_safe_eps(contact, float(v), rtol) for v in gs)
    residual = math.sqrt(sum((e - t) ** 2 for e, t in zip(forward, targets)) / len(forward))
    return Calibrated(contact, tuple(float(v) for v in gs), tuple(float(t) for t in targets), forward, residual)


def _safe_eps(contact: Contact, g: float, rtol: float) -> float:
    return _eps_or_zero(contact.problem, contact.omega(g), rtol)

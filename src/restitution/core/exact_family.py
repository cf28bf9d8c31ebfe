"""The exact family alpha = 2 gamma + 1: every collision is the linear dashpot's at (gamma+1) Omega.

In the phase plane (v = x' as a function of x) the contact law reads v dv/dx = -Omega x^alpha - x^gamma v.
With S = x^(gamma+1)/(gamma+1), dS = x^gamma dx, and alpha = 2 gamma + 1 (so x^alpha = x^gamma (gamma+1) S),

    v dv/dS = -(gamma+1) Omega S - v,

the linear spring-dashpot (:mod:`restitution.core.dashpot`) at Omega' = (gamma+1) Omega, in the same v.
Its end conditions map too: the zero force Omega x^(alpha-gamma) + v = 0 is Omega' S + v = 0, and
x = 0 is S = 0. Hence, under both end rules,

    eps(2 gamma + 1, gamma; Omega) = eps_dashpot((gamma+1) Omega),   1 - eps likewise,
    x_b, x_c = ((gamma+1) S_b)^(1/(gamma+1)), ((gamma+1) S_c)^(1/(gamma+1)),

and under the overlap rule the bodies stick exactly where the dashpot is overdamped or critical,
Omega <= 1/(4 (gamma+1)), whatever the impact speed (an overdamped dashpot never returns to S = 0).
(gamma = 0 is the dashpot itself; (3/2, 1/4) is Hertz with delta^(1/4) damping, LAMMPS' tsuji and
coeff_restitution and LIGGGHTS' hertz.)

Time is not mapped identically: dtau = dx / v = dT / x^gamma with T the dashpot's time, so

    tau = (gamma+1)^(-a) integral_0^T S(T')^(-a) dT',   a = gamma/(gamma+1) < 1,

over the dashpot's closed-form S(T) = e^(-T/2) s(T), s = sin(wT)/w, sinh(wT)/w or T
(w = sqrt|Omega' - 1/4|). The integrand is singular (integrably) where S vanishes: at T = 0, and
at the half period T0 = pi/w of an underdamped dashpot, which the overlap rule reaches and the force
rule nears for large Omega. Near each zero, T = u^(gamma+1) (resp. T0 - T = u^(gamma+1)) removes the
singularity exactly: T^(-a) dT = (gamma+1) du. What is left, (gamma+1) (T/S)^a, is bounded and
smooth in u, and adaptive Gauss-Legendre quadrature (24 against 48 points, halving) integrates it
at a requested 1.2e-14 (within 2.3e-15 of scipy's quad, which served before, over gamma = 1/4, 1/3, 1,
7/5, both end rules and Omega 1e-6 to 1e10; numpy only, whose import is a tenth of scipy's).
Measured against mpmath
(its Taylor integrator of the original equation at 25 digits, and its tanh-sinh quadrature of the
integral at 30): tau_b and tau_c within 5e-15 relative for gamma = 1/4, 1/3, 1, 7/5, Omega 1e-6 to
1e10 and 1.01 times the sticking threshold (where tau_c reaches 2e8), both end rules (with quad);
the test suite holds this quadrature's to 3e-14 (tests/library/test_exact_family.py).

Accuracy of eps: it is exp(-T_c/2) with T_c from the dashpot's cancellation-free forms, so its
relative error is a few rounding errors times (1 + ln(1/eps)) (the absolute error of T_c/2 is a
few ulp of T_c/2 = ln(1/eps)): :func:`eps_bound`. (gamma+1) Omega and (gamma+1) Omega - 1/4 are
formed in exact rational arithmetic, because the overlap rule's half period pi/sqrt(Omega' - 1/4)
would turn one rounding of Omega' into an unbounded relative error near the sticking threshold.
"""

from __future__ import annotations

import math
import sys
from dataclasses import replace
from fractions import Fraction
from functools import lru_cache

import numpy as np

from .collision import IntegrationError, UnresolvedError
from .sticking import StickError, stick_bound, stick_reason
from .dashpot import contact_times, dashpot_collision
from .errors import ParameterError, require_positive_finite
from .exponents import Exponents, as_exponents
from .results import Collision
from .problem import Problem, as_problem

__all__ = ["in_family", "sticking_threshold", "exact_collision", "exact_eps", "eps_bound", "EPS_ULPS",
           "LOSS_ULPS", "TIME_RTOL"]

#: Unit roundoff of a double (2^-53).
_U = sys.float_info.epsilon / 2
#: Relative error of eps is at most EPS_ULPS u (1 + ln(1/eps)); of 1 - eps at most LOSS_ULPS u.
#: The largest errors measured against mpmath (tests/library/test_exact_family.py, Omega 1e-300
#: to 1e300 and near the sticking threshold, six gammas) were a quarter of the first, 0.4 of the second.
EPS_ULPS = 8.0
LOSS_ULPS = 8.0
#: quad's requested relative tolerance for tau_b and tau_c (its floor is 50 machine epsilon).
TIME_RTOL = 1.2e-14
#: ln of the smallest normal double: eps = exp(-T_c/2) below it is not resolved.
_LOG_TINY = -math.log(sys.float_info.min)


def in_family(problem) -> bool:
    """Whether alpha = 2 gamma + 1, the family whose collisions are the linear dashpot's.

    Parameters
    ----------
    problem
        A Problem, an Exponents or an (alpha, gamma) pair (anything
        :func:`restitution.core.exponents.as_exponents` accepts).

    Returns
    -------
    bool
        True for alpha = 2 gamma + 1 exactly (rational arithmetic).

    Examples
    --------
    >>> in_family(("3/2", "1/4")), in_family((1, 0)), in_family(("3/2", "1/2"))
    (True, True, False)
    """
    ex = as_exponents(problem)
    return ex.alpha == 2 * ex.gamma + 1


def _family(ex: Exponents) -> Exponents:
    if ex.alpha != 2 * ex.gamma + 1:
        raise ParameterError("alpha", str(ex.alpha), f"must be 2 gamma + 1 = {2 * ex.gamma + 1} for the exact "
                                                     "family (restitution.core.exact_family)")
    return ex


def sticking_threshold(problem) -> Fraction:
    """The Omega at or below which the bodies never separate under the overlap rule: 1/(4 (gamma+1)).

    There the equivalent dashpot, at (gamma+1) Omega <= 1/4, is overdamped or critical and never
    returns to S = 0; above it, it always does. The threshold does not depend on the impact speed.

    Parameters
    ----------
    problem
        A Problem (its end rule applies), an Exponents or an (alpha, gamma) pair, with
        alpha = 2 gamma + 1.

    Returns
    -------
    Fraction
        1/(4 (gamma+1)), exact.

    Raises
    ------
    ParameterError
        If alpha != 2 gamma + 1.

    Examples
    --------
    >>> sticking_threshold(("3/2", "1/4"))
    Fraction(1, 5)
    >>> sticking_threshold((1, 0))
    Fraction(1, 4)
    """
    ex = _family(as_exponents(problem))
    return Fraction(1, 4) / (ex.gamma + 1)


#: Below this Omega' the overlap rule's half period is ill-conditioned enough in Omega' - 1/4 that
#: Omega' and the excess are formed exactly (tens of microseconds); above, one rounding is harmless.
_EXACT_BELOW = 0.5


def _scaled(ex: Exponents, omega: float, rule: str) -> tuple[float, float]:
    """(Omega', Omega' - 1/4) for Omega' = (gamma+1) Omega: under the overlap rule and below
    _EXACT_BELOW (near its sticking threshold) each rounded once from exact rationals; otherwise a
    product of doubles (the force rule's eps is well conditioned in Omega' everywhere)."""
    wp = float(ex.gamma + 1) * omega
    if wp >= _EXACT_BELOW or rule != "overlap":
        return wp, wp - 0.25
    exact = (ex.gamma + 1) * Fraction(omega)
    return float(exact), float(exact - Fraction(1, 4))


def _eps_bound(eps: float) -> float:
    if not eps >= sys.float_info.min:
        return math.inf
    return EPS_ULPS * _U * (1.0 - math.log(eps))


def eps_bound(eps) -> np.ndarray:
    """The stated relative error bound of the exact family's eps: EPS_ULPS u (1 + ln(1/eps)).

    eps = exp(-T_c/2) carries the absolute error of T_c/2 = ln(1/eps) as a relative one, and T_c
    is accurate to a few rounding errors; the rounding of exp itself is the 1.

    Parameters
    ----------
    eps : float or array_like
        Values of eps in (0, 1] (as computed).

    Returns
    -------
    numpy.ndarray
        The bound for each eps (inf where eps is 0 or below the smallest normal double).

    Examples
    --------
    >>> float(eps_bound(1.0)) < 2e-15, float(eps_bound(1e-100)) < 1e-12
    (True, True)
    """
    e = np.asarray(eps, dtype=float)
    return np.array([_eps_bound(float(x)) for x in e.ravel()]).reshape(e.shape)


def exact_eps(problem: Problem, omega) -> np.ndarray:
    """eps of the family alpha = 2 gamma + 1 at each Omega, from the dashpot at (gamma+1) Omega.

    Parameters
    ----------
    problem : Problem
        The exponents, with alpha = 2 gamma + 1, and the end-of-contact rule
        (restitution.core.results.END_RULES).
    omega : float or array_like
        Omega > 0, finite.

    Returns
    -------
    numpy.ndarray
        eps, shaped like ``omega``; relative error within :func:`eps_bound`.

    Raises
    ------
    ParameterError
        If alpha != 2 gamma + 1 or an Omega is not finite and > 0.
    StickError
        Under the overlap rule at Omega <= 1/(4 (gamma+1)) (the bodies stick).
    UnresolvedError
        Under the overlap rule just above that threshold, where eps is below the smallest normal double.

    Examples
    --------
    >>> from restitution.core.dashpot import dashpot_collision
    >>> from restitution.core.problem import Problem
    >>> e = exact_eps(Problem.of("2", "1/2"), [0.3, 2.0])
    >>> bool(e[1] == dashpot_collision(3.0).eps)
    True
    >>> family = Problem.of("3/2", "1/4")
    >>> float(exact_eps(family.with_end("overlap"), 0.3)) < float(exact_eps(family, 0.3))
    True
    """
    problem = as_problem(problem)
    ex = _family(problem.ex)
    rule = problem.end
    om = np.asarray(omega, dtype=float)
    # the dashpot's contact time directly (exact_collision's eps bit for bit, without its dataclass)
    out = [math.exp(-0.5 * _dashpot_tau_c(ex, require_positive_finite("omega", float(w)), rule)) for w in om.ravel()]
    return np.array(out).reshape(om.shape)


def _dashpot_tau_c(ex: Exponents, omega: float, rule: str) -> float:
    """The equivalent dashpot's T_c, refusing where the bodies stick or eps underflows."""
    wp, z = _scaled(ex, omega, rule)
    if rule == "overlap":
        # at or below the threshold, or at the double nearest it (so "0.2" for 1/5 refuses, as the
        # ladder's core.collision.stick_bound does, though that double lies 1e-17 above 1/5)
        if not z > 0 or omega <= stick_bound(ex):
            raise StickError.at(omega, stick_reason(ex))
        t_c = math.pi / math.sqrt(z)
    else:
        t_c = contact_times(wp)[1]
    if 0.5 * t_c > _LOG_TINY:
        raise UnresolvedError("omega", omega, f"eps = exp(-{0.5 * t_c:.6g}) lies below the smallest normal double: "
                                              "Omega is this close above the overlap rule's sticking threshold "
                                              f"{float(sticking_threshold(ex)):.6g}")
    return t_c


def exact_collision(problem: Problem, omega, *, times: bool = True) -> Collision:
    """The forward collision of the family alpha = 2 gamma + 1 in closed form (tau by quadrature).

    eps and 1 - eps (no cancellation) are the dashpot's at (gamma+1) Omega; x_b and x_c its S_b and
    S_c mapped back; tau_b and tau_c the integral of the module docstring (scipy.integrate.quad,
    relative accuracy about 1e-14).

    Parameters
    ----------
    problem : Problem
        The exponents, with alpha = 2 gamma + 1 (any rational gamma >= 0 the library accepts),
        and the end-of-contact rule.
    omega : float
        Omega > 0, finite (no range limit: nothing is integrated in time).
    times : bool
        False skips the two quadratures (tau_b and tau_c are then NaN): eps alone costs microseconds.

    Returns
    -------
    Collision
        As :func:`restitution.core.collision.collide` returns, with ``rtol`` 0.0 (nothing
        integrated in time), ``error_bound`` from :func:`eps_bound` and ``one_minus_eps_bound``
        LOSS_ULPS u.

    Raises
    ------
    ParameterError
        If alpha != 2 gamma + 1, or Omega is not finite and > 0.
    StickError
        Under the overlap rule at Omega <= 1/(4 (gamma+1)) (or the double nearest it).
    UnresolvedError
        Under the overlap rule so close above the threshold that eps = exp(-pi/(2 sqrt(Omega' - 1/4)))
        is below the smallest normal double (within about 2e-5 relative of it).

    Examples
    --------
    >>> from restitution.core.problem import Problem
    >>> family = Problem.of("3/2", "1/4")
    >>> c = exact_collision(family, 0.7)
    >>> round(c.eps, 12), round(c.tau_c, 10), c.ended_by
    (0.279827939466, 2.972394226, 'force')
    >>> exact_collision(family.with_end("overlap"), 0.7).ended_by
    'separation'
    >>> exact_collision(family.with_end("overlap"), 0.2)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    restitution.core.sticking.StickError: omega = 0.2: under the overlap rule contact never ends here: ...
    """
    problem = as_problem(problem)
    ex = _family(problem.ex)
    omega = require_positive_finite("omega", omega)
    rule = problem.end
    _dashpot_tau_c(ex, omega, rule)     # refuses a sticking or an eps below doubles first
    wp, z = _scaled(ex, omega, rule)
    d = dashpot_collision(wp, rule, excess=z)
    k = float(ex.gamma + 1)
    fields = dict(problem=problem, omega=omega, error_bound=_eps_bound(d.eps),
                  one_minus_eps_bound=LOSS_ULPS * _U)
    if ex.gamma == 0:
        return replace(d, **fields)
    if times:
        tau_b = _tau(ex, wp, z, d.tau_b, None)
        # the overlap rule ends at the half period; the force rule before it, T0 - T_c computed
        # without cancellation: w T_c = atan2(w, 1/2 - Omega'), so pi - w T_c = atan2(w, Omega' - 1/2)
        if z > 0:
            w = math.sqrt(z)
            to_zero = 0.0 if rule == "overlap" else math.atan2(w, z - 0.25) / w
        else:
            to_zero = None
        tau_c = _tau(ex, wp, z, d.tau_c, to_zero)
    else:
        tau_b = tau_c = math.nan
    return replace(d, tau_b=tau_b, tau_c=tau_c, x_b=(k * d.x_b) ** (1.0 / k), x_c=(k * d.x_c) ** (1.0 / k),
                   **fields)


@lru_cache(maxsize=2)
def _legendre(n: int) -> tuple:
    nodes, weights = np.polynomial.legendre.leggauss(n)
    return tuple(map(float, nodes)), tuple(map(float, weights))


def _gauss(f, lo: float, hi: float, n: int) -> float:
    nodes, weights = _legendre(n)
    mid, half = 0.5 * (hi + lo), 0.5 * (hi - lo)
    return half * math.fsum(w * f(mid + half * x) for x, w in zip(nodes, weights))


#: Halvings of an interval before :func:`_gauss_adaptive` gives up (2^-40 of it: far below any
#: smooth integrand's need, so reaching it means the integrand is not smooth there)
_MAX_HALVINGS = 40


def _gauss_adaptive(f, lo: float, hi: float, rtol: float, depth: int = 0) -> float:
    """The integral of a smooth positive f over [lo, hi]: Gauss-Legendre of 24 and 48 points, the
    interval halved where they differ by more than rtol of the larger (the 24-point rule's error;
    the 48-point one's is far below). Positive f: each half's relative error bounds the whole's.
    An interval still unresolved after _MAX_HALVINGS halvings raises IntegrationError: a time
    stated to TIME_RTOL must meet it, never return what it reached there."""
    coarse, fine = _gauss(f, lo, hi, 24), _gauss(f, lo, hi, 48)
    if abs(fine - coarse) <= rtol * abs(fine):
        return fine
    if depth >= _MAX_HALVINGS:
        raise IntegrationError(f"the contact time's quadrature did not reach rtol {rtol:g} on [{lo!r}, {hi!r}] "
                               f"after {_MAX_HALVINGS} halvings (its two rules differ by "
                               f"{abs(fine - coarse) / abs(fine) if fine else math.inf:.3g})")
    mid = 0.5 * (lo + hi)
    return _gauss_adaptive(f, lo, mid, rtol, depth + 1) + _gauss_adaptive(f, mid, hi, rtol, depth + 1)


def _tau(ex: Exponents, wp: float, z: float, t_end: float, to_zero: float | None) -> float:
    """The contact's time at the dashpot's time t_end: (gamma+1)^(-a) integral_0^t_end S^(-a) dT.

    ``to_zero``: T0 - t_end, the dashpot's time left to its half period T0 = pi/w (underdamped
    only; None otherwise). Below T0/2 the integral runs in u = T^(1/(gamma+1)), above it in
    u = (T0 - T)^(1/(gamma+1)): each removes the T^(-a) singularity at its end exactly.
    """
    k = float(ex.gamma + 1)
    a = float(ex.gamma / (ex.gamma + 1))
    w = math.sqrt(abs(z))
    under = z > 0

    def ratio(y: float) -> float:
        """log of y/sin(y), y/sinh(y) (w T = y), or 0 at critical damping."""
        if not y:
            return 0.0
        if under:
            return math.log(y / math.sin(y))
        if z == 0:
            return 0.0
        if y < 20.0:
            return math.log(y / math.sinh(y))
        return math.log(2.0 * y) - y - math.log1p(-math.exp(-2.0 * y))

    def left(u: float) -> float:        # T = u^k: k (T/S(T))^a, S = e^(-T/2) s(T)
        t = u ** k
        if under or z == 0:
            return k * math.exp(a * (0.5 * t + ratio(w * t)))
        # overdamped: T/2 - wT = T Omega'/(1/2 + w) without cancellation
        y = w * t
        if y < 20.0:
            return k * math.exp(a * (0.5 * t + ratio(y)))
        return k * math.exp(a * (t * wp / (0.5 + w) + math.log(2.0 * y) - math.log1p(-math.exp(-2.0 * y))))

    def right(u: float) -> float:       # T0 - T = u^k = phi: k (phi/S(T))^a, s(T) = sin(w phi)/w
        phi = u ** k
        return k * math.exp(a * (0.5 * (math.pi / w - phi) + ratio(w * phi)))

    def integral(f, lo: float, hi: float) -> float:
        return _gauss_adaptive(f, lo, hi, TIME_RTOL) if hi > lo else 0.0

    scale = k ** (-a)
    if to_zero is None or to_zero >= 0.5 * math.pi / w:
        return scale * integral(left, 0.0, t_end ** (1.0 / k))
    half = (0.5 * math.pi / w) ** (1.0 / k)
    return scale * (integral(left, 0.0, half) + integral(right, to_zero ** (1.0 / k), half))

"""The exact connection of the forward and inverse collisions: Omega~ as a function of Omega.

The rebound speed g~ = eps g put into the definition of Omega gives the true
Omega~(Omega) = Omega eps^((alpha-1-2gamma)/(gamma+1)); the paper approximates it by
Omega~ = c0 + c1 Omega + c2 Omega^2. Here: that exact relation from the reference integrator
(:func:`exact_omega_tilde`), c0-c2 fitted to it by least squares (:func:`fit_connection`), eps from
any such c's and where they give no eps or eps > 1 (:func:`eps_from_connection`,
:func:`connection_validity`), and :func:`retrace`: the inverse collision started from the forward
end state, mapped back to forward variables, must reproduce the forward trajectory (a check of the
exact connection and of the variable change between the two scalings).

The paper's own procedure for c0-c2 is the audit's (:mod:`restitution.audit.matching`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import ParameterError, require_positive_finite
from .exponents import as_exponents

__all__ = ["FitResult", "RetraceResult", "rebound_omega", "rebound_start", "exact_omega_tilde", "fit_connection", "fit_quadratic",
           "eps_from_connection", "omega_tilde_from_c", "connection_validity", "retrace"]

def rebound_omega(ex, omega, eps):
    """Omega~ = Omega eps^((alpha-1-2gamma)/(gamma+1)): Omega with the rebound speed eps g for g.

    Parameters
    ----------
    ex : Exponents
        alpha and gamma.
    omega : float or numpy.ndarray
        The forward collision's Omega.
    eps : float or numpy.ndarray
        Its coefficient of restitution.

    Returns
    -------
    float or numpy.ndarray
        Omega~.

    Examples
    --------
    >>> from restitution.core.exponents import as_exponents
    >>> round(rebound_omega(as_exponents(("3/2", "1")), 1.0, 0.5), 6)      # 0.5^(-3/4)
    1.681793
    """
    return omega * eps ** float(ex.omega_exponent)


def rebound_start(ex, x_c, eps):
    """x~_c = x_c eps^(-1/(gamma+1)): the end of contact in the inverse collision's own variables.

    Parameters
    ----------
    ex : Exponents
        alpha and gamma.
    x_c : float
        Where the forward contact ended, in its variables.
    eps : float
        The forward collision's coefficient of restitution.

    Returns
    -------
    float
        x~_c.

    Examples
    --------
    >>> from restitution.core.exponents import as_exponents
    >>> round(rebound_start(as_exponents(("3/2", "1")), 0.3, 0.5), 6)      # 0.3 / sqrt(0.5)
    0.424264
    """
    return x_c * eps ** (-1.0 / float(ex.gamma + 1))


def exact_omega_tilde(problem, omegas, *, rtol: float = 1e-12) -> dict:
    """The true connection from the reference integrator.

    Omega~ = Omega eps^((alpha-1-2gamma)/(gamma+1)) (the rebound speed g~ = eps g put into the
    definition of Omega). Also returns eps, x_c and x~_c = x_c eps^(-1/(gamma+1)), the start of the
    inverse collision in its own variables.

    Parameters
    ----------
    problem : Problem or tuple
        The exponents (an Exponents or an (alpha, gamma) pair).
    omegas : array_like
        Forward Omegas.
    rtol : float, optional
        The reference integrator's tolerance.

    Returns
    -------
    dict
        {"omega", "omega_tilde", "eps", "x_c", "x_tilde_c", "tau_b", "x_b", "tau_c", "ended_by"},
        arrays over ``omegas``.

    Examples
    --------
    >>> e = exact_omega_tilde(("3/2", "1"), [1.0])
    >>> round(float(e["eps"][0]), 6), round(float(e["omega_tilde"][0]), 6)
    (0.499731, 1.682471)
    """
    from .collision import collide_many

    ex = as_exponents(problem)
    omegas = np.asarray(omegas, dtype=float)
    res = collide_many(ex, omegas, rtol=rtol)
    eps = res["eps"]
    return {"omega": omegas, "omega_tilde": rebound_omega(ex, omegas, eps), "eps": eps, "x_c": res["x_c"],
            "x_tilde_c": rebound_start(ex, res["x_c"], eps), "tau_b": res["tau_b"],
            "x_b": res["x_b"], "tau_c": res["tau_c"], "ended_by": res["ended_by"]}


@dataclass(frozen=True)
class FitResult:
    """Least-squares fit Omega~ ~ c0 + c1 Omega + c2 Omega^2 to the exact connection.

    The residuals are model error (a quadratic cannot follow Omega~(Omega) exactly), not noise;
    ``stderr`` is the usual OLS estimate sqrt(diag(s^2 (X^T X)^-1)), s^2 = RSS/(n - 3), and says how
    strongly the coefficients depend on that misfit, not a statistical uncertainty.
    ``max_abs_residual`` bounds |Omega~_exact - fit| over the sampled Omegas.

    Parameters
    ----------
    c, stderr : tuple of float
        c0-c2 and their standard errors.
    covariance : numpy.ndarray
        The 3 x 3 covariance the standard errors come from.
    omega, omega_tilde, residuals : numpy.ndarray
        The points fitted and the fit's misfit at each.
    max_abs_residual, rms, max_rel_residual : float
        The largest, root-mean-square and largest relative misfit.

    Examples
    --------
    >>> import numpy as np
    >>> x = np.linspace(1.0, 4.0, 5)
    >>> fit = fit_quadratic(x, 1.0 + 2.0 * x + 3.0 * x ** 2 + 0.01 * np.cos(x))
    >>> sorted(fit.as_dict())[:3], fit.max_abs_residual < 0.01
    (['c', 'max_abs_residual', 'max_rel_residual'], True)
    """

    c: tuple
    covariance: np.ndarray
    stderr: tuple
    omega: np.ndarray
    omega_tilde: np.ndarray
    residuals: np.ndarray
    max_abs_residual: float
    rms: float
    max_rel_residual: float

    def as_dict(self) -> dict:
        return {"c": list(self.c), "stderr": list(self.stderr),
                "omega_min": float(self.omega.min()), "omega_max": float(self.omega.max()),
                "n": int(self.omega.size), "max_abs_residual": self.max_abs_residual, "rms": self.rms,
                "max_rel_residual": self.max_rel_residual}


def fit_quadratic(omegas, omega_tilde) -> FitResult:
    """OLS fit of omega_tilde on [1, Omega, Omega^2] (see FitResult).

    Parameters
    ----------
    omegas, omega_tilde : array_like
        The points, at least 4.

    Returns
    -------
    FitResult

    Raises
    ------
    ParameterError
        With fewer than 4 points.

    Examples
    --------
    >>> import numpy as np
    >>> x = np.linspace(1.0, 4.0, 5)
    >>> [round(c, 9) for c in fit_quadratic(x, 1.0 + 2.0 * x + 3.0 * x ** 2).c]
    [1.0, 2.0, 3.0]
    """
    x = np.asarray(omegas, float)
    y = np.asarray(omega_tilde, float)
    if x.size < 4:
        raise ParameterError("omegas", x.size, "need at least 4 points for a 3-parameter fit")
    X = np.vander(x, 3, increasing=True)
    c, *_ = np.linalg.lstsq(X, y, rcond=None)
    resid = y - X @ c
    s2 = float(resid @ resid) / (x.size - 3)
    cov = s2 * np.linalg.inv(X.T @ X)
    return FitResult(tuple(float(v) for v in c), cov, tuple(float(v) for v in np.sqrt(np.diag(cov))),
                     x, y, resid, float(np.max(np.abs(resid))), float(np.sqrt(np.mean(resid ** 2))),
                     float(np.max(np.abs(resid / y))))


def fit_connection(problem, omegas, *, rtol: float = 1e-12) -> FitResult:
    """Fit c0-c2 to the exact Omega~(Omega) at the given Omegas (>= 4 of them).

    Parameters
    ----------
    problem, omegas, rtol
        As :func:`exact_omega_tilde` takes them; at least 4 Omegas.

    Returns
    -------
    FitResult
        :func:`fit_quadratic`'s, of the exact Omega~ at these Omegas.

    Raises
    ------
    ParameterError
        With fewer than 4 Omegas.

    Examples
    --------
    >>> import numpy as np
    >>> fit = fit_connection(("3/2", "1"), np.linspace(0.5, 2.0, 6))
    >>> [round(c, 4) for c in fit.c], fit.max_abs_residual < 5e-3
    ([0.5335, 1.1812, -0.034], True)
    """
    exact = exact_omega_tilde(problem, omegas, rtol=rtol)
    return fit_quadratic(exact["omega"], exact["omega_tilde"])


def omega_tilde_from_c(omega, c) -> np.ndarray:
    """c0 + c1 Omega + c2 Omega^2 (+ ...) for a sequence of coefficients c.

    Parameters
    ----------
    omega : array_like
        Omegas.
    c : sequence of float
        c0, c1, c2, ...

    Returns
    -------
    numpy.ndarray

    Examples
    --------
    >>> omega_tilde_from_c([0.0, 1.0, 2.0], (1.0, 2.0, 3.0))
    array([ 1.,  6., 17.])
    """
    omega = np.asarray(omega, float)
    return sum(float(ci) * omega ** i for i, ci in enumerate(c))


def eps_from_connection(problem, omega, c):
    """eps = (Omega~/Omega)^((gamma+1)/(alpha-1-2gamma)) with Omega~ = c0 + c1 Omega + c2 Omega^2.

    Undefined (ParameterError) when alpha - 1 - 2 gamma = 0: then Omega~ = Omega whatever eps is.
    NaN where Omega~ <= 0 (no real eps). Values above 1 are returned as computed: they are
    unphysical (the rebound would be faster than the impact: energy gained from a dissipative
    force) and flag where the relation fails. With k = alpha - 1 - 2gamma, eps > 1 exactly where
    Omega~ < Omega for k < 0 (the paper's case, k = -1/2) and where Omega~ > Omega for k > 0;
    :func:`connection_validity` gives those Omega intervals for a set of c's.

    Parameters
    ----------
    problem : Problem or tuple
        The exponents.
    omega : float or array_like
        Omegas.
    c : sequence of float
        c0, c1, c2, ...

    Returns
    -------
    float or numpy.ndarray
        eps (a float for a scalar Omega).

    Raises
    ------
    ParameterError
        Where alpha - 1 - 2 gamma = 0.

    Examples
    --------
    >>> import numpy as np
    >>> c = fit_connection(("3/2", "1"), np.linspace(0.5, 2.0, 6)).c
    >>> round(float(eps_from_connection(("3/2", "1"), 1.0, c)), 3)    # the exact eps is 0.4997
    0.5
    """
    ex = as_exponents(problem)
    k = ex.omega_exponent
    if k == 0:
        raise ParameterError("alpha, gamma", f"{ex.alpha}, {ex.gamma}",
                             "eps from the connection needs alpha - 1 - 2 gamma != 0 (otherwise "
                             "Omega~ = Omega for every eps)")
    omega = np.asarray(omega, float)
    wt = omega_tilde_from_c(omega, c)
    with np.errstate(invalid="ignore", divide="ignore"):
        out = np.where((wt > 0) & (omega > 0), (wt / omega) ** (1.0 / float(k)), np.nan)
    return float(out) if out.ndim == 0 else out


def connection_validity(problem, c) -> dict:
    """Omega > 0 intervals where Omega~ = sum c_i Omega^i gives no eps (Omega~ <= 0) or eps > 1.

    Returns {"omega_tilde_nonpositive": [(lo, hi), ...], "eps_above_one": [(lo, hi), ...]}, from the
    real positive roots of the polynomials (hi = inf for an unbounded interval).

    Parameters
    ----------
    problem : Problem or tuple
        The exponents.
    c : sequence of float
        c0, c1, c2, ...

    Returns
    -------
    dict
        {"omega_tilde_nonpositive": intervals, "eps_above_one": intervals}.

    Raises
    ------
    ParameterError
        As :func:`eps_from_connection` does (alpha - 1 - 2 gamma = 0).

    Examples
    --------
    The paper's printed c0-c2 give no eps for Omega in about (4.25, 55.3):

    >>> v = connection_validity(("3/2", "1"), (6.0203, -1.5257, 0.0256))
    >>> [(round(lo, 2), round(hi, 2)) for lo, hi in v["omega_tilde_nonpositive"]]
    [(4.25, 55.35)]
    """
    ex = as_exponents(problem)
    k = ex.omega_exponent
    if k == 0:
        raise ParameterError("alpha, gamma", f"{ex.alpha}, {ex.gamma}",
                             "needs alpha - 1 - 2 gamma != 0")
    c = [float(v) for v in c]

    def intervals(poly, bad):
        roots = sorted(r.real for r in np.roots(poly[::-1]) if abs(r.imag) < 1e-12 and r.real > 0) \
            if any(poly[1:]) else []
        edges = [0.0] + roots + [math.inf]
        out = []
        for lo, hi in zip(edges[:-1], edges[1:]):
            mid = 0.5 * (lo + hi) if math.isfinite(hi) else lo + 1.0
            if bad(sum(ci * mid ** i for i, ci in enumerate(poly))):
                out.append((lo, hi))
        return out

    nonpos = intervals(c, lambda v: v <= 0)
    minus = list(c) + [0.0] * max(0, 2 - len(c))
    minus[1] -= 1.0  # Omega~ - Omega
    above = intervals(minus, (lambda v: v < 0) if k < 0 else (lambda v: v > 0))
    # eps > 1 only counts where eps exists: subtract the Omega~ <= 0 intervals
    for a, b in nonpos:
        pieces = []
        for lo, hi in above:
            if hi <= a or lo >= b:
                pieces.append((lo, hi))
                continue
            if lo < a:
                pieces.append((lo, a))
            if hi > b:
                pieces.append((b, hi))
        above = pieces
    as_float = lambda iv: [(float(lo), float(hi)) for lo, hi in iv]  # noqa: E731
    return {"omega_tilde_nonpositive": as_float(nonpos), "eps_above_one": as_float(above)}


# ------------------------------------------------------------------------------------------ retrace
@dataclass(frozen=True)
class RetraceResult:
    """The inverse collision from the forward end state, mapped back onto the forward one.

    ``max_deviation`` = max |x_retraced - x_forward| / x_b over ``tau`` (forward variables);
    ``v_end_error`` = |eps x~'(end) + 1|: the inverse run must arrive with x' = 1 in forward variables;
    ``tau_error`` = |tau_c - s^-gamma tau~_end|: and at forward time 0.

    Parameters
    ----------
    omega, omega_tilde, eps : float
        The forward Omega, the inverse one and the forward eps.
    x_tilde_start : float
        Where the inverse collision starts, in its variables.
    tau, x_forward, x_retraced : numpy.ndarray
        The forward times compared and both trajectories there.
    max_deviation, v_end_error, tau_error : float
        As above.

    Examples
    --------
    >>> r = retrace(("3/2", "1"), 1.0, samples=21)
    >>> r.tau.size <= 21, round(r.omega_tilde, 6)
    (True, 1.682471)
    """

    omega: float
    omega_tilde: float
    eps: float
    x_tilde_start: float
    tau: np.ndarray
    x_forward: np.ndarray
    x_retraced: np.ndarray
    max_deviation: float
    v_end_error: float
    tau_error: float


def retrace(problem, omega, *, rtol: float = 1e-12, samples: int = 201) -> RetraceResult:
    """Integrate the inverse collision from the forward end state and compare trajectories.

    Change of variables (derived from the physical scaling xi = A x, t = B tau with
    A = (g/D2)^(1/(gamma+1)), B = (D2 g^gamma)^(-1/(gamma+1)) and the inverse collision scaled with
    the rebound speed g~ = eps g): A~/A = eps^(1/(gamma+1)) =: s, B~/B = eps^(-gamma/(gamma+1)) = s^-gamma,
    and the inverse time runs backwards from t_c. Hence

        x = s x~,   tau = tau_c - s^(-gamma) tau~,   dx/dtau = -eps dx~/dtau~,

    and x'' + Omega x^alpha + x^gamma x' = 0 becomes x~'' + Omega s^(alpha-1-2gamma) x~^alpha - x~^gamma x~' = 0:
    Omega~ = Omega eps^((alpha-1-2gamma)/(gamma+1)), x~(0) = x_c / s, x~'(0) = 1.

    Parameters
    ----------
    problem : Problem or tuple
        The exponents.
    omega : float
        The forward Omega.
    rtol : float, optional
        The integrators' tolerance.
    samples : int, optional
        How many forward times the two trajectories are compared at.

    Returns
    -------
    RetraceResult

    Raises
    ------
    ParameterError
        Where omega is not a finite number > 0.

    Examples
    --------
    >>> r = retrace(("3/2", "1"), 1.0)
    >>> r.max_deviation < 1e-8, r.v_end_error < 1e-8
    (True, True)
    """
    from .collision import collide, inverse_collide

    ex = as_exponents(problem)
    omega = require_positive_finite("omega", omega)
    fwd = collide(ex, omega, rtol=rtol)
    gp1 = float(ex.gamma + 1)
    s = fwd.eps ** (1.0 / gp1)
    omega_t = rebound_omega(ex, omega, fwd.eps)
    x_start = fwd.x_c / s
    # common samples strictly inside the contact, forward time
    tau = np.linspace(0.0, fwd.tau_c, samples)
    tau_t = (fwd.tau_c - tau) * s ** float(ex.gamma)  # decreasing in tau
    order = np.argsort(tau_t)
    inv = inverse_collide(ex, omega_t, x_start, rtol=rtol, t_eval=tau_t[order])
    fwd_traj = collide(ex, omega, rtol=rtol, t_eval=tau).trajectory
    x_fwd = np.full(tau.shape, np.nan)
    x_fwd[: fwd_traj.x.size] = fwd_traj.x
    x_ret = np.full(tau.shape, np.nan)
    n = inv.trajectory.x.size
    x_ret[order[:n]] = s * inv.trajectory.x
    # a sample at either end may fall a rounding error beyond the end of a run: compare the rest
    ok = np.isfinite(x_ret) & np.isfinite(x_fwd)
    dev = np.abs(x_ret[ok] - x_fwd[ok]) / fwd.x_b
    return RetraceResult(omega, omega_t, fwd.eps, x_start, tau[ok], x_fwd[ok], x_ret[ok],
                         float(dev.max()), abs(fwd.eps * inv.v_end + 1.0),
                         abs(fwd.tau_c - s ** (-float(ex.gamma)) * inv.tau_end))

"""The numbers of the claims ledger (:mod:`restitution.audit.claims`), computed with the library:
series against the printed ones, where the series stop tracking the reference, the reference
points and Delta's of the paper's procedure, c0-c2 for each reading and fitted, Omega and tau_b
at the figures' impact speed, the radii of convergence, the closed forms and figure 4's shape.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from . import printed
from ..core.errors import ParameterError

__all__ = ["DEFAULT_SETTINGS", "compute_claim_values", "printed_max_power", "tracking_values", "radius_estimate"]

DEFAULT_SETTINGS = {
    "g_figure": printed.G_FIGURES,      # impact speed of figures 1-2 and of the Omega, tau_b claims
    "g_fit": (0.01, 1.0),               # g range of the c0-c2 fit (figure 4's range)
    "g_wide": (0.001, 10.0),            # a wider range for the second fit and figure 4's shape
    "points": 41,                       # Omegas per fit (log-spaced in g)
    "rtol": 1e-10,                      # reference integrations
    "tracking_thresholds": (0.01, 0.05, 0.1),  # "stops tracking": |series - reference| > this * x_b
    "tracking_samples": 1201,
    "series_max_power": 11,             # the paper's truncation for figures 1-2
    "radius_max_power": 201,            # x0 coefficients used to estimate the radius
    "readings": None,                   # None: connection.all_readings(x~_c at g_figure)
}


# ===================================================================================== computing
def _series_values(problem) -> list[dict] | None:
    """Each printed x_n (forward, inverse) against the exact engine; None for other exponents."""
    from ..core.exponents import as_exponents
    from ..core.series import series_for

    ex = as_exponents(problem)
    if ex != as_exponents(printed.ALPHA, printed.GAMMA):
        return None
    out = []
    for direction, orders in printed.PRINTED_SERIES.items():
        ours = series_for(ex, max(orders), printed_max_power(orders), direction)
        for n, terms in orders.items():
            mine = dict(ours.terms(n))
            bad = [[p, c, str(mine.get(Fraction(p), 0))] for p, c in terms
                   if mine.get(Fraction(p), Fraction(0)) != Fraction(c)]
            out.append({"direction": direction, "n": n, "n_terms": len(terms),
                        "n_match": len(terms) - len(bad), "mismatches": bad})
    return out


def printed_max_power(orders: dict) -> Fraction:
    return max(Fraction(p) for terms in orders.values() for p, _ in terms)


#: Where the series stop tracking is located to this (absolute, in tau): well below the 3 decimals
#: the ledger prints.
TRACKING_XTOL = 1e-8


def _first_exceedance(tau, err, limit, err_at=None):
    """First tau where err > limit (None if never): bracketed by the samples, then located by root
    finding on ``err_at(t) - limit`` (the error recomputed at any t) when given."""
    idx = np.flatnonzero(np.asarray(err) > limit)
    if not idx.size:
        return None
    i = int(idx[0])
    if err_at is None or i == 0:
        return float(tau[i])
    from scipy.optimize import brentq
    return float(brentq(lambda t: err_at(t) - limit, float(tau[i - 1]), float(tau[i]), xtol=TRACKING_XTOL))


def tracking_values(problem, omega, omega_tilde, *, thresholds=(0.01, 0.05, 0.1), samples=1201,
                    max_power=11, rtol=1e-10, orders=(1, 2, 3, 4)) -> dict:
    """Where the perturbation series stop tracking the reference solution.

    Definition: the first tau at which |x_series - x_reference| > threshold * x_b, bracketed on a
    uniform grid of ``samples`` points over the contact and located by root finding to
    TRACKING_XTOL, for each threshold. Forward: the forward series of order
    N at Omega against collide(Omega). Inverse: the inverse series (which start at x~ = 0) at Omega~
    against inverse_collide(Omega~, x_start = 0), i.e. against the problem those series solve.
    Inverse times are also mapped to forward time, both as the paper writes it, tau = tau_c - tau~,
    and with the change of time scale, tau = tau_c - eps^(-gamma/(gamma+1)) tau~.
    Keys of the per-threshold dicts are str(threshold), then str(order).
    """
    from ..core.collision import collide, inverse_collide
    from ..core.exponents import as_exponents
    from ..core.series import series_for

    fwd = collide(problem, omega, rtol=rtol)
    tau = np.linspace(0.0, fwd.tau_c, samples)
    ref = collide(problem, omega, rtol=rtol, t_eval=tau).trajectory
    ps = series_for(problem, max(orders), max_power, "forward")
    err_f = {n: np.abs(ps.evaluate(ref.tau, omega, order=n) - ref.x) for n in orders}
    # "for tau > 2 the first order is better": compared only where some truncation still follows
    # the solution (within a tracking threshold x x_b); where all are off by order one, "better"
    # means nothing. One fraction (and sample count) per threshold.
    first_best_late, comparable = {}, {}
    if 1 in err_f and len(orders) > 1:
        higher = np.min([err_f[n] for n in orders if n > 1], axis=0)
        closest = np.min([err_f[n] for n in orders], axis=0)
        for thr in thresholds:
            late = (ref.tau > 2.0) & (closest <= thr * fwd.x_b)
            comparable[str(float(thr))] = int(late.sum())
            first_best_late[str(float(thr))] = float(np.mean(err_f[1][late] <= higher[late])) if late.any() else None

    inv0 = inverse_collide(problem, omega_tilde, 0.0, rtol=rtol)
    tau_t = np.linspace(0.0, inv0.tau_end, samples)
    iref = inverse_collide(problem, omega_tilde, 0.0, rtol=rtol, t_eval=tau_t).trajectory
    pi = series_for(problem, max(orders), max_power, "inverse")
    err_i = {n: np.abs(pi.evaluate(iref.tau, omega_tilde, order=n) - iref.x) for n in orders}

    g = float(as_exponents(problem).gamma)
    time_scale = fwd.eps ** (-g / (g + 1.0))
    out = {"omega": float(omega), "omega_tilde": float(omega_tilde), "thresholds": [float(t) for t in thresholds],
           "tau_c": fwd.tau_c, "tau_b": fwd.tau_b, "x_b": fwd.x_b, "x_b_inverse": inv0.x_b, "eps": fwd.eps,
           "first_order_best_after_2": first_best_late, "comparable_samples_after_2": comparable,
           "samples_after_2": int((ref.tau > 2.0).sum()),
           "forward": {}, "inverse_tau_tilde": {}, "inverse_tau_paper": {}, "inverse_tau_scaled": {}}
    def fwd_err(n):
        return lambda t: abs(float(ps.evaluate(np.array([t]), omega, order=n)[0])
                             - float(collide(problem, omega, rtol=rtol, t_eval=[t]).trajectory.x[0]))

    def inv_err(n):
        return lambda t: abs(float(pi.evaluate(np.array([t]), omega_tilde, order=n)[0])
                             - float(inverse_collide(problem, omega_tilde, 0.0, rtol=rtol, t_eval=[t]).trajectory.x[0]))

    # the same criterion both ways: the first time, in the run's own direction, at which the series
    # is off by more than the threshold times that run's maximum compression
    for thr in thresholds:
        key = str(float(thr))
        fw = {str(n): _first_exceedance(ref.tau, err_f[n], thr * fwd.x_b, fwd_err(n)) for n in orders}
        iv = {str(n): _first_exceedance(iref.tau, err_i[n], thr * inv0.x_b, inv_err(n)) for n in orders}
        out["forward"][key] = fw
        out["inverse_tau_tilde"][key] = iv
        out["inverse_tau_paper"][key] = {n: (None if v is None else fwd.tau_c - v) for n, v in iv.items()}
        out["inverse_tau_scaled"][key] = {n: (None if v is None else fwd.tau_c - time_scale * v)
                                          for n, v in iv.items()}
    return out


def radius_estimate(gamma, direction: str, max_power=201) -> float:
    """Radius of convergence of the damped-only Taylor series x0 from its last two nonzero terms.

    R = |c_k / c_k'|^(1/(k' - k)) (ratio test); for tanh / tan the corrections fall like 3^-k.
    """
    from ..core.series import series_for

    ps = series_for((2, gamma), 0, max_power, direction)  # x0 does not depend on alpha
    terms = ps.terms(0)
    (p1, c1), (p2, c2) = terms[-2], terms[-1]
    return float(abs(Fraction(c1) / Fraction(c2)) ** (1.0 / float(p2 - p1)))


def _inverse_form_values(x_c: float = 0.5, h: float = 1e-4) -> dict:
    """Residuals of the paper's printed inverse closed form in the inverse and forward equations."""
    from ..core.damped import paper_inverse_closed_form

    tau = np.linspace(0.05, 0.6, 12)
    f = lambda t: paper_inverse_closed_form(t, x_c)  # noqa: E731
    x, xp, xm = f(tau), f(tau + h), f(tau - h)
    d1, d2 = (xp - xm) / (2 * h), (xp - 2 * x + xm) / h ** 2
    small = paper_inverse_closed_form(np.array([0.5]), 1e-12)[0]
    return {"x_c": x_c,
            "residual_inverse": float(np.max(np.abs(d2 - x * d1))),
            "residual_forward": float(np.max(np.abs(d2 + x * d1))),
            "limit_at_tau_half": float(small),
            "sqrt2_tan_at_tau_half": math.sqrt(2) * math.tan(0.5 / math.sqrt(2)),
            "sqrt2_tanh_at_tau_half": math.sqrt(2) * math.tanh(0.5 / math.sqrt(2))}


def _local_slope(fun, x1, x2):
    return (math.log(fun(x2)) - math.log(fun(x1))) / (math.log(x2) - math.log(x1))


def _curve_shape(g, eps) -> dict:
    ok = np.isfinite(eps)
    d = np.diff(eps[ok])
    return {"monotone_increasing": bool(ok.sum() > 1 and np.all(d > 0)),
            "monotone_decreasing": bool(ok.sum() > 1 and np.all(d < 0)),
            "min": float(np.min(eps[ok])) if ok.any() else None,
            "max": float(np.max(eps[ok])) if ok.any() else None,
            "n": int(eps.size), "n_undefined": int((~ok).sum()), "n_above_1": int(np.sum(eps[ok] > 1)),
            "g_undefined": [float(v) for v in g[~ok]][:3],
            "g_min": float(g.min()), "g_max": float(g.max())}


def reference_inputs(material_params: dict, settings: dict | None = None) -> dict:
    """What the pipeline's rules hand to :func:`compute_claim_values`, computed here with the same
    library calls (for tests and for use outside the pipeline): the reference collision at
    g_figure (reference_trajectories), the eps curve on g_wide (reference_eps_curve), the fit on
    g_fit (connection_fit) and every reading of the paper's procedure (connection_readings)."""
    from ..core import connection
    from ..core.collision import collide
    from ..core.model import Material
    from . import matching, readings

    st = {**DEFAULT_SETTINGS, **(settings or {})}
    mat = Material(material_params["alpha"], material_params["gamma"], material_params["D1"],
                   material_params["D2"])
    ex, rtol = mat.exponents, float(st["rtol"])
    omega_fig = mat.omega(float(st["g_figure"]))
    fig = collide(ex, omega_fig, rtol=rtol)
    g = np.geomspace(float(st["g_wide"][0]), float(st["g_wide"][1]), int(st["points"]))
    exact = connection.exact_omega_tilde(ex, mat.omega(g), rtol=rtol)
    curve = {"g": g, "omega": exact["omega"], "eps": exact["eps"], "omega_tilde": exact["omega_tilde"]}
    lo, hi = st["g_fit"]
    fit = connection.fit_connection(ex, np.sort(mat.omega(np.geomspace(lo, hi, int(st["points"])))), rtol=rtol)
    x_tilde_c = connection.rebound_start(ex, fig.x_c, fig.eps)
    chosen = st["readings"] if st["readings"] is not None else readings.all_readings(
        x_tilde_c if 0 < x_tilde_c < 1 else None)
    rows = [matching.reading_row(ex, r) for r in chosen]
    return {"at_figure": {"omega": omega_fig, "eps": fig.eps, "tau_b": fig.tau_b, "x_c": fig.x_c},
            "curve": curve, "fit": {**fit.as_dict(), "g_min": float(lo), "g_max": float(hi)},
            "readings": rows}


def compute_claim_values(material_params: dict, settings: dict | None = None, *, at_figure: dict,
                         curve: dict, fit: dict, readings: list) -> dict:
    """Every value the ledger needs. It consumes what other stages computed and computes only
    what no other stage does (the series comparison, the Delta formulas, where the series stop
    tracking, local slopes, radii, the wide fit, figure 4's shape).

    ``material_params``: alpha, gamma, D1, D2 (other keys ignored). ``settings``: see
    DEFAULT_SETTINGS. ``at_figure``: omega, eps, tau_b, x_c of the reference collision at
    g_figure; ``curve``: arrays g, omega, eps, omega_tilde of the reference eps curve (g_wide);
    ``fit``: the least-squares c0-c2 on g_fit (FitResult.as_dict with g_min, g_max);
    ``readings``: the paper's procedure for each reading (ConnectionCoefficients.as_dict with c).
    :func:`reference_inputs` computes all four the way the pipeline does.
    """
    from ..core import connection
    from ..core.collision import collide
    from ..core.model import Material
    from . import matching
    from . import reference_points as rd
    from .readings import Reading

    st = {**DEFAULT_SETTINGS, **(settings or {})}
    mat = Material(material_params["alpha"], material_params["gamma"], material_params["D1"],
                   material_params["D2"])
    ex = mat.exponents
    rtol = float(st["rtol"])
    g_fig = float(st["g_figure"])
    omega_fig = float(at_figure["omega"])
    k = ex.omega_exponent
    omega_t_fig = connection.rebound_omega(ex, omega_fig, at_figure["eps"])
    x_tilde_c_fig = connection.rebound_start(ex, at_figure["x_c"], at_figure["eps"])

    values: dict = {
        "alpha": str(ex.alpha), "gamma": str(ex.gamma), "D1": mat.D1, "D2": mat.D2,
        "g_figure": g_fig, "settings": {k_: v for k_, v in st.items() if k_ != "readings"},
    }
    values["series"] = _series_values(ex)
    values["d_star"] = mat.d_star
    values["omega_at_g"] = omega_fig
    values["tau_b_at_g"] = float(at_figure["tau_b"])
    values["eps_at_g"] = float(at_figure["eps"])
    values["omega_tilde_at_g"] = omega_t_fig
    values["x_tilde_c_at_g"] = x_tilde_c_fig

    # Delta formulas and the reference points
    try:
        delta, delta_t = matching.lowest_order_deltas(ex)
        tau0, tau0t = rd.reference_times(ex)
        values["tau0"], values["tau0_tilde"] = float(tau0.evalf(20)), float(tau0t.evalf(20))
        values["delta_derived"] = [str(delta), str(delta_t)]
        p_delta, p_delta_t = matching.printed_deltas()
        values["delta_printed"] = [str(p_delta), str(p_delta_t)]
        values["delta_equal"] = [bool((delta - p_delta).expand() == 0),
                                 bool((delta_t - p_delta_t).expand() == 0)]
        # tau_b from the lowest-order Delta with converged x1'(tau_0)
        vals = rd.reference_derivatives(ex, Reading(truncation="converged"))
        a11 = float(vals.a[rd.a_sym(1, 1)])
        values["tau_b_lowest_order"] = values["tau0"] + float(delta.subs({rd.W: omega_fig, rd.a_sym(1, 1): a11}))
        values["tau_b_lowest_order_at_zero"] = values["tau0"] + float(delta.subs(rd.W, 0))
    except ParameterError as err:  # gamma = 0: the reference point tau_0 does not exist
        values["delta_error"] = str(err)

    values["readings"] = list(readings)

    # the fit on g_fit (connection_fit), and one on the whole curve (the ledger's own)
    values["fit"] = dict(fit)
    g = np.asarray(curve["g"], float)
    omegas = np.asarray(curve["omega"], float)
    omega_tilde = np.asarray(curve["omega_tilde"], float)
    if k != 0:   # else Omega~ = Omega: nothing to fit
        order = np.argsort(omegas)
        wide = connection.fit_quadratic(omegas[order], omega_tilde[order])
        values["fit_wide"] = {**wide.as_dict(), "g_min": float(g.min()), "g_max": float(g.max())}

    # figure 4: eps(g) from the paper's relation and from the reference
    eps_ref = np.asarray(curve["eps"], float)
    if k != 0:
        eps_paper = np.asarray(connection.eps_from_connection(ex, omegas, printed.PRINTED_C), float)
        fit_c = values["fit"].get("c")
        eps_fit = (np.asarray(connection.eps_from_connection(ex, omegas, fit_c), float) if fit_c is not None
                   else np.full(g.shape, np.nan))
    else:
        eps_paper = eps_fit = np.full(g.shape, np.nan)
    in_fit = (g >= fit["g_min"] * (1 - 1e-12)) & (g <= fit["g_max"] * (1 + 1e-12))
    values["fig4"] = {
        "paper": _curve_shape(g, eps_paper), "reference": _curve_shape(g, eps_ref),
        "fit": _curve_shape(g, eps_fit),
        "max_abs_error_paper_in_fit_range": _nanmax(np.abs(eps_paper - eps_ref)[in_fit]),
        "max_abs_error_fit_in_fit_range": _nanmax(np.abs(eps_fit - eps_ref)[in_fit]),
        "paper_relation_omega_tilde_max_rel_error_in_fit_range": _nanmax(
            np.abs(connection.omega_tilde_from_c(omegas, printed.PRINTED_C) - omega_tilde)[in_fit]
            / omega_tilde[in_fit]),
    }

    if k != 0:
        val = connection.connection_validity(ex, printed.PRINTED_C)
        to_g = lambda w: (w / mat.omega(1.0)) ** (1.0 / float(k)) if math.isfinite(w) and w > 0 else (  # noqa: E731
            math.inf if float(k) < 0 else 0.0)
        values["paper_relation_validity"] = {
            key: [{"omega": [lo, hi], "g": sorted([to_g(lo), to_g(hi)])} for lo, hi in ivs]
            for key, ivs in val.items()}

    # g-scalings
    values["omega_g_exponent"] = str(k)
    values["omega_g_slope"] = _local_slope(mat.omega, 0.01, 1.0)
    eps_of = lambda w: collide(ex, w, rtol=rtol).eps  # noqa: E731
    # small Omega = large g (damping dominates), large Omega = small g (nearly elastic)
    small_window = (1e-4, 2e-4)   # deep in the viscous limit, far below the crossover at Omega ~ 1
    slope_eps_small_omega = _local_slope(eps_of, *small_window)
    loss_window = (1e3, 2e3)   # beyond figure 4's grid: the elastic limit proper
    slope_loss_large_omega = _local_slope(lambda w: 1.0 - eps_of(w), *loss_window)
    slope_loss_range = _local_slope(lambda w: 1.0 - eps_of(w), float(np.max(omegas)) / 2, float(np.max(omegas)))
    values["omega_tilde_small_omega_exponent"] = 1.0 + float(k) * slope_eps_small_omega
    values["omega_tilde_small_omega_window"] = small_window
    values["eps_scaling"] = {
        "eps_g_exponent_large_g": slope_eps_small_omega * float(k),
        "loss_g_exponent_small_g": slope_loss_large_omega * float(k),
        "loss_slope_omegas": list(loss_window),
        "loss_g_exponent_at_g_min": slope_loss_range * float(k),
        # the paper's eps is a function of Omega ~ g^k alone, hence of g^(1/4) iff 4k is an integer
        "paper_relation_powers_of_g_quarter": bool((4 * k).denominator == 1),
    }

    # where the series stop tracking (figures 1-2)
    values["tracking"] = tracking_values(ex, omega_fig, omega_t_fig,
                                         thresholds=tuple(st["tracking_thresholds"]),
                                         samples=int(st["tracking_samples"]),
                                         max_power=st["series_max_power"], rtol=rtol)

    # Taylor radii and the printed inverse closed form (damped-only, gamma as given)
    values["radius_forward"] = radius_estimate(ex.gamma, "forward", st["radius_max_power"])
    values["radius_inverse"] = radius_estimate(ex.gamma, "inverse", st["radius_max_power"])
    values["paper_inverse_form"] = _inverse_form_values() if ex.gamma == 1 else None
    return values


def _nanmax(a) -> float | None:
    a = np.asarray(a, float)
    return float(np.nanmax(a)) if np.any(np.isfinite(a)) else None

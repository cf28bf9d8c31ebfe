"""The connection of forward and inverse collisions: the paper's procedure, the exact one, the retrace."""

import math
from dataclasses import replace

import mpmath
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from restitution.core import connection
from restitution.audit import matching, readings, reference_points
from restitution.core import damped
from restitution.core.collision import collide
from restitution.core.errors import ParameterError
from restitution.core.series import perturbation_series

SQRT2 = math.sqrt(2)


# ------------------------------------------------------------------------------ reference points
def test_reference_times_are_where_the_damped_closed_forms_reach_one():
    tau0, tau0t = reference_points.reference_times(("3/2", 1))
    t0, t0t = float(tau0.evalf(20)), float(tau0t.evalf(20))
    assert damped.forward(t0)[0] == pytest.approx(1.0, abs=1e-14)
    assert damped.inverse(t0t)[0] == pytest.approx(1.0, abs=1e-14)
    # and the quadrature of the first integrals gives the same numbers
    assert float(mpmath.quad(lambda x: 1 / (1 - x * x / 2), [0, 1])) == pytest.approx(t0, rel=1e-14)
    assert float(mpmath.quad(lambda x: 1 / (1 + x * x / 2), [0, 1])) == pytest.approx(t0t, rel=1e-14)


@pytest.mark.parametrize("gamma", ["1/2", "2"])
def test_reference_times_for_other_gamma_match_an_integration(gamma):
    g = float(sp.Rational(gamma))
    tau0, tau0t = (float(t.evalf(15)) for t in reference_points.reference_times(("3/2", gamma)))
    for sign, expected in ((+1, tau0), (-1, tau0t)):
        hit = lambda t, y: y[0] - 1.0  # noqa: E731
        hit.terminal = True
        sol = solve_ivp(lambda t, y: [y[1], -sign * y[0] ** g * y[1]], (0, 10), [1e-300, 1.0],
                        events=hit, rtol=1e-12, atol=1e-14)
        assert sol.t_events[0][0] == pytest.approx(expected, rel=1e-8)


def test_gamma_zero_is_refused_with_a_reason():
    with pytest.raises(ParameterError, match="never|does not exist"):
        reference_points.reference_times(("3/2", 0))
    with pytest.raises(ParameterError):
        matching.paper_procedure(("3/2", 0))


def test_x_tilde_c_reference_time_is_where_the_inverse_closed_form_reaches_one():
    _, tau0t = reference_points.reference_times(("3/2", 1), x_tilde_c=0.5)
    assert damped.inverse(float(tau0t.evalf(20)), 0.5)[0] == pytest.approx(1.0, abs=1e-13)


# ---------------------------------------------------------------------------------- the Delta's
def test_derived_lowest_order_deltas_equal_the_printed_ones():
    derived = matching.lowest_order_deltas(("3/2", 1))
    printed = matching.printed_deltas()
    for d, p in zip(derived, printed):
        assert sp.expand(d - p) == 0


def test_a_wrong_printed_formula_would_be_caught():
    delta, _ = matching.lowest_order_deltas(("3/2", 1))
    assert sp.expand(delta - (1 + 3 * reference_points.a_sym(1, 1) * reference_points.W)) != 0


def test_lowest_order_delta_for_other_gamma():
    # x0' = gamma/(gamma+1), x0'' = -gamma/(gamma+1) at x0 = 1: Delta = 1 + ((gamma+1)/gamma) x1' Omega
    delta, delta_t = matching.lowest_order_deltas(("3/2", "1/2"))
    assert sp.expand(delta - (1 + 3 * reference_points.a_sym(1, 1) * reference_points.W)) == 0
    # inverse: x~0' = x~0'' = (gamma+2)/(gamma+1) at x~0 = 1
    assert sp.expand(delta_t - (-1 - sp.Rational(3, 5) * reference_points.b_sym(1, 1) * reference_points.WT)) == 0


# -------------------------------------------------------------------------------- the procedure
READINGS = readings.all_readings(x_tilde_c=0.5)


@pytest.mark.parametrize("reading", READINGS, ids=[r.label for r in READINGS])
@pytest.mark.slow
def test_every_reading_gives_finite_coefficients_or_says_why_not(reading):
    cc = matching.paper_procedure(("3/2", 1), reading)
    if cc.defined:
        assert all(math.isfinite(c) for c in cc.c)
        assert cc.reason == ""
        assert reading.describe()
    else:
        assert all(math.isnan(c) for c in cc.c) and cc.reason


def test_rescaled_reading_has_c0_zero_and_others_positive_c0():
    assert matching.paper_procedure(("3/2", 1), replace(readings.Reading(), rescale=True)).c0 == 0.0
    cc = matching.paper_procedure(("3/2", 1), replace(readings.Reading(), omega_orders=2))
    assert cc.defined and cc.c0 > 0 and cc.c0 == min(cc.c0_roots)


def test_converged_quadratic_delta_has_a_double_root_at_omega_zero():
    # x0'(tau_0 + Delta) to second order: 1/2 - Delta/2 + Delta^2/8 = (Delta - 2)^2 / 8 for gamma = 1
    cc = matching.paper_procedure(("3/2", 1), readings.Reading("converged", 2, 2, "quadratic"))
    assert not cc.defined and "forward" in cc.reason


def _match_function(reading):
    """M(Omega, Omega~) for a 'printed Delta' reading, written directly in floats (independent code)."""
    mp = 11 if reading.truncation == "printed" else 120
    N, K = reading.omega_orders, reading.match_order
    fs = perturbation_series("3/2", 1, N, mp, "forward")
    inv = perturbation_series("3/2", 1, N, mp, "inverse")
    t0, t0t = SQRT2 * math.atanh(1 / SQRT2), SQRT2 * math.atan(1 / SQRT2)
    a = lambda n, j: float(fs.order_values(t0, n, j))  # noqa: E731
    b = lambda n, j: float(inv.order_values(t0t, n, j))  # noqa: E731

    def M(w, wt):
        d = 1 + 2 * a(1, 1) * w
        dt = -1 - 2 / 3 * b(1, 1) * wt
        xf = sum(w ** n * sum(a(n, j) * d ** j / math.factorial(j) for j in range(K + 1)) for n in range(N + 1))
        xi = sum(wt ** n * sum(b(n, j) * dt ** j / math.factorial(j) for j in range(K + 1)) for n in range(N + 1))
        return xf - xi
    return M


@pytest.mark.parametrize("reading", [readings.Reading(omega_orders=2), readings.Reading(omega_orders=2, match_order=1)],
                         ids=lambda r: r.label)
def test_coefficients_agree_with_finite_differences_of_an_independent_root_finder(reading):
    cc = matching.paper_procedure(("3/2", 1), reading)
    M = _match_function(reading)
    h = 1e-3
    roots = {w: brentq(lambda wt: M(w, wt), cc.c0 - 1.0, cc.c0 + 1.0, xtol=1e-14) for w in (-h, 0.0, h)}
    assert roots[0.0] == pytest.approx(cc.c0, abs=1e-9)
    c1 = (roots[h] - roots[-h]) / (2 * h)
    c2 = (roots[h] - 2 * roots[0.0] + roots[-h]) / (2 * h * h)
    assert c1 == pytest.approx(cc.c1, abs=1e-5)
    assert c2 == pytest.approx(cc.c2, abs=1e-3)


def test_converged_values_match_the_closed_form_of_x0():
    vals = reference_points.reference_derivatives(("3/2", 1), readings.Reading(truncation="converged", omega_orders=1))
    # the converged reading takes x0 from the first integral: 1, 1/2, -1/2, 1/4 at tau_0
    assert [float(vals.a[reference_points.a_sym(0, j)]) for j in range(4)] == [1.0, 0.5, -0.5, 0.25]
    # and x1 there is the long series: compare with a numerical derivative of the ODE solution
    omega, t0 = 1e-5, SQRT2 * math.atanh(1 / SQRT2)
    sol = solve_ivp(lambda t, y: [y[1], -omega * max(y[0], 0) ** 1.5 - y[0] * y[1]], (0, t0), [0, 1],
                    rtol=1e-13, atol=1e-15, method="DOP853")
    x1_numeric = (sol.y[0, -1] - 1.0) / omega
    assert x1_numeric == pytest.approx(float(vals.a[reference_points.a_sym(1, 0)]), rel=1e-3)
    assert vals.truncation_change < 1e-10


def test_taylor_series_from_x_tilde_c_solves_the_inverse_equation():
    r = readings.Reading(truncation="converged", omega_orders=2, x_tilde_c=0.5)
    vals = reference_points.reference_derivatives(("3/2", 1), r)
    _, tau0t = reference_points.reference_times(("3/2", 1), 0.5)
    t = float(tau0t.evalf(20))
    wt = 1e-2
    sol = solve_ivp(lambda s, y: [y[1], -wt * y[0] ** 1.5 + y[0] * y[1]], (0, t), [0.5, 1.0],
                    rtol=1e-13, atol=1e-15, method="DOP853")
    series = sum(wt ** n * float(vals.b[reference_points.b_sym(n, 0)]) for n in range(3))
    assert series == pytest.approx(sol.y[0, -1], abs=5 * wt ** 3)
    assert float(vals.b[reference_points.b_sym(0, 0)]) == pytest.approx(1.0, abs=1e-12)


@pytest.mark.parametrize("bad", [dict(truncation="full"), dict(omega_orders=0), dict(match_order=3),
                                 dict(delta="cubic"), dict(x_tilde_c=1.5), dict(convention="x")])
def test_reading_validation(bad):
    with pytest.raises(ParameterError):
        readings.Reading(**bad)


def test_rescale_is_undefined_when_omega_does_not_depend_on_g():
    with pytest.raises(ParameterError):
        matching.paper_procedure(("3", 1), readings.Reading(rescale=True))


# ---------------------------------------------------------------------------- exact connection
@pytest.fixture(scope="module")
def fit_and_check():
    omegas = np.geomspace(0.08, 1.5, 15)
    fit = connection.fit_connection(("3/2", 1), omegas, rtol=1e-10)
    held_out = np.sqrt(omegas[1:] * omegas[:-1])  # between the fit points
    exact = connection.exact_omega_tilde(("3/2", 1), held_out, rtol=1e-10)
    return fit, exact


def test_fit_reproduces_the_exact_connection_within_its_stated_residual(fit_and_check):
    fit, exact = fit_and_check
    err = np.abs(connection.omega_tilde_from_c(exact["omega"], fit.c) - exact["omega_tilde"])
    # off the fit points the misfit of a smooth quadratic is bounded by its residual on them
    assert err.max() <= 1.2 * fit.max_abs_residual
    assert fit.rms <= fit.max_abs_residual and all(s > 0 for s in fit.stderr)


def test_perturbed_coefficients_break_that_bound(fit_and_check):
    fit, exact = fit_and_check
    for i in range(3):
        c = list(fit.c)
        c[i] += 3 * fit.max_abs_residual
        err = np.abs(connection.omega_tilde_from_c(exact["omega"], c) - exact["omega_tilde"])
        assert err.max() > 1.2 * fit.max_abs_residual


def test_eps_round_trip_through_the_connection():
    omega = 0.47
    exact = connection.exact_omega_tilde(("3/2", 1), [omega], rtol=1e-11)
    eps = connection.eps_from_connection(("3/2", 1), omega, (exact["omega_tilde"][0], 0.0, 0.0))
    assert eps == pytest.approx(exact["eps"][0], rel=1e-12)
    assert eps == pytest.approx(collide(("3/2", 1), omega, rtol=1e-11).eps, rel=1e-9)


def test_eps_from_connection_edge_cases():
    assert math.isnan(connection.eps_from_connection(("3/2", 1), 1.0, (-1.0, 0.0, 0.0)))
    with pytest.raises(ParameterError):
        connection.eps_from_connection(("3", 1), 1.0, (1.0, 0.0, 0.0))
    # Omega~ < Omega with a negative exponent gives eps > 1: returned, flagged by the caller
    assert connection.eps_from_connection(("3/2", 1), 2.0, (1.0, 0.0, 0.0)) > 1


# ---------------------------------------------------------------------------------- the retrace
@pytest.mark.parametrize("alpha,gamma,omega", [("3/2", 1, 0.05), ("3/2", 1, 0.4726), ("3/2", 1, 5.0),
                                               ("5/2", "1/2", 0.7), ("1", "1/2", 0.7), ("2", 1, 2.0)])
def test_inverse_from_the_forward_end_retraces_the_forward_collision(alpha, gamma, omega):
    r = connection.retrace((alpha, gamma), omega, rtol=1e-12)
    assert r.tau.size > 100
    assert r.max_deviation < 1e-8
    assert r.v_end_error < 1e-8 and r.tau_error < 1e-8


def test_retrace_fails_without_the_change_of_scale():
    # the same inverse run read without x = s x~ (s = eps^(1/(gamma+1))) misses the forward one
    r = connection.retrace(("3/2", 1), 0.4726, rtol=1e-10)
    s = r.eps ** 0.5
    assert np.max(np.abs(r.x_retraced / s - r.x_forward)) / np.max(r.x_forward) > 0.1


def test_connection_validity_intervals_agree_with_eps_from_connection():
    c = (6.0203, -1.5257, 0.0256)
    val = connection.connection_validity(("3/2", 1), c)
    assert val["omega_tilde_nonpositive"] and val["eps_above_one"]
    for lo, hi in val["omega_tilde_nonpositive"]:
        assert math.isnan(connection.eps_from_connection(("3/2", 1), 0.5 * (lo + hi), c))
    for lo, hi in val["eps_above_one"]:
        assert connection.eps_from_connection(("3/2", 1), 0.5 * (lo + hi), c) > 1
    assert 0 < connection.eps_from_connection(("3/2", 1), 0.5 * val["eps_above_one"][0][0], c) < 1

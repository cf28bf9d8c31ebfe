"""Closed forms of the damped-only problem, including the paper's printed inverse solution."""

import math

import numpy as np
import pytest

from restitution.core import damped

TAU = np.linspace(0.0, 1.0, 11)


def _residual(x_of_tau, sign, tau=TAU, h=1e-4):
    """x'' + sign x x' by central differences."""
    x0, xp, xm = x_of_tau(tau), x_of_tau(tau + h), x_of_tau(tau - h)
    d1 = (xp - xm) / (2 * h)
    d2 = (xp - 2 * x0 + xm) / h ** 2
    return d2 + sign * x0 * d1


@pytest.mark.parametrize("x_start", [0.0, 0.3, 1.0])
def test_forward_closed_form_solves_the_forward_equation(x_start):
    x, v = damped.forward(TAU, x_start)
    assert np.max(np.abs(_residual(lambda t: damped.forward(t, x_start)[0], +1))) < 1e-6
    np.testing.assert_allclose(damped.forward_first_integral(x, v), 1 + x_start ** 2 / 2, rtol=1e-14)
    assert x[0] == pytest.approx(x_start) and v[0] == pytest.approx(1.0)


@pytest.mark.parametrize("x_start", [0.0, 0.3, 1.0, math.sqrt(2), 1.6])
def test_inverse_closed_form_solves_the_inverse_equation(x_start):
    tau = TAU * 0.3
    x, v = damped.inverse(tau, x_start)
    assert np.max(np.abs(_residual(lambda t: damped.inverse(t, x_start)[0], -1, tau))) < 1e-5
    np.testing.assert_allclose(damped.inverse_first_integral(x, v), 1 - x_start ** 2 / 2, rtol=1e-12)
    assert x[0] == pytest.approx(x_start) and v[0] == pytest.approx(1.0)


def test_forward_at_zero_start_is_sqrt2_tanh():
    x, _ = damped.forward(TAU)
    np.testing.assert_allclose(x, math.sqrt(2) * np.tanh(TAU / math.sqrt(2)), rtol=1e-15)


def test_paper_printed_inverse_form_solves_the_forward_equation_not_the_inverse():
    # The paper's G tanh(...) with G = sqrt(x_c^2 + 2) starts right (x = x_c, x' = 1) but obeys
    # x'' + x x' = 0; its x_c -> 0 limit is sqrt(2) tanh, not the sqrt(2) tan the text states.
    x_c = 0.3
    printed = lambda t: damped.paper_inverse_closed_form(t, x_c)  # noqa: E731
    assert np.max(np.abs(_residual(printed, +1))) < 1e-6
    assert np.max(np.abs(_residual(printed, -1))) > 0.1
    np.testing.assert_allclose(printed(TAU), damped.forward(TAU, x_c)[0], rtol=1e-14)
    limit = damped.paper_inverse_closed_form(TAU, 0.0)
    np.testing.assert_allclose(limit, math.sqrt(2) * np.tanh(TAU / math.sqrt(2)), rtol=1e-15)


def test_first_integrals_generalise_in_gamma():
    x = np.array([0.2, 0.5])
    assert damped.forward_first_integral(x, 1 - x ** 1.5 / 1.5, gamma=0.5) == pytest.approx(1.0)


def test_negative_start_is_refused():
    from restitution.core.errors import ParameterError
    with pytest.raises(ParameterError):
        damped.forward(TAU, -0.1)

"""Closed form of the linear spring-dashpot collision (alpha = 1, gamma = 0)."""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from restitution.core.dashpot import contact_times, dashpot_collision, dashpot_trajectory
from restitution.core.errors import ParameterError

QUANTITIES = ("eps", "tau_b", "x_b", "tau_c", "x_c")
QUARTER = 0.25
NEAR_QUARTER = [QUARTER * (1 - 1e-6), QUARTER * (1 - 1e-12), QUARTER, QUARTER * (1 + 1e-12), QUARTER * (1 + 1e-6)]
OMEGAS = [1e-12, 1e-6, 1e-3, 0.1, 3 / 16, 0.2, *NEAR_QUARTER, 0.3, 0.5, 1.0, 10.0, 1e3, 1e8]


def _independent(omega: float) -> dict:
    """Roots of x' and of Omega x + x' found by mpmath on the motion written as a matrix exponential,
    so no formula of the module under test is reused."""
    with mp.workdps(50):
        W = mp.mpf(omega)
        A = mp.matrix([[0, 1], [-W, -1]])

        def state(t):
            y = mp.expm(A * t) * mp.matrix([0, 1])
            return y[0], y[1]

        guess = dashpot_collision(omega)
        tb = mp.findroot(lambda t: state(t)[1], mp.mpf(guess.tau_b))
        tc = mp.findroot(lambda t: W * state(t)[0] + state(t)[1], mp.mpf(guess.tau_c))
        return {"eps": -state(tc)[1], "tau_b": tb, "x_b": state(tb)[0], "tau_c": tc, "x_c": state(tc)[0]}


@pytest.mark.parametrize("omega", OMEGAS)
def test_closed_form_matches_independent_high_precision_roots(omega):
    exact = dashpot_collision(omega)
    ref = _independent(omega)
    for q in QUANTITIES:
        assert float(abs(getattr(exact, q) / ref[q] - 1)) < 5e-15, q
    assert exact.ended_by == "force" and exact.direction == "forward"
    assert exact.rtol == 0.0 and exact.trajectory is None


@pytest.mark.parametrize("omega", NEAR_QUARTER)
def test_critical_neighbourhood_is_continuous(omega):
    """tau_b = 2, tau_c = 4 at Omega = 1/4, approached without cancellation from both sides."""
    tau_b, tau_c = contact_times(omega)
    dz = abs(omega - QUARTER)
    # With z = Omega - 1/4: tau_b = 2 - 8z/3 + O(z^2), tau_c = 4 - 16z/3 + O(z^2) on both sides.
    assert tau_b == pytest.approx(2.0 - 8.0 * (omega - QUARTER) / 3.0, abs=10 * dz ** 2 + 1e-15)
    assert tau_c == pytest.approx(4.0 - 16.0 * (omega - QUARTER) / 3.0, abs=100 * dz ** 2 + 2e-15)
    c = dashpot_collision(omega)
    assert c.eps == pytest.approx(math.exp(-2.0), rel=3 * dz + 1e-15)
    assert c.x_b == pytest.approx(2.0 / math.e, rel=4 * dz + 1e-15)


@pytest.mark.parametrize("omega", [0.6, 1.0, 10.0, 1e4])
def test_eps_agrees_with_schwager_poeschel(omega):
    """Granular Matter 9, 465 (2007): eps = exp(-(beta/w) (pi - arctan(2 beta w / (w^2 - beta^2))))
    for w^2 = Omega - beta^2 > beta^2, here beta = 1/2."""
    w = math.sqrt(omega - 0.25)
    eps = math.exp(-(0.5 / w) * (math.pi - math.atan(w / (w * w - 0.25))))
    assert dashpot_collision(omega).eps == pytest.approx(eps, rel=1e-14)


@pytest.mark.parametrize("omega", OMEGAS)
def test_trajectory_hits_the_contact_events(omega):
    c = dashpot_collision(omega)
    x, v = dashpot_trajectory(np.array([0.0, c.tau_b, c.tau_c]), omega)
    assert x[0] == 0.0 and v[0] == 1.0
    assert x[1] == pytest.approx(c.x_b, rel=1e-13)
    assert abs(v[1]) < 1e-14
    assert x[2] == pytest.approx(c.x_c, rel=1e-13)
    assert v[2] == pytest.approx(-c.eps, rel=1e-13)


@pytest.mark.parametrize("omega", [1e-6, 0.2, 0.25, 0.3, 5.0])
def test_trajectory_solves_the_equation(omega):
    tau = np.linspace(0.0, 30.0, 301)
    x, v = dashpot_trajectory(tau, omega)
    with mp.workdps(30):
        A = mp.matrix([[0, 1], [-mp.mpf(omega), -1]])
        for t, xi, vi in zip(tau[::25], x[::25], v[::25]):
            y = mp.expm(A * mp.mpf(t)) * mp.matrix([0, 1])
            scale = max(abs(float(y[0])), abs(float(y[1])))
            assert abs(xi - float(y[0])) <= 1e-13 * scale
            assert abs(vi - float(y[1])) <= 1e-13 * scale


def test_trajectory_far_out_neither_overflows_nor_cancels():
    omega = 1e-6
    x, v = dashpot_trajectory(np.array([1e4, 1e6, 1e7]), omega)
    assert np.all(np.isfinite(x)) and np.all(np.isfinite(v))
    # x ~ e^(-Omega tau) / (2w) on the slow mode: at tau = 1e6 that is e^-1 / sqrt(1 - 4 Omega).
    assert x[1] == pytest.approx(math.exp(-omega / (math.sqrt(0.25 - omega) + 0.5) * 1e6) / (2 * math.sqrt(0.25 - omega)),
                                 rel=1e-12)
    assert v[1] == pytest.approx(-omega / (math.sqrt(0.25 - omega) + 0.5) * x[1], rel=1e-9)


@pytest.mark.parametrize("omega", [0.0, -1.0, float("nan"), float("inf"), "abc", None])
def test_bad_omega_is_a_parameter_error(omega):
    with pytest.raises(ParameterError):
        dashpot_collision(omega)
    with pytest.raises(ParameterError):
        dashpot_trajectory([0.0, 1.0], omega)

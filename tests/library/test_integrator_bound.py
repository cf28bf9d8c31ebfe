"""The compiled integrator keeps its stated bound for exponents with p >= 3 (alpha, gamma with a
common denominator of 3 or 4), where its u legs once took steps past the curvature (issue 28)."""

import numpy as np
import pytest

from restitution.api import collide
from restitution.core.collision import collide as reference
from restitution.core.exponents import as_exponents
from restitution.fast.integrator import END_FORCE, INTERPRETED_MAX_POINTS, collide_fast
from restitution.fast.rung import integrator_bound


def _viscous_k(ex) -> float:
    """eps / Omega in the viscous limit, (gamma + 1)^((alpha - gamma)/(gamma + 1))."""
    return float(ex.gamma + 1) ** float((ex.alpha - ex.gamma) / (ex.gamma + 1))


@pytest.mark.parametrize("alpha, gamma", [("2", "3/4"), ("7/4", "1/2"), ("5/3", "1/3")])
@pytest.mark.parametrize("omega", [1e-3, 1.0, 1e3, 6e5])
@pytest.mark.parametrize("rtol", [1e-9, 1e-12])
def test_compiled_integrator_within_its_bound_for_p_at_least_3(alpha, gamma, omega, rtol):
    truth = reference((alpha, gamma), omega, rtol=1e-14).eps       # stated accuracy 2.4e-13
    got = collide(alpha, gamma, omega, method="integrator", rtol=rtol).eps
    assert abs(got / truth - 1) <= integrator_bound(rtol, as_exponents(alpha, gamma)) - 2.4e-13


def test_tableau_is_scipys_own():
    # read from scipy's file without importing scipy.integrate: the same numbers as the import gives
    from scipy.integrate._ivp import dop853_coefficients as dop

    from restitution.fast import dop853
    n = dop.N_STAGES
    assert dop853.N_STAGES == n
    for ours, theirs in ((dop853.A, dop.A[:n, :n]), (dop853.B, dop.B), (dop853.C, dop.C[:n]),
                         (dop853.E3, dop.E3), (dop853.E5, dop.E5)):
        assert ours.shape == theirs.shape and ours.tobytes() == np.ascontiguousarray(theirs, float).tobytes()


@pytest.mark.parametrize("alpha, gamma", [("3/2", "1"), ("1", "0"), ("2", "1/2"), ("5/2", "3/2")])
@pytest.mark.parametrize("omega", [1e-9, 1e-12])
def test_contact_times_within_the_bound_at_small_omega(alpha, gamma, omega):
    """tau_b and tau_c keep the bound where the turn comes slowly (v' ~ Omega x^alpha there): with v'
    taken from the carried force, v kept the errors it made while of order 1 and the turn moved by
    error / slope: tau_b off by 2.6e-9 at Omega = 1e-9 and 6e-6 at 1e-12 (3/2, 1; rtol 1e-12), the
    scipy reference right to 4e-14 against mpmath."""
    truth = reference((alpha, gamma), omega, rtol=1e-13)    # stated accuracy 1.1e-12
    got = collide(alpha, gamma, omega, method="integrator", rtol=1e-12)
    for name in ("eps", "tau_b", "x_b", "tau_c"):
        assert abs(getattr(got, name) / getattr(truth, name) - 1) <= integrator_bound(1e-12, as_exponents(alpha, gamma)) + 1.1e-12, name


@pytest.mark.parametrize("alpha, gamma", [("1", "0"), ("2", "1/2"), ("8", "0")])
def test_the_turn_is_found_where_its_speed_is_one_rounding_of_the_start(alpha, gamma):
    """Near Omega = 1e-16 the speed at the turn, Omega x^(alpha-gamma), is one rounding of the speed
    it started from: with v' from the carried force v stopped just above 0 and the kernel ran into
    its step limit. Checked on the kernel: eps is the viscous limit k Omega to double precision there."""
    ex = as_exponents(alpha, gamma)
    row = collide_fast(ex.p, ex.q_alpha, ex.q_gamma, [1e-16], 1e-12)[0]
    assert row[5] == END_FORCE and abs(row[0] / (_viscous_k(ex) * 1e-16) - 1) <= 1e-13


@pytest.mark.parametrize("alpha, gamma, omega, rtol", [("5/2", "0", 1e-200, 1e-14), ("5/2", "1", 1e-300, 1e-10),
                                                       ("15/2", "0", 1e-250, 1e-12), ("5", "3/2", 1e-250, 1e-8)])
def test_locating_an_event_of_tiny_size_bisects_instead_of_dividing_by_zero(alpha, gamma, omega, rtol):
    """At Omega ~ 1e-200 the located force is so small that the Illinois halving takes it to zero and
    the secant's denominator vanished: compiled code raised ZeroDivisionError (12 of 2,720 runs of 34
    pairs, Omega 1e-13..1e-300, rtol 1e-6..1e-14), where plain Python bisected on the NaN. Checked
    on the kernel, against the viscous limit k Omega."""
    ex = as_exponents(alpha, gamma)
    # more points than a process without numba runs as plain Python: the compiled kernel, which raised
    row = collide_fast(ex.p, ex.q_alpha, ex.q_gamma, [omega] * (INTERPRETED_MAX_POINTS + 1), rtol)[0]
    assert row[5] == END_FORCE and abs(row[0] / (_viscous_k(ex) * omega) - 1) <= integrator_bound(rtol, ex)


#: The worst cases of 500 random pairs against mpmath (force rule): (alpha, gamma, Omega, rtol, which).
LARGE_EXPONENT_CASES = [("38/5", "7", 2055.329307323975, 1e-14, "integrator"),      # 1.1e-12: 7.3 times 10 rtol + 5e-14
                        ("32/5", "27/5", 1017343.8827904565, 1e-13, "integrator"),  # 2.8e-12: 2.6 times
                        ("41/6", "13/2", 257206439.23306733, 1e-12, "integrator"),  # 1.4e-11: 1.4 times
                        ("32/5", "5", 5.288759030071241, 1e-14, "reference")]  # 3.6e-13: 1.8 times 10 rtol + 1e-13


@pytest.mark.parametrize("alpha, gamma, omega, rtol, method", LARGE_EXPONENT_CASES)
def test_both_double_methods_keep_their_bound_for_large_exponents(alpha, gamma, omega, rtol, method):
    """For alpha + gamma well above 4 both double-precision integrators missed the bounds they stated
    (core.conditioning.EXPONENT_SCALE: the error grows about as (alpha + gamma)^3); the bounds now
    carry that factor, and collide states it."""
    from restitution.core.highprec import reference_collision
    from restitution.fast.rung import reference_bound

    ex = as_exponents(alpha, gamma)
    truth = float(reference_collision(ex, omega, digits=22).eps)
    got = collide(alpha, gamma, omega, method=method, rtol=rtol)
    stated = integrator_bound(rtol, ex) if method == "integrator" else reference_bound(rtol, ex)
    assert abs(got.eps / truth - 1) <= stated
    if method == "reference":
        assert abs(got.eps / truth - 1) <= got.error_bound


def test_epsilon_states_what_holds_for_large_exponents():
    """Through the API: eps for (38/5, 7) at Omega = 2055 and tol 2e-13 came from the compiled
    integrator at rtol 1e-14, stated 1.5e-13 and was off by 1.1e-12."""
    from restitution.core.highprec import reference_collision
    from restitution.core.problem import Problem
    from restitution.fast.ladder import epsilon

    omega = 2055.329307323975
    truth = float(reference_collision(("38/5", "7"), omega, digits=22).eps)
    for tol in (2e-13, 1e-11, 1e-9):
        r = epsilon(Problem.of("38/5", "7"), omega=[omega], tol=tol, build=False)
        assert r.error_bound <= tol and abs(r.eps[0] / truth - 1) <= r.error_bound, (tol, r.method)


@pytest.mark.slow   # mpmath at 1e-40: about 2 s a pair
@pytest.mark.parametrize("alpha, gamma", [("3/2", "1"), ("1", "0"), ("5/2", "1/2"), ("7", "17/5")])
@pytest.mark.parametrize("omega", [3e-15, 1e-40])
def test_below_1e_12_every_quantity_keeps_the_bound(alpha, gamma, omega):
    """The compiled integrator's range now reaches 1e-300 for eps (the viscous limit, to double
    precision from about 1e-18 on) and 1e-100 for the contact times (master.TIMES_OMEGA_MIN);
    checked against mpmath where eps is not yet k Omega to the last digit and further down."""
    from restitution.core.highprec import reference_collision

    ex = as_exponents(alpha, gamma)
    truth = reference_collision(ex, omega, digits=20)
    for rtol in (1e-8, 1e-12):
        got = collide(alpha, gamma, omega, method="integrator", rtol=rtol)
        for name in ("eps", "tau_b", "x_b", "tau_c"):
            assert abs(getattr(got, name) / float(getattr(truth, name)) - 1) <= integrator_bound(rtol, ex), name


def test_eps_answers_down_to_1e_300_but_contact_times_stop_at_1e_100():
    from restitution.core.errors import ParameterError
    from restitution.core.problem import Problem
    from restitution.fast.ladder import epsilon

    r = epsilon(Problem.of("3/2", "1"), omega=[1e-300, 1e-200], tol=1e-9, method="integrator", build=False)
    np.testing.assert_allclose(r.eps, 2 ** 0.25 * np.array([1e-300, 1e-200]), rtol=1e-9)
    assert collide("3/2", "1", 1e-100, method="integrator").ended_by == "force"
    with pytest.raises(ParameterError, match=r"\[1e-100, 1e\+14\]"):
        collide("3/2", "1", 1e-120, method="integrator")

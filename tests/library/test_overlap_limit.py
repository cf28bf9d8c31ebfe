"""The overlap rule's viscous limit eps ~ C Omega^k (restitution.core.overlap_limit) against the integrators."""

from fractions import Fraction

import numpy as np
import pytest

from restitution.core.asymptotics import inner_constant
from restitution.core.collision import collide
from restitution.core.errors import ParameterError
from restitution.core.highprec import reference_collision
from restitution.core.problem import Problem
from restitution.core.overlap_limit import inner_rebound_speed, overlap_limit

PAIRS = [("3/2", "1/2"), ("3/2", "1"), ("1", "1/2"), ("2", "1"), ("3", "3/2")]


@pytest.mark.parametrize("alpha,gamma", PAIRS)
@pytest.mark.slow
def test_law_matches_reference_integrator_at_small_omega(alpha, gamma):
    L = overlap_limit((alpha, gamma))
    assert L.k_exact == (Fraction(gamma) + 1) / (2 * Fraction(gamma) + 1 - Fraction(alpha))
    assert L.C_error < 1e-9 * L.C
    for om in (1e-2, 1e-4, 1e-6):
        e = collide(Problem.of(alpha, gamma, "overlap"), om).eps
        assert e == pytest.approx(L.C * om ** L.k, rel=1e-9)


@pytest.mark.parametrize("alpha,gamma", PAIRS[:3])
@pytest.mark.slow
def test_exponent_measured_by_the_integrator(alpha, gamma):
    L = overlap_limit((alpha, gamma))
    e1, e2 = (collide(Problem.of(alpha, gamma, "overlap"), om).eps for om in (1e-5, 1e-3))
    assert np.log(e2 / e1) / np.log(1e-3 / 1e-5) == pytest.approx(L.k, rel=1e-9)


def test_prefactor_matches_independent_mpmath_integrator():
    # at Omega = 1e-2 the correction to the law is below 1e-30 (exp(-c/Omega), c > 0.8)
    for alpha, gamma in PAIRS[:2]:
        L = overlap_limit((alpha, gamma))
        e = float(reference_collision(Problem.of(alpha, gamma, "overlap"), 1e-2, digits=20).eps)
        assert e / 1e-2 ** L.k == pytest.approx(L.C, rel=1e-10)


def test_correction_is_negative_and_dies_out_faster_than_a_power():
    L = overlap_limit(("3/2", "1"))
    devs = [collide(Problem.of("3/2", "1", "overlap"), om).eps / (L.C * om ** L.k) - 1.0 for om in (0.3, 0.1, 0.05)]
    assert all(d < 0 for d in devs)
    assert abs(devs[1]) < 1e-2 * abs(devs[0]) and abs(devs[2]) < 1e-3 * abs(devs[1])


@pytest.mark.slow
def test_same_inner_problem_as_the_force_rule_below_alpha_equal_gamma():
    # for alpha < gamma both rules coincide and asymptotics.inner_constant integrates the same problem
    for alpha, gamma in (("1/2", "1"), ("1", "2")):
        assert inner_rebound_speed((alpha, gamma))[0] == pytest.approx(inner_constant((alpha, gamma)), rel=1e-9)


def test_equal_exponents_are_exact():
    L = overlap_limit(("1", "1"))
    assert L.C == 1.0 and L.k == 1.0


def test_rebound_speed_is_independent_of_impact_speed():
    L = overlap_limit(("3/2", "1"))
    D1, D2 = 0.000296, 0.0109
    p1, p2 = L.speed_exponents
    assert (p1, p2) == (Fraction(4, 3), Fraction(-5, 3))
    v = float(L.rebound_speed(D1, D2))
    for g in (100.0, 1000.0):
        omega = D1 * g ** (-0.75) * D2 ** (-1.25)
        assert collide(Problem.of("3/2", "1", "overlap"), omega).eps * g == pytest.approx(v, rel=1e-9)


@pytest.mark.parametrize("alpha,gamma", [("1", "0"), ("2", "1/2"), ("1/2", "1")])
def test_refused_outside_its_range(alpha, gamma):
    with pytest.raises(ParameterError):
        overlap_limit((alpha, gamma))

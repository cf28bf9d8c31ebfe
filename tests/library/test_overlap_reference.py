"""The high-precision reference at any Omega (core.highprec.highprec_eps, issue 54): below CREEP_MAX the
creeping return through its inner problem (C to 30 digits by Taylor series in z = y^(-m)), above it
the Taylor integration of the whole collision. Checked against that integration where both run, against
the exact C = 1 of alpha = gamma, against the double-precision C of core.overlap_limit, and, through
the Taylor integration it hands over to, against the exact family's closed form up to Omega = 1e20."""

from __future__ import annotations

import mpmath
import numpy as np
import pytest

from restitution.core.collision import UnresolvedError, collide
from restitution.core.errors import ParameterError
from restitution.core.exact_family import exact_eps, sticking_threshold
from restitution.core.exponents import as_exponents
from restitution.core.problem import Problem
from restitution.core.highprec import (CREEP_MAX, creep_distance_bound, creep_rebound_speed, highprec_eps,
                                      reference_collision)
from restitution.core.overlap_limit import overlap_limit

SEED = int(np.random.SeedSequence().entropy % 2**32)
RNG = np.random.default_rng(SEED)
# Kim's pair, LAMMPS' Hertz with viscoelastic damping, a pair whose rules coincide (alpha < gamma), one more
PAIRS = [("3/2", "1"), ("3/2", "1/2"), ("1/2", "1"), ("5/2", "3/2")]


def _law_at(pair, w: float) -> tuple[mpmath.mpf, mpmath.mpf]:
    """C Omega^k and its accuracy, from the creep's C, at an Omega where highprec_eps integrates."""
    C, err = creep_rebound_speed(pair, digits=25)
    ex = as_exponents(pair)
    k = (ex.gamma + 1) / (2 * ex.gamma + 1 - ex.alpha)
    with mpmath.workdps(40):
        return C * mpmath.mpf(w) ** (mpmath.mpf(k.numerator) / k.denominator), err


@pytest.mark.parametrize("pair", [PAIRS[0], PAIRS[2]] + [pytest.param(p, marks=pytest.mark.slow) for p in PAIRS[1::2]])
def test_the_creep_law_is_the_taylor_integration_where_both_run(pair):
    """At Omega = 1e-3 the creep's distance from C Omega^k is below 1e-17 by its stated bound: the two
    references, which share only the return leg's last unit of y, agree to their 20 digits (25 and 30
    measured: 2.7e-30 for Kim's pair)."""
    for w in (1e-3,):
        full = reference_collision(Problem.of(*pair, end="overlap"), w, digits=20)
        law, err = _law_at(pair, w)
        with mpmath.workdps(40):
            assert abs(law / full.eps - 1) <= 10 * (err + full.error_estimate), (pair, w)


@pytest.mark.slow   # the Taylor integration creeps: ~0.2/Omega steps, a minute at 1e-5
def test_the_two_references_agree_down_to_where_the_taylor_integration_reaches():
    for w in (1e-4, CREEP_MAX):
        full = reference_collision(Problem.of("3/2", "1", end="overlap"), w, digits=18)
        law, err = _law_at(("3/2", "1"), w)
        with mpmath.workdps(40):
            assert abs(law / full.eps - 1) <= 10 * (err + full.error_estimate), w


@pytest.mark.parametrize("pair", PAIRS)
def test_the_stated_distance_from_the_creep_holds_where_it_is_visible(pair):
    """At Omega 1e-2..1e-1 the collision is visibly off C Omega^k (1e-4 at 0.1): the bound that
    highprec_eps adds below CREEP_MAX is checked there against the whole integration."""
    for w in (0.1, 0.03):
        full = reference_collision(Problem.of(*pair, end="overlap"), w, digits=16)
        law, err = _law_at(pair, w)
        with mpmath.workdps(40):
            assert abs(law / full.eps - 1) <= creep_distance_bound(pair, w), (pair, w)


def test_alpha_equal_gamma_creeps_at_exactly_the_speed_one():
    for pair in [("1", "1"), ("1/2", "1/2"), ("2", "2")]:
        C, err = creep_rebound_speed(pair, digits=30)
        assert C == 1 and err == 0


@pytest.mark.parametrize("pair", [("3/2", "1"), ("3/2", "1/2"), ("5/4", "1/2"), ("5/2", "3/2"), ("1", "1/3")])
def test_the_double_precision_prefactor_is_within_its_stated_error(pair):
    C, err = creep_rebound_speed(pair, digits=20)
    lim = overlap_limit(pair)
    assert err < 1e-18
    assert abs(lim.C - float(C)) <= lim.C_error + 4e-16 * float(C)


def test_where_the_bodies_can_stick_there_is_no_creep():
    with pytest.raises(ParameterError, match="alpha < 2 gamma"):
        creep_rebound_speed(("3", "1"))


def test_the_creep_reference_meets_the_scipy_reference_at_the_far_end():
    """Omega 1e-12..1e-6 drawn at random (seed printed on failure): Radau at rtol 1e-11, within its bound."""
    for pair in [("3/2", "1"), ("3/2", "1/2")]:
        for w in 10.0 ** RNG.uniform(-12, -6, 1):
            eps, err = highprec_eps(Problem.of(*pair, end="overlap"), w, digits=20)
            ref = collide(Problem.of(*pair, end="overlap"), w, rtol=1e-10)
            assert err < 1e-19
            assert abs(ref.eps / float(eps) - 1) <= ref.error_bound, f"seed {SEED}: {pair} Omega={w:.6g}"


@pytest.mark.parametrize("end", ["force", "overlap"])
@pytest.mark.parametrize("pair", [("1", "0"), ("3", "1"), ("2", "1/2")])
def test_the_exact_family_up_to_omega_1e20(pair, end):
    """The closed form of alpha = 2 gamma + 1 (the linear dashpot) against highprec_eps at random Omegas
    from just above the overlap rule's sticking threshold to 1e20 (seed printed on failure)."""
    lo = float(sticking_threshold(pair)) * 1.5 if end == "overlap" else 1e-9
    for w in 10.0 ** RNG.uniform(np.log10(lo), 20, 2):
        eps, err = highprec_eps(Problem.of(*pair, end=end), w, digits=16)
        exact = float(np.asarray(exact_eps(Problem.of(*pair, end=end), w)).ravel()[0])
        assert err < 1e-14
        assert abs(exact / float(eps) - 1) <= 1e-13, f"seed {SEED}: {pair} {end} Omega={w:.6g}"


def test_the_scipy_reference_answers_from_a_tighter_rtol_with_that_runs_bound():
    """(1, 1/2) at Omega = 1e-11: here Radau loses its way in the creep at rtol 1e-12 and 1e-13 and
    answers at 1e-14 (whether it does differs between machines); collide answers from the tighter run
    and states that run's bound, which the creep reference confirms, or refuses in one line."""
    try:
        ref = collide(Problem.of("1", "1/2", end="overlap"), 1e-11, rtol=1e-12)
    except UnresolvedError as err:
        assert "creeping return defeated the integrator" in str(err) and "\n" not in str(err)
        return
    assert ref.rtol <= 1e-12
    eps, err = highprec_eps(Problem.of("1", "1/2", end="overlap"), 1e-11, digits=20)
    assert err < 1e-19
    assert abs(ref.eps / float(eps) - 1) <= ref.error_bound


def test_a_refused_rtol_is_retried_tighter_never_looser(monkeypatch):
    """The retry's order, on any machine: the integration at the asked rtol made to lose its way, the
    answer comes from rtol / 10; when every run loses its way, the first refusal stands."""
    from restitution.core import collision

    real, asked = collision._collide, []

    def lost_first(problem, omega, rtol, t_eval, *, every=False):
        asked.append(rtol)
        if every or len(asked) == 1:
            raise UnresolvedError("rtol", rtol, "the creeping return defeated the integrator (made to)")
        return real(problem, omega, rtol, t_eval)

    monkeypatch.setattr(collision, "_collide", lost_first)
    got = collide(Problem.of("3/2", "1", end="overlap"), 0.01, rtol=1e-10)
    assert asked == pytest.approx([1e-10, 1e-11]) and got.rtol == pytest.approx(1e-11)
    asked.clear()
    monkeypatch.setattr(collision, "_collide", lambda *a: lost_first(*a, every=True))
    with pytest.raises(UnresolvedError, match="rtol = 1e-10"):
        collide(Problem.of("3/2", "1", end="overlap"), 0.01, rtol=1e-10)
    assert asked == pytest.approx([1e-10, 1e-11, 1e-12])

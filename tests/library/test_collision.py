"""Reference integrator: self-consistency, exact limits, end types, the inverse run, bad input."""

from __future__ import annotations

import json
import math
from fractions import Fraction

import numpy as np
import pytest

from restitution.core.collision import (Collision, InverseCollision, RunawayError, Trajectory, collide,
                                   collide_many, inverse_collide)
from restitution.core.dashpot import dashpot_collision, dashpot_trajectory
from restitution.core.errors import ParameterError
from restitution.core.exponents import Exponents
from restitution.core.problem import Problem

QUANTITIES = ("eps", "tau_b", "x_b", "tau_c", "x_c")
PAIRS = [("3/2", "1"), ("3/2", "1/2"), ("1", "0"), ("2", "1"), ("3", "3/2"), ("1", "1"), ("5/4", "3/2"),
         ("5/2", "0")]
OMEGAS = [1e-3, 1e-2, 0.1, 1.0, 10.0, 100.0, 1e3]


def _relative_errors(a: Collision, b: Collision) -> dict:
    return {q: abs(getattr(a, q) - getattr(b, q)) / abs(getattr(b, q)) if getattr(b, q) else abs(getattr(a, q))
            for q in QUANTITIES}


@pytest.fixture(scope="module")
def tight():
    """collide(..., rtol=1e-14) memoised across tests (the expensive half of every comparison)."""
    cache = {}

    def get(alpha, gamma, omega):
        key = (alpha, gamma, omega)
        if key not in cache:
            cache[key] = collide((alpha, gamma), omega, rtol=1e-14)
        return cache[key]
    return get


# ------------------------------------------------------------------ accuracy
@pytest.mark.parametrize("alpha,gamma", PAIRS)
@pytest.mark.slow
def test_default_rtol_agrees_with_tightest(alpha, gamma, tight):
    for omega in OMEGAS:
        errors = _relative_errors(collide((alpha, gamma), omega), tight(alpha, gamma, omega))
        assert max(errors.values()) < 1e-9, (omega, errors)


@pytest.mark.parametrize("alpha,gamma,omega", [("3/2", "1", 1e-8), ("3/2", "1", 1e8), ("1", "0", 1e8),
                                               ("5/2", "0", 1e-8), ("3", "3/2", 1e8), ("5/4", "3/2", 1e-6),
                                               ("1", "1", 1e8)])
@pytest.mark.slow
def test_extremes_stay_accurate(alpha, gamma, omega, tight):
    """Huge Omega: x_c ~ (eps/Omega)^(1/(alpha-gamma)) is tiny, resolved in u. Tiny Omega: v creeps
    at O(Omega) and the force is carried as a state, so tau_c keeps its relative accuracy."""
    hit = collide((alpha, gamma), omega)
    errors = _relative_errors(hit, tight(alpha, gamma, omega))
    assert max(errors.values()) < 1e-9, errors
    assert all(math.isfinite(getattr(hit, q)) for q in QUANTITIES)


@pytest.mark.parametrize("omega", [1e-8, 1e-3, 0.1, 0.2, 0.25 * (1 - 1e-9), 0.25, 0.25 * (1 + 1e-9), 0.3, 1.0,
                                   10.0, 1e3, 1e8])
def test_linear_dashpot_matches_closed_form(omega):
    hit, exact = collide((1, 0), omega), dashpot_collision(omega)
    errors = _relative_errors(hit, exact)
    assert max(errors.values()) < 1e-9, errors
    assert hit.ended_by == exact.ended_by == "force"


def test_trajectory_matches_closed_form_dashpot():
    omega = 0.7
    exact = dashpot_collision(omega)
    tau = np.linspace(0.0, 1.2 * exact.tau_c, 241)
    traj = collide((1, 0), omega, t_eval=tau).trajectory
    assert isinstance(traj, Trajectory)
    assert traj.tau[-1] <= exact.tau_c * (1 + 1e-12) < tau[-1]   # samples past the end are dropped
    assert np.array_equal(traj.tau, tau[: traj.tau.size])
    x, v = dashpot_trajectory(traj.tau, omega)
    assert np.max(np.abs(traj.x - x)) < 1e-10 * exact.x_b
    assert np.max(np.abs(traj.v - v)) < 1e-10
    assert traj.x[0] == 0.0 and traj.v[0] == 1.0
    with pytest.raises(ValueError):
        traj.x[0] = 1.0   # results are read-only


@pytest.mark.parametrize("alpha,gamma,omega", [("3/2", "1", 1.0), ("5/4", "3/2", 1.0), ("3/2", "1", 1e4)])
def test_trajectory_runs_through_every_leg_and_ends_on_the_contact_end(alpha, gamma, omega):
    first = collide((alpha, gamma), omega)
    tau = np.linspace(0.0, first.tau_c, 400)
    traj = collide((alpha, gamma), omega, t_eval=tau).trajectory
    assert traj.tau.size == tau.size and np.all(np.isfinite(traj.x)) and np.all(np.isfinite(traj.v))
    assert np.all(traj.x >= 0.0)
    assert traj.x[-1] == pytest.approx(first.x_c, rel=1e-8, abs=1e-12 * first.x_b)
    assert traj.v[-1] == pytest.approx(-first.eps, rel=1e-8)
    assert np.max(traj.x) <= first.x_b * (1 + 1e-12)
    assert np.all(np.diff(traj.v) < 0)   # the force decelerates the motion until it vanishes


# ------------------------------------------------------------------ exact limits and physics
def test_damped_only_limit_gamma_one():
    """Omega -> 0 with gamma = 1: x0 = sqrt(2) tanh(tau / sqrt(2)), so x_b -> sqrt(2)."""
    deviations = [math.sqrt(2) - collide(("3/2", 1), w).x_b for w in (1e-4, 1e-6, 1e-8)]
    assert all(d > 0 for d in deviations)
    assert deviations[0] > deviations[1] > deviations[2]
    assert deviations[2] < 1e-6
    tau = np.linspace(0.0, 6.0, 61)
    traj = collide(("3/2", 1), 1e-12, t_eval=tau).trajectory
    assert np.max(np.abs(traj.x - math.sqrt(2) * np.tanh(traj.tau / math.sqrt(2)))) < 1e-10
    assert np.max(np.abs(traj.v - 1.0 / np.cosh(traj.tau / math.sqrt(2)) ** 2)) < 1e-10


@pytest.mark.parametrize("alpha,gamma,end", [("3/2", "1", "force"), ("3/2", "1/2", "force"), ("5/2", "0", "force"),
                                             ("1", "1", "separation"), ("3/2", "3/2", "separation"),
                                             ("5/4", "3/2", "separation"), ("1/2", "1", "separation")])
@pytest.mark.parametrize("omega", [1e-2, 1.0, 1e2])
def test_end_type_follows_sign_of_alpha_minus_gamma(alpha, gamma, end, omega):
    """At f = 0 (v < 0), f' = Omega (alpha-gamma) x^(alpha-gamma-1) v: f can only cross zero when
    alpha > gamma; otherwise x reaches 0 first."""
    hit = collide((alpha, gamma), omega)
    assert hit.ended_by == end
    assert 0.0 < hit.eps < 1.0
    assert 0.0 < hit.tau_b < hit.tau_c and 0.0 < hit.x_b
    assert all(math.isfinite(getattr(hit, q)) for q in QUANTITIES)
    if end == "separation":
        assert hit.x_c == 0.0
    else:
        assert 0.0 < hit.x_c < hit.x_b


def test_alpha_equals_gamma_rebounds_slower_than_omega():
    """alpha = gamma: f = Omega + v obeys f' = -x^gamma f, stays positive, so eps < Omega; for small
    Omega, f has decayed by e^-(integral of x^gamma) and eps is Omega to all digits."""
    assert Fraction(1) - Fraction(collide((1, 1), 0.1).eps) / Fraction(0.1) == pytest.approx(1.8e-4, rel=0.05)
    assert collide((1, 1), 1e-3).eps == pytest.approx(1e-3, rel=1e-13)


# ------------------------------------------------------------------ inverse collision
def _retrace(alpha, gamma, omega):
    ex = Exponents.parse(alpha, gamma)
    fwd = collide((alpha, gamma), omega)
    k = float(ex.gamma) + 1.0
    omega_tilde = omega * fwd.eps ** float(ex.omega_exponent)
    inv = inverse_collide((alpha, gamma), omega_tilde, fwd.x_c * fwd.eps ** (-1.0 / k))
    return fwd, inv, fwd.eps ** (-float(ex.gamma) / k)


@pytest.mark.parametrize("alpha,gamma", [p for p in PAIRS if Fraction(p[0]) > Fraction(p[1])])
@pytest.mark.parametrize("omega", [1e-3, 0.1, 1.0, 10.0, 1e3])
def test_inverse_retraces_forward_force_end(alpha, gamma, omega):
    """Run backwards from (x_c, eps) and rescaled, the inverse ends at x~' = -1/eps after tau_c."""
    fwd, inv, time_back = _retrace(alpha, gamma, omega)
    assert isinstance(inv, InverseCollision)
    assert inv.v_end * fwd.eps == pytest.approx(-1.0, rel=1e-8)
    assert inv.tau_end * time_back == pytest.approx(fwd.tau_c, rel=1e-8)
    assert (inv.tau_end - inv.tau_b) * time_back == pytest.approx(fwd.tau_b, rel=1e-8)
    assert inv.x_b * fwd.eps ** (1.0 / (float(Fraction(gamma)) + 1)) == pytest.approx(fwd.x_b, rel=1e-8)


@pytest.mark.parametrize("alpha,gamma", [("1", "1"), ("5/4", "3/2")])
@pytest.mark.parametrize("omega", [1.0, 100.0])
def test_inverse_retraces_forward_separation_end(alpha, gamma, omega):
    """Separation ends retrace too, from x~ = 0; at small Omega they cannot: the creeping return
    relaxes like e^-(integral of x^gamma), which the inverse amplifies by the same factor."""
    fwd, inv, time_back = _retrace(alpha, gamma, omega)
    assert inv.x_start == 0.0
    assert inv.v_end * fwd.eps == pytest.approx(-1.0, rel=1e-8)
    assert inv.tau_end * time_back == pytest.approx(fwd.tau_c, rel=1e-8)


@pytest.mark.parametrize("omega", [0.3, 1.0, 7.0])
def test_inverse_linear_dashpot_is_exact(omega):
    """x~'' - x~' + Omega x~ = 0 from 0: x~ = e^(tau/2) sin(w tau)/w returns at tau = pi/w."""
    w = math.sqrt(omega - 0.25)
    inv = inverse_collide((1, 0), omega)
    assert inv.tau_end == pytest.approx(math.pi / w, rel=1e-10)
    assert inv.v_end == pytest.approx(-math.exp(math.pi / (2 * w)), rel=1e-10)
    assert inv.tau_b == pytest.approx(math.atan2(-2 * w, 1) / w + math.pi / w, rel=1e-10)


@pytest.mark.parametrize("alpha,gamma,omega", [(1, 0, 0.25), (1, 0, 0.1), ("3/2", 1, 0.1), (3, "3/2", 1e-2),
                                               (1, 1, 1.0)])
def test_inverse_runaway_is_reported(alpha, gamma, omega):
    """Negative damping can win for good (alpha <= 2 gamma + 1): the inverse never turns around.
    (1, 1, 1.0) sits exactly on the separatrix x~ = tau~, caught by the generous bound."""
    with pytest.raises(RunawayError) as info:
        inverse_collide((alpha, gamma), omega)
    assert isinstance(info.value, ParameterError) and info.value.field == "omega_tilde"


def test_inverse_near_threshold_returns_from_far_away():
    """Just above Omega~ = 1/4 the linear inverse does come back, from x~ ~ 5e6."""
    inv = inverse_collide((1, 0), 0.26)
    assert inv.tau_end == pytest.approx(math.pi / 0.1, rel=1e-9)
    assert inv.x_b > 1e6


# ------------------------------------------------------------------ API
def test_as_dict_is_json_ready():
    hit = collide(("3/2", 1), 0.5)
    data = json.loads(json.dumps(hit.as_dict()))
    assert data == {"alpha": "3/2", "gamma": "1", "omega": 0.5, "eps": hit.eps, "tau_b": hit.tau_b,
                    "x_b": hit.x_b, "tau_c": hit.tau_c, "x_c": hit.x_c, "end": "force", "ended_by": "force",
                    "one_minus_eps": hit.one_minus_eps, "error_bound": 10 * 1e-12 + 1e-13,
                    "one_minus_eps_bound": 10 * 1e-12 + 1e-13}
    assert hit.direction == "forward" and hit.rtol == 1e-12 and hit.trajectory is None
    assert isinstance(hit.alpha, Fraction) and hit.alpha == Fraction(3, 2)
    json.dumps(inverse_collide(("3/2", 1), 6.0).as_dict())


def test_exponent_spellings_agree():
    a = collide(("3/2", "1"), 0.5)
    for problem in [(1.5, 1), (Fraction(3, 2), 1.0), Exponents.parse("3/2", 1), Problem.of("3/2", 1)]:
        assert collide(problem, 0.5) == a


def test_collide_many_matches_single_calls():
    omegas = [0.01, 1.0, 100.0]
    many = collide_many(("5/4", "3/2"), omegas, rtol=1e-10)
    assert set(many) == {"eps", "tau_b", "x_b", "tau_c", "x_c", "ended_by"}
    for i, w in enumerate(omegas):
        one = collide(("5/4", "3/2"), w, rtol=1e-10)
        assert [many[q][i] for q in QUANTITIES] == [getattr(one, q) for q in QUANTITIES]
        assert many["ended_by"][i] == one.ended_by
    assert many["ended_by"].dtype.kind == "U"


@pytest.mark.parametrize("kwargs", [
    {"omega": 0.0}, {"omega": -1.0}, {"omega": float("nan")}, {"omega": float("inf")}, {"omega": "x"},
    {"omega": 1.0, "rtol": 1e-15}, {"omega": 1.0, "rtol": 1e-2}, {"omega": 1.0, "rtol": float("nan")},
    {"omega": 1.0, "rtol": 0}, {"omega": 1.0, "alpha": 0}, {"omega": 1.0, "alpha": "-3/2"},
    {"omega": 1.0, "gamma": -1}, {"omega": 1.0, "t_eval": [1.0, 0.5]}, {"omega": 1.0, "t_eval": [-1.0, 0.5]},
    {"omega": 1.0, "t_eval": [[0.0, 1.0]]}, {"omega": 1.0, "t_eval": [0.0, float("nan")]},
])
def test_bad_input_is_a_parameter_error(kwargs):
    args = {"alpha": "3/2", "gamma": 1, **kwargs}
    alpha, gamma, omega = args.pop("alpha"), args.pop("gamma"), args.pop("omega")
    with pytest.raises(ParameterError):
        collide((alpha, gamma), omega, **args)
    with pytest.raises(ParameterError):
        inverse_collide((alpha, gamma), omega if omega != 1.0 else 6.0, **args)


@pytest.mark.parametrize("x_start", [-1.0, float("nan"), float("inf"), "a"])
def test_bad_inverse_start_is_a_parameter_error(x_start):
    with pytest.raises(ParameterError):
        inverse_collide(("3/2", 1), 6.0, x_start)


def test_bad_omegas_array_is_a_parameter_error():
    with pytest.raises(ParameterError):
        collide_many(("3/2", 1), [[1.0, 2.0]])
    with pytest.raises(ParameterError):
        collide_many(("3/2", 1), [1.0, -2.0])


@pytest.mark.parametrize("alpha, gamma, omega", [("3/2", "1", 1e4), ("3/2", "1", 1e10), ("1", "3/2", 1e8),
                                                 ("1", "3/2", 1e10), ("2", "1/2", 1e9), ("3/2", "1/2", 100.0),
                                                 ("3/2", "1", 0.5)])
def test_one_minus_eps_is_accurate_relative_to_itself(alpha, gamma, omega):
    """1 - eps from the dissipated energy keeps its relative accuracy where 1 - eps by subtraction
    has none (the elastic limit): against the mpmath reference at 30 digits, to 1e-9 relative."""
    from restitution.core.highprec import reference_collision

    hit = collide((alpha, gamma), omega, rtol=1e-12)
    exact = float(1 - reference_collision((alpha, gamma), omega, digits=30).eps)
    assert hit.one_minus_eps == pytest.approx(exact, rel=1e-9)
    assert hit.eps < 1.0 or hit.one_minus_eps < 1e-16   # never above one; 1.0 only where the loss rounds away


def test_one_minus_eps_agrees_with_a_tighter_run():
    loose, tight = (collide(("1", "3/2"), 1e6, rtol=r).one_minus_eps for r in (1e-10, 1e-13))
    assert loose == pytest.approx(tight, rel=1e-8)

"""The exact family alpha = 2 gamma + 1 (core.exact_family, the exact-family rung, collide's closed
form): checked against methods that know nothing of the mapping onto the dashpot, the scipy
reference integrator (fast) and mpmath's Taylor integrator (slow), under both end rules, Omega from
1e-6 to 1e6 and at the overlap rule's sticking threshold 1/(4 (gamma+1))."""

from __future__ import annotations

import doctest
import io
import json
import math
from fractions import Fraction

import numpy as np
import pytest

import restitution
from restitution.api import Ladder, collide
from restitution.cli import main
from restitution.core.problem import Problem
from restitution.core import exact_family
from restitution.core.collision import StickError, UnresolvedError, collide as reference_collide
from restitution.core.dashpot import dashpot_collision
from restitution.core.errors import ParameterError
from restitution.core.exact_family import eps_bound, exact_collision, exact_eps, in_family, sticking_threshold
from restitution.core.highprec import reference_collision

#: (alpha, gamma): Hertz with delta^(1/4) damping, (2, 1/2), (3, 1), the dashpot, two more gammas.
PAIRS = [("3/2", "1/4"), ("2", "1/2"), ("3", "1"), ("1", "0"), ("5/3", "1/3"), ("19/5", "7/5")]
OMEGAS = [1e-6, 1e-3, 0.05, 0.3, 1.0, 7.0, 1e3, 1e6]
RULES = ("force", "overlap")
RTOL = 1e-12
#: A closed-form time against the reference's: quad's 1e-14 besides the reference's own bound.
TIME_SLACK = 1e-13


def _omegas(alpha, gamma, end):
    """OMEGAS, under the overlap rule only those above the threshold, plus 1.01 times it."""
    if end == "force":
        return OMEGAS
    th = float(sticking_threshold((alpha, gamma)))
    return [w for w in OMEGAS if w > th] + [th * 1.01]


def test_doctests_run():
    result = doctest.testmod(exact_family, optionflags=doctest.ELLIPSIS)
    assert result.attempted >= 10 and result.failed == 0


@pytest.mark.parametrize("end", RULES)
@pytest.mark.parametrize("alpha,gamma", PAIRS)
def test_against_the_reference_integrator(alpha, gamma, end):
    """eps, 1 - eps, tau_b, x_b, tau_c, x_c of the closed form within the reference's stated bound."""
    for w in _omegas(alpha, gamma, end):
        got = exact_collision(Problem.of(alpha, gamma, end), w)
        ref = reference_collide(Problem.of(alpha, gamma, end), w, rtol=RTOL)
        assert got.ended_by == ref.ended_by, w
        assert abs(got.eps / ref.eps - 1) <= ref.error_bound + got.error_bound, (w, got.eps, ref.eps)
        assert abs(got.one_minus_eps / ref.one_minus_eps - 1) <= ref.one_minus_eps_bound + got.one_minus_eps_bound, w
        for f in ("tau_b", "x_b", "tau_c") + (("x_c",) if end == "force" else ()):
            # the located events carry rtol-size errors in time and place (100 rtol), more near the
            # overlap rule's sticking threshold, where the reference widens its own bound
            tol = max(100 * RTOL, ref.error_bound) + TIME_SLACK
            assert math.isclose(getattr(got, f), getattr(ref, f), rel_tol=tol), (w, f)


@pytest.mark.slow
@pytest.mark.parametrize("end", RULES)
@pytest.mark.parametrize("alpha,gamma", PAIRS[:3] + PAIRS[4:5])
def test_against_mpmath_at_rounding_level(alpha, gamma, end):
    """eps within its stated bound (rounding level) of mpmath's Taylor integrator at 22 digits, 1 - eps
    within LOSS_ULPS u, tau_c and tau_b within 3e-14 (quad)."""
    worst = 0.0
    for w in [1e-6, 0.3, 7.0, 1e6] if end == "force" else [float(sticking_threshold((alpha, gamma))) * 1.01, 0.3, 7.0, 1e6]:
        got = exact_collision(Problem.of(alpha, gamma, end), w)
        hp = reference_collision(Problem.of(alpha, gamma, end), w, digits=22)
        err = abs(got.eps / float(hp.eps) - 1)
        worst = max(worst, err / got.error_bound)
        assert err <= got.error_bound, (w, err, got.error_bound)
        assert abs(got.one_minus_eps / float(1 - hp.eps) - 1) <= got.one_minus_eps_bound, w
        for f in ("tau_b", "tau_c", "x_b"):
            assert math.isclose(getattr(got, f), float(getattr(hp, f)), rel_tol=3e-14), (w, f)
    assert worst > 0   # the comparison was made, not vacuous


@pytest.mark.parametrize("alpha,gamma", PAIRS)
def test_sticking_threshold_exactly_under_the_overlap_rule(alpha, gamma):
    """Just below 1/(4 (gamma+1)) every door refuses with StickError; just above, the closed form
    answers and the reference integrator agrees (it knows nothing of the threshold's formula)."""
    th = sticking_threshold((alpha, gamma))
    assert th == Fraction(1, 4) / (Fraction(gamma) + 1)
    below = math.nextafter(float(th), 0.0)
    for call in (lambda w: exact_collision(Problem.of(alpha, gamma, "overlap"), w),
                 lambda w: exact_eps(Problem.of(alpha, gamma, "overlap"), w),
                 lambda w: collide(alpha, gamma, w, method="closed-form", end="overlap"),
                 lambda w: restitution.epsilon(alpha=alpha, gamma=gamma, omega=w, end="overlap")):
        with pytest.raises(StickError, match="contact never ends here"):
            call(below)
    above = float(th) * (1 + 1e-3)
    got = restitution.epsilon(alpha=alpha, gamma=gamma, omega=above, end="overlap")
    assert got.method == "exact-family" and 0 < float(got.eps) < 1e-30
    ref = reference_collide(Problem.of(alpha, gamma, "overlap"), above, rtol=RTOL)
    assert abs(float(got.eps) / ref.eps - 1) <= ref.error_bound + got.error_bound
    # the force rule is smooth across the threshold (no sticking there)
    f = exact_collision(Problem.of(alpha, gamma, "force"), below)
    assert abs(f.eps / reference_collide((alpha, gamma), below, rtol=RTOL).eps - 1) <= 1e-10


def test_eps_below_doubles_just_above_the_threshold_is_refused_in_one_line():
    w = float(sticking_threshold(("3/2", "1/4"))) * (1 + 1e-7)
    with pytest.raises(UnresolvedError, match="below the smallest normal double"):
        restitution.epsilon(alpha="3/2", gamma="1/4", omega=w, end="overlap")


def test_stuck_and_unresolved_are_parameter_errors():
    assert issubclass(StickError, ParameterError) and issubclass(UnresolvedError, ParameterError)
    with pytest.raises(ParameterError, match="2 gamma \\+ 1"):
        exact_collision(("3/2", "1/2"), 1.0)


@pytest.mark.parametrize("end", RULES)
@pytest.mark.parametrize("alpha,gamma", PAIRS)
def test_the_chooser_takes_the_exact_rung_first_and_builds_nothing(alpha, gamma, end, tmp_path):
    om = np.geomspace(1e-6, 1e6, 25)
    if end == "overlap":
        om = om[om > float(sticking_threshold((alpha, gamma)))]
    lad = Ladder((alpha, gamma), cache_dir=str(tmp_path), stream=io.StringIO())
    r = lad.with_end(end).evaluate(om)
    assert r.method == "exact-family" and r.error_bound < 1e-13
    assert not list(tmp_path.iterdir())   # no curve and no uniform fit built for these pairs
    assert lad.uniform() is None
    # even with everything its other rungs read built and cached, and a big request
    r = lad.with_end(end).evaluate(np.geomspace(1e-3, 1e3, 2000), build=True) if end == "force" else r
    assert r.method == "exact-family" and not list(tmp_path.glob("uniform*"))
    closed = next(c for c in r.candidates if c["method"] == "uniform")
    if (alpha, gamma) != ("1", "0"):
        assert not closed["available"] and "exact-family" in closed["reason"]


@pytest.mark.parametrize("end", RULES)
@pytest.mark.parametrize("alpha,gamma", [("2", "1/2"), ("3/2", "1/4")])
def test_cli_eps_answers_by_the_exact_rung(alpha, gamma, end, capsys):
    """The issue's acceptance: equal to the dashpot at (gamma+1) Omega to 1e-13 relative."""
    om = ["1e-6", "0.21", "1", "30", "1e6"] if end == "force" else ["0.21", "1", "30", "1e6"]
    assert main(["eps", "--alpha", alpha, "--gamma", gamma, "--omega", *om, "--end", end, "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["method"] == "exact-family" and out["error_bound"] < 1e-13
    k = float(Fraction(gamma) + 1)
    for w, e in zip(om, out["eps"]):
        assert abs(e / dashpot_collision(k * float(w), end).eps - 1) <= 1e-13


def test_cli_refuses_below_the_threshold(capsys):
    assert main(["eps", "--alpha", "2", "--gamma", "1/2", "--omega", "0.1666", "--end", "overlap"]) == 2
    err = capsys.readouterr().err
    assert "contact never ends here" in err and "1/(4 (gamma+1))" in err


def test_collide_closed_form_covers_the_family():
    got = collide("3", "1", 2.0, method="closed-form", end="overlap")
    ref = collide("3", "1", 2.0, end="overlap")
    assert got.rtol == 0.0 and abs(got.eps / ref.eps - 1) <= ref.error_bound + got.error_bound
    assert math.isclose(got.tau_c, ref.tau_c, rel_tol=1e-10)
    with pytest.raises(ParameterError, match="alpha = 2 gamma \\+ 1"):
        collide("3/2", "1/2", 1.0, method="closed-form")


def test_bounds_are_stated_and_monotone():
    """eps rises with Omega under both rules (the rung's bound is taken at the smallest Omega)."""
    om = np.geomspace(0.21, 1e8, 400)
    for end in RULES:
        e = exact_eps(Problem.of("3/2", "1/4", end), om)
        assert np.all(np.diff(e) > 0)
    assert float(eps_bound(1.0)) < 1e-15 and float(eps_bound(1e-300)) < 1e-12 and eps_bound(0.0) == np.inf
    assert in_family(("5/3", "1/3")) and not in_family(("3/2", "1"))


@pytest.mark.parametrize("alpha,gamma", [("3/2", "1/4"), ("3", "1")])
def test_extreme_omegas_against_the_reference_and_the_fast_integrator(alpha, gamma):
    """Beyond 1e-6..1e6: the reference's ends (1e-12, 1e10), and the compiled integrator at 1e14."""
    for w in (1e-12, 1e10):
        got, ref = exact_collision((alpha, gamma), w), reference_collide((alpha, gamma), w, rtol=RTOL)
        assert abs(got.eps / ref.eps - 1) <= ref.error_bound + got.error_bound, w
        assert math.isclose(got.tau_c, ref.tau_c, rel_tol=1e-9), w
    fast = collide(alpha, gamma, 1e14, method="integrator", rtol=1e-13)
    got = exact_collision((alpha, gamma), 1e14)
    assert math.isclose(got.eps, fast.eps, rel_tol=1e-11) and math.isclose(got.tau_c, fast.tau_c, rel_tol=1e-9)


@pytest.mark.slow   # 2 s: builds one master curve
def test_cached_false_answers_as_with_an_empty_cache(tmp_path):
    """What the DEM layer asks for a scene: no build read or made; the exact rung where it serves,
    the compiled integrator elsewhere, even with a master curve cached."""
    lad = Ladder(("3/2", "1/2"), cache_dir=str(tmp_path), stream=io.StringIO())
    om = np.geomspace(0.01, 100.0, 5)
    lad.master                                                            # the curve, built and cached
    assert lad.evaluate(om, build=False).method != "integrator"           # and used
    assert lad.evaluate(om, build=False, cached=False).method == "integrator"
    with pytest.raises(ParameterError, match="build"):
        lad.evaluate(om, build=True, cached=False)
    fam = Ladder(("3/2", "1/4"), cache_dir=str(tmp_path), stream=io.StringIO())
    assert fam.with_end("overlap").evaluate(om[om > 0.2], build=False, cached=False).method == "exact-family"


def test_dem_contact_times_and_reach_come_from_the_closed_form():
    """Hertz with tsuji damping is (3/2, 1/4): its contact time agrees with the reference integrator's
    (which knows nothing of the mapping) and costs no integration."""
    from restitution.dem.contact import Contact, scaled_collision
    for end in RULES:
        c = Contact("3/2", "1/4", 1e5, 80.0, end)
        ref = reference_collide(Problem.of("3/2", "1/4", end), c.omega(1.0), rtol=RTOL)
        assert c.collision(1.0).rtol == 0.0
        assert math.isclose(c.contact_time(1.0), ref.tau_c * float(c.material.time_scale(1.0)), rel_tol=1e-10)
    # beyond the reference's Omega range the closed form still answers (no flag for lack of a method)
    assert scaled_collision(("3/2", "1/4"), 1e13).tau_c > 0


def test_typed_e_table_hertz_and_hooke_rows_agree_exactly():
    """LIGGGHTS' hertz law is (3/2, 1/4), its hooke law (1, 0): both are the dashpot at the same
    Omega', so their typed-e rows are equal to rounding; and they match the reference integrator."""
    from restitution.dem.engines.typed_e_table import TYPED_E_CODES, typed_e_table
    rows = typed_e_table([0.1, 0.5, 0.9])
    for r in rows:
        for rule in ("limitForce off (default)", "limitForce on"):
            hertz, hooke = r[f"LIGGGHTS hertz, {rule}"], r[f"LIGGGHTS hooke, {rule}"]
            assert abs(hertz / hooke - 1) <= 1e-14
        c = TYPED_E_CODES["LAMMPS hertz + damping tsuji (default)"](r["e"])
        ref = reference_collide(Problem.of(c.alpha, c.gamma, c.end), c.omega(1.0), rtol=RTOL)
        assert abs(r["LAMMPS hertz + damping tsuji (default)"] / ref.eps - 1) <= ref.error_bound + 1e-14


def test_the_contact_time_quadrature_raises_where_it_cannot_meet_its_tolerance():
    """A step in the integrand keeps the two Gauss rules apart at every halving of the interval that
    holds it: the cap of halvings raises instead of returning the last, unresolved value."""
    from restitution.core.collision import IntegrationError

    def step(x):
        return 1.0 if x < 1.0 / 3.0 else 2.0
    with pytest.raises(IntegrationError, match="did not reach rtol"):
        exact_family._gauss_adaptive(step, 0.0, 1.0, exact_family.TIME_RTOL)
    # a smooth integrand still meets it: the integral of e^x over [0, 1]
    assert exact_family._gauss_adaptive(math.exp, 0.0, 1.0, exact_family.TIME_RTOL) == pytest.approx(
        math.e - 1.0, rel=1e-14)

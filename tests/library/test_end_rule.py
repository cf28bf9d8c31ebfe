"""The two end-of-contact rules: "force" (contact ends where the total force vanishes) and
"overlap" (contact ends when x returns to 0, the force turning attractive on the way)."""

import io
import json
import math

import pytest
from scipy.integrate import solve_ivp

import restitution
from restitution.api import collide
from restitution.cli import main
from restitution.core.collision import StickError
from restitution.core.problem import Problem
from restitution.core.dashpot import dashpot_collision
from restitution.core.errors import ParameterError
from restitution.core.highprec import reference_collision

RTOL = 1e-12
BOUND = 10 * RTOL + 1e-13        # the reference integrator's stated accuracy, for both rules


@pytest.mark.parametrize("omega", [0.3, 0.5, 1.0, 10.0, 1e3, 1e6])
def test_overlap_rule_matches_the_dashpots_half_period(omega):
    exact = dashpot_collision(omega, end="overlap")
    w = math.sqrt(omega - 0.25)
    assert exact.tau_c == pytest.approx(math.pi / w, rel=1e-15)
    got = collide(1, 0, omega, end="overlap", rtol=RTOL)
    assert got.ended_by == "separation" and got.end == "overlap" and got.x_c == 0.0
    for field in ("tau_b", "x_b", "tau_c", "one_minus_eps"):
        assert math.isclose(getattr(got, field), getattr(exact, field), rel_tol=BOUND), field
    assert math.isclose(got.eps, exact.eps, rel_tol=BOUND)


@pytest.mark.parametrize("omega", [0.3, 1.0, 1e3])
def test_force_rule_still_matches_the_dashpots_closed_form(omega):
    got = collide(1, 0, omega, rtol=RTOL)
    assert got == collide(1, 0, omega, rtol=RTOL, end="force")
    exact = dashpot_collision(omega)
    assert got.ended_by == exact.ended_by == "force" and got.end == "force"
    assert math.isclose(got.eps, exact.eps, rel_tol=BOUND)


@pytest.mark.parametrize("alpha, gamma, omega", [
    ("3/2", "1", 0.5), ("3/2", "1", 1e-3), ("3/2", "1/2", 1.0), ("3/2", "1/4", 1.0), ("3/2", "0", 1.0),
    ("2", "1/2", 0.3), ("3/2", "1/2", 200.0)])
@pytest.mark.slow
def test_overlap_rule_matches_mpmath(alpha, gamma, omega):
    truth = reference_collision(Problem.of(alpha, gamma, "overlap"), omega, digits=20)
    assert truth.ended_by == "separation" and truth.error_estimate < 1e-18
    got = collide(alpha, gamma, omega, rtol=RTOL, end="overlap")
    for field in ("eps", "tau_b", "x_b", "tau_c"):
        assert math.isclose(getattr(got, field), float(getattr(truth, field)), rel_tol=BOUND), field
    # the attractive phase costs energy: eps is lower than the force rule's
    assert got.eps < collide(alpha, gamma, omega, rtol=RTOL).eps


def _plain_ivp_overlap(alpha, gamma, omega):
    """An independent integration in (x, v) against tau, a different variable and solver, at the
    tightest tolerance: x^a of a negative trial x is clipped, the end is the event x = 0."""
    def rhs(t, y):
        x = max(y[0], 0.0)
        return [y[1], -omega * x ** alpha - x ** gamma * y[1]]

    def back(t, y):
        return y[0] if t > 1e-3 else 1.0
    back.terminal, back.direction = True, -1
    sol = solve_ivp(rhs, (0, 1e4), [0.0, 1.0], method="DOP853", rtol=2.3e-14, atol=1e-16, events=back)
    return -sol.y_events[0][0][1], sol.t_events[0][0]


@pytest.mark.parametrize("alpha, gamma, omega", [(1.5, 1.0, 0.5), (2.0, 1.0, 2.0), (1.5, 0.5, 1.0)])
def test_overlap_rule_matches_a_plain_integration_in_tau(alpha, gamma, omega):
    eps, tau_c = _plain_ivp_overlap(alpha, gamma, omega)
    got = collide(alpha, gamma, omega, end="overlap")
    assert math.isclose(got.eps, eps, rel_tol=1e-9) and math.isclose(got.tau_c, tau_c, rel_tol=1e-9)


@pytest.mark.parametrize("alpha, gamma, omega", [("1", "3/2", 0.3), ("1", "1", 2.0), ("1/2", "1", 1.0)])
def test_both_rules_agree_where_the_force_cannot_vanish(alpha, gamma, omega):
    force = collide(alpha, gamma, omega)
    overlap = collide(alpha, gamma, omega, end="overlap")
    assert force.ended_by == overlap.ended_by == "separation" and force.eps == overlap.eps


def test_overlap_loss_is_the_dissipated_energy():
    got = collide("3/2", "1/2", 1e4, end="overlap")
    assert got.one_minus_eps == pytest.approx(1.0 - got.eps, rel=1e-9)


@pytest.mark.parametrize("alpha, gamma, omega", [("1", "0", 0.25), ("1", "0", 0.01), ("3/2", "1/4", 0.2),
                                                 ("3", "1", 0.125)])
def test_overdamped_self_similar_returns_stick(alpha, gamma, omega):
    """alpha = 2 gamma + 1 and Omega <= 1/(4 (gamma+1)): the bodies never separate."""
    with pytest.raises(StickError, match="never ends"):
        collide(alpha, gamma, omega, end="overlap")
    assert collide(alpha, gamma, omega).eps > 0     # the force rule still ends


def test_just_above_the_stick_threshold_the_bodies_separate():
    got = collide("3/2", "1/4", 0.21, end="overlap")
    truth = reference_collision(Problem.of("3/2", "1/4", "overlap"), 0.21, digits=20)
    assert 0 < got.eps < 1e-3 and math.isclose(got.eps, float(truth.eps), rel_tol=BOUND)


def test_dashpot_closed_form_refuses_a_stuck_overlap():
    with pytest.raises(ParameterError, match="omega"):
        dashpot_collision(0.2, end="overlap")


def test_epsilon_overlap_uses_only_rungs_that_know_the_rule():
    res = restitution.epsilon(alpha="3/2", gamma=1, omega=[0.5, 2.0], end="overlap")
    assert res.method in ("uniform", "master", "integrator", "reference", "highprec")
    for w, e in zip([0.5, 2.0], res.eps):
        assert math.isclose(e, collide("3/2", 1, w, end="overlap").eps, rel_tol=1e-9)
    served = {c["method"] for c in res.candidates if c["available"]}
    assert served <= {"uniform", "master", "integrator", "reference", "highprec"}
    with pytest.raises(ParameterError, match="method"):   # the force rule's expansion
        restitution.epsilon(alpha="3/2", gamma=1, omega=0.5, end="overlap", method="elastic")
    dash = restitution.epsilon(alpha=1, gamma=0, omega=0.5, end="overlap")
    # the dashpot is the exact family's gamma = 0 member: that rung answers it first
    assert dash.method == "exact-family" and dash.eps == pytest.approx(dashpot_collision(0.5, "overlap").eps)


def test_fast_method_serves_the_overlap_rule():
    """It used to refuse it (it stopped at zero force); now it ends at x = 0 (issue 23)."""
    fast = collide("3/2", 1, 0.5, method="integrator", end="overlap")
    assert fast.end == "overlap" and fast.ended_by == "separation"
    assert math.isclose(fast.eps, collide("3/2", 1, 0.5, end="overlap").eps, rel_tol=1e-9)
    with pytest.raises(ParameterError, match="contact never ends"):
        collide("5/2", "1/2", 0.1, method="integrator", end="overlap")


def test_bad_end_is_one_line_exit_2(capsys):
    assert main(["collide", "--alpha", "3/2", "--gamma", "1", "--omega", "0.5", "--end", "both"]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "end" in err and "force, overlap" in err
    assert main(["eps", "--alpha", "1", "--gamma", "0", "--omega", "0.2", "--end", "overlap"]) == 2


def test_cli_end_overlap():
    out = io.StringIO()
    assert main(["collide", "--alpha", "3/2", "--gamma", "1", "--omega", "0.5", "--end", "overlap",
                 "--json"], out=out) == 0
    data = json.loads(out.getvalue())
    assert data["end"] == "overlap" and data["ended_by"] == "separation"
    assert data["eps"] == collide("3/2", 1, 0.5, end="overlap").eps
    out = io.StringIO()
    assert main(["eps", "--alpha", "3/2", "--gamma", "1", "--omega", "0.5", "--end", "overlap", "--json"],
                out=out) == 0
    assert json.loads(out.getvalue())["eps"][0] == pytest.approx(data["eps"], rel=1e-9)


# --- issue 28, classes 1 and 2: the creeping return under the overlap rule (gamma < 1, small Omega)
#: For alpha = 3/2, gamma = 1/2 the scaling x = Omega^2 X, tau = T / Omega turns the equation into
#: its Omega = 1 form with impact speed Omega^-3, whose rebound speed has a finite limit: eps is
#: C Omega^3 as soon as the creep has forgotten the impact (mpmath: the same C to 16 digits at
#: Omega = 1e-2, 1e-3 and 1e-4). C itself is read off mpmath at Omega = 1e-2 below.
def _overlap_constant():
    return float(reference_collision(Problem.of("3/2", "1/2", "overlap"), 1e-2, digits=25).eps) / 1e-6


@pytest.mark.parametrize("omega", [1e-4, 1e-5, 1e-8, 1e-12])
@pytest.mark.parametrize("rtol", [1e-6, 1e-9, 1e-12])
@pytest.mark.slow
def test_creeping_return_keeps_its_relative_bound(omega, rtol):
    """Class 1: eps = 5.2e-12 at Omega = 1e-4 was off by 3.5e-8 relative whatever the tolerance (x'
    carried beside the force kept an absolute rounding error of the creep speed)."""
    truth = _overlap_constant() * omega ** 3
    got = collide("3/2", "1/2", omega, rtol=rtol, end="overlap")
    assert math.isclose(got.eps, truth, rel_tol=10 * rtol + 1e-13)


@pytest.mark.parametrize("alpha, gamma, omega", [("1", "1/2", 1e-3), ("5/2", "1", 1e-3)])
@pytest.mark.slow
def test_creeping_return_matches_mpmath_for_other_pairs(alpha, gamma, omega):
    truth = float(reference_collision(Problem.of(alpha, gamma, "overlap"), omega, digits=20).eps)
    assert truth < 1e-4
    for rtol in (1e-8, RTOL):
        got = collide(alpha, gamma, omega, rtol=rtol, end="overlap")
        assert math.isclose(got.eps, truth, rel_tol=10 * rtol + 1e-13), rtol


@pytest.mark.parametrize("argv", [["--omega", "1e-4"], ["--omega", "1e-4", "--tol", "1e-12"],
                                  ["--omega", "1e-5"], ["--omega", "1e-9", "--tol", "1e-6"]])
@pytest.mark.slow
def test_cli_answers_a_tiny_overlap_eps_within_its_bound(argv, tmp_path, monkeypatch):
    """The issue's examples through the CLI: within the stated bound, and no false "they stick"."""
    monkeypatch.setenv("RESTITUTION_CACHE", str(tmp_path))
    out = io.StringIO()
    assert main(["eps", "--alpha", "3/2", "--gamma", "1/2", "--end", "overlap", "--json", *argv], out=out) == 0
    data = json.loads(out.getvalue())
    omega = float(argv[1])
    assert math.isclose(data["eps"][0], _overlap_constant() * omega ** 3, rel_tol=data["error_bound"])
    if data["error_bound"] < 1e-11:   # below what a uniform form or an overlap curve states: nothing built
        assert not list(tmp_path.iterdir()), sorted(p.name for p in tmp_path.iterdir())


@pytest.mark.parametrize("alpha, gamma", [("3/2", "1/2"), ("1", "1/2"), ("3/2", "1"), ("2", "3/2")])
def test_below_alpha_2gamma_plus_1_the_bodies_always_separate(alpha, gamma):
    """Class 2: alpha < 2 gamma + 1 has no trapped return (x' ~ x^d reaching (0, 0) balances no two
    terms of the equation), so a tiny eps is computed, never called sticking."""
    for omega in (1e-6, 1e-9, 1e-12):
        assert collide(alpha, gamma, omega, rtol=1e-9, end="overlap").eps > 0


@pytest.mark.parametrize("alpha, gamma, omega", [("5/2", "1/2", 0.1), ("3", "1/2", 1e-3), ("3", "1/4", 1.0)])
def test_above_alpha_2gamma_plus_1_sticking_is_proved(alpha, gamma, omega):
    """alpha > 2 gamma + 1: sticking is claimed only where the return enters the trap of
    collision._Trap (at maximum compression already below collision.stick_bound), and says where."""
    with pytest.raises(StickError, match="slower than 2 Omega|trapped from maximum compression"):
        collide(alpha, gamma, omega, end="overlap")
    assert collide(alpha, gamma, 10.0, end="overlap").eps > 0


@pytest.mark.parametrize("rtol", [1e-9, 1e-12])
def test_equal_exponents_never_take_the_pulling_leg(rtol):
    """alpha = gamma: f = Omega + x' only decays towards 0, so the overlap rule is the force rule; a
    rounding-negative f once sent this case down the pulling leg, which failed at Omega = 0.01."""
    for omega in (1e-3, 0.01, 0.1):
        assert collide("1", "1", omega, rtol=rtol, end="overlap").eps == collide("1", "1", omega, rtol=rtol).eps


# --- issue 28: near a sticking boundary eps is a small remainder of O(1) speeds, so a
# double-precision integration's relative error grows like 1/eps there (core.conditioning). The
# factor was measured on seven other pairs; these points are held out.
NEAR_STICKING = [("9/2", "1/2", 1.0),                 # the fuzz's case: 1.4 % above Omega_stick = 0.98605
                 ("7/2", "1/2", 0.623236 * 1.002),    # eps = 2.8e-4
                 ("2", "0", 1.40228 * 1.002),         # eps = 2.8e-4
                 ("3", "1", 0.125 * 1.01)]            # alpha = 2 gamma + 1: eps = 2.3e-14


@pytest.mark.parametrize("alpha, gamma, omega", NEAR_STICKING)
@pytest.mark.slow
def test_near_sticking_every_stated_bound_holds(alpha, gamma, omega, tmp_path, monkeypatch):
    monkeypatch.setenv("RESTITUTION_CACHE", str(tmp_path))
    truth = float(reference_collision(Problem.of(alpha, gamma, "overlap"), omega, digits=24).eps)
    for rtol in (1e-10, 1e-12, 1e-13):
        got = collide(alpha, gamma, omega, rtol=rtol, end="overlap")
        assert got.error_bound > 10 * rtol + 1e-13       # widened: the plain bound failed here
        assert math.isclose(got.eps, truth, rel_tol=got.error_bound), rtol
    for tol in (1e-6, 1e-9, 1e-12):
        res = restitution.epsilon(alpha=alpha, gamma=gamma, omega=[omega], tol=tol, end="overlap", build=False)
        assert res.error_bound <= tol and math.isclose(res.eps[0], truth, rel_tol=res.error_bound), tol
    # a forced rung that cannot reach it: a tol its plain overlap bound (3e-12 and up) meets, the
    # widened one near sticking does not
    with pytest.raises(ParameterError, match="sticking boundary"):
        restitution.epsilon(alpha=alpha, gamma=gamma, omega=[omega], tol=2e-11, method="reference",
                            end="overlap", build=False)


def test_at_the_edge_of_sticking_a_stalled_return_is_refused_in_one_line(capsys):
    """Within ~1e-8 of the boundary (here (5, 1/3)) the return stalls before the trap can prove
    sticking: both integrators gave up with a traceback."""
    for cmd in ("collide", "eps"):
        assert main([cmd, "--alpha", "5", "--gamma", "1/3", "--omega", "2.41545761", "--end", "overlap"]) == 2
        err = capsys.readouterr().err.strip()
        assert "\n" not in err and "edge of sticking" in err


@pytest.mark.parametrize("omega", [1e8, 1e10])
def test_near_the_elastic_limit_the_overlap_rule_keeps_its_widened_bound(omega, tmp_path, monkeypatch):
    """Found by make fuzz: for alpha = 8, gamma = 1 both double-precision integrators were up to 3.3
    (collide) and 7.7 (compiled) times over their plain bound at Omega >= 1e8."""
    monkeypatch.setenv("RESTITUTION_CACHE", str(tmp_path))
    truth = float(reference_collision(Problem.of("8", "1", "overlap"), omega, digits=24).eps)
    for rtol in (1e-10, 1e-12, 1e-14):
        got = collide("8", "1", omega, rtol=rtol, end="overlap")
        assert math.isclose(got.eps, truth, rel_tol=got.error_bound), rtol
    for tol in (1e-9, 1e-12):
        res = restitution.epsilon(alpha="8", gamma="1", omega=[omega], tol=tol, end="overlap", build=False)
        assert res.error_bound <= tol and math.isclose(res.eps[0], truth, rel_tol=res.error_bound), tol


@pytest.mark.parametrize("alpha, gamma", [("3/2", "0"), ("2", "1/4"), ("3", "1/2"), ("5/2", "1/2"), ("4", "0"),
                                          ("7/2", "1/4")])
def test_sticking_proved_without_integrating_lies_below_the_integrators_boundary(alpha, gamma):
    """stick_bound is sufficient, not the boundary: the compiled integrator's own trap agrees just
    below it, and the boundary it finds by bisection lies above."""
    from restitution.core.collision import stick_bound
    from restitution.core.exponents import as_exponents
    from restitution.fast.master import reference_eps
    from restitution.fast.overlap_master import sticking_boundary
    ex = as_exponents(alpha, gamma)
    bound = stick_bound(ex)
    assert 0 < bound < sticking_boundary(ex)
    with pytest.raises(StickError):
        reference_eps(Problem(as_exponents(ex), "overlap"), [0.999 * bound], 1e-10)


@pytest.mark.parametrize("alpha, gamma", [("1", "0"), ("3/2", "1/4"), ("3", "1")])
def test_stick_bound_is_the_self_similar_threshold(alpha, gamma):
    from restitution.core.collision import stick_bound
    assert stick_bound((alpha, gamma)) == 1.0 / (4.0 * (float(restitution.core.exponents.as_exponents(
        alpha, gamma).gamma) + 1.0))
    assert stick_bound(("3/2", "1/2")) == 0.0


@pytest.mark.parametrize("alpha, gamma", [("3/2", "0"), ("1", "0"), ("3", "1/2")])
def test_sticking_below_the_references_range_is_refused_at_once(alpha, gamma):
    """Below Omega = 1e-12 only the mpmath rung was left, which cannot prove sticking: a deck audit
    (hertz/material with velocity damping, Omega 5e-14) followed its creep for over ten minutes."""
    for omega in (1e-13, 1e-200):
        with pytest.raises(StickError, match="never ends"):
            restitution.epsilon(alpha=alpha, gamma=gamma, omega=omega, end="overlap")
    assert float(restitution.epsilon(alpha=alpha, gamma=gamma, omega=1e-13).eps) > 0   # the force rule ends


@pytest.mark.parametrize("alpha, gamma", [("3/2", "1/2"), ("3/2", "1"), ("1", "1/2"), ("2", "1"), ("3", "3/2"),
                                          ("5/2", "1")])
@pytest.mark.slow   # the scipy reference's creep at 1e-12: 1-4 s a pair
def test_overlap_law_rung_agrees_with_the_reference(alpha, gamma):
    """eps = C Omega^k answers at Omega <= 1e-8 within its bound, checked against the scipy
    reference down to its range's end; below it, where nothing else answers, it answers too."""
    omegas = [1e-12, 1e-10, 1e-8]
    got = restitution.epsilon(alpha=alpha, gamma=gamma, omega=omegas, end="overlap", method="overlap-law")
    assert got.method == "overlap-law" and got.error_bound < 1e-9
    for w, e in zip(omegas, got.eps):
        # rtol 1e-11: at 1e-12 Radau fails in the creep of (1, 1/2) at Omega = 1e-11 and 1e-10 (refused)
        ref = collide(alpha, gamma, w, end="overlap", rtol=1e-11)
        assert abs(e / ref.eps - 1) <= got.error_bound + ref.error_bound
    deep = restitution.epsilon(alpha=alpha, gamma=gamma, omega=1e-13, end="overlap")
    assert deep.method == "overlap-law" and 0 < float(deep.eps) < got.eps[0]


def test_mpmath_rung_takes_the_creeps_law_under_the_overlap_rule():
    """Its Taylor integration would take ~0.2/Omega steps on a creeping return: below 1e-5 it
    answers with the creep's law C Omega^k, C integrated in mpmath (core.highprec.highprec_eps),
    within its bound of the double-precision law (core.overlap_limit: C integrated another way, in
    scipy); it used to refuse there. Where the bodies stick the refusal is the exact one, and an eps
    below the normal doubles is refused."""
    omegas = [1e-9, 1e-12]
    got = restitution.epsilon(alpha="3/2", gamma="1/2", omega=omegas, end="overlap", method="highprec")
    law = restitution.epsilon(alpha="3/2", gamma="1/2", omega=omegas, end="overlap", method="overlap-law")
    assert got.method == "highprec" and got.error_bound <= 1e-14
    for e, ref in zip(got.eps, law.eps):
        assert abs(e / ref - 1) <= got.error_bound + law.error_bound
    with pytest.raises(StickError, match="never ends"):
        restitution.epsilon(alpha="5/2", gamma="1/2", omega=1e-6, end="overlap", method="highprec")
    with pytest.raises(ParameterError, match="below the smallest normal double"):
        restitution.epsilon(alpha="1", gamma="1/2", omega=1e-300, end="overlap")


@pytest.mark.slow   # mpmath's Taylor integration at Omega = 1e-2, 25 digits: seconds
def test_mpmath_rung_below_its_taylor_range_meets_the_taylor_constant():
    """Between 1e-5 and the double-precision law's range (1e-8) only the scipy reference served the
    overlap rule; the mpmath rung's law there agrees with C read off its own Taylor integration at
    Omega = 1e-2 (eps / Omega^3 is C to 16 digits from 1e-2 down) to its stated bound."""
    omegas = [1e-6, 1e-7, 3e-9]
    got = restitution.epsilon(alpha="3/2", gamma="1/2", omega=omegas, end="overlap", method="highprec", tol=1e-12)
    assert got.error_bound <= 1e-14
    for w, e in zip(omegas, got.eps):
        assert math.isclose(e, _overlap_constant() * w ** 3, rel_tol=got.error_bound + 1e-15)


def test_a_creep_that_defeats_the_reference_is_not_called_sticking():
    """Whether Radau gets through this creep at rtol 1e-12 differs between machines (it stalls on
    some, finishes on others): either way it must not call the contact sticking, and an answer must
    be the limit law's to their bounds."""
    try:
        got = collide("1", "1/2", 1e-10, end="overlap", rtol=1e-12)
    except ParameterError as err:
        assert "creeping return defeated the integrator" in str(err)
        return
    law = restitution.epsilon(alpha="1", gamma="1/2", omega=1e-10, end="overlap", method="overlap-law")
    assert got.ended_by == "separation" and got.eps > 0
    assert abs(got.eps / float(law.eps) - 1) <= got.error_bound + law.error_bound


@pytest.mark.slow   # 5 s: the reference gets far into the creep before its Jacobian overflows
def test_reference_refuses_an_eps_whose_return_overflows():
    """alpha = 23/12, gamma = 1/2 at Omega = 1e-10 (eps = 6e-170): the return's Jacobian 1/v^2
    overflows and scipy stopped with a ValueError traceback; now one line, and the law answers."""
    with pytest.raises(ParameterError, match="below what a double-precision integration resolves"):
        collide("23/12", "1/2", 1e-10, end="overlap")
    assert restitution.epsilon(alpha="23/12", gamma="1/2", omega=1e-10, end="overlap").method == "overlap-law"


def test_a_contact_far_below_the_references_range_sticks_at_once():
    """The deck audit's case: Hertz with velocity damping (alpha = 3/2, gamma = 0) at Omega = 1e-13."""
    from restitution.dem.contact import Contact
    contact = Contact(alpha="3/2", gamma=0, D1=1.0, D2=10 ** 5.2, end="overlap")
    assert contact.omega(1.0) == pytest.approx(1e-13, rel=1e-9)
    with pytest.raises(StickError):
        contact.eps(1.0)


@pytest.mark.slow
def test_a_stalled_pulling_leg_is_refused_not_followed():
    """Found by make fuzz: Radau's step collapsed short of u = 0 for (25/4, 9/2) at Omega = 1e-12 with
    rtol 1e-11 and it ran on for hours; now a one-line refusal after PULL_MAX_CALLS evaluations, and
    the neighbouring rtol still answers."""
    law = restitution.epsilon(alpha="25/4", gamma="9/2", omega=1e-12, end="overlap", method="overlap-law")
    # Whether Radau's step collapses at rtol 1e-11 differs between machines: a refusal in one line
    # or the law's eps, never hours of following the creep (the time limit is the suite's)
    for rtol in (1e-11, 1e-12):
        try:
            ref = collide("25/4", "9/2", 1e-12, end="overlap", rtol=rtol)
        except ParameterError as err:
            assert rtol == 1e-11 and "creeping return defeated the integrator" in str(err)
            continue
        assert abs(ref.eps / float(law.eps) - 1) <= ref.error_bound + law.error_bound


def test_a_forced_method_is_refused_with_the_reason_of_the_rule_asked():
    """Of the two "integrator" rungs (one per end rule), the refusal under the overlap rule is its own
    range, not the force rule's rung saying it serves the force rule only; a method no rung of
    this rule serves is named as such."""
    with pytest.raises(ParameterError, match=r"Omega outside \[1e-05, 1e14\]"):
        restitution.epsilon(alpha="3/2", gamma="1/2", omega=[1e-7], method="integrator", end="overlap", tol=None)
    with pytest.raises(ParameterError, match="does not serve end = overlap"):
        restitution.epsilon(alpha="3/2", gamma="1", omega=[1.0], method="fitted-c", end="overlap")

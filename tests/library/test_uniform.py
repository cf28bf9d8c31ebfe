"""The uniform closed form eps(Omega) (restitution.core.uniform, built by restitution.fast.uniform_build):
exact in both limits to first order, and its stated bound held on points it never saw."""

from __future__ import annotations

import json
import math
from fractions import Fraction

import numpy as np
import pytest

from restitution.audit.stability import DEFAULT_ALPHAS, DEFAULT_GAMMAS
from restitution.cli import main
from restitution.core import asymptotics as asy
from restitution.core.collision import collide
from restitution.core.errors import ParameterError
from restitution.core.uniform import DEGREE, FORM_RANGE, MAX_DEGREE, UniformForm, skeleton
from restitution.fast.uniform_build import build_uniform

PAIRS = [("3/2", "1"), ("3/2", "1/2"), ("1", "0"), ("2", "1/2"), ("5/2", "0")]


# the whole module is in `make test` only: each form takes about a second to build
pytestmark = pytest.mark.slow


@pytest.fixture(scope="module", params=PAIRS, ids=lambda p: f"a{p[0]}-g{p[1]}")
def form(request):
    return build_uniform(request.param)


def test_viscous_limit_is_exact_to_first_order(form):
    """eps_form / (k Omega [1 - Omega (c_log ln(1/Omega) + c_const)]) - 1, measured against the size of
    the first-order term itself, goes to zero: below 5 % of it at Omega = 1e-10, and falling by at least
    ten from 1e-8 to 1e-10 (the fitted term is O(Omega^(1 + sigma m0)); or it is at the rounding of a double)."""
    V = asy.viscous_limit((form.alpha, form.gamma))
    om = np.array([1e-8, 1e-10])
    first = om * (V.c_log * np.log(1 / om) + abs(V.c_const))
    ratio = np.abs(form.eps(om) / V.eps(om, 1) - 1) / first
    assert ratio[1] < 0.05
    assert ratio[1] < max(ratio[0] / 10, 1e-15 / first[1])


def test_elastic_limit_is_exact_to_first_order(form):
    """(1 - eps_form) / (C1 Omega^-A) -> 1, its deviation falling at least like Omega^(-A/2)."""
    E = asy.elastic_limit((form.alpha, form.gamma))
    om = np.array([1e10, 1e14, 1e18])
    dev = np.abs(form.one_minus_eps(om) / (E.C1 * om ** -E.A) - 1)
    assert dev[1] < dev[0] * 1e4 ** (-E.A / 2) and dev[2] < dev[1] * 1e4 ** (-E.A / 2)
    assert dev[2] < 1e-3


def test_stated_bound_holds_on_fresh_points(form):
    """Points from another seed than the build's, eps and 1 - eps from the scipy reference (1 - eps
    from the dissipated energy, relative accuracy ~1e-12)."""
    om = np.sort(10 ** np.random.default_rng(2026).uniform(-8, 8, 24))
    runs = [collide((form.alpha, form.gamma), float(w), rtol=1e-12) for w in om]
    err = np.abs(form.eps(om) / np.array([r.eps for r in runs]) - 1)
    assert err.max() <= form.bound_eps
    el = om >= 1
    err1 = np.abs(form.one_minus_eps(om[el]) / np.array([r.one_minus_eps for r in runs])[el] - 1)
    assert err1.max() <= form.bound_one_minus_eps


def test_targets_for_the_paper_and_hertz_exponents(form):
    """For (3/2, 1) and (3/2, 1/2): 12 fitted numbers and a bound of at most 1e-4 in eps and 1e-3 in
    1 - eps (issue 13's target); for the others (more numbers only where 12 do not reach it) at most 1e-3."""
    paper_like = (str(form.alpha), str(form.gamma)) in {("3/2", "1"), ("3/2", "1/2")}
    assert len(form.coef) == DEGREE + 1 == 12 if paper_like else len(form.coef) <= MAX_DEGREE + 1
    assert form.bound_eps <= (1e-4 if paper_like else 1e-3)
    assert form.bound_one_minus_eps <= 1e-3


def test_formula_line_computes_the_same_eps(form):
    """The one-line formula a DEM user types (C/Python syntax) gives what the library gives."""
    line = form.formula()
    for W in (1e-7, 0.03, 2.0, 5e6):
        env = {"W": W, "pow": math.pow, "log": math.log, "tanh": math.tanh}
        exec(line, env)  # noqa: S102 - the library's own output
        assert env["eps"] == pytest.approx(float(form.eps(W)), rel=1e-13)


def test_serialised_form_round_trips_and_rejects_a_changed_constant(form):
    d = json.loads(json.dumps(form.as_dict()))
    back = UniformForm.from_dict(d)
    om = np.geomspace(*FORM_RANGE, 50)
    assert np.array_equal(back.eps(om), form.eps(om))
    d["c3"] = d["c3"] * (1 + 1e-9)
    with pytest.raises(ValueError):
        UniformForm.from_dict(d)


@pytest.mark.parametrize("alpha,gamma,why", [("1", "3/2", "alpha < gamma"), ("3/2", "3/2", "exact closed form")])
def test_pairs_without_a_uniform_form_are_refused_with_the_reason(alpha, gamma, why):
    with pytest.raises(ParameterError, match=why):
        skeleton((alpha, gamma))


def test_cli_uniform_json_contract(tmp_path, capsys):
    """`restitution eps ... --method uniform --json`: eps, method, error_bound, coefficients."""
    assert main(["eps", "--alpha", "3/2", "--gamma", "1", "--omega", "1e-6", "0.3", "1e7",
                 "--method", "uniform", "--json"]) == 0
    captured = capsys.readouterr()
    out = json.loads(captured.out)
    assert out["method"] == "uniform" and len(out["eps"]) == 3 and "closed-form" not in captured.err
    assert 0 < out["error_bound"] <= 1e-4
    c = out["coefficients"]
    assert {"k", "A", "b", "c_log", "c3", "sigma", "m0", "m1", "a"} <= set(c) and len(c["a"]) == 12
    ref = collide(("3/2", "1"), 0.3, rtol=1e-12).eps
    assert abs(out["eps"][1] / ref - 1) <= out["error_bound"]


def test_cli_old_name_closed_form_still_answers_with_a_one_line_note(capsys):
    """The uniform approximation was called closed-form: that name still works, says so once on
    stderr, and answers as "uniform" does."""
    argv = ["eps", "--alpha", "3/2", "--gamma", "1", "--omega", "0.3", "--json", "--method"]
    assert main([*argv, "uniform"]) == 0
    new = json.loads(capsys.readouterr().out)
    assert main([*argv, "closed-form"]) == 0
    captured = capsys.readouterr()
    old = json.loads(captured.out)
    err = captured.err.strip().splitlines()
    assert len(err) == 1 and '"closed-form"' in err[0] and '"uniform"' in err[0] and "Traceback" not in captured.err
    assert old["method"] == "uniform" and old["eps"] == new["eps"] and old["error_bound"] == new["error_bound"]


def test_collide_closed_form_stays_the_exact_family(capsys):
    """collide's "closed-form" is the exact family's whole collision (a genuine closed form), no note;
    the uniform approximation gives eps alone and is no collide method."""
    exact = main(["collide", "--alpha", "3", "--gamma", "1", "--omega", "2", "--json", "--method", "closed-form"])
    captured = capsys.readouterr()
    assert exact == 0 and captured.err == ""
    assert main(["collide", "--alpha", "3", "--gamma", "1", "--omega", "2", "--method", "uniform"]) == 2


def test_cli_refuses_uniform_for_alpha_below_gamma(capsys):
    assert main(["eps", "--alpha", "1", "--gamma", "3/2", "--omega", "0.3", "--method", "uniform"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "alpha < gamma" in err[0]


def test_printed_digits_reproduce_the_form(form):
    """Twelve significant digits of every number (what the manuscript prints) change eps by a small
    part of the bound. Measured: 7e-8 to 2.7e-7 of it for the forms of twelve coefficients; 2.0e-3 for
    (5/2, 0), whose 24 power coefficients reach 1.5e7 (small A: the longer forms are less well
    conditioned; its coefficients are printed nowhere). Which shape and degree the fit picks, and so
    this number, moves with the last bits of the least squares on another CPU: one machine gave
    below 1e-3 for (5/2, 0), another 2.0e-3, hence a hundredth."""
    om = np.geomspace(*FORM_RANGE, 400)
    assert np.max(np.abs(form.rounded(12).eps(om) / form.eps(om) - 1)) < 1e-2 * form.bound_eps
    assert np.max(np.abs(form.rounded(3).eps(om) / form.eps(om) - 1)) > 1e-6   # the check can fail


def test_compiled_evaluation_equals_the_formula(form):
    """The ladder's compiled loop (fast.uniform_eval) gives the numpy formula's eps to rounding,
    and stays finite and in (0, 1] far outside the fitted range."""
    from restitution.fast.uniform_eval import uniform_eps

    om = np.geomspace(*FORM_RANGE, 2001)
    assert np.max(np.abs(uniform_eps(form, om) / form.eps(om) - 1)) < max(1e-13, 1e-6 * form.bound_eps)
    wide = np.geomspace(1e-300, 1e300, 301)
    e = uniform_eps(form, wide)
    assert np.all(np.isfinite(e) & (e > 0) & (e <= 1))


ATLAS_PAIRS = [(a, g) for a in DEFAULT_ALPHAS for g in DEFAULT_GAMMAS
               if Fraction(a) > Fraction(g) and (a, g) not in PAIRS]


@pytest.mark.parametrize("alpha,gamma", ATLAS_PAIRS)
def test_every_atlas_pair_keeps_its_bound_on_fresh_points(alpha, gamma):
    """Every pair of the stability atlas with alpha > gamma: the form is built, its bound is at most
    1e-3 and holds on points from another seed (eps and 1 - eps from the scipy reference)."""
    form = build_uniform((alpha, gamma))
    assert form.bound_eps <= 1e-3 and form.bound_one_minus_eps <= 1e-3
    om = np.sort(10 ** np.random.default_rng(7).uniform(-8, 8, 12))
    runs = [collide((alpha, gamma), float(w), rtol=1e-12) for w in om]
    assert np.max(np.abs(form.eps(om) / np.array([r.eps for r in runs]) - 1)) <= form.bound_eps
    el = om >= 1
    ome = np.array([r.one_minus_eps for r in runs])[el]
    assert np.max(np.abs(form.one_minus_eps(om[el]) / ome - 1)) <= form.bound_one_minus_eps


def test_bound_covers_the_dense_scan_of_held_out_points(form):
    """The stated bound is twice the largest error over every held-out set, the dense scan included:
    the scan's own maximum (recomputed here on its points against the integrator) is inside half of it."""
    from restitution.core.problem import Problem
    from restitution.fast.master import reference_eps
    from restitution.fast.uniform_build import BOUND_FACTOR, dense_points

    m = form.measured
    assert m["n_dense"] == dense_points().size
    om = dense_points()
    err = np.max(np.abs(form.eps(om) / reference_eps(Problem.of(form.alpha, form.gamma, "force"), om, 1e-14) - 1))
    assert err == pytest.approx(m["dense_eps"], rel=1e-6)
    assert BOUND_FACTOR * max(m["dense_eps"], m["test_eps"], m["selection_eps"]) <= form.bound_eps


def test_dense_scan_points_are_neither_fit_nor_selection_points():
    """Every dense-scan point lies a quarter of GRID_STEP (in log10 Omega) from the nearest fit or
    model-selection point (log10 Omega = -9 + k GRID_STEP), so the scan is held out; and it spans the
    form's range."""
    from restitution.fast.uniform_build import GRID_STEP, dense_points

    om = dense_points()
    offset = (np.log10(om) + 9.0) / GRID_STEP
    assert np.min(np.abs(offset - np.round(offset))) > 0.2
    assert FORM_RANGE[0] < om.min() and om.max() < FORM_RANGE[1] and om.size >= 16 * 40

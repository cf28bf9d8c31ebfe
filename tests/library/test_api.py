"""restitution.collide: one entry point, one result type, every integrator as a method."""

import json
import math

import pytest

import restitution
from restitution.api import METHODS, collide
from restitution.cli import main
from restitution.core.errors import ParameterError
from restitution.core.results import Collision

FIELDS = ("eps", "tau_b", "x_b", "tau_c", "x_c")


@pytest.mark.parametrize("alpha, gamma, omega", [("3/2", "1", 0.5), ("3/2", "1/2", 20.0), ("1", "3/2", 0.3)])
def test_every_method_gives_the_same_collision_within_its_bound(alpha, gamma, omega):
    truth = collide(alpha, gamma, omega, method="highprec", digits=30)
    for method, rtol in (("reference", 1e-12), ("integrator", 1e-12)):
        got = collide(alpha, gamma, omega, method=method, rtol=rtol)
        assert isinstance(got, Collision) and got.ended_by == truth.ended_by and got.rtol == rtol
        for f in FIELDS[:4]:   # x_c is ~0 for a separation end
            assert math.isclose(getattr(got, f), getattr(truth, f), rel_tol=10 * rtol + 1e-13), (method, f)
    assert truth.rtol == pytest.approx(1e-29)


def test_the_closed_form_is_a_method_for_the_linear_dashpot_only():
    exact = collide(1, 0, 0.5, method="closed-form")
    numeric = collide(1, 0, 0.5, method="reference", rtol=1e-12)
    assert exact.rtol == 0.0 and math.isclose(exact.eps, numeric.eps, rel_tol=1e-11)
    with pytest.raises(ParameterError, match="alpha = 1, gamma = 0"):
        collide("3/2", 1, 0.5, method="closed-form")


@pytest.mark.parametrize("kwargs, field", [
    ({"method": "bogus"}, "method"),
    ({"method": "integrator", "omega": 1e15}, "omega"),
    ({"method": "integrator", "rtol": 1e-3}, "rtol"),
    ({"method": "integrator", "t_eval": [0.0, 1.0]}, "t_eval"),
    ({"method": "highprec", "digits": 5}, "digits"),
])
def test_bad_method_arguments_name_the_field(kwargs, field):
    kwargs = {"omega": 0.5, **kwargs}
    omega = kwargs.pop("omega")
    with pytest.raises(ParameterError) as err:
        collide("3/2", 1, omega, **kwargs)
    assert err.value.field == field


def test_the_package_and_the_cli_use_this_entry_point(capsys):
    assert restitution.collide is collide and METHODS[0] == "reference"
    assert main(["collide", "--alpha", "3/2", "--gamma", "1", "--omega", "0.5", "--method", "integrator", "--json"]) == 0
    fast = json.loads(capsys.readouterr().out)
    assert fast["eps"] == pytest.approx(collide("3/2", 1, 0.5).eps, rel=1e-10)
    assert main(["collide", "--alpha", "3/2", "--gamma", "1", "--omega", "0.5", "--method", "x"]) == 2
    assert capsys.readouterr().err.count("\n") == 1


def test_collide_and_epsilon_name_the_same_rungs():
    from restitution.fast.collide import ALIASES
    from restitution.fast.rungs import RUNGS
    names = {r.name for r in RUNGS}
    # an alias names a rung too: collide's "closed-form" is the exact family's (epsilon's old name of
    # "uniform" is another matter: restitution.fast.ladder.RENAMED)
    assert set(METHODS) - set(ALIASES) <= names and set(ALIASES.values()) <= names
    assert {"reference", "integrator", "highprec", "exact-family", "closed-form"} == set(METHODS)
    via_collide = collide("3/2", 1, 0.5, method="integrator", rtol=1e-12).eps
    via_epsilon = restitution.epsilon(alpha="3/2", gamma=1, omega=[0.5], method="integrator", tol=1e-9)
    assert via_epsilon.method == "integrator" and via_epsilon.eps[0] == pytest.approx(via_collide, rel=1e-9)


def test_the_old_name_fast_still_works_and_says_the_new_one(capsys):
    old = collide("3/2", 1, 0.5, method="fast")
    assert old == collide("3/2", 1, 0.5, method="integrator")
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and '"integrator"' in err


def test_a_problem_carries_its_rule():
    from restitution import Problem
    p = Problem.of("3/2", 1, end="overlap")
    by_problem = collide(problem=p, omega=0.5)
    assert by_problem == collide("3/2", 1, 0.5, end="overlap") and by_problem.end == "overlap"
    assert by_problem.ended_by == "separation"
    assert collide(problem=p, omega=0.5, method="integrator").end == "overlap"
    eps = restitution.epsilon(problem=p, omega=[0.5], tol=1e-6)
    assert eps.eps[0] == pytest.approx(by_problem.eps, rel=1e-6)
    with pytest.raises(ParameterError) as err:
        collide(problem=p, omega=0.5, end="force")
    assert err.value.field == "end"
    with pytest.raises(ParameterError) as err:
        collide("3/2", 1, 0.5, problem=p)
    assert err.value.field == "problem"

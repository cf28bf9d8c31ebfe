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
    for method, rtol in (("reference", 1e-12), ("fast", 1e-12)):
        got = collide(alpha, gamma, omega, method=method, rtol=rtol)
        assert isinstance(got, Collision) and got.end == truth.end and got.rtol == rtol
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
    ({"method": "fast", "omega": 1e15}, "omega"),
    ({"method": "fast", "rtol": 1e-3}, "rtol"),
    ({"method": "fast", "t_eval": [0.0, 1.0]}, "t_eval"),
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
    assert main(["collide", "--alpha", "3/2", "--gamma", "1", "--omega", "0.5", "--method", "fast", "--json"]) == 0
    fast = json.loads(capsys.readouterr().out)
    assert fast["eps"] == pytest.approx(collide("3/2", 1, 0.5).eps, rel=1e-10)
    assert main(["collide", "--alpha", "3/2", "--gamma", "1", "--omega", "0.5", "--method", "x"]) == 2
    assert capsys.readouterr().err.count("\n") == 1

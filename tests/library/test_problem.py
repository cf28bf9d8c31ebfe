"""The physics problem as one value (core.problem): what it accepts, and that every core function
takes it (or an Exponents, or an (alpha, gamma) pair) as its first argument."""

import doctest

import pytest

import restitution
from restitution.core import problem as problem_module
from restitution.core.collision import collide
from restitution.core.errors import ParameterError
from restitution.core.exponents import Exponents, as_exponents
from restitution.core.problem import Problem, as_problem


def test_doctests_run():
    result = doctest.testmod(problem_module, optionflags=doctest.ELLIPSIS)
    assert result.attempted > 0 and result.failed == 0


def test_exported_from_the_package():
    assert restitution.Problem is Problem


def test_every_spelling_is_the_same_problem():
    p = Problem.of("3/2", 1)
    assert as_problem(p) is p
    assert as_problem(Exponents.parse("3/2", 1)) == p == as_problem(("3/2", 1)) == as_problem((1.5, "1"))
    assert as_exponents(p) is p.ex and hash(p) == hash(Problem.of(1.5, 1))


def test_the_rule_travels_one_way():
    p = Problem.of("3/2", 1, end="overlap")
    assert restitution.epsilon(problem=p, end="overlap", omega=1.0).end == "overlap"
    with pytest.raises(ParameterError) as info:   # the public call's end must agree with the problem's
        restitution.epsilon(problem=p, end="force", omega=1.0)
    assert info.value.field == "end"
    with pytest.raises(ParameterError):
        Problem("3/2", "force")     # numbers go through Problem.of


def test_core_functions_take_the_problem_first():
    by_pair = collide(("3/2", 1), 0.5)
    assert collide(Problem.of("3/2", 1), 0.5) == by_pair == collide(Exponents.parse("3/2", 1), 0.5)

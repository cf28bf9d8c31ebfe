"""Scaling and exponent handling."""

import math
from fractions import Fraction

import numpy as np
import pytest

from restitution.audit import printed
from restitution.core.errors import ParameterError
from restitution.core.exponents import Exponents
from restitution.core.model import ELASTIC, VISCOUS, Material


@pytest.mark.parametrize("alpha,gamma,D1,D2,g", [
    ("3/2", "1", 0.000296, 0.0109, 0.1),
    ("3/2", "1/2", 2.3, 0.7, 3.0),
    ("1", "0", 5.0, 0.3, 0.01),
    ("5/2", "3/2", 1e-3, 40.0, 17.0),
])
def test_scales_turn_the_physical_equation_into_the_scaled_one(alpha, gamma, D1, D2, g):
    # xi = A x(t/B) solves xi'' + D1 xi^a + D2 xi^c xi' = 0 iff D2 A^c B = 1, D1 A^(a-1) B^2 = Omega,
    # and xi'(0) = g iff A / B = g.
    m = Material(alpha, gamma, D1, D2)
    A, B = m.length_scale(g), m.time_scale(g)
    a, c = float(m.alpha), float(m.gamma)
    assert D2 * A ** c * B == pytest.approx(1, rel=1e-13)
    assert D1 * A ** (a - 1) * B ** 2 == pytest.approx(m.omega(g), rel=1e-13)
    assert A / B == pytest.approx(g, rel=1e-13)


def test_paper_form_of_omega_agrees_where_it_is_defined():
    m = Material(printed.ALPHA, printed.GAMMA, printed.D1, printed.D2)
    g = np.array([0.01, 0.1, 1.0])
    v = m.D2 ** (1 / float(m.gamma)) * g
    paper_form = m.d_star * v ** float((m.alpha - 1 - 2 * m.gamma) / (m.gamma + 1))
    np.testing.assert_allclose(m.omega(g), paper_form, rtol=1e-13)


def test_omega_scales_with_the_stated_power_of_g():
    m = Material("3/2", 1, printed.D1, printed.D2)
    assert m.exponents.omega_exponent == Fraction(-3, 4)
    assert m.omega(0.2) / m.omega(0.1) == pytest.approx(2 ** -0.75, rel=1e-14)


def test_paper_material_is_viscous_dominant():
    m = Material("3/2", 1, printed.D1, printed.D2)
    assert m.d_star == pytest.approx(printed.D1 / math.sqrt(printed.D2))
    assert m.regime == VISCOUS
    assert Material("3/2", 1, 2.0, 1.0).regime == ELASTIC


def test_gamma_zero_has_omega_but_no_d_star():
    m = Material(1, 0, 0.5, 2.0)
    assert m.d_star is None and m.regime is None
    # alpha = 1, gamma = 0: Omega = D1 / D2^2, independent of g.
    np.testing.assert_allclose(m.omega([0.1, 1, 10]), 0.5 / 4.0, rtol=1e-14)


def test_omega_is_vectorised_and_finite_for_extreme_constants():
    m = Material("3/2", 1, 1e-300, 1e-300)
    out = m.omega(np.logspace(-3, 3, 7))
    assert out.shape == (7,) and np.all(np.isfinite(out)) and np.all(out > 0)


@pytest.mark.parametrize("D1,D2,g", [(1e300, 1e-300, 1e300), (1e-300, 1e300, 1e-300)])
def test_omega_leaving_double_precision_is_refused(D1, D2, g):
    with pytest.raises(ParameterError) as info:
        Material("3/2", 1, D1, D2).omega(g)
    assert info.value.field == "g" and "Omega" in str(info.value)


@pytest.mark.parametrize("text,expected", [("3/2", Fraction(3, 2)), ("1", Fraction(1)), (1.5, Fraction(3, 2)),
                                           ("0.5", Fraction(1, 2)), (2, Fraction(2)), (Fraction(5, 4), Fraction(5, 4))])
def test_exponents_parse_exactly(text, expected):
    assert Exponents.parse(text, 1).alpha == expected


def test_float_exponent_near_a_short_rational_is_refused_naming_it():
    with pytest.raises(ParameterError) as info:
        Exponents.parse(1.4166667, 1)  # 17/12 typed to 7 digits: eps would be that of another exponent
    assert info.value.field == "alpha" and "'17/12'" in str(info.value)
    ex = Exponents.parse(17 / 12, 1)
    assert ex.alpha == Fraction(17, 12) and ex.p == 12 and ex.q_alpha == 17 and ex.q_gamma == 12


def test_float_exponent_far_from_short_rationals_is_refused_naming_the_nearest():
    with pytest.raises(ParameterError) as info:
        Exponents.parse(math.sqrt(2), 1)
    assert info.value.field == "alpha" and "17/12" in str(info.value)


@pytest.mark.parametrize("value", [np.int64(2), np.float64(1.5), Fraction(3, 2)])
def test_numpy_and_fraction_exponents_are_accepted(value):
    assert Exponents.parse(value, 1).alpha in (Fraction(2), Fraction(3, 2))


@pytest.mark.parametrize("field,kwargs", [
    ("alpha", dict(alpha=0, gamma=1)), ("alpha", dict(alpha=-1, gamma=1)),
    ("alpha", dict(alpha=float("nan"), gamma=1)), ("alpha", dict(alpha="inf", gamma=1)),
    ("alpha", dict(alpha="1/97", gamma=1)), ("alpha", dict(alpha="three", gamma=1)),
    ("alpha", dict(alpha=True, gamma=1)), ("gamma", dict(alpha=1, gamma=-0.5)),
    ("alpha", dict(alpha="1e400", gamma=1)), ("alpha", dict(alpha=1e300, gamma=1)),
    ("gamma", dict(alpha=1, gamma="17")), ("alpha", dict(alpha=3.14159, gamma=1)),
])
def test_bad_exponents_name_the_field(field, kwargs):
    with pytest.raises(ParameterError) as info:
        Exponents.parse(**kwargs)
    assert info.value.field == field and "rational" in str(info.value)


@pytest.mark.parametrize("field,args", [
    ("D1", (0, 1.0)), ("D1", (-1, 1.0)), ("D1", (float("nan"), 1.0)), ("D2", (1.0, float("inf"))),
    ("D2", (1.0, "x")),
])
def test_bad_material_constants_name_the_field(field, args):
    with pytest.raises(ParameterError) as info:
        Material("3/2", 1, *args)
    assert info.value.field == field


@pytest.mark.parametrize("g", [0, -0.1, float("nan"), float("inf"), [0.1, -1.0], []])
def test_bad_speeds_are_refused(g):
    with pytest.raises(ParameterError) as info:
        Material("3/2", 1, 1.0, 1.0).omega(g)
    assert info.value.field == "g"

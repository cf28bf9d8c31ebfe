"""A float exponent is read only where it is a short rational to the last bit. On 85c8edf
`epsilon(alpha=1.4999999, gamma=1, omega=1)` answered at alpha = 3/2 with its bound for 3/2, while
eps at the float exponent differs by 2.75e-8 (relative; mpmath at rationals around 3/2, and scipy at
the float itself): wrong beyond the bound it stated, with exit status 0. The CLI only noted the
replacement on stderr. Library and CLI now refuse it in one line, naming the rational to pass."""

from __future__ import annotations

import io
from fractions import Fraction

import numpy as np
import pytest

from restitution import Exponents, ParameterError, epsilon
from restitution.cli import main


@pytest.mark.parametrize("alpha", [1.4999999, 1.5000001, 1.4166667, "1.4999999", np.float32(1 / 3) + 1])
def test_a_float_near_but_not_at_a_short_rational_is_refused_naming_it(alpha):
    with pytest.raises(ParameterError) as err:
        epsilon(alpha=alpha, gamma=1, omega=1.0, build=False)
    message = str(err.value)
    assert err.value.field == "alpha" and "\n" not in message
    nearest = Fraction(float(alpha)).limit_denominator(12)
    assert f"'{nearest}'" in message and f"Fraction({nearest.numerator}, {nearest.denominator})" in message


@pytest.mark.parametrize("alpha, gamma, expected", [
    (1.5, 1, (Fraction(3, 2), Fraction(1))), (0.25, 0.5, (Fraction(1, 4), Fraction(1, 2))),
    (1 / 3 + 1, 1 / 3, (Fraction(4, 3), Fraction(1, 3))), (17 / 12, 0.0, (Fraction(17, 12), Fraction(0))),
    (0.1 + 0.2, 1, (Fraction(3, 10), Fraction(1))),        # one unit in the last place from 3/10
    (np.float64(2.5), np.int64(1), (Fraction(5, 2), Fraction(1))), ("0.5", "1", (Fraction(1, 2), Fraction(1))),
])
def test_floats_that_are_short_rationals_still_work(alpha, gamma, expected):
    ex = Exponents.parse(alpha, gamma)
    assert (ex.alpha, ex.gamma) == expected


def test_the_answer_for_a_float_that_is_a_rational_is_the_rationals():
    a = epsilon(alpha=1.5, gamma=0.5, omega=[0.3, 2.0], build=False)
    b = epsilon(alpha="3/2", gamma=Fraction(1, 2), omega=[0.3, 2.0], build=False)
    assert np.array_equal(a.eps, b.eps) and a.error_bound == b.error_bound


@pytest.mark.parametrize("argv", [
    ["eps", "--alpha", "1.4999999", "--gamma", "1", "--omega", "1", "--no-build"],
    ["collide", "--alpha", "3/2", "--gamma", "0.3333333", "--omega", "1"],
    ["calibrate", "--alpha", "1.5000001", "--gamma", "1", "--D1", "1e5", "--eps", "0.6", "--g", "0.3"],
    ["series", "--alpha", "1.4166667", "--gamma", "1", "--omega-order", "0", "--max-power", "3"],
])
def test_the_cli_refuses_it_as_the_library_does(argv, capsys):
    out = io.StringIO()
    assert main(argv, out) == 2 and out.getvalue() == ""
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "Fraction(" in err[0] and "Traceback" not in err[0], err

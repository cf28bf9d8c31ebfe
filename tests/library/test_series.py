"""The exact series engine against the paper's printed coefficients and against independent algebra."""

from fractions import Fraction

import numpy as np
import pytest
import sympy as sp

from restitution.core.errors import ParameterError
from restitution.audit.printed import PRINTED_SERIES
from restitution.core.series import perturbation_series

PRINTED_CASES = [(direction, n, Fraction(power), Fraction(coeff))
                 for direction, orders in PRINTED_SERIES.items()
                 for n, terms in orders.items()
                 for power, coeff in terms]


@pytest.fixture(scope="module")
def paper_series():
    return {d: perturbation_series("3/2", 1, omega_order=4, max_power=11, direction=d)
            for d in ("forward", "inverse")}


@pytest.mark.parametrize("direction,n,power,coeff", PRINTED_CASES,
                         ids=[f"{d}-x{n}-tau^{p}" for d, n, p, _ in PRINTED_CASES])
def test_every_printed_coefficient_is_reproduced_exactly(paper_series, direction, n, power, coeff):
    assert dict(paper_series[direction].terms(n))[power] == coeff


@pytest.mark.parametrize("direction", ["forward", "inverse"])
def test_no_unprinted_terms_below_the_printed_truncation(paper_series, direction):
    # The paper prints x_n up to its last shown power; below that our series has no extra terms.
    for n, printed in PRINTED_SERIES[direction].items():
        last = Fraction(printed[-1][0])
        ours = [(pw, c) for pw, c in paper_series[direction].terms(n) if pw <= last]
        assert ours == [(Fraction(pw), Fraction(c)) for pw, c in printed]


def _residual_coefficients(alpha, gamma, sign, order, max_power):
    """Plug the truncated series into the ODE with sympy (independently of the engine's recurrence)
    and return the residual's coefficients that the truncation must make vanish."""
    ps = perturbation_series(alpha, gamma, order, max_power, "forward" if sign > 0 else "inverse")
    p = ps.p
    s, W = sp.symbols("s Omega", positive=True)  # tau = s**p
    tau = s ** p
    x = sum(W ** n * ps.to_sympy(n, tau) for n in range(order + 1))
    x = sp.expand(sp.powsimp(sp.expand(x), force=True))
    y = sp.expand(x / s ** p)  # x / tau = 1 + O(s)
    depth = int(max_power * p) - 2 * p  # residual is trustworthy below tau^(max_power - 2)
    a, g = Fraction(alpha), Fraction(gamma)
    y_a = sp.series(y ** sp.Rational(a.numerator, a.denominator), s, 0, depth + 1).removeO()
    y_g = sp.series(y ** sp.Rational(g.numerator, g.denominator), s, 0, depth + 1).removeO()
    dx = sp.diff(x, s) / sp.diff(tau, s)
    ddx = sp.diff(dx, s) / sp.diff(tau, s)
    residual = ddx + W * s ** int(a * p) * y_a + sign * s ** int(g * p) * y_g * dx
    residual = sp.expand(residual * s ** (2 * p))  # clear the 1/s^(2p) from the chain rule
    poly = sp.Poly(residual, s, W)
    # After the factor s^(2p), the residual is exact for powers of s up to max_power * p.
    limit = int(max_power * p)
    below = [(ks, kw, c) for (ks, kw), c in poly.terms() if ks <= limit and kw <= order]
    tail = [(ks, kw, c) for (ks, kw), c in poly.terms() if ks > limit]
    return below, tail


@pytest.mark.parametrize("alpha,gamma,sign,order,max_power", [
    ("3/2", "1", 1, 3, 8),
    ("3/2", "1", -1, 3, 8),
    ("3/2", "1/2", 1, 2, 7),
    ("2", "1", 1, 3, 8),
    ("5/4", "1/2", 1, 2, 5),
    ("1", "3/2", 1, 2, 6),
])
def test_series_solves_the_equation_order_by_order(alpha, gamma, sign, order, max_power):
    below, tail = _residual_coefficients(alpha, gamma, sign, order, max_power)
    assert below == []  # every term the truncation keeps cancels exactly
    assert tail  # and the truncation does leave a tail, so the check saw a real residual


def test_damped_only_forward_is_the_taylor_series_of_sqrt2_tanh():
    t = sp.Symbol("tau")
    exact = sp.series(sp.sqrt(2) * sp.tanh(t / sp.sqrt(2)), t, 0, 22).removeO()
    ps = perturbation_series("3/2", 1, 0, 21)
    assert sp.expand(ps.to_sympy(0, t) - exact) == 0


def test_damped_only_inverse_is_the_taylor_series_of_sqrt2_tan():
    t = sp.Symbol("tau")
    exact = sp.series(sp.sqrt(2) * sp.tan(t / sp.sqrt(2)), t, 0, 22).removeO()
    ps = perturbation_series("3/2", 1, 0, 21, "inverse")
    assert sp.expand(ps.to_sympy(0, t) - exact) == 0


def test_linear_spring_dashpot_series_matches_its_closed_form():
    # alpha = 1, gamma = 0: x = exp(-tau/2) sin(w tau)/w with w^2 = Omega - 1/4, analytic in Omega.
    t, W = sp.symbols("tau Omega")
    K = 12
    w2 = W - sp.Rational(1, 4)
    sin_over_w = sum((-1) ** m * w2 ** m * t ** (2 * m + 1) / sp.factorial(2 * m + 1) for m in range(K))
    exact = sp.expand(sp.series(sp.exp(-t / 2), t, 0, K + 1).removeO() * sin_over_w)
    order = 4
    ps = perturbation_series(1, 0, order, K)
    ours = sp.expand(sum(W ** n * ps.to_sympy(n, t) for n in range(order + 1)))
    exact_poly = sp.Poly(exact, t, W)
    ours_poly = sp.Poly(ours, t, W)
    for k in range(1, K + 1):
        for n in range(order + 1):
            assert ours_poly.coeff_monomial(t ** k * W ** n) == exact_poly.coeff_monomial(t ** k * W ** n)


def test_evaluate_sums_orders_and_differentiates():
    ps = perturbation_series("3/2", 1, 2, 11)
    tau = np.array([0.0, 0.3, 0.7])
    h = 1e-6
    numeric = (ps.evaluate(tau[1:] + h, 0.4) - ps.evaluate(tau[1:] - h, 0.4)) / (2 * h)
    np.testing.assert_allclose(ps.evaluate(tau[1:], 0.4, derivative=1), numeric, rtol=1e-8)
    manual = sum(0.4 ** n * ps.order_values(tau, n) for n in range(3))
    np.testing.assert_allclose(ps.evaluate(tau, 0.4), manual, rtol=0, atol=1e-15)
    assert ps.evaluate(0.0, 0.4, derivative=1) == pytest.approx(1.0)
    np.testing.assert_allclose(ps.evaluate(tau, 0.4, order=0), ps.order_values(tau, 0))


def test_latex_prints_fractions():
    ps = perturbation_series("3/2", 1, 1, 6)
    assert ps.latex(1) == r"-\frac{4}{35}\tau^{7/2} + \frac{107}{3465}\tau^{11/2}"
    assert ps.latex(0).startswith(r"\tau - \frac{1}{6}\tau^{3}")


@pytest.mark.parametrize("kwargs,field", [
    (dict(alpha=0, gamma=1), "alpha"),
    (dict(alpha="-3/2", gamma=1), "alpha"),
    (dict(alpha="3/2", gamma=-1), "gamma"),
    (dict(alpha="3/2", gamma=1, omega_order=-1), "omega_order"),
    (dict(alpha="3/2", gamma=1, max_power="1/2"), "max_power"),
    (dict(alpha="3/2", gamma=1, direction="sideways"), "direction"),
])
def test_bad_arguments_name_the_field(kwargs, field):
    with pytest.raises(ParameterError) as info:
        perturbation_series(**kwargs)
    assert info.value.field == field


def test_a_long_derivation_says_its_price_on_stderr(capsys, monkeypatch):
    """series --omega-order 50 --max-power 200 ran for minutes without a word; now the CLI says how
    far it is and about how long it takes (here forced from the first power on)."""
    import io

    from restitution import cli
    monkeypatch.setattr(cli.common.Progress, "FIRST", 0.0)
    assert cli.main(["series", "--alpha", "3/2", "--gamma", "1", "--omega-order", "2", "--max-power", "8"],
                    io.StringIO()) == 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "powers of tau after" in err[0] and "in all" in err[0], err


def test_the_progress_hook_sees_every_power_and_changes_nothing():
    seen = []
    got = perturbation_series("3/2", "1/4", 3, 6, progress=lambda done, total: seen.append((done, total)))
    total = seen[0][1]
    assert [d for d, _ in seen] == list(range(1, total + 1)) and all(t == total for _, t in seen)
    assert got.as_dict() == perturbation_series("3/2", "1/4", 3, 6).as_dict()

"""Checks of the mpmath reference integrator against exact solutions and itself."""

from fractions import Fraction

import pytest
from mpmath import mp

from restitution.core.errors import ParameterError
from restitution.core.highprec import HighPrecisionCollision, reference_collision

QUANTITIES = ("eps", "tau_b", "x_b", "tau_c")


def rel(a, b):
    return abs(a - b) / abs(b)


# ---------------------------------------------------------------- linear spring-dashpot
#
# alpha = 1, gamma = 0: x'' + x' + Omega x = 0, x(0) = 0, x'(0) = 1.
# Underdamped (Omega > 1/4), w = sqrt(Omega - 1/4):
#   x   = e^(-t/2) sin(w t) / w
#   x'  = e^(-t/2) [cos(w t) - sin(w t) / (2 w)]           -> tan(w tau_b) = 2 w
#   x'' = e^(-t/2) [sin(w t) (1/(4w) - w) - cos(w t)]       -> tan(w tau_c) = w / (1/2 - Omega)
# (1/4 - w^2 = 1/2 - Omega); the first positive roots are the atan2 values in (0, pi),
# and x first returns to 0 at w t = pi, after tau_c, so contact ends by force.
# Overdamped (Omega < 1/4), k = sqrt(1/4 - Omega): sin -> sinh, tan -> tanh, w -> k and
#   1/(4k) + k replaces 1/(4w) - w, giving tanh(k tau_b) = 2k, tanh(k tau_c) = k / (1/2 - Omega).
# Critical (Omega = 1/4): x = t e^(-t/2), tau_b = 2, tau_c = 4.


def linear_exact(omega):
    om = mp.mpf(omega.numerator) / omega.denominator
    half = mp.mpf(1) / 2
    if om > mp.mpf(1) / 4:
        w = mp.sqrt(om - mp.mpf(1) / 4)

        def x(t):
            return mp.exp(-t / 2) * mp.sin(w * t) / w

        def v(t):
            return mp.exp(-t / 2) * (mp.cos(w * t) - mp.sin(w * t) / (2 * w))

        tau_b = mp.atan2(2 * w, 1) / w
        tau_c = mp.atan2(w, half - om) / w
    elif om < mp.mpf(1) / 4:
        k = mp.sqrt(mp.mpf(1) / 4 - om)

        def x(t):
            return mp.exp(-t / 2) * mp.sinh(k * t) / k

        def v(t):
            return mp.exp(-t / 2) * (mp.cosh(k * t) - mp.sinh(k * t) / (2 * k))

        tau_b = mp.atanh(2 * k) / k
        tau_c = mp.atanh(k / (half - om)) / k
    else:
        def x(t):
            return t * mp.exp(-t / 2)

        def v(t):
            return mp.exp(-t / 2) * (1 - t / 2)

        tau_b, tau_c = mp.mpf(2), mp.mpf(4)
    return dict(tau_b=tau_b, x_b=x(tau_b), tau_c=tau_c, x_c=x(tau_c), eps=-v(tau_c),
                v_b=v(tau_b), acc_c=-v(tau_c) - om * x(tau_c))


@pytest.mark.parametrize("omega", [
    Fraction(1, 1000), Fraction(1, 10), Fraction(1, 4) - Fraction(1, 10**6), Fraction(1, 4),
    Fraction(1, 4) + Fraction(1, 10**6), Fraction(1), Fraction(1000)])
def test_linear_spring_dashpot(omega):
    with mp.workdps(60):
        exact = linear_exact(omega)
        # the closed forms themselves: x'(tau_b) = 0 and x''(tau_c) = -x' - Omega x = 0
        assert abs(exact["v_b"]) < mp.mpf(10) ** -50
        assert abs(exact["acc_c"]) < mp.mpf(10) ** -50
    r = reference_collision((1, 0), omega, digits=30)
    assert r.ended_by == "force"
    with mp.workdps(60):
        for name in QUANTITIES + ("x_c",):
            assert rel(getattr(r, name), exact[name]) < 1e-20, name
    assert r.error_estimate < 1e-25


# --------------------------------------------------------------- gamma = 1, Omega -> 0
#
# With gamma = 1 the first integral is x' + x^2/2 = 1 - Omega I(tau), I = int_0^tau x^alpha,
# so x_b^2 = 2 (1 - Omega I_b). For small Omega, x ~ x0 = sqrt2 tanh(tau/sqrt2) and
# I_b = 2^(alpha/2) tau_b - K + o(1), K = int_0^inf 2^(alpha/2) (1 - tanh^alpha(t/sqrt2)) dt,
# the error being O(Omega log^2 Omega) relative.


@pytest.mark.parametrize("alpha", ["3/2", "2"])
@pytest.mark.slow
def test_gamma_one_small_omega_bound_tends_to_sqrt2(alpha):
    a = mp.mpf(Fraction(alpha).numerator) / Fraction(alpha).denominator
    with mp.workdps(30):
        K = mp.quad(lambda t: 2 ** (a / 2) * (1 - mp.tanh(t / mp.sqrt(2)) ** a), [0, mp.inf])
    previous = None
    for om in ("1e-4", "1e-8", "1e-12"):
        r = reference_collision((alpha, 1), om, digits=25)
        with mp.workdps(30):
            omega = mp.mpf(om)
            gap = mp.sqrt(2) - r.x_b
            assert gap > 0
            # I_b <= 2^(alpha/2) tau_b because x <= sqrt2 during compression
            assert gap <= omega * 2 ** (a / 2) * r.tau_b / r.x_b
            predicted = omega * (2 ** (a / 2) * r.tau_b - K) * 2 / (mp.sqrt(2) + r.x_b)
            assert rel(gap, predicted) < 10 * omega * mp.log(omega) ** 2
            if previous is not None:
                assert gap < previous / 1000
            previous = gap
    assert previous < 1e-10


# ---------------------------------------------------------------------- alpha = gamma
#
# f = Omega + v and v dv/dy = -(Omega + v) with y = x^(gamma+1)/(gamma+1); integrating,
# v - Omega ln(Omega + v) + y = 1 - Omega ln(1 + Omega). Hence f never vanishes, contact
# ends by separation (y = 0) with eps + 1 = Omega ln((1 + Omega)/(Omega - eps)), and
# y_b = 1 - Omega ln((1 + Omega)/Omega). The trajectory in (y, v) does not depend on gamma.


@pytest.mark.parametrize("gamma", ["1", "3/2", "1/3"])
@pytest.mark.parametrize("omega", ["0.01", "0.5", "20"])
def test_alpha_equals_gamma_exact_separation(gamma, omega):
    r = reference_collision((gamma, gamma), omega, digits=30)
    assert r.ended_by == "separation"
    assert r.x_c == 0
    with mp.workdps(50):
        om = mp.mpf(omega)
        g1 = mp.mpf(Fraction(gamma).numerator) / Fraction(gamma).denominator + 1
        # the left side minus the right is decreasing in eps on (0, Omega): bisection
        lo, hi = mp.zero, om
        for _ in range(250):
            mid = (lo + hi) / 2
            if mid + 1 - om * mp.log((1 + om) / (om - mid)) > 0:
                lo = mid
            else:
                hi = mid
        eps = (lo + hi) / 2
        y_b = 1 - om * mp.log((1 + om) / om)
        x_b = (g1 * y_b) ** (1 / g1)
        assert 0 < eps < 1
        assert rel(r.eps, eps) < 1e-25
        assert rel(r.x_b, x_b) < 1e-25


# -------------------------------------------------------------------- self-consistency


# The check run behind digits=30 is itself a 40-digit run, so r30.error_estimate is the
# 30-vs-40 difference; what makes it trustworthy is r40.error_estimate (40 vs 50 digits),
# which shows the 40-digit values are many orders closer to the truth.


@pytest.mark.parametrize("alpha,gamma", [("3/2", "1"), ("3/2", "1/2"), ("2", "1")])
@pytest.mark.parametrize("omega", ["1e-3", "1", "1e3"])
@pytest.mark.slow
def test_digits_30_against_40(alpha, gamma, omega):
    r30 = reference_collision((alpha, gamma), omega, digits=30)
    r40 = reference_collision((alpha, gamma), omega, digits=40)
    assert r30.ended_by == r40.ended_by == "force"
    with mp.workdps(60):
        for name in QUANTITIES:
            assert rel(getattr(r30, name), getattr(r40, name)) < 1e-28, name
    assert r30.error_estimate < 1e-28
    assert r40.error_estimate < 1e-38


# ------------------------------------------------------------------------ separation


@pytest.mark.parametrize("omega", ["1e-3", "0.1", "1", "1e3"])
@pytest.mark.slow
def test_alpha_below_gamma_separates(omega):
    r = reference_collision((1, "3/2"), omega, digits=30)
    assert r.ended_by == "separation"
    assert r.x_c == 0
    assert 0 < r.eps < 1
    assert 0 < r.tau_b < r.tau_c
    assert r.error_estimate < 1e-25


def test_result_fields_and_floats():
    r = reference_collision(("3/2", 1), 0.5521, digits=20)
    assert isinstance(r, HighPrecisionCollision)
    assert r.alpha == Fraction(3, 2) and r.gamma == Fraction(1)
    d = r.as_floats()
    assert set(d) >= {"eps", "tau_b", "x_b", "tau_c", "x_c", "end", "ended_by", "error_estimate"}
    assert all(isinstance(d[k], float) for k in ("eps", "tau_b", "x_b", "tau_c", "x_c"))
    assert 0 < d["eps"] < 1 and d["tau_b"] < d["tau_c"] and d["x_c"] < d["x_b"]
    assert d["ended_by"] == "force"


def test_caller_precision_untouched():
    before = mp.dps
    reference_collision(("3/2", 1), 1, digits=20)
    assert mp.dps == before


@pytest.mark.parametrize("kwargs", [
    dict(alpha="3/2", gamma=1, omega=0),
    dict(alpha="3/2", gamma=1, omega=-1.0),
    dict(alpha="3/2", gamma=1, omega=float("nan")),
    dict(alpha="3/2", gamma=1, omega="abc"),
    dict(alpha="3/2", gamma=1, omega=True),
    dict(alpha=0, gamma=1, omega=1.0),
    dict(alpha="3/2", gamma=-1, omega=1.0),
    dict(alpha="3/2", gamma=1, omega=1.0, digits=3),
    dict(alpha="3/2", gamma=1, omega=1.0, digits=30.0),
])
def test_bad_parameters(kwargs):
    with pytest.raises(ParameterError):
        reference_collision((kwargs.pop("alpha"), kwargs.pop("gamma")), **kwargs)


@pytest.mark.parametrize("alpha, gamma, omega", [("1/11", "1/12", 1.0), ("5/12", "7/11", 3.0), ("11/12", "1/11", 0.5)])
@pytest.mark.slow
def test_denominators_eleven_and_twelve_agree_with_the_scipy_reference(alpha, gamma, omega):
    """p = 132: the Taylor order must reach past the gap of the sparse series at u = 0 (it used to
    fail with an IndexError, and a too-short series would have looked converged)."""
    from restitution.core.collision import collide

    ref = reference_collision((alpha, gamma), omega, digits=16)
    assert float(ref.eps) == pytest.approx(collide((alpha, gamma), omega).eps, rel=1e-9)

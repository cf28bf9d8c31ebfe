"""The viscous and elastic limits derived in restitution.core.asymptotics, checked against the integrators.

The compiled integrator (restitution.fast.integrator) at rtol 1e-14 is accurate to ~1e-14 (checked against
the mpmath reference in test_epsilon.py); the published constants are checked both as formulas and
by extracting them from high-precision data alone.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from scipy import special

from restitution.core import asymptotics as asy
from restitution.core.exponents import as_exponents
from restitution.fast.integrator import collide_fast
from restitution.core.highprec import reference_collision
from restitution.fast.calibration import MUELLER_POESCHEL_PADE
from restitution.core.model import Material


def ref(alpha, gamma, omegas, rtol=1e-14):
    ex = as_exponents(alpha, gamma)
    out = collide_fast(ex.p, ex.q_alpha, ex.q_gamma, np.atleast_1d(omegas), rtol)
    assert np.all(out[:, 5] != 2), "integrator failed"
    return out


FORCE_CASES = [("3/2", "1"), ("3/2", "1/2"), ("1", "0"), ("2", "0"), ("5/2", "1/2"), ("5/4", "1"), ("2", "1")]


# ----------------------------------------------------------------------------- viscous limit
@pytest.mark.parametrize("alpha", ["1", "3/2", "2", "5/2"])
def test_gamma_zero_constants_are_elementary(alpha):
    """gamma = 0: x0 = 1 - exp(-tau), so X = B = 1 and K0 = H_alpha exactly."""
    V = asy.viscous_limit((alpha, "0"))
    a = float(as_exponents(alpha, "0").alpha)
    assert V.X == 1.0 and V.lam == 1.0
    assert V.B == pytest.approx(1.0, rel=1e-12)
    assert V.K0 == pytest.approx(special.digamma(a + 1) + np.euler_gamma, rel=1e-12)
    assert V.k == 1.0


def test_gamma_one_constants_match_tanh_solution():
    """gamma = 1: x0 = sqrt2 tanh(tau/sqrt2), so X = lambda = sqrt2, B = 2 sqrt2, k = 2^((alpha-1)/2)."""
    V = asy.viscous_limit(("3/2", "1"))
    assert V.X == pytest.approx(math.sqrt(2), rel=1e-15)
    assert V.lam == pytest.approx(math.sqrt(2), rel=1e-15)
    assert V.B == pytest.approx(2 * math.sqrt(2), rel=1e-12)
    assert V.k == pytest.approx(2 ** 0.25, rel=1e-15)
    # K0 = 2^(3/4) sqrt2 int_0^inf (1 - tanh^(3/2) s) ds, by mpmath
    with mpmath.workdps(25):
        k0 = 2 ** 0.75 * math.sqrt(2) * float(mpmath.quad(lambda s: 1 - mpmath.tanh(s) ** 1.5, [0, 1, 10, mpmath.inf]))
    assert V.K0 == pytest.approx(k0, rel=1e-12)


@pytest.mark.parametrize("alpha,gamma", FORCE_CASES + [("2", "3/2")])
def test_damped_constants_closed_forms_equal_their_quadratures(alpha, gamma):
    """B and K0 in digamma form against the defining quadratures of the damped-only motion."""
    ex = as_exponents(alpha, gamma)
    a, n = float(ex.alpha), float(ex.gamma) + 1
    X, lam, B, K0 = asy._damped_constants(ex.alpha, ex.gamma)
    with mpmath.workdps(40):   # X in 40 digits, so that 1 - G(y) vanishes at y = X as it must
        n_, a_ = mpmath.mpf(ex.gamma.numerator) / ex.gamma.denominator + 1, mpmath.mpf(a)
        X_ = n_ ** (1 / n_)
        lam_ = X_ ** (n_ - 1)
        # in d = X - y, with 1 - G(X - d) = -expm1(n log1p(-d/X)): no cancellation as d -> 0
        one_minus_G = lambda d: -mpmath.expm1(n_ * mpmath.log1p(-d / X_))  # noqa: E731
        lnB = mpmath.log(X_) + mpmath.quad(lambda d: lam_ / one_minus_G(d) - 1 / d, [0, X_ / 2, X_])
        k0 = mpmath.quad(lambda d: (X_ ** a_ - (X_ - d) ** a_) / one_minus_G(d), [0, X_ / 2, X_])
        lnB, k0 = float(lnB), float(k0)
    assert B == pytest.approx(math.exp(lnB), rel=1e-13)
    assert K0 == pytest.approx(k0, rel=1e-13)


def test_paper_exponents_viscous_constants_are_elementary():
    """alpha = 3/2, gamma = 1: c_log = 2^(1/4)/2, c_const = (2^(1/4)/4)((9/2) ln 2 + pi/2 - 5)."""
    V = asy.viscous_limit(("3/2", "1"))
    q = 2 ** 0.25
    assert V.c_log == pytest.approx(q / 2, rel=1e-15)
    assert V.L == pytest.approx(3.5 * math.log(2), rel=1e-14)
    assert V.K0 == pytest.approx(q * (4 - math.pi / 2 - math.log(2)), rel=1e-14)
    assert V.c_const == pytest.approx(q / 4 * (4.5 * math.log(2) + math.pi / 2 - 5), rel=1e-13)


@pytest.mark.parametrize("alpha,gamma", [("3/2", "1"), ("3/2", "1/2"), ("1", "0"), ("2", "1")])
def test_viscous_correction_constant_extracted_from_the_integrator(alpha, gamma):
    """c_const from data alone: c(Omega) = (1 - eps/(k Omega))/Omega - c_log ln(1/Omega) fitted by
    c_const + Omega (a L^2 + b L + c) + Omega^2 (d L^4 + e L^3 + f L^2) on Omega in [1e-6, 1e-3]
    (eps to ~1e-14, so c(Omega) to ~1e-8 at the smallest Omega); the derived constant within 1e-8."""
    V = asy.viscous_limit((alpha, gamma))
    om = np.geomspace(1e-6, 1e-3, 25)
    L = np.log(1 / om)
    c = (1 - ref(alpha, gamma, om)[:, 0] / (V.k * om)) / om - V.c_log * L
    M = np.vstack([np.ones_like(om), om * L * L, om * L, om, om * om * L ** 4, om * om * L ** 3,
                   om * om * L * L]).T
    fitted = np.linalg.lstsq(M, c, rcond=None)[0][0]
    assert abs(fitted - V.c_const) < 1e-8


@pytest.mark.slow
@pytest.mark.parametrize("alpha,gamma", FORCE_CASES)
def test_viscous_leading_constant(alpha, gamma):
    """eps/Omega -> k = (gamma+1)^((alpha-gamma)/(gamma+1)), at the rate Omega ln(1/Omega)."""
    V = asy.viscous_limit((alpha, gamma))
    g = float(as_exponents(alpha, gamma).gamma)
    a = float(as_exponents(alpha, gamma).alpha)
    assert V.k == pytest.approx((g + 1) ** ((a - g) / (g + 1)), rel=1e-15)
    om = np.array([1e-6, 1e-8])
    eps = ref(alpha, gamma, om)[:, 0]
    dev = np.abs(eps / (V.k * om) - 1)
    assert np.all(dev <= 20 * om * np.log(1 / om))
    assert dev[1] < dev[0] / 50  # it really goes to zero


@pytest.mark.parametrize("alpha,gamma", FORCE_CASES)
def test_viscous_first_correction(alpha, gamma):
    """With the derived O(Omega ln Omega) term the remainder is O((Omega ln Omega)^2).

    Without the correction the remainder would be ~ c_log Omega ln(1/Omega) ~ 1e-5 at 1e-6,
    three orders above what is asserted.
    """
    V = asy.viscous_limit((alpha, gamma))
    om = np.array([1e-5, 1e-6, 1e-7])
    eps = ref(alpha, gamma, om)[:, 0]
    r = np.abs(V.eps(om, 1) / eps - 1)
    assert np.all(r <= 20 * (om * np.log(1 / om)) ** 2)


@pytest.mark.parametrize("alpha, gamma", [("3/2", "1/4"), ("2", "1/2"), ("3", "1"), ("5", "2"), ("7/3", "2/3")])
def test_viscous_correction_of_the_exact_family_is_the_dashpots(alpha, gamma):
    """For alpha = 2 gamma + 1, eps(Omega) is the dashpot's at l Omega (l = gamma + 1), whose expansion
    W [1 - W (2 ln(1/W) - 2)] gives c_log = 2 l and c_const = -2 l (ln l + 1): the digamma closed forms,
    which do not use the mapping, must reproduce both (referee r18's analytic check, gamma > 0)."""
    v = asy.viscous_limit((alpha, gamma))
    ell = float(as_exponents(alpha, gamma).gamma) + 1.0
    assert v.kind == "force"
    assert v.c_log == pytest.approx(2.0 * ell, rel=1e-13)
    assert v.c_const == pytest.approx(-2.0 * ell * (math.log(ell) + 1.0), rel=1e-13)


def test_viscous_first_correction_against_mpmath():
    V = asy.viscous_limit(("3/2", "1"))
    hp = float(reference_collision(("3/2", "1"), 1e-6, digits=20).eps)
    assert abs(V.eps(1e-6, 1) / hp - 1) < 2e-10
    assert abs(V.eps(1e-6, 0) / hp - 1) > 1e-6  # the correction matters


@pytest.mark.parametrize("alpha,gamma", [("3/2", "1"), ("1", "0")])
def test_viscous_contact_time(alpha, gamma):
    """tau_c = (2 ln(1/Omega) + L)/lambda + O(Omega ln Omega)."""
    V = asy.viscous_limit((alpha, gamma))
    om = np.array([1e-6, 1e-8])
    tc = ref(alpha, gamma, om)[:, 3]
    assert np.all(np.abs(V.tau_c(om) - tc) <= 1e3 * om)


@pytest.mark.parametrize("gamma", ["0", "1/2", "1", "3/2"])
def test_equal_exponents_closed_form(gamma):
    """alpha = gamma: eps = Omega - (1 + Omega) exp(-(1 + eps)/Omega) for every Omega."""
    om = np.array([1e-3, 0.05, 1.0, 20.0, 1e3, 1e5, 1e8])
    closed = asy.equal_exponents_eps(om)
    if gamma != "0":
        num = ref(gamma, gamma, om)[:, 0]
        assert np.max(np.abs(num / closed - 1)) < 5e-14
    # the defining relation holds (where it is not cancellation-limited)
    mid = om <= 20
    lhs = closed[mid]
    rhs = om[mid] - (1 + om[mid]) * np.exp(-(1 + closed[mid]) / om[mid])
    assert np.max(np.abs(lhs / rhs - 1)) < 1e-13
    # limits: eps/Omega -> 1 (exponentially), eps = 1 - 2/(3 Omega) + O(Omega^-2)
    assert closed[0] == pytest.approx(1e-3, rel=1e-15)
    assert abs(1 - closed[-1] - 2 / (3 * 1e8)) < 1e-15


def test_equal_exponents_against_mpmath():
    for w in (0.05, 1.0, 1e4):
        hp = float(reference_collision(("1", "1"), w, digits=20).eps)
        assert abs(asy.equal_exponents_eps(w) / hp - 1) < 2e-15


@pytest.mark.parametrize("alpha,gamma", [("1", "3/2"), ("1", "2"), ("5/4", "3/2")])
def test_inner_law_alpha_below_gamma(alpha, gamma):
    """alpha < gamma: eps = K Omega^((gamma+1)/(2gamma+1-alpha)), K from the inner problem.

    The inner rescaling is exact with initial speed Omega^(-b); memory of it dies out on the
    attracting slow manifold, so the law holds to the accuracy of K already at Omega ~ 1e-2.
    """
    V = asy.viscous_limit((alpha, gamma))
    ex = as_exponents(alpha, gamma)
    assert V.kind == "inner"
    assert V.power == pytest.approx(float((ex.gamma + 1) / (2 * ex.gamma + 1 - ex.alpha)))
    ks = [asy.inner_constant((alpha, gamma), y_start=y) for y in (30.0, 300.0)]
    assert abs(ks[0] / ks[1] - 1) < 1e-10
    om = np.array([1e-2, 1e-4])
    eps = ref(alpha, gamma, om, 1e-13)[:, 0]
    assert np.max(np.abs(V.eps(om) / eps - 1)) < 5e-12
    assert eps[1] / 1e-4 > eps[0] / 1e-2  # eps/Omega diverges: no finite k


# ----------------------------------------------------------------------------- elastic limit
def test_published_constants_from_formulas():
    """Ramirez et al. (1999) C1 = 1.1534489, Schwager-Poeschel C2 = 0.7982666, T0 = 3.2180655."""
    assert asy.RAMIREZ_C1 == pytest.approx(1.1534489, abs=5e-8)
    assert asy.RAMIREZ_C2 == pytest.approx(0.7982666, abs=5e-8)
    assert asy.HERTZ_CONTACT_TIME == pytest.approx(3.2180655, abs=5e-8)
    E = asy.elastic_limit(("3/2", "1/2"))
    # the general-exponent formulas reduce to the published closed forms
    assert E.C1 == pytest.approx(asy.RAMIREZ_C1, rel=1e-14)
    assert E.C2 == pytest.approx(asy.RAMIREZ_C2, rel=1e-14)
    assert E.A == 0.6 and E.E == pytest.approx(4 / 15) and E.end_power == 2.5
    assert E.T0 == pytest.approx(asy.HERTZ_CONTACT_TIME, rel=1e-14)
    assert asy.elastic_limit(("3/2", "1")).T0 == pytest.approx(asy.HERTZ_CONTACT_TIME, rel=1e-14)


def test_omega_maps_onto_the_published_expansion_variable():
    """Force rho xi^(3/2) + (3/2) A rho xi^(1/2) xi' (per unit mass): D1 = rho, D2 = (3/2) A rho.

    Their expansion variable (3/2) A rho^(2/5) g^(1/5) equals Omega^(-3/5) in our scaling.
    """
    rho, A = 2.7e4, 3.1e-5
    mat = Material("3/2", "1/2", rho, 1.5 * A * rho)
    g = np.array([0.01, 0.3, 7.0])
    assert np.allclose(mat.omega(g) ** (-0.6), 1.5 * A * rho ** 0.4 * g ** 0.2, rtol=1e-13)


@pytest.mark.slow
def test_published_constants_reproduced_from_data():
    """C1, C2 (and the end term and T0) extracted from mpmath data alone, without the formulas.

    (1 - eps)/delta = C1 - C2 delta - E delta^(3/2) + c3 delta^2 + c4 delta^(5/2) + ..., delta = Omega^(-3/5):
    solve the 6x6 system at 7 points (least squares) for delta in [1e-5, 1e-3].
    """
    with mpmath.workdps(30):
        ds = np.geomspace(1e-5, 1e-3, 7)
        rows = []
        for d in ds:
            w = mpmath.mpf(d) ** (-mpmath.mpf(5) / 3)
            r = reference_collision(("3/2", "1/2"), w, digits=28)
            dd = w ** (-mpmath.mpf(3) / 5)
            rows.append((dd, (1 - r.eps) / dd, r.tau_c * w ** (mpmath.mpf(2) / 5)))
        M = mpmath.matrix([[d ** p for p in (0, 1, 1.5, 2, 2.5, 3)] for d, _, _ in rows])
        sol = mpmath.lu_solve(M.T * M, M.T * mpmath.matrix([y for _, y, _ in rows]))
        T = mpmath.matrix([[d ** p for p in (0, 1, 2, 3)] for d, _, _ in rows])
        tsol = mpmath.lu_solve(T.T * T, T.T * mpmath.matrix([t for _, _, t in rows]))
    assert abs(float(sol[0]) / 1.1534489 - 1) < 1e-6          # published C1
    assert abs(-float(sol[1]) / 0.7982666 - 1) < 1e-6         # published C2
    assert abs(float(sol[0]) / asy.RAMIREZ_C1 - 1) < 1e-12
    assert abs(-float(sol[1]) / asy.RAMIREZ_C2 - 1) < 1e-8
    assert abs(-float(sol[2]) - 4 / 15) < 1e-5                # derived end-of-contact term
    assert abs(float(tsol[0]) / 3.2180655 - 1) < 1e-6         # published contact time
    assert abs(float(tsol[0]) / asy.HERTZ_CONTACT_TIME - 1) < 1e-10


@pytest.mark.parametrize("alpha,gamma", [("3/2", "1/2"), ("3/2", "1"), ("1", "0"), ("5/2", "1/2"),
                                         ("1", "1"), ("1", "3/2")])
def test_elastic_expansion_general_exponents(alpha, gamma):
    """Remainder after C1, C2 = A C1^2 and the end term is O(delta^q), q = min(3, end_power + 1)."""
    E = asy.elastic_limit((alpha, gamma))
    q = min(3.0, E.end_power + 1)
    om = np.array([1e4, 1e6])
    om = om[E.delta(om) > 1e-5]  # keep the remainder above the integrator's noise
    eps = ref(alpha, gamma, om)[:, 0]
    d = E.delta(om)
    r2 = np.abs(E.eps(om, 2) - eps)
    r1 = np.abs(E.eps(om, 1) - eps)
    assert np.all(r2 <= 3 * d ** q + 1e-14)
    assert np.all(r1 > 10 * r2)  # the second-order terms are right, not just small


@pytest.mark.parametrize("alpha,gamma", [("3/2", "1/2"), ("3/2", "1"), ("2", "1")])
def test_elastic_contact_time(alpha, gamma):
    E = asy.elastic_limit((alpha, gamma))
    om = np.array([1e8, 1e10])
    tc = ref(alpha, gamma, om)[:, 3]
    dev = np.abs(tc / E.tau_c(om) - 1)
    assert np.all(dev <= 3 * E.delta(om))
    assert dev[1] < dev[0]


def test_mueller_poeschel_pade_is_consistent_with_the_expansion():
    """(1 + a v)/(1 + a v + b2 v^2 + b3 v^3 + b4 v^4) = 1 - b2 v^2 + (b3 - a b2)(-v^3) + c4 v^4 ...

    with v^2 = delta: -C1 at v^2, nothing at v^3, +C2 at v^4 (to the 6 digits printed).
    """
    c = MUELLER_POESCHEL_PADE
    a, b2, b3, b4 = c["a"], c["b2"], c["b3"], c["b4"]
    assert b2 == pytest.approx(asy.RAMIREZ_C1, rel=1e-5)
    assert abs(b3 - a * b2) < 5e-6
    c4 = b2 * (b2 - a * a) + a * b3 - b4
    assert c4 == pytest.approx(asy.RAMIREZ_C2, rel=1e-5)


@pytest.mark.parametrize("omega", [1.6e16, 2e16, 1e20, 1e100, 1e300])
def test_equal_exponents_closed_form_deep_in_the_elastic_regime(omega):
    """Newton's slope used to be 0/0 from Omega ~ 1.6e16 on (a traceback through `eps`): here
    1 - eps = 2/(3 Omega) to leading order (u = 2/Omega, eps = 1 - u/3 + ...)."""
    from restitution.core.asymptotics import equal_exponents_eps

    eps = float(equal_exponents_eps(omega))
    assert math.isfinite(eps) and eps <= 1.0
    assert 1.0 - eps == pytest.approx(2.0 / (3.0 * omega), rel=1e-3, abs=2.3e-16)

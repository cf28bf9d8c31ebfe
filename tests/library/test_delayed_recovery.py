"""Schwager and Poeschel's series re-derived (restitution.core.delayed_recovery), checked against the ladder.

The ladder's eps at tol 1e-12 (master curve or integrator, independent of the module's own
integrations) is fitted at large Omega; the fit, not the derivation, gives the numbers compared here.
"""

from __future__ import annotations

import numpy as np
import pytest

from restitution.api import epsilon
from restitution.core.asymptotics import elastic_limit
from restitution.core.delayed_recovery import (end_of_contact_eps, overlap_damping_coefficients,
                                               schwager_poeschel_series)
from restitution.core.errors import ParameterError


def ladder(omega, end):
    return np.asarray(epsilon(alpha="3/2", gamma="1/2", omega=omega, end=end, tol=1e-12).eps)


@pytest.fixture(scope="module")
def series():
    return schwager_poeschel_series(12)


def test_end_relation_holds_to_the_order_derived():
    """eps_force from eps_overlap at the same Omega: the remainder is O(delta^(15/2)), and dropping the
    delta^5 term leaves a remainder a hundred times larger where it can be measured."""
    om = np.array([10.0, 30.0, 100.0])
    d = om ** -0.6
    ef, eo = ladder(om, "force"), ladder(om, "overlap")
    full = np.abs(ef - end_of_contact_eps(eo, d))
    assert np.all(full < 0.05 * d ** 7.5 + 1e-12)
    first_only = np.abs(ef - (eo + (4 / 15) * eo ** 1.5 * d ** 2.5))
    assert np.all(first_only[:2] > 100 * full[:2])


def test_coefficients_against_a_fit_of_the_ladder(series):
    """Fit (eps - sum_{k<=5} h_k s^k) / s^6 = h6 + h7 s + ... on s in [0.09, 0.36] (Omega 30..3000)."""
    om = np.geomspace(30.0, 3000.0, 16)
    s = om ** -0.3
    ef = ladder(om, "force")
    r = (ef - series.eps(om, 5)) / s ** 6
    fit = np.polynomial.polynomial.polyfit(s, r, 6)
    assert fit[0] == pytest.approx(series.h[6], abs=2e-5)
    assert fit[1] == pytest.approx(series.h[7], abs=5e-4)
    assert fit[2] == pytest.approx(series.h[8], abs=5e-3)


def test_low_orders_are_the_closed_forms(series):
    E = elastic_limit(("3/2", "1/2"))
    assert series.h[1] == 0.0 and series.h[3] == 0.0
    assert series.h[2] == -E.C1 and series.h[4] == E.C2
    assert series.h[5] == pytest.approx(E.E, rel=1e-15)
    assert series.h[7] == pytest.approx(-0.4 * E.C1, rel=1e-14)


def test_overlap_coefficients_reproduce_the_closed_forms():
    """The numerically derived c1, c2 meet -C1 and (3/5) C1^2 (not used by the series itself)."""
    c = overlap_damping_coefficients(4)
    E = elastic_limit(("3/2", "1/2"))
    assert c[0] == pytest.approx(1.0, abs=1e-12)
    assert c[1] == pytest.approx(-E.C1, abs=1e-9)
    assert c[2] == pytest.approx(E.C2, abs=1e-8)


def test_truncation_error_falls_with_order(series):
    om = np.array([1e3])
    ef = ladder(om, "force")
    errs = [abs(float(series.eps(om, k)[0] - ef[0])) for k in (4, 6, 8, 10)]
    assert all(b < a / 10 for a, b in zip(errs, errs[1:]))


@pytest.mark.parametrize("kmax", [4, 15, 7.0])
def test_kmax_out_of_range_is_refused(kmax):
    with pytest.raises(ParameterError, match="kmax"):
        schwager_poeschel_series(kmax)

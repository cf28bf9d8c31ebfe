"""The compiled integrator keeps its stated bound for exponents with p >= 3 (alpha, gamma with a
common denominator of 3 or 4), where its u legs once took steps past the curvature (issue 28)."""

import numpy as np
import pytest

from restitution.api import collide
from restitution.core.collision import collide as reference
from restitution.fast.rung import integrator_bound


@pytest.mark.parametrize("alpha, gamma", [("2", "3/4"), ("7/4", "1/2"), ("5/3", "1/3")])
@pytest.mark.parametrize("omega", [1e-3, 1.0, 1e3, 6e5])
@pytest.mark.parametrize("rtol", [1e-9, 1e-12])
def test_compiled_integrator_within_its_bound_for_p_at_least_3(alpha, gamma, omega, rtol):
    truth = reference(alpha, gamma, omega, rtol=1e-14).eps       # stated accuracy 2.4e-13
    got = collide(alpha, gamma, omega, method="fast", rtol=rtol).eps
    assert abs(got / truth - 1) <= integrator_bound(rtol) - 2.4e-13


def test_tableau_is_scipys_own():
    # read from scipy's file without importing scipy.integrate: the same numbers as the import gives
    from scipy.integrate._ivp import dop853_coefficients as dop

    from restitution.fast import integrator
    n = dop.N_STAGES
    for ours, theirs in ((integrator._A, dop.A[:n, :n]), (integrator._B, dop.B), (integrator._C, dop.C[:n]),
                         (integrator._E3, dop.E3), (integrator._E5, dop.E5)):
        assert ours.shape == theirs.shape and ours.tobytes() == np.ascontiguousarray(theirs, float).tobytes()

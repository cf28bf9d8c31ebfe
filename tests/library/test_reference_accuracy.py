"""Acceptance test of the double-precision integrator against the mpmath reference.

``restitution.core.collision.collide`` (scipy DOP853/Radau) and ``restitution.core.highprec``
(Taylor series in mpmath) share no code, so agreement to 1e-8 relative over the whole
Omega range and several exponent pairs is evidence that both are right, not that they
repeat the same mistake. The reference runs at 20 digits: its own error estimate must be
far below the tolerance, otherwise the comparison would measure the reference.
"""

from functools import lru_cache

import pytest

collision = pytest.importorskip("restitution.core.collision")
from restitution.core.highprec import reference_collision  # noqa: E402

#: Acceptance bar for collide(rtol=1e-12); the brief aims for 1e-9.
TOLERANCE = 1e-8
#: The reference must be this much better than the bar to act as truth.
REFERENCE_MARGIN = 1e-6
REFERENCE_DIGITS = 20

OMEGAS = (1e-3, 1e-2, 0.1, 1.0, 10.0, 100.0, 1e3)
PAIRS = (
    ("3/2", "1"),     # the paper's case
    ("3/2", "1/2"),
    ("2", "1"),
    ("1", "0"),       # linear spring-dashpot
    ("3", "3/2"),
    ("1", "3/2"),     # alpha < gamma: ends by separation
    ("1", "1"),       # alpha = gamma: the force never vanishes, separation
    ("5/3", "1/3"),   # p = 3
)
COMPARED = ("eps", "tau_b", "x_b", "tau_c")


@lru_cache(maxsize=None)
def reference(alpha, gamma, omega):
    return reference_collision((alpha, gamma), omega, digits=REFERENCE_DIGITS)


def relative_errors(alpha, gamma, omega):
    ref = reference(alpha, gamma, omega)
    got = collision.collide((alpha, gamma), omega, rtol=1e-12)
    truth = ref.as_floats()
    errors = {name: abs(getattr(got, name) - truth[name]) / abs(truth[name]) for name in COMPARED}
    if ref.ended_by == "force":
        errors["x_c"] = abs(got.x_c - truth["x_c"]) / truth["x_c"]
    return ref, got, errors


@pytest.mark.parametrize("alpha,gamma", PAIRS)
@pytest.mark.parametrize("omega", OMEGAS)
@pytest.mark.slow
def test_collide_matches_reference(alpha, gamma, omega):
    ref, got, errors = relative_errors(alpha, gamma, omega)
    assert ref.error_estimate < TOLERANCE * REFERENCE_MARGIN
    assert got.ended_by == ref.ended_by
    report = ", ".join(f"{k} {v:.2e}" for k, v in errors.items())
    assert max(errors.values()) < TOLERANCE, f"alpha={alpha} gamma={gamma} Omega={omega}: {report}"

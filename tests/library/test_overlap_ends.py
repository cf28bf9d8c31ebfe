"""The overlap rule's master curve at its two ends (issue 54, item 2): the viscous law C Omega^k
below its panels where the bodies cannot stick, the elastic expansion above; each stated bound
checked against the high-precision reference (core.highprec.highprec_eps: the Taylor integration,
and below 1e-5 the creeping return through its inner problem) over 1e-12..1e20; a sticking pair
keeps its refusal."""

from __future__ import annotations

import io
import math

import numpy as np
import pytest

from restitution.core.collision import StickError
from restitution.core.highprec import highprec_eps
from restitution.core.overlap_limit import overlap_limit
from restitution.core.exponents import as_exponents
from restitution.core.problem import Problem
from restitution.fast.ladder import Ladder
from restitution.fast.overlap_master import OMEGA_HI, OMEGA_LO

SEED = int(np.random.SeedSequence().entropy % 2**32)
RNG = np.random.default_rng(SEED)
# Kim's pair, LAMMPS' Hertz with viscoelastic damping, and two pairs not named in the issue
PAIRS = [("3/2", "1"), ("3/2", "1/2"), ("5/4", "1/2"), ("5/2", "3/2")]


@pytest.fixture(scope="module")
def curves(tmp_path_factory):
    root = tmp_path_factory.mktemp("ends")
    return {p: Ladder(p, cache_dir=str(root), stream=io.StringIO()) for p in PAIRS + [("3/2", "0")]}


def _truth(pair, w: float) -> tuple[float, float]:
    """eps and its accuracy from the high-precision reference (below 1e-5 through the creep's inner problem)."""
    eps, err = highprec_eps(Problem(as_exponents(pair), "overlap"), w, digits=20)
    return float(eps), float(err) + 1.2e-16


def _spread(lo10: float, hi10: float, n: int) -> np.ndarray:
    """n points, one at random in each of n equal slices of [lo10, hi10] in log10 Omega."""
    edges = np.linspace(lo10, hi10, n + 1)
    return 10.0 ** RNG.uniform(edges[:-1], edges[1:])


@pytest.mark.slow   # mpmath's creep at 3e-5: seconds a pair
@pytest.mark.parametrize("pair", PAIRS)
def test_the_ends_hold_their_bound_at_a_few_points(curves, pair):
    lad = curves[pair]
    for w in (3e-5, 1e12):
        r = lad.with_end("overlap").evaluate([w], tol=1e-9, method="master", build=True)
        truth, acc = _truth(pair, w)
        assert abs(float(r.eps[0]) / truth - 1) <= r.error_bound + acc, (pair, w)
        assert r.error_bound <= 1e-9


@pytest.mark.slow   # mpmath at 9 points (a few seconds each; the creep's C once a pair)
@pytest.mark.parametrize("pair", PAIRS)
def test_every_stated_bound_holds_over_the_whole_domain(curves, pair):
    """12 points or more spread over 1e-12..1e20, each within the bound the chooser states for it
    (the law below 1e-4, the panels, the elastic expansion above 1e8)."""
    lad = curves[pair]
    points = np.concatenate([_spread(-12, -5, 4), _spread(-5, 8, 5), _spread(8, 20, 4)])
    for w in points:
        r = lad.with_end("overlap").evaluate([w], tol=1e-9, method="master", build=True)
        truth, acc = _truth(pair, float(w))
        err = abs(float(r.eps[0]) / truth - 1)
        assert err <= r.error_bound + acc, f"seed {SEED}: {pair} Omega={w:.6g} err {err:.3g} > {r.error_bound:.3g}"


@pytest.mark.parametrize("pair", PAIRS)
def test_far_below_every_reference_the_curve_is_the_law(curves, pair):
    curve = curves[pair].overlap_curve()
    lim = overlap_limit(pair)
    om = np.array([1e-200, 1e-100, 1e-40, 1e-13]) if curve.lowest < 1e-200 else np.array([1e-40, 1e-13])
    got = curve.eps(om)
    rounding = 2.3e-16 * (1 + lim.k * np.abs(np.log(om)))
    assert np.all(np.abs(got / lim.eps(om) - 1) <= rounding)
    assert curve.bound(float(om[0]), float(om[0])) >= curve.law_bound + rounding[0]


def test_an_array_over_every_decade_is_one_call_of_the_curve(curves):
    lad = curves[("3/2", "1")]
    om = np.geomspace(1e-7, 1e7, 20_000)
    r = lad.with_end("overlap").evaluate(om, tol=1e-9)
    assert r.methods == {"master": om.size} and r.error_bound <= 1e-9
    assert lad.overlap_curve().omega_lo == pytest.approx(OMEGA_LO) and lad.overlap_curve().omega_hi >= OMEGA_HI


def test_where_the_bodies_can_stick_there_is_no_law_and_the_refusal_stays(curves):
    lad = curves[("3/2", "0")]
    curve = lad.overlap_curve()
    assert curve.law is None and curve.lowest == curve.omega_lo > curve.stick_below > 0
    with pytest.raises(StickError):
        lad.with_end("overlap").evaluate([curve.stick_below * 0.5, 1.0], tol=1e-9)
    # above the boundary but below the curve: another rung answers those points
    w = 0.5 * (curve.stick_below + curve.lowest)
    r = lad.with_end("overlap").evaluate([w, 10.0], tol=1e-6)
    assert r.methods.get("master", 0) == 1 and sum(r.methods.values()) == 2
    assert math.isfinite(r.error_bound) and r.error_bound <= 1e-6

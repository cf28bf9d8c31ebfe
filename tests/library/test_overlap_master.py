"""The overlap rule's own master curve (issue 23, items 2-4): built on its own in seconds, its stated
bound held against the mpmath reference at fresh points, a tampered file detected and rebuilt, the
sticking boundary found once, stored, and right on both sides."""

from __future__ import annotations

import io
import json
import math

import numpy as np
import pytest

from restitution.core.collision import StickError, collide
from restitution.core.errors import ParameterError
from restitution.core.exponents import as_exponents
from restitution.core.problem import Problem
from restitution.core.highprec import reference_collision
from restitution.fast.cache import cache_path
from restitution.fast.ladder import Ladder
from restitution.fast.overlap_master import NODE_RTOL, build_overlap_curve, sticking_boundary
from restitution.fast.rung import integrator_bound

SEED = int(np.random.SeedSequence().entropy % 2**32)
RNG = np.random.default_rng(SEED)


@pytest.fixture(scope="module")
def curves(tmp_path_factory):
    root = tmp_path_factory.mktemp("ovl")
    out = {}
    for pair in (("3/2", "1"), ("3/2", "1/2")):
        lad = Ladder(pair, cache_dir=str(root), stream=io.StringIO())
        out[pair] = (lad.overlap_curve(), lad)
    return out


@pytest.mark.parametrize("pair", [("3/2", "1"), ("3/2", "1/2")])
@pytest.mark.slow
def test_bound_holds_against_mpmath_at_fresh_points(curves, pair):
    curve, _ = curves[pair]
    assert curve.bound_inside <= 1e-9
    for w in np.exp(RNG.uniform(math.log(curve.omega_lo), math.log(curve.omega_hi), 4)):
        truth = float(reference_collision(Problem(as_exponents(pair), "overlap"), float(w), digits=20).eps)
        err = abs(float(curve.eps(np.array([w]))[0]) / truth - 1)
        assert err <= curve.bound_inside, f"seed {SEED}: Omega={w:.6g} err {err:.3g} > {curve.bound_inside:.3g}"


@pytest.mark.parametrize("pair", [("3/2", "1"), ("3/2", "1/2")])
def test_bound_carries_the_overlap_rules_node_accuracy(curves, pair):
    # the nodes come from the compiled integrator under the overlap rule: its bound, not the force rule's
    curve, _ = curves[pair]
    nodes = integrator_bound(NODE_RTOL, Problem.of(*pair, "overlap"))
    assert nodes > integrator_bound(NODE_RTOL, as_exponents(*pair))
    assert curve.bound_inside >= 2.0 * nodes


def test_epsilon_uses_the_curve_once_it_is_there(curves):
    _, lad = curves[("3/2", "1")]
    om = np.logspace(-3, 3, 200)
    r = lad.with_end("overlap").evaluate(om, tol=1e-9)
    assert r.method == "master" and r.error_bound <= 1e-9
    ref = np.array([collide(Problem.of("3/2", 1, "overlap"), float(w), rtol=1e-13).eps for w in om[::40]])
    assert np.max(np.abs(r.eps[::40] / ref - 1)) <= 1e-9 + 2e-12


def test_a_large_request_builds_the_curve_alone(tmp_path):
    err = io.StringIO()
    lad = Ladder(("3/2", "1"), cache_dir=str(tmp_path), stream=err)
    r = lad.with_end("overlap").evaluate(np.geomspace(1e-3, 1e3, 100_000), tol=1e-9)
    assert r.method == "master"
    entries = [p.name for p in tmp_path.iterdir() if p.suffix != ".lock"]   # the per-entry build locks stay
    assert entries == [cache_path(lad.overlap_key, tmp_path).name]   # not the force bundle
    # (whether the build is named on stderr depends on its measured time, over a second or not:
    # the announcement has its own test with a priced build)


@pytest.mark.parametrize("change", [
    lambda c: c["coef"][7].__setitem__(0, c["coef"][7][0] + 1e-6),
    lambda c: c.__setitem__("bound_inside", 1e-20),
])
@pytest.mark.slow
def test_a_tampered_curve_is_detected_and_rebuilt(tmp_path, change):
    import hashlib

    lad = Ladder(("3/2", "1"), cache_dir=str(tmp_path), stream=io.StringIO())
    good = lad.overlap_curve().eps(np.array([0.47, 30.0]))
    (path,) = tmp_path.glob("*.json")
    stored = json.loads(path.read_text())
    change(stored["content"])
    text = json.dumps(stored["content"], sort_keys=True, separators=(",", ":"))
    stored["sha256"] = hashlib.sha256(text.encode()).hexdigest()   # resealed: only the checks can tell
    path.write_text(json.dumps(stored))
    fresh = Ladder(("3/2", "1"), cache_dir=str(tmp_path), stream=io.StringIO())
    assert fresh.cached_overlap_curve() is None
    np.testing.assert_allclose(fresh.overlap_curve().eps(np.array([0.47, 30.0])), good, rtol=1e-13)


@pytest.mark.parametrize("alpha, gamma", [("5/2", "1/2"), ("3", "1/4"), ("3", "1/2")])
def test_sticking_boundary_is_right_on_both_sides(alpha, gamma):
    b = sticking_boundary((alpha, gamma))
    assert 1e-4 < b < 1e8
    with pytest.raises(StickError):
        collide(Problem.of(alpha, gamma, "overlap"), b * (1 - 1e-4))
    assert collide(Problem.of(alpha, gamma, "overlap"), b * (1 + 1e-4)).eps > 0


def test_self_similar_boundary_is_the_proved_one():
    assert sticking_boundary(("1", "0")) == 0.25 and sticking_boundary(("3/2", "1/4")) == 0.2
    assert sticking_boundary(("3/2", "1")) == 0.0   # alpha < 2 gamma + 1: never sticks


def test_the_curve_of_a_sticking_pair_starts_above_its_stored_boundary(tmp_path):
    lad = Ladder(("5/2", "1/2"), cache_dir=str(tmp_path), stream=io.StringIO())
    c = lad.overlap_curve()
    assert c.omega_lo > c.stick_below > 0.3
    assert lad.with_end("overlap").evaluate([2.0, 50.0], tol=1e-9, method="master").error_bound <= 1e-9
    with pytest.raises(ParameterError, match="contact never ends"):
        lad.with_end("overlap").evaluate([0.9 * c.stick_below], tol=1e-9)


def test_a_curve_without_a_viscous_law_answers_at_its_first_node(tmp_path):
    # the linear spring-dashpot sticks below its curve, so the curve has no law below it: its bound
    # at the first node read the missing law and raised a TypeError (make fuzz, Omega = 1)
    lad = Ladder(("1", "0"), cache_dir=str(tmp_path), stream=io.StringIO())
    c = lad.overlap_curve()
    assert c.law is None
    r = lad.with_end("overlap").evaluate([c.omega_lo], tol=1e-9, method="master")
    ref = collide(Problem.of(1, 0, "overlap"), c.omega_lo, rtol=1e-13).eps
    assert r.error_bound <= 1e-9 and abs(r.eps[0] / ref - 1) <= r.error_bound + 2e-12

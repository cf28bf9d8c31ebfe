"""Each point of an array answered by its own cheapest adequate rung (issue 54, item 1): a few
points outside a fast rung's domain cost what they cost alone, every point gets the value its
part gets when asked alone, bit for bit, and the result says which rung answered how many."""

from __future__ import annotations

import io

import numpy as np
import pytest

from restitution.core.errors import ParameterError
from restitution.fast.ladder import Ladder
from restitution.fast.parts import part_ranges

PAIR = ("3/2", "1")
NEAR = np.geomspace(1e-2, 1e2, 400)
FAR = np.geomspace(1e-10, 1e-9, 5)


@pytest.fixture()
def ladder(tmp_path):
    return Ladder(PAIR, cache_dir=str(tmp_path), stream=io.StringIO())


def _mixed():
    both = np.concatenate([NEAR, FAR])
    order = np.random.default_rng(5).permutation(both.size)   # parts interleaved in the array
    return both[order], order


def test_far_points_do_not_send_the_array_to_another_rung(ladder):
    om, _ = _mixed()
    r = ladder.with_end("overlap").evaluate(om, tol=1e-9, build=False)
    assert r.methods == {"overlap-law": FAR.size, "integrator": NEAR.size}
    assert r.method == "overlap-law+integrator"
    assert r.error_bound <= 1e-9 and np.all(r.bounds <= 1e-9)
    assert r.error_bound == max(p.bound for p in r.parts)


def test_each_part_gets_what_it_gets_alone_bit_for_bit(ladder):
    om, order = _mixed()
    r = ladder.with_end("overlap").evaluate(om.reshape(5, -1), tol=1e-9, build=False)
    assert r.eps.shape == (5, om.size // 5)
    near = ladder.with_end("overlap").evaluate(NEAR, tol=1e-9, build=False)
    far = ladder.with_end("overlap").evaluate(FAR, tol=1e-9, build=False)
    expect = np.concatenate([near.eps, far.eps])[order]
    assert np.array_equal(r.eps.ravel(), expect)
    bounds = np.concatenate([np.full(NEAR.size, near.error_bound), np.full(FAR.size, far.error_bound)])[order]
    assert np.array_equal(r.bounds.ravel(), bounds)


def test_one_rung_for_all_is_one_part(ladder):
    r = ladder.with_end("overlap").evaluate(NEAR, tol=1e-9, build=False)
    assert r.method == "integrator" and r.methods == {"integrator": NEAR.size} and len(r.parts) == 1
    assert np.array_equal(r.bounds, np.full(NEAR.shape, r.error_bound))


def test_a_forced_method_answers_the_whole_array_or_refuses(ladder):
    om, _ = _mixed()
    with pytest.raises(ParameterError, match="method"):   # the law does not cover NEAR: no split
        ladder.with_end("overlap").evaluate(om, tol=1e-9, build=False, method="overlap-law")
    r = ladder.evaluate(om, tol=1e-9, build=False, method="integrator")
    assert r.methods == {"integrator": om.size} and len(r.parts) == 1


def test_part_ranges_count_each_point_once_at_its_cut():
    rng = np.random.default_rng(3)
    om = 10.0 ** rng.uniform(-12, 12, 3001)
    cuts = np.array([1e-8, 1e-4, 1.0, 1e8])
    om[:4] = cuts   # a point at a cut belongs above it
    counts, lows, highs = part_ranges(om, cuts)
    k = np.searchsorted(cuts, om, side="right")
    assert counts.tolist() == np.bincount(k, minlength=cuts.size + 1).tolist()
    for j in range(cuts.size + 1):
        assert (lows[j], highs[j]) == (om[k == j].min(), om[k == j].max())

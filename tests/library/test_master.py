"""Master curves: held-out errors against the mpmath reference, the joins, serialisation, the cache.

Small curves (Omega in [1e-4, 1e4], wide panels) are built in the test session; one moderate check
builds the default curve for the paper's exponents and tests the fast-rung target on it.
"""

from __future__ import annotations

import copy
import io
import json
import math

import numpy as np
import pytest

from restitution.fast import cache
from restitution.core.exponents import as_exponents
from restitution.fast.integrator import collide_fast
from restitution.core.highprec import reference_collision
from restitution.fast.master import MasterCurve, MasterSettings, build_master, reference_eps

SMALL = MasterSettings(log10_omega_min=-4.0, log10_omega_max=4.0, grid_step=0.25, degree=12, width=1.0,
                       heldout_per_panel=2, n_highprec=2)
HELD_OUT_SEED = 987654  # not the build seed


@pytest.fixture(scope="module")
def small_kim():
    return build_master(("3/2", "1"), SMALL)


def _hp(alpha, gamma, w, digits=20):
    return float(reference_collision((alpha, gamma), float(w), digits=digits).eps)


def test_small_master_heldout_against_mpmath(small_kim):
    m = small_kim
    assert m.omega_lo == pytest.approx(1e-4) and m.omega_hi >= 1e4 * 0.999
    assert m.bound_inside <= 1e-11
    rng = np.random.default_rng(HELD_OUT_SEED)
    pts = np.exp(rng.uniform(math.log(1e-4), math.log(1e4), 4))
    hp = np.array([_hp("3/2", "1", w) for w in pts])
    err = np.abs(m.eps(pts) / hp - 1)
    assert np.all(err <= m.bound_at(pts)), (err, m.bound_at(pts))
    assert m.checks["highprec"]["n"] == 2
    assert m.checks["fit_err_heldout"] <= m.bound_inside


def test_small_master_beyond_the_joins(small_kim):
    """Outside [Omega_lo, Omega_hi] the expansions take over; their fitted bounds must hold far beyond."""
    m = small_kim
    pts = np.array([1e-9, 1e-7, 1e-5, 5e-5, 3e4, 1e6, 1e9, 1e12])
    ref = reference_eps(("3/2", "1"), pts, 1e-14)
    err = np.abs(m.eps(pts) / ref - 1)
    assert np.all(err <= m.bound_at(pts) + 2e-13)
    # the bounds are informative (fall off away from the joins) and the expansions are really used
    b = m.bound_at(pts)
    assert b[0] < 1e-12 and b[-1] < 1e-12 and b[2] > b[0]
    # one point against mpmath
    assert abs(m.eps(1e-6) / _hp("3/2", "1", 1e-6) - 1) <= m.bound_at(np.array([1e-6]))[0]


def test_bound_is_the_max_over_inputs(small_kim):
    m = small_kim
    pts = np.array([1e-6, 1.0, 1e6])
    assert m.bound(pts) == pytest.approx(np.max(m.bound_at(pts)))
    assert m.bound(np.array([1.0, 2.0])) == m.bound_inside


def test_json_roundtrip(small_kim):
    d = json.loads(json.dumps(small_kim.as_dict()))
    m2 = MasterCurve.from_dict(d)
    pts = np.geomspace(1e-8, 1e8, 101)
    assert np.array_equal(m2.eps(pts), small_kim.eps(pts))
    assert np.array_equal(m2.bound_at(pts), small_kim.bound_at(pts))
    d["version"] = -1
    with pytest.raises(ValueError):
        MasterCurve.from_dict(d)


def test_equal_exponents_master_uses_the_closed_form():
    m = build_master(("1", "1"), MasterSettings(**{**SMALL.as_dict(), "n_highprec": 1}))
    pts = np.geomspace(1e-7, 1e9, 61)
    from restitution.core.asymptotics import equal_exponents_eps
    err = np.abs(m.eps(pts) / equal_exponents_eps(pts) - 1)
    assert np.all(err <= m.bound_at(pts))
    # down to the domain's edge, where eps = Omega must not lose |ln Omega| ulps on the way
    edge = np.geomspace(1e-300, 1e-8, 30)
    assert np.all(np.abs(m.eps(edge) / equal_exponents_eps(edge) - 1) <= m.bound_at(edge))
    # at the join, whichever side the evaluator takes, the bound stated there holds
    join = m.omega_lo * (1.0 + np.arange(-8, 9) * 2.0 ** -52)
    assert np.all(np.abs(m.eps(join) / equal_exponents_eps(join) - 1) <= m.bound_at(join))
    assert m.bound_inside < 1e-9  # wide test panels; exp(-1/Omega) makes the curve steep near 0.05
    _strict_json_roundtrip(m, pts)


def _strict_json_roundtrip(m, pts):
    text = json.dumps(m.as_dict(), allow_nan=False)  # what the cache writes
    assert np.array_equal(MasterCurve.from_dict(json.loads(text)).eps(pts), m.eps(pts))


@pytest.mark.slow
def test_alpha_below_gamma_master():
    """Separation-ended contacts, stiff creeping return: the grid stops at 1e-5, the inner law beyond."""
    s = MasterSettings(**{**SMALL.as_dict(), "log10_omega_min": -6.0, "log10_omega_max": 3.0, "n_highprec": 0})
    m = build_master(("1", "3/2"), s)
    assert m.omega_lo >= 1e-5 * 0.99
    pts = np.array([3e-5, 2e-3, 0.4, 30.0, 1e5])
    ref = np.array([_hp("1", "3/2", w, 16) if w >= 1e-3 else np.nan for w in pts])
    small = pts < 1e-3
    ref[small] = reference_eps(("1", "3/2"), pts[small], 1e-13)  # mpmath is too slow in the creep
    err = np.abs(m.eps(pts) / ref - 1)
    assert np.all(err <= m.bound_at(pts) + 1e-12)
    _strict_json_roundtrip(m, pts)


@pytest.mark.slow
def test_default_master_meets_the_fast_target():
    """The one moderate check: the default curve for the paper's exponents, 1e-9 over 1e-6..1e6."""
    m = build_master(("3/2", "1"), MasterSettings(n_highprec=3))
    assert m.omega_lo <= 1e-6 and m.omega_hi >= 1e5
    rng = np.random.default_rng(HELD_OUT_SEED + 1)
    pts = np.exp(rng.uniform(math.log(1e-6), math.log(1e6), 3000))
    ex = as_exponents("3/2", "1")
    ref = collide_fast(ex.p, ex.q_alpha, ex.q_gamma, pts, 1e-14)[:, 0]
    err = np.abs(m.eps(pts) / ref - 1)
    assert err.max() <= 1e-9
    assert np.all(err <= m.bound_at(pts) + 2e-13)
    assert m.bound(pts) <= 1e-9
    assert m.checks["highprec"]["max_rel_err_master"] <= m.bound_inside
    # its speed (>= 1e7 evaluations per second) is a benchmark row (make bench), not a test


# ----------------------------------------------------------------------------- the cache module
def test_atomic_write_and_load(tmp_path):
    p = tmp_path / "sub" / "x.json"
    cache.save_json_atomic(p, {"a": 1})
    assert cache.load_json(p) == {"a": 1}
    assert not [q for q in p.parent.iterdir() if q.suffix == ".tmp"]
    with pytest.raises(ValueError):  # NaN is not JSON: refused, and no partial file replaces the old
        cache.save_json_atomic(p, {"a": math.nan})
    assert cache.load_json(p) == {"a": 1}
    assert not [q for q in p.parent.iterdir() if q.suffix == ".tmp"]


def test_a_changed_cache_file_is_refused_even_as_valid_json(tmp_path):
    p = tmp_path / "x.json"
    cache.save_json_atomic(p, {"coef": [[1.0, 2.0]], "rtol": 1e-12})
    stored = json.loads(p.read_text())
    for change in (lambda c: c["coef"][0].__setitem__(0, 1.01), lambda c: c.__setitem__("rtol", 1e-6),
                   lambda c: c["coef"][0].__setitem__(1, "NaN")):
        bad = copy.deepcopy(stored)
        change(bad["content"])
        p.write_text(json.dumps(bad))
        err = io.StringIO()
        assert cache.load_json(p, err) is None and "changed after it was written" in err.getvalue()
    p.write_text('{"coef": [[1.0, 2.0]]}')   # no seal at all (an older or foreign file)
    assert cache.load_json(p, io.StringIO()) is None
    p.write_text(json.dumps(stored)[:20])     # truncated
    assert cache.load_json(p, io.StringIO()) is None


def test_get_or_build_rebuilds_corrupt_and_invalid(tmp_path):
    calls = []

    def build():
        calls.append(1)
        return {"v": 2}

    path = cache.cache_path("k/ey with space", tmp_path)
    assert path.parent == tmp_path and " " not in path.name and "/" not in path.name
    path.write_text("{ half a file")
    (tmp_path / (path.name + ".abc.tmp")).write_text("stale")
    err = io.StringIO()
    assert cache.get_or_build("k/ey with space", build, directory=tmp_path, stream=err) == {"v": 2}
    assert len(calls) == 1 and "building" in err.getvalue()
    assert cache.get_or_build("k/ey with space", build, directory=tmp_path, stream=err) == {"v": 2}
    assert len(calls) == 1  # cached now
    cache.get_or_build("k/ey with space", build, valid=lambda d: d.get("v") == 3, directory=tmp_path,
                       stream=err)
    assert len(calls) == 2  # invalid -> rebuilt


def test_unwritable_cache_is_not_fatal(tmp_path):
    """A cache location that cannot be created (here: a file where the directory should be; also
    what a read-only or full disk gives) means: build, use, say so on stderr."""
    blocker = tmp_path / "blocker"
    blocker.write_text("not a directory")
    err = io.StringIO()
    assert cache.get_or_build("x", lambda: {"ok": True}, directory=blocker / "sub", stream=err) == {"ok": True}
    assert "is a file, not a directory: nothing is read from or written to the cache" in err.getvalue()


def test_a_cache_write_that_fails_is_not_fatal(tmp_path, monkeypatch):
    """A full or read-only disk: build, use, say so on stderr."""
    def full(path, data):
        raise OSError(28, "No space left on device")
    monkeypatch.setattr(cache, "save_json_atomic", full)
    err = io.StringIO()
    assert cache.get_or_build("x", lambda: {"ok": True}, directory=tmp_path / "c", stream=err) == {"ok": True}
    assert "could not write the cache" in err.getvalue() and "No space left" in err.getvalue()


def test_cache_dir_from_environment(monkeypatch, tmp_path):
    monkeypatch.setenv(cache.ENV_VAR, str(tmp_path / "c"))
    assert cache.cache_dir() == tmp_path / "c"
    monkeypatch.delenv(cache.ENV_VAR)
    assert cache.cache_dir().name == "restitution"

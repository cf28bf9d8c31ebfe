"""A large array is evaluated in slices on threads (restitution.fast.panels): every point gets the
double one pass gives it."""

from __future__ import annotations

import numpy as np

from restitution.fast import panels


def test_slices_on_threads_give_the_single_pass_bit_for_bit(monkeypatch):
    rng = np.random.default_rng(11)
    om = 10.0 ** rng.uniform(-9, 11, 4 * panels.THREAD_MIN_POINTS + 7)
    coef = rng.normal(size=(40, 11)) * 1e-3
    vis = np.array([0.0, 0.8, 0.1, 0.2, 1.0])
    el = np.array([0.8, 0.5, 0.2, 5.0, 0.1])
    monkeypatch.setattr(panels, "worker_threads", lambda: 4)
    sliced = panels.chebyshev_panels_eval(om, -9.0, 0.25, coef, vis, el)
    monkeypatch.setattr(panels, "THREAD_MIN_POINTS", om.size + 1)
    one = panels.chebyshev_panels_eval(om, -9.0, 0.25, coef, vis, el)
    assert np.array_equal(sliced, one)


def test_slices_cover_every_point_once(monkeypatch):
    monkeypatch.setattr(panels, "worker_threads", lambda: 3)   # more slices than this machine may have
    om = np.geomspace(1e-3, 1e3, 3 * panels.THREAD_MIN_POINTS + 2)
    coef = np.zeros((30, 4))
    coef[:, 0] = np.log(0.5)
    out = panels.chebyshev_panels_eval(om, np.log(1e-3), 0.5, coef, np.zeros(5), np.zeros(5))
    assert np.all(out == np.exp(np.log(0.5)))

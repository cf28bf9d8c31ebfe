"""Building the uniform closed form of :mod:`restitution.core.uniform` for one pair of exponents.

Three disjoint sets of points, so that the stated bound is a measurement, not a fit residual:

1. fit: every other point of a grid in log10 Omega (steps of GRID_STEP over [1e-9, 1e9]), eps from
   the compiled integrator at rtol 1e-14 (accurate to ~1e-14, validated against mpmath);
2. choice of the shape (sigma, m0, m1): the grid points in between;
3. bound: N_TEST points drawn log-uniformly in [1e-8, 1e8] (fixed seed), eps and 1 - eps from the
   scipy reference (:func:`restitution.core.collision.collide`, 1 - eps from the dissipated energy).

The stated bounds are BOUND_FACTOR times the largest relative error over sets 2 and 3 inside the
form's range (for 1 - eps: the points with Omega >= 1), plus the references' own accuracy.
"""

from __future__ import annotations

import numpy as np

from ..core.collision import collide
from ..core.exponents import as_exponents
from ..core.uniform import FORM_RANGE, UniformForm, fit_uniform, rel_errors
from .master import reference_eps

__all__ = ["build_uniform", "GRID_STEP", "N_TEST", "BOUND_FACTOR"]

GRID_STEP = 0.05
N_TEST = 32
BOUND_FACTOR = 2.0
#: Accuracy of the references (relative): integrator at rtol 1e-14, scipy reference at 1e-12.
REFERENCE_ACCURACY = 1e-11
#: eps of the form must lie in (0, 1) on this many points across its range.
SANITY_POINTS = 4001


def _grid() -> np.ndarray:
    n = int(round(18 / GRID_STEP))
    return 10.0 ** np.linspace(-9.0, 9.0, n + 1)


def bound_points(alpha, gamma) -> np.ndarray:
    """The bound's points: log-uniform in FORM_RANGE, seeded by the exponents (same on every machine)."""
    ex = as_exponents(alpha, gamma)
    seed = [ex.alpha.numerator, ex.alpha.denominator, ex.gamma.numerator, ex.gamma.denominator]
    lo, hi = np.log10(FORM_RANGE)
    return np.sort(10.0 ** np.random.default_rng(seed).uniform(lo, hi, N_TEST))


def build_uniform(alpha, gamma, progress=None) -> UniformForm:
    """Fit, choose and measure the uniform form (a few seconds)."""
    ex = as_exponents(alpha, gamma)
    say = progress or (lambda m: None)
    om = _grid()
    say(f"uniform form: {om.size} integrations for the fit")
    eps = reference_eps(ex, None, om, 1e-14)
    ome = 1.0 - eps
    idx = np.arange(om.size)
    train, select = idx % 2 == 0, idx % 2 == 1
    form = fit_uniform(ex, None, om, eps, ome, train, select)

    say(f"uniform form: {N_TEST} reference collisions for its bound")
    tp = bound_points(ex, None)
    runs = [collide(ex, None, float(w), rtol=1e-12) for w in tp]
    t_eps = np.array([r.eps for r in runs])
    t_ome = np.array([r.one_minus_eps for r in runs])
    inside = select & (om >= FORM_RANGE[0]) & (om <= FORM_RANGE[1])
    sel_eps, sel_ome = rel_errors(form, om[inside], eps[inside], ome[inside])
    test_eps, test_ome = rel_errors(form, tp, t_eps, t_ome)

    dense = np.geomspace(*FORM_RANGE, SANITY_POINTS)
    e = form.eps(dense)
    if not np.all((e > 0) & (e < 1)):
        raise ArithmeticError(f"the uniform form for alpha={ex.alpha}, gamma={ex.gamma} leaves (0, 1)")
    measured = {"selection_eps": sel_eps, "selection_one_minus_eps": sel_ome, "test_eps": test_eps,
                "test_one_minus_eps": test_ome, "n_fit": int(train.sum()), "n_selection": int(inside.sum()),
                "n_test": N_TEST}
    bound_eps = BOUND_FACTOR * max(sel_eps, test_eps) + REFERENCE_ACCURACY
    bound_ome = BOUND_FACTOR * max(sel_ome, test_ome) + REFERENCE_ACCURACY
    return UniformForm(form.alpha, form.gamma, form.skel, form.sigma, form.m0, form.m1, form.coef,
                       float(bound_eps), float(bound_ome), measured)

"""Building the uniform approximation of :mod:`restitution.core.uniform` for one pair of exponents.

Three disjoint sets of points, so that its stated error (``bound_eps``) is a measurement, not a fit residual
(an estimate with a margin, not a proven bound):

1. fit: every other point of a grid in log10 Omega (steps of GRID_STEP over [1e-9, 1e9]), eps from
   the compiled integrator at rtol 1e-14 (accurate to ~1e-14, validated against mpmath);
2. choice of the shape (sigma, m0, m1): the grid points in between;
3. held out: N_TEST points drawn log-uniformly in [1e-8, 1e8] (fixed seed), eps and 1 - eps from the
   scipy reference (:func:`restitution.core.collision.collide`, 1 - eps from the dissipated energy),
   and a dense scan, DENSE_PER_DECADE log-spaced points per decade over the same range, placed
   between the points of sets 1 and 2, eps from the compiled integrator at rtol 1e-14.

The stated bounds are BOUND_FACTOR times the largest relative error over sets 2 and 3 inside the
form's range (for 1 - eps: the points with Omega >= 1), plus the references' own accuracy. The
factor is a margin for the supremum between the points, which no finite set reaches: measured on the
stability atlas's pairs, the dense scan's maximum (four times finer than set 2) exceeds set 2's by at
most 2 % under the force rule and 9 % under the overlap rule (the pipeline prints the force rule's
ratio), far inside the factor.

Under the overlap rule the creeping return makes an integration below Omega ~ 1e-3 cost
milliseconds to seconds, and there eps is the limit law C Omega^kv
(:mod:`restitution.core.overlap_limit`) to the accuracy of C: below LAW_BELOW the references are
that law, and the build measures the law against the integrator on LAW_CHECK points above it
(refusing the build if they differ by more than LAW_AGREEMENT); that difference and C's own error
are added to the references' accuracy.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..core.collision import collide
from ..core.exponents import as_exponents
from ..core.problem import Problem, as_problem
from ..core.overlap_limit import overlap_limit
from ..core.uniform import FORM_RANGE, UniformForm, fit_uniform, rel_errors
from .master import reference_eps

__all__ = ["build_uniform", "dense_points", "GRID_STEP", "N_TEST", "DENSE_PER_DECADE", "BOUND_FACTOR",
           "REFERENCE_ACCURACY", "FIT_RTOL"]

GRID_STEP = 0.05
N_TEST = 32
#: The dense scan of held-out points: this many per decade (a quarter of the fit grid's spacing; 0.1 to
#: 0.2 s of integrations per pair and rule, measured).
DENSE_PER_DECADE = 40
BOUND_FACTOR = 2.0
#: Relative tolerance of the integrations the coefficients are fitted to (the manuscript prints it).
FIT_RTOL = 1e-14
#: Accuracy of the references (relative): integrator at rtol 1e-14, scipy reference at 1e-12.
REFERENCE_ACCURACY = 1e-11
#: eps of the form must lie in (0, 1) on this many points across its range.
SANITY_POINTS = 4001
#: Overlap rule: the limit law is the reference below LAW_BELOW, checked against the integrator at
#: LAW_CHECK (measured: within 2e-12 on (3/2, 1/2), (3/2, 1), (2, 1), (5/2, 1) up to Omega = 0.03).
LAW_BELOW = 1e-3
LAW_CHECK = (1e-3, 2e-3, 4e-3)
LAW_AGREEMENT = 1e-10


def _grid() -> np.ndarray:
    n = int(round(18 / GRID_STEP))
    return 10.0 ** np.linspace(-9.0, 9.0, n + 1)


def bound_points(problem) -> np.ndarray:
    """The bound's points: log-uniform in FORM_RANGE, seeded by the exponents (same on every machine)."""
    ex = as_exponents(problem)
    seed = [ex.alpha.numerator, ex.alpha.denominator, ex.gamma.numerator, ex.gamma.denominator]
    lo, hi = np.log10(FORM_RANGE)
    return np.sort(10.0 ** np.random.default_rng(seed).uniform(lo, hi, N_TEST))


def dense_points() -> np.ndarray:
    """The dense scan: DENSE_PER_DECADE points per decade over FORM_RANGE, each midway between two
    consecutive points of a grid of that spacing started at FORM_RANGE[0], so that none is a fit or
    model-selection point (those lie at whole multiples of GRID_STEP / 2 from 1e-9).

    Examples
    --------
    >>> om = dense_points()
    >>> om.size, bool(1e-8 < om[0] < om[-1] < 1e8)
    (640, True)
    """
    lo, hi = np.log10(FORM_RANGE)
    n = int(round((hi - lo) * DENSE_PER_DECADE))
    return 10.0 ** (lo + (np.arange(n) + 0.5) / DENSE_PER_DECADE)


class _References:
    """eps and 1 - eps at given Omegas for one pair and rule, as accurate as ``accuracy``."""

    def __init__(self, problem: Problem):
        ex, end = problem.ex, problem.end
        self.problem, self.end, self.accuracy, self.law_checked = problem, end, REFERENCE_ACCURACY, None
        if end == "overlap":
            lim = overlap_limit(ex)
            self.law = lim.eps
            at = np.array(LAW_CHECK)
            diff = float(np.max(np.abs(reference_eps(problem, at, 1e-14) / lim.eps(at) - 1.0)))
            if not diff <= LAW_AGREEMENT:
                raise ArithmeticError(f"alpha={ex.alpha}, gamma={ex.gamma}: the overlap rule's limit law differs "
                                      f"from the integrator by {diff:.2g} at Omega >= {LAW_BELOW:g}")
            self.law_checked = diff
            self.accuracy += diff + lim.C_error / lim.C

    def _split(self, om):
        return om < LAW_BELOW if self.end == "overlap" else np.zeros(om.shape, bool)

    def grid(self, om) -> np.ndarray:
        """eps from the compiled integrator at rtol 1e-14 (or the law)."""
        law = self._split(om)
        eps = np.empty(om.size)
        eps[~law] = reference_eps(self.problem, om[~law], FIT_RTOL)
        if law.any():
            eps[law] = self.law(om[law])
        return eps

    def test(self, om) -> tuple[np.ndarray, np.ndarray]:
        """eps and 1 - eps from the scipy reference (1 - eps from the dissipated energy) or the law."""
        law = self._split(om)
        eps, ome = np.empty(om.size), np.empty(om.size)
        runs = [collide(self.problem, float(w), rtol=1e-12) for w in om[~law]]
        eps[~law] = [r.eps for r in runs]
        ome[~law] = [r.one_minus_eps for r in runs]
        if law.any():
            eps[law] = self.law(om[law])
            ome[law] = 1.0 - eps[law]
        return eps, ome


def build_uniform(problem, progress=None) -> UniformForm:
    """Fit, choose and measure the uniform form for the problem's end rule (plain exponents: the
    force rule; a few seconds)."""
    problem = as_problem(problem)
    ex, end = problem.ex, problem.end
    say = progress or (lambda m: None)
    refs = _References(problem)
    om = _grid()
    say(f"uniform form ({end} rule): {om.size} reference values for the fit")
    eps = refs.grid(om)
    ome = 1.0 - eps
    idx = np.arange(om.size)
    train, select = idx % 2 == 0, idx % 2 == 1
    form = fit_uniform(problem, om, eps, ome, train, select)

    say(f"uniform form ({end} rule): {N_TEST} reference collisions for its bound")
    tp = bound_points(ex)
    t_eps, t_ome = refs.test(tp)
    inside = select & (om >= FORM_RANGE[0]) & (om <= FORM_RANGE[1])
    sel_eps, sel_ome = rel_errors(form, om[inside], eps[inside], ome[inside])
    test_eps, test_ome = rel_errors(form, tp, t_eps, t_ome)
    say(f"uniform form ({end} rule): a dense scan of held-out points")
    dp = dense_points()
    d_eps = refs.grid(dp)
    dense_eps, dense_ome = rel_errors(form, dp, d_eps, 1.0 - d_eps)
    worst_at = float(dp[np.argmax(np.abs(form.eps(dp) / d_eps - 1.0))])

    dense = np.geomspace(*FORM_RANGE, SANITY_POINTS)
    e = form.eps(dense)
    if not np.all((e > 0) & (e < 1)):
        raise ArithmeticError(f"the uniform form for alpha={ex.alpha}, gamma={ex.gamma} leaves (0, 1)")
    measured = {"selection_eps": sel_eps, "selection_one_minus_eps": sel_ome, "test_eps": test_eps,
                "test_one_minus_eps": test_ome, "n_fit": int(train.sum()), "n_selection": int(inside.sum()),
                "n_test": N_TEST, "dense_eps": dense_eps, "dense_one_minus_eps": dense_ome,
                "dense_eps_at": worst_at, "n_dense": int(dp.size)}
    if refs.law_checked is not None:
        measured.update(law_below=LAW_BELOW, law_vs_integrator=refs.law_checked)
    bound_eps = BOUND_FACTOR * max(sel_eps, test_eps, dense_eps) + refs.accuracy
    bound_ome = BOUND_FACTOR * max(sel_ome, test_ome, dense_ome) + refs.accuracy
    return replace(form, bound_eps=float(bound_eps), bound_one_minus_eps=float(bound_ome), measured=measured)

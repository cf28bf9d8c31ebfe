"""Both end rules against a bare numpy Chebyshev pass, side by side in one run (issue 54): 10^6
Omegas log-spaced over 1e-7..1e7 at tol 1e-9, warm (every build made and every kernel compiled
before the timing), for Kim's pair and a second one (or the pairs given as arguments, e.g.
``5/4,1/4``). Prints ratios only (targets: the overlap rule
at most 1, the force rule at most 0.6).

The baseline is numpy's ``chebval`` of a 32-term series at ln Omega mapped onto [-1, 1], over the
same array: what a plain numpy master curve with one panel would cost. Each figure is the median of
REPEATS runs, the three calls taking turns (benchmarks/side_by_side.py).
"""

from __future__ import annotations

import math
import sys

import numpy as np
from numpy.polynomial import chebyshev as cheb
from side_by_side import medians

from restitution import epsilon

PAIRS = [("3/2", "1"), ("3/2", "1/2")]
OMEGA = np.geomspace(1e-7, 1e7, 10**6)
TOL = 1e-9
REPEATS = 7
COEF = np.random.default_rng(54).normal(size=32) / np.arange(1, 33) ** 2


def chebyshev_pass(om: np.ndarray) -> np.ndarray:
    return cheb.chebval(np.log(om) / math.log(1e7), COEF)


def main(argv=None) -> int:
    pairs = [tuple(a.split(",")) for a in (sys.argv[1:] if argv is None else argv)] or PAIRS
    print(f"{'alpha':>6} {'gamma':>6}  {'force / chebyshev':>18} {'overlap / chebyshev':>20}  methods (force; overlap)")
    for alpha, gamma in pairs:
        calls = {"chebyshev": lambda: chebyshev_pass(OMEGA)}
        for end in ("force", "overlap"):
            calls[end] = lambda end=end: epsilon(alpha=alpha, gamma=gamma, omega=OMEGA, tol=TOL, end=end)
        med = medians(calls, REPEATS)
        methods = "; ".join(calls[end]().method for end in ("force", "overlap"))
        print(f"{alpha:>6} {gamma:>6}  {med['force'] / med['chebyshev']:>18.2f} "
              f"{med['overlap'] / med['chebyshev']:>20.2f}  {methods}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

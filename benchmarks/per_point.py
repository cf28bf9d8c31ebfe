"""An array's far points cost what they cost alone (issue 54): 10^5 Omegas in 1e-2..1e2 plus 10 at
1e-7, answered in one call, against the two parts answered apart, both end rules, warm (every build
made and every kernel compiled before the timing). Prints ratios only (target: at most 1.5).

Each timing is the median of REPEATS runs, the three calls taking turns (benchmarks/side_by_side.py);
the last column divides the fastest runs instead: each call lasts milliseconds, and on a shared
machine one busy spell of the scheduler moves a median by several times (7x seen with 5 turns).
"""

from __future__ import annotations

import statistics
import sys

import numpy as np
from side_by_side import timings

from restitution import epsilon

PAIRS = [("3/2", "1"), ("3/2", "1/2")]
NEAR = np.geomspace(1e-2, 1e2, 10**5)
FAR = np.full(10, 1e-7)
TOL = 1e-9
REPEATS = 21   # a shared machine: five turns let one busy spell decide a millisecond call (7x seen)


def main() -> int:
    both = np.concatenate([NEAR, FAR])
    print(f"{'alpha':>6} {'gamma':>6} {'end':>8}  {'methods (one call)':<40} {'one call / apart':>16} {'(fastest runs)':>15}")
    for alpha, gamma in PAIRS:
        for end in ("force", "overlap"):
            calls = {name: (lambda om=om: epsilon(alpha=alpha, gamma=gamma, omega=om, tol=TOL, end=end))
                     for name, om in (("near", NEAR), ("far", FAR), ("both", both))}
            runs = timings(calls, REPEATS)
            med = {name: statistics.median(t) for name, t in runs.items()}
            best = {name: min(t) for name, t in runs.items()}
            methods = ", ".join(f"{m} {n}" for m, n in calls["both"]().methods.items())
            print(f"{alpha:>6} {gamma:>6} {end:>8}  {methods:<40} {med['both'] / (med['near'] + med['far']):>16.2f} "
                  f"{best['both'] / (best['near'] + best['far']):>15.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

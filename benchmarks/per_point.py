"""An array's far points cost what they cost alone (issue 54): 10^5 Omegas in 1e-2..1e2 plus 10 at
1e-7, answered in one call, against the two parts answered apart, both end rules, warm (every build
made and every kernel compiled before the timing). Prints ratios only (target: at most 1.5).

Each timing is the median of REPEATS runs, the three calls taking turns (benchmarks/side_by_side.py).
"""

from __future__ import annotations

import sys

import numpy as np
from side_by_side import medians

from restitution import epsilon

PAIRS = [("3/2", "1"), ("3/2", "1/2")]
NEAR = np.geomspace(1e-2, 1e2, 10**5)
FAR = np.full(10, 1e-7)
TOL = 1e-9
REPEATS = 5


def main() -> int:
    both = np.concatenate([NEAR, FAR])
    print(f"{'alpha':>6} {'gamma':>6} {'end':>8}  {'methods (one call)':<40} {'one call / apart':>16}")
    for alpha, gamma in PAIRS:
        for end in ("force", "overlap"):
            calls = {name: (lambda om=om: epsilon(alpha=alpha, gamma=gamma, omega=om, tol=TOL, end=end))
                     for name, om in (("near", NEAR), ("far", FAR), ("both", both))}
            med = medians(calls, REPEATS)
            methods = ", ".join(f"{m} {n}" for m, n in calls["both"]().methods.items())
            print(f"{alpha:>6} {gamma:>6} {end:>8}  {methods:<40} {med['both'] / (med['near'] + med['far']):>16.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

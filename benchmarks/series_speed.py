"""How long the exact series takes to derive (issue target: Omega^8, tau^20 for alpha=3/2, gamma=1 under 2 s).

Prints one line per case; the derivation cache is cleared before each timing so every
number is a cold derivation.
"""

from __future__ import annotations

import sys
import time

from restitution.core.series import _coefficients, perturbation_series

CASES = [
    ("3/2", "1", 8, 20, "forward"),
    ("3/2", "1", 8, 20, "inverse"),
    ("3/2", "1/2", 8, 20, "forward"),
    ("5/4", "1/2", 6, 15, "forward"),
    ("5/2", "3/2", 8, 20, "forward"),
]


def main() -> int:
    print(f"{'alpha':>6} {'gamma':>6} {'order':>6} {'tau^':>5} {'direction':>9} {'seconds':>9} {'terms':>6}")
    for alpha, gamma, order, power, direction in CASES:
        _coefficients.cache_clear()
        start = time.perf_counter()
        ps = perturbation_series(alpha, gamma, order, power, direction)
        elapsed = time.perf_counter() - start
        terms = sum(len(ps.terms(n)) for n in range(order + 1))
        print(f"{alpha:>6} {gamma:>6} {order:>6} {power:>5} {direction:>9} {elapsed:>9.4f} {terms:>6}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

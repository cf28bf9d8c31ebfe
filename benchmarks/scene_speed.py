"""How long a scene takes to answer on a warm cache (issue 26): 20 materials x 5 sizes (100 atom
types, 5,050 type pairs) over 1,000 check speeds per pair, and how the cost grows: the slope of log
time against log pairs (5, 10, 20 materials at 1,000 speeds) and against log speeds (250 and 1,000
at 5,050 pairs).

    .venv/bin/python benchmarks/scene_speed.py        (part of make bench; prints one table)

Targets: a third of the material pairs a measured table that falls with speed (a speed-dependent
model is needed), the others a constant e. The first answer of each size builds or loads what the
evaluator needs (master curves, cached on disk); the time reported is the best of the next runs,
wall clock on one core.
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np


from restitution.dem.scene import answer_scene
from restitution.dem.scene.file import scene_from_dict

TARGET_SECONDS = 10.0


def scene(materials: int, sizes: int, speeds: int) -> dict:
    names = [f"m{i}" for i in range(materials)]
    mats = {n: {"E": float(1e8 * 10 ** (2.0 * i / max(1, materials - 1))), "nu": 0.2 + 0.2 * i / max(1, materials),
                "density": 1000.0 + 350.0 * i} for i, n in enumerate(names)}
    species = [{"name": f"p{i}", "material": n, "radius": [float(r) for r in np.geomspace(5e-4, 4e-3, sizes)]}
               for i, n in enumerate(names)]
    targets = []
    for i, a in enumerate(names):
        for j, b in enumerate(names[i:], start=i):
            e = 0.6 + 0.3 * ((7 * i + 13 * j) % 17) / 16
            if (i + j) % 3 == 0:
                targets.append({"pair": [a, b], "table": [[0.1, min(0.97, e + 0.03)], [1.0, e], [5.0, e - 0.03]]})
            else:
                targets.append({"pair": [a, b], "e": e})
    return {"name": "bench", "code": "lammps", "tolerance": 0.01, "speeds": [0.1, 5.0], "check_points": speeds,
            "options": {"normal": "hertz/material", "damping": "choose", "limit_damping": False},
            "materials": mats, "species": species, "targets": targets}


def timed(materials: int, sizes: int, speeds: int, repeats: int = 2) -> tuple[float, int, dict]:
    sc = scene_from_dict(scene(materials, sizes, speeds))
    res = answer_scene(sc)             # warm: builds or loads the evaluator's curves
    best = math.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        res = answer_scene(sc)
        best = min(best, time.perf_counter() - t0)
    return best, len(res["contacts"]), res


def main() -> int:
    sizes = ((5, 1000), (10, 1000), (20, 1000), (20, 250))
    rows = [(m, *timed(m, 5, n)[1::-1], n) for m, n in sizes]    # (materials, pairs, seconds, speeds)
    by_pairs = [r for r in rows if r[3] == 1000]
    slope_pairs = float(np.polyfit(np.log([r[1] for r in by_pairs]), np.log([r[2] for r in by_pairs]), 1)[0])
    slope_speeds = math.log(rows[2][2] / rows[3][2]) / math.log(1000 / 250)
    print(f"{'materials':>9} {'types':>6} {'pairs':>6} {'speeds':>6} {'seconds':>8}")
    for m, p, t, n in rows:
        print(f"{m:>9} {m * 5:>6} {p:>6} {n:>6} {t:8.2f}")
    big = rows[2][2]
    print(f"scene of 100 types (5,050 pairs) x 1,000 speeds on a warm cache: {big:.2f} s "
          f"(target {TARGET_SECONDS:g} s: {'met' if big < TARGET_SECONDS else 'NOT met'}); "
          f"cost ~ pairs^{slope_pairs:.2f} at 1,000 speeds, ~ speeds^{slope_speeds:.2f} at 5,050 pairs")
    return 0


if __name__ == "__main__":
    sys.exit(main())

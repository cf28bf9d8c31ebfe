"""Wall and CPU time of one `restitution eps` call as a whole process, beside the floors it stands on.

    .venv/bin/python benchmarks/cli_speed.py [--runs 7] [--out results/bench]

Issue 22's target is one `restitution eps --alpha 3/2 --gamma 1 --omega 0.1` in at most 0.3 s wall on
an idle machine. Rows (median over --runs, after one warm-up run that fills the compiled-kernel
cache; CPU = user + sys of the child, from the operating system's accounting):

* the call itself, with a fresh master-curve cache (the ladder answers with the integrator: one point
  in a process that has not started numba runs as plain Python);
* the same call with the master curve cached (built beforehand; its checks pass on the warm-up run
  and are remembered beside it), which answers from the curve;
* a call that a closed form answers (alpha = gamma): no kernel runs, so numba is never imported;
* python starting and importing numpy: what any call costs;
* python importing numba and calling one cached one-line kernel: what any compiled answer costs
  before our own code runs, the floor of the integrator's answer;
* python calling ``epsilon`` once per speed for 200 speeds (nothing built): a loop of small requests,
  which runs as plain Python only until that has cost numba's start (``fast.jit.PLAIN_BUDGET``).

Each row's CPU is also given against python's importing numpy (``cpu_vs_numpy``; issue 44 asks at
most 2x for the first row). The package's bytecode is compiled first, as an installed package has
it. Writes ``<out>/cli_speed.csv``. Timings vary from run to run and with the machine's load: compare
rows of one run, not runs of different days.
"""

from __future__ import annotations

import argparse
import compileall
import csv
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BIN = Path(sys.executable).parent
ROOT = Path(__file__).resolve().parents[1]
KERNEL = "from numba import njit\n@njit(cache=True)\ndef twice(x):\n    return 2.0 * x\n"


def timed(argv, env) -> tuple[float, float]:
    """(wall s, cpu s) of one run of ``argv``; its output is discarded."""
    start = time.perf_counter()
    proc = subprocess.Popen(argv, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(argv)} exited {proc.returncode}: {proc.stderr.read().decode()[-400:]}")
    return wall, usage.ru_utime + usage.ru_stime


def measure(argv, env, runs: int) -> dict:
    timed(argv, env)   # warm-up: compiled kernels cached, files in the page cache
    walls, cpus = zip(*(timed(argv, env) for _ in range(runs)))
    return {"wall_median_s": statistics.median(walls), "wall_min_s": min(walls),
            "cpu_median_s": statistics.median(cpus), "runs": runs}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--out", default="results/bench")
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    # the package's bytecode as an installed one has it (pip compiles on install): a source edited
    # since `make venv` would otherwise be compiled again in every call where PYTHONDONTWRITEBYTECODE
    # is set, and the rows would time the compiler
    compileall.compile_dir(str(ROOT / "src"), quiet=2)
    with tempfile.TemporaryDirectory(prefix="restitution-cli-speed-") as tmp:
        env = {**os.environ, "RESTITUTION_CACHE": str(Path(tmp) / "cache")}
        (Path(tmp) / "kernel.py").write_text(KERNEL)
        cases = [
            ("restitution eps --alpha 3/2 --gamma 1 --omega 0.1",
             [str(BIN / "restitution"), "eps", "--alpha", "3/2", "--gamma", "1", "--omega", "0.1"]),
            ("restitution eps --alpha 1 --gamma 1 --omega 0.1",   # a closed form: no kernel, no numba
             [str(BIN / "restitution"), "eps", "--alpha", "1", "--gamma", "1", "--omega", "0.1"]),
            ("python -c 'import numpy'", [sys.executable, "-c", "import numpy"]),
            ("python: import numba, call one cached kernel",
             [sys.executable, "-c", "import importlib.util as u; "
              f"s = u.spec_from_file_location('kernel', {str(Path(tmp) / 'kernel.py')!r}); "
              "import sys; m = sys.modules['kernel'] = u.module_from_spec(s); s.loader.exec_module(m); m.twice(1.0)"]),
            ("python: epsilon() once per speed, 200 speeds",
             [sys.executable, "-c", "import numpy as np; from restitution import epsilon\n"
              "for w in np.geomspace(1e-3, 1e3, 200): epsilon(alpha='3/2', gamma=1, omega=[w], build=False)"]),
        ]
        warm = {**env, "RESTITUTION_CACHE": str(Path(tmp) / "warm-cache")}
        subprocess.run([sys.executable, "-c", "import numpy as np; from restitution import epsilon; "
                        "epsilon(alpha='3/2', gamma=1, omega=np.geomspace(1e-3, 1e3, 100000))"],
                       env=warm, check=True, stderr=subprocess.DEVNULL)
        cases.insert(1, ("restitution eps ... --omega 0.1, master curve cached", cases[0][1], warm))
        for what, command, *own_env in cases:
            row = {"command": what, **measure(command, own_env[0] if own_env else env, args.runs)}
            rows.append(row)
            print(f"{what:<52} wall {row['wall_median_s']:.3f} s (min {row['wall_min_s']:.3f})  "
                  f"cpu {row['cpu_median_s']:.3f} s")
    numpy_cpu = next(r["cpu_median_s"] for r in rows if r["command"] == "python -c 'import numpy'")
    for row in rows:   # issue 44's yardstick: the one-value call at most 2x this
        row["cpu_vs_numpy"] = row["cpu_median_s"] / numpy_cpu
    print(f"one value, CPU against python -c 'import numpy': {rows[0]['cpu_vs_numpy']:.2f}x")
    with open(out / "cli_speed.csv", "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=list(rows[0]), lineterminator="\n")
        writer.writeheader()
        for row in rows:
            writer.writerow({k: f"{v:.4f}" if isinstance(v, float) else v for k, v in row.items()})
    return 0


if __name__ == "__main__":
    sys.exit(main())

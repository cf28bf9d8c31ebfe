"""CPU time of the development loop, side by side in one run: the test suite and a cold paper build.

    .venv/bin/python benchmarks/loop_cpu.py --base ../restitution-2b0b3c9 [--what paper pytest] [--out DIR]

Each of ``--base`` and this checkout (``--tree``, default: this one) must be a checkout with its own
environment (`make venv`; for the suite, the tools `make test` installs). For each measured thing the
two trees run at the same time, so a shared machine's load falls on both alike:

* ``paper``: a cold `make paper` in a copy of each tree (its sources only, as workflow/tools/rebuild.py
  copies them, with the tree's .venv linked in): no results, logs, build or .snakemake, an empty HOME
  and an empty master-curve cache, so that nothing is reused;
* ``pytest``: the suite as `make test` runs it (`python -m pytest -q -rs -n 2`), in each tree.

CPU is user + sys of the whole process tree (os.wait4 on the top process: every descendant it
waited for is included). The table gives both trees' figures and their ratio; quote the ratio, not
the seconds: they move with the machine's load, the ratio of a side-by-side pair much less.
Writes ``<out>/loop_cpu.csv`` when ``--out`` is given.
"""

from __future__ import annotations

import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
#: As `make` sets them: the build must be the one a user gets.
ENV = {"SOURCE_DATE_EPOCH": "1700000000", "PYTHONHASHSEED": "0"}
#: Never copied into a cold tree (what rebuild.py leaves out, and the trees' own outputs).
IGNORE = shutil.ignore_patterns(".venv", ".git", "results", ".snakemake", "build", "logs", "notebooks",
                                ".pytest_cache", "*.egg-info", ".ipynb_checkpoints", "_build")


def cold_copy(tree: Path, dest: Path) -> Path:
    """``tree``'s sources in ``dest`` with its .venv linked in. numba's kernel caches
    (src/**/__pycache__) come along: `make venv` made them, a fresh clone's first build has them."""
    shutil.copytree(tree, dest, ignore=IGNORE, symlinks=True)
    (dest / "results").mkdir()
    (dest / ".venv").symlink_to(tree / ".venv", target_is_directory=True)
    return dest


def empty_home(scratch: Path) -> dict:
    """HOME, the caches and the master-curve cache in an empty directory: nothing is reused."""
    home = Path(tempfile.mkdtemp(prefix="home-", dir=scratch))
    return {"HOME": str(home), "RESTITUTION_CACHE": str(home / "cache"), "XDG_CACHE_HOME": str(home / ".cache"),
            "XDG_CONFIG_HOME": str(home / ".config"), "MPLCONFIGDIR": str(home / "mpl")}


def start(argv: list[str], cwd: Path, env: dict, log: Path) -> subprocess.Popen:
    with open(log, "w") as out:
        return subprocess.Popen(argv, cwd=cwd, env={**os.environ, **ENV, **env}, stdout=out,
                                stderr=subprocess.STDOUT)


def side_by_side(runs: dict[str, tuple[list[str], Path, dict, Path]]) -> dict[str, dict]:
    """Start every run at once; CPU (user + sys, descendants included) and wall of each."""
    t0 = time.monotonic()
    procs = {name: start(*spec) for name, spec in runs.items()}
    done = {}
    while len(done) < len(procs):
        pid, status, usage = os.wait4(-1, 0)
        for name, p in procs.items():
            if p.pid == pid:
                p.returncode = os.waitstatus_to_exitcode(status)
                done[name] = {"cpu": usage.ru_utime + usage.ru_stime, "wall": time.monotonic() - t0,
                              "exit": p.returncode, "log": str(runs[name][3])}
    return done


def measure(what: str, trees: dict[str, Path], scratch: Path) -> dict[str, dict]:
    runs = {}
    for name, tree in trees.items():
        log = scratch / f"{what}-{name}.log"
        if what == "paper":
            cold = cold_copy(tree, scratch / f"{what}-{name}")
            runs[name] = (["make", "--no-print-directory", "-o", ".venv/.installed-stamp", "-o", "tex", "paper"],
                          cold, empty_home(scratch), log)
        else:
            runs[name] = ([str(tree / ".venv" / "bin" / "python"), "-m", "pytest", "-q", "-rs", "-n", "2"],
                          tree, {}, log)
    return side_by_side(runs)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--base", type=Path, required=True, help="the checkout to compare against")
    ap.add_argument("--tree", type=Path, default=ROOT, help="the checkout measured (default: this one)")
    ap.add_argument("--what", nargs="+", choices=["paper", "pytest"], default=["paper", "pytest"])
    ap.add_argument("--out", type=Path, help="write loop_cpu.csv here")
    ap.add_argument("--keep", action="store_true", help="keep the cold trees and logs (their path is printed)")
    args = ap.parse_args(argv)
    trees = {"base": args.base.resolve(), "tree": args.tree.resolve()}
    for name, tree in trees.items():
        if not (tree / ".venv" / "bin" / "python").exists():
            ap.error(f"{name} {tree} has no .venv: run `make venv` there first")
    scratch = Path(tempfile.mkdtemp(prefix="loop-cpu-"))
    rows = []
    try:
        for what in args.what:
            got = measure(what, trees, scratch)
            b, t = got["base"], got["tree"]
            rows.append({"what": what, "base_cpu_s": round(b["cpu"], 1), "tree_cpu_s": round(t["cpu"], 1),
                         "cpu_ratio": round(t["cpu"] / b["cpu"], 3), "base_wall_s": round(b["wall"], 1),
                         "tree_wall_s": round(t["wall"], 1), "base_exit": b["exit"], "tree_exit": t["exit"]})
            for name, r in got.items():
                if r["exit"] != 0:
                    print(f"{what} in {name} exited {r['exit']}: see {r['log']}", file=sys.stderr)
    finally:
        if args.keep:
            print(f"trees and logs kept in {scratch}", file=sys.stderr)
        else:
            shutil.rmtree(scratch, ignore_errors=True)
    print(f"base: {trees['base']}\ntree: {trees['tree']}")
    print(f"{'what':8} {'base cpu s':>11} {'tree cpu s':>11} {'ratio':>7} {'base wall s':>12} {'tree wall s':>12}")
    for r in rows:
        print(f"{r['what']:8} {r['base_cpu_s']:11.1f} {r['tree_cpu_s']:11.1f} {r['cpu_ratio']:7.3f} "
              f"{r['base_wall_s']:12.1f} {r['tree_wall_s']:12.1f}")
    if args.out:
        args.out.mkdir(parents=True, exist_ok=True)
        with open(args.out / "loop_cpu.csv", "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]), lineterminator="\n")
            w.writeheader()
            w.writerows(rows)
    return 0 if all(r["base_exit"] == 0 and r["tree_exit"] == 0 for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())

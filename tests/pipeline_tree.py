"""Helpers for tests that run the real pipeline in temporary copies of the project.

Never runs anything in the working tree. A copy gets the project minus .venv/results/.snakemake/
logs/build (workflow/tools/rebuild.py's copy_tree) and a symlink to this checkout's .venv (so that
`make` finds its tools; make runs with `-o` on the environment stamps and `tex` so it can never reinstall
the shared environment or install TeX).

One clean build (`make paper`) is shared by every test module that asks for it (`built_tree`, the
`built` fixture of conftest.py), and every tree starts from one snapshot of the sources taken at
the first use (`source_snapshot`).
"""

from __future__ import annotations

import atexit
import fcntl
import hashlib
import os
import shutil
import signal
import subprocess
import tempfile
import time
from pathlib import Path


ROOT = Path(__file__).resolve().parents[1]
BIN = ROOT / ".venv" / "bin"

import rebuild  # noqa: E402  (workflow/tools/rebuild.py)

ENV = {**os.environ, **rebuild.ENV}
ENV.pop("LOCK_WAIT", None)
ENV.pop("PIPELINE_MIN_FREE_MB", None)
#: The default target of a full build: the PDF needs TeX.
ALL = "all" if rebuild.have_tex() else "outputs"

_BUILT: dict[str, Path] = {}


def source_snapshot() -> Path:
    """The project's sources, copied once per test session: every tree a test builds starts from
    the same files even while the working tree is being edited."""
    if "source" not in _BUILT:
        base = Path(tempfile.mkdtemp(prefix="restitution-source-"))
        atexit.register(shutil.rmtree, base, ignore_errors=True)
        _BUILT["source"] = rebuild.copy_tree(base / "tree")
    return _BUILT["source"]


def fresh_tree(dest: Path) -> Path:
    """A clean copy of the project (from the session's snapshot), with the shared .venv linked in,
    and the compiled kernels this checkout has so far (rebuild.kernel_cache: a test's compile
    since the snapshot included)."""
    tree = Path(shutil.copytree(source_snapshot(), dest, symlinks=True))
    (tree / ".venv").symlink_to(ROOT / ".venv", target_is_directory=True)
    rebuild.kernel_cache(tree)
    return tree


def copy_built(src: Path, dest: Path) -> Path:
    """A copy of a built tree: outputs, timestamps and Snakemake's metadata included."""
    shutil.copytree(src, dest, symlinks=True, ignore=shutil.ignore_patterns(".git"))
    return dest


def make_cmd(target: str = "outputs", *extra: str) -> list[str]:
    # -o: never remake an environment stamp (the .venv is shared with the working tree: a pip install
    # run from the copy would point the shared editable install at it), and never install TeX from
    # inside a test (`make test` did that, or it cannot be done here)
    return ["make", "--no-print-directory", "-o", ".venv/.installed-stamp", "-o", ".venv/.kratos-stamp",
            "-o", ".venv/.docs-stamp", "-o", "tex", target, *extra]


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


#: Seconds the shared clean build may take before every test that needs it fails with that reason.
BUILD_TIMEOUT = float(os.environ.get("PIPELINE_BUILD_TIMEOUT", "900"))


def shared_dir(base: Path) -> Path:
    """A directory every pytest-xdist worker of this test run shares (this session's own without xdist)."""
    run = os.environ.get("PYTEST_XDIST_TESTRUNUID")
    path = base.parent / f"shared-{run}" if run else base / "shared"
    path.mkdir(exist_ok=True)
    return path


def _shared(base: Path, name: str, what: str, build) -> Path:
    """``build(tree)`` once per test run in shared/<name>, for every module and every worker: the first
    to ask builds, the others wait on the lock. ``build`` returns an error message or None; ``what``
    names the build in the messages."""
    if name not in _BUILT:
        shared = shared_dir(base)
        tree, ok, failed = shared / name, shared / f"{name}.ok", shared / f"{name}.failed"
        with open(shared / f"{name}.lock", "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            if failed.exists():
                raise AssertionError(failed.read_text())
            if not ok.exists():
                # Whatever stops this build is written down for every later test and worker: a
                # timeout left the tree behind, and each of them failed on it with FileExistsError
                # instead of reading why (48 errors on a loaded machine).
                try:
                    error = build(tree)
                except subprocess.TimeoutExpired:
                    error = (f"{what} did not finish within {BUILD_TIMEOUT:g} s "
                             "(a loaded machine? PIPELINE_BUILD_TIMEOUT=S gives it longer)")
                except Exception as err:
                    error = f"{what} could not start: {type(err).__name__}: {err}"
                if error:
                    failed.write_text(error)
                    raise AssertionError(error)
                ok.touch()
        _BUILT[name] = tree
    return _BUILT[name]


def built_tree(base: Path) -> Path:
    """One clean build per test run, through `make paper` as a user runs it (the PDF too when TeX
    is there), shared by every module and every worker (conftest.py starts it early). Tests only
    read it, or work on copies."""
    def build(tree):
        proc = make(fresh_tree(tree), "paper", timeout=BUILD_TIMEOUT)
        return f"clean build failed:\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}" if proc.returncode else None

    return _shared(base, "session-build", "the shared clean build (make paper)", build)


#: A fourth material with gamma = (alpha - 1)/2 > 0: Omega, and so eps, must not depend on g.
FLAT = {"name": "flat", "alpha": "2", "gamma": "1/2", "D1": 0.01, "D2": 0.1,
        "g_range": {"min": 0.01, "max": 10.0, "points": 5, "spacing": "log"},
        "readings": ["P-N2-K2-Dprinted"]}
#: The same as a `snakemake --config` value (YAML flow style).
FLAT_CONFIG = ('extra_variants=[{name: flat, alpha: "2", gamma: "1/2", D1: 0.01, D2: 0.1, '
               'g_range: {min: 0.01, max: 10, points: 5}, readings: [P-N2-K2-Dprinted]}]')
FLAT_STUDY = "results/flat/study.txt"


def flat_study_tree(base: Path) -> Path:
    """A copy of the clean build with the one-off study of FLAT run into it (`snakemake
    results/flat/study.txt --config extra_variants=...`), once per test run: the study's tests and
    the cluster test, which compares its own run with a local one, read the same local build."""
    def build(tree):
        copy_built(built_tree(base), tree)
        proc = snakemake(tree, "--cores", "2", FLAT_STUDY, "--config", FLAT_CONFIG, timeout=BUILD_TIMEOUT)
        return f"the one-off study failed:\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}" if proc.returncode else None

    return _shared(base, "flat-study", "the shared one-off study", build)


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

"""Before and after a run: a writable results/ with room, what earlier runs left behind, outputs
changed since the pipeline wrote them, and whether a failed run died of the disk.

Each problem is one line saying which directory, why (read-only, permission, full, a file in the
way) and what to do. The errno advice is the atomic writer's (workflow/lib/restitution_workflow/atomic.py,
installed beside the package), so a job that cannot write
and a run that cannot start say the same thing.
"""

from __future__ import annotations

import contextlib
import fcntl
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from restitution_workflow.atomic import advice, compact_written, verify_written

#: One run at a time in a tree: whoever holds an flock on this file (guard.py passes it to Snakemake).
LOCK = Path("build") / ".pipeline.lock"
#: Directories the pipeline writes to (relative to the tree).
WRITABLE = ("results", "logs", "build", ".snakemake")
MIN_FREE_MB = float(os.environ.get("PIPELINE_MIN_FREE_MB", "50"))
PROBE_BYTES = 64 * 1024
#: What a job's log says when it could not write (errno names and messages).
WRITE_FAILURES = ("No space left on device", "Disk quota exceeded", "Read-only file system", "ENOSPC",
                  "EROFS", "EDQUOT", "File too large")


def say(msg: str) -> None:
    print(f"pipeline: {msg}", file=sys.stderr, flush=True)


def check_dir(tree: Path, name: str, min_free_mb: float = MIN_FREE_MB) -> str | None:
    """None if tree/name is (or can be made) a writable directory with room; else one line."""
    path, shown = tree / name, f"{name}/"
    if path.exists() and not path.is_dir():
        return f"{shown} is not a directory ({'a symlink to ' if path.is_symlink() else ''}a file is in the way): move it away"
    if path.is_symlink() and not path.exists():
        return f"{shown} is a broken symlink (to {os.readlink(path)}): fix or remove it"
    try:
        path.mkdir(parents=True, exist_ok=True)
        # a real write of some size: a nearly full disk or a quota fails here, not in a job
        with tempfile.NamedTemporaryFile(prefix=".write-probe-", dir=path) as fh:
            fh.write(b"\0" * PROBE_BYTES)
            fh.flush()
            os.fsync(fh.fileno())
    except OSError as err:
        return f"cannot write in {shown}: {advice(err)}"
    st = os.statvfs(path)
    free_mb = st.f_bavail * st.f_frsize / 2**20
    if free_mb < min_free_mb:
        return (f"{shown} has only {free_mb:.1f} MB free (the pipeline needs about {min_free_mb:g} MB; "
                "PIPELINE_MIN_FREE_MB sets this): free some space and rerun")
    return None


def preflight(tree: Path, min_free_mb: float = MIN_FREE_MB) -> list[str]:
    return [p for p in (check_dir(tree, d, min_free_mb) for d in WRITABLE) if p]


def diagnose(tree: Path, since: float) -> list[str]:
    """After a failed run: lines saying so if the cause was the disk (full, read-only), else none."""
    out = [f"the run failed, and {p}" for p in preflight(tree, min_free_mb=max(MIN_FREE_MB, 1.0))]
    logs = [f for d in ("logs", ".snakemake/log") for f in (tree / d).rglob("*.log")
            if f.is_file() and f.stat().st_mtime >= since - 1]
    for f in sorted(logs):
        text = f.read_text(errors="replace") if os.access(f, os.R_OK) else ""
        hit = next((w for w in WRITE_FAILURES if w in text), None)
        if hit:
            line = next(l for l in text.splitlines() if hit in l).strip()
            out.append(f"the run failed because a job could not write its output ({f.relative_to(tree)}: "
                       f"{line[:200]}); free some space (or make results/ writable) and rerun")
            break
    return out


def tidy(tree: Path, snakemake: str) -> None:
    """Under the lock: what earlier runs left behind, and outputs changed since they were written."""
    for stray in (tree / "results").rglob(".*.tmp*"):
        stray.unlink(missing_ok=True)
    changed, missing = verify_written(tree)
    for rel in changed:
        dest = tree / "build" / "damaged" / rel
        dest.parent.mkdir(parents=True, exist_ok=True)
        shutil.move(tree / rel, dest)
        say(f"{rel} is not what the pipeline wrote (changed since): moved to build/damaged/, rebuilding it")
    for rel in missing:
        say(f"{rel} is missing: rebuilding it")
    unlock(tree, snakemake)


def unlock(tree: Path, snakemake: str) -> None:
    """Snakemake's own locks of a run that was stopped (safe only under the pipeline's lock)."""
    locks = list((tree / ".snakemake" / "locks").glob("*.lock"))
    if locks and subprocess.run([snakemake, "--unlock", "--quiet"], cwd=tree, capture_output=True).returncode == 0:
        say(f"removed {len(locks)} stale Snakemake lock(s) left by a run that was stopped; "
            "its unfinished jobs will be rerun")


def acquire(tree: Path, wait: float | None) -> int | None:
    """A descriptor holding the lock, or None if it was not obtained within `wait` seconds."""
    fd = os.open(tree / LOCK, os.O_RDWR | os.O_CREAT, 0o666)
    deadline = None if wait is None else time.monotonic() + wait
    for attempt in range(sys.maxsize):
        with contextlib.suppress(BlockingIOError):
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
            if attempt:
                say("the other run has finished; going on.")
            return fd
        if wait is not None and wait <= 0:
            say("another run is running in this tree; not starting a second one (nothing was changed)")
            return os.close(fd)
        if attempt == 0:
            say("another run is running in this tree; waiting for it to finish (LOCK_WAIT=0 stops instead) ...")
        if deadline is not None and time.monotonic() >= deadline:
            say(f"the other run is still running after {wait:g} s; stopped without changing anything.")
            return os.close(fd)
        time.sleep(0.2)

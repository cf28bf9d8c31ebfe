"""Run the pipeline so that faults end in a clear message and a rerun finishes the job.

    python workflow/tools/guard.py [--wait SECONDS] -- snakemake --cores 2 all ...

(the Makefile's `make paper` and `make outputs` go through here). In order:

1. **Preflight**: results/, logs/, build/ and .snakemake/ must be directories this user can
   write, with at least PIPELINE_MIN_FREE_MB (default 50) megabytes free. Otherwise one line
   says which, why (read-only, permission, full, a file in the way) and what to do; exit 1.
2. **One run at a time**: an exclusive lock on build/.pipeline.lock. A second `make paper` in the
   same tree says who holds it and waits (then usually finds nothing left to do); with
   ``--wait S`` (Makefile: LOCK_WAIT=S) it gives up after S seconds, exit 75, touching nothing.
3. **Stale Snakemake locks**: a Snakemake killed with SIGKILL (or a power loss) leaves
   .snakemake/locks behind and every later run would stop with "Directory cannot be locked".
   Holding our lock, and with no snakemake process running in this directory, they are stale:
   removed, and said so. Jobs the killed run left half-done are rerun (--rerun-incomplete).
4. **The run**: the command runs in its own process group. SIGINT/SIGTERM/SIGHUP are passed on
   to it (Snakemake then finishes or cancels its jobs and cleans up); when it ends, any job it
   left behind (its parent was SIGKILLed) is stopped, so no orphan keeps writing into results/.
   If it failed, the preflight runs again to tell a full or read-only disk from other errors.

Exit status: the command's, or 1 (preflight), 75 (lock not obtained in time), 128+N (signal N).
"""

from __future__ import annotations

import argparse
import errno
import fcntl
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
#: Directories the pipeline writes to (relative to the tree).
WRITABLE = ("results", "logs", "build", ".snakemake")
LOCK = Path("build") / ".pipeline.lock"
EX_TEMPFAIL = 75
MIN_FREE_MB = float(os.environ.get("PIPELINE_MIN_FREE_MB", "50"))
PROBE_BYTES = 64 * 1024

_ADVICE = {
    errno.ENOSPC: "the file system is full: free some space and rerun",
    errno.EDQUOT: "disk quota exceeded: free some space and rerun",
    errno.EROFS: "the file system is read-only: remount it read-write, or make it a symlink to a writable place",
    errno.EACCES: "permission denied: make it writable by this user (chmod/chown)",
    errno.EPERM: "operation not permitted: make it writable by this user (chmod/chown)",
    errno.ENOTDIR: "a file is in the way where a directory is needed: move it away",
    errno.EEXIST: "a file is in the way where a directory is needed: move it away",
    errno.EFBIG: "a file size limit (ulimit -f) stops the writes: raise it",
}


def say(msg: str) -> None:
    print(f"pipeline: {msg}", file=sys.stderr, flush=True)


def _describe(err: OSError) -> str:
    return f"{_ADVICE.get(err.errno, err.strerror or str(err))} ({errno.errorcode.get(err.errno, err.errno)})"


# ------------------------------------------------------------------------------------ preflight
def check_dir(tree: Path, name: str, min_free_mb: float = MIN_FREE_MB) -> str | None:
    """None if tree/name is (or can be made) a writable directory with room; else one line."""
    path = tree / name
    shown = f"{name}/"
    if path.exists() and not path.is_dir():
        return f"{shown} is not a directory ({'a symlink to ' if path.is_symlink() else ''}a file is in the way): move it away"
    if path.is_symlink() and not path.exists():
        return f"{shown} is a broken symlink (to {os.readlink(path)}): fix or remove it"
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        return f"cannot create {shown}: {_describe(err)}"
    try:
        fd, probe = tempfile.mkstemp(prefix=".write-probe-", dir=path)
    except OSError as err:
        return f"cannot write in {shown}: {_describe(err)}"
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(b"\0" * PROBE_BYTES)
            fh.flush()
            os.fsync(fh.fileno())
    except OSError as err:
        return f"cannot write in {shown}: {_describe(err)}"
    finally:
        try:
            os.unlink(probe)
        except OSError:
            pass
    st = os.statvfs(path)
    free_mb = st.f_bavail * st.f_frsize / 2**20
    if free_mb < min_free_mb:
        return (f"{shown} has only {free_mb:.1f} MB free (the pipeline needs about {min_free_mb:g} MB; "
                "PIPELINE_MIN_FREE_MB sets this): free some space and rerun")
    return None


def preflight(tree: Path, min_free_mb: float = MIN_FREE_MB) -> list[str]:
    return [p for p in (check_dir(tree, d, min_free_mb) for d in WRITABLE) if p]


# ------------------------------------------------------------------------------------ the lock
def _holder(lock_path: Path) -> str:
    try:
        info = json.loads(lock_path.read_text() or "{}")
    except (OSError, ValueError):
        return "another run"
    if not info:
        return "another run"
    since = time.strftime("%H:%M:%S", time.localtime(info.get("since", 0)))
    return f"another run (pid {info.get('pid')}, `{info.get('command', '?')}`, since {since})"


def acquire(tree: Path, wait: float | None, command: str):
    """The open lock file, locked; None if it could not be obtained within `wait` seconds."""
    lock_path = tree / LOCK
    fh = open(lock_path, "a+")
    try:
        fcntl.flock(fh, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        holder = _holder(lock_path)
        if wait is not None and wait <= 0:
            say(f"{holder} is running in this tree; not starting a second one (nothing was changed). "
                "Wait for it, or rerun without LOCK_WAIT to queue behind it.")
            fh.close()
            return None
        limit = "" if wait is None else f" for up to {wait:g} s"
        say(f"{holder} is running in this tree; waiting{limit} for it to finish "
            "(LOCK_WAIT=0 stops instead) ...")
        deadline = None if wait is None else time.monotonic() + wait
        while True:
            try:
                fcntl.flock(fh, fcntl.LOCK_EX | fcntl.LOCK_NB)
                break
            except BlockingIOError:
                if deadline is not None and time.monotonic() >= deadline:
                    say(f"{holder} is still running after {wait:g} s; stopped without changing anything.")
                    fh.close()
                    return None
                time.sleep(0.2)
        say("the other run has finished; going on.")
    fh.seek(0)
    fh.truncate()
    fh.write(json.dumps({"pid": os.getpid(), "command": command, "since": time.time()}))
    fh.flush()
    return fh


# ------------------------------------------------------------------------------------ stale locks
def snakemake_running_in(tree: Path) -> list[int]:
    """Pids of snakemake processes whose working directory is `tree` (Linux /proc; [] elsewhere)."""
    found = []
    proc = Path("/proc")
    if not proc.is_dir():
        return found
    me = os.getpid()
    for p in proc.iterdir():
        if not p.name.isdigit() or int(p.name) == me:
            continue
        try:
            if Path(os.readlink(p / "cwd")).resolve() != tree.resolve():
                continue
            argv = (p / "cmdline").read_bytes().split(b"\0")
        except OSError:
            continue
        # the snakemake main process, not the job scripts it starts (they run .snakemake/scripts/*)
        if any(Path(a.decode(errors="replace")).name in ("snakemake", "snakemake-script") or
               a == b"snakemake" for a in argv[:3]):
            found.append(int(p.name))
    return found


def clear_stale_locks(tree: Path) -> None:
    locks = tree / ".snakemake" / "locks"
    stale = sorted(locks.glob("*.lock")) if locks.is_dir() else []
    if not stale:
        return
    running = snakemake_running_in(tree)
    if running:
        say(f"a snakemake started outside make (pid {', '.join(map(str, running))}) is running in this "
            "tree; its locks are left alone")
        return
    for f in stale:
        f.unlink(missing_ok=True)
    say(f"removed {len(stale)} stale Snakemake lock(s) left by a run that was killed; "
        "its unfinished jobs will be rerun")


# ------------------------------------------------------------------------------------ the run
def run(cmd: list[str], tree: Path) -> int:
    child = subprocess.Popen(cmd, cwd=tree, start_new_session=True)
    received = []

    def forward(signum, _frame):
        received.append(signum)
        try:
            os.killpg(child.pid, signum)
        except ProcessLookupError:
            pass

    previous = {s: signal.signal(s, forward) for s in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)}
    try:
        rc = child.wait()
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler)
        _stop_leftovers(child.pid)
    if received:
        say(f"stopped by signal {received[0]}; rerun the same command to finish (finished steps are kept)")
        return 128 + received[0]
    if rc < 0:
        say(f"snakemake was killed (signal {-rc}); rerun the same command to finish "
            "(finished steps are kept, half-done ones are redone)")
        return 128 - rc
    return rc


def _stop_leftovers(pgid: int) -> None:
    """Jobs of a snakemake that died without cleaning up (SIGKILL) would go on writing: stop them."""
    for sig, pause in ((signal.SIGTERM, 2.0), (signal.SIGKILL, 0.0)):
        try:
            os.killpg(pgid, 0)
        except (ProcessLookupError, PermissionError):
            return
        try:
            os.killpg(pgid, sig)
        except ProcessLookupError:
            return
        deadline = time.monotonic() + pause
        while time.monotonic() < deadline:
            try:
                os.killpg(pgid, 0)
            except ProcessLookupError:
                return
            time.sleep(0.1)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--wait", type=float, default=None,
                        help="seconds to wait for another run in this tree (default: as long as it takes)")
    parser.add_argument("--tree", type=Path, default=Path.cwd(), help="project tree (default: .)")
    parser.add_argument("command", nargs=argparse.REMAINDER, help="-- then the command to run")
    args = parser.parse_args(argv)
    cmd = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not cmd:
        parser.error("no command given (put it after --)")
    tree = args.tree.resolve()

    problems = preflight(tree)
    if problems:
        for p in problems:
            say(p)
        return 1
    lock = acquire(tree, args.wait, " ".join(Path(cmd[0]).name if i == 0 else c for i, c in enumerate(cmd)))
    if lock is None:
        return EX_TEMPFAIL
    try:
        clear_stale_locks(tree)
        started = time.time()
        rc = run(cmd, tree)
        if rc != 0 and rc < 128:
            diagnose(tree, started)
        return rc
    finally:
        lock.close()


#: What a job's log says when it could not write (errno names and messages).
_WRITE_FAILURES = ("No space left on device", "Disk quota exceeded", "Read-only file system", "ENOSPC",
                   "EROFS", "EDQUOT", "File too large")


def diagnose(tree: Path, since: float) -> None:
    """After a failed run: say so if the cause was the disk (full, read-only), else stay quiet."""
    for p in preflight(tree, min_free_mb=max(MIN_FREE_MB, 1.0)):
        say(f"the run failed, and {p}")
    logs = [f for d in ("logs", ".snakemake/log") for f in (tree / d).rglob("*.log")
            if f.is_file() and f.stat().st_mtime >= since - 1]
    for f in sorted(logs):
        try:
            text = f.read_text(errors="replace")
        except OSError:
            continue
        hit = next((w for w in _WRITE_FAILURES if w in text), None)
        if hit:
            line = next(l for l in text.splitlines() if hit in l).strip()
            say(f"the run failed because a job could not write its output ({f.relative_to(tree)}: {line[:200]}); "
                "free some space (or make results/ writable) and rerun")
            break


if __name__ == "__main__":
    sys.exit(main())

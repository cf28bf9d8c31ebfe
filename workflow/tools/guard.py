"""`guard.py [--wait S] -- snakemake ...`: one run at a time (preflight.acquire's flock, inherited
by Snakemake so it lives exactly as long as the build), preflight checks and tidy-up before it,
a clear message after. Exit: the command's, 2 (preflight refusal: a tree it cannot write to, as
for every refusal of bad input in this project), 75 (lock not had in time), 128+N (signal N).

``--watch PID`` (make's pid, which the Makefile passes): make killed by SIGTERM dies at once and
leaves its recipe's processes running; the guard notices the next half second and stops the build
as if it had received the SIGTERM itself. The guard itself killed (kill -9 of make's process
group, which does not reach Snakemake's own session) stops the build too, through a watcher
process beside it: a build the user killed must not go on writing results/. Ctrl-C reaches make,
the shell and the guard together (one process group); the guard passes it to Snakemake, which
runs in a session of its own, and stops Snakemake's running jobs, so that the build ends within
seconds.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import psutil   # a dependency of Snakemake's
from preflight import acquire, compact_written, diagnose, preflight, say, tidy, unlock

GRACE = float(os.environ.get("PIPELINE_STOP_GRACE", "20"))  # seconds from a signal to SIGKILL


EXIT_REFUSED = 2


def _alive(pid: int | None) -> bool:
    if pid is None:
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


#: Beside the build, in a session of its own so that a SIGKILL to make's process group does not
#: reach it: once the guard is gone (killed: it cannot forward anything then), it stops the build,
#: which runs in its own session and would otherwise go on writing results/ for the user who
#: killed it. SIGTERM to the build's whole process group (Snakemake and its jobs), SIGKILL after
#: GRACE seconds. The guard ends it when the build ends as usual.
_ORPHAN_WATCH = """
import os, signal, sys, time
build, guard, grace = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3])
while os.getppid() == guard:
    time.sleep(0.2)
try:
    os.killpg(build, signal.SIGTERM)
    end = time.monotonic() + grace
    while time.monotonic() < end:
        time.sleep(0.2)
        os.killpg(build, 0)
    os.killpg(build, signal.SIGKILL)
except ProcessLookupError:
    pass
"""


def run(cmd: list[str], tree: Path, lock_fd: int, watch: int | None = None) -> int:
    child = subprocess.Popen(cmd, cwd=tree, start_new_session=True, pass_fds=(lock_fd,))
    watcher = subprocess.Popen([sys.executable, "-c", _ORPHAN_WATCH, str(child.pid), str(os.getpid()), str(GRACE)],
                               start_new_session=True, stdin=subprocess.DEVNULL)
    try:
        return _wait(child, watch)
    finally:
        watcher.kill()
        watcher.wait()


def _wait(child: subprocess.Popen, watch: int | None) -> int:
    received = []

    def forward(signum, _frame):
        # To Snakemake, which keeps what its jobs finished, and then to its running jobs: on a signal
        # Snakemake alone waits for them to finish (minutes for a long one, until GRACE runs out),
        # which a terminal's Ctrl-C, reaching the jobs too, would not let it do. A stopped job counts as failed: Snakemake removes its
        # outputs and exits within a second; one stopped between writing and being recorded is
        # marked incomplete and redone by the next run. The jobs are those running before the
        # signal: what Snakemake starts on it (a cluster executor's scancel) is left alone.
        received.append((signum, time.monotonic()))
        try:
            jobs = psutil.Process(child.pid).children(recursive=True)
        except psutil.Error:
            jobs = []
        with contextlib.suppress(ProcessLookupError):
            os.kill(child.pid, signum)
        for job in jobs:
            with contextlib.suppress(psutil.Error):
                job.terminate()

    for s in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        signal.signal(s, forward)
    rc = None
    while rc is None:  # Snakemake can deadlock in its own signal handler: wait for it, not forever
        with contextlib.suppress(subprocess.TimeoutExpired):
            rc = child.wait(timeout=0.5)
        if rc is None and not received and not _alive(watch):
            say("make was stopped; stopping the build")
            forward(signal.SIGTERM, None)
        if rc is None and received and time.monotonic() - received[-1][1] > GRACE:
            say(f"snakemake did not stop within {GRACE:g} s of the signal; killing it")
            os.killpg(child.pid, signal.SIGKILL)
            received.append((received[0][0], float("inf")))
    for sig in (signal.SIGTERM, signal.SIGKILL):  # jobs of a snakemake that died without cleaning up
        try:
            os.killpg(child.pid, sig)
            time.sleep(1.0)
        except ProcessLookupError:
            break
    if received or rc < 0:
        signum = received[0][0] if received else -rc
        what = f"stopped by signal {signum}" if received else f"snakemake was killed (signal {signum})"
        say(f"{what}; rerun the same command to finish (finished steps are kept, half-done ones are redone)")
        return 128 + signum
    return rc


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--wait", type=float, default=None, help="seconds to wait for another run here")
    parser.add_argument("--watch", type=int, default=None,
                        help="pid of the make that started us: its death stops the build like a SIGTERM")
    parser.add_argument("command", nargs=argparse.REMAINDER, help="-- then the snakemake command")
    args = parser.parse_args(argv)
    cmd, tree = args.command[1:] if args.command[:1] == ["--"] else args.command, Path.cwd()
    problems = [say(p) or p for p in preflight(tree)]
    lock = None if problems else acquire(tree, args.wait)
    if lock is None:
        return EXIT_REFUSED if problems else 75
    tidy(tree, cmd[0])
    started, rc = time.time(), run(cmd, tree, lock, args.watch)
    for line in diagnose(tree, started) if 0 < rc < 128 else []:
        say(line)
    if rc == 0:
        compact_written(tree)
    elif rc >= 128:  # still under our lock: Snakemake's own locks of the stopped run can go now
        unlock(tree, cmd[0])
    return rc


if __name__ == "__main__":
    sys.exit(main())

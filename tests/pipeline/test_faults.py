"""Faults: killed runs, two runs at once, read-only or full results/, half-written files.

Unit tests cover the pieces (workflow/lib/restitution_workflow/atomic.py, workflow/tools/guard.py and preflight.py); the slow
tests run the real pipeline (`make outputs`, no TeX) in temporary copies of the project and
compare what they end with against one clean build, byte for byte.
"""

from __future__ import annotations

import errno
import fcntl
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from pipeline_tree import (ENV, ROOT, cmdline, copy_built, descendants, digests, fresh_tree, make, make_cmd,
                           running_jobs, snakemake_pid, stop_all, wait_for)

import guard  # noqa: E402
import preflight  # noqa: E402
from restitution_workflow import atomic as _atomic  # noqa: E402


def can_mount() -> bool:
    """Root with mount namespaces (unshare -m): read-only and tiny file systems can be made for real."""
    if os.geteuid() != 0 or shutil.which("unshare") is None:
        return False
    return subprocess.run(["unshare", "-m", "true"], capture_output=True).returncode == 0


needs_mount = pytest.mark.skipif(not can_mount(), reason="needs root and unshare -m (mount namespaces)")


# ------------------------------------------------------------------------------------ atomic writes
def test_atomic_path_renames_only_a_finished_file(tmp_path):
    final = tmp_path / "sub" / "table.csv"
    with _atomic.atomic_path(final) as tmp:
        assert tmp.parent == final.parent and tmp.name.startswith(".table.csv.") and tmp.suffix == ".csv"
        tmp.write_text("a,b\n")
        assert not final.exists()          # nothing under the final name while writing
    assert final.read_text() == "a,b\n"
    assert [p.name for p in final.parent.iterdir()] == ["table.csv"]


def test_atomic_path_keeps_the_old_file_when_writing_fails(tmp_path):
    final = tmp_path / "values.tex"
    final.write_text("old\n")
    with pytest.raises(RuntimeError):
        with _atomic.atomic_path(final) as tmp:
            tmp.write_text("half")
            raise RuntimeError("killed halfway")
    assert final.read_text() == "old\n"
    assert [p.name for p in tmp_path.iterdir()] == ["values.tex"]


def test_atomic_path_full_disk_is_one_clear_line(tmp_path, monkeypatch):
    def full(src, dst):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(_atomic.os, "replace", full)
    with pytest.raises(_atomic.OutputError) as err:
        _atomic.write_text_atomic(tmp_path / "x.txt", "data")
    message = str(err.value)
    assert "\n" not in message and "x.txt" in message and "full" in message and "ENOSPC" in message
    assert list(tmp_path.iterdir()) == []


def test_atomic_path_file_in_the_way(tmp_path):
    (tmp_path / "results").write_text("not a directory")
    with pytest.raises(_atomic.OutputError) as err:
        _atomic.write_text_atomic(tmp_path / "results" / "stability" / "atlas.csv", "x")
    assert "a file is in the way" in str(err.value)


def test_pipeline_scripts_of_this_stage_write_atomically():
    import inspect

    from restitution_workflow import pipeline

    # a figure saved through save_figure is written under a temporary name and renamed, as atomic_path does
    assert "atomic_path(" in inspect.getsource(pipeline.save_figure)
    for name in ("stability_atlas.py", "fig_stability.py"):
        text = (ROOT / "workflow" / "scripts" / name).read_text()
        assert "atomic_path" in text or "write_text_atomic" in text or "save_figure(" in text, name
        assert ".to_csv(snakemake" not in text and ".savefig(snakemake" not in text, name


# A file-writing call whose target is not a temporary path from restitution_workflow.atomic.atomic_path.
_DIRECT_WRITE = re.compile(r"""\.to_csv\(|\.savefig\(|\.write_text\(|\.write_bytes\(|\bopen\([^)]*["'][wax]b?["']""")


def test_every_workflow_script_writes_outputs_through_the_atomic_helpers():
    """Every output is written under a temporary name and renamed: scripts call _pipeline's writers
    (write_json, write_text, write_csv, save_figure) or restitution_workflow.atomic directly; a direct write may only
    target the temporary path (or the job's log, which Snakemake does not treat as an output)."""
    offenders = []
    scripts = ROOT / "workflow" / "scripts"
    helpers = ROOT / "workflow" / "lib" / "restitution_workflow"
    for path in sorted([*scripts.glob("*.py"), helpers / "pipeline.py", helpers / "latex.py"]):
        for number, line in enumerate(path.read_text().splitlines(), 1):
            code = line.split("#", 1)[0]
            # a figure measured in memory (io.BytesIO) writes no file
            if _DIRECT_WRITE.search(code) and "tmp" not in code and "open(log" not in code and "BytesIO()" not in code:
                offenders.append(f"{path.name}:{number}: {line.strip()}")
    assert not offenders, "\n".join(offenders)
    pipeline = (helpers / "pipeline.py").read_text()
    assert "from .atomic import atomic_path" in pipeline


def test_shell_rules_write_through_the_atomic_writer():
    """The rules that write with shell commands (PDF copy, main figures, study list) go through the
    one atomic writer (a hidden temporary name, renamed; the digest recorded), placeholders quoted."""
    for smk, rule in (("manuscript.smk", "rule manuscript:"), ("manuscript.smk", "rule supplement:"),
                      ("manuscript.smk", "rule article_labels:"),
                      ("figures.smk", "rule main_figure:"),
                      ("variants.smk", "rule study:")):
        text = (ROOT / "workflow" / "rules" / smk).read_text()
        body = text[text.index(rule):].split("\nrule ", 1)[0]
        assert "{ATOMIC} install" in body or "{ATOMIC} write" in body, (smk, rule)
        assert re.search(r"\{output[.\w]*:q\}", body), (smk, rule)
        assert not re.search(r"\{(input|output|log|params)[.\w]*\}", body), (smk, rule)   # all quoted


def test_the_atomic_writer_records_what_it_wrote_and_installs_for_shell_rules(tmp_path):
    src = tmp_path / "build" / "made.pdf"
    src.parent.mkdir()
    src.write_bytes(b"%PDF finished")
    dest = tmp_path / "results" / "paper" / "x.pdf"
    proc = subprocess.run([sys.executable, str(ROOT / "workflow/lib/restitution_workflow/atomic.py"), "install", str(src), str(dest)],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    proc = subprocess.run([sys.executable, str(ROOT / "workflow/lib/restitution_workflow/atomic.py"), "write",
                           str(tmp_path / "results" / "list.txt")], input="a\nb\n", capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    assert dest.read_bytes() == b"%PDF finished"
    assert set(_atomic.written(tmp_path)) == {"results/paper/x.pdf", "results/list.txt"}
    assert _atomic.verify_written(tmp_path) == ([], [])
    dest.write_bytes(b"%PDF changed")
    assert _atomic.verify_written(tmp_path) == (["results/paper/x.pdf"], [])


# ------------------------------------------------------------------------------------ the guard
def test_preflight_passes_on_a_writable_tree(tmp_path):
    assert preflight.preflight(tmp_path, min_free_mb=0) == []
    assert {p.name for p in tmp_path.iterdir()} == set(preflight.WRITABLE)
    assert not any(p.name.startswith(".write-probe") for d in tmp_path.iterdir() for p in d.iterdir())


def test_preflight_file_in_the_way(tmp_path):
    (tmp_path / "results").write_text("oops")
    problems = preflight.preflight(tmp_path, min_free_mb=0)
    assert problems == ["results/ is not a directory (a file is in the way): move it away"]


def test_preflight_too_little_space(tmp_path):
    problems = preflight.preflight(tmp_path, min_free_mb=1e12)
    assert len(problems) == 4 and all("MB free" in p for p in problems)


def test_second_run_waits_or_stops(tmp_path, capsys):
    (tmp_path / "build").mkdir()
    first = preflight.acquire(tmp_path, None)
    assert first is not None
    assert preflight.acquire(tmp_path, 0) is None
    assert "not starting a second one" in capsys.readouterr().err
    t0 = time.monotonic()
    assert preflight.acquire(tmp_path, 0.6) is None
    assert time.monotonic() - t0 >= 0.5
    assert "still running after" in capsys.readouterr().err
    os.close(first)
    second = preflight.acquire(tmp_path, 0)
    assert second is not None
    os.close(second)


def _guarded(tree: Path, *cmd: str) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, str(ROOT / "workflow/tools/guard.py"), "--", *cmd], cwd=tree,
                            stderr=subprocess.PIPE, text=True,
                            env={**ENV, "PIPELINE_MIN_FREE_MB": "0"})


def test_the_lock_lives_as_long_as_the_build_and_a_killed_wrapper_stops_the_build(tmp_path):
    """kill -9 of the wrapper (as of make's whole process group: the build runs in a session of its
    own, which that kill does not reach) used to leave the build running, writing results/ for a
    user who had killed it. Now the build stops within seconds, and only then is the lock free."""
    build = _guarded(tmp_path, "sh", "-c", "sleep 60; echo finished > after-the-kill")
    try:
        assert wait_for(lambda: any("sleep 60" in cmdline(p) for p in descendants(build.pid)), 20)
        sleeper = next(p for p in descendants(build.pid) if "sleep 60" in cmdline(p))
        assert preflight.acquire(tmp_path, 0) is None, "the build does not hold the lock"
        build.kill()
        build.wait()
        assert wait_for(lambda: _no_process_left([sleeper]), 10), "the build outlived its killed wrapper"
        fd = preflight.acquire(tmp_path, 5)
        assert fd is not None, "the lock outlived the build"
        os.close(fd)
        assert not (tmp_path / "after-the-kill").exists()
    finally:
        stop_all(build)


def test_stray_temporary_files_of_killed_jobs_are_removed(tmp_path):
    stab = tmp_path / "results" / "stability"
    stab.mkdir(parents=True)
    strays = [stab / ".atlas.png.k2j3.tmp.png", tmp_path / "results" / ".x.csv.1234.tmp"]
    for f in strays:
        f.write_bytes(b"")
    (stab / "atlas.png").write_bytes(b"a finished figure")
    (tmp_path / "build").mkdir()
    preflight.tidy(tmp_path, "true")
    assert not any(f.exists() for f in strays)
    assert (stab / "atlas.png").read_bytes() == b"a finished figure"


def test_outputs_changed_after_they_were_written_are_moved_aside(tmp_path, capsys):
    """What the writer recorded is checked before every run: changed bytes (even with the time
    stamp put back) are moved to build/damaged/, a deleted output is reported, good ones stay."""
    res = tmp_path / "results" / "kim"
    for name in ("eps_curve.csv", "claims.csv", "fit.json"):
        _atomic.write_text_atomic(res / name, f"the pipeline's {name}")
    stat = (res / "eps_curve.csv").stat()
    (res / "eps_curve.csv").write_text("the pipe")          # truncated ...
    os.utime(res / "eps_curve.csv", ns=(stat.st_atime_ns, stat.st_mtime_ns))   # ... time stamp restored
    (res / "claims.csv").unlink()
    assert _atomic.verify_written(tmp_path) == (["results/kim/eps_curve.csv"], ["results/kim/claims.csv"])
    preflight.tidy(tmp_path, "true")
    err = capsys.readouterr().err
    assert "results/kim/eps_curve.csv is not what the pipeline wrote" in err
    assert "results/kim/claims.csv is missing: rebuilding it" in err
    assert not (res / "eps_curve.csv").exists()
    assert (tmp_path / "build/damaged/results/kim/eps_curve.csv").read_text() == "the pipe"
    assert (res / "fit.json").read_text() == "the pipeline's fit.json\n"
    assert _atomic.verify_written(tmp_path) == ([], ["results/kim/claims.csv", "results/kim/eps_curve.csv"])


def test_guard_stops_the_jobs_of_a_killed_snakemake(tmp_path):
    """A snakemake killed by SIGKILL leaves its jobs running; the guard stops them."""
    (tmp_path / "child.sh").write_text("sleep 60 &\necho $! > job.pid\nkill -9 $$\n")
    t0 = time.monotonic()
    with open(tmp_path / "lock", "w") as lock:
        rc = guard.run(["sh", "child.sh"], tmp_path, lock.fileno())
    assert rc == 128 + signal.SIGKILL
    job = int((tmp_path / "job.pid").read_text())
    assert wait_for(lambda: not Path(f"/proc/{job}").exists() or
                    Path(f"/proc/{job}/stat").read_text().split(") ")[1].startswith("Z"), 10)
    assert time.monotonic() - t0 < 30


# ------------------------------------------------------------------------------------ the real pipeline
def _start(tree: Path, env: dict | None = None) -> subprocess.Popen:
    return subprocess.Popen(make_cmd("outputs"), cwd=tree, env={**ENV, **(env or {})}, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)


def _change(path: Path) -> None:
    """Change a source file's content (not only its time stamp: Snakemake compares checksums)."""
    path.write_text(path.read_text() + "\n# changed by a test\n")


def _half_written(tree: Path) -> list[str]:
    """Outputs that exist although Snakemake marks them incomplete (the restart must redo them)."""
    inc = tree / ".snakemake" / "incomplete"
    if not inc.is_dir():
        return []
    import base64

    names = [base64.b64decode(p.name).decode() for p in inc.iterdir() if p.is_file()]
    return [n for n in names if (tree / n).exists()]


def _no_process_left(pids) -> bool:
    def gone(pid):
        stat = Path(f"/proc/{pid}/stat")
        try:
            return stat.read_text().split(") ")[1].startswith("Z")
        except (OSError, IndexError):
            return True
    return all(gone(p) for p in pids)


@pytest.mark.slow
def test_killed_runs_restart_to_the_clean_build(built, tmp_path):
    """A change to the atlas code reruns the stability stage (two ~15 s shard jobs, the merge, the
    figure). 1: SIGKILL to snakemake while the shards run; 2: `make outputs` again, SIGTERM to
    snakemake during the merge or the figure; 3: `make outputs` finishes. The result is byte for
    byte the clean build."""
    tree = copy_built(built, tmp_path / "t")
    _change(tree / "src" / "restitution" / "audit" / "stability.py")
    shards = tree / "results" / "stability" / "shards"
    # by name: pathlib's glob("*.csv") also matches a shard's temporary file (.0-of-2.csv.<random>.tmp.csv)
    names = ("0-of-2.csv", "1-of-2.csv")

    # 1. SIGKILL in the middle of the shard jobs
    proc = _start(tree)
    try:
        assert wait_for(lambda: len(running_jobs(proc.pid, "stability_atlas.py")) >= 2, 300)
        time.sleep(2.0)
        smk = snakemake_pid(proc.pid)
        jobs = descendants(smk)
        os.kill(smk, signal.SIGKILL)
        out, err = proc.communicate(timeout=120)
    finally:
        stop_all(proc)
    assert proc.returncode != 0
    assert "snakemake was killed (signal 9)" in err, err[-2000:]
    assert wait_for(lambda: _no_process_left(jobs), 20), "a job outlived its snakemake"
    # a SIGKILLed snakemake leaves its locks; the guard, still holding the pipeline's lock, clears them
    assert "removed 2 stale Snakemake lock(s)" in err, err[-2000:]
    assert not list((tree / ".snakemake" / "locks").glob("*.lock"))
    assert not any((shards / n).exists() for n in names), "half-done shards must not exist under their final names"
    assert not list((tree / "results").rglob(".*.tmp*"))

    # 2. restart; SIGTERM (as `kill` or a closed terminal sends it to the run) once the shards are
    # done (merge or figure running). Snakemake stops, or, if it hangs in its own signal handler
    # (it can), the guard kills it after PIPELINE_STOP_GRACE seconds.
    proc = _start(tree, env={"PIPELINE_STOP_GRACE": "10"})
    try:
        # both shards written and recorded as finished by Snakemake (no incomplete marker left)
        assert wait_for(lambda: all((shards / n).exists() for n in names) and
                        not [n for n in _half_written(tree) if "shards" in n], 300)
        guard_pid = next(p for p in descendants(proc.pid)
                         if "guard.py" in cmdline(p) and cmdline(p).split()[0].endswith("python"))
        os.kill(guard_pid, signal.SIGTERM)
        out, err = proc.communicate(timeout=300)
    finally:
        stop_all(proc)
    assert "stopped by signal 15" in err, err[-2000:]
    assert not list((tree / ".snakemake" / "locks").glob("*.lock")), "SIGTERM: no Snakemake lock is left"
    for name in names:
        assert (shards / name).read_bytes() == (built / "results" / "stability" / "shards" / name).read_bytes()
    assert not list((tree / "results").rglob(".*.tmp*"))

    # 3. restart to the end
    restart = make(tree)
    assert restart.returncode == 0, restart.stderr[-3000:]
    assert _half_written(tree) == []
    assert digests(tree) == digests(built)


@pytest.mark.slow
def test_two_make_runs_at_once(built, tmp_path):
    """The second `make outputs` waits for the first and then finds nothing to do; with LOCK_WAIT=0
    it stops at once and says why. Either way the outputs are those of a clean build."""
    tree = copy_built(built, tmp_path / "t")
    _change(tree / "workflow" / "scripts" / "fig_stability.py")
    first = _start(tree)
    try:
        assert wait_for(lambda: len(running_jobs(first.pid, "fig_stability.py")) >= 1, 300)
        impatient = make(tree, env={"LOCK_WAIT": "0"})
        assert impatient.returncode != 0
        assert "not starting a second one (nothing was changed)" in impatient.stderr
        second = _start(tree)
        out2, err2 = second.communicate(timeout=600)
        out1, err1 = first.communicate(timeout=600)
    finally:
        stop_all(first)
    assert first.returncode == 0, err1[-2000:]
    assert second.returncode == 0, err2[-2000:]
    assert "waiting for it to finish" in err2 and "the other run has finished" in err2
    assert "Nothing to be done" in out2 + err2
    assert digests(tree) == digests(built)


def test_results_is_a_file_gives_a_clear_message(tmp_path):
    tree = fresh_tree(tmp_path / "t")
    (tree / "results").write_text("a file where the outputs should go\n")
    proc = make(tree)
    assert proc.returncode != 0
    assert "pipeline: results/ is not a directory (a file is in the way): move it away" in proc.stderr
    assert "Traceback" not in proc.stderr
    assert (tree / "results").read_text() == "a file where the outputs should go\n"


@needs_mount
@pytest.mark.slow
def test_read_only_results_gives_a_clear_message_and_changes_nothing(built, tmp_path):
    tree = copy_built(built, tmp_path / "t")
    _change(tree / "workflow" / "scripts" / "fig_stability.py")   # there would be work to do
    before = digests(tree)
    script = ("mount --bind results results && mount -o remount,bind,ro results && "
              f"exec {' '.join(make_cmd('outputs'))}")
    proc = subprocess.run(["unshare", "-m", "sh", "-c", script], cwd=tree, env=ENV, capture_output=True, text=True,
                          timeout=300)
    assert proc.returncode != 0
    assert "pipeline: cannot write in results/: the file system is read-only" in proc.stderr, proc.stderr
    assert digests(tree) == before


@needs_mount
def test_full_results_gives_a_clear_message_before_starting(tmp_path):
    tree = fresh_tree(tmp_path / "t")
    (tree / "results").mkdir()
    script = f"mount -t tmpfs -o size=256k tmpfs results && exec {' '.join(make_cmd('outputs'))}"
    proc = subprocess.run(["unshare", "-m", "sh", "-c", script], cwd=tree, env=ENV, capture_output=True, text=True,
                          timeout=300)
    assert proc.returncode != 0
    assert "pipeline: results/ has only" in proc.stderr and "MB free" in proc.stderr, proc.stderr
    assert "free some space" in proc.stderr
    assert not (tree / ".snakemake" / "log").exists()       # snakemake never started


@needs_mount
@pytest.mark.slow
def test_disk_full_during_a_job_is_diagnosed_and_nothing_half_written_remains(built, tmp_path):
    """results/stability on a file system just large enough for the inputs: the figure cannot be
    written. The run fails with a message about the disk, and no partial figure is left."""
    tree = copy_built(built, tmp_path / "t")
    _change(tree / "workflow" / "scripts" / "fig_stability.py")
    stab = tree / "results" / "stability"
    saved = tmp_path / "saved"
    shutil.copytree(stab, saved)
    for f in ("atlas.pdf", "atlas.png"):
        (saved / f).unlink()
    size_kb = sum(f.stat().st_size for f in saved.rglob("*") if f.is_file()) // 1024 + 48
    script = (f"mount -t tmpfs -o size={size_kb}k tmpfs results/stability && cp -a {saved}/. results/stability/ && "
              f"{' '.join(make_cmd('outputs'))}; rc=$?; echo LISTING; ls -a results/stability; exit $rc")
    proc = subprocess.run(["unshare", "-m", "sh", "-c", script], cwd=tree, env={**ENV, "PIPELINE_MIN_FREE_MB": "0"},
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode != 0
    assert "the run failed" in proc.stderr and ("full" in proc.stderr or "No space" in proc.stderr), proc.stderr[-3000:]
    listing = proc.stdout.split("LISTING", 1)[1].split()
    assert "atlas.png" not in listing and "atlas.pdf" not in listing
    assert not [n for n in listing if n.endswith(".tmp.png") or n.endswith(".tmp.pdf")]


@pytest.mark.slow
def test_a_damaged_or_deleted_output_is_rebuilt_never_used(built, tmp_path):
    """Truncated with its time stamp put back, changed in place, deleted (an intermediate and a
    final output): `make verify` names each, `make outputs` moves the changed ones aside and
    rebuilds all of them from their inputs, and ends with the clean build's bytes."""
    tree = copy_built(built, tmp_path / "t")
    curve = tree / "results/kim/reference/eps_curve.csv"
    stamp = curve.stat()
    with open(curve, "r+b") as fh:
        fh.truncate(2000)
    os.utime(curve, ns=(stamp.st_atime_ns, stamp.st_mtime_ns))
    fit = tree / "results/kim/connection/fit.json"
    fit.write_text(fit.read_text().replace('"applies": true', '"applies": false'))
    for gone in ("results/kim/series/forward.json", "results/kim/claims.csv"):
        (tree / gone).unlink()
    assert "Nothing to be done" not in snakemake_dry_run(tree)

    check = make(tree, "verify")
    assert check.returncode == 2     # make's status for a failed recipe, as docs/howto/pipeline.md says
    script = subprocess.run([str(ROOT / ".venv/bin/python"), str(ROOT / "workflow/lib/restitution_workflow/atomic.py"),
                             "verify", str(tree)], capture_output=True, text=True)
    assert script.returncode == 1    # the script's own, as docs/howto/pipeline.md says
    for rel, what in (("results/kim/reference/eps_curve.csv", "changed"), ("results/kim/connection/fit.json", "changed"),
                      ("results/kim/series/forward.json", "missing"), ("results/kim/claims.csv", "missing")):
        assert f"verify: {rel}: {what}" in check.stdout, check.stdout

    proc = make(tree)
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert "results/kim/reference/eps_curve.csv is not what the pipeline wrote" in proc.stderr
    assert (tree / "build/damaged/results/kim/reference/eps_curve.csv").stat().st_size == 2000
    assert digests(tree) == digests(built)
    assert make(tree, "verify").returncode == 0


def snakemake_dry_run(tree: Path) -> str:
    proc = subprocess.run([str(ROOT / ".venv/bin/snakemake"), "outputs", "--dry-run", "--cores", "1"], cwd=tree,
                          env=ENV, capture_output=True, text=True)
    return proc.stdout + proc.stderr


# ------------------------------------------------------------------------------------ the test harness
def test_a_shared_build_that_times_out_is_one_clear_error_for_every_test(tmp_path, monkeypatch):
    """A shared build past its timeout left its tree behind; every later test then failed with
    FileExistsError on session-build (48 errors on a loaded machine) instead of saying why."""
    import pipeline_tree

    def slow_make(tree, target="outputs", *extra, env=None, timeout=900):
        raise subprocess.TimeoutExpired(["make", target], timeout)
    monkeypatch.delenv("PYTEST_XDIST_TESTRUNUID", raising=False)   # this test's own shared dir
    monkeypatch.setattr(pipeline_tree, "_BUILT", {})
    monkeypatch.setattr(pipeline_tree, "fresh_tree", lambda tree: tree.mkdir() or tree)
    monkeypatch.setattr(pipeline_tree, "make", slow_make)
    for _ in range(2):   # the build's test, then any later one
        with pytest.raises(AssertionError, match="did not finish within"):
            pipeline_tree.built_tree(tmp_path)

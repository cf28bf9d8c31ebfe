"""The cluster profile for real: one extra variant's study through `--profile workflow/profiles/slurm`
on a one-node SLURM cluster of this machine (workflow/tools/slurm-local), against a local build of
the same target, byte for byte.

Needs root (the cluster's daemons) and Debian's SLURM packages, which `make test` installs as root
with snakemake-executor-plugin-slurm; skipped with the reason elsewhere. About 50 s on the 2-core
machine: the profile groups the variant's 10 computing rules into one SLURM job, its four plots and
its LaTeX section run on the submitting host once that job is done. The local build it is compared with
is the test run's shared one of the same target (conftest.py's `flat_study`, which the one-off study's
own test reads too).
(With the plots in the group job, 15 rules, the job ran 41 s and was seen done only at the plugin's
status check 68 s after submission: it waits 10 s longer before each check while nothing finished.)
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest


from pipeline_tree import BIN, ENV, FLAT_CONFIG, FLAT_STUDY, ROOT, digests  # noqa: E402

SLURM_LOCAL = ROOT / "workflow/tools/slurm-local"
TARGET = FLAT_STUDY
#: The local cluster has no accounting database (slurmdbd), so the plugin asks squeue, not sacct; and
#: it is this machine's own, so it may be asked every 2 s (Snakemake's default, 10 s, is for a shared
#: queue: here it left the finished job waiting up to 10 s more).
CLUSTER_ARGS = ["--slurm-status-command", "squeue", "--slurm-init-seconds-before-status-checks", "2",
                "--seconds-between-status-checks", "2", "--slurm-keep-successful-logs"]

pytestmark = [pytest.mark.slurm, pytest.mark.slow]


def why_not() -> str | None:
    if os.geteuid() != 0:
        return "needs root to start a SLURM cluster on this machine (CI runs make test as root)"
    missing = [c for c in ("munged", "slurmctld", "slurmd", "sbatch") if not shutil.which(c)]
    if missing:
        return f"needs {', '.join(missing)}: as root, apt-get install munge slurmctld slurmd slurm-client"
    return None


def plugin_or_skip() -> None:
    """snakemake-executor-plugin-slurm in the environment (make test installs it; a test run alone
    installs the version constraints.txt pins)."""
    probe = [str(BIN / "python"), "-c", "import snakemake_executor_plugin_slurm"]
    if subprocess.run(probe, capture_output=True).returncode == 0:
        return
    pip = subprocess.run([str(BIN / "python"), "-m", "pip", "install", "--quiet", "-c", str(ROOT / "constraints.txt"),
                          "snakemake-executor-plugin-slurm"], capture_output=True, text=True)
    if pip.returncode != 0:
        pytest.skip(f"snakemake-executor-plugin-slurm could not be installed: {pip.stderr.strip()[-300:]}")


def snakemake(tree: Path, *args: str, env: dict | None = None) -> subprocess.Popen:
    return subprocess.Popen([str(BIN / "snakemake"), *args, TARGET, "--config", FLAT_CONFIG], cwd=tree,
                            env={**ENV, **(env or {})}, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def finished(proc: subprocess.Popen, timeout: float = 900) -> str:
    out, _ = proc.communicate(timeout=timeout)
    assert proc.returncode == 0, out[-4000:]
    return out


def slurm_jobs(tree: Path) -> dict[int, set[str]]:
    """SLURM job id -> the rules it ran, from the plugin's per-job logs,
    .snakemake/slurm_logs/{rule_<rule>,group_<group>}/<wildcards>/<SLURM job id>.log (each holds the
    output of the Snakemake that ran the job or the group's jobs)."""
    return {int(log.stem): set(re.findall(r"^rule (\w+):", log.read_text(), re.M))
            for log in (tree / ".snakemake/slurm_logs").rglob("*.log")}


def completed_jobs(jobcomp: Path) -> dict[int, dict[str, str]]:
    """SLURM's job completion log: one line of key=value per finished job."""
    jobs = {}
    for line in jobcomp.read_text().splitlines():
        fields = dict(re.findall(r"(\w+)=(\S*)", line))
        jobs[int(fields["JobId"])] = fields
    return jobs


@pytest.mark.skipif(why_not() is not None, reason=why_not() or "")
def test_one_variant_study_through_the_slurm_profile_matches_a_local_build(fresh, flat_study):
    plugin_or_skip()
    # munged runs as its own user and must reach its socket: a world-traversable directory
    cluster = Path(tempfile.mkdtemp(prefix="slurm-local-"))
    cluster.chmod(0o755)
    env = {"SLURM_LOCAL_DIR": str(cluster)}
    try:
        start = subprocess.run([str(SLURM_LOCAL), "start"], env={**ENV, **env}, capture_output=True, text=True)
        assert start.returncode == 0, start.stderr
        env.update([start.stdout.strip().split("=", 1)])                 # SLURM_CONF
        t0 = time.perf_counter()
        out = finished(snakemake(fresh, "--profile", "workflow/profiles/slurm", *CLUSTER_ARGS, env=env))
        elapsed = time.perf_counter() - t0
        pids = [int((cluster / p).read_text()) for p in ("slurmctld.pid", "slurmd.pid", "munge/munged.pid")]
    finally:
        stop = subprocess.run([str(SLURM_LOCAL), "stop"], env={**ENV, **env}, capture_output=True, text=True)
    assert stop.returncode == 0, stop.stderr
    try:
        # every job of the study except the local rules (`study`, the plots, the section) went through sbatch and
        # completed, all of them in one submission: the profile groups a variant's rules into one SLURM job
        by_job = slurm_jobs(fresh)
        ran = set().union(*by_job.values())
        planned = set(re.findall(r"^\s*rule (\w+):", out, re.M))   # indented inside a group job's listing
        on_host = set(re.findall(r"^\s*localrule (\w+):", out, re.M))
        assert ran == planned - {"study"} and len(ran) >= 10, (by_job, planned)
        assert {"fig1_forward", "fig2_inverse", "fig3_phase", "fig4_eps", "variant_section"} <= on_host and not on_host & ran, on_host
        assert len(by_job) == 1, by_job
        jobs = completed_jobs(cluster / "jobcomp.log")
        run_id = re.search(r"SLURM run ID: (\S+)", out).group(1)
        for job_id, rules in by_job.items():
            assert jobs[job_id]["JobState"] == "COMPLETED" and jobs[job_id]["Name"] == run_id, (rules, jobs[job_id])
        submitted = set(map(int, re.findall(r"_slurm_rpc_submit_batch_job: JobId=(\d+)",
                                            (cluster / "slurmctld.log").read_text())))
        assert set(by_job) <= submitted
        # the per-rule resources of the profile reached sbatch: the group that ran connection_readings
        # (30 min, 2000 MB) asked for at least that
        readings = jobs[next(j for j, rules in by_job.items() if "connection_readings" in rules)]
        assert int(readings["TimeLimit"]) >= 30 and int(re.search(r"mem=(\d+)M", readings["Tres"]).group(1)) >= 2000, \
            readings
        # stop leaves nothing running
        assert not [pid for pid in pids if Path(f"/proc/{pid}").exists()]
        assert not Path("/etc/slurm/slurm.conf").exists() or str(cluster) not in \
            Path("/etc/slurm/slurm.conf").read_text()
    finally:
        shutil.rmtree(cluster, ignore_errors=True)
    # the local build ran into a copy of the clean build: its study is what it has under results/flat/
    cluster_outputs, shared = digests(fresh), digests(flat_study)
    local_outputs = {f: d for f, d in shared.items() if f.startswith("results/flat/") or f in cluster_outputs}
    assert len(cluster_outputs) >= 30 and cluster_outputs == local_outputs
    print(f"SLURM run of {TARGET}: {elapsed:.0f} s, {len(by_job)} SLURM jobs for {len(ran)} rules")

"""The GitHub workflow (issue 45) against GitHub's published workflow schema, which check-jsonschema
ships (`--builtin-schema vendor.github-workflows`: no network), since no runner is reachable from here;
and what it runs is what a newcomer runs."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parents[2]
WORKFLOWS = sorted((ROOT / ".github" / "workflows").glob("*.yml"))
CHECK = Path(sys.executable).with_name("check-jsonschema")


def test_there_is_a_workflow():
    assert WORKFLOWS


@pytest.mark.skipif(not CHECK.exists(), reason="needs check-jsonschema from the docs group (make test installs it)")
@pytest.mark.parametrize("workflow", WORKFLOWS, ids=lambda p: p.name)
def test_the_workflow_passes_the_published_schema(workflow):
    proc = subprocess.run([str(CHECK), "--builtin-schema", "vendor.github-workflows", str(workflow)],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_the_workflow_runs_the_newcomers_commands_and_keeps_the_artifacts():
    flow = yaml.safe_load((ROOT / ".github" / "workflows" / "ci.yml").read_text())
    steps = [s for job in flow["jobs"].values() for s in job["steps"]]
    runs = [s.get("run", "").strip().split("sudo --preserve-env=CORES,PIP_CACHE_DIR ")[-1] for s in steps]
    order = [runs.index(c) for c in ("make test", "make paper", "make check", "make docs")]
    assert order == sorted(order)
    kept = " ".join(s["with"]["path"] for s in steps if s.get("uses", "").startswith("actions/upload-artifact"))
    for path in ("results/paper/restitution.pdf", "results/paper/supplement.pdf", "docs/_build/html"):
        assert path in kept
    cache = next(s for s in steps if s.get("uses", "").startswith("actions/cache"))
    assert "constraints.txt" in cache["with"]["key"]

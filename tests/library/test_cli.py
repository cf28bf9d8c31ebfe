"""The installed `restitution` command: contracts of its JSON and of its errors."""

import json
import os
import subprocess
import sys
from fractions import Fraction

import pytest

from restitution.audit.printed import PRINTED_SERIES

EXE = os.path.join(os.path.dirname(sys.executable), "restitution")


def run(*args):
    return subprocess.run([EXE, *args], capture_output=True, text=True, timeout=120)


@pytest.mark.parametrize("direction", ["forward", "inverse"])
def test_series_json_reproduces_the_printed_coefficients(direction):
    args = ["series", "--alpha", "3/2", "--gamma", "1", "--omega-order", "4", "--max-power", "11", "--json"]
    proc = run(*args, *(["--inverse"] if direction == "inverse" else []))
    assert proc.returncode == 0, proc.stderr
    data = json.loads(proc.stdout)
    assert (data["alpha"], data["gamma"], data["direction"], data["p"]) == ("3/2", "1", direction, 2)
    assert sorted(data["orders"]) == ["0", "1", "2", "3", "4"]
    for n, printed in PRINTED_SERIES[direction].items():
        ours = {Fraction(pw): Fraction(c) for pw, c in data["orders"][str(n)]}
        for pw, c in printed:
            assert ours[Fraction(pw)] == Fraction(c), (direction, n, pw)
        powers = [Fraction(pw) for pw, _ in data["orders"][str(n)]]
        assert powers == sorted(powers) and max(powers) <= 11
        assert all(Fraction(c) != 0 for _, c in data["orders"][str(n)])


def test_series_table_is_human_readable():
    proc = run("series", "--alpha", "3/2", "--gamma", "1", "--omega-order", "1", "--max-power", "4")
    assert proc.returncode == 0
    assert "-1/6" in proc.stdout and "7/2" in proc.stdout and "-4/35" in proc.stdout


def test_a_float_exponent_that_is_no_short_rational_is_one_line_and_json_stays_empty():
    proc = run("series", "--alpha", "1.4166667", "--gamma", "1", "--omega-order", "0", "--max-power", "3",
               "--json")
    assert proc.returncode == 2 and proc.stdout == ""
    assert "'17/12'" in proc.stderr and len(proc.stderr.strip().splitlines()) == 1


@pytest.mark.slow
def test_collide_json_fields():
    proc = run("collide", "--alpha", "3/2", "--gamma", "1", "--omega", "0.5", "--json")
    assert proc.returncode == 0, proc.stderr
    data = json.loads(proc.stdout)
    assert set(data) >= {"alpha", "gamma", "omega", "eps", "tau_b", "x_b", "tau_c", "x_c", "end", "ended_by"}
    assert (data["alpha"], data["gamma"], data["omega"]) == ("3/2", "1", 0.5)
    assert 0 < data["eps"] < 1 and data["ended_by"] in ("force", "separation")


def test_collide_from_material_constants_uses_the_scaled_omega():
    from restitution.core.model import Material
    proc = run("collide", "--alpha", "3/2", "--gamma", "1", "--D1", "0.000296", "--D2", "0.0109", "--g", "0.1",
               "--json")
    assert proc.returncode == 0, proc.stderr
    assert json.loads(proc.stdout)["omega"] == pytest.approx(Material("3/2", 1, 0.000296, 0.0109).omega(0.1),
                                                              rel=1e-15)


def test_eps_json_contract():
    proc = run("eps", "--alpha", "3/2", "--gamma", "1", "--omega", "0.5", "2", "--tol", "1e-8", "--no-build",
               "--json")
    assert proc.returncode == 0, proc.stderr
    data = json.loads(proc.stdout)
    assert set(data) == {"eps", "method", "error_bound", "methods", "parts"}
    assert data["methods"] == {data["method"]: 2}
    assert len(data["eps"]) == 2 and data["error_bound"] <= 1e-8
    from restitution.core.collision import collide
    for om, e in zip((0.5, 2.0), data["eps"]):
        assert e == pytest.approx(collide(("3/2", 1), om).eps, rel=2e-8)


def test_eps_json_counts_the_points_each_rung_answered():
    # under the overlap rule the viscous law answers 1e-9 and the compiled integrator the rest
    proc = run("eps", "--alpha", "3/2", "--gamma", "1", "--omega", "0.5", "1e-9", "2", "--end", "overlap",
               "--no-build", "--json")
    assert proc.returncode == 0, proc.stderr
    data = json.loads(proc.stdout)
    assert data["methods"] == {"overlap-law": 1, "integrator": 2}
    assert data["method"] == "overlap-law+integrator"
    assert [(p["method"], p["count"]) for p in data["parts"]] == [("overlap-law", 1), ("integrator", 2)]
    assert data["error_bound"] == max(p["error_bound"] for p in data["parts"]) <= 1e-9


BAD = [
    ("series", "--alpha", "0", "--gamma", "1"),
    ("series", "--alpha", "-3/2", "--gamma", "1"),
    ("series", "--alpha", "3/2", "--gamma", "-1"),
    ("series", "--alpha", "nan", "--gamma", "1"),
    ("series", "--alpha", "abc", "--gamma", "1"),
    ("series", "--alpha", "3/2", "--gamma", "1", "--omega-order", "x"),
    ("series", "--alpha", "3/2", "--gamma", "1", "--max-power", "0"),
    ("series", "--alpha", "3/2"),
    ("collide", "--alpha", "3/2", "--gamma", "1", "--omega", "0"),
    ("collide", "--alpha", "3/2", "--gamma", "1", "--omega", "-1"),
    ("collide", "--alpha", "3/2", "--gamma", "1", "--omega", "nan"),
    ("collide", "--alpha", "3/2", "--gamma", "1", "--omega", "inf"),
    ("collide", "--alpha", "3/2", "--gamma", "1", "--omega", "1e"),
    ("collide", "--alpha", "0", "--gamma", "1", "--omega", "1"),
    ("collide", "--alpha", "3/2", "--gamma", "-1", "--omega", "1"),
    ("collide", "--alpha", "3/2", "--gamma", "1", "--D1", "0", "--D2", "1", "--g", "1"),
    ("collide", "--alpha", "3/2", "--gamma", "1", "--D1", "1", "--D2", "-1", "--g", "1"),
    ("collide", "--alpha", "3/2", "--gamma", "1", "--D1", "1", "--D2", "1", "--g", "0"),
    ("collide", "--alpha", "3/2", "--gamma", "1", "--D1", "1", "--D2", "1", "--g", "nan"),
    ("collide", "--alpha", "3/2", "--gamma", "1", "--D1", "1", "--D2", "1"),
    ("collide", "--alpha", "3/2", "--gamma", "1", "--omega", "1", "--g", "1"),
    ("collide", "--alpha", "3/2", "--gamma", "1", "--omega", "1", "--rtol", "0"),
    ("eps", "--alpha", "3/2", "--gamma", "1", "--omega", "0"),
    ("eps", "--alpha", "3/2", "--gamma", "1", "--omega", "1", "nan"),
    ("eps", "--alpha", "3/2", "--gamma", "1", "--omega", "1", "--tol", "1e-30"),
    ("eps", "--alpha", "3/2", "--gamma", "1", "--omega", "1", "--tol", "2"),
    ("eps", "--alpha", "3/2", "--gamma", "1", "--D1", "1", "--D2", "1"),
    ("eps", "--alpha", "3/2", "--gamma", "1", "--omega", "1", "--g", "1"),
    ("eps", "--alpha", "0", "--gamma", "1", "--omega", "1"),
    ("collide", "--alpha", "3/2", "--gamma", "1", "--omega", "-inf"),
    ("collide", "--alpha", "3/2", "--gamma", "-1/2", "--omega", "1"),
    ("collide", "--alpha", "3/2", "--gamma", "1", "--omega", "1e300"),
    ("collide", "--alpha", "1.41421356", "--gamma", "1", "--omega", "1"),
    ("frobnicate",),
    (),
]


@pytest.mark.parametrize("args", BAD, ids=[" ".join(a) or "no-args" for a in BAD])
def test_bad_input_gives_one_line_and_exit_2(args):
    proc = run(*args)
    assert proc.returncode == 2
    assert proc.stdout == ""
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in proc.stderr
    assert lines[0].startswith("restitution")


@pytest.mark.parametrize("argv, method, unused", [
    # scipy.integrate's import was most of a one-point call; the compiled integrator reads only its tableau
    (["--alpha", "3/2", "--gamma", "1", "--omega", "0.1", "--no-build"], "integrator", "scipy.integrate"),
    # numba's import and start cost most of a second; a request no compiled kernel serves skips them
    (["--alpha", "1", "--gamma", "1", "--omega", "0.1", "3"], "uniform", "numba"),
])
def test_a_one_off_eps_call_imports_only_what_its_answer_needs(argv, method, unused, empty_cache):
    # an empty cache of its own: with a master curve that an earlier test built in the session's
    # cache, the curve answers instead of the integrator (the suite run slow tests first failed so)
    code = ("import sys\nfrom restitution.cli import main\n"
            f"assert main(['eps', *{argv!r}]) == 0\n"
            f"print(sorted(m for m in sys.modules if m == {unused!r} or m.startswith({unused!r} + '.')))")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert f"method {method}" in proc.stdout
    assert proc.stdout.strip().splitlines()[-1] == "[]"

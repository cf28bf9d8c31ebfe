"""Bad input through the command line, the Python API and config.yaml.

Every mistake must end in one line naming the field and what is allowed (CLI: exit status 2;
workflow: "config error: ..."), never a traceback, and must leave earlier results untouched.
Cases that are still mishandled are marked xfail(strict=True) with what happens today: when one
is fixed the test turns into an unexpected pass, and its marker must go.
"""

from __future__ import annotations

import copy
import math
import shlex
import subprocess
import warnings
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
import yaml

from restitution.core.errors import ParameterError

from cli_run import run_cli
from pipeline_tree import BIN, ENV, ROOT, copy_built, digests, fresh_tree, make, snakemake

from restitution_workflow.config import ConfigError, check_config
from mutation import set_at  # noqa: E402
from tsv_rows import tsv_rows  # noqa: E402


def known_bug(reason):
    return pytest.mark.xfail(strict=True, reason=reason)


# ------------------------------------------------------------------------------------ command line
def assert_one_line_error(code, out, err, field, allowed):
    lines = [line for line in err.splitlines() if line.strip()]
    assert code == 2, f"exit {code}: {err[-600:]}"
    assert "Traceback" not in err
    assert len(lines) == 1, err
    assert field in lines[0] and allowed in lines[0], lines[0]
    assert out == ""


COLLIDE = ["collide", "--alpha", "3/2", "--gamma", "1"]
#: (argv, what the line must name, what it must say is allowed), from bad_cli_input.tsv beside this
#: file: the cases that were always refused in one line, and those once mishandled (tracebacks,
#: argparse's "expected one argument", silent rounding), now one line each.
CLI_CASES = [(shlex.split(cmd), field, allowed)
             for cmd, field, allowed in tsv_rows(Path(__file__).with_name("bad_cli_input.tsv"), 3)]


@pytest.mark.parametrize("argv, field, allowed", CLI_CASES, ids=[" ".join(c[0])[:60] for c in CLI_CASES])
def test_cli_bad_input_is_one_line_and_exit_2(argv, field, allowed):
    assert_one_line_error(*run_cli(argv), field, allowed)


def test_cli_exit_status_and_stderr_as_a_process():
    """The installed entry point: exit 2, one line on stderr, nothing on stdout."""
    exe = BIN / "restitution"
    for argv in (COLLIDE + ["--omega", "nan"], ["collide", "--alpha", "7/19", "--gamma", "1", "--omega", "1"]):
        proc = subprocess.run([str(exe), *argv], capture_output=True, text=True, env=ENV, timeout=120)
        assert proc.returncode == 2 and proc.stdout == ""
        assert len(proc.stderr.strip().splitlines()) == 1, proc.stderr


# ------------------------------------------------------------------------------------ Python API
def _api_cases():
    from restitution import Material, collide, perturbation_series
    from restitution.core.collision import collide_many, inverse_collide
    from restitution.core.highprec import reference_collision

    return [
        ("omega", lambda: collide("3/2", 1, 0)),
        ("omega", lambda: collide("3/2", 1, -1.0)),
        ("omega", lambda: collide("3/2", 1, math.nan)),
        ("omega", lambda: collide("3/2", 1, math.inf)),
        ("omega", lambda: collide("3/2", 1, None)),
        ("omega", lambda: collide("3/2", 1, "abc")),
        ("omega", lambda: collide("3/2", 1, np.array([1.0, 2.0]))),
        ("alpha", lambda: collide(0, 1, 1.0)),
        ("alpha", lambda: collide("-3/2", 1, 1.0)),
        ("alpha", lambda: collide(math.nan, 1, 1.0)),
        ("alpha", lambda: collide(Fraction(7, 19), 1, 1.0)),
        ("alpha", lambda: collide(None, 1, 1.0)),
        ("gamma", lambda: collide("3/2", -1, 1.0)),
        ("gamma", lambda: collide("3/2", "1/13", 1.0)),
        ("rtol", lambda: collide("3/2", 1, 1.0, rtol=0)),
        ("rtol", lambda: collide("3/2", 1, 1.0, rtol=math.nan)),
        ("t_eval", lambda: collide("3/2", 1, 1.0, t_eval=[0.0, math.nan])),
        ("omegas", lambda: collide_many(("3/2", 1), [[1.0]])),
        ("omega", lambda: collide_many(("3/2", 1), [1.0, -1.0])),
        ("omega_tilde", lambda: inverse_collide(("3/2", 1), 0)),
        ("x_start", lambda: inverse_collide(("3/2", 1), 1.0, x_start=-1)),
        ("omega_tilde", lambda: inverse_collide((1, 0), 0.1)),   # runs away: a ParameterError too
        ("D1", lambda: Material("3/2", 1, math.nan, 1)),
        ("D2", lambda: Material("3/2", 1, 1, math.inf)),
        ("D1", lambda: Material("3/2", 1, 0, 1)),
        ("g", lambda: Material("3/2", 1, 1, 1).omega(0)),
        ("g", lambda: Material("3/2", 1, 1, 1).omega([1.0, math.nan])),
        ("omega_order", lambda: perturbation_series("3/2", 1, -1, 11)),
        ("omega_order", lambda: perturbation_series("3/2", 1, 2.5, 11)),
        ("max_power", lambda: perturbation_series("3/2", 1, 2, 0)),
        ("max_power", lambda: perturbation_series("3/2", 1, 2, "nan")),
        ("direction", lambda: perturbation_series("3/2", 1, 2, 11, "sideways")),
        ("digits", lambda: reference_collision(("3/2", 1), 1.0, digits=5)),
        ("omega", lambda: reference_collision(("3/2", 1), -1)),
    ]


API_CASES = _api_cases()


@pytest.mark.parametrize("i", range(len(API_CASES)), ids=[f"{c[0]}-{i}" for i, c in enumerate(API_CASES)])
def test_api_bad_input_raises_parameter_error_naming_the_field(i):
    field, call = API_CASES[i]
    with pytest.raises(ParameterError) as err:
        call()
    assert err.value.field == field
    assert "\n" not in str(err.value) and str(err.value).startswith(field)


def test_api_epsilon_refuses_what_no_rung_supports():
    from restitution import api as ladder

    with pytest.raises(ParameterError, match="tol"):
        ladder.epsilon(alpha="3/2", gamma=1, omega=[1.0], tol=1e-20, build=False)
    with pytest.raises(ParameterError, match="not available here"):
        ladder.epsilon(alpha="3/2", gamma=1, omega=[0.5], method="viscous", build=False)


@pytest.mark.parametrize("field, call", [
    pytest.param("omega", lambda: __import__("restitution").collide("3/2", 1, True)),
    pytest.param("alpha", lambda: __import__("restitution").collide("1e400", 1, 1.0)),
    pytest.param("alpha", lambda: __import__("restitution").collide(3.14159, 1, 1.0)),
    pytest.param("omega", lambda: __import__("restitution").collide("3/2", 1, 1e300)),
    pytest.param("alpha", lambda: __import__("restitution").collide(1e300, 1, 1.0)),
    pytest.param("g", lambda: __import__("restitution").Material("3/2", 1, 1e300, 1e-300).omega(1e300)),
    pytest.param("g", lambda: __import__("restitution").Material("3/2", 1, 1e-300, 1e300).omega(1.0)),
])
def test_api_bad_input_once_mishandled(field, call):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(ParameterError) as err:
            call()
    assert err.value.field == field


def test_api_accepts_numpy_integer_exponents():
    from restitution import collide

    assert collide(np.int64(2), 1, 1.0).alpha == 2


# ------------------------------------------------------------------------------------ config.yaml
SCHEMA = ROOT / "workflow" / "schemas" / "config.schema.yaml"


@pytest.fixture(scope="module")
def schema_path():
    return str(SCHEMA)


BASE = yaml.safe_load((ROOT / "config.yaml").read_text())


def _variant(cfg):
    return cfg["variants"][0]


def _rename(name):
    def mutate(cfg):
        old = _variant(cfg)["name"]
        _variant(cfg)["name"] = name
        if cfg["main_variant"] == old:
            cfg["main_variant"] = name
    return mutate


def _drop(path):
    def mutate(cfg):
        node = cfg
        for key in path[:-1]:
            node = node[key]
        del node[path[-1]]
    return mutate


V = ("variants", 0)
CONFIG_CASES = [
    ("zero D1", set_at(V + ("D1",), 0), "D1 = 0"),
    ("negative D2", set_at(V + ("D2",), -1.0), "D2 = -1.0"),
    ("negative g_figure", set_at(V + ("g_figure",), -0.1), "g_figure = -0.1"),
    ("zero g_range.min", set_at(V + ("g_range", "min"), 0), "g_range.min = 0"),
    ("alpha zero", set_at(V + ("alpha",), "0"), "alpha = '0'"),
    ("alpha negative", set_at(V + ("alpha",), "-3/2"), "alpha = '-3/2'"),
    ("alpha not a short rational", set_at(V + ("alpha",), "7/19"), "alpha = '7/19'"),
    ("alpha NaN", set_at(V + ("alpha",), math.nan), "alpha = nan"),
    ("gamma infinite", set_at(V + ("gamma",), math.inf), "gamma = inf"),
    ("name with a space", _rename("my variant"), "name = 'my variant'"),
    ("name with a slash", _rename("a/b"), "name = 'a/b'"),
    ("name going up", _rename("../up"), "name = '../up'"),
    ("name with ;", _rename("kim;rm -rf ~"), "name = 'kim;rm -rf ~'"),
    ("name with $()", _rename("$(touch x)"), "name = '$(touch x)'"),
    ("name with backticks", _rename("kim`id`"), "name = 'kim`id`'"),
    ("empty name", _rename(""), "name = ''"),
    ("missing D1", _drop(V + ("D1",)), "missing required field(s) D1"),
    ("missing variants", _drop(("variants",)), "missing required field(s) variants"),
    ("mistyped numerics key", set_at(("numerics", "rtoll"), 1e-10), "numerics.rtoll"),
    ("mistyped top-level key", set_at(("numerix",), {}), "numerix"),
    ("mistyped variant key", set_at(V + ("D3",), 1.0), "D3"),
    ("rtol as text", set_at(("numerics", "rtol"), "tight"), "numerics.rtol = 'tight'"),
    ("rtol too small", set_at(("numerics", "rtol"), 1e-20), "numerics.rtol = 1e-20"),
    ("variants not a list", set_at(("variants",), "kim"), "variants = 'kim'"),
    ("main_variant unknown", set_at(("main_variant",), "nope"), "main_variant = 'nope'"),
]


@pytest.mark.parametrize("label, mutate, field", CONFIG_CASES, ids=[c[0] for c in CONFIG_CASES])
def test_config_error_is_one_line_naming_the_field(schema_path, label, mutate, field):
    cfg = copy.deepcopy(BASE)
    mutate(cfg)
    with pytest.raises(ConfigError) as err:
        check_config(cfg, schema_path)
    message = str(err.value)
    assert "\n" not in message and field in message, message


# Once mishandled (NaN and infinities passed the schema's bounds, a NaN g_range.min was reported
# against g_range.max, names had no length limit), now one line naming the field.
CONFIG_CASES_ONCE_MISHANDLED = [
    ("NaN D1", set_at(V + ("D1",), math.nan), "D1 = nan: must be a finite number > 0"),
    ("infinite D2", set_at(V + ("D2",), math.inf), "D2 = inf: must be a finite number > 0"),
    ("NaN rtol", set_at(("numerics", "rtol"), math.nan), "rtol = nan: must be a finite number in [1e-14, 0.001]"),
    ("infinite g_range.max", set_at(V + ("g_range", "max"), math.inf), "g_range.max = inf"),
    ("NaN g_range.min", set_at(V + ("g_range", "min"), math.nan), "g_range.min = nan:"),
    ("NaN g_range.min as text", set_at(V + ("g_range", "min"), "nan"), "g_range.min = nan:"),
    ("NaN fit_g_range.max", set_at(V + ("fit_g_range",), {"min": 0.01, "max": math.nan}), "fit_g_range.max = nan:"),
    ("infinite compare.omega_max", set_at(("compare", "omega_max"), math.inf), "compare.omega_max = inf:"),
    ("NaN validation tolerance", set_at(("validation", "pade_tolerance"), math.nan), "pade_tolerance = nan:"),
    ("infinite tau_max_forward", set_at(V + ("plot", "tau_max_forward"), math.inf), "tau_max_forward = inf:"),
    ("alpha 3.14159", set_at(V + ("alpha",), 3.14159), "alpha = 3.14159"),
    ("alpha 1e300", set_at(V + ("alpha",), 1e300), "alpha = 1e+300"),
    ("300-character name", _rename("k" * 300), "name = 'kkk"),
]


@pytest.mark.parametrize("label, mutate, field", CONFIG_CASES_ONCE_MISHANDLED,
                         ids=[c[0] for c in CONFIG_CASES_ONCE_MISHANDLED])
def test_config_bad_input_once_mishandled(schema_path, label, mutate, field):
    cfg = copy.deepcopy(BASE)
    mutate(cfg)
    with pytest.raises(ConfigError) as err:
        check_config(cfg, schema_path)
    assert "\n" not in str(err.value) and field in str(err.value), str(err.value)


def test_config_name_of_64_characters_is_accepted(schema_path):
    cfg = copy.deepcopy(BASE)
    _rename("k" * 64)(cfg)
    check_config(cfg, schema_path)


@pytest.mark.parametrize("text, where", [
    ("main_variant: kim\nseries: [\n  omega_order: 4\n", "config.yaml, line 4, column 1: not valid YAML"),
    ("main_variant: kim\nseries:\n  omega_order: 4\n\tmax_power: 11\n", "config.yaml, line 4, column 1: not valid YAML"),
    ('main_variant: "kim\n', "config.yaml, line 2, column 1: not valid YAML"),
    ("- kim\n", "config.yaml = ['kim']: must be a mapping"),
])
@pytest.mark.pipeline
def test_config_yaml_syntax_error_is_one_line_with_the_line_number(tmp_path, text, where):
    """Through Snakemake: the Snakefile checks config.yaml before its `configfile:` loads it."""
    tree = fresh_tree(tmp_path / "tree")
    (tree / "config.yaml").write_text(text)
    proc = snakemake(tree, "--dry-run", "outputs")
    lines = [line for line in proc.stderr.splitlines() if line.strip()]
    assert proc.returncode == 2, proc.stderr[-2000:]
    assert len(lines) == 1 and lines[0].startswith(f"config error: {where}"), proc.stderr[-2000:]


@pytest.fixture(scope="module")
def fresh(tmp_path_factory):
    return fresh_tree(tmp_path_factory.mktemp("bad-input") / "tree")


@pytest.mark.parametrize("block, message", [
    ({"per_decade": 0}, "config error: stability.per_decade = 0: must be"),
    ({"perdecade": 4}, "config error: stability.perdecade = 4: unknown field"),
    ({"rtol": "fine"}, "config error: stability.rtol = 'fine': must be"),
    ({"omega_min": -1.0}, "config error: stability.omega_min = -1.0: must be"),
    ({"omega_min": 3.0e-8}, "config error: stability.omega_min = 3e-08: must be a power of ten"),
    ({"reference_omegas": [3.0e-3]}, "config error: stability.reference_omegas = 0.003: must lie on the Omega grid"),
    ({"tight_rtol": 1.0e-6}, "config error: stability.tight_rtol = 1e-06: must be a number in"),
    ({"shards": 0}, "config error: stability.shards = 0: must be"),
    ({"alphas": ["3/2", "7/19"]}, "config error: stability.alphas['7/19'] = '7/19': must be a rational number in (0, 8]"),
    ("dense", "config error: stability = 'dense': must be"),
])
def test_workflow_stability_settings_are_checked_before_anything_runs(fresh, block, message):
    """Through Snakemake itself (the schema and the stage's own checks): one line, nothing runs."""
    cfg = copy.deepcopy(BASE)
    cfg["stability"] = block
    (fresh / "config.yaml").write_text(yaml.safe_dump(cfg, sort_keys=False))
    proc = snakemake(fresh, "--dry-run", "outputs")
    errors = [line for line in proc.stderr.splitlines() if line.startswith("config error:")]
    assert proc.returncode != 0
    assert len(errors) == 1 and errors[0].startswith(message), proc.stderr[-2000:]
    assert "Traceback" not in proc.stderr
    assert not (fresh / "results").exists() or not any((fresh / "results").rglob("*.csv"))


BREAKS = [
    ("D1: 0.000296", "D1: -1", "variants[kim].D1 = -1"),
    ("name: kim", "name: kim dir; touch PWNED", "name = 'kim dir; touch PWNED'"),
    ("main_variant: kim", "main_variant: kim\nnumerix: {}", "numerix"),
    ('alpha: "3/2"', 'alpha: "0"', "alpha = '0'"),
    ("main_variant: kim", "main_variant: kim\nstability: {per_decade: 0}", "stability.per_decade = 0"),
]


@pytest.mark.slow
def test_a_bad_config_leaves_earlier_results_untouched(built, tmp_path):
    """Build, break config.yaml, run `make outputs`: one line, exit != 0, results/ byte-identical."""
    tree = copy_built(built, tmp_path / "t")
    before = digests(tree)
    original = (tree / "config.yaml").read_text()
    for old, new, field in BREAKS:
        assert old in original, old
        (tree / "config.yaml").write_text(original.replace(old, new, 1))
        proc = make(tree)
        errors = [line for line in proc.stderr.splitlines() if line.startswith("config error:")]
        assert proc.returncode != 0, new
        assert len(errors) == 1 and field in errors[0], proc.stderr[-2000:]
        assert "Traceback" not in proc.stderr + proc.stdout
        assert digests(tree) == before, f"results/ changed after: {new}"
        assert not (tree / "PWNED").exists()
    (tree / "config.yaml").write_text(original)
    proc = make(tree)
    assert proc.returncode == 0 and digests(tree) == before

"""The one strict YAML loader (restitution.core.strict_yaml) and the scene files read through it: a
value YAML 1.1 and YAML 1.2 read differently, a number beyond a double, or nesting deeper than
Python's recursion allows is one line naming the field (or the line) and exit status 2. On 85c8edf
`02500` was read as 1344, `41:40` as 2500, `no` as False, a 400-digit number as inf and a scene nested
5,000 deep ended in a RecursionError traceback."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from cli_run import run_cli
from restitution.core.strict_yaml import MAX_DEPTH, Refused, StrictLoader

ROOT = Path(__file__).resolve().parents[2]
SMALL = (ROOT / "scenes" / "small.yaml").read_text()

#: What YAML 1.1 (PyYAML, Snakemake) reads, and YAML 1.2's core schema otherwise
DIFFERENT = [("02500", 1344), ("41:40", 2500), ("0x9C4", 2500), ("2_500", 2500), ("no", False), ("yes", True),
             ("on", True), ("Off", False), ("0o17", "0o17"), ("1_000.5", 1000.5), ("190:20:30.15", 685230.15),
             ("0b101", 5), ("017", 15), ("2001-12-14", None)]


@pytest.mark.parametrize("text, yaml_1_1", DIFFERENT)
def test_a_value_yaml_readers_differ_on_is_refused_naming_the_field(text, yaml_1_1):
    if yaml_1_1 is not None:   # the reading this loader refuses to guess between
        assert yaml.safe_load(f"a: {text}")["a"] == yaml_1_1
    with pytest.raises(Refused) as err:
        yaml.load(f"x: 1\nfield: {text}\n", Loader=StrictLoader)
    assert err.value.problem.startswith(f"field = {text}: YAML readers differ") and err.value.problem_mark.line == 1
    assert "\n" not in err.value.problem


@pytest.mark.parametrize("text, value", [("2500", 2500), ("-0", 0), ("+12", 12), ("2.5e3", 2500.0), ("6.3e10", 6.3e10),
                                         ("1e-3", 1e-3), (".5", 0.5), ("1.", 1.0), ("true", True), ("False", False),
                                         ("'02500'", "02500"), ("'no'", "no"), ("~", None), ("y", "y"),
                                         ("1e308", 1e308), ("5e-324", 5e-324)])
def test_what_every_reader_takes_alike_is_read(text, value):
    got = yaml.load(f"a: {text}", Loader=StrictLoader)["a"]
    assert got == value and type(got) is type(value)


@pytest.mark.parametrize("text, words", [("1" + "0" * 399, "beyond the range of a double"),
                                         ("1" + "0" * 399 + ".0", "beyond the range of a double"),
                                         ("-1e400", "beyond the range of a double"),
                                         ("9" * 5000, "beyond the range of a double"),
                                         ("1e-400", "below the smallest double")])
def test_a_number_a_double_cannot_hold_is_refused(text, words):
    with pytest.raises(Refused) as err:
        yaml.load(f"tolerance: {text}\n", Loader=StrictLoader)
    assert err.value.problem.startswith("tolerance = ") and words in err.value.problem
    assert len(err.value.problem) < 200


@pytest.mark.parametrize("text", ["[" * 5000 + "]" * 5000, "{a: " * 5000 + "1" + "}" * 5000,
                                  "\n" + "- " * (MAX_DEPTH + 5) + "1"])
def test_deep_nesting_is_refused_not_a_recursion_error(text):
    with pytest.raises(Refused, match=f"nested deeper than {MAX_DEPTH} levels"):
        yaml.load(f"a: {text}\n", Loader=StrictLoader)
    assert yaml.load("a: " + "[" * (MAX_DEPTH - 1) + "]" * (MAX_DEPTH - 1), Loader=StrictLoader)


# ------------------------------------------------------------------------- through `restitution scene`
def _scene(tmp_path, text) -> tuple[int, str, str]:
    path = tmp_path / "scene.yaml"
    path.write_text(text)
    return run_cli(["scene", str(path)])


@pytest.mark.parametrize("old, new, field", [
    ("tolerance: 0.01", "tolerance: 1" + "0" * 399, "tolerance = 1"),
    ("density: 2500}", "density: 1" + "0" * 399 + ".0}", "density = 1"),
    ("density: 2500}", "density: 02500}", "density = 02500"),
    ("density: 2500}", "density: 41:40}", "density = 41:40"),
    ("density: 2500}", "density: 0x9C4}", "density = 0x9C4"),
    ("density: 2500}", "density: 2_500}", "density = 2_500"),
    ("limit_damping: false", "limit_damping: no", "limit_damping = no"),
    ("name: small", "name: no", "name = no"),
    ("walls: [steel]", "walls: " + "[" * 5000 + "]" * 5000, "nested deeper than"),
])
def test_a_scene_that_readers_could_take_differently_is_one_line_exit_2(tmp_path, old, new, field):
    assert old in SMALL
    code, out, err = _scene(tmp_path, SMALL.replace(old, new, 1))
    assert code == 2 and out == "", err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err, err
    assert field in err and "line" in err, err


def test_the_example_scenes_still_read():
    for path in (ROOT / "scenes").glob("*.yaml"):
        assert isinstance(yaml.load(path.read_text(), Loader=StrictLoader), dict), path

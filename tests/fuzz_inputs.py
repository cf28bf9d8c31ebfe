"""The fuzz's input cases (issue 28): random argument vectors for every subcommand (numbers of every
class, strings, repeats, missing values) and random mutations of config.yaml. Never a traceback; a
value out of range by construction is never answered with exit status 0; a refusal is one line."""

from __future__ import annotations

import copy
import io
import json
import math
import sys
import time
import traceback
from pathlib import Path

from hypothesis import strategies as st

ROOT = Path(__file__).resolve().parents[1]


# ------------------------------------------------------------------------------------ inputs
NUMBER_TOKENS = {
    # token -> is it acceptable as a positive finite number?
    "valid": ["1", "0.47", "3e-2", "2.5", "1e-3", "0.1", "10", "1e5"],
    "invalid": ["0", "-1", "nan", "inf", "-inf", "1e400", "-0", "abc", "", "1,5", "0x10", "1_0", " 2", "--",
                "1e-400", "NaN", "+inf", "3/2/1", "∞", "1e", ".", "e5"],
}
EXPONENT_TOKENS = {"valid": ["3/2", "1", "1/2", "2", "1.5", "0.5", "5/2", "1/3"],
                   "invalid": ["0", "-1", "9", "3/0", "1/13", "x", "", "3.14159", "nan", "inf", "1e9", "8/0"]}
SUBCOMMANDS = {
    "series": {"--alpha": "exp", "--gamma": "exp0", "--omega-order": "int", "--max-power": "pow",
               "--inverse": "flag", "--json": "flag"},
    "collide": {"--alpha": "exp", "--gamma": "exp0", "--omega": "num", "--D1": "num", "--D2": "num", "--g": "num",
                "--rtol": "rtol", "--method": "collide-method", "--digits": "int", "--end": "end", "--json": "flag"},
    "eps": {"--alpha": "exp", "--gamma": "exp0", "--omega": "nums", "--D1": "num", "--D2": "num", "--g": "nums",
            "--tol": "tol", "--method": "eps-method", "--no-build": "flag", "--end": "end", "--json": "flag"},
    "calibrate": {"--alpha": "exp", "--gamma": "exp0", "--D1": "num", "--eps": "unit", "--g": "nums",
                  "--end": "end", "--json": "flag"},
    "lammps": {"--normal": "normal", "--damping": "damping", "--k-n": "num", "--E": "num", "--nu": "nu",
               "--eta-n0": "num", "--eps": "unit", "--limit-damping": "flag", "--radius": "nums",
               "--density": "nums", "--g": "nums", "--json": "flag"},
}
CHOICES = {
    "collide-method": (["reference", "fast", "closed-form"], ["bogus", "", "REFERENCE"]),
    "eps-method": (["integrator", "uniform", "closed-form", "viscous", "elastic", "reference"], ["bogus", "master2"]),
    "end": (["force", "overlap"], ["both", "", "Force"]),
    "normal": (["hooke", "hertz", "hertz/material"], ["dmt", ""]),
    "damping": (["velocity", "mass_velocity", "viscoelastic", "tsuji", "coeff_restitution"], ["mdr", ""]),
}


@st.composite
def value_tokens(draw, kind):
    """(tokens, invalid?) for one option of ``kind``; invalid means every sensible reading refuses it."""
    bad = draw(st.integers(0, 3)) == 0
    if kind == "flag":
        return [], False
    if kind in ("exp", "exp0"):
        pool = EXPONENT_TOKENS["invalid" if bad else "valid"]
        if kind == "exp0" and not bad:
            pool = pool + ["0", "1/4"]
        tok = draw(st.sampled_from(pool))
        if kind == "exp0" and tok == "0":
            bad = False
        return [tok], bad
    if kind in CHOICES:
        good, wrong = CHOICES[kind]
        return [draw(st.sampled_from(wrong if bad else good))], bad
    if kind == "int":
        return ([draw(st.sampled_from(["-1", "x", "1.5", ""]))], True) if bad else ([str(draw(st.integers(0, 4)))], False)
    if kind == "pow":
        return ([draw(st.sampled_from(["0", "-2", "x", "1/0"]))], True) if bad else ([draw(st.sampled_from(["4", "6", "11/2"]))], False)
    if kind == "rtol":
        return ([draw(st.sampled_from(["0", "1", "nan", "1e-20", "-1e-9"]))], True) if bad else \
            ([draw(st.sampled_from(["1e-8", "1e-10", "1e-12"]))], False)
    if kind == "tol":
        return ([draw(st.sampled_from(["0", "1", "2", "nan", "1e-17", "-1e-9"]))], True) if bad else \
            ([draw(st.sampled_from(["1e-3", "1e-6", "1e-9"]))], False)
    if kind == "unit":
        return ([draw(st.sampled_from(["0", "1", "1.5", "-0.5", "nan"]))], True) if bad else \
            ([draw(st.sampled_from(["0.3", "0.6", "0.9"]))], False)
    if kind == "nu":
        return ([draw(st.sampled_from(["0.6", "-1", "2", "nan"]))], True) if bad else ([draw(st.sampled_from(["0.3", "0.2"]))], False)
    # num / nums
    n = draw(st.integers(1, 3)) if kind == "nums" else 1
    if bad:
        toks = [draw(st.sampled_from(NUMBER_TOKENS["valid"])) for _ in range(n - 1)]
        toks.insert(draw(st.integers(0, len(toks))), draw(st.sampled_from(NUMBER_TOKENS["invalid"])))
        return toks, True
    toks = [draw(st.sampled_from(NUMBER_TOKENS["valid"] + ["1e-300", "1e300", "1e-12", "1e12"]))
            for _ in range(n)]
    return toks, False


@st.composite
def argv_cases(draw):
    """(argv, must_refuse): a random command line; must_refuse when some value is invalid by
    construction or the same option is given twice."""
    sub = draw(st.sampled_from(sorted(SUBCOMMANDS)))
    options = SUBCOMMANDS[sub]
    chosen = draw(st.lists(st.sampled_from(sorted(options)), max_size=len(options) + 2))
    argv, must_refuse, seen = [sub], False, set()
    for opt in chosen:
        tokens, bad = draw(value_tokens(options[opt]))
        if opt in seen:
            must_refuse = True   # a repeat
        seen.add(opt)
        style = draw(st.integers(0, 9))
        if style == 0 and tokens:            # the value missing
            argv.append(opt)
            must_refuse = True
            continue
        if style == 1 and len(tokens) == 1:
            argv.append(f"{opt}={tokens[0]}")
        else:
            argv += [opt, *tokens]
        # an empty token is a value only for the options that read strings
        must_refuse |= bad
    if draw(st.integers(0, 14)) == 0:
        argv.insert(draw(st.integers(1, len(argv))), draw(st.sampled_from(["--bogus", "extra", "-x", "--"])))
        must_refuse = True
    return argv, must_refuse


def check_argv_case(argv, must_refuse) -> dict:
    """Run the CLI in process; a record with status ok / FAIL and why."""
    from restitution import cli

    out, err = io.StringIO(), io.StringIO()
    real_err = sys.stderr
    sys.stderr = err
    t0 = time.perf_counter()
    try:
        code = cli.main(list(argv), out=out)
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else 1
        err.write(f"SystemExit({exc.code!r}) escaped main\n")
    except BaseException as exc:  # noqa: BLE001 - a traceback is the failure we look for
        code = 1
        err.write("Traceback (most recent call last):\n" + "".join(traceback.format_exception(exc)))
    finally:
        sys.stderr = real_err
    text = err.getvalue()
    lines = [line for line in text.splitlines() if line.strip() and "taken as" not in line
             and not line.startswith("restitution: note:") and "building" not in line
             and "built " not in line and not line.startswith("restitution:   ")]
    rec = {"method": "cli:" + argv[0], "rule": "-", "argv": list(argv), "code": code,
           "seconds": time.perf_counter() - t0}
    problems = []
    if "Traceback" in text or "SystemExit" in text:
        problems.append("traceback")
    if code not in (0, 2):
        problems.append(f"exit status {code}")
    if code == 0 and must_refuse:
        problems.append("exit 0 on a refused value")
    if code == 2 and len(lines) != 1:
        problems.append(f"refusal in {len(lines)} lines")
    if code == 0 and not out.getvalue().strip():
        problems.append("exit 0 without output")
    rec.update(status="FAIL" if problems else ("refused" if code == 2 else "answered"),
               ratio=0.0, detail="; ".join(problems) + (" | " + text[-400:] if problems else ""))
    return rec


# ----------------------------------------------------------------------------- config mutations
def _config_tools():
    import yaml
    from restitution_workflow.config import ConfigError, check_config
    return yaml, ConfigError, check_config


BAD_VALUES = [float("nan"), float("inf"), -1.0, 0.0, "abc", None, [], {}, True, 1e400, -1e-300, "", "3/0",
              10 ** 400]


def _paths(node, prefix=()):
    if isinstance(node, dict):
        for k, v in node.items():
            yield prefix + (k,), v
            yield from _paths(v, prefix + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield prefix + (i,), v
            yield from _paths(v, prefix + (i,))


@st.composite
def config_cases(draw):
    """(mutated config, must_refuse): one to three mutations of config.yaml's document."""
    yaml, _, _ = _config_tools()
    base = yaml.safe_load((ROOT / "config.yaml").read_text())
    config = copy.deepcopy(base)
    must_refuse = False
    bad = {}   # path -> is the value now there surely refused (a later mutation may replace or delete it)
    for _ in range(draw(st.integers(1, 3))):
        leaves = [p for p, v in _paths(config) if not isinstance(v, (dict, list))]
        if not leaves:
            break
        path = draw(st.sampled_from(leaves))
        parent = config
        for k in path[:-1]:
            parent = parent[k]
        kind = draw(st.sampled_from(["bad", "delete", "unknown", "reserved", "same"]))
        if kind == "bad":
            old = parent[path[-1]]
            parent[path[-1]] = draw(st.sampled_from(BAD_VALUES))
            # None where the config itself has null (plot.tau_max_forward, fit_g_range) is no mutation:
            # make fuzz counted such configs, equal to config.yaml, as wrongly accepted
            bad[path] = ((_surely_bad(path, parent[path[-1]]) and parent[path[-1]] != old)
                         or path[-1] == "surely_not_a_field")
        elif kind == "delete" and isinstance(parent, dict):
            del parent[path[-1]]
            bad.pop(path, None)
        elif kind == "unknown" and isinstance(parent, dict):
            # tracked like a bad value: a later mutation may delete it again (make fuzz counted two
            # configs that had lost it as wrongly accepted)
            parent["surely_not_a_field"] = 1
            bad[path[:-1] + ("surely_not_a_field",)] = True
        elif kind == "reserved" and "variants" in config and config["variants"]:
            config["variants"][0]["name"] = draw(st.sampled_from(["paper", "figures", "bench", "dem",
                                                                  "stability", "fuzz"]))
            must_refuse = True
    return config, must_refuse or any(bad.values())


def _surely_bad(path, value) -> bool:
    """Values no field of ours accepts: NaN, infinities, None where a number is, containers where a
    scalar is, booleans where a number is, numbers beyond doubles."""
    if isinstance(value, float) and not math.isfinite(value):
        return True
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) > 1e308:
        return True
    return isinstance(value, (list, dict)) or value is None


def check_config_case(config, must_refuse) -> dict:
    yaml, ConfigError, check_config = _config_tools()
    rec = {"method": "config", "rule": "-", "ratio": 0.0}
    try:
        check_config(copy.deepcopy(config), str(ROOT / "workflow" / "schemas" / "config.schema.yaml"))
        ok, detail = not must_refuse, "accepted" + (" a value that must be refused" if must_refuse else "")
        rec.update(status="answered" if ok else "FAIL", detail="" if ok else detail)
    except ConfigError as exc:
        one = "\n" not in str(exc) and str(exc).strip() != ""
        rec.update(status="refused" if one else "FAIL", detail="" if one else f"refusal of several lines: {exc}")
    except Exception as exc:  # noqa: BLE001
        rec.update(status="FAIL", detail="".join(traceback.format_exception_only(exc)).strip())
    if rec["status"] == "FAIL":
        rec["config"] = json.dumps(config, default=str)[:2000]
        # what the mutations changed, in full: the config above is cut, and a change is hard to see in it
        rec["mutations"] = _changes(yaml.safe_load((ROOT / "config.yaml").read_text()), config)
    return rec


def _changes(base, config, path: str = "") -> list[str]:
    """Where ``config`` differs from ``base``: "field: old -> new", "field: deleted", "field: added"."""
    if isinstance(base, dict) and isinstance(config, dict):
        out = []
        for key in list(base) + [k for k in config if k not in base]:
            field = f"{path}.{key}" if path else str(key)
            if key not in config:
                out.append(f"{field}: deleted")
            elif key not in base:
                out.append(f"{field}: added {config[key]!r}")
            else:
                out += _changes(base[key], config[key], field)
        return out
    if isinstance(base, list) and isinstance(config, list) and len(base) == len(config):
        return [c for i, (b, v) in enumerate(zip(base, config)) for c in _changes(b, v, f"{path}[{i}]")]
    nans = isinstance(base, float) and isinstance(config, float) and base != base and config != config
    same = base == config or nans
    return [] if same and type(base) is type(config) else [f"{path}: {base!r} -> {config!r}"]

"""Property-based and differential fuzzing (issue 28): the strategies, the checks and the long run.

Kinds of case:

* **numbers**: an accepted exponent pair, an end rule, Omega (log-uniform over the domain where the
  mpmath reference is affordable, weighted toward the tightest bounds: tiny eps, 1 - eps near 0,
  both limits of Omega, the overlap rule, gamma < 1) and a tolerance. Every answer -- the default
  ladder's, each forced rung's (with its own bound) and ``collide``'s, 1 - eps included -- must lie
  within its stated relative bound of the mpmath reference, or be refused with a one-line
  ParameterError. Under the overlap rule the reference cannot prove sticking: ``collide`` is asked
  first, and where it proves sticking every answer must be a refusal.
* **inputs**: random argument vectors for every subcommand (numbers of every class, strings,
  repeats, missing values), random mutations of config.yaml, and random decks with one line cut,
  damaged, repeated or dropped. Never a traceback; a value that is
  out of range by construction is never answered with exit status 0; a refusal is one line.
* **scenes** and **decks** (with LAMMPS, LIGGGHTS installed): a random scene's chosen contacts, and
  every type pair and flat wall of a random input deck as `restitution deck` reads it, run head-on
  in the real engine with the scene's lines or the deck's own; extrapolated to dt = 0 the engine
  must give the eps listed, and keep together the bodies said to stick.

``tests/library/test_fuzz.py`` runs a small derandomized profile in ``make test``; ``make fuzz`` runs
``python tests/fuzzing.py``: the long profile in parallel over the cores, a table of cases,
failures and the worst error/bound ratio per rung and rule written to results/fuzz/.
"""

from __future__ import annotations

import argparse
import copy
import dataclasses
import functools
import io
import json
import math
import os
import re
import sys
import time
import traceback
from fractions import Fraction
from pathlib import Path

from hypothesis import strategies as st

ROOT = Path(__file__).resolve().parents[1]

# ------------------------------------------------------------------------------------ numbers
#: Denominators of the accepted exponents (at most 12); small ones are the materials people use.
DENOMINATORS = (1, 2, 3, 4, 6, 12, 5, 7, 8, 9, 10, 11)
#: The reference digits: the bounds checked go down to about 1e-14 (and the reference's own
#: two-run error estimate is added to the allowance).
REF_DIGITS = 20
#: Below these Omega the mpmath reference takes minutes (it steps through the slow creeping
#: return; under the force rule for alpha > gamma it carries log10(1/Omega) more digits: 2 s at
#: 1e-40, 35 s at 1e-190); the rungs' own domains go further, the differential check stops here.
OMEGA_FLOOR = {"alpha<=gamma": 1e-3, "overlap": 1e-4, "force": 1e-40}
OMEGA_CEIL = 1e14


@st.composite
def exponents(draw):
    """An accepted pair (alpha in (0, 8], gamma in [0, 8]) over one denominator p <= 12; half of
    the gammas below 1. (Pairs whose common denominator exceeds 12, such as 68/9 with 9/10, are
    accepted too, but the mpmath reference, stepping in tau^(1/p), takes minutes there.)"""
    den = draw(st.sampled_from(DENOMINATORS))
    below_one = draw(st.booleans())
    gamma = Fraction(draw(st.integers(0, den - 1 if below_one else 8 * den)), den)
    alpha = Fraction(draw(st.integers(1, 8 * den)), den)
    return str(alpha), str(gamma)


@st.composite
def large_exponents(draw):
    """Both exponents above 4 over one denominator: where the double-precision integrators' error
    grows about as (alpha + gamma)^3 (core.conditioning.EXPONENT_SCALE), which the plain draw above
    reaches too rarely to have found."""
    den = draw(st.sampled_from(DENOMINATORS[:6]))
    gamma = Fraction(draw(st.integers(4 * den, 8 * den - 1)), den)
    alpha = Fraction(draw(st.integers(gamma.numerator * den // gamma.denominator + 1, 8 * den)), den)
    return str(alpha), str(gamma)


#: The exponent pairs people use, drawn a third of the time.
COMMON_PAIRS = (("3/2", "1"), ("3/2", "1/2"), ("1", "0"), ("5/2", "1/2"), ("2", "1/3"), ("1", "1"), ("1", "2"),
                ("3/2", "1/4"))


@st.composite
def number_cases(draw, cheap: bool = False):
    alpha, gamma = draw(st.one_of(st.sampled_from(COMMON_PAIRS), exponents(), large_exponents()))
    end = draw(st.sampled_from(["force", "overlap"]))
    a, g = Fraction(alpha), Fraction(gamma)
    key = "alpha<=gamma" if a <= g else end
    lo = math.log10(OMEGA_FLOOR[key])
    hi = math.log10(OMEGA_CEIL)
    if cheap:   # make test: the mpmath reference at its quickest
        lo = max(lo, -8.0 if key == "force" else -2.0)
        hi = min(hi, 10.0)
    # weight: a third at each end (tiny eps / 1 - eps near 0), a third anywhere; where the overlap
    # rule can stick, a share just above the sticking boundary (eps -> 0 there)
    zones = ["low", "high", "any"] + (["edge"] * 2 if end == "overlap" and a >= 2 * g + 1 else [])
    zone = draw(st.sampled_from(zones))
    edge = _sticking_boundary(alpha, gamma) if zone == "edge" else None
    if edge:
        log_omega = math.log10(edge * (1.0 + 10.0 ** draw(st.floats(-3.0, 0.0))))
    else:
        span = {"low": (lo, lo + 0.25 * (hi - lo)), "high": (hi - 0.25 * (hi - lo), hi)}.get(zone, (lo, hi))
        log_omega = draw(st.floats(*span, allow_nan=False, allow_infinity=False))
    tol = 10.0 ** draw(st.floats(-13.5, -3.0))
    rtol = 10.0 ** draw(st.floats(-13.0, -6.0))
    return {"alpha": alpha, "gamma": gamma, "end": end, "omega": 10.0 ** log_omega, "tol": tol, "rtol": rtol}


@functools.lru_cache(maxsize=None)
def _sticking_boundary(alpha: str, gamma: str) -> float | None:
    """The overlap rule's sticking boundary in [1e-3, 1e3], None where there is none there."""
    from restitution.fast.overlap_master import sticking_boundary
    try:
        w = sticking_boundary((alpha, gamma), lo=1e-3, hi=1e3)
    except ArithmeticError:   # sticks over the whole range
        return None
    return w if 1e-3 < w < 1e3 else None


def _reference(case):
    """(eps, 1 - eps, estimates of the reference's own relative errors in both) or ("stick", ...)."""
    from restitution.core.collision import StickError, collide
    from restitution.core.highprec import reference_collision

    a, g = Fraction(case["alpha"]), Fraction(case["gamma"])
    if case["end"] == "overlap" and a > g:
        try:
            collide((case["alpha"], case["gamma"]), case["omega"], end="overlap", rtol=1e-8)
        except StickError:
            return "stick", None, 0.0, 0.0
        except Exception:  # noqa: BLE001 - judged below, by the reference
            pass
    r = reference_collision((case["alpha"], case["gamma"]), case["omega"], digits=REF_DIGITS, end=case["end"])
    if 0 < 1 - r.eps < 1e-3:
        # 1 - eps has only REF_DIGITS + log10(1 - eps) correct digits: carry that many more
        extra = int(-math.log10(float(1 - r.eps))) + 1
        r = reference_collision((case["alpha"], case["gamma"]), case["omega"], digits=REF_DIGITS + extra,
                                end=case["end"])
    one_minus = 1 - r.eps
    err = float(r.error_estimate)
    return r.eps, one_minus, err, (err * float(r.eps / one_minus) if one_minus > 0 else math.inf)


def _one_line(exc) -> bool:
    return "\n" not in str(exc) and str(exc).strip() != ""


def check_number_case(case) -> list[dict]:
    """One record per answer: method, rule, status (answered / refused / FAIL), ratio error/bound."""
    import mpmath as mp

    from restitution import api
    from restitution.core.errors import ParameterError

    rule = case["end"]
    try:
        ref, ref_one_minus, ref_err, ref_err1 = _reference(case)
    except ParameterError as exc:
        return [{"method": "reference-mpmath", "rule": rule, "status": "refused", "ratio": 0.0,
                 "detail": str(exc), "case": case}]
    records = []

    def judge(method, eps, bound, one_minus=None, one_minus_bound=None):
        rec = {"method": method, "rule": rule, "case": case, "bound": bound}
        if ref == "stick":
            rec.update(status="FAIL", ratio=math.inf,
                       detail=f"eps = {eps!r} answered where collide proves sticking")
            return rec
        err = float(abs(mp.mpf(eps) - ref) / ref)
        ratio = err / bound if bound > 0 else math.inf
        slack = 1e-9 + ref_err / bound if bound > 0 else 0.0
        rec.update(status="answered" if ratio <= 1.0 + slack else "FAIL", ratio=ratio, error=err,
                   detail=f"eps = {eps!r}, reference {mp.nstr(ref, 17)}, relative error {err:.3g}, bound {bound:.3g}")
        if one_minus is not None and one_minus_bound is not None and rec["status"] != "FAIL" and ref_one_minus > 0:
            err1 = float(abs(mp.mpf(one_minus) - ref_one_minus) / ref_one_minus)
            r1 = err1 / one_minus_bound
            if r1 > 1.0 + 1e-9 + ref_err1 / one_minus_bound:
                rec.update(status="FAIL", ratio=max(ratio, r1),
                           detail=f"1 - eps = {one_minus!r}, reference {mp.nstr(ref_one_minus, 17)}, "
                                  f"relative error {err1:.3g}, bound {one_minus_bound:.3g}")
            rec["ratio"] = max(rec["ratio"], r1)
        return rec

    def attempt(method, call):
        try:
            return call()
        except ParameterError as exc:
            if not _one_line(exc):
                records.append({"method": method, "rule": rule, "status": "FAIL", "ratio": math.inf,
                                "detail": f"refusal of several lines: {exc!s}", "case": case})
            else:
                records.append({"method": method, "rule": rule, "status": "refused", "ratio": 0.0,
                                "detail": str(exc), "case": case})
        except Exception as exc:  # noqa: BLE001 - a traceback is a failure
            records.append({"method": method, "rule": rule, "status": "FAIL", "ratio": math.inf,
                            "detail": "".join(traceback.format_exception_only(exc)).strip(), "case": case})
        return None

    common = dict(alpha=case["alpha"], gamma=case["gamma"], omega=[case["omega"]], end=rule)
    r = attempt("ladder", lambda: api.epsilon(tol=case["tol"], build=False, **common))
    if r is not None:
        rec = judge("ladder:" + r.method, float(r.eps[0]), float(r.error_bound))
        if r.error_bound > case["tol"] * (1 + 1e-12):
            rec.update(status="FAIL", detail=f"bound {r.error_bound:.3g} above tol {case['tol']:.3g}")
        records.append(rec)
    for method in api.RUNG_NAMES:
        if method == "highprec":   # the reference itself at other digits: its cost, not a check
            continue
        # the master curves (force rule, overlap rule) are built for the common pairs, in seconds,
        # so that their rungs are checked too, and the uniform forms (both rules, 1-5 s each) for the
        # paper's and Hertz exponents; the relations' builds take minutes and stay unbuilt
        pair = (case["alpha"], case["gamma"])
        build = ((method == "master" and pair in COMMON_PAIRS)
                 or (method == "closed-form" and pair in COMMON_PAIRS[:2]))
        r = attempt(method, lambda m=method: api.epsilon(tol=None, method=m, build=build, **common))
        if r is not None:
            records.append(judge(method, float(r.eps[0]), float(r.error_bound)))
    c = attempt("collide", lambda: api.collide(case["alpha"], case["gamma"], case["omega"], rtol=case["rtol"],
                                               end=rule))
    if c is not None:
        # the accuracies collide states (10 rtol + 1e-13, widened near a sticking boundary for eps,
        # by eps / (1 - eps) for a large 1 - eps taken by subtraction)
        plain = 10 * max(case["rtol"], 2.2e-14) + 1e-13
        b = c.error_bound if getattr(c, "error_bound", None) is not None else plain
        b1 = c.one_minus_eps_bound if getattr(c, "one_minus_eps_bound", None) is not None else plain
        records.append(judge("collide", c.eps, b, getattr(c, "one_minus_eps", None), b1))
    return records


# ------------------------------------------------------------------------------------ deep overlap
#: Below OMEGA_FLOOR["overlap"] the mpmath reference is out of reach; there the overlap rule is
#: checked against what holds without it: a pair that can stick (alpha >= 2 gamma + 1) must be
#: refused as sticking (core.collision.stick_bound lies far above 1e-8 for every accepted pair), and
#: otherwise eps = C Omega^k exactly scales the scipy reference's eps at DEEP_ANCHOR (rtol 1e-11).
DEEP_ANCHOR = 1e-12
#: A request that takes longer than this is a creep no rung should follow.
DEEP_SECONDS = 30.0


@st.composite
def deep_overlap_cases(draw):
    law = draw(st.booleans())   # half the cases where the law holds, half where the bodies can stick
    alpha, gamma = draw(st.one_of(st.sampled_from(COMMON_PAIRS), exponents()).filter(
        lambda p: Fraction(p[1]) < Fraction(p[0]) and (Fraction(p[0]) < 2 * Fraction(p[1]) + 1) == law))
    omega = 10.0 ** draw(st.floats(-300.0, -8.0))
    return {"alpha": alpha, "gamma": gamma, "end": "overlap", "omega": omega, "tol": 10.0 ** draw(st.floats(-10.0, -3.0))}


def check_deep_overlap_case(case) -> list[dict]:
    from restitution import api
    from restitution.core.collision import StickError, collide
    from restitution.core.errors import ParameterError
    from restitution.core.overlap_limit import overlap_limit

    a, g = Fraction(case["alpha"]), Fraction(case["gamma"])
    rec = {"method": "ladder", "rule": "overlap (deep)", "case": case, "ratio": 0.0}
    t0 = time.perf_counter()
    try:
        got = api.epsilon(alpha=case["alpha"], gamma=case["gamma"], omega=[case["omega"]], tol=case["tol"],
                          end="overlap", build=False)
    except StickError as exc:
        ok = a >= 2 * g + 1 and _one_line(exc)
        return [{**rec, "status": "answered" if ok else "FAIL", "detail": f"sticks: {exc}"}]
    except ParameterError as exc:
        return [{**rec, "status": "refused" if _one_line(exc) and a < 2 * g + 1 else "FAIL", "detail": str(exc)}]
    except Exception as exc:  # noqa: BLE001 - a traceback is a failure
        return [{**rec, "status": "FAIL", "detail": "".join(traceback.format_exception_only(exc)).strip()}]
    seconds = time.perf_counter() - t0
    rec["method"] = "ladder:" + got.method
    eps, bound = float(got.eps[0]), float(got.error_bound)
    if a >= 2 * g + 1:
        return [{**rec, "status": "FAIL", "ratio": math.inf, "detail": f"eps = {eps!r} where the bodies provably stick"}]
    try:
        anchor = collide((case["alpha"], case["gamma"]), DEEP_ANCHOR, end="overlap", rtol=1e-11)
    except ParameterError as exc:   # the anchor is out of the reference's reach: nothing to compare
        return [{**rec, "status": "answered", "detail": f"eps = {eps!r}; no anchor ({exc})"}]
    truth = anchor.eps * (case["omega"] / DEEP_ANCHOR) ** overlap_limit((a, g)).k
    err = abs(eps / truth - 1.0)
    allowed = bound + anchor.error_bound + 1e-13 * abs(math.log(case["omega"] / DEEP_ANCHOR))
    ok = err <= allowed and seconds <= DEEP_SECONDS
    return [{**rec, "status": "answered" if ok else "FAIL", "ratio": err / allowed, "error": err,
             "detail": f"eps = {eps!r}, anchor-scaled {truth!r}, relative error {err:.3g}, allowed {allowed:.3g}, "
                       f"{seconds:.1f} s"}]


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
    "eps-method": (["integrator", "closed-form", "viscous", "elastic", "reference"], ["bogus", "master2"]),
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
    return rec


# ------------------------------------------------------------------------------------ scenes
#: A met contact's eps, extrapolated to dt = 0 from LAMMPS runs at t_c/2000, /4000, /8000, must be
#: the listed eps to this (relative); at the scene's own dt, to the scene's tolerance (absolute).
SCENE_EXTRAPOLATED = 1e-5
SCENE_STEPS = 2000


def _extrapolated(first, finer, gamma, listed: float) -> float:
    """eps extrapolated to dt = 0 from ``first``, the runs at t_c/SCENE_STEPS, /2, /4; where that
    misses the listed eps by over SCENE_EXTRAPOLATED, from ``finer()``, the same at four times the
    steps. A heavily damped contact leaves more than that at 2000 steps (make fuzz, seed 7373: a
    LIGGGHTS pair listed at eps = 0.07 extrapolated to 0.0700008 from 2000 steps, 0.07000003 from
    8000, 0.070000002 from 32000): the engine's eps converges to the listed one, the first
    extrapolation had not."""
    from restitution.dem.extrapolate import richardson

    eps0 = richardson(*first, gamma)
    if abs(eps0 / listed - 1.0) > SCENE_EXTRAPOLATED:
        eps0 = richardson(*finer(), gamma)
    return eps0


@st.composite
def scene_cases(draw):
    """A random LAMMPS scene: two materials (one radius each, 0.1 to 100 mm) and maybe a wall of
    the second, a normal model with its stiffness (E and nu, or k_n), a damping option or "choose",
    limit_damping, a speed range inside 1e-3..1e3 m/s, constant or tabulated targets, a tolerance."""
    normal = draw(st.sampled_from(["hooke", "hertz", "hertz/material"]))
    log = lambda lo, hi: 10.0 ** draw(st.floats(lo, hi))  # noqa: E731
    materials = {}
    for name in ("m1", "m2"):
        m = {"density": log(2.7, 4.3)}
        if normal == "hertz/material":
            m.update(E=log(6.0, 11.5), nu=draw(st.floats(0.0, 0.49)))
        else:
            m["k_n"] = log(5.0, 11.0) if normal == "hertz" else log(1.0, 6.0)
        materials[name] = m
    lo = log(-3.0, 0.5)
    hi = lo * log(0.3, 2.5)
    targets = []
    for pair in (["m1", "m1"], ["m1", "m2"], ["m2", "m2"]):
        e0 = round(draw(st.floats(0.05, 0.97)), 3)
        if draw(st.booleans()):
            targets.append({"pair": pair, "e": e0})
        else:
            targets.append({"pair": pair, "table": [[lo, e0], [hi, round(max(0.05, e0 - draw(st.floats(0.0, 0.2))), 3)]]})
    return {"name": "fuzz", "code": "lammps", "tolerance": draw(st.sampled_from([1e-3, 1e-2, 5e-2])),
            "options": {"normal": normal, "damping": draw(st.sampled_from(["choose", "coeff_restitution", "tsuji",
                                                                            "viscoelastic", "velocity",
                                                                            "mass_velocity"])),
                        "limit_damping": draw(st.booleans())},
            "speeds": [lo, hi], "check_points": 200, "materials": materials,
            "species": [{"name": "a", "material": "m1", "radius": log(-4.0, -1.0)},
                        {"name": "b", "material": "m2", "radius": log(-4.0, -1.0)}],
            "walls": ["m2"] if draw(st.booleans()) else [], "targets": targets}


def _answer(scene, method: str):
    """(the scene's answer, None), or (None, [its record]) where the library refuses it: in one line
    (refused) or otherwise (a failure)."""
    from restitution.core.errors import ParameterError
    from restitution.dem.scene import answer_scene
    from restitution.dem.scene_file import scene_from_dict

    try:
        return answer_scene(scene_from_dict(copy.deepcopy(scene))), None
    except Exception as exc:  # noqa: BLE001
        ok = isinstance(exc, ParameterError) and _one_line(exc)
        return None, [{"method": method, "rule": "-", "status": "refused" if ok else "FAIL", "ratio": 0.0,
                       "case": scene, "detail": "" if ok else "".join(traceback.format_exception_only(exc)).strip()}]


def _verdict(rec: dict, worst: float, detail: str) -> dict:
    """A run contact's record: failed where it used more than its allowance."""
    return {**rec, "status": "FAIL" if worst > 1.0 else "answered", "ratio": worst,
            "detail": detail if worst > 1.0 else ""}


def _against(c, g, listed, eps0, at_dt, tolerance, engine) -> tuple[float, str]:
    """A scene contact's listed eps against the engine's: (the larger share of its allowance used,
    extrapolated or at the listed dt; what was compared)."""
    ratio = max(abs(eps0 / listed - 1.0) / SCENE_EXTRAPOLATED, abs(at_dt - listed) / tolerance)
    return ratio, (f"{c['a']}-{c['b']} at {g:.4g} m/s: listed {listed:.8g}, {engine} {eps0:.8g} at dt = 0, "
                   f"{at_dt:.8g} at the listed dt (tolerance {tolerance:g})")


def _met_contacts(res, scene, label: str, records: list):
    """(contact, its record) for each contact of a scene's answer that is met and run in the engine;
    the others go to ``records`` as refused (no model, or an overlap that breaks the geometry)."""
    for c in res["contacts"]:
        rec = {"method": f"{label}: {c['chosen'] or 'none'}", "rule": c["end"], "ratio": 0.0, "case": scene,
               "contact": f"{c['a']}-{c['b']}"}
        if c["chosen"] is None or not c["overlap_ok"]:
            records.append({**rec, "status": "refused"})
        else:
            yield c, rec


def check_scene_case(scene) -> list[dict]:
    """Every met contact of the scene in the real LAMMPS engine, head-on at its lowest and highest
    listed speed (a pair of spheres, or a sphere onto the wall), the scene's whole deck loaded:
    extrapolated to dt = 0 within SCENE_EXTRAPOLATED of the listed eps, and at the listed dt within
    the scene's tolerance. A contact whose overlap breaks the geometry is reported not met and is
    not run; a pair without a model gets a placeholder line so that LAMMPS takes the deck."""
    from restitution.dem.engines.lammps.run import lammps_eps, lammps_wall_eps
    from restitution.dem.pair import Pair

    res, refusal = _answer(scene, "scene")
    if refusal:
        return refusal
    types = {t["number"]: t for t in res["types"]}
    have = {tuple(int(x) for x in ln.split()[1:3]) for ln in res["input_lines"] if ln.startswith("pair_coeff")}
    fill = [f"pair_coeff {i} {j} hooke 1 0 tangential linear_nohistory 0 0"
            for i in types for j in types if i <= j and (i, j) not in have]
    deck = "\n".join(res["input_lines"] + fill)
    pairs = "\n".join([ln for ln in res["input_lines"] if ln.startswith("pair_coeff")] + fill)
    records = []
    for c, rec in _met_contacts(res, scene, "scene", records):
        a = types[c["types"][0]]
        worst, detail = 0.0, ""
        for i in (0, len(c["speeds"]) - 1):
            g, listed, t_c = c["speeds"][i], c["eps"][i], c["contact_time"][i]
            # under the force rule the force ends at an overlap the bodies then leave at eps g
            t_run = 3.0 * t_c + 2.0 * c["max_overlap"][i] / (listed * g)
            if c["types"][1] == "wall":
                run = lambda dt: lammps_wall_eps(a["radius"], a["density"], deck, g, dt, t_run,  # noqa: E731
                                                 atom_type=a["number"], ntypes=len(types))
            else:
                b = types[c["types"][1]]
                pair = Pair.spheres(a["radius"], b["radius"], a["density"], b["density"])
                run = lambda dt: lammps_eps(pair, pairs, g, dt, t_run, types=tuple(c["types"]),  # noqa: E731
                                            ntypes=len(types))
            try:
                three = lambda steps: [run(t_c / steps / m) for m in (1, 2, 4)]  # noqa: E731, B023
                eps0 = _extrapolated(three(SCENE_STEPS), lambda: three(4 * SCENE_STEPS), c["gamma"], listed)
                at_dt = run(c["dt"])
            except Exception as exc:  # noqa: BLE001
                worst, detail = math.inf, f"LAMMPS at {g:.4g} m/s: {str(exc).splitlines()[0]}"
                break
            ratio, text = _against(c, g, listed, eps0, at_dt, res["tolerance"], "LAMMPS")
            if ratio > worst:
                worst, detail = ratio, text
        records.append(_verdict(rec, worst, detail))
    return records


@st.composite
def liggghts_scene_cases(draw):
    """A random LIGGGHTS scene: hertz, limitForce on or off, two materials (E 1e6-1e11, nu 0-0.45,
    density), two species (0.1 to 100 mm), maybe a wall, a speed range inside 1e-3..1e3 m/s,
    constant or tabulated targets, a tolerance."""
    log = lambda lo, hi: 10.0 ** draw(st.floats(lo, hi))  # noqa: E731
    scene = draw(scene_cases())
    scene.update(code="liggghts", options={"model": "hertz", "limitForce": draw(st.booleans())})
    scene["materials"] = {name: {"density": m["density"], "E": log(6.0, 11.0), "nu": draw(st.floats(0.0, 0.45))}
                          for name, m in scene["materials"].items()}
    return scene


def check_liggghts_scene_case(scene) -> list[dict]:
    """Every met contact of a LIGGGHTS scene in the real engine (two spheres, or a sphere onto a
    primitive wall of the wall's atom type), head-on at the lowest and highest listed speed with the
    scene's own lines: extrapolated to dt = 0 within SCENE_EXTRAPOLATED of the listed eps, at the
    listed dt within the scene's tolerance."""
    from restitution.dem.engines.liggghts.run import liggghts_eps_runs, liggghts_wall_eps_runs
    from restitution.dem.pair import Pair

    res, refusal = _answer(scene, "liggghts scene")
    if refusal:
        return refusal
    types = {t["number"]: t for t in res["types"]}
    n = len(types) + len({c["types"][1] for c in res["contacts"] if c["b"].startswith("wall:")})
    lines = "\n".join([f"create_box {n} box"] + [ln for ln in res["input_lines"] if not ln.startswith("#")])
    records = []
    for c, rec in _met_contacts(res, scene, "liggghts scene", records):
        a, b = types[c["types"][0]], types.get(c["types"][1])   # b: None for a wall (its own atom type)
        ends = (0, len(c["speeds"]) - 1)
        runs = []
        for i in ends:
            g, t_c = c["speeds"][i], c["contact_time"][i]
            t_run = 3.0 * t_c + 2.0 * c["max_overlap"][i] / (c["eps"][i] * g)
            runs += [(lines, g, c["dt"], t_run, *c["types"])]
            runs += [(lines, g, t_c / SCENE_STEPS / m, t_run, *c["types"]) for m in (1, 2, 4)]
        pair = None if b is None else Pair.spheres(a["radius"], b["radius"], a["density"], b["density"])

        def engine(runs):
            if pair is None:
                return liggghts_wall_eps_runs(a["radius"], a["density"], runs)  # noqa: B023
            return liggghts_eps_runs(pair, [(*r[:4], tuple(r[4:])) for r in runs])  # noqa: B023
        worst, detail = 0.0, ""
        try:
            eps = engine(runs)
            for k, i in enumerate(ends):
                g, listed, t_c, t_run = c["speeds"][i], c["eps"][i], c["contact_time"][i], runs[4 * k][3]
                finer = lambda: engine([(lines, g, t_c / (4 * SCENE_STEPS) / m, t_run, *c["types"])  # noqa: E731, B023
                                        for m in (1, 2, 4)])
                eps0 = _extrapolated(eps[4 * k + 1: 4 * k + 4], finer, c["gamma"], listed)
                ratio, text = _against(c, g, listed, eps0, eps[4 * k], res["tolerance"], "LIGGGHTS")
                if ratio > worst:
                    worst, detail = ratio, text
        except Exception as exc:  # noqa: BLE001
            worst, detail = math.inf, f"LIGGGHTS: {_engine_error(exc)}"
        records.append(_verdict(rec, worst, detail))
    return records


# ------------------------------------------------------------------------------------ decks
#: What `restitution deck` says a LAMMPS deck gives, against the deck's own pair_coeff lines run in
#: LAMMPS: extrapolated to dt = 0 from t_c/2000, /4000, /8000, to this (relative; absolute below it).
DECK_EXTRAPOLATED = 1e-5
DECK_STEPS = 2000
#: A pair the audit says sticks must stay together in LAMMPS for this many elastic contact times, or
#: leave with eps below DECK_STICK_EPS.
DECK_STICK_TIMES = 30
DECK_STICK_EPS = 1e-3
#: Smallest eps run in LAMMPS, per end rule: below it the spheres take too many steps to part (under the
#: overlap rule a creeping return; under the force rule they leave overlapping, at eps g).
DECK_MIN_EPS = {"overlap": 1e-3, "force": 0.02}
#: Nor a run of more steps than this (a strongly overdamped pair: the step follows the damping's
#: fast time, the creep its slow one; or a force-rule pair leaving slowly while still overlapping).
DECK_MAX_STEPS = 400_000


def _damping_for(normal: str, damping: str, radius: float, density: float, k: float, nu: float, omega: float,
                 g: float) -> float:
    """The damping coefficient of a one-type line (eta_n0) that puts its like pair at
    about ``omega`` at speed g: Omega = D1 g^((alpha-1-2 gamma)/(gamma+1)) D2^(-(alpha+1)/(gamma+1)),
    solved for D2 and mapped back through the LAMMPS dictionary."""
    from restitution.dem.engines.lammps.contact import lammps_contact, lammps_eta_n0
    from restitution.dem.pair import Pair

    pair = Pair.spheres(radius, radius, density, density)
    stiff = {"E": k, "nu": nu} if normal == "hertz/material" else {"k_n": k}
    unit = lammps_contact(pair, normal=normal, damping=damping, limit_damping=False,
                          eta_n0=1.0, **stiff)
    a, c = float(unit.alpha), float(unit.gamma)
    d2 = (omega / (unit.D1 * g ** ((a - 1 - 2 * c) / (c + 1)))) ** (-(c + 1) / (a + 1))
    return lammps_eta_n0(pair, damping, dataclasses.replace(unit, D2=d2))


def _lammps_deck_draws(draw) -> tuple:
    """What a random LAMMPS deck starts from: 1-3 types (radius 0.05-50 mm, density 500-20,000),
    one normal and one damping model, an impact speed: (n, normal, damping, g, types)."""
    log = lambda lo, hi: 10.0 ** draw(st.floats(lo, hi))  # noqa: E731
    n = draw(st.integers(1, 3))
    normal = draw(st.sampled_from(["hooke", "hertz", "hertz/material"]))
    damping = draw(st.sampled_from(["velocity", "mass_velocity", "viscoelastic", "tsuji", "coeff_restitution"]))
    g = log(-2.0, 0.5)
    types = {t: {"radius": log(-4.3, -1.3), "density": log(2.7, 4.3)} for t in range(1, n + 1)}
    return n, normal, damping, g, types


def _coeff_numbers(draw, normal: str, damping: str, m: dict, g: float) -> list[str]:
    """A pair_coeff line's numbers for a type of radius and density ``m``: a stiffness, and a
    damping that puts its like pair at a random Omega in 1e-3..30 at speed g (tsuji,
    coeff_restitution: e in 0.05..0.97), with nu for hertz/material."""
    log = lambda lo, hi: 10.0 ** draw(st.floats(lo, hi))  # noqa: E731
    if normal == "hertz/material":
        k, nu = log(6.0, 11.0), draw(st.floats(0.0, 0.45))
    else:
        k, nu = (log(4.0, 10.0) if normal == "hertz" else log(0.0, 5.0)), 0.0
    if damping in ("tsuji", "coeff_restitution"):
        d = draw(st.floats(0.05, 0.97))
    else:
        d = _damping_for(normal, damping, m["radius"], m["density"], k, nu, log(-3.0, 1.5), g)
    return [f"{k:.8g}", f"{d:.8g}"] + ([f"{nu:.4g}"] if normal == "hertz/material" else [])


def _coeff_text(draw, i, j, normal: str, damping: str, numbers: list) -> str:
    """The pair_coeff line of those numbers, limit_damping on some."""
    limit = " limit_damping" if draw(st.booleans()) else ""
    return f"pair_coeff {i} {j} {normal} {' '.join(numbers)} damping {damping} tangential linear_nohistory 0 0{limit}"


@st.composite
def deck_cases(draw):
    """A random LAMMPS deck: 1-3 atom types (radius 0.05-50 mm, density 500-20,000), one normal
    model (stiffness per type), one damping model with each type's coefficient set for a like-pair
    Omega in 1e-3..30 (tsuji, coeff_restitution: e in 0.05..0.97), limit_damping on some lines, maybe an explicit line
    for a cross pair, maybe a `pair_coeff * *` written first and overridden, maybe numbers through
    variables, maybe a flat wall at z = 0 (on all types or a group); and two impact speeds a decade
    apart. Returns (deck text, speeds, types)."""
    n, normal, damping, g, types = _lammps_deck_draws(draw)
    lines, variables = [], []

    def coeff_line(i, j, t):
        numbers = _coeff_numbers(draw, normal, damping, types[t], g)
        if draw(st.integers(0, 3)) == 0:      # a number through a variable
            name = f"k{len(variables)}"
            variables.append(f"variable {name} equal {numbers[0]}")
            numbers[0] = "${" + name + "}"
        return _coeff_text(draw, i, j, normal, damping, numbers)

    if draw(st.booleans()):
        lines.append(coeff_line("*", "*", 1))
    for t in types:
        lines.append(coeff_line(t, t, t))
    if n > 1 and draw(st.booleans()):
        i, j = sorted(draw(st.sampled_from([(a, b) for a in types for b in types if a < b])))
        lines.append(coeff_line(i, j, i))
    if draw(st.booleans()):   # a flat wall, its model drawn like a type's own line
        lines += _wall_lines(draw, types, "fix floor GROUP wall/gran granular "
                             + coeff_line("*", "*", draw(st.sampled_from(list(types)))).split(" ", 3)[3]
                             + " zplane 0.0 NULL")
    body = "\n".join(["units si", "atom_style sphere", "boundary f f f", "region box block -1 1 -1 1 -1 1",
                      f"create_box {n} box"]
                     + [f"set type {t} diameter {2 * m['radius']:.8g} density {m['density']:.8g}" for t, m in types.items()]
                     + variables + ["pair_style granular"] + lines)
    return body + "\n", [g, 10.0 * g], {t: {k: float(f"{v:.8g}") for k, v in m.items()} for t, m in types.items()}


def _wall_lines(draw, types: dict, wall: str) -> list[str]:
    """The ``wall`` line on all types, or (with several) on a group of some of them (its GROUP),
    defined after atoms exist (a group holds the atoms present when it is defined)."""
    if len(types) > 1 and draw(st.booleans()):
        members = sorted(draw(st.sets(st.sampled_from(list(types)), min_size=1)))
        return [f"create_atoms {t} random 1 {4242 + t} NULL" for t in types] + [
            f"group walled type {' '.join(map(str, members))}", wall.replace("GROUP", "walled")]
    return [wall.replace("GROUP", "all")]


@st.composite
def liggghts_deck_cases(draw):
    """A random LIGGGHTS deck: 1-3 atom types (radius 0.05-50 mm, density 500-20,000, E 1e5-1e11,
    nu 0-0.55), a symmetric coefficientRestitution matrix (0.02-0.97), hertz or hooke (with a
    characteristicVelocity), limitForce on or off, maybe soft_particles / hard_particles yes, maybe
    E through a variable, maybe a wall of one of the types at z = 0 (a plane or a mesh face, its own
    limitForce or none); two speeds a decade
    apart (some draws break LIGGGHTS' own limits on E, nu
    and e: the audit must refuse exactly those). Returns (deck text, speeds, types)."""
    log = lambda lo, hi: 10.0 ** draw(st.floats(lo, hi))  # noqa: E731
    n = draw(st.integers(1, 3))
    model = draw(st.sampled_from(["hertz", "hooke"]))
    g = log(-2.0, 0.5)
    types = {t: {"radius": log(-4.3, -1.3), "density": log(2.7, 4.3)} for t in range(1, n + 1)}
    E = [f"{log(5.0, 11.0) if draw(st.integers(0, 7)) == 0 else log(6.8, 9.0):.6g}" for _ in types]
    nu = [f"{draw(st.floats(0.0, 0.55) if draw(st.integers(0, 9)) == 0 else st.floats(0.0, 0.45)):.4g}"
          for _ in types]
    e = {(i, j): f"{draw(st.floats(0.02, 0.97) if draw(st.integers(0, 9)) == 0 else st.floats(0.06, 0.97)):.4g}"
         for i in types for j in types if i <= j}
    matrix = " ".join(e[min(i, j), max(i, j)] for i in types for j in types)
    lines = ["atom_style granular", "units si", "region box block -1 1 -1 1 -1 1 units box", f"create_box {n} box"]
    lines += [f"{what}_particles yes" for what in ("soft", "hard") if draw(st.booleans())]
    if draw(st.booleans()):
        lines.append(f"variable E1 equal {E[0]}")
        E[0] = "${E1}"
    lines += [f"fix m1 all property/global youngsModulus peratomtype {' '.join(E)}",
              f"fix m2 all property/global poissonsRatio peratomtype {' '.join(nu)}",
              f"fix m3 all property/global coefficientRestitution peratomtypepair {n} {matrix}",
              f"fix m4 all property/global coefficientFriction peratomtypepair {n} " + " ".join(["0.5"] * n * n)]
    wall = draw(st.sampled_from([None, "hertz", "hooke"]))
    if "hooke" in (model, wall):
        lines.append(f"fix m5 all property/global characteristicVelocity scalar {log(-1.0, 1.0):.4g}")
    limit = draw(st.sampled_from(["on", "off"]))
    tangential = f"tangential {draw(st.sampled_from(['history', 'no_history']))}"
    lines += [f"pair_style gran model {model} {tangential} limitForce {limit}", "pair_coeff * *"]
    if wall is not None:
        # a flat wall of one of the types: a plane or a mesh face (plate.stl, written by the check),
        # a model of its own (LIGGGHTS 3.8.0 runs a hooke wall beside hertz pairs, though its manual
        # says it must match) and a limitForce of its own, or none
        models = f"model {wall} {tangential}"
        w, own = draw(st.sampled_from(list(types))), draw(st.sampled_from(["", " limitForce on", " limitForce off"]))
        if draw(st.booleans()):
            lines += _wall_lines(draw, types, f"fix floor GROUP wall/gran {models} primitive type {w} zplane 0.0{own}")
        else:
            lines += [f"fix mesh1 all mesh/surface file plate.stl type {w}"]
            lines += _wall_lines(draw, types, f"fix floor GROUP wall/gran {models} mesh n_meshes 1 meshes mesh1{own}")
    lines += [f"fix pts{t} all particletemplate/sphere {15485863 + t} atom_type {t} density constant "
              f"{m['density']:.8g} radius constant {m['radius']:.8g}" for t, m in types.items()]
    return "\n".join(lines) + "\n", [g, 10.0 * g], {t: {k: float(f"{v:.8g}") for k, v in m.items()}
                                                       for t, m in types.items()}


# ------------------------------------------------------------------ decks in the input language
def _disguised(draw, x: str) -> str:
    """A LAMMPS formula whose value is the number ``x``, written with the grammar's corners (unary
    minus above ^, ^ left to right, log base 10, !, ternary, comparisons): LAMMPS evaluates it in
    the engine run, the reader in the audit, and a reader that got a rule wrong gives another
    number."""
    v = float(x)
    forms = [x, f"-(-{x})", f"--{x}", f"({x}/2)*2", f"10^log({x})", f"sqrt({x}^2)", f"exp(ln({x}))",
             f"-{math.sqrt(v)!r}^2", f"{x}*(2^3^2==64)", f"{x}*!0", f"ternary(1<2&&!(3<2),{x},{2 * v!r})",
             f"{x}*(1|^0)", f"{x}+0*round(-2.5)"]
    return draw(st.sampled_from(forms))


@st.composite
def script_deck_cases(draw):
    """A random LAMMPS deck written with the constructs of its input language that decide which
    contact lines run (issue 42): 1-3 run stages, each with new coefficients for every type (1-3
    types, radius 0.05-50 mm), each line written plainly, or behind an if (numbers or strings
    compared, the other branch a decoy), after a jump over a decoy, as the last turn of a loop over
    an index variable, beside a decoy in double or triple quotes; numbers through equal-style
    formulas and $(...); a pair_style of another style between stages (which discards the
    coefficients) or the same style again (which keeps them); type labels. The last line runs the
    last stage. Returns (deck text, speeds, types, the number of head lines)."""
    n, normal, damping, g, types = _lammps_deck_draws(draw)
    labels = draw(st.booleans())
    name = {t: f"{'abc'[t - 1]}{t}" if labels else str(t) for t in types}
    head = ["units si", "atom_style sphere", "boundary f f f", "region box block -1 1 -1 1 -1 1", f"create_box {n} box"]
    head += [f"set type {t} diameter {2 * m['radius']:.8g} density {m['density']:.8g}" for t, m in types.items()]
    body = [] if not labels else ["labelmap atom " + " ".join(f"{t} {name[t]}" for t in types)]
    body.append("pair_style granular")
    count = iter(range(10 ** 6))

    def line(i, j, t):
        numbers = _coeff_numbers(draw, normal, damping, types[t], g)
        k = next(count)
        how = draw(st.sampled_from(["plain", "variable", "immediate"]))
        if how == "variable":
            body.append(f"variable n{k} equal {_disguised(draw, numbers[0])}")
            numbers[0] = f"${{n{k}}}"
        elif how == "immediate":
            numbers[1] = f"$({_disguised(draw, numbers[1])})"
        return _coeff_text(draw, name[i], name[j], normal, damping, numbers), k

    def decoy(i, j):
        return _coeff_text(draw, name[i], name[j], normal, damping, _coeff_numbers(draw, normal, damping,
                                                                                     types[i], g))

    def write(i, j, t):
        text, k = line(i, j, t)
        how = draw(st.sampled_from(["plain", "if", "string if", "jump", "loop", "quoted", "triple"]))
        if how == "if":
            flag = draw(st.integers(0, 1))
            body.append(f"variable c{k} equal {flag}")
            taken, other = (text, decoy(i, j)) if flag else (decoy(i, j), text)
            body.append(f'if "${{c{k}}} == 1 && 2 > 1" then "{taken}" else "{other}"')
        elif how == "string if":
            body.append(f"variable s{k} string yes{k}")
            body.append(f'if "${{s{k}}} != yes{k}" then "{decoy(i, j)}" elif "${{s{k}}} == yes{k}" "{text}"')
        elif how == "jump":
            body.extend([f"jump SELF skip{k}", decoy(i, j), f"label skip{k}", text])
        elif how == "loop":
            last = text.split()[5]              # the damping, the number after the stiffness
            body.extend([f"variable d{k} index {decoy(i, j).split()[5]} {last}", f"label loop{k}",
                     " ".join(text.split()[:5] + [f"${{d{k}}}"] + text.split()[6:]), f"next d{k}", f"jump SELF loop{k}"])
        elif how == "quoted":
            body.extend([text, f'print "{decoy(i, j)}"'])
        elif how == "triple":
            body.extend([text, 'print """', decoy(i, j), '"""'])
        else:
            body.append(text)

    stages = draw(st.integers(1, 3))
    for s in range(stages):
        if s:
            body.append("run 0")
            restyle = draw(st.sampled_from(["none", "other", "same"]))
            if restyle == "other":       # discards every coefficient: all are written again below
                body += ["pair_style gran/hooke 1000.0 NULL 10.0 NULL 0.5 0", "pair_coeff * *", "pair_style granular"]
            elif restyle == "same":
                body.append("pair_style granular")
        for t in types:
            write(t, t, t)
        if n > 1 and draw(st.booleans()):
            i, j = sorted(draw(st.sampled_from([(a, b) for a in types for b in types if a < b])))
            write(i, j, i)
    body.append("run 0")
    return "\n".join(head + body) + "\n", [g, 10.0 * g], \
        {t: {k: float(f"{v:.8g}") for k, v in m.items()} for t, m in types.items()}, len(head)


def check_script_deck_case(text: str, speeds: list, types: dict, nhead: int) -> list[dict]:
    """Every stage of a deck of script_deck_cases, every type pair, run head-on in LAMMPS with the
    deck's own lines up to that stage's first run (the control flow, quotes, variables and labels
    as LAMMPS itself runs them, from a file it includes: jump SELF needs one): extrapolated to
    dt = 0 within DECK_EXTRAPOLATED of the stage's eps."""
    import tempfile

    from restitution.core.errors import ParameterError
    from restitution.dem.deck import audit_deck
    from restitution.dem.pair import Pair

    case = {"deck": text, "speeds": speeds}
    try:
        res = audit_deck(text, speeds)
    except Exception as exc:  # noqa: BLE001
        ok = isinstance(exc, ParameterError) and _one_line(exc)
        return [{"method": "script deck (lammps)", "rule": "-", "status": "refused" if ok else "FAIL",
                 "ratio": 0.0, "case": case, "detail": "" if ok else "".join(traceback.format_exception_only(exc))}]
    lines = text.splitlines()
    records = []
    with tempfile.TemporaryDirectory() as tmp:
        for k, stage in enumerate(res["stages"]):
            first = stage["runs"][0]["line"]             # the deck's line number of the stage's first run
            # the engine needs no run: the earlier runs become no-ops, the stage ends before its own
            own = ["print run" if ln == "run 0" else ln for ln in lines[nhead:first - 1]]
            path = Path(tmp) / f"in.stage{k}"
            path.write_text("\n".join(own) + "\n")
            engine = _lammps_runner(f"include {path}", len(types))
            for p in stage["pairs"]:
                i, j = p["types"]
                pair = Pair.spheres(types[i]["radius"], types[j]["radius"], types[i]["density"], types[j]["density"])
                worst, detail, checked = _check_deck_row(p, pair, (i, j), engine, "lammps",
                                                         f"stage {k + 1} pair {i}-{j}")
                records.append({"method": "script deck (lammps)", "rule": p["end"], "case": case, "pair": f"{i}-{j}",
                                "status": "FAIL" if worst > 1.0 else "answered" if checked else "refused",
                                "ratio": worst, "detail": detail if worst > 1.0 else ""})
    return records


#: What a damaged deck word becomes: numbers of every class, unset variables, expressions, ranges
_DECK_DAMAGE = ("x", "", "-1", "0", "1e999", "nan", "inf", "1e-320", "2.5", "${nope}", "$(1/0)", "v_nope", "*", "1*",
                "*0", "NULL", "hertz", "tsuji", "zplane", "primitive", "mesh", "type", "all")


@st.composite
def deck_mutation_cases(draw):
    """A random LAMMPS or LIGGGHTS deck (walls included), or one written with the input language's
    constructs (script_deck_cases), with one line cut short, one word replaced, or a line repeated
    or dropped. Returns the deck text."""
    text = draw(st.sampled_from([deck_cases, liggghts_deck_cases, script_deck_cases]).flatmap(lambda f: f()))[0]
    lines = text.splitlines()
    i = draw(st.integers(0, len(lines) - 1))
    words = lines[i].split()
    how = draw(st.sampled_from(["cut", "word", "repeat", "drop"]))
    if how == "cut":
        lines[i] = " ".join(words[:draw(st.integers(1, len(words)))])
    elif how == "word":
        j = draw(st.integers(0, len(words) - 1))
        lines[i] = " ".join(words[:j] + [draw(st.sampled_from(_DECK_DAMAGE))] + words[j + 1:])
    elif how == "repeat":
        lines.insert(i, lines[i])
    else:
        del lines[i]
    return "\n".join(lines) + "\n"


def check_deck_mutation(text: str) -> dict:
    """A damaged deck is answered or refused in one line (ParameterError), never another exception."""
    from restitution.core.errors import ParameterError
    from restitution.dem.deck import audit_deck

    rec = {"method": "deck mutation", "rule": "-", "ratio": 0.0, "case": {"deck": text}}
    try:
        audit_deck(text, [0.5, 5.0])
        rec.update(status="answered", detail="")
    except ParameterError as exc:
        one = _one_line(exc)
        rec.update(status="refused" if one else "FAIL", detail="" if one else f"refusal of several lines: {exc}")
    except Exception as exc:  # noqa: BLE001
        rec.update(status="FAIL", detail="".join(traceback.format_exception_only(exc)).strip())
    return rec


def _lammps_runner(engine_lines: str, ntypes: int):
    """runs -> (relative velocity after / -g, or the exception) for runs (pair, types, g, dt, t_run),
    each in its own LAMMPS instance with the deck's own variable and pair_coeff lines."""
    from restitution.dem.engines.lammps.run import lammps_eps

    def run(runs):
        out = []
        for pair, types, g, dt, t_run in runs:
            try:
                out.append(lammps_eps(pair, engine_lines, g, dt, t_run, types, ntypes))
            except Exception as exc:  # noqa: BLE001
                out.append(exc)
        return out
    return run


def _liggghts_runner(engine_lines: str):
    """As _lammps_runner, all runs of one pair in one LIGGGHTS process (its start costs a second)."""
    from restitution.dem.engines.liggghts.run import liggghts_states

    def run(runs):
        if not runs:
            return []
        pair = runs[0][0]
        try:
            states = liggghts_states(pair, [(engine_lines, g, dt, t_run, types) for _, types, g, dt, t_run in runs])
        except Exception as exc:  # noqa: BLE001
            return [exc] * len(runs)
        return [-rel / g if gap > pair.R1 + pair.R2 else ArithmeticError("the spheres had not separated")
                for (_, _, g, _, _), (rel, gap) in zip(runs, states)]
    return run


def _check_deck_row(p: dict, pair, key: tuple, engine, code: str, name: str) -> tuple:
    """One audited contact (a type pair, or a type on a wall) in the engine at each listed speed:
    (the worst error over DECK_EXTRAPOLATED, what it was, whether anything ran). ``engine`` runs
    (pair, key, g, dt, t_run) tuples as _lammps_runner's function does."""
    from restitution.dem.contact import TIMES_OMEGA_MAX, Contact
    from restitution.dem.extrapolate import richardson

    a, c = float(Fraction(p["alpha"])), float(Fraction(p["gamma"]))
    runs, checks = [], []
    for g, listed, sticks, through in zip(p["speeds"], p["eps"], p["sticks"], p["passes_through"]):
        # not run: no eps listed (the centres would meet), or the bodies would take too many
        # steps to part (the force rule leaves them overlapping, moving apart at eps g)
        if through or (not sticks and listed < DECK_MIN_EPS[p["end"]]):
            continue
        # the undamped contact: its largest overlap bounds the damped one's, and its duration;
        # the step also resolves the damping's own time 1 / (D2 delta^gamma) (overdamped contacts)
        reach = (g * g * (a + 1.0) / (2.0 * p["D1"])) ** (1.0 / (a + 1.0))
        t_el = 2.0 * reach / g * math.sqrt(math.pi) * math.gamma(1.0 + 1.0 / (a + 1.0)) / \
            math.gamma(0.5 + 1.0 / (a + 1.0))
        fastest = min(t_el, 1.0 / (p["D2"] * reach ** c))
        if sticks:
            if DECK_STICK_TIMES * t_el / (fastest / DECK_STEPS) > DECK_MAX_STEPS:
                continue
            checks.append((g, listed, True, len(runs)))
            runs.append((pair, key, g, fastest / DECK_STEPS, DECK_STICK_TIMES * t_el))
            continue
        contact = Contact(p["alpha"], p["gamma"], p["D1"], p["D2"], p["end"])
        try:
            t_c = contact.contact_time(g)
        except Exception as exc:  # noqa: BLE001
            if not contact.omega(g) > TIMES_OMEGA_MAX:
                checks.append((g, listed, False, exc))
                continue
            # beyond the contact times' Omega the contact is all but undamped: its duration is
            # the elastic one to O(Omega^-1/2), enough to choose the steps
            t_c = t_el
        t_run = 1.2 * t_c + (2.0 * reach / (listed * g) if p["end"] == "force" else 0.0)
        # a whole number of steps per contact: where the damping force does not vanish at zero
        # overlap (gamma = 0) the last step's share of it, O(dt) and set by where the contact's
        # end falls in that step, would otherwise make eps(dt) jagged
        dt = t_c / (DECK_STEPS * math.ceil(t_c / fastest))
        if 4.0 * t_run / dt > DECK_MAX_STEPS:
            continue
        checks.append((g, listed, False, len(runs)))
        runs += [(pair, key, g, dt / m, t_run) for m in (1, 2, 4)]
    got = engine(runs)
    worst, detail = 0.0, ""
    for g, listed, sticks, at in checks:
        if isinstance(at, Exception):
            ratio, what = math.inf, f"t_c: {at}"
        elif sticks:
            eps = got[at]
            if isinstance(eps, ArithmeticError):     # still together: what the audit said
                continue
            if isinstance(eps, Exception):
                ratio, what = math.inf, f"{code}: {_engine_error(eps)}"
            else:
                ratio = eps / DECK_STICK_EPS
                what = f"the audit says they stick, {code} lets them go with eps {eps:.4g}"
        else:
            three = got[at: at + 3]
            bad = next((e for e in three if isinstance(e, Exception)), None)
            if bad is not None:
                ratio, what = math.inf, f"{code}: {_engine_error(bad)}"
            else:
                eps = richardson(*three, c)
                ratio = abs(eps - listed) / (DECK_EXTRAPOLATED * listed)
                what = f"the audit says eps {listed:.8g}, {code} {eps:.8g} at dt = 0"
        if ratio > worst:
            worst, detail = ratio, f"{name} ({p['model']}, {p['end']} rule) at {g:.4g}: {what}"
    return worst, detail, bool(checks)


def _engine_lines(text: str, code: str, wall: bool = False) -> str:
    """The deck's lines an engine run takes. LAMMPS: its variables and pair_coeff lines (the runner
    writes the pair style), for a wall also the pair style, the groups and the wall's line.
    LIGGGHTS: the box, the materials and the pair style, never the wall or its mesh (_wall_runner
    passes the deck's own wall lines apart); the particle templates only gave radii."""
    body = text.splitlines()
    if code == "lammps":
        return "\n".join(ln for ln in body if ln.startswith(("variable", "pair_", "group", "fix floor") if wall
                                                         else ("variable", "pair_coeff")))
    start = next(k for k, ln in enumerate(body) if ln.startswith("create_box"))
    return "\n".join([body[start]] + [ln for ln in body[start + 1:]
                                      if not ln.startswith(("fix pts", "fix floor", "fix mesh1", "group",
                                                            "create_atoms"))]
                     + [ln for ln in body[:start] if ln.startswith("variable")])


def _wall_runner(text: str, code: str, ntypes: int, types: dict, wall: dict):
    """As _lammps_runner for a sphere of the key's type falling onto the deck's own wall (placed at
    z = 0 as the deck writes it; _engine_lines); for LIGGGHTS on all atoms, its mesh a triangle
    scaled to the sphere (centre 2.1 radii from its nearest edge). All runs in one process unless
    one stays on the wall (then one each)."""
    from restitution.dem.engines.lammps.run import lammps_wall_eps
    from restitution.dem.engines.liggghts.run import liggghts_wall_eps_runs

    lines = _engine_lines(text, code, wall=True)
    own = [re.sub(r"^fix floor \S+", "fix floor all", ln) for ln in text.splitlines()
           if ln.startswith(("fix mesh1", "fix floor"))]

    def batch(runs):
        (t,) = runs[0][1]
        r, rho = types[t]["radius"], types[t]["density"]
        try:
            if code == "lammps":
                return [lammps_wall_eps(r, rho, lines, g, dt, t_run, atom_type=t, ntypes=ntypes)
                        for _, _, g, dt, t_run in runs]
            plate = "".join(["solid plate\nfacet normal 0 0 1\n outer loop\n",
                             *(f"  vertex {x * r!r} {y * r!r} 0\n" for x, y in ((-3, -3), (6, -3), (-3, 6))),
                             " endloop\nendfacet\nendsolid plate\n"])
            return liggghts_wall_eps_runs(r, rho, [(lines, g, dt, t_run, t, wall["wall_type"])
                                                   for _, _, g, dt, t_run in runs],
                                          wall="\n".join(own), files={"plate.stl": plate})
        except Exception as exc:  # noqa: BLE001
            return [exc]

    def run(runs):
        if code == "liggghts":       # one process for all, unless one of them stays on the wall
            got = batch(runs) if runs else []
            if len(got) == len(runs):
                return got
        return [batch([one])[0] for one in runs]
    return run


def _check_liggghts_deck(text, speeds, types):
    return check_deck_case(text, speeds, types, "liggghts")


def _engine_error(exc) -> str:
    """The engine's ERROR line of a failed run, else the exception's first line."""
    lines = str(exc).splitlines()
    return next((ln.strip() for ln in lines if "ERROR" in ln), lines[0] if lines else repr(exc))


def _with_exact_line(text: str, line: str, code: str) -> str:
    """The deck with a pair's exact line in force: a later pair_coeff (LAMMPS), or the
    coefficientRestitution fix replaced (LIGGGHTS)."""
    if code == "lammps":
        return text + line + "\n"
    return "\n".join(line if "coefficientRestitution" in ln else ln for ln in text.splitlines()) + "\n"


def check_deck_case(text: str, speeds: list, types: dict, code: str = "lammps", exact: tuple | None = None) -> list[dict]:
    """Every type pair of the deck in the real engine (LAMMPS or LIGGGHTS), head-on at both speeds,
    with the deck's own contact lines: where the audit gives eps, the engine extrapolated to dt = 0
    must agree to DECK_EXTRAPOLATED; where it says the spheres stick, the engine must keep them
    together (or let them go with eps below DECK_STICK_EPS). Where the audit writes a pair's exact
    line (the e that gives eps = the e typed, at the middle speed), the deck with that line is
    checked the same way for that pair alone (``exact``: the pair and the eps it must give): the
    audit must now say eps = e, and the engine agree. Every type on the deck's wall likewise, a
    sphere of that type falling onto the deck's own wall line, and its exact line (``exact`` =
    ("wall", type, e)) the same way."""
    from restitution.core.errors import ParameterError
    from restitution.dem.deck import audit_deck
    from restitution.dem.pair import Pair

    case = {"deck": text, "speeds": speeds}
    lines = _engine_lines(text, code)
    engine = _lammps_runner(lines, len(types)) if code == "lammps" else _liggghts_runner(lines)
    try:
        res = audit_deck(text, speeds)
    except Exception as exc:  # noqa: BLE001
        ok = isinstance(exc, ParameterError) and _one_line(exc)
        detail = "" if ok else "".join(traceback.format_exception_only(exc)).strip()
        if ok and "stops" in str(exc):
            # the engine's own limits: it must refuse the deck too, with a sphere of each type present
            # (LIGGGHTS checks a type's material only when it has atoms)
            ran = engine([(Pair.spheres(types[1]["radius"], types[t]["radius"], types[1]["density"],
                                        types[t]["density"]), (1, t), 1.0, 1e-9, 1e-8) for t in types])
            if not any(isinstance(r, RuntimeError) for r in ran):
                ok, detail = False, f"the audit says {exc}, but {code} runs the deck"
        return [{"method": f"deck ({code})", "rule": "-", "status": "refused" if ok else "FAIL", "ratio": 0.0,
                 "case": case, "detail": detail}]
    records = []
    for p in res["pairs"]:
        i, j = p["types"]
        if exact is not None and (i, j) != exact[:2]:
            continue
        rec = {"method": f"deck ({code})" + (": exact line" if exact else ""), "rule": p["end"], "case": case,
               "pair": f"{i}-{j}", "ratio": 0.0}
        pair = Pair.spheres(types[i]["radius"], types[j]["radius"], types[i]["density"], types[j]["density"])
        worst, detail, checked = _check_deck_row(p, pair, (i, j), engine, code, f"pair {i}-{j}")
        if exact is not None and p["eps"][0] is not None and abs(p["eps"][0] - exact[2]) > 1e-8:
            worst, detail = math.inf, (f"pair {i}-{j}: with its exact line the audit says eps {p['eps'][0]:.10g}, "
                                       f"not the e typed {exact[2]:.10g}")
        # "refused": nothing of this pair could be run (no eps, or too many steps)
        status = "FAIL" if worst > 1.0 else "answered" if checked or exact is not None else "refused"
        records.append({**rec, "status": status, "ratio": worst, "detail": detail if worst > 1.0 else ""})
        if exact is None and p["exact_line"]:
            middle = p["speeds"][len(p["speeds"]) // 2]
            records += check_deck_case(_with_exact_line(text, p["exact_line"], code), [middle], types, code,
                                       (i, j, p["typed_e"]))
    for w in res["walls"]:
        (t,) = w["types"]
        if exact is not None and exact[:2] != ("wall", t):
            continue
        worst, detail, checked = _check_deck_row(w, Pair.wall(types[t]["radius"], types[t]["density"]), (t,),
                                                 _wall_runner(text, code, len(types), types, w), code,
                                                 f"type {t} on wall {w['wall']}")
        if exact is not None and w["eps"][0] is not None and abs(w["eps"][0] - exact[2]) > 1e-8:
            worst, detail = math.inf, (f"type {t} on wall {w['wall']}: with its exact line the audit says eps "
                                       f"{w['eps'][0]:.10g}, not the e typed {exact[2]:.10g}")
        records.append({"method": f"deck ({code}): wall" + (": exact line" if exact else ""), "rule": w["end"],
                        "case": case, "pair": f"{t}-wall", "ratio": worst, "detail": detail if worst > 1.0 else "",
                        "status": "FAIL" if worst > 1.0 else "answered" if checked or exact else "refused"})
        if exact is None and w["exact_line"]:
            # LAMMPS: the wall's own line replaced (the deck's wall is the line starting "fix floor");
            # LIGGGHTS: the coefficientRestitution line, as for a pair
            fixed = ("\n".join(w["exact_line"] if ln.startswith("fix floor") else ln for ln in text.splitlines())
                     + "\n" if code == "lammps" else _with_exact_line(text, w["exact_line"], code))
            records += check_deck_case(fixed, [w["speeds"][len(w["speeds"]) // 2]], types, code,
                                       ("wall", t, w["typed_e"]))
    return records


# ------------------------------------------------------------------------------------ the long run
def _collect(strategy, check, n: int, seed: int, unpack: bool) -> list[dict]:
    """Draw n cases from ``strategy`` (generation only, no shrinking) and check each."""
    from hypothesis import HealthCheck, Phase, given, settings
    from hypothesis import seed as hseed

    records: list[dict] = []

    @hseed(seed)
    @settings(max_examples=n, deadline=None, database=None, phases=[Phase.generate],
              suppress_health_check=list(HealthCheck))
    @given(strategy)
    def run(case):
        t0 = time.perf_counter()
        got = check(*case) if unpack else check(case)
        for rec in got if isinstance(got, list) else [got]:
            rec.setdefault("seconds", time.perf_counter() - t0)
            records.append(rec)

    run()
    return records


#: kind of case -> (its strategy, its check, whether a case is the check's argument tuple)
KINDS = {"numbers": (number_cases, check_number_case, False), "argv": (argv_cases, check_argv_case, True),
         "config": (config_cases, check_config_case, True), "scenes": (scene_cases, check_scene_case, False),
         "decks": (deck_cases, check_deck_case, True),
         "liggghts scenes": (liggghts_scene_cases, check_liggghts_scene_case, False),
         "liggghts decks": (liggghts_deck_cases, _check_liggghts_deck, True),
         "deep overlap": (deep_overlap_cases, check_deep_overlap_case, False),
         "deck mutations": (deck_mutation_cases, check_deck_mutation, False),
         "script decks": (script_deck_cases, check_script_deck_case, True)}


def _worker(job):
    kind, n, seed = job
    os.environ.setdefault("PYTHONHASHSEED", "0")
    strategy, check, unpack = KINDS[kind]
    return kind, _collect(strategy(), check, n, seed, unpack)


def table(records: list[dict], seconds: float) -> list[dict]:
    rows: dict = {}
    for rec in records:
        key = (rec["method"].split(":")[0] if rec["method"].startswith("ladder") else rec["method"], rec["rule"])
        if rec["method"].startswith("ladder:"):
            key = ("ladder (chosen: " + rec["method"].split(":", 1)[1] + ")", rec["rule"])
        row = rows.setdefault(key, {"method": key[0], "rule": key[1], "cases": 0, "answered": 0, "refused": 0,
                                    "failures": 0, "worst_error_over_bound": 0.0, "seconds": 0.0})
        row["cases"] += 1
        row["seconds"] += rec.get("seconds", 0.0)
        if rec["status"] == "FAIL":
            row["failures"] += 1
        elif rec["status"] == "refused":
            row["refused"] += 1
        else:
            row["answered"] += 1
        if rec["status"] != "refused" and math.isfinite(rec.get("ratio", 0.0)):
            row["worst_error_over_bound"] = max(row["worst_error_over_bound"], rec.get("ratio", 0.0))
    out = sorted(rows.values(), key=lambda r: (r["method"], r["rule"]))
    return out


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description="the long fuzz profile of issue 28")
    p.add_argument("--numbers", type=int, default=1100, help="drawn; a few coincide (1,100 gave over 1,000 distinct)")
    p.add_argument("--inputs", type=int, default=20000, help="argument vectors and config mutations together")
    p.add_argument("--scenes", type=int, default=40, help="random LAMMPS scenes, and as many LIGGGHTS scenes "
                                                          "(each skipped without its engine)")
    p.add_argument("--decks", type=int, default=40, help="random LAMMPS decks, as many written with if/jump/label, "
                                                         "quotes, restyles, stages, labels and formulas, and as "
                                                         "many LIGGGHTS decks (each skipped without its engine)")
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    p.add_argument("--seed", type=int, default=28)
    p.add_argument("--out", default="results/fuzz")
    args = p.parse_args(argv)
    from multiprocessing import get_context

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    chunks = max(1, args.jobs) * 4
    n_cfg = args.inputs // 10   # config checks cost ten times an argument vector
    jobs = ([("numbers", -(-args.numbers // chunks), args.seed + i) for i in range(chunks)]
            + [("argv", -(-(args.inputs - n_cfg) // chunks), args.seed + 100 + i) for i in range(chunks)]
            + [("config", -(-n_cfg // chunks), args.seed + 200 + i) for i in range(chunks)]
            + [("deep overlap", -(-args.numbers // 10 // chunks), args.seed + 700 + i) for i in range(chunks)]
            + [("deck mutations", -(-args.inputs // 20 // chunks), args.seed + 800 + i) for i in range(chunks)])
    from restitution.dem.engines.lammps.run import available
    if available():
        jobs += [("scenes", -(-args.scenes // chunks), args.seed + 300 + i) for i in range(chunks)]
        jobs += [("decks", -(-args.decks // chunks), args.seed + 400 + i) for i in range(chunks)]
        jobs += [("script decks", -(-args.decks // chunks), args.seed + 900 + i) for i in range(chunks)]
    else:
        print("fuzz: LAMMPS not installed (pip install -e '.[dem]'): no scenes, no decks", file=sys.stderr)
    from restitution.dem.engines.liggghts.run import available as liggghts_available
    if liggghts_available():
        jobs += [("liggghts decks", -(-args.decks // chunks), args.seed + 500 + i) for i in range(chunks)]
        jobs += [("liggghts scenes", -(-args.scenes // chunks), args.seed + 600 + i) for i in range(chunks)]
    else:
        print("fuzz: LIGGGHTS not installed (as root: apt-get install liggghts): no LIGGGHTS decks or scenes",
              file=sys.stderr)
    jobs = [job for job in jobs if job[1] > 0]     # e.g. --numbers 0, or too few for every chunk
    t0 = time.time()
    records: list[dict] = []
    counts = dict.fromkeys(KINDS, 0)
    with get_context("spawn").Pool(args.jobs, maxtasksperchild=1) as pool:
        for kind, recs in pool.imap_unordered(_worker, jobs):
            records += recs
            counts[kind] += len({json.dumps(r.get("case", r.get("argv", r.get("config"))), sort_keys=True, default=str)
                                 for r in recs}) if kind != "argv" and kind != "config" else len(recs)
            print(f"fuzz: {kind} chunk done ({len(recs)} records, {time.time() - t0:.0f} s)", file=sys.stderr,
                  flush=True)
    seconds = time.time() - t0
    rows = table(records, seconds)
    failures = [r for r in records if r["status"] == "FAIL"]
    header = ["method", "rule", "cases", "answered", "refused", "failures", "worst_error_over_bound",
              "seconds"]
    lines = [",".join(header)] + [",".join(f"{r[h]:.3g}" if isinstance(r[h], float) else str(r[h]) for h in header)
                                  for r in rows]
    (out / "table.csv").write_text("\n".join(lines) + "\n")
    (out / "failures.json").write_text(json.dumps(failures, indent=1, default=str) + "\n")
    summary = (f"number cases {counts['numbers']}, deep overlap cases {counts['deep overlap']}, argument vectors {counts['argv']}, config mutations "
               f"{counts['config']}, deck mutations {counts['deck mutations']}, LAMMPS scenes {counts['scenes']}, LAMMPS decks {counts['decks']}, LAMMPS script decks {counts['script decks']}, LIGGGHTS decks {counts['liggghts decks']}, LIGGGHTS scenes {counts['liggghts scenes']}, failures {len(failures)}, wall time "
               f"{seconds:.0f} s on {args.jobs} processes")
    (out / "summary.txt").write_text(summary + "\n")
    print("\n".join(lines))
    print(summary)
    return 1 if any(r["status"] == "FAIL" for r in records) else 0


if __name__ == "__main__":
    sys.exit(main())

"""The fuzz's number cases (issue 28): an accepted exponent pair, an end rule, Omega and a tolerance;
every answer -- the default ladder's, each forced rung's and ``collide``'s, 1 - eps included -- must lie
within its stated relative bound of the mpmath reference, or be refused in one line. Below the
reference's reach, the deep overlap cases check the overlap rule against its scaling law."""

from __future__ import annotations

import functools
import math
import time
import traceback
from fractions import Fraction

import numpy as np
from hypothesis import strategies as st

from fuzz_outcome import one_line
from restitution.core.problem import Problem

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
            collide(Problem.of(case["alpha"], case["gamma"], "overlap"), case["omega"], rtol=1e-8)
        except StickError:
            return "stick", None, 0.0, 0.0
        except Exception:  # noqa: BLE001 - judged below, by the reference
            pass
    r = reference_collision(Problem.of(case["alpha"], case["gamma"], case["end"]), case["omega"], digits=REF_DIGITS)
    if 0 < 1 - r.eps < 1e-3:
        # 1 - eps has only REF_DIGITS + log10(1 - eps) correct digits: carry that many more
        extra = int(-math.log10(float(1 - r.eps))) + 1
        r = reference_collision(Problem.of(case["alpha"], case["gamma"], case["end"]), case["omega"], digits=REF_DIGITS + extra)
    one_minus = 1 - r.eps
    err = float(r.error_estimate)
    return r.eps, one_minus, err, (err * float(r.eps / one_minus) if one_minus > 0 else math.inf)


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
            if not one_line(exc):
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
                 or (method == "uniform" and pair in COMMON_PAIRS[:2]))
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
#: A request that takes more CPU seconds than this is a creep no rung should follow (CPU time, not
#: wall time: a fresh clone's suite under a loaded machine's nice took 65.6 s of wall time on one case)
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
    t0 = time.process_time()
    try:
        got = api.epsilon(alpha=case["alpha"], gamma=case["gamma"], omega=[case["omega"]], tol=case["tol"],
                          end="overlap", build=False)
    except StickError as exc:
        ok = a >= 2 * g + 1 and one_line(exc)
        return [{**rec, "status": "answered" if ok else "FAIL", "detail": f"sticks: {exc}"}]
    except ParameterError as exc:
        return [{**rec, "status": "refused" if one_line(exc) and a < 2 * g + 1 else "FAIL", "detail": str(exc)}]
    except Exception as exc:  # noqa: BLE001 - a traceback is a failure
        return [{**rec, "status": "FAIL", "detail": "".join(traceback.format_exception_only(exc)).strip()}]
    seconds = time.process_time() - t0
    rec["method"] = "ladder:" + got.method
    eps, bound = float(got.eps[0]), float(got.error_bound)
    if a >= 2 * g + 1:
        return [{**rec, "status": "FAIL", "ratio": math.inf, "detail": f"eps = {eps!r} where the bodies provably stick"}]
    try:
        anchor = collide(Problem.of(case["alpha"], case["gamma"], "overlap"), DEEP_ANCHOR, rtol=1e-11)
    except ParameterError as exc:   # the anchor is out of the reference's reach: nothing to compare
        return [{**rec, "status": "answered", "detail": f"eps = {eps!r}; no anchor ({exc})"}]
    truth = anchor.eps * (case["omega"] / DEEP_ANCHOR) ** overlap_limit((a, g)).k
    err = abs(eps / truth - 1.0)
    allowed = bound + anchor.error_bound + 1e-13 * abs(math.log(case["omega"] / DEEP_ANCHOR))
    ok = err <= allowed and seconds <= DEEP_SECONDS
    return [{**rec, "status": "answered" if ok else "FAIL", "ratio": err / allowed, "error": err,
             "detail": f"eps = {eps!r}, anchor-scaled {truth!r}, relative error {err:.3g}, allowed {allowed:.3g}, "
                       f"{seconds:.1f} s"}]


# ------------------------------------------------------------------------------ straddling arrays
#: Omega windows on both sides of the rungs' domain edges (the overlap law's 1e-8, the compiled
#: integrator's and the mpmath rung's 1e-5 under the overlap rule, the expansions' 1e-3 and 1e2, the
#: overlap curve's 1e-4 and 1e8, the uniform forms' 1e-8 and 1e8), each cheap for the rungs that
#: serve it without a build (no creeping return below 1e-5 under the overlap rule except the law's).
STRADDLE_WINDOWS = ((-12.0, -8.5), (-4.9, -3.5), (-3.5, -1.0), (-1.0, 2.0), (2.0, 7.0), (7.0, 12.0))
#: Kim's pair, Hertz with viscoelastic damping, a pair that sticks under the overlap rule, one more.
STRADDLE_PAIRS = (("3/2", "1"), ("3/2", "1/2"), ("5/2", "1/2"), ("5/2", "3/2"))


@st.composite
def straddling_cases(draw):
    alpha, gamma = draw(st.sampled_from(STRADDLE_PAIRS))
    end = draw(st.sampled_from(["force", "overlap"]))
    windows = draw(st.lists(st.sampled_from(STRADDLE_WINDOWS), min_size=2, max_size=4, unique=True))
    log_omegas = [draw(st.floats(*w)) for w in windows for _ in range(draw(st.integers(1, 4)))]
    order = draw(st.permutations(range(len(log_omegas))))
    return {"alpha": alpha, "gamma": gamma, "end": end, "omegas": [10.0 ** log_omegas[i] for i in order],
            "tol": 10.0 ** draw(st.floats(-12.0, -4.0))}


def check_straddling_case(case) -> list[dict]:
    """An array across rung domains: each part answered as epsilon answers its points alone (bit for
    bit, by the same rung), every point within tol, the counts adding up; or one one-line refusal.
    The rule's master curve is built first (seconds, cached), so that its rung and the expansions
    take parts too; a few points make no build pay, so nothing else is built."""
    from restitution import api
    from restitution.core.errors import ParameterError

    rec = {"method": "ladder (array)", "rule": case["end"], "case": case, "ratio": 0.0}
    common = dict(alpha=case["alpha"], gamma=case["gamma"], tol=case["tol"], end=case["end"])
    om = np.array(case["omegas"])
    try:
        api.epsilon(alpha=case["alpha"], gamma=case["gamma"], omega=[1e6], end=case["end"], method="master",
                    build=True, tol=None)
        got = api.epsilon(omega=om, **common)
    except ParameterError as exc:
        return [{**rec, "status": "refused" if one_line(exc) else "FAIL", "detail": str(exc)}]
    except Exception as exc:  # noqa: BLE001 - a traceback is a failure
        return [{**rec, "status": "FAIL", "detail": "".join(traceback.format_exception_only(exc)).strip()}]
    problems = []
    if sum(got.methods.values()) != om.size:
        problems.append(f"counts {got.methods} for {om.size} points")
    if not (got.error_bound <= case["tol"] and np.all(got.bounds <= case["tol"])):
        problems.append(f"bound {got.error_bound:.3g} above tol {case['tol']:.3g}")
    for part in got.parts:
        where = (om >= part.omega_min) & (om <= part.omega_max)
        alone = api.epsilon(omega=om[where], **common)
        if alone.method != part.method or not np.array_equal(alone.eps, got.eps[where]):
            problems.append(f"{part.method} on {part.count} point(s) in {part.omega_min:.3g}..{part.omega_max:.3g}: "
                            f"alone {alone.method}, eps equal: {np.array_equal(alone.eps, got.eps[where])}")
    return [{**rec, "method": "ladder (array): " + got.method, "status": "FAIL" if problems else "answered",
             "ratio": got.error_bound / case["tol"], "detail": "; ".join(problems) or f"{got.methods}"}]

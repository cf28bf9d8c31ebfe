"""The stability atlas's invariants (the checks listed in :mod:`restitution.audit.stability`), its
per-pair summary, and the agreement of the atlas with the small- and large-Omega limits.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from typing import Iterable

from .stability import QUANTITIES, rel_error

__all__ = ["Violation", "check_invariants", "summarize", "limit_agreement"]


# ------------------------------------------------------------------------------------------ checks
@dataclass(frozen=True)
class Violation:
    """One failed invariant at one point: ``value`` against ``limit`` (see the module docstring)."""

    check: str
    alpha: str
    gamma: str
    omega: float
    value: float
    limit: float
    detail: str = ""

    def __str__(self) -> str:
        return (f"{self.check} at alpha={self.alpha}, gamma={self.gamma}, Omega={self.omega:.6g}: "
                f"{self.detail or f'{self.value:.3g} vs {self.limit:.3g}'}")

    def as_dict(self) -> dict:
        return dict(self.__dict__)


def _by_pair(records: Iterable[dict]) -> dict[tuple[str, str], list[dict]]:
    groups: dict[tuple[str, str], list[dict]] = {}
    for r in records:
        groups.setdefault((str(r["alpha"]), str(r["gamma"])), []).append(r)
    for rows in groups.values():
        rows.sort(key=lambda r: float(r["omega"]))
    return groups


def _nan(x) -> bool:
    try:
        return math.isnan(float(x))
    except (TypeError, ValueError):
        return True


def _accuracy(accuracy, a: str, g: str) -> float:
    return float(accuracy(a, g)) if callable(accuracy) else float(accuracy)


def check_invariants(records: Iterable[dict], accuracy) -> tuple[list[Violation], dict]:
    """All violations of the invariants, and per-pair counts of unresolved monotonicity steps.

    ``records`` may come from run_atlas or from the atlas CSV (values as read by pandas or csv:
    numbers may be strings); ``accuracy`` is the stated relative accuracy, or a function of the
    pair (alpha, gamma) giving it (AtlasSpec.accuracy_for). Returns (violations, {(alpha, gamma):
    unresolved steps}).
    """
    out: list[Violation] = []
    unresolved: dict[tuple[str, str], int] = {}
    for (a, g), rows in _by_pair(records).items():
        fa, fg = Fraction(a), Fraction(g)
        pair_accuracy = _accuracy(accuracy, a, g)
        expected_end = "force" if fa > fg else "separation"
        prev = None
        unresolved[(a, g)] = 0
        for r in rows:
            w = float(r["omega"])
            vals = {q: float(r[q]) for q in QUANTITIES}

            def bad(check, value, limit, detail=""):
                out.append(Violation(check, a, g, w, float(value), float(limit), detail))

            if str(r.get("status", "ok")) not in ("ok", "", "nan"):
                bad("finite", math.nan, 0.0, f"run failed: {r['status']}")
                prev = None
                continue
            nonfinite = [q for q, v in vals.items() if not math.isfinite(v)]
            if nonfinite:
                bad("finite", vals[nonfinite[0]], 0.0, f"{nonfinite[0]} = {vals[nonfinite[0]]!r}")
                prev = None
                continue
            eps = vals["eps"]
            if not 0.0 < eps < 1.0:
                bad("eps_range", eps, 1.0, f"eps = {eps!r} outside (0, 1)")
            if not 0.0 < vals["tau_b"] < vals["tau_c"]:
                bad("order", vals["tau_b"], vals["tau_c"], f"tau_b = {vals['tau_b']!r}, tau_c = {vals['tau_c']!r}")
            if not 0.0 <= vals["x_c"] < vals["x_b"]:
                bad("order", vals["x_c"], vals["x_b"], f"x_c = {vals['x_c']!r}, x_b = {vals['x_b']!r}")
            if r["ended_by"] == "force" and not vals["x_c"] > 0.0:
                bad("x_c", vals["x_c"], 0.0, f"force end with x_c = {vals['x_c']!r}")
            if r["ended_by"] != expected_end:
                bad("ended_by", math.nan, math.nan, f"ended by {r['ended_by']}, expected {expected_end}")
            if prev is not None:
                step = eps - prev
                allowance = 2.0 * pair_accuracy * max(eps, prev)
                if step <= 0.0:
                    if step < -allowance:
                        bad("monotone", step, -allowance,
                            f"eps falls by {-step:.3g} from Omega={prev_w:.6g} (more than {allowance:.3g})")
                    else:
                        unresolved[(a, g)] += 1
            prev, prev_w = eps, w
            for check, col, worst in (("tight", "err_tight", "worst_tight"), ("reference", "err_ref", "worst_ref"),
                                      ("exact", "err_exact", "worst_exact")):
                if not _nan(r.get(col)) and not float(r[col]) <= pair_accuracy:
                    bad(check, float(r[col]), pair_accuracy,
                        f"{r.get(worst) or 'a quantity'} off by {float(r[col]):.3g} (stated accuracy {pair_accuracy:.3g})")
    return out, unresolved


# ------------------------------------------------------------------------------------------ summary
def _max_at(rows: list[dict], col: str) -> tuple[float, float]:
    """(largest finite-or-inf value of col, Omega where it occurs); (nan, nan) if never computed."""
    vals = [(float(r[col]), float(r["omega"])) for r in rows if not _nan(r.get(col))]
    if not vals:
        return math.nan, math.nan
    return max(vals, key=lambda t: t[0])


def summarize(records: Iterable[dict], accuracy) -> list[dict]:
    """One row per exponent pair: extent of the quantities, worst errors and invariant counts."""
    records = list(records)
    violations, unresolved = check_invariants(records, accuracy)
    rows = []
    for (a, g), rs in _by_pair(records).items():
        ok = [r for r in rs if str(r.get("status", "ok")) in ("ok", "", "nan")]
        ends = sorted({r["ended_by"] for r in ok})
        eps = [float(r["eps"]) for r in ok]
        xc = [float(r["x_c"]) for r in ok if r["ended_by"] == "force"]
        row = {
            "alpha": a, "gamma": g, "accuracy": _accuracy(accuracy, a, g), "points": len(rs), "failed": len(rs) - len(ok),
            "ended_by": "/".join(ends),
            "eps_min": min(eps) if eps else math.nan, "eps_max": max(eps) if eps else math.nan,
            "one_minus_eps_min": 1.0 - max(eps) if eps else math.nan,
            "tau_c_max": max((float(r["tau_c"]) for r in ok), default=math.nan),
            "x_c_min": min(xc) if xc else math.nan,
        }
        for name, col in (("tight", "err_tight"), ("ref", "err_ref"), ("exact", "err_exact")):
            err, at = _max_at(rs, col)
            row[f"n_{name}"] = sum(1 for r in rs if not _nan(r.get(col)))
            row[f"max_err_{name}"] = err
            row[f"omega_max_err_{name}"] = at
        row["max_tight_ref"] = _max_at(rs, "tight_ref")[0]
        row["max_ref_estimate"] = _max_at(rs, "ref_estimate")[0]
        row["unresolved_steps"] = unresolved.get((a, g), 0)
        row["violations"] = sum(1 for v in violations if (v.alpha, v.gamma) == (a, g))
        row["violated"] = ",".join(sorted({v.check for v in violations if (v.alpha, v.gamma) == (a, g)}))
        rows.append(row)
    return rows


# ------------------------------------------------------------------------------------------ limits
def limit_agreement(records: Iterable[dict]) -> list[dict]:
    """How the atlas meets the limits of ``restitution.core.asymptotics`` at its two ends, per pair.

    At the smallest Omega: eps against the viscous expansion (with its first correction where it has
    one) and, for alpha > gamma, tau_c against (2 ln(1/Omega) + L) / lambda. At the largest Omega:
    1 - eps against 1 - (1 - C1 delta + C2 delta^2 + ...) and tau_c against T0 Omega^(-1/(alpha+1)).
    Relative deviations; they contain both the truncation of the expansion and the atlas's own
    error (1 - eps loses the digits that eps has near 1). Empty if asymptotics is not available.
    """
    try:
        from ..core import asymptotics as asy
    except ImportError:  # pragma: no cover - built by another stage
        return []
    out = []
    for (a, g), rows in _by_pair(records).items():
        ok = [r for r in rows if str(r.get("status", "ok")) in ("ok", "", "nan")]
        if not ok:
            continue
        lo, hi = ok[0], ok[-1]
        vl, el = asy.viscous_limit((a, g)), asy.elastic_limit((a, g))
        w_lo, w_hi = float(lo["omega"]), float(hi["omega"])
        eps_v = float(vl.eps(w_lo, order=1))
        tc_v = float(vl.tau_c(w_lo)) if vl.kind == "force" else math.nan
        one_minus_el = 1.0 - float(el.eps(w_hi, order=2))
        tc_e = float(el.tau_c(w_hi))
        out.append({
            "alpha": a, "gamma": g, "viscous_kind": vl.kind,
            "omega_lo": w_lo, "eps_lo": float(lo["eps"]), "eps_viscous": eps_v,
            "dev_eps_viscous": rel_error(float(lo["eps"]), eps_v),
            "tau_c_lo": float(lo["tau_c"]), "tau_c_viscous": tc_v,
            "dev_tau_c_viscous": rel_error(float(lo["tau_c"]), tc_v) if math.isfinite(tc_v) else math.nan,
            "omega_hi": w_hi, "one_minus_eps_hi": 1.0 - float(hi["eps"]), "one_minus_eps_elastic": one_minus_el,
            "dev_one_minus_eps_elastic": rel_error(1.0 - float(hi["eps"]), one_minus_el),
            "tau_c_hi": float(hi["tau_c"]), "tau_c_elastic": tc_e,
            "dev_tau_c_elastic": rel_error(float(hi["tau_c"]), tc_e),
        })
    return out

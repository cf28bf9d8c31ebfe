# %% [markdown]
# # Every number the manuscript prints
#
# Collected from the stage outputs (reference integrations, series, accuracy study, relations)
# and written twice: values.tex with one \newcommand per number (the manuscript \input's it,
# so no number is typed by hand) and values.json with the raw values, their kind and the
# tolerance `make check` allows.

# %%
if "snakemake" not in globals():  # opened as a notebook: replay the pipeline's last run
    import pathlib, sys  # noqa: E401
    here = next(p for p in (pathlib.Path.cwd(), *pathlib.Path.cwd().parents) if (p / "Snakefile").exists())
    sys.path.insert(0, str(here / "workflow" / "scripts"))
    from _pipeline import replay
    snakemake = replay("values")

import math  # noqa: E402
import re  # noqa: E402
from fractions import Fraction  # noqa: E402

import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from _pipeline import read_json, start, write_json, write_text  # noqa: E402

from restitution import damped, printed  # noqa: E402
from restitution.model import Material  # noqa: E402
from restitution.series import perturbation_series  # noqa: E402

start(snakemake)

#: make check tolerances (relative) by where a number comes from.
TOLERANCE = {"exact": 0.0, "formula": 1e-12, "integration": 1e-6, "config": 0.0, "paper": 0.0}
WORDS = ["Zero", "One", "Two", "Three", "Four", "Five", "Six", "Seven", "Eight"]


def sci(x: float, sig: int = 4) -> str:
    """x with `sig` significant digits; scientific as a\\times10^{b} outside [1e-3, 1e5)."""
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "---"
    if x == 0:
        return "0"
    mant, exp = f"{x:.{sig - 1}e}".split("e")
    e = int(exp)
    if -3 <= e < 5:
        return f"{x:.{max(sig - 1 - e, 0)}f}"
    return rf"\ensuremath{{{mant}\times 10^{{{e}}}}}"


def frac_tex(q: Fraction) -> str:
    if q.denominator == 1:
        return rf"\ensuremath{{{q.numerator}}}"
    sign = "-" if q < 0 else ""
    return rf"\ensuremath{{{sign}{abs(q.numerator)}/{q.denominator}}}"


class Values:
    """Name -> (raw value, LaTeX text, kind, note)."""

    def __init__(self):
        self.items: dict[str, dict] = {}

    def add(self, name, value, tex=None, *, kind="integration", sig=4, note=""):
        if not re.fullmatch(r"[A-Za-z]+", name):
            raise ValueError(f"LaTeX macro names are letters only: {name!r}")
        if name in self.items:
            raise ValueError(f"duplicate value {name!r}")
        if tex is None:
            if isinstance(value, Fraction):
                tex = frac_tex(value)
            elif isinstance(value, bool):
                tex = "yes" if value else "no"
            elif isinstance(value, int):
                tex = str(value)
            elif isinstance(value, float):
                tex = sci(value, sig)
            else:
                tex = str(value)
        raw = str(value) if isinstance(value, Fraction) else value
        if isinstance(raw, float) and not math.isfinite(raw):
            raw = None
        self.items[name] = {"value": raw, "tex": tex, "kind": kind,
                            "tolerance": TOLERANCE[kind], "note": note}

    def verdict(self, name, ok: bool, note=""):
        self.add(name, "reproduced" if ok else "not reproduced", kind="exact", note=note)


def first_departure(tau, x_series, x_ref, tol):
    """First tau where the series is off the reference by more than tol (None if never)."""
    off = np.abs(np.asarray(x_series) - np.asarray(x_ref)) > tol
    return float(tau[np.argmax(off)]) if off.any() else None


# %% Inputs
p = snakemake.params
V = Values()
summary = read_json(snakemake.input.summary)
fwd = pd.read_csv(snakemake.input.forward)
inv = pd.read_csv(snakemake.input.inverse)
curve = pd.read_csv(snakemake.input.curve)
acc = pd.read_csv(snakemake.input.accuracy)
agreement = read_json(snakemake.input.agreement)
relations = {r["kind"]: r for r in (read_json(f) for f in snakemake.input.relations)}
mat = Material(p.exponents["alpha"], p.exponents["gamma"], p.D1, p.D2)
ex = mat.exponents
g = summary["g"]
omega = summary["omega"]
eps = summary["eps"]
e_omega = float(ex.omega_exponent)

# %% Model and scaling
V.add("ExpAlpha", ex.alpha, kind="config")
V.add("ExpGamma", ex.gamma, kind="config")
V.add("ExpP", ex.p, kind="exact", note="common denominator of alpha and gamma")
V.add("DOne", p.D1, tex=f"{p.D1:g}", kind="config")
V.add("DTwo", p.D2, tex=f"{p.D2:g}", kind="config")
V.add("Dstar", mat.d_star, kind="formula", note="D* = D1 / D2^((alpha-1)/gamma)")
V.add("Regime", mat.regime or "undefined", kind="exact")
V.add("GFig", g, tex=f"{g:g}", kind="config")
V.add("OmegaExponent", ex.omega_exponent, kind="exact", note="Omega proportional to g^this")
# When alpha - 1 - 2 gamma = 0, Omega does not depend on g, Omega~ = Omega and eps is g-independent.
V.add("EpsExponent", 1 / ex.omega_exponent if ex.omega_exponent else None, kind="exact",
      note="eps = (Omega~/Omega)^this for the paper's relation")
V.add("OmegaAtG", omega, kind="formula")
V.add("LengthScaleAtG", summary["length_scale"], kind="formula", note="A, xi = A x")
V.add("TimeScaleAtG", summary["time_scale"], kind="formula", note="B, t = B tau")

# %% Reference collision at g_figure
V.add("EpsAtG", eps)
V.add("TauBAtG", summary["tau_b"])
V.add("XBAtG", summary["x_b"])
V.add("TauCAtG", summary["tau_c"])
V.add("XCAtG", summary["x_c"])
V.add("EndAtG", summary["end"], kind="exact", note="force: contact ends where the force vanishes")
V.add("TimeBAtG", summary["tau_b"] * summary["time_scale"], note="t_b = B tau_b (physical)")
V.add("XiBAtG", summary["x_b"] * summary["length_scale"], note="xi_b = A x_b (physical)")
V.add("OmegaTildeAtG", summary["inverse"]["omega_tilde"])
V.add("XTildeCAtG", summary["inverse"]["x_tilde_c"])
V.add("TauTildeBAtG", summary["inverse"]["tau_tilde_b"])
V.add("TauTildeEndAtG", summary["inverse"]["tau_tilde_end"])
V.add("RTol", p.rtol, tex=sci(p.rtol, 1), kind="config")

# %% Where each truncation of the series stops tracking the reference
tol = p.track_tolerance
V.add("TrackTol", tol, tex=f"{tol:g}", kind="config")
V.add("SeriesOmegaOrder", p.omega_order, kind="config")
V.add("SeriesMaxPower", Fraction(p.max_power), kind="config")
s_fwd = perturbation_series(ex.alpha, ex.gamma, omega_order=p.omega_order, max_power=p.max_power,
                            direction="forward")
s_inv = perturbation_series(ex.alpha, ex.gamma, omega_order=p.omega_order, max_power=p.max_power,
                            direction="inverse")
tau = fwd["tau"].to_numpy()
for n in range(p.omega_order + 1):
    t_off = first_departure(tau, s_fwd.evaluate(tau, omega, order=n), fwd["x"], tol)
    V.add(f"FwdTrack{WORDS[n]}", t_off, note=f"forward, series to Omega^{n}: first tau off by > tol")
# The inverse series start at x~(0) = 0; the physical inverse run starts at x~_c. Compared with
# the latter they are off from the start whenever x~_c > tol, so report both.
omega_t = summary["inverse"]["omega_tilde"]
tau_t = inv["tau_tilde"].to_numpy()
t_scale = eps ** (float(ex.gamma) / float(ex.gamma + 1))
for n in range(p.omega_order + 1):
    t_off = first_departure(tau_t, s_inv.evaluate(tau_t, omega_t, order=n), inv["x_tilde"], tol)
    V.add(f"InvTrack{WORDS[n]}", t_off, note=f"inverse vs reversed forward run, series to Omega~^{n}")
    if "x_tilde_from_zero" in inv:
        ok = inv["x_tilde_from_zero"].notna().to_numpy()
        t_off0 = first_departure(tau_t[ok], s_inv.evaluate(tau_t[ok], omega_t, order=n),
                                 inv["x_tilde_from_zero"][ok], tol)
        V.add(f"InvZeroTrack{WORDS[n]}", t_off0,
              note=f"inverse vs x~(0) = 0 integration, series to Omega~^{n}")
        V.add(f"InvZeroTrackFwdTau{WORDS[n]}",
              None if t_off0 is None else summary["tau_c"] - t_off0 / t_scale,
              note="the same instant in forward time tau = tau_c - tau~ eps^(-gamma/(gamma+1))")

# %% Series agreement with the printed coefficients
for d, D in (("forward", "Fwd"), ("inverse", "Inv")):
    a = agreement[d]
    V.add(f"SeriesTerms{D}", a["ours"], kind="exact", note="nonzero coefficients we derive")
    V.add(f"SeriesPrinted{D}", a["printed_within_max_power"], kind="exact")
    V.add(f"SeriesAgree{D}", a["agree"], kind="exact")
    V.add(f"SeriesDiffer{D}", len(a["differ"]), kind="exact")

# %% Impact-speed range of figure 4
V.add("GMin", float(curve["g"].min()), tex=f"{curve['g'].min():g}", kind="config")
V.add("GMax", float(curve["g"].max()), tex=f"{curve['g'].max():g}", kind="config")
V.add("GPoints", int(len(curve)), kind="config")
V.add("OmegaMin", float(curve["omega"].min()), kind="formula")
V.add("OmegaMax", float(curve["omega"].max()), kind="formula")
V.add("EpsMin", float(curve["eps"].min()))
V.add("EpsMax", float(curve["eps"].max()))
V.add("OmegaTildeMin", float(curve["omega_tilde"].min()))
V.add("OmegaTildeMax", float(curve["omega_tilde"].max()))
V.add("ForceEnds", int((curve["end"] == "force").sum()), kind="exact",
      note="impact speeds whose contact ends where the force vanishes")

# %% Accuracy of the reference integration (tolerance study)
acc = acc.sort_values("rtol")
best, loose = acc.iloc[0], acc.iloc[-1]
V.add("AccRTolTight", float(best["rtol"]), tex=sci(best["rtol"], 1), kind="config")
V.add("AccRTolLoose", float(loose["rtol"]), tex=sci(loose["rtol"], 1), kind="config")
V.add("AccEpsErrLoose", float(loose["eps_error"]), sig=2, note="|eps(loosest) - eps(tightest)|")
V.add("AccTauCErrLoose", float(loose["tau_c_error"]), sig=2)
at = acc[np.isclose(acc["rtol"], p.rtol, rtol=1e-9, atol=0)]
if len(at) and at.iloc[0]["rtol"] != best["rtol"]:
    V.add("AccEpsErrWorking", float(at.iloc[0]["eps_error"]), sig=2,
          note="|eps(working rtol) - eps(tightest)|")
    V.add("AccTauCErrWorking", float(at.iloc[0]["tau_c_error"]), sig=2)

# %% Comparison with the paper's printed numbers (only for the paper's exponents)
if p.compare_with_paper:
    V.add("PaperDstar", printed.D_STAR, tex=r"\ensuremath{3\times 10^{-3}}", kind="paper")
    V.add("PaperOmegaAtG", printed.OMEGA_AT_G, tex=f"{printed.OMEGA_AT_G}", kind="paper")
    V.add("PaperTauBAtG", printed.TAU_B_AT_G, tex=f"{printed.TAU_B_AT_G}", kind="paper")
    V.add("PaperOmegaExponent", Fraction(printed.OMEGA_G_EXPONENT), kind="paper")
    V.add("PaperFwdDiverge", printed.FORWARD_DIVERGENCE_TAU, tex=f"{printed.FORWARD_DIVERGENCE_TAU}",
          kind="paper")
    V.add("PaperInvDiverge", printed.INVERSE_DIVERGENCE_TAU, tex=f"{printed.INVERSE_DIVERGENCE_TAU}",
          kind="paper")
    # D* is printed to one digit ("~ 3 x 10^-3"); Omega to four; tau_b to two.
    V.verdict("DstarVerdict", abs(mat.d_star - printed.D_STAR) <= 0.5e-3)
    V.add("OmegaRelDiff", 100.0 * (printed.OMEGA_AT_G - omega) / omega, sig=3, kind="formula",
          note="(paper - ours) / ours, percent")
    V.verdict("OmegaVerdict", abs(omega - printed.OMEGA_AT_G) <= 0.5e-4)
    # The impact speed at which the paper's own formula would give the printed Omega.
    V.add("GForPaperOmega", (printed.OMEGA_AT_G / mat.omega(1.0)) ** (1.0 / e_omega), kind="formula")
    V.verdict("OmegaExponentVerdict", ex.omega_exponent == Fraction(printed.OMEGA_G_EXPONENT))
    V.add("TauBDiff", summary["tau_b"] - printed.TAU_B_AT_G, sig=3)
    V.verdict("TauBVerdict", abs(summary["tau_b"] - printed.TAU_B_AT_G) <= 0.05)
    V.verdict("SeriesVerdict", agreement["forward"]["agree"] == agreement["forward"]["printed_within_max_power"]
              and agreement["inverse"]["agree"] == agreement["inverse"]["printed_within_max_power"])
    # Where the higher orders stop tracking: the paper gives one decimal; we allow +-0.1.
    fwd_top = V.items[f"FwdTrack{WORDS[p.omega_order]}"]["value"]
    V.verdict("FwdDivergeVerdict", fwd_top is not None
              and abs(fwd_top - printed.FORWARD_DIVERGENCE_TAU) <= 0.1,
              note="highest-order forward truncation leaves the reference near the paper's tau")
    key = f"InvZeroTrackFwdTau{WORDS[p.omega_order]}"
    inv_top = V.items[key]["value"] if key in V.items else None
    V.verdict("InvDivergeVerdict", inv_top is not None
              and abs(inv_top - printed.INVERSE_DIVERGENCE_TAU) <= 0.1,
              note="highest-order inverse truncation (vs the x~(0) = 0 run) leaves it near the paper's tau")
    c = list(printed.PRINTED_C)
    for i, name in enumerate(("CZeroPaper", "COnePaper", "CTwoPaper")):
        V.add(name, c[i], tex=f"{c[i]}", kind="paper")
    rel_t = float(np.polynomial.polynomial.polyval(omega, c))
    V.add("PaperOmegaTildeAtG", rel_t, kind="formula", note="c0 + c1 Omega + c2 Omega^2 at g_figure")
    eps_paper = (rel_t / omega) ** (1.0 / e_omega) if rel_t > 0 else None
    V.add("PaperEpsAtG", eps_paper, kind="formula", note="eps from the paper's relation at g_figure")
    # The relation is judged by the eps it gives, against the reference: within 5 percent.
    V.verdict("EpsRelationVerdict", eps_paper is not None and abs(eps_paper - eps) <= 0.05 * eps)
    if "printed" in relations:
        o = curve["omega"].to_numpy()
        rel = np.polynomial.polynomial.polyval(o, relations["printed"]["c"])
        with np.errstate(invalid="ignore"):
            eps_rel = np.where(rel > 0, (rel / o) ** (1.0 / e_omega), np.nan)
        err = np.abs(eps_rel - curve["eps"].to_numpy()) / curve["eps"].to_numpy()
        V.add("PaperEpsMaxRelErr", float(np.nanmax(err)) if np.isfinite(err).any() else None, sig=3,
              kind="integration", note="max over the g range of |eps_paper - eps_ref| / eps_ref")
        V.add("PaperEpsMinRelErr", float(np.nanmin(err)) if np.isfinite(err).any() else None, sig=3,
              kind="integration")
        V.add("PaperEpsUndefined", int(np.isnan(eps_rel).sum()), kind="integration",
              note="impact speeds where the paper's Omega~ <= 0")

# %% The paper's printed damped-only inverse solution (gamma = 1 only)
if ex.gamma == 1:
    import sympy as sp

    t, xc = sp.symbols("tau x_c", nonnegative=True)
    G = sp.sqrt(xc ** 2 + 2)
    y = G * sp.tanh(sp.atanh(xc / G) + G * t / 2)
    fwd_res = sp.simplify((y.diff(t, 2) + y * y.diff(t)).rewrite(sp.exp))
    inv_res = y.diff(t, 2) - y * y.diff(t)
    V.add("PaperInvClosedFormForwardResidual", str(fwd_res), tex=rf"\ensuremath{{{sp.latex(fwd_res)}}}", kind="exact",
          note="the paper's G tanh(...) in x'' + x x' (forward damped-only)")
    x_t = summary["inverse"]["x_tilde_c"]
    taus = np.linspace(0.0, 1.0, 101)
    res = sp.lambdify(t, inv_res.subs(xc, x_t), "numpy")(taus)
    V.add("PaperInvClosedFormInverseResidual", float(np.max(np.abs(res))), kind="formula",
          note="max over tau~ in [0, 1] of |y'' - y y'| at x~_c of g_figure")
    same = np.max(np.abs(damped.paper_inverse_closed_form(taus, x_t) - damped.forward(taus, x_t)[0]))
    V.add("PaperInvClosedFormVsForward", float(same), sig=2, kind="formula",
          note="max |paper's inverse closed form - forward damped-only solution| on [0, 1]")
    V.verdict("InvClosedFormVerdict", float(np.max(np.abs(res))) < 1e-8,
              note="does the paper's closed form solve the inverse damped-only equation?")

# %% Write
lines = [f"% generated by workflow/scripts/values.py for variant {snakemake.wildcards.variant}"
         " -- do not edit"]
for name, item in V.items.items():
    note = f"  % {item['note']}" if item["note"] else ""
    lines.append(rf"\newcommand{{\{name}}}{{{item['tex']}}}{note}")
write_text(snakemake.output.tex, "\n".join(lines))
write_json(snakemake.output.json, V.items)
print(f"{len(V.items)} values")

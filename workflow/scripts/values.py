# %% [markdown]
# # Every number the manuscript prints
#
# Collected from the stage outputs (reference integrations, series, accuracy study, connection,
# eps errors, validation and, for the paper's exponents, the claims ledger) and written twice:
# values.tex with one \newcommand per number (the manuscript \input's it, so no number is typed
# by hand) and values.json with the raw values, their kind and the tolerance `make check` allows.
# Nothing is computed here that another stage computes: each number has one source, and the
# paper's printed numbers come from `restitution.audit.printed`.

# %%
import math
import re
from fractions import Fraction

import numpy as np
import pandas as pd
from restitution_workflow.latex import esc, frac_tex, math_text, sci, sci_up
from restitution_workflow.pipeline import read_json, start, write_json, write_text

from restitution.audit import claims as cl
from restitution.audit import printed
from restitution.audit.readings import PRINTED_MAX_POWER
from restitution.core.connection import eps_from_connection
from restitution.core.model import Material

start(snakemake)

#: make check tolerances (relative) by where a number comes from. An "error" is a difference of
#: two computed numbers near the rounding floor (a retrace deviation, |eps(rtol) - eps(tightest)|):
#: its last digits move with the CPU's rounding (up to 1.5e-4 relative between two machines), so
#: it is pinned like the validation measurements, to 1e-2.
TOLERANCE = {"exact": 0.0, "formula": 1e-12, "integration": 1e-6, "error": 1e-2, "config": 0.0, "paper": 0.0}


class Values:
    """Name -> (raw value, LaTeX text, kind, note)."""

    def __init__(self):
        self.items: dict[str, dict] = {}

    def add(self, name, value, tex=None, *, kind="integration", sig=4, note=""):
        if not re.fullmatch(r"[A-Za-z]+", name):
            raise ValueError(f"LaTeX macro names are letters only: {name!r}")
        if name in self.items:
            raise ValueError(f"duplicate value {name!r}")
        if isinstance(value, (np.floating, np.integer, np.bool_)):
            value = value.item()
        if tex is None:
            if isinstance(value, Fraction):
                tex = frac_tex(value)
            elif isinstance(value, bool):
                tex = "yes" if value else "no"
            elif isinstance(value, int):
                tex = str(value)
            elif isinstance(value, float):
                tex = sci(value, sig)
            elif value is None:
                tex = "---"
            else:
                tex = esc(value)
        raw = str(value) if isinstance(value, Fraction) else value
        if isinstance(raw, float) and not math.isfinite(raw):
            raw = None
        self.items[name] = {"value": raw, "tex": tex, "kind": kind,
                            "tolerance": TOLERANCE[kind], "note": note}


# %% Inputs
inp, p = snakemake.input, snakemake.params
V = Values()
summary = read_json(inp.summary)
curve = pd.read_csv(inp.curve)
agreement = read_json(inp.agreement)
readings = read_json(inp.readings)
fit = read_json(inp.fit)
errors = pd.read_csv(inp.errors, keep_default_na=False, na_values=[""])
mat = Material(p.exponents["alpha"], p.exponents["gamma"], p.D1, p.D2)
ex = mat.exponents
g = summary["g"]
omega = summary["omega"]
eps = summary["eps"]

# %% Model and scaling
V.add("ExpAlpha", ex.alpha, kind="config")
V.add("ExpGamma", ex.gamma, kind="config")
V.add("RefPointSlope", ex.gamma / (ex.gamma + 1), kind="exact",
      note="x' = 1 - x^(gamma+1)/(gamma+1) of the damped-only motion at x = 1: the paper's reference point")
V.add("ExpP", ex.p, kind="exact", note="common denominator of alpha and gamma")
V.add("DOne", p.D1, tex=f"{p.D1:g}", kind="config")
V.add("DTwo", p.D2, tex=f"{p.D2:g}", kind="config")
V.add("Dstar", mat.d_star, kind="formula", note="D* = D1 / D2^((alpha-1)/gamma); undefined for gamma = 0")
V.add("Regime", mat.regime or "undefined", kind="exact")
V.add("GFig", g, tex=f"{g:g}", kind="config")
V.add("OmegaExponent", ex.omega_exponent, kind="exact", note="Omega proportional to g^this")
# When alpha - 1 - 2 gamma = 0, Omega does not depend on g, Omega~ = Omega and eps is g-independent.
V.add("EpsExponent", 1 / ex.omega_exponent if ex.omega_exponent else None, kind="exact",
      note="eps = (Omega~/Omega)^this for a relation Omega~(Omega)")
V.add("OmegaAtG", omega, kind="formula")
V.add("LengthScaleAtG", summary["length_scale"], kind="formula", note="A, xi = A x")
V.add("TimeScaleAtG", summary["time_scale"], kind="formula", note="t_*, t = t_* tau")

# %% Reference collision at g_figure
V.add("EpsAtG", eps)
V.add("TauBAtG", summary["tau_b"])
V.add("XBAtG", summary["x_b"])
V.add("TauCAtG", summary["tau_c"])
V.add("XCAtG", summary["x_c"])
V.add("EndAtG", summary["ended_by"], kind="exact", note="force: contact ends where the force vanishes")
V.add("TimeBAtG", summary["tau_b"] * summary["time_scale"], note="t_b = t_* tau_b (physical)")
V.add("XiBAtG", summary["x_b"] * summary["length_scale"], note="xi_b = A x_b (physical)")
V.add("OmegaTildeAtG", summary["inverse"]["omega_tilde"])
V.add("XTildeCAtG", summary["inverse"]["x_tilde_c"])
V.add("TauTildeBAtG", summary["inverse"]["tau_tilde_b"])
V.add("TauTildeEndAtG", summary["inverse"]["tau_tilde_end"])
V.add("RTol", p.rtol, tex=sci(p.rtol, 1), kind="config")

# %% Series agreement with the printed coefficients
V.add("SeriesOmegaOrder", p.omega_order, kind="config")
V.add("SeriesMaxPower", Fraction(p.max_power), kind="config")
for d, terms, printed_n, agree, differ in (
        ("forward", "SeriesTermsFwd", "SeriesPrintedFwd", "SeriesAgreeFwd", "SeriesDifferFwd"),
        ("inverse", "SeriesTermsInv", "SeriesPrintedInv", "SeriesAgreeInv", "SeriesDifferInv")):
    a = agreement[d]
    V.add(terms, a["ours"], kind="exact", note="nonzero coefficients we derive")
    V.add(printed_n, a["printed_within_max_power"], kind="exact")
    V.add(agree, a["agree"], kind="exact")
    V.add(differ, len(a["differ"]), kind="exact")
V.add("SeriesAgreeAll", sum(agreement[d]["agree"] for d in ("forward", "inverse")), kind="exact",
      note="printed coefficients, forward and inverse, equal to ours")
V.add("SeriesPrintedAll", sum(agreement[d]["printed_within_max_power"] for d in ("forward", "inverse")), kind="exact")

# %% Impact-speed range of figure 4
V.add("GMin", float(curve["g"].min()), tex=f"{curve['g'].min():g}", kind="config")
V.add("GMax", float(curve["g"].max()), tex=f"{curve['g'].max():g}", kind="config")
V.add("GPoints", int(len(curve)), kind="config")
V.add("OmegaMin", float(curve["omega"].min()), kind="formula")
V.add("OmegaMax", float(curve["omega"].max()), kind="formula")
# The balance of the two forces in one impact is Omega (elastic over dissipative), not D*.
V.add("ElasticSpeeds", int((curve["omega"] > 1.0).sum()), kind="exact",
      note="figure-4 speeds with Omega > 1: the elastic force dominates")
V.add("GOmegaOne", mat.omega(1.0) ** (-1.0 / float(ex.omega_exponent)) if ex.omega_exponent else None,
      sig=3, kind="formula", note="impact speed with Omega = 1")
V.add("EpsMin", float(curve["eps"].min()))
V.add("EpsMax", float(curve["eps"].max()))
V.add("OmegaTildeMin", float(curve["omega_tilde"].min()))
V.add("OmegaTildeMax", float(curve["omega_tilde"].max()))
V.add("ForceEnds", int((curve["ended_by"] == "force").sum()), kind="exact",
      note="impact speeds whose contact ends where the force vanishes")

# %% Accuracy of the reference integration (tolerance study; main variant)
if p.accuracy:
    acc = pd.read_csv(inp.accuracy).sort_values("rtol")
    best, loose = acc.iloc[0], acc.iloc[-1]
    V.add("AccRTolTight", float(best["rtol"]), tex=sci(best["rtol"], 1), kind="config")
    V.add("AccRTolLoose", float(loose["rtol"]), tex=sci(loose["rtol"], 1), kind="config")
    V.add("AccEpsErrLoose", float(loose["eps_error"]), sig=2, kind="error", note="|eps(loosest) - eps(tightest)|")
    V.add("AccTauCErrLoose", float(loose["tau_c_error"]), sig=2, kind="error")
    at = acc[np.isclose(acc["rtol"], p.rtol, rtol=1e-9, atol=0)]
    if len(at) and at.iloc[0]["rtol"] != best["rtol"]:
        V.add("AccEpsErrWorking", float(at.iloc[0]["eps_error"]), sig=2, kind="error",
              note="|eps(working rtol) - eps(tightest)|")
        V.add("AccTauCErrWorking", float(at.iloc[0]["tau_c_error"]), sig=2, kind="error")

# %% The paper's procedure (connection_readings.py)
rows = readings["readings"]
V.add("ReadingsComputed", len(rows), kind="exact")
V.add("ReadingsDefined", sum(1 for r in rows if r["defined"]), kind="exact")
V.add("XTildeCReading", readings["x_tilde_c"], note="x~_c at g_figure, start of the x~_c reading")
chosen = next((r for r in rows if r["reading"] == readings["figure_reading"]), None)
V.add("FigReading", chosen["reading"] if chosen else "none", tex=rf"\texttt{{{esc(chosen['reading'])}}}"
      if chosen else "none", kind="exact", note="reading drawn in figure 4")
V.add("FigReadingText", chosen["description"] if chosen else "", tex=math_text(chosen["description"])
      if chosen else "", kind="exact")
for i, name in enumerate(("FigCZero", "FigCOne", "FigCTwo")):
    V.add(name, chosen["c"][i] if chosen else None, kind="formula",
          note="c_i of the figure-4 reading (sympy/mpmath, deterministic)")
if chosen:
    V.add("FigTauZero", chosen["tau0"], kind="formula")
    V.add("FigTauZeroTilde", chosen["tau0_tilde"], kind="formula")
plain = next((r for r in rows if r["reading"] == "P-N1-K2-Dprinted"), None)
if plain is not None:
    status = (rf"gives $c_0 = {plain['c'][0]:.4f}$, $c_1 = {plain['c'][1]:.4f}$, $c_2 = {plain['c'][2]:.4f}$"
              if plain["defined"] else "has no solution: " + math_text(plain["reason"]))
    V.add("PlainReadingStatus", bool(plain["defined"]), tex=status, kind="exact",
          note="the plainest reading P-N1-K2-Dprinted")
if rows and not any(r["defined"] for r in rows):
    V.add("ReadingsReason", rows[0].get("reason", ""), tex=math_text(rows[0].get("reason", "")), kind="exact")

# %% The least-squares fit and the retrace check (connection_fit.py)
V.add("FitApplies", bool(fit["applies"]), kind="exact")
V.add("FitGMin", fit["g_min"], tex=f"{fit['g_min']:g}", kind="config")
V.add("FitGMax", fit["g_max"], tex=f"{fit['g_max']:g}", kind="config")
V.add("FitPoints", fit["n"], kind="exact")
if fit["applies"]:
    V.add("FitOmegaMin", fit["omega_min"], kind="formula")
    V.add("FitOmegaMax", fit["omega_max"], kind="formula")
    for i, (name, err) in enumerate((("FitCZero", "FitCZeroErr"), ("FitCOne", "FitCOneErr"),
                                     ("FitCTwo", "FitCTwoErr"))):
        V.add(name, fit["c"][i], sig=4)
        V.add(err, fit["stderr"][i], sig=2, note="OLS standard error (model misfit)")
    V.add("FitMaxResidual", fit["max_abs_residual"], sig=2)
    V.add("FitRMS", fit["rms"], sig=2)
    V.add("FitMaxRelResidual", fit["max_rel_residual"], tex=sci_up(fit["max_rel_residual"], 2), sig=2)   # "at most"
else:
    V.add("FitReason", fit["reason"], tex=math_text(fit["reason"]), kind="exact")
rt = fit["retrace"]
if "max_deviation" in rt:
    V.add("RetraceMaxDev", rt["max_deviation"], sig=2, kind="error", note="max |x_retraced - x_forward| / x_b")
    V.add("RetraceVEnd", rt["v_end_error"], sig=2, kind="error")
    V.add("RetraceTau", rt["tau_error"], sig=2, kind="error")
    V.add("RetraceSamples", rt["samples"], kind="exact")

# %% eps(g) every way (eps_compare.py)
ERROR_COLUMNS = ("max_abs_error", "median_abs_error", "max_rel_error", "median_rel_error", "max_rel_error_fit_range")
#: kind -> (defined, one macro per ERROR_COLUMNS, undefined count, count above one)
EPS_MACROS = {
    "printed": ("PrintedEpsDefined", ("PrintedEpsMaxAbs", "PrintedEpsMedianAbs", "PrintedEpsMaxRel",
                                      "PrintedEpsMedianRel", "PrintedEpsMaxRelFit"),
                "PrintedEpsUndefined", "PrintedEpsAboveOne"),
    "derived": ("DerivedEpsDefined", ("DerivedEpsMaxAbs", "DerivedEpsMedianAbs", "DerivedEpsMaxRel",
                                      "DerivedEpsMedianRel", "DerivedEpsMaxRelFit"),
                "DerivedEpsUndefined", "DerivedEpsAboveOne"),
    "fitted": ("FittedEpsDefined", ("FittedEpsMaxAbs", "FittedEpsMedianAbs", "FittedEpsMaxRel",
                                    "FittedEpsMedianRel", "FittedEpsMaxRelFit"),
               "FittedEpsUndefined", "FittedEpsAboveOne"),
}
for _, r in errors.iterrows():
    defined_name, error_names, undefined_name, above_name = EPS_MACROS[r["kind"]]
    defined = int(r["n_defined"]) > 0
    V.add(defined_name, defined, kind="exact")
    for col, name in zip(ERROR_COLUMNS, error_names):
        err = float(r[col]) if defined and r[col] != "" else None
        # a largest error is printed as a bound ("up to", "at most"): rounded up, so that it still bounds
        V.add(name, err, tex=sci_up(err, 2) if col.startswith("max") else None, sig=2)
    V.add(undefined_name, int(r["n_undefined"]), kind="exact", note="speeds with Omega~ <= 0 (no eps)")
    V.add(above_name, int(r["n_above_one"]), kind="exact", note="speeds with eps > 1")

# %% The claims ledger (paper's exponents only)
if p.claims:
    cv = read_json(inp.claims_values)
    ledger = pd.read_csv(inp.claims_csv, keep_default_na=False)
    counts = ledger["verdict"].value_counts()
    V.add("ClaimsTotal", int(len(ledger)), kind="exact")
    V.add("ClaimsReproduced", int(counts.get("reproduced", 0)), kind="exact")
    V.add("ClaimsNotReproduced", int(counts.get("not reproduced", 0)), kind="exact")
    V.add("ClaimsAmbiguous", int(counts.get("ambiguous", 0)), kind="exact")
    # Row numbers and verdicts of the ledger, so the text can point at them (rows by their stable id).
    by_id = ledger.set_index("id")

    def row(row_name, verdict_name, row_id):
        V.add(row_name, int(by_id.loc[row_id, "row"]), kind="exact", note=row_id)
        V.add(verdict_name, by_id.loc[row_id, "verdict"], kind="exact")

    row("RowDstar", "VerdictDstar", "dstar")
    row("RowOmega", "VerdictOmega", "omega")
    row("RowTauB", "VerdictTauB", "tau-b")
    row("RowFwdTrack", "VerdictFwdTrack", "fwd-track")
    row("RowFirstOrder", "VerdictFirstOrder", "first-order")
    row("RowInvTrack", "VerdictInvTrack", "inv-track")
    row("RowRadiusFwd", "VerdictRadiusFwd", "radius-forward")
    row("RowRadiusInv", "VerdictRadiusInv", "radius-inverse")
    row("RowInvForm", "VerdictInvForm", "inv-form")
    row("RowDelta", "VerdictDelta", "delta")
    row("RowCTriple", "VerdictCTriple", "c-triple")
    row("RowOmegaScaling", "VerdictOmegaScaling", "omega-scaling")
    row("RowEpsScaling", "VerdictEpsScaling", "eps-scaling")
    row("RowShape", "VerdictShape", "fig4-shape")
    row("RowSeries", "VerdictSeries", "series")
    V.add("ReadingsReproduced", sum(cl.reproduces_printed_c(r["c"]) for r in cv["readings"]), kind="exact",
          note="readings whose c0-c2 equal the printed ones within the ledger's tolerance")

    # The paper's printed numbers (restitution.audit.printed) and ours next to them.
    # the sharpest consequence of the printed c's: eps at the paper's own impact speed
    V.add("PrintedEpsAtG", eps_from_connection(ex, omega, printed.PRINTED_C), kind="formula",
          note="eps from the printed c0-c2 at g_figure (the reference gives EpsAtG)")
    V.add("PaperAlpha", Fraction(printed.ALPHA), kind="paper")
    V.add("PaperGamma", Fraction(printed.GAMMA), kind="paper")
    V.add("PaperSeriesMaxPower", PRINTED_MAX_POWER, kind="paper", note="the paper prints every series to this power of tau")
    V.add("PaperDstar", printed.D_STAR, tex=r"\ensuremath{3\times 10^{-3}}", kind="paper")
    V.add("PaperOmegaAtG", printed.OMEGA_AT_G, tex=f"{printed.OMEGA_AT_G}", kind="paper")
    V.add("PaperTauBAtG", printed.TAU_B_AT_G, tex=f"{printed.TAU_B_AT_G}", kind="paper")
    V.add("PaperOmegaExponent", Fraction(printed.OMEGA_G_EXPONENT), kind="paper")
    V.add("PaperEpsExponent", Fraction(printed.EPS_G_EXPONENT), kind="paper")
    V.add("PaperFwdDiverge", printed.FORWARD_DIVERGENCE_TAU, tex=f"{printed.FORWARD_DIVERGENCE_TAU}", kind="paper")
    V.add("PaperInvDiverge", printed.INVERSE_DIVERGENCE_TAU, tex=f"{printed.INVERSE_DIVERGENCE_TAU}", kind="paper")
    for i, name in enumerate(("CZeroPaper", "COnePaper", "CTwoPaper")):
        V.add(name, printed.PRINTED_C[i], tex=rf"\ensuremath{{{printed.PRINTED_C[i]}}}", kind="paper")
    V.add("OmegaRatio", printed.OMEGA_AT_G / cv["omega_at_g"], kind="formula", note="printed / ours")
    # The impact speed at which our (and the paper's) formula gives the printed Omega.
    V.add("GForPaperOmega", (printed.OMEGA_AT_G / mat.omega(1.0)) ** (1.0 / float(ex.omega_exponent)),
          kind="formula")
    V.add("TauZero", cv["tau0"], kind="formula", note="damped-only forward solution reaches x = 1")
    V.add("TauZeroTilde", cv["tau0_tilde"], kind="formula")
    V.add("TauBLowestOrder", cv["tau_b_lowest_order"], note="tau_0 + Delta, lowest order, converged x1'")
    V.add("TauBLowestOrderAtZero", cv["tau_b_lowest_order_at_zero"], kind="formula", note="tau_0 + 1")
    tr = cv["tracking"]
    keys = [str(float(t)) for t in tr["thresholds"]]
    mid = keys[len(keys) // 2]
    V.add("TrackThreshold", float(mid), tex=f"{float(mid):g}", kind="config",
          note="|series - reference| > this x x_b")
    V.add("TrackThresholdLow", float(keys[0]), tex=f"{float(keys[0]):g}", kind="config")
    V.add("TrackThresholdHigh", float(keys[-1]), tex=f"{float(keys[-1]):g}", kind="config")

    def first(d, pick):
        vals = [v for k, v in d.items() if int(k) >= 2 and v is not None]
        return pick(vals) if vals else None
    for key, fwd, inv_paper, inv_scaled in (
            (keys[0], "FwdDepartLow", "InvDepartPaperLow", "InvDepartScaledLow"),
            (mid, "FwdDepart", "InvDepartPaper", "InvDepartScaled"),
            (keys[-1], "FwdDepartHigh", "InvDepartPaperHigh", "InvDepartScaledHigh")):
        V.add(fwd, first(tr["forward"][key], min), note="first departure, orders >= 2")
        V.add(inv_paper, first(tr["inverse_tau_paper"][key], max), note="inverse, forward time tau_c - tau~")
        V.add(inv_scaled, first(tr["inverse_tau_scaled"][key], max),
              note="inverse, forward time with the time scale applied")
    V.add("FwdDepartOrderOne", tr["forward"][mid]["1"])
    share = tr["first_order_best_after_2"].get(mid)
    V.add("FirstOrderBetterShare", None if share is None else 100.0 * share, sig=2,
          note="percent of the comparable tau > 2 samples where x0 + Omega x1 is closest")
    V.add("FirstOrderComparable", tr["comparable_samples_after_2"][mid], kind="exact",
          note="tau > 2 samples where some truncation is within the threshold of the reference")
    V.add("FirstOrderSamples", tr["samples_after_2"], kind="exact")
    V.add("TrackOmegaTilde", tr["omega_tilde"])
    V.add("RadiusFwd", cv["radius_forward"], kind="formula")
    V.add("RadiusInv", cv["radius_inverse"], kind="formula")
    pf = cv["paper_inverse_form"]
    V.add("InvFormXc", pf["x_c"], tex=f"{pf['x_c']:g}", kind="config")
    V.add("InvFormResidualInverse", pf["residual_inverse"], sig=2, kind="error", note="finite differences")
    V.add("InvFormResidualForward", pf["residual_forward"], sig=2, kind="error", note="finite differences")
    V.add("RelationMaxRelError", cv["fig4"]["paper_relation_omega_tilde_max_rel_error_in_fit_range"], sig=3,
          note="max |Omega~_printed - Omega~_exact| / Omega~_exact over the fit range")
    # the absolute counterpart of PrintedEpsMaxRelFit, as the ledger's discussion quotes it (four digits)
    V.add("PrintedEpsMaxAbsFit", cv["fig4"]["max_abs_error_paper_in_fit_range"], sig=4,
          note="max |eps_printed - eps_reference| over the fit range")
    V.add("OmegaTildeSmallExponent", cv["omega_tilde_small_omega_exponent"], sig=3,
          note="local slope of the exact Omega~ at Omega = 1e-4")
    lo_w, hi_w = cv.get("omega_tilde_small_omega_window", (None, None))
    if lo_w is not None:
        V.add("OmegaTildeSlopeFrom", lo_w, sig=1, kind="config", note="the slope's Omega window, lower end")
        V.add("OmegaTildeSlopeTo", hi_w, sig=1, kind="config", note="the slope's Omega window, upper end")
    V.add("OmegaTildeExactExponent", (ex.alpha - ex.gamma) / (ex.gamma + 1), kind="exact",
          note="Omega~ ~ Omega^this as Omega -> 0: 1 + (alpha - 1 - 2 gamma)/(gamma + 1), from eps ~ k Omega")
    es = cv["eps_scaling"]
    V.add("LossExponentSmallG", es["loss_g_exponent_small_g"], sig=3, note="1 - eps ~ g^this as g -> 0 (measured)")
    V.add("LossExponentExact", (2 * ex.gamma + 1 - ex.alpha) / (ex.alpha + 1), kind="exact",
          note="1 - eps ~ delta ~ g^this as g -> 0: (2 gamma + 1 - alpha)/(alpha + 1)")
    V.add("LossExponentAtGMin", es["loss_g_exponent_at_g_min"], sig=3,
          note="local slope at the largest Omega of figure 4's grid (its slowest impact)")
    lo, hi = es.get("loss_slope_omegas", (1e3, 2e3))
    V.add("LossSlopeOmegaLo", lo, tex=f"{lo:g}", kind="config", note="the window of LossExponentSmallG")
    V.add("LossSlopeOmegaHi", hi, tex=f"{hi:g}", kind="config")
    V.add("EpsExponentLargeG", es["eps_g_exponent_large_g"], sig=3, note="eps ~ g^this as g -> infinity")
    validity = cv.get("paper_relation_validity") or {}
    nonpos = validity.get("omega_tilde_nonpositive", [])
    if nonpos:
        # the interval of the printed relation's Omega~ <= 0, within the speeds studied (figure 4's range)
        g_lo, g_hi = float(curve["g"].min()), float(curve["g"].max())
        V.add("PrintedNoEpsGMin", max(nonpos[0]["g"][0], g_lo), sig=3, note="clipped to the studied speeds")
        V.add("PrintedNoEpsGMax", min(nonpos[0]["g"][1], g_hi), sig=3, note="clipped to the studied speeds")
        # the whole interval, not clipped: Omega~ is a quadratic in Omega with two roots, and below the slower
        # speed (the larger Omega) it is positive again, so "no eps below g = ..." would be false
        V.add("PrintedNoEpsGRootLow", nonpos[0]["g"][0], sig=3, note="slower root: Omega~ > 0 again below it")
        V.add("PrintedNoEpsGRootHigh", nonpos[0]["g"][1], sig=3, note="faster root of the printed Omega~")
        V.add("PrintedNoEpsOmegaRootLow", min(nonpos[0]["omega"]), sig=4, note="smaller Omega root")
        V.add("PrintedNoEpsOmegaRootHigh", max(nonpos[0]["omega"]), sig=4, note="larger Omega root")
        # the fastest studied speed inside that interval: the edge above is where Omega~ crosses zero, between
        # two studied speeds
        inside = curve["g"][(curve["g"] >= nonpos[0]["g"][0]) & (curve["g"] <= nonpos[0]["g"][1])]
        if len(inside):
            V.add("PrintedNoEpsGLast", float(inside.max()), sig=3, note="fastest studied speed without eps")

# %% Write
lines = [f"% generated by workflow/scripts/values.py for variant {snakemake.wildcards.variant}"
         " -- do not edit"]
for name, item in V.items.items():
    note = f"  % {item['note']}" if item["note"] else ""
    lines.append(rf"\newcommand{{\{name}}}{{{item['tex']}}}{note}")
write_text(snakemake.output.tex, "\n".join(lines))
write_json(snakemake.output.json, V.items)
print(f"{len(V.items)} values")

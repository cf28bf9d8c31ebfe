# %% [markdown]
# # The overlap rule's viscous limit: fast impacts rebound at a material speed
#
# For every exponent pair with gamma <= alpha < 2 gamma + 1 (the variants' and a few checks'), the
# library's law eps ~ C Omega^k (restitution.core.overlap_limit) is set against the reference
# integrator and the independent mpmath integrator under the overlap rule, next to the force rule;
# the script writes the numbers the manuscript prints, a table and a figure. It only calls the
# library and writes what it returns.

# %%
from fractions import Fraction
from functools import lru_cache

import numpy as np
import pandas as pd
from matplotlib.lines import Line2D
from restitution_workflow.latex import esc, frac_tex, sci, sci_up
from restitution_workflow.pipeline import (TEXT_WIDTH_PT, save_figure, setup_matplotlib, start, write_csv,
                                          write_text)
from restitution.core.problem import Problem

from restitution.core.collision import collide
from restitution.core.exponents import as_exponents
from restitution.core.highprec import reference_collision
from restitution.core.overlap_limit import overlap_limit
from restitution.fast.master import reference_eps
from restitution.fast.rung import integrator_bound

start(snakemake)
P = snakemake.params
out = snakemake.output
RTOL = 1e-12
CURVE_RTOL = 1e-14


@lru_cache(maxsize=None)
def eps(a, g, om, rule):
    """One reference collision (each is needed by several of the numbers below)."""
    return collide(Problem.of(a, g, rule), om, rtol=RTOL).eps


pairs = []
for a, g, label in P.pairs:
    if (a, g) not in [(q[0], q[1]) for q in pairs]:
        pairs.append((a, g, label))

# %% the law against both integrators
rows, curves = [], []
for a, g, label in pairs:
    L = overlap_limit((a, g))
    law = lambda om: L.C * om ** L.k  # noqa: E731
    small = {om: eps(a, g, om, "overlap") / law(om) - 1.0 for om in P.check_omegas}
    hp_om = P.highprec_omega
    hp = float(reference_collision(Problem.of(a, g, "overlap"), hp_om, digits=P.highprec_digits).eps) / law(hp_om) - 1.0
    o1, o2 = min(P.check_omegas), max(P.check_omegas)
    slope = np.log(eps(a, g, o2, "overlap") / eps(a, g, o1, "overlap")) / np.log(o2 / o1)
    moderate = {om: eps(a, g, om, "overlap") / law(om) - 1.0 for om in P.moderate_omegas}
    ratio = {om: eps(a, g, om, "overlap") / eps(a, g, om, "force") for om in P.moderate_omegas}
    rows.append({"alpha": a, "gamma": g, "label": label, "k": str(L.k_exact), "C": L.C, "C_error": L.C_error,
                 "slope": slope, "max_dev_small": max(abs(v) for v in small.values()), "dev_highprec": hp,
                 **{f"dev_{om:g}": v for om, v in moderate.items()},
                 **{f"ratio_{om:g}": v for om, v in ratio.items()}, "force_k": L.force_k, "decay": L.decay})
    om = np.logspace(np.log10(P.curve_omega[0]), np.log10(P.curve_omega[1]), P.curve_points)
    eo, ef = reference_eps(Problem.of(a, g, "overlap"), om, CURVE_RTOL), reference_eps(Problem.of(a, g, "force"), om, CURVE_RTOL)
    curves += [{"alpha": a, "gamma": g, "omega": w, "eps_overlap": o, "eps_force": f, "law_overlap": law(w),
                "law_force": L.force_k * w} for w, o, f in zip(om, eo, ef)]
table = pd.DataFrame(rows)
curve = pd.DataFrame(curves)
write_csv(out.csv, table)
write_csv(out.curves, curve)

# %% table
frac = lambda s: frac_tex(Fraction(s))  # noqa: E731
mods = list(P.moderate_omegas)
lines = [r"\begin{tabular}{" + "l" * (6 + len(mods)) + "}", r"\toprule",
         r"$\alpha$ & $\gamma$ & $\kappa$ & $C_o$ & slope & dev., $\Omega \le " + sci(max(P.check_omegas), 1) + "$ & "
         + " & ".join(rf"dev., $\Omega = {sci(om, 2)}$" for om in mods) + r" \\", r"\midrule"]
# A deviation at moderate Omega no larger than twice the pair's accuracy floor (its column "dev., Omega <= ...":
# how far the two integrations and the high-precision one are from the law where it holds) is marked with a
# dagger: it is at the limit of what the integrations resolve, not a measured departure from the law.
FLOOR_FACTOR = 2.0


def floor_of(r):
    return max(r["max_dev_small"], abs(r["dev_highprec"]))


def moderate_entry(r, om):
    dev = r[f"dev_{om:g}"]
    return sci(dev, 2) + (r"$^\dagger$" if abs(dev) <= FLOOR_FACTOR * floor_of(r) else "")


for r in rows:
    lines.append(" & ".join([frac(r["alpha"]), frac(r["gamma"]), frac(r["k"]), sci(r["C"], 11), sci(r["slope"], 10),
                             sci(floor_of(r), 1)]
                            + [moderate_entry(r, om) for om in mods]) + r" \\")
lines += [r"\bottomrule", r"\end{tabular}"]
write_text(out.table, "\n".join(lines))

# %% the numbers the manuscript prints
main = next(r for r in rows if r["label"] == "main")
hertz = next(r for r in rows if (r["alpha"], r["gamma"]) == ("3/2", "1/2"))
Lm = overlap_limit((main["alpha"], main["gamma"]))
p1, p2 = Lm.speed_exponents
mat = P.material
speed = float(Lm.rebound_speed(mat["D1"], mat["D2"]))
a_, g_ = Fraction(main["alpha"]), Fraction(main["gamma"])
w = float((a_ - 1 - 2 * g_) / (g_ + 1))
scale = mat["D1"] * mat["D2"] ** (-float(a_ + 1) / float(g_ + 1))      # Omega = scale g^w
om_max = scale * mat["g_max"] ** w                                      # smallest Omega of figure 4
gmax_ratio = eps(main["alpha"], main["gamma"], om_max, "force") / eps(main["alpha"], main["gamma"], om_max, "overlap")
TENTH = sorted(mods)[len(mods) // 2]           # the middle of the moderate Omegas
dev_tenth = max(abs(r[f"dev_{TENTH:g}"]) for r in rows)
macros = {
    "OverlapPairs": str(len(rows)),
    "OverlapPairList": ", ".join(rf"$({frac(r['alpha'])}, {frac(r['gamma'])})$" for r in rows),
    "OverlapCheckMin": sci(min(P.check_omegas), 1), "OverlapCheckMax": sci(max(P.check_omegas), 1),
    "OverlapRtol": sci(RTOL, 1),     # the direct integrations' relative tolerance (Table 2, the text)
    "OverlapMaxDevSmall": sci_up(max(r["max_dev_small"] for r in rows), 2),   # "holds to": a bound, rounded up
    "OverlapHighprecOmega": sci(P.highprec_omega, 1), "OverlapHighprecDigits": str(P.highprec_digits),
    "OverlapMaxDevHighprec": sci_up(max(abs(r["dev_highprec"]) for r in rows), 2),   # "agrees ... to": a bound
    "OverlapMaxCError": sci_up(max(r["C_error"] for r in rows), 2),     # "at most": a bound, rounded up
    "OverlapMaxSlopeDev": sci_up(max(abs(r["slope"] - float(Fraction(r["k"]))) for r in rows), 2),
    "OverlapDevTenth": sci_up(dev_tenth, 2), "OverlapTenthOmega": sci(TENTH, 2), "OverlapDevModerateMax": sci(max(abs(r[f"dev_{max(mods):g}"]) for r in rows), 2),
    "OverlapModerateMax": sci(max(mods), 2), "OverlapFloorFactor": f"{FLOOR_FACTOR:g}",
    "OverlapMainK": frac(main["k"]), "OverlapMainC": sci(main["C"], 10),
    "OverlapMainCErr": sci(main["C_error"], 1), "OverlapMainForceK": sci(main["force_k"], 10),
    "OverlapMainDecay": sci(main["decay"], 4),
    "OverlapMainRatioExp": frac(str(Fraction(main["k"]) - 1)),
    "OverlapHertzK": frac(hertz["k"]), "OverlapHertzC": sci(hertz["C"], 10),
    "OverlapSpeedPOne": frac(str(p1)), "OverlapSpeedPTwo": frac(str(p2)),
    "OverlapMainSpeed": sci(speed, 4), "OverlapMainGMax": sci(mat["g_max"], 2),
    "OverlapMainOmegaAtGMax": sci(om_max, 3), "OverlapMainRuleRatioAtGMax": sci(gmax_ratio, 3),
    "OverlapMainSpeedAtGMax": sci(eps(main["alpha"], main["gamma"], om_max, "overlap") * mat["g_max"], 4),
    "OverlapMainRatioAtTenth": sci(main[f"ratio_{TENTH:g}"], 3),
    # where the law starts to hold (deviation OverlapDevTenth at TENTH) the rebound is already weak: the largest
    # eps of the pairs there, under the overlap rule (the practical range of the law, issue 53)
    "OverlapEpsAtTenthMax": sci_up(max(eps(r["alpha"], r["gamma"], TENTH, "overlap") for r in rows), 2),
}
write_text(out.values, "\n".join(rf"\newcommand{{\{k}}}{{{v}}}" for k, v in macros.items()))

# %% figure: the two rules over Omega, and how fast the law is approached
plt = setup_matplotlib()
# drawn at the size it prints (width: a fraction of TEXT_WIDTH_PT): 10.5 pt puts tick exponents and legend
# indices (0.7 of it) above 7 pt
plt.rcParams.update(dict.fromkeys(("axes.labelsize", "xtick.labelsize", "ytick.labelsize", "legend.fontsize",
                                   "axes.titlesize"), 10.5))
# drawn at 0.9 of the text width, the width the article prints it at (at the full width its tick exponents printed
# at 6.7 pt, referee r19), and as high as it printed before
PRINT_WIDTH = 0.9
fig, (left, right) = plt.subplots(1, 2, figsize=(PRINT_WIDTH * TEXT_WIDTH_PT / 72.27, PRINT_WIDTH * 3.4))
colours = ["C0", "C1", "C2", "C3", "C4", "C5", "C6"]
LAW_OMEGA_MAX = 0.3
# a marker and a line style per exponent pair as well as a colour: the figure reads in greyscale
markers = ["o", "s", "^", "D", "v", "P", "X"]
dashes = ["-", (0, (5, 1.5)), "-.", (0, (1, 1.2)), (0, (6, 1.5, 1, 1.5, 1, 1.5)), (0, (3, 1)), "-"]
for i, r in enumerate(rows):
    c = curve[(curve["alpha"] == r["alpha"]) & (curve["gamma"] == r["gamma"])]
    lab = rf"$\alpha = {r['alpha']}$, $\gamma = {r['gamma']}$"
    pair = {"color": colours[i % 7], "marker": markers[i % 7], "mfc": "none", "ms": 4}
    left.loglog(c["omega"], c["eps_overlap"] / c["eps_force"], lw=1.0, ls="-", label=lab,
                markevery=(i % 4 * max(len(c) // 32, 1), max(len(c) // 8, 1)), **pair)
    # the leading laws are laws of the viscous limit: drawn up to a moderate Omega (beyond, they run off the top);
    # as wide pale bands under the integrations' thin solid lines: a thin dashed line of the same colour was hard
    # to tell from the integration it lies on, a band shows the line inside it where they agree and apart where not
    law = c["omega"] <= LAW_OMEGA_MAX
    left.loglog(c["omega"][law], (c["law_overlap"] / c["law_force"])[law], color=colours[i % 7], lw=5.0,
                alpha=0.3, solid_capstyle="butt", zorder=1)
    inv = np.asarray(P.decay_inverse_omegas, dtype=float)
    d = np.abs(reference_eps(Problem.of(r["alpha"], r["gamma"], "overlap"), 1.0 / inv, CURVE_RTOL)
               / (r["C"] * inv ** -float(Fraction(r["k"]))) - 1.0)
    # below its bound under this rule the integrator's own error shows (the plateau near 5e-13)
    keep = d > integrator_bound(CURVE_RTOL, Problem.of(r["alpha"], r["gamma"], "overlap"))
    right.semilogy(inv[keep], d[keep], ls=dashes[i % 7], lw=1.0, label=lab, **pair)
left.set_ylim(top=3.0)
left.set_xlabel(r"$\Omega$")
left.set_ylabel(r"$\varepsilon_{\mathrm{overlap}} / \varepsilon_{\mathrm{force}}$")
# a key of the two styles in the panel itself (black: the colours are the exponent pairs of the figure's legend)
styles = [Line2D([], [], color="k", lw=1.0, marker="o", mfc="none", ms=4, label="integration"),
          Line2D([], [], color="k", lw=5.0, alpha=0.3, solid_capstyle="butt",
                 label=rf"ratio of leading laws ($\Omega \leq {LAW_OMEGA_MAX:g}$)")]
right.set_xlabel(r"$1/\Omega$")
right.set_ylabel(r"$|\varepsilon_{\mathrm{overlap}} / (C_o\,\Omega^\kappa) - 1|$")
# the two styles' key below the panels with the exponent pairs' (inside the left panel it covered the curves
# of the pairs with the steepest laws)
handles, labels = right.get_legend_handles_labels()
fig.legend(handles + styles, labels + [h.get_label() for h in styles], loc="lower center", ncol=3, frameon=False,
           fontsize=9.5)
fig.set_layout_engine("tight", rect=(0, 0.19, 1, 1))
save_figure(fig, out.pdf, out.png, width=PRINT_WIDTH)

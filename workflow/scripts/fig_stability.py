# %% [markdown]
# # The stability atlas as a figure
#
# One column per damping exponent gamma, one colour per elastic exponent alpha. Rows:
# eps against Omega with the viscous limit (dashed), 1 - eps with the elastic limit (dashed),
# the contact time tau_c with both limits, and the measured relative errors of the atlas runs
# (against the tight tolerance, the mpmath reference and the closed forms) under the stated
# accuracy (grey line). The limits come from `restitution.core.asymptotics`; this script only draws.

# %%
from fractions import Fraction

import math

import numpy as np
import pandas as pd
from restitution_workflow.pipeline import TEXT_WIDTH_PT, save_figure, setup_matplotlib, start

from restitution.audit import stability as st

try:
    from restitution.core import asymptotics as asy
except ImportError:  # pragma: no cover - the limits are another stage's work
    asy = None

start(snakemake)
plt = setup_matplotlib()
# drawn at the size it prints (width: a fraction of TEXT_WIDTH_PT): 10.5 pt puts tick exponents and legend
# indices (0.7 of it) above 7 pt
plt.rcParams.update(dict.fromkeys(("axes.labelsize", "xtick.labelsize", "ytick.labelsize", "legend.fontsize",
                                   "axes.titlesize"), 10.5))
spec = st.AtlasSpec.from_config(snakemake.params.spec)
atlas = pd.read_csv(snakemake.input.atlas, dtype={"alpha": str, "gamma": str}, keep_default_na=False,
                    na_values=["", "nan", "NaN"])
ok = atlas[atlas["status"].fillna("ok").isin(["ok", ""])]

# %%
alphas, gammas = list(spec.alphas), list(spec.gammas)
# five alphas: a qualitative palette, and a line style and marker of their own (told apart in grey print too)
colours = dict(zip(alphas, [plt.get_cmap("tab10")(i % 10) for i in range(len(alphas))]))
STYLES = ["-", "--", "-.", (0, (1, 1)), (0, (5, 1.5, 1, 1.5, 1, 1.5))]
MARKERS = ["o", "s", "^", "D", "v"]
styles = {a: dict(ls=STYLES[i % len(STYLES)], marker=MARKERS[i % len(MARKERS)], markersize=3.2,
                  markerfacecolor="none", markeredgewidth=0.7) for i, a in enumerate(alphas)}
# no row of eps itself: on log axes the pairs' curves coincide there (the caption gives their spread), so
# the rows that tell the alphas apart get its height; 6.2 in, not more: a taller atlas stood alone on a
# float page with a fifth of it empty, this one heads a page of text
rows = ("one_minus", "tau_c", "error")
fig, axes = plt.subplots(len(rows), len(gammas), figsize=(TEXT_WIDTH_PT / 72.27, 6.2), sharex=True, sharey="row",
                         squeeze=False)
w_lo, w_hi = spec.omega_min, spec.omega_max
viscous_w = np.logspace(np.log10(w_lo), -2, 60)
elastic_w = np.logspace(2, np.log10(w_hi), 60)


def frac(text):
    q = Fraction(text)
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


for j, g in enumerate(gammas):
    for a in alphas:
        d = ok[(ok["alpha"] == a) & (ok["gamma"] == g)].sort_values("omega")
        if d.empty:
            continue
        c = colours[a]
        w = d["omega"].to_numpy()
        st_ = dict(styles[a], markevery=(alphas.index(a) % 4 + 1, 6))   # markers offset per alpha
        axes[0, j].plot(w, 1.0 - d["eps"], color=c, lw=1.2, label=rf"$\alpha = {frac(a)}$", **st_)
        axes[1, j].plot(w, d["tau_c"], color=c, lw=1.2, **st_)
        # sizes in pt^2 at print size (the figure is drawn at the width it prints): about 4.5 to 5 pt
        # across, so that each marker's shape can be told at print size (at 3 pt it could not)
        for col, marker, size in (("err_tight", "o", 20), ("err_ref", "s", 25), ("err_exact", "x", 20)):
            e = d[col].to_numpy(dtype=float)
            m = np.isfinite(e)
            axes[2, j].scatter(w[m], np.maximum(e[m], 1e-17), s=size, marker=marker,
                               facecolors="none" if marker != "x" else c, edgecolors=c if marker != "x" else None,
                               color=c if marker == "x" else None, lw=0.8)
        if asy is not None:
            vl, el = asy.viscous_limit((a, g)), asy.elastic_limit((a, g))
            axes[0, j].plot(elastic_w, 1.0 - el.eps(elastic_w, order=2), "-", color="black", lw=0.6, alpha=0.6)
            axes[1, j].plot(elastic_w, el.tau_c(elastic_w), "-", color="black", lw=0.6, alpha=0.6)
            if vl.kind == "force":
                axes[1, j].plot(viscous_w, vl.tau_c(viscous_w), "-", color="black", lw=0.6, alpha=0.6)
    axes[0, j].set_title(rf"$\gamma = {frac(g)}$")
    axes[2, j].axhline(max(spec.accuracy_for(a, g) for a in spec.alphas), color="grey", lw=1.0)

for ax in axes.flat:
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.grid(True, which="major", alpha=0.3)
    # two labels, well inside the panel: at its edges the labels of neighbouring panels ran into each other
    ax.set_xticks([1e-4, 1e4] if len(gammas) > 2 else [1e-6, 1e-3, 1, 1e3, 1e6])
for ax, label in zip(axes[:, 0], (r"$1-\varepsilon$", r"$\tau_c$", "relative error")):
    ax.set_ylabel(label)
axes[2, 0].set_ylim(1e-17, 1e-6)
for ax in axes[-1]:
    ax.set_xlabel(r"$\Omega$")
for ax in axes[:, 0]:
    ax.set_xlim(w_lo, w_hi)
handles, labels = axes[0, 0].get_legend_handles_labels()
handles += [plt.Line2D([], [], ls="-", color="black", lw=0.6, alpha=0.6),
            plt.Line2D([], [], ls="", marker="o", mfc="none", color="grey"),
            plt.Line2D([], [], ls="", marker="s", mfc="none", color="grey"),
            plt.Line2D([], [], ls="", marker="x", color="grey"),
            plt.Line2D([], [], color="grey")]
tight_exp = round(math.log10(spec.tight_rtol))
labels += ["limits", rf"against tolerance $10^{{{tight_exp}}}$", "against the high-precision integrator",
           "against the closed forms", "stated accuracy"]
# the curves' key in one row, the markers' key in two below it
n_lines = len(alphas) + 1
fig.legend(handles[:n_lines], labels[:n_lines], loc="lower center", ncol=n_lines, frameon=False,
           bbox_to_anchor=(0.5, 0.085), columnspacing=1.0, handletextpad=0.4)   # above the two rows below, clear of them
fig.legend(handles[n_lines:], labels[n_lines:], loc="lower center", ncol=2, frameon=False, bbox_to_anchor=(0.5, 0.0),
           columnspacing=1.2, handletextpad=0.4)
fig.tight_layout(rect=(0, 0.13, 1, 1), h_pad=0.4, w_pad=0.3)

# %%
save_figure(fig, snakemake.output.pdf, snakemake.output.png, width=1.0)

# %% [markdown]
# # eps(Omega) across variants, with the known results they are validated against
#
# One curve per variant from its reference integrations on the common grid of Omega
# (validation.py); the part of the grid its figure-4 impact speeds cover is drawn bold.
# The known results of validation.py (closed forms, the elastic-limit series, the Pade form) are
# drawn over the curve of the variant they apply to.

# %%
import numpy as np
import pandas as pd
from restitution_workflow.law_names import law_name
from restitution_workflow.pipeline import save_figure, setup_matplotlib, start

start(snakemake)
plt = setup_matplotlib()

KNOWN = {"eps_dashpot": ("closed form",   # after the law's name: "linear dashpot: closed form"
                         dict(ls="none", marker="o", ms=4, mfc="none")),
         "eps_equal_exponents": (r"$\alpha = \gamma$, closed form", dict(ls="none", marker="s", ms=4, mfc="none")),
         "eps_elastic_series": ("two-term elastic expansion + end-of-contact term", dict(ls="--", lw=1.2)),
         "eps_pade": ("Padé form attributed to Müller & Pöschel", dict(ls=":", lw=1.8))}

# %%
p = snakemake.params
# below: each variant's eps divided by the first variant's on the common grid, since on the log axes above
# the curves of laws with similar k run on top of each other
fig, (ax, ax_ratio) = plt.subplots(2, 1, figsize=(5.6, 7.4), sharex=True, height_ratios=(3, 1.3))
first = None
colors = plt.cm.tab10(np.arange(len(p.variants)) % 10)
LINESTYLES = ["-", "--", "-.", (0, (5, 1.5, 1, 1.5, 1, 1.5))]
MARKERS = ["o", "s", "^", "v", "D"]
for i, (name, known_file, curve_file) in enumerate(zip(p.variants, snakemake.input.known, snakemake.input.curves)):
    known = pd.read_csv(known_file)
    curve = pd.read_csv(curve_file)
    alpha, gamma = p.exponents[name]
    # a line style and hollow markers of its own (offset per variant): at small Omega the variants' curves
    # run close together (eps ~ k Omega with similar k), and colour alone would not tell them apart
    ax.plot(known["omega"], known["eps_reference"], color=colors[i], lw=1.4, ls=LINESTYLES[i % len(LINESTYLES)],
            marker=MARKERS[i % len(MARKERS)], markersize=4.5, markerfacecolor="none",
            markevery=(i % 3, 3), label=rf"{law_name(name, tex=False)} ($\alpha = {alpha}$, $\gamma = {gamma}$)")
    if first is None:
        first = known
    if not np.allclose(known["omega"], first["omega"], rtol=1e-12, atol=0):
        raise SystemExit(f"variant {name}: its validation grid is not the first variant's")
    ax_ratio.plot(known["omega"], known["eps_reference"] / first["eps_reference"], color=colors[i], lw=1.4,
                  ls=LINESTYLES[i % len(LINESTYLES)], marker=MARKERS[i % len(MARKERS)], markersize=4.5,
                  markerfacecolor="none", markevery=(i % 3, 3))
    lo, hi = curve["omega"].min(), curve["omega"].max()
    if hi > lo * (1 + 1e-9):
        ax.plot(curve["omega"], curve["eps"], color=colors[i], lw=3.5, alpha=0.6, solid_capstyle="butt")
    else:  # one Omega for every g (alpha - 1 - 2 gamma = 0)
        ax.plot([lo], [curve["eps"].iloc[0]], "D", color=colors[i], ms=6, alpha=0.7)
    for col, (label, style) in KNOWN.items():
        if col in known:
            ok = np.isfinite(known[col]) & (known[col] > 0)
            ax.plot(known["omega"][ok], known[col][ok], color="black", label=f"{law_name(name, tex=False)}: {label}", **style)
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_ylim(max(ax.get_ylim()[0], 1e-4), 1.5)
ax.set_xlim(min(p.grid["omega_min"], ax.get_xlim()[0]), p.grid["omega_max"])
ax_ratio.set_xlabel(r"$\Omega$")
ax_ratio.set_ylabel(rf"$\varepsilon$ / $\varepsilon$ of the first law")
ax.set_ylabel(r"coefficient of restitution $\varepsilon$")
# below the axes: inside, it covered the curves at small Omega
fig.legend(*ax.get_legend_handles_labels(), loc="lower center", ncol=1, frameon=False)
fig.tight_layout(rect=(0, 0.2, 1, 1))
save_figure(fig, snakemake.output.pdf, snakemake.output.png, width=0.8)

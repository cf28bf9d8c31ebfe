# %% [markdown]
# # Figure 4: coefficient of restitution versus impact speed
#
# The reference eps(g) from one integration per impact speed, and eps implied by each relation
# Omega~ = c0 + c1 Omega + c2 Omega^2 of the variant: the paper's printed c's (paper's exponents
# only), our c's from the paper's procedure (one documented reading) and our least-squares c's.
# The curves are computed by eps_compare.py (`restitution.core.connection.eps_from_connection`); this
# script only draws them. Where a relation gives no real eps (Omega~ <= 0) its curve has a gap.
# When alpha - 1 - 2 gamma = 0, Omega and eps do not depend on g and eps(g) is a flat line: the
# figure then shows what does vary, eps(Omega) on the validation grid, with this material's Omega.

# %%
import numpy as np
import pandas as pd
from matplotlib.transforms import ScaledTranslation
from scipy.optimize import brentq
from restitution_workflow.latex import sci
from restitution_workflow.pipeline import TEXT_WIDTH_PT, save_figure, setup_matplotlib, start, write_text

from restitution.core.connection import eps_from_connection
from restitution.core.exponents import Exponents

start(snakemake)
plt = setup_matplotlib()
# drawn at the size it prints (width: a fraction of TEXT_WIDTH_PT): 10.5 pt puts tick exponents and legend
# indices (0.7 of it) above 7 pt
plt.rcParams.update(dict.fromkeys(("axes.labelsize", "xtick.labelsize", "ytick.labelsize", "legend.fontsize",
                                   "axes.titlesize"), 10.5))
# the article prints it at 0.9 of the text width (the variants at the full width): drawn at that size, so that the
# sizes above print as set; at the full width its tick exponents printed at 6.7 pt (referee r19)
PRINT_WIDTH = 0.9

STYLE = {"printed": dict(ls="--", color="tab:red"), "derived": dict(ls="-.", color="tab:blue"),
         "fitted": dict(ls=":", color="tab:green", lw=2.2)}

# %%
p = snakemake.params
ex = Exponents.parse(p.exponents["alpha"], p.exponents["gamma"])
curves = pd.read_csv(snakemake.input.curves)
errors = pd.read_csv(snakemake.input.errors, keep_default_na=False)


def finish(fig, ax, xlabel, loc):
    """Axis labels, and the legend below the axes, in two columns (beside the axes, it left the plot a third of
    the text width; inside, it covered part of the range the relations' curves run through). ``loc`` is kept
    for the figure of eps(Omega), whose few markers leave a corner empty."""
    ax.set_xlabel(xlabel)
    # short: the full name ran taller than the axes of the flat eps(g) figure (referee r31)
    ax.set_ylabel(r"restitution $\varepsilon$")
    ax.set_title(rf"$\alpha = {p.exponents['alpha']}$, $\gamma = {p.exponents['gamma']}$")
    if loc is None:
        # hung below the x label by a fixed distance in points, measured once drawn: at a fixed fraction of the
        # axes height (-0.3) it touched the label where that runs deeper (subscripts; supplement Fig. S9, r22)
        fig.set_layout_engine("tight")
        fig.canvas.draw()
        label_depth = (ax.get_window_extent().y0 - ax.xaxis.label.get_window_extent().y0) * 72.0 / fig.dpi
        below = ax.transAxes + ScaledTranslation(0.0, -(label_depth + 4.0) / 72.0, fig.dpi_scale_trans)
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, 0.0), bbox_transform=below, ncol=2, frameon=False,
                  borderaxespad=0)
    else:
        ax.legend(loc=loc, frameon=False)
    fig.set_layout_engine("tight")
    return fig


def draw_eps_of_omega():
    """alpha - 1 - 2 gamma = 0: eps(Omega) on the validation grid, this material's Omega marked."""
    known = pd.read_csv(snakemake.input.known)
    fig, ax = plt.subplots(figsize=(PRINT_WIDTH * TEXT_WIDTH_PT / 72.27, PRINT_WIDTH * 2.8))
    ax.loglog(known["omega"], known["eps_reference"], color="black", lw=2.6, label="reference integration")
    closed = [c for c in known.columns if c.startswith("eps_") and c != "eps_reference"]
    for c, marker in zip(closed, "osD^"):
        ax.loglog(known["omega"], known[c], ls="none", marker=marker, mfc="none", color="tab:orange",
                  label=f"closed form ({c[4:]})")
    w = float(curves["omega"].iloc[0])
    ax.plot([w], [float(curves["eps_reference"].iloc[0])], "o", color="tab:red", ms=8,
            label=rf"this material: $\Omega = {w:.4g}$ for every $g$")
    return finish(fig, ax, r"$\Omega$ (here independent of the impact speed)", "lower right")


def draw_eps_of_g():
    """eps(g) from the reference and from every relation."""
    # 3.05 in: at 2.95 the axes were four times as wide as high (referee r31); at 3.4 the article ran a page over
    fig, ax = plt.subplots(figsize=(PRINT_WIDTH * TEXT_WIDTH_PT / 72.27, PRINT_WIDTH * 3.05))
    ax.plot(curves["g"], curves["eps_reference"], color="black", lw=2.6, label="reference integration")
    drawn = [curves["eps_reference"].to_numpy()]
    for _, rel in errors.iterrows():
        col = f"eps_{rel['kind']}"
        if col not in curves:
            continue
        style = {"lw": 1.6, **STYLE[rel["kind"]]}
        # the relations name Kim's paper "the paper"; in a figure of this article that would be ours
        ax.plot(curves["g"], curves[col], label=rel["label"].replace("paper's", "Kim's"), **style)
        drawn.append(curves[col].to_numpy())
    ax.axvline(p.g_figure, color="grey", ls=":", lw=1)
    ax.axhline(1.0, color="grey", ls="-", lw=0.8)
    if p.fit_g_range:
        ax.axvspan(p.fit_g_range["min"], p.fit_g_range["max"], color="tab:green", alpha=0.07, lw=0)
    ax.set_xscale("log")
    ax.set_yscale("log")
    # Room for every curve, but not for a relation that runs off to 0 or infinity.
    values = np.concatenate(drawn)
    values = values[np.isfinite(values) & (values > 0)]
    lo, hi = max(0.5 * values.min(), 1e-4), min(max(3.0, 1.5 * values.max()), 30.0)
    ax.set_ylim(lo, 3 * hi)   # 3: room for the label of g above the curves
    clip["top"] = 3 * hi
    for _, rel in errors.iterrows():
        col = f"eps_{rel['kind']}"
        if col in curves and (curves[col] > clip["top"]).any():
            clip["curves"].append(col)
            # the slowest speed at which the drawn line (straight between grid points on these log axes) is
            # still inside the axes, coming from above: where the axes start to cut it off
            y = curves[col].to_numpy()
            g = curves["g"].to_numpy()
            out = np.nonzero(y > clip["top"])[0]
            i = out[-1]
            if i + 1 < len(y) and np.isfinite(y[i + 1]):
                # where the relation itself reaches the top, between the two sampled speeds (the drawn line,
                # straight between them, left it at 0.0058 where the relation does at 0.0055: referee r33).
                # Omega is a power of g, so its logarithm is exactly linear in log g between the samples
                c = [float(rel[k]) for k in ("c0", "c1", "c2")]
                lw = np.log(curves["omega"].to_numpy()[[i, i + 1]])
                lg = np.log(g[[i, i + 1]])

                def above_top(x):
                    omega = float(np.exp(lw[0] + (x - lg[0]) * (lw[1] - lw[0]) / (lg[1] - lg[0])))
                    return np.log(float(eps_from_connection(ex, omega, c)) / clip["top"])
                clip["below_g"] = float(np.exp(brentq(above_top, lg[0], lg[1], xtol=1e-14)))
    # the label sits at the top of its line, where no curve runs at g = 0.1
    ax.annotate(rf"$g = {p.g_figure:g}$", (p.g_figure, 1.0), xycoords=("data", "axes fraction"), xytext=(3, -3),
                textcoords="offset points", va="top", color="grey")
    ax.set_xlim(curves["g"].min(), curves["g"].max())
    return finish(fig, ax, r"impact speed $g$ (in the units of $D_1$, $D_2$)", None)


# %%
# What the axes cut off at the top (the caption of the article's figure says it; referee r23): the top of the axes,
# the curves that leave it, and the speed below which the one that does is cut off
clip = {"top": None, "curves": [], "below_g": None}
fig = draw_eps_of_omega() if curves["omega"].nunique() == 1 else draw_eps_of_g()
save_figure(fig, snakemake.output.pdf, snakemake.output.png, width=PRINT_WIDTH)
if clip["curves"] not in ([], ["eps_printed"]) or (clip["curves"] and clip["below_g"] is None):
    # the article's caption says the printed coefficients' curve, and only it, is cut off below a speed
    raise SystemExit(f"fig4: curves clipped {clip['curves']} (cut off below g = {clip['below_g']}): "
                     "the caption names the printed coefficients' curve alone, cut off below a speed")
macros = {
    "FigEpsAxisTop": sci(clip["top"], 2) if clip["top"] else "---",
    "FigEpsClipBelowG": sci(clip["below_g"], 2) if clip["below_g"] else "---",
}
write_text(snakemake.output.values, "\n".join(rf"\newcommand{{\{k}}}{{{v}}}" for k, v in macros.items()))

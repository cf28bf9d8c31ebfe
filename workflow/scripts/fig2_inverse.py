# %% [markdown]
# # Figure 2: inverse collision, reference vs perturbation series
#
# The reference is the forward trajectory at g_figure run backwards from the end of contact
# and rescaled into the inverse variables (see reference_trajectories.py): it starts at
# x~(0) = x~_c > 0 with x~'(0) = 1. The series are the paper's, with x~(0) = 0, evaluated at
# Omega~ = Omega eps^((alpha-1-2 gamma)/(gamma+1)). The bottom axis is the inverse time tau~;
# the top axis gives the same instants in the forward time tau = tau_c - tau~ eps^(-gamma/(gamma+1)).

# %%
from fractions import Fraction

import numpy as np
import pandas as pd
from restitution_workflow.pipeline import order_style, read_json, save_figure, setup_matplotlib, start

from restitution.core.series import perturbation_series

start(snakemake)
plt = setup_matplotlib()

# %%
p = snakemake.params
ref = pd.read_csv(snakemake.input.trajectory)
summary = read_json(snakemake.input.summary)
inv = summary["inverse"]
series = perturbation_series(p.exponents["alpha"], p.exponents["gamma"], omega_order=p.omega_order,
                             max_power=p.max_power, direction="inverse")
omega_t = inv["omega_tilde"]
gamma = float(Fraction(p.exponents["gamma"]))
t_scale = summary["eps"] ** (gamma / (gamma + 1.0))  # tau~ = t_scale (tau_c - tau)
tau_t = np.linspace(0.0, inv["tau_tilde_end"], 801)
x_max = float(ref["x_tilde"].max())

# %%
fig, (ax, ax_err) = plt.subplots(2, 1, sharex=True, figsize=(5.6, 6.3),
                                 gridspec_kw={"height_ratios": [3, 1.5]})
ax.plot(ref["tau_tilde"], ref["x_tilde"], color="black", lw=2.4,
        label=r"forward run reversed (from $\tilde x_c$)")
has_zero = "x_tilde_from_zero" in ref
if has_zero:
    ax.plot(ref["tau_tilde"], ref["x_tilde_from_zero"], color="grey", lw=1.6,
            label=r"inverse equation from $\tilde x = 0$")
    target = ref["x_tilde_from_zero"].to_numpy()
else:
    target = ref["x_tilde"].to_numpy()
grid = ref["tau_tilde"].to_numpy()
for n in range(p.omega_order + 1):
    ax.plot(tau_t, series.evaluate(tau_t, omega_t, order=n), lw=1.3, label=rf"series to $\tilde\Omega^{{{n}}}$",
            **order_style(n, tau_t.size))
    err = np.abs(series.evaluate(grid, omega_t, order=n) - target)
    ax_err.semilogy(grid, np.maximum(err, 1e-16), lw=1.1, **order_style(n, grid.size))
for a in (ax, ax_err):
    a.axvline(inv["tau_tilde_b"], color="grey", ls=":", lw=1)
ax.annotate(r"$\tilde\tau_b$", (inv["tau_tilde_b"], 0.05 * x_max), xytext=(4, 0),
            textcoords="offset points", color="grey")
ax.set_ylim(-0.1 * x_max, p.plot["y_margin"] * x_max)
ax.set_xlim(0.0, inv["tau_tilde_end"])
ax.set_ylabel(r"inverse deformation $\tilde x$")
top = ax.secondary_xaxis("top", functions=(lambda s: summary["tau_c"] - s / t_scale,
                                           lambda t: (summary["tau_c"] - t) * t_scale))
top.set_xlabel(r"forward time $\tau = \tau_c - \tilde\tau\,\varepsilon^{-\gamma/(\gamma+1)}$")
# what is drawn, as the legend's title below the axes: inside them the curves ran through it
fig.legend(*ax.get_legend_handles_labels(), loc="lower center", ncol=2, frameon=False,
           title=rf"inverse collision, $g = {summary['g']:g}$, $\tilde\Omega = {omega_t:.4f}$; "
                 rf"each $\tilde x_n$ to $\tilde\tau^{{{p.max_power}}}$",
           title_fontsize=11)   # its exponent >= 7 pt printed at 0.75 of the text width
ax_err.set_ylim(1e-10, 10)
ax_err.set_xlabel(r"inverse time $\tilde\tau$ (from the end of contact)")
ax_err.set_ylabel(r"$|\tilde x_{\rm series} - \tilde x_{\rm ref}|$")   # ref: the grey curve where drawn
fig.align_ylabels()
fig.set_layout_engine("tight", rect=(0, 0.2, 1, 1))   # redone when save_figure resizes
save_figure(fig, snakemake.output.pdf, snakemake.output.png, width=0.75)   # the variants' width; the main one: 0.8

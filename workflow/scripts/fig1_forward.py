# %% [markdown]
# # Figure 1: forward collision, reference vs perturbation series
#
# x(tau) at the impact speed g_figure from the reference integration, and the perturbation
# solution sum_{n <= N} Omega^n x_n(tau) for N = 0..omega_order, each x_n kept up to
# tau^max_power (the paper prints the terms up to tau^11). The lower panel shows how far each
# truncation is from the reference.

# %%
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
series = perturbation_series(p.exponents["alpha"], p.exponents["gamma"], omega_order=p.omega_order,
                             max_power=p.max_power, direction="forward")
omega = summary["omega"]
tau_end = p.plot["tau_max_forward"] or summary["tau_c"]
tau = np.linspace(0.0, tau_end, 801)
x_max = float(ref["x"].max())

# %%
fig, (ax, ax_err) = plt.subplots(2, 1, sharex=True, figsize=(5.6, 5.6),
                                 gridspec_kw={"height_ratios": [3, 1.5]})
ax.plot(ref["tau"], ref["x"], color="black", lw=2.4, label="reference integration")
ref_on_grid = ref["tau"].to_numpy()
for n in range(p.omega_order + 1):
    label = rf"series to $\Omega^{{{n}}}$"
    ax.plot(tau, series.evaluate(tau, omega, order=n), lw=1.3, label=label, **order_style(n, tau.size))
    err = np.abs(series.evaluate(ref_on_grid, omega, order=n) - ref["x"].to_numpy())
    ax_err.semilogy(ref_on_grid, np.maximum(err, 1e-16), lw=1.1, **order_style(n, ref_on_grid.size))
for a in (ax, ax_err):
    a.axvline(summary["tau_b"], color="grey", ls=":", lw=1)
ax.annotate(r"$\tau_b$", (summary["tau_b"], 0.05 * x_max), xytext=(4, 0), textcoords="offset points",
            color="grey")
ax.set_ylim(-0.1 * x_max, p.plot["y_margin"] * x_max)
ax.set_xlim(0.0, tau_end)
ax.set_ylabel(r"scaled deformation $x = \xi / A$")
ax.set_title(rf"forward collision, $g = {summary['g']:g}$, $\Omega = {omega:.4f}$;" "\n"
             rf"each $x_n$ to $\tau^{{{p.max_power}}}$", fontsize=11)
fig.legend(*ax.get_legend_handles_labels(), loc="lower center", ncol=2, frameon=False)
ax_err.set_ylim(1e-10, 10)
ax_err.set_xlabel(r"scaled time $\tau = t / t_*$")
ax_err.set_ylabel(r"$|x_{\rm series} - x_{\rm ref}|$")
fig.align_ylabels()
fig.set_layout_engine("tight", rect=(0, 0.11, 1, 1))   # redone when save_figure resizes
save_figure(fig, snakemake.output.pdf, snakemake.output.png, width=0.75)   # the variants' width; the main one: 0.8

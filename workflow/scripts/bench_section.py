# %% [markdown]
# # Speed against accuracy (from the recorded `make bench` table)
#
# One row per method and setting for the main variant's exponents: cost per evaluation, and the
# maximum and median relative error in eps against the mpmath reference over the benchmark's fixed
# Omega set. The plot puts every method on the error-cost plane; lower left is better.

# %%
import math

import pandas as pd
from restitution_workflow.latex import esc, sci
from restitution_workflow.pipeline import save_figure, setup_matplotlib, start, write_text

start(snakemake)
plt = setup_matplotlib()

# %%
ex = snakemake.params.exponents
bench = pd.read_csv(snakemake.input.table, dtype={"alpha": str, "gamma": str})
rows = bench[(bench["alpha"] == ex["alpha"]) & (bench["gamma"] == ex["gamma"])]
# The reference itself (error 0 by definition) and the bulk call (no error column) are not methods
# to compare on this plane.
rows = rows[rows["max_rel_err"].notna() & (rows["max_rel_err"] > 0)]


def err(x):
    return "no value" if not math.isfinite(x) else sci(float(x), 2)


lines = [r"\begin{tabular}{llrrrlr}", r"\toprule",
         r"method & setting & evaluations/s & max rel.\ error & median rel.\ error & $\Omega$ domain & points \\",
         r"\midrule"]
for _, r in rows.iterrows():
    # each method is measured on the points of the fixed held-out set that lie in its own domain
    domain = f"{sci(float(r['omega_min']), 1)}--{sci(float(r['omega_max']), 1)}"
    lines.append(f"{esc(r['method'])} & {esc(str(r['setting']))} & {sci(float(r['evals_per_s']), 2)} & "
                 f"{err(r['max_rel_err'])} & {err(r['median_rel_err'])} & {domain} & {int(r['n_points'])} \\\\")
lines += [r"\bottomrule", r"\end{tabular}"]
write_text(snakemake.output.table, "\n".join(lines))

# %%
fig, ax = plt.subplots()
# More methods than a colour cycle has colours: each gets its own colour and marker as well.
colors = plt.get_cmap("tab20").colors
markers = "os^DvP*X<>hp"
# Methods whose points coincide on these axes (the perturbative route gives the same error at nearly
# the same cost at every order) are drawn as concentric hollow markers of different shapes, largest first,
# so that every legend entry stays visible: the rank of a method among those at its (rounded) place.
place_rank, seen = {}, {}
for method, group in rows.groupby("method", sort=True):
    finite = group[group["max_rel_err"].apply(math.isfinite)]
    if not finite.empty:
        key = (round(math.log10(finite["cost_per_eval_s"].iloc[0]) * 2), round(math.log10(finite["max_rel_err"].iloc[0]) * 2))
        place_rank[method] = seen.get(key, 0)
        seen[key] = place_rank[method] + 1
for i, (method, group) in enumerate(rows.groupby("method", sort=True)):
    finite = group[group["max_rel_err"].apply(math.isfinite)]
    if finite.empty:
        continue
    ax.plot(finite["cost_per_eval_s"], finite["max_rel_err"], marker=markers[i % len(markers)],
            markersize=max(3.0, 13.0 - 3.0 * place_rank[method]), markerfacecolor="none", markeredgewidth=1.2,
            color=colors[(2 * i) % 20 + (i // 10) % 2], linestyle="-", label=method)
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("cost per evaluation (s, one core, recorded)")
ax.set_ylabel(r"max relative error in $\varepsilon$")
ax.set_title(rf"$\alpha = {ex['alpha']}$, $\gamma = {ex['gamma']}$: error against cost")
fig.legend(*ax.get_legend_handles_labels(), loc="lower center", ncol=3, frameon=False)
fig.set_size_inches(5.6, 5.4)
fig.tight_layout(rect=(0, 0.22, 1, 1))
save_figure(fig, snakemake.output.pdf, snakemake.output.png)

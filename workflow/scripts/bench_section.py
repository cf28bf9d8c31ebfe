# %% [markdown]
# # Speed against accuracy (from the recorded `make bench` table)
#
# One row per method and setting for the main variant's exponents: cost per evaluation, and the
# maximum and median relative error in eps against the mpmath reference over the benchmark's fixed
# Omega set. The plot puts every method on the error-cost plane; lower left is better.

# %%
import math
import re

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


# What each recorded method is, in the words of the manuscript (the recorded names are the library's).
SHOWN = {
    "master": r"Chebyshev in $\ln\Omega$",
    "uniform": "uniform approx.",
    "closed-form": "uniform approx.",   # the uniform rung's name in runs recorded before its rename
    "viscous": "viscous limit",
    "elastic": "elastic limit",
    "paper-c": "Kim, printed $c_i$",
    "fitted-c": "Kim, fitted $c_i$",
    "integrator": "DOP853, compiled",
    "solve_ivp plain": r"DOP853, plain $x(\tau)$",
    "collide (scipy)": "DOP853, regularised",
}
READING_PREFIX = "perturbation-"
# The reading of Kim's procedure behind each perturbation row, as the run recorded it in its note ("paper's
# procedure, reading C-N1-K2-Dlinear"): the supplement names the rows by these labels, which are those of its
# readings section, not by the benchmark's short names (N1 ... N4 alone named no row of the readings table).
READING_LABEL = {r["method"]: m.group(1) for _, r in rows.iterrows()
                 if str(r["method"]).startswith(READING_PREFIX)
                 and (m := re.search(r"reading (\S+)", str(r.get("note", ""))))}


def reading_label(method, tex=True):
    """The label of the reading of Kim's procedure behind a perturbation row (typewriter type in the table;
    plain in the figure, whose text matplotlib sets without TeX)."""
    return rf"\texttt{{{READING_LABEL[method]}}}" if tex else READING_LABEL[method]


def reading_range(labels):
    """Readings that differ only in their order N as one legend entry (C-N1..N4-K2-Dlinear): four labels in
    full made the legend too wide to print at 7 pt.

    Examples
    --------
    >>> reading_range(["C-N1-K2-Dlinear", "C-N2-K2-Dlinear", "C-N4-K2-Dlinear"])
    'C-N1..N4-K2-Dlinear'
    >>> reading_range(["C-N1-K2-Dlinear", "P-N2-K2-Dprinted"])
    'C-N1-K2-Dlinear, P-N2-K2-Dprinted'
    """
    parts = [re.fullmatch(r"(.*-N)(\d+)(-.*)", label) for label in labels]
    if len(labels) > 1 and all(parts) and len({(m.group(1), m.group(3)) for m in parts}) == 1:
        return f"{parts[0].group(1)}{parts[0].group(2)}..N{parts[-1].group(2)}{parts[0].group(3)}"
    return ", ".join(labels)


def shown(method, tex=True):
    """The manuscript's name of a recorded method; a perturbation row is named by its reading's label."""
    if method.startswith(READING_PREFIX):
        return "Kim, " + reading_label(method, tex)
    return SHOWN.get(method, esc(method))


def power_of_ten(text: str) -> str:
    """1e-06, 1e6 as $10^{-6}$, $10^{6}$."""
    mant, _, exp = text.lower().partition("e")
    head = "" if float(mant) == 1 else rf"{mant} \times "
    return rf"${head}10^{{{int(exp)}}}$"


def setting_tex(setting: str) -> str:
    """A recorded setting (the benchmark's own shorthand) as the manuscript writes it."""
    fixed_names = {"C1,C2,E": r"$C_1, C_2$ and $\beta\mu^q$", "C1 only": r"$C_1$ only", "c0-c2": r"$c_0, c_1, c_2$",
                   "Mueller-Poeschel": r"as in~\cite{granularsjl}"}
    if setting in fixed_names:
        return fixed_names[setting]
    parts = []
    for part in setting.split(", "):
        if m := re.fullmatch(r"r?tol=([0-9.e+-]+)", part):
            parts.append("tolerance " + power_of_ten(m.group(1)))
        elif m := re.fullmatch(r"digits=(\d+)", part):
            parts.append(f"{m.group(1)} digits")
        elif m := re.fullmatch(r"(\d+)x(\d+) (.*)", part):
            parts.append(rf"${m.group(1)} \times {m.group(2)}$ {esc(m.group(3))}")
        elif m := re.fullmatch(r"([0-9.]+e[0-9+-]+) (.*)", part):
            parts.append(f"{power_of_ten(m.group(1))} {esc(m.group(2))}")
        else:
            parts.append(esc(part))
    return ", ".join(parts)


def bound(x: float) -> str:
    """An end of an Omega domain: a power of ten as one, anything else to four digits."""
    k = round(math.log10(x))
    return rf"$10^{{{k}}}$" if abs(x / 10.0 ** k - 1.0) < 1e-9 else sci(x, 4)


def err(x):
    return "no value" if not math.isfinite(x) else sci(float(x), 2)


lines = [r"\begin{tabular}{llrrrlr}", r"\toprule",
         r"method & setting & evaluations/s & max rel.\ error & median rel.\ error & $\Omega$ domain & points \\",
         r"\midrule"]
for _, r in rows.iterrows():
    # each method is measured on the points of the fixed held-out set that lie in its own domain
    domain = f"{bound(float(r['omega_min']))}--{bound(float(r['omega_max']))}"
    setting = setting_tex(str(r["setting"]))
    lines.append(f"{shown(r['method'])} & {setting} & {sci(float(r['evals_per_s']), 2)} & "
                 f"{err(r['max_rel_err'])} & {err(r['median_rel_err'])} & {domain} & {int(r['n_points'])} \\\\")
lines += [r"\bottomrule", r"\end{tabular}"]
write_text(snakemake.output.table, "\n".join(lines))


# %% the few figures of the table the article's cost sentence quotes (same recorded run)
def one(method, setting=None):
    pick = rows[rows["method"] == method]
    if setting is not None:
        pick = pick[pick["setting"] == setting]
    assert len(pick) == 1, (method, setting, len(pick))
    return pick.iloc[0]


form = one("uniform" if (rows["method"] == "uniform").any() else "closed-form")   # renamed, see SHOWN
master = one("master")
compiled, plain = one("integrator", "rtol=1e-12"), one("solve_ivp plain", "rtol=1e-12")
# the sentence compares the two "on the same points" and calls the interpolant "as fast or faster": hold the
# recorded run to both, so that a new recording that breaks either stops here instead of printing it
same = ["omega_min", "omega_max", "n_points"]
if [float(form[c]) for c in same] != [float(master[c]) for c in same]:
    raise SystemExit("the article's cost sentence compares the formula and the interpolant on the same points: "
                     f"they were measured on {[form[c] for c in same]} and {[master[c] for c in same]}")
if float(master["evals_per_s"]) < float(form["evals_per_s"]):
    raise SystemExit("the article calls the interpolant as fast as the formula or faster: the recorded run has it slower")
macros = {
    # the point set both were measured on (Table S13's held-out set within their domain)
    "BenchSamePoints": str(int(form["n_points"])),
    "BenchSameOmegaMin": bound(float(form["omega_min"])).strip("$"),
    "BenchSameOmegaMax": bound(float(form["omega_max"])).strip("$"),
    "BenchFormEvals": sci(float(form["evals_per_s"]), 2),
    "BenchFormErr": sci(float(form["max_rel_err"]), 2),
    "BenchMasterEvals": sci(float(master["evals_per_s"]), 2),
    "BenchMasterErr": sci(float(master["max_rel_err"]), 2),
    "BenchCompiledMicro": sci(float(compiled["cost_per_eval_s"]) * 1e6, 2),
    "BenchCompiledErr": sci(float(compiled["max_rel_err"]), 2),
    "BenchPlainMilli": sci(float(plain["cost_per_eval_s"]) * 1e3, 2),
    "BenchPlainErr": sci(float(plain["max_rel_err"]), 2),
}
write_text(snakemake.output.values, "\n".join(
    ["% generated by workflow/scripts/bench_section.py -- do not edit"]
    + [rf"\newcommand{{\{name}}}{{{value}}}" for name, value in macros.items()]))

# %%
fig, ax = plt.subplots()
# More methods than a colour cycle has colours: each gets its own colour and marker as well.
colors = plt.get_cmap("tab20").colors
markers = "os^DvP*X<>hp"
# Methods whose points coincide on these axes (the perturbative route gives the same error at nearly the same
# cost at every order) are drawn once, with one legend entry naming them all: concentric markers of the same
# point could not be told apart. One point: cost and error within a twentieth of a decade of each other.
def same_point(a, b):
    return all(abs(math.log10(a[c].iloc[0] / b[c].iloc[0])) < 0.05 for c in ("cost_per_eval_s", "max_rel_err"))


entries = []  # [methods, frame]
for method, group in rows.groupby("method", sort=True):
    finite = group[group["max_rel_err"].apply(math.isfinite)]
    if finite.empty:
        continue
    twin = next((e for e in entries if len(finite) == len(e[1]) == 1 and same_point(finite, e[1])), None)
    if twin is not None:
        twin[0].append(method)
    else:
        entries.append([[method], finite])
for i, (methods, finite) in enumerate(entries):
    if len(methods) == 1:
        label = shown(methods[0], tex=False)
    elif all(m.startswith(READING_PREFIX) for m in methods):
        label = "Kim, " + reading_range([reading_label(m, tex=False) for m in methods]) + " (one point)"
    else:
        label = ", ".join(shown(m, tex=False) for m in methods) + " (one point)"
    ax.plot(finite["cost_per_eval_s"], finite["max_rel_err"], marker=markers[i % len(markers)], markersize=7.0,
            markerfacecolor="none", markeredgewidth=1.2, color=colors[(2 * i) % 20 + (i // 10) % 2], linestyle="-",
            label=label)
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("cost per evaluation (s, one core, one timing run)")
ax.set_ylabel(r"max relative error in $\varepsilon$")
ax.set_title(rf"$\alpha = {ex['alpha']}$, $\gamma = {ex['gamma']}$: error against cost")
fig.legend(*ax.get_legend_handles_labels(), loc="lower center", ncol=2, frameon=False)
fig.set_size_inches(5.6, 5.8)
fig.tight_layout(rect=(0, 0.24, 1, 1))
save_figure(fig, snakemake.output.pdf, snakemake.output.png, width=0.8)

# %% [markdown]
# # The uniform closed form for every exponent pair of the stability atlas
#
# For alpha > gamma the library fits the form and measures its bound on points it did not use
# (restitution.fast.uniform_build; the variants' pairs come from rule uniform_form, which made the
# same call); alpha = gamma has an exact closed form and alpha < gamma none.
# Where gamma < alpha < 2 gamma + 1 the overlap end rule has its own form, built the same way.
# One row per pair, as CSV and as the appendix's LaTeX table.

# %%
from fractions import Fraction

import pandas as pd
from common.latex import frac_tex, sci
from common.pipeline import read_json, start, write_csv, write_text

from restitution.core.errors import ParameterError
from restitution.core.exponents import as_exponents
from restitution.core.uniform import UniformForm, skeleton
from restitution.fast.uniform_build import build_uniform

start(snakemake)

# %% the forms rule uniform_form built for the variants, by (alpha, gamma, end rule)
built = {}
for path in [*snakemake.input.forms, *snakemake.input.overlap_forms]:
    d = read_json(path)
    if d["available"]:
        f = UniformForm.from_dict(d)
        built[(f.alpha, f.gamma, f.end)] = f


def form(alpha, gamma, end="force"):
    """The uniform form for the pair and rule: a variant's as built, else built here."""
    ex = as_exponents(alpha, gamma)
    return built.get((ex.alpha, ex.gamma, end)) or build_uniform(ex, None, end=end)


# %%
rows = []
for alpha, gamma in snakemake.params.pairs:
    row = {"alpha": alpha, "gamma": gamma}
    try:
        skeleton(alpha, gamma)
    except ParameterError as why:
        row["form"] = "exact" if Fraction(alpha) == Fraction(gamma) else "none"
        row["reason"] = why.allowed
    else:
        print(f"alpha={alpha}, gamma={gamma}", flush=True)
        f = form(alpha, gamma)
        m = f.measured
        row.update(form="uniform", n_coef=len(f.coef), sigma=f.sigma, m0=f.m0, m1=f.m1, bound_eps=f.bound_eps,
                   bound_one_minus_eps=f.bound_one_minus_eps, test_eps=m["test_eps"],
                   test_one_minus_eps=m["test_one_minus_eps"], selection_eps=m["selection_eps"])
        try:
            skeleton(alpha, gamma, "overlap")
        except ParameterError:
            row["overlap_form"] = "none (the bodies can stick)"
        else:
            o = form(alpha, gamma, "overlap")
            row.update(overlap_form="uniform", overlap_n_coef=len(o.coef), overlap_bound_eps=o.bound_eps,
                       overlap_bound_one_minus_eps=o.bound_one_minus_eps)
    rows.append(row)
table = pd.DataFrame(rows)
write_csv(snakemake.output.csv, table)

# %%
lines = [r"\begin{tabular}{llllllll}", r"\toprule",
         r"$\alpha$ & $\gamma$ & $(\sigma, m_0, m_1)$ & $n + 1$ & bound $\varepsilon$ & bound $1-\varepsilon$ & largest test error "
         r"& overlap rule: $n + 1$, bounds \\",
         r"\midrule"]
for r in rows:
    ab = f"{frac_tex(Fraction(r['alpha']))} & {frac_tex(Fraction(r['gamma']))}"
    if r["form"] == "uniform":
        lines.append(rf"{ab} & ({sci(r['sigma'], 3)}, {r['m0']}, {r['m1']}) & {r['n_coef']} & {sci(r['bound_eps'], 2)} & "
                     rf"{sci(r['bound_one_minus_eps'], 2)} & {sci(max(r['test_eps'], r['test_one_minus_eps']), 2)} & "
                     + (rf"{r['overlap_n_coef']}: {sci(r['overlap_bound_eps'], 2)}, {sci(r['overlap_bound_one_minus_eps'], 2)} \\"
                        if r["overlap_form"] == "uniform" else r"sticks \\"))
    else:
        what = "exact closed form" if r["form"] == "exact" else "no uniform form (first viscous correction unknown)"
        lines.append(rf"{ab} & \multicolumn{{6}}{{l}}{{{what}}} \\")
lines += [r"\bottomrule", r"\end{tabular}"]
write_text(snakemake.output.tex, "\n".join(lines) + "\n")

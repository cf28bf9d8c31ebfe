# %% [markdown]
# # The uniform closed form for every exponent pair of the stability atlas
#
# For alpha > gamma the library fits the form and measures its bound on points it did not use
# (restitution.fast.uniform_build); alpha = gamma has an exact closed form and alpha < gamma none.
# Where gamma < alpha < 2 gamma + 1 the overlap end rule has its own form, built the same way.
#
# Two rules run this script. `uniform_shard` builds the forms of its share of the pairs no variant
# has and writes them as JSON; `uniform_atlas` reads those and the variants' forms (rule
# uniform_form) and writes one row per pair, as CSV and as the appendix's LaTeX table.

# %%
from fractions import Fraction

import pandas as pd
from common.latex import frac_tex, sci
from common.pipeline import read_json, start, write_csv, write_json, write_text

from restitution.core.errors import ParameterError
from restitution.core.exponents import as_exponents
from restitution.core.uniform import UniformForm, skeleton

start(snakemake)


def no_form(alpha, gamma, end="force") -> str | None:
    """Why the pair has no uniform form under ``end``; None when it has one."""
    try:
        skeleton(alpha, gamma, end)
    except ParameterError as why:
        return why.allowed
    return None


def build_shard():
    """One shard: the forms of its pairs, as the library stores them."""
    from restitution.fast.uniform_build import build_uniform

    forms = []
    for alpha, gamma in snakemake.params.pairs:
        for end in ("force", "overlap"):
            if no_form(alpha, gamma, end) is None:
                print(f"alpha={alpha}, gamma={gamma}, {end} rule", flush=True)
                forms.append(build_uniform(alpha, gamma, end=end).as_dict())
    write_json(snakemake.output[0], forms)


def write_table():
    """Every pair's row, its form from the shards or the variants' forms."""
    built = {}
    shards = [d for path in snakemake.input.shards for d in read_json(path)]
    variants = [read_json(path) for path in [*snakemake.input.forms, *snakemake.input.overlap_forms]]
    for d in shards + [d for d in variants if d["available"]]:
        f = UniformForm.from_dict(d)
        built[(f.alpha, f.gamma, f.end)] = f
    rows = [row(alpha, gamma, built) for alpha, gamma in snakemake.params.pairs]
    write_csv(snakemake.output.csv, pd.DataFrame(rows))
    write_text(snakemake.output.tex, latex(rows))


def row(alpha, gamma, built) -> dict:
    ex = as_exponents(alpha, gamma)
    out = {"alpha": alpha, "gamma": gamma}
    reason = no_form(alpha, gamma)
    if reason is not None:
        out["form"] = "exact" if Fraction(alpha) == Fraction(gamma) else "none"
        out["reason"] = reason
    else:
        f = built[(ex.alpha, ex.gamma, "force")]
        m = f.measured
        out.update(form="uniform", n_coef=len(f.coef), sigma=f.sigma, m0=f.m0, m1=f.m1, bound_eps=f.bound_eps,
                   bound_one_minus_eps=f.bound_one_minus_eps, test_eps=m["test_eps"],
                   test_one_minus_eps=m["test_one_minus_eps"], selection_eps=m["selection_eps"])
        if no_form(alpha, gamma, "overlap") is not None:
            out["overlap_form"] = "none (the bodies can stick)"
        else:
            o = built[(ex.alpha, ex.gamma, "overlap")]
            out.update(overlap_form="uniform", overlap_n_coef=len(o.coef), overlap_bound_eps=o.bound_eps,
                       overlap_bound_one_minus_eps=o.bound_one_minus_eps)
    return out


def latex(rows) -> str:
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
    return "\n".join(lines) + "\n"


# %%
build_shard() if snakemake.rule == "uniform_shard" else write_table()

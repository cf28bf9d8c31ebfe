# %% [markdown]
# # The uniform closed form for every exponent pair of the stability atlas
#
# For alpha > gamma the library fits the form and measures its bound on points it did not use
# (restitution.fast.uniform_build); alpha = gamma has an exact closed form and alpha < gamma none.
# Where gamma < alpha < 2 gamma + 1 the overlap end rule has its own form, built the same way.
#
# Two rules run this script. `uniform_shard` builds the forms of its share of the pairs and writes
# them as JSON; `uniform_atlas` reads the shards and writes one row per pair, as CSV and as the
# appendix's LaTeX table.

# %%
from fractions import Fraction

import pandas as pd
from restitution_workflow.latex import frac_tex, sci
from restitution_workflow.pipeline import read_json, start, write_csv, write_json, write_text

from restitution.core.errors import ParameterError
from restitution.core.problem import Problem
from restitution.core.uniform import skeleton

start(snakemake)


def no_form(alpha, gamma, end="force") -> str | None:
    """Why the pair has no uniform form under ``end``; None when it has one."""
    try:
        skeleton(Problem.of(alpha, gamma, end))
    except ParameterError as why:
        return why.allowed
    return None


def build_shard():
    """One shard: for each of its pairs and both end rules, the form as the library stores it
    (with available: true) or why there is none (available: false)."""
    from restitution.fast.uniform_build import build_uniform

    records = []
    for alpha, gamma in snakemake.params.pairs:
        for end in ("force", "overlap"):
            reason = no_form(alpha, gamma, end)
            if reason is None:
                print(f"alpha={alpha}, gamma={gamma}, {end} rule", flush=True)
                records.append({"available": True, "end": end, **build_uniform(Problem.of(alpha, gamma, end)).as_dict()})
            else:
                records.append({"available": False, "reason": reason, "alpha": alpha, "gamma": gamma, "end": end})
    write_json(snakemake.output[0], records)


def write_table():
    """Every pair's row, from its records in the shards (read as written: the overlap rule's
    skeleton costs a limit-law integration per pair to derive again)."""
    records = {(Fraction(d["alpha"]), Fraction(d["gamma"]), d["end"]): d
               for path in snakemake.input.shards for d in read_json(path)}
    rows = [row(alpha, gamma, records) for alpha, gamma in snakemake.params.pairs]
    write_csv(snakemake.output.csv, pd.DataFrame(rows))
    write_text(snakemake.output.tex, latex(rows))


def row(alpha, gamma, records) -> dict:
    a, g = Fraction(alpha), Fraction(gamma)
    f, o = records[(a, g, "force")], records[(a, g, "overlap")]
    out = {"alpha": alpha, "gamma": gamma}
    if not f["available"]:
        out["form"] = "exact" if a == g else "none"
        out["reason"] = f["reason"]
        return out
    m = f["measured"]
    out.update(form="uniform", n_coef=len(f["a"]), sigma=f["sigma"], m0=f["m0"], m1=f["m1"], bound_eps=f["bound_eps"],
               bound_one_minus_eps=f["bound_one_minus_eps"], test_eps=m["test_eps"],
               test_one_minus_eps=m["test_one_minus_eps"], selection_eps=m["selection_eps"])
    if o["available"]:
        out.update(overlap_form="uniform", overlap_n_coef=len(o["a"]), overlap_bound_eps=o["bound_eps"],
                   overlap_bound_one_minus_eps=o["bound_one_minus_eps"])
    else:
        out["overlap_form"] = "none (the bodies can stick)"
    return out


def latex(rows) -> str:
    lines = [r"\begin{tabular}{llllllll}", r"\toprule",
             r"$\alpha$ & $\gamma$ & $(\sigma, s_0, s_1)$ & $n + 1$ & $2\times$ max.\ error $\varepsilon$ & $2\times$ max.\ error $1-\varepsilon$ "
             r"& largest test error in $\varepsilon$ & overlap rule: $\bar n + 1$, $2\times$ max.\ errors \\",
             r"\midrule"]
    for r in rows:
        ab = f"{frac_tex(Fraction(r['alpha']))} & {frac_tex(Fraction(r['gamma']))}"
        if r["form"] == "uniform":
            lines.append(rf"{ab} & ({sci(r['sigma'], 3)}, {r['m0']}, {r['m1']}) & {r['n_coef']} & {sci(r['bound_eps'], 2)} & "
                         rf"{sci(r['bound_one_minus_eps'], 2)} & {sci(r['test_eps'], 2)} & "
                         + (rf"{r['overlap_n_coef']}: {sci(r['overlap_bound_eps'], 2)}, {sci(r['overlap_bound_one_minus_eps'], 2)} \\"
                            if r["overlap_form"] == "uniform" else r"sticks \\"))
        else:
            what = "exact closed form" if r["form"] == "exact" else "no uniform form (first viscous correction unknown)"
            lines.append(rf"{ab} & \multicolumn{{6}}{{l}}{{{what}}} \\")
    lines += [r"\bottomrule", r"\end{tabular}"]
    return "\n".join(lines) + "\n"


# %%
if snakemake.rule == "uniform_shard":
    build_shard()
else:
    write_table()

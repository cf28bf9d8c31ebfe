# %% [markdown]
# # The uniform closed form of one variant
#
# Fits eps(Omega) in the form of `restitution.core.uniform` (the library chooses its shape and
# measures its bound on points it was not fitted on), then evaluates it where the manuscript needs
# it: relative errors in eps and 1 - eps over Omega in [1e-8, 1e8] (against the compiled
# integrator at rtol 1e-14), and eps(g) on the variant's figure-4 speeds.

# %%
import numpy as np
import pandas as pd
from common.pipeline import start, write_csv, write_json

from restitution.core.errors import ParameterError
from restitution.core.uniform import FORM_RANGE, skeleton
from restitution.fast.master import reference_eps
from restitution.fast.uniform_build import build_uniform

start(snakemake)
ex = snakemake.params.exponents
PRINTED_DIGITS = 12

# %%
try:
    skeleton(ex["alpha"], ex["gamma"])
except ParameterError as why:   # alpha <= gamma: no uniform form; the section says why
    write_json(snakemake.output.json, {"available": False, "reason": why.allowed, **ex})
    write_csv(snakemake.output.errors, pd.DataFrame(columns=["omega", "eps", "err_eps", "err_one_minus_eps"]))
    write_csv(snakemake.output.curve, pd.DataFrame(columns=["g", "omega", "eps_reference", "eps_closed_form"]))
else:
    form = build_uniform(ex["alpha"], ex["gamma"], progress=print)
    om = np.geomspace(*FORM_RANGE, 801)
    # what the manuscript prints (12 significant digits) must give the same eps to far below the bound
    printed = float(np.max(np.abs(form.rounded(PRINTED_DIGITS).eps(om) / form.eps(om) - 1)))
    write_json(snakemake.output.json, {"available": True, **form.as_dict(), "formula": form.formula(),
                                       "printed_digits": PRINTED_DIGITS, "printed_max_change": printed})
    eps = reference_eps(ex["alpha"], ex["gamma"], om, 1e-14)
    write_csv(snakemake.output.errors, pd.DataFrame({
        "omega": om, "eps": eps, "err_eps": np.abs(form.eps(om) / eps - 1),
        "err_one_minus_eps": np.abs(form.one_minus_eps(om) / (1 - eps) - 1)}))
    curve = pd.read_csv(snakemake.input.curve)
    cols = ["g", "omega", "eps_reference"] + (["eps_printed"] if "eps_printed" in curve else [])
    out = curve[cols].copy()
    out["eps_closed_form"] = form.eps(curve["omega"].to_numpy())
    write_csv(snakemake.output.curve, out)

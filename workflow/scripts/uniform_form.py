# %% [markdown]
# # The uniform approximation of one variant
#
# Fits eps(Omega) in the forms of `restitution.core.uniform`, one per end rule (the library chooses
# the shape and measures the bound on points it was not fitted on), then evaluates them where the
# manuscript needs it: relative errors in eps and 1 - eps over Omega in [1e-8, 1e8] (against the
# compiled integrator at rtol 1e-14; under the overlap rule from 1e-3 up), and eps(g) of the force
# rule's form on the variant's figure-4 speeds.

# %%
import numpy as np
import pandas as pd
from restitution_workflow.pipeline import start, write_csv, write_json

from restitution.core.errors import ParameterError
from restitution.core.uniform import FORM_RANGE, skeleton
from restitution.core.problem import Problem
from restitution.fast.master import reference_eps
from restitution.fast.uniform_build import LAW_BELOW, build_uniform

start(snakemake)
ex = snakemake.params.exponents
PRINTED_DIGITS = 12

# %%
def form_and_errors(end: str, json_path: str, errors_path: str, lowest: float):
    """Build the form for ``end``, write it with its printed-digit check, and its errors against the
    compiled integrator on Omega in [lowest, FORM_RANGE[1]]; None (and the reason) where there is none."""
    try:
        skeleton(Problem.of(ex["alpha"], ex["gamma"], end))
    except ParameterError as why:   # no uniform form for this rule: the section says why
        write_json(json_path, {"available": False, "reason": why.allowed, **ex})
        write_csv(errors_path, pd.DataFrame(columns=["omega", "eps", "err_eps", "err_one_minus_eps"]))
        return None
    form = build_uniform(Problem.of(ex["alpha"], ex["gamma"], end), progress=print)
    om = np.geomspace(lowest, FORM_RANGE[1], 801)
    # what the manuscript prints (12 significant digits) must give the same eps to far below the bound
    printed = float(np.max(np.abs(form.rounded(PRINTED_DIGITS).eps(om) / form.eps(om) - 1)))
    write_json(json_path, {"available": True, **form.as_dict(), "formula": form.formula(),
                           "printed_digits": PRINTED_DIGITS, "printed_max_change": printed})
    eps = reference_eps(Problem.of(ex["alpha"], ex["gamma"], end), om, 1e-14)
    write_csv(errors_path, pd.DataFrame({
        "omega": om, "eps": eps, "err_eps": np.abs(form.eps(om) / eps - 1),
        "err_one_minus_eps": np.abs(form.one_minus_eps(om) / (1 - eps) - 1)}))
    return form


form = form_and_errors("force", snakemake.output.json, snakemake.output.errors, FORM_RANGE[0])
# under the overlap rule each integration below LAW_BELOW follows the creeping return for a long time
# (the build's references there are the limit law, checked against the integrator above it)
form_and_errors("overlap", snakemake.output.overlap_json, snakemake.output.overlap_errors, LAW_BELOW)
if form is None:
    write_csv(snakemake.output.curve, pd.DataFrame(columns=["g", "omega", "eps_reference", "eps_uniform"]))
else:
    curve = pd.read_csv(snakemake.input.curve)
    cols = ["g", "omega", "eps_reference"] + (["eps_printed"] if "eps_printed" in curve else [])
    out = curve[cols].copy()
    out["eps_uniform"] = form.eps(curve["omega"].to_numpy())
    write_csv(snakemake.output.curve, out)

# %% [markdown]
# # The exact connection Omega~(Omega), its least-squares quadratic, and the retrace check
#
# The reference eps(g) of figure 4 gives the exact connection Omega~ = Omega eps^k,
# k = (alpha-1-2 gamma)/(gamma+1), at every impact speed of the curve. Fitting
# c0 + c1 Omega + c2 Omega^2 to the points whose g lies in the variant's `fit_g_range`
# (`restitution.core.connection.fit_quadratic`) needs no integration of its own. The fit does not
# exist when k = 0 (then Omega does not depend on g and Omega~ = Omega identically) or when fewer
# than four points fall in the range.
#
# Check of the exact connection (`restitution.core.connection.retrace`): the inverse collision
# integrated from the forward end state at g_figure and mapped back into forward variables must
# retrace the forward trajectory.

# %%
import pandas as pd
from restitution_workflow.pipeline import read_json, start, write_csv, write_json

from restitution.core import connection
from restitution.core.errors import ParameterError
from restitution.core.exponents import Exponents

start(snakemake)

# %% Points of the exact connection inside the fit range
p = snakemake.params
ex = Exponents.parse(p.exponents["alpha"], p.exponents["gamma"])
curve = pd.read_csv(snakemake.input.curve)
rng = p.fit_g_range or {"min": float(curve["g"].min()), "max": float(curve["g"].max())}
# Figure-4 points are log-spaced: allow a rounding error at the ends of the range.
inside = (curve["g"] >= rng["min"] * (1 - 1e-12)) & (curve["g"] <= rng["max"] * (1 + 1e-12))
pts = curve[inside].sort_values("omega")

fit = {"applies": False, "g_min": rng["min"], "g_max": rng["max"], "n": int(len(pts))}
residuals = pd.DataFrame(columns=["g", "omega", "omega_tilde", "omega_tilde_fit", "residual"])
if ex.omega_exponent == 0:
    fit["reason"] = ("alpha - 1 - 2 gamma = 0: Omega does not depend on g, so every impact speed has the same "
                     "Omega and Omega~ = Omega; there is no curve to fit and eps does not depend on g")
elif pts["omega"].nunique() < 4:
    fit["reason"] = f"only {pts['omega'].nunique()} distinct Omega in the fit range (4 needed)"
else:
    res = connection.fit_quadratic(pts["omega"].to_numpy(), pts["omega_tilde"].to_numpy())
    fit.update(res.as_dict(), applies=True, g_min=rng["min"], g_max=rng["max"])
    validity = connection.connection_validity(ex, res.c)
    fit["validity"] = {k: [list(iv) for iv in v] for k, v in validity.items()}
    residuals = pd.DataFrame({"g": pts["g"], "omega": pts["omega"], "omega_tilde": pts["omega_tilde"],
                              "omega_tilde_fit": pts["omega_tilde"] - res.residuals,
                              "residual": res.residuals})
    print(f"fit over {len(pts)} points: c = {res.c}, stderr = {res.stderr}, max |r| = {res.max_abs_residual:.3g}")

# %% The retrace check at g_figure
summary = read_json(snakemake.input.summary)
try:
    rt = connection.retrace(ex, summary["omega"], rtol=p.rtol)
    fit["retrace"] = {"omega": rt.omega, "omega_tilde": rt.omega_tilde, "eps": rt.eps,
                      "x_tilde_start": rt.x_tilde_start, "samples": int(rt.tau.size),
                      "max_deviation": rt.max_deviation, "v_end_error": rt.v_end_error,
                      "tau_error": rt.tau_error}
    print(f"retrace at g = {summary['g']}: max deviation {rt.max_deviation:.3g} (relative to x_b)")
except ParameterError as err:
    fit["retrace"] = {"reason": str(err)}

# %% Outputs
write_json(snakemake.output.json, fit)
write_csv(snakemake.output.residuals, residuals)
write_json(snakemake.output.relation, {
    "kind": "fitted", "source": "least squares on the exact connection (restitution.core.connection.fit_quadratic)",
    "label": r"least-squares $c_0, c_1, c_2$" if fit["applies"] else None,
    "c": fit.get("c"), "reason": fit.get("reason", ""),
})

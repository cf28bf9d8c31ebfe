# %% [markdown]
# # Exact perturbation series (forward and inverse)
#
# x(tau; Omega) = sum_n Omega^n x_n(tau), each x_n a series in tau^(1/p) with rational
# coefficients, from `restitution.core.series.perturbation_series`. Written as JSON with the
# rationals as strings ("-4/35"), so nothing is rounded.

# %%
from restitution_workflow.pipeline import start, write_json

from restitution.core.series import perturbation_series

start(snakemake)

# %%
ex = snakemake.params.exponents
for direction in ("forward", "inverse"):
    s = perturbation_series(ex["alpha"], ex["gamma"], omega_order=snakemake.params.omega_order,
                            max_power=snakemake.params.max_power, direction=direction)
    data = s.as_dict()
    data["omega_order"] = snakemake.params.omega_order
    data["max_power"] = snakemake.params.max_power
    write_json(snakemake.output[direction], data)
    n_terms = sum(len(v) for v in data["orders"].values())
    print(f"{direction}: p = {s.p}, {n_terms} nonzero coefficients up to tau^{data['max_power']}")

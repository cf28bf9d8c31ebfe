# %% [markdown]
# # Exact perturbation series (forward and inverse)
#
# x(tau; Omega) = sum_n Omega^n x_n(tau), each x_n a series in tau^(1/p) with rational
# coefficients, from `restitution.series.perturbation_series`. Written as JSON with the
# rationals as strings ("-4/35"), so nothing is rounded.

# %%
if "snakemake" not in globals():  # opened as a notebook: replay the pipeline's last run
    import pathlib, sys  # noqa: E401
    here = next(p for p in (pathlib.Path.cwd(), *pathlib.Path.cwd().parents) if (p / "Snakefile").exists())
    sys.path.insert(0, str(here / "workflow" / "scripts"))
    from _pipeline import replay
    snakemake = replay("series")

from _pipeline import start, write_json  # noqa: E402

from restitution.series import perturbation_series  # noqa: E402

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

# %% [markdown]
# # Reference eps(g) over the impact speeds of figure 4
#
# One integration per impact speed (restitution.collision.collide_many); g enters only
# through Omega(g). The table also carries Omega~ = Omega eps^((alpha-1-2 gamma)/(gamma+1)),
# the exact connection the paper's c0 + c1 Omega + c2 Omega^2 approximates.

# %%
if "snakemake" not in globals():  # opened as a notebook: replay the pipeline's last run
    import pathlib, sys  # noqa: E401
    here = next(p for p in (pathlib.Path.cwd(), *pathlib.Path.cwd().parents) if (p / "Snakefile").exists())
    sys.path.insert(0, str(here / "workflow" / "scripts"))
    from _pipeline import replay
    snakemake = replay("reference_eps_curve")

import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from _pipeline import start, write_csv  # noqa: E402

from restitution.collision import collide_many  # noqa: E402
from restitution.model import Material  # noqa: E402

start(snakemake)


def speeds(rng: dict) -> np.ndarray:
    if rng["spacing"] == "log":
        return np.geomspace(rng["min"], rng["max"], rng["points"])
    return np.linspace(rng["min"], rng["max"], rng["points"])


# %%
p = snakemake.params
mat = Material(p.exponents["alpha"], p.exponents["gamma"], p.D1, p.D2)
ex = mat.exponents
g = speeds(p.g_range)
omega = np.asarray(mat.omega(g), dtype=float)
res = collide_many(ex.alpha, ex.gamma, omega, rtol=p.rtol)
table = pd.DataFrame({"g": g, "omega": omega})
for key, values in res.items():
    if key not in table:
        table[key] = np.asarray(values)
table["omega_tilde"] = table["omega"] * table["eps"] ** float(ex.omega_exponent)
write_csv(snakemake.output[0], table)
print(table.describe().to_string())

# %% [markdown]
# # Reference eps(g) over the impact speeds of figure 4
#
# One integration per impact speed (restitution.core.collision.collide_many); g enters only
# through Omega(g). The table also carries Omega~ = Omega eps^((alpha-1-2 gamma)/(gamma+1)),
# the exact connection the paper's c0 + c1 Omega + c2 Omega^2 approximates.

# %%
import numpy as np
import pandas as pd
from restitution_workflow.pipeline import start, write_csv

from restitution.core.collision import collide_many
from restitution.core.model import Material

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
res = collide_many(ex, omega, rtol=p.rtol)
table = pd.DataFrame({"g": g, "omega": omega})
for key, values in res.items():
    if key not in table:
        table[key] = np.asarray(values)
table["omega_tilde"] = table["omega"] * table["eps"] ** float(ex.omega_exponent)
write_csv(snakemake.output[0], table)
print(table.describe().to_string())

# %% [markdown]
# # Accuracy of the reference integration
#
# eps, tau_b, x_b, tau_c, x_c at g_figure recomputed at each solver tolerance and compared
# with the tightest one. This is the speed/accuracy trade of the reference solver; wall
# times go to the log only (they are not reproducible, the results are).

# %%
import time

import pandas as pd
from restitution_workflow.pipeline import start, write_csv

from restitution.core.collision import collide
from restitution.core.model import Material

start(snakemake)

QUANTITIES = ("eps", "tau_b", "x_b", "tau_c", "x_c")

# %%
p = snakemake.params
mat = Material(p.exponents["alpha"], p.exponents["gamma"], p.D1, p.D2)
ex = mat.exponents
omega = mat.omega(p.g)
rows = []
for rtol in sorted(p.rtols, reverse=True):
    t0 = time.perf_counter()
    hit = collide(ex, omega, rtol=rtol)
    elapsed = time.perf_counter() - t0
    rows.append({"rtol": rtol, **{q: float(getattr(hit, q)) for q in QUANTITIES}})
    print(f"rtol = {rtol:.0e}: eps = {hit.eps:.15g} ({elapsed * 1e3:.1f} ms)")
table = pd.DataFrame(rows)
best = table.iloc[-1]
for q in QUANTITIES:
    table[f"{q}_error"] = (table[q] - best[q]).abs()
write_csv(snakemake.output[0], table)

# %% [markdown]
# # Accuracy of the reference integration
#
# eps, tau_b, x_b, tau_c, x_c at g_figure recomputed at each solver tolerance and compared
# with the tightest one. This is the speed/accuracy trade of the reference solver; wall
# times go to the log only (they are not reproducible, the results are).

# %%
if "snakemake" not in globals():  # opened as a notebook: replay the pipeline's last run
    import pathlib, sys  # noqa: E401
    here = next(p for p in (pathlib.Path.cwd(), *pathlib.Path.cwd().parents) if (p / "Snakefile").exists())
    sys.path.insert(0, str(here / "workflow" / "scripts"))
    from _pipeline import replay
    snakemake = replay("reference_accuracy")

import time  # noqa: E402

import pandas as pd  # noqa: E402
from _pipeline import start, write_csv  # noqa: E402

from restitution.collision import collide  # noqa: E402
from restitution.model import Material  # noqa: E402

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
    hit = collide(ex.alpha, ex.gamma, omega, rtol=rtol)
    elapsed = time.perf_counter() - t0
    rows.append({"rtol": rtol, **{q: float(getattr(hit, q)) for q in QUANTITIES}})
    print(f"rtol = {rtol:.0e}: eps = {hit.eps:.15g} ({elapsed * 1e3:.1f} ms)")
table = pd.DataFrame(rows)
best = table.iloc[-1]
for q in QUANTITIES:
    table[f"{q}_error"] = (table[q] - best[q]).abs()
write_csv(snakemake.output[0], table)

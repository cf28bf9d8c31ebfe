# %% [markdown]
# # Figure 4: coefficient of restitution versus impact speed
#
# The reference eps(g) from one integration per impact speed, and eps implied by each relation
# Omega~ = sum_k c_k Omega^k available for this variant (the paper's printed c's; later our
# derived and fitted ones). Our reading of the paper: the inverse collision has the rebound
# speed g~ = eps g, so Omega~ = Omega eps^((alpha-1-2 gamma)/(gamma+1)) and
#
#     eps = (Omega~ / Omega)^((gamma+1)/(alpha-1-2 gamma)).

# %%
if "snakemake" not in globals():  # opened as a notebook: replay the pipeline's last run
    import pathlib, sys  # noqa: E401
    here = next(p for p in (pathlib.Path.cwd(), *pathlib.Path.cwd().parents) if (p / "Snakefile").exists())
    sys.path.insert(0, str(here / "workflow" / "scripts"))
    from _pipeline import replay
    snakemake = replay("fig4_eps")

import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from _pipeline import read_json, save_figure, setup_matplotlib, start  # noqa: E402

from restitution.exponents import Exponents  # noqa: E402

start(snakemake)
plt = setup_matplotlib()


def eps_from_relation(omega: np.ndarray, c: list[float], omega_exponent: float) -> np.ndarray:
    """eps = (Omega~/Omega)^(1/omega_exponent) with Omega~ = sum c_k Omega^k (NaN where Omega~ <= 0)."""
    omega_t = np.polynomial.polynomial.polyval(omega, c)
    with np.errstate(invalid="ignore", divide="ignore"):
        out = np.where(omega_t > 0, (omega_t / omega) ** (1.0 / omega_exponent), np.nan)
    return out


# %%
p = snakemake.params
ex = Exponents.parse(p.exponents["alpha"], p.exponents["gamma"])
curve = pd.read_csv(snakemake.input.curve)
relations = [read_json(f) for f in snakemake.input.relations]

fig, ax = plt.subplots()
ax.plot(curve["g"], curve["eps"], color="black", lw=2.4, label="reference integration")
styles = ["--", "-.", ":", (0, (5, 1, 1, 1))]
for i, rel in enumerate(relations if ex.omega_exponent else []):  # no eps from Omega~ = Omega
    eps = eps_from_relation(curve["omega"].to_numpy(), rel["c"], float(ex.omega_exponent))
    ax.plot(curve["g"], eps, ls=styles[i % len(styles)], lw=1.6, label=rel["label"])
ax.axvline(p.g_figure, color="grey", ls=":", lw=1)
ax.axhline(1.0, color="grey", ls="-", lw=0.8)
ax.set_xscale("log")
ax.set_yscale("log")
# Room for every curve, but not for a relation that runs off to 0 or infinity.
lo = max(min(np.nanmin(line.get_ydata()) for line in ax.get_lines()[:1 + len(relations)]), 1e-6)
ax.set_ylim(0.5 * lo, 3.0)
ax.annotate(rf"$g = {p.g_figure:g}$ (figs. 1-2)", (p.g_figure, 1.0), xytext=(4, -12),
            textcoords="offset points", color="grey", fontsize=8)
ax.set_xlim(curve["g"].min(), curve["g"].max())
ax.set_xlabel(r"impact speed $g$ (units of the $D_1$, $D_2$ fit)")
ax.set_ylabel(r"coefficient of restitution $\varepsilon$")
ax.legend(loc="lower left", title=rf"$\alpha = {ex.alpha}$, $\gamma = {ex.gamma}$")
fig.tight_layout()
save_figure(fig, snakemake.output.pdf, snakemake.output.png)

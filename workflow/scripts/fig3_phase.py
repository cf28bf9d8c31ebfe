# %% [markdown]
# # Figure 3: phase diagram of the damped-only motions (Omega = 0)
#
# With no elastic force the forward motion keeps x' + x^(gamma+1)/(gamma+1) = 1 and the inverse
# one x~' - x~^(gamma+1)/(gamma+1) = 1 (their first integrals from x = 0, x' = 1). Shifting the
# inverse curve down by 1 makes the two cross where x^(gamma+1)/(gamma+1) = 1/2, which is the
# line x = 1 for gamma = 1: the reference point the paper uses to join the two solutions.
# For gamma = 1 the closed forms sqrt(2) tanh(tau/sqrt(2)) and sqrt(2) tan(tau/sqrt(2))
# (restitution.core.damped) are drawn as markers on top of the curves.

# %%
from fractions import Fraction

import numpy as np
from restitution_workflow.pipeline import save_figure, setup_matplotlib, start

from restitution.core import damped

start(snakemake)
plt = setup_matplotlib()

# %%
gamma = Fraction(snakemake.params.gamma)
n = snakemake.params.points
k = float(gamma + 1)
x_turn = k ** (1.0 / k)                 # forward: x' = 0 (maximum of the damped-only motion)
x_cross = (k / 2.0) ** (1.0 / k)        # where the shifted inverse curve meets the forward one
x_f = np.linspace(0.0, x_turn, n)
x_i = np.linspace(0.0, 1.5 * x_turn, n)
v_f = 1.0 - x_f ** k / k
v_i = 1.0 + x_i ** k / k

fig, ax = plt.subplots(figsize=(6.3, 3.0))   # wide and low: the legend stands beside the axes
ax.plot(x_f, v_f, color="tab:blue", lw=2, label=r"forward: $x' + x^{\gamma+1}/(\gamma+1) = 1$")
ax.plot(x_i, v_i, color="tab:red", lw=2,
        label=r"inverse: $\tilde x' - \tilde x^{\gamma+1}/(\gamma+1) = 1$")
ax.plot(x_i, v_i - 1.0, color="tab:red", lw=1.5, ls="--", label="inverse shifted down by 1")
ax.axvline(x_cross, color="black", lw=1, ls=":",
           label=rf"$x = {x_cross:g}$" if gamma == 1 else rf"$x = {x_cross:.4f}$")
ax.plot([x_cross], [1.0 - x_cross ** k / k], "ko", ms=4)
if gamma == 1:
    tau_f = np.linspace(0.0, 4.0, 17)
    xs, vs = damped.forward(tau_f)
    ax.plot(xs, vs, "o", color="tab:blue", ms=3.5, mfc="none", label=r"$\sqrt{2}\tanh(\tau/\sqrt{2})$")
    tau_i = np.linspace(0.0, 1.2, 13)
    xs, vs = damped.inverse(tau_i)
    keep = xs <= x_i[-1]
    ax.plot(xs[keep], vs[keep], "s", color="tab:red", ms=3.5, mfc="none",
            label=r"$\sqrt{2}\tan(\tilde\tau/\sqrt{2})$")
ax.set_xlim(0.0, x_i[-1])
ax.set_ylim(-0.1, float(v_i[-1]) * 1.05)
ax.set_xlabel(r"scaled deformation $x$, $\tilde x$")
ax.set_ylabel(r"scaled velocity $x' = dx/d\tau$, $\tilde x'$")
# beside the axes: inside them, the inverse curve ran through it for gamma = 0 (the dashpot), and below
# them it made a tall, narrow figure that left the page's width empty; bbox_inches="tight" keeps it
fig.legend(*ax.get_legend_handles_labels(), loc="center left", bbox_to_anchor=(1.0, 0.5),
           title=rf"damped only ($\Omega = 0$), $\gamma = {gamma}$")
fig.set_layout_engine("tight")   # redone when save_figure resizes
save_figure(fig, snakemake.output.pdf, snakemake.output.png, width=1.0)   # the main figure and the variants' width

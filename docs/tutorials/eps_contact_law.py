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
# # eps for my contact law, and the speed-accuracy trade
#
# You have a contact law: Hertz spheres (alpha = 3/2) with Kuwabara-Kono damping (gamma = 1/2),
# D1 and D2 in your units, and impact speeds from 1 cm/s to 10 m/s. What coefficient of restitution
# does it give, how sure is each number, and what does asking for more digits cost?
#
# The answer depends on the exponents and the single scaled parameter Omega (see
# [the physics](../explanation/physics.md)); `Material` turns your constants into Omega.

# %%
import time

import matplotlib.pyplot as plt
import numpy as np

from restitution import Material, epsilon

law = Material(alpha="3/2", gamma="1/2", D1=1.5e8, D2=2.0e4)   # Hertz + Kuwabara-Kono, SI units
g = np.geomspace(0.01, 10.0, 200)                              # impact speeds (m/s)
omega = law.omega(g)
print(f"Omega runs from {omega.min():.3g} to {omega.max():.3g}")

# %% [markdown]
# Ask for eps to a relative tolerance. The result says which method answered and the error bound
# it guarantees over all the inputs. Most DEM codes end contact when the overlap returns to zero
# (`end="overlap"`), not when the force vanishes (`end="force"`, the default): compute both.

# %%
force = epsilon(alpha="3/2", gamma="1/2", omega=omega, tol=1e-9)
overlap = epsilon(alpha="3/2", gamma="1/2", omega=omega, tol=1e-9, end="overlap")
for name, r in (("force", force), ("overlap", overlap)):
    print(f"{name:8s} method {r.method:12s} bound {r.error_bound:.1e}   eps at 1 m/s "
          f"{np.interp(1.0, g, r.eps):.6f}")

# %%
fig, ax = plt.subplots(figsize=(6, 3.6))
ax.semilogx(g, force.eps, label="contact ends at zero force")
ax.semilogx(g, overlap.eps, "--", label="contact ends at zero overlap")
ax.set_xlabel("impact speed g (m/s)")
ax.set_ylabel("coefficient of restitution eps")
ax.set_title("Hertz + Kuwabara-Kono damping")
ax.legend()
fig.tight_layout()

# %% [markdown]
# The two end rules differ most for fast, strongly damped impacts: there the attractive force the
# overlap rule lets act slows the rebound.
#
# ## What more digits cost
#
# Each tolerance is met by the cheapest method whose bound reaches it, counting what a build would
# cost against the number of points. Below, 20,000 speeds are asked at tolerances from 1e-3 to
# 1e-12; `method` names the rung that answered. The times are
# this build's and vary from machine to machine: the point is their ratio.

# %%
many = law.omega(np.geomspace(0.01, 10.0, 20_000))
rows = []
for tol in (1e-3, 1e-6, 1e-9, 1e-12):
    epsilon(alpha="3/2", gamma="1/2", omega=many, tol=tol)           # builds, if any, are made here
    t0 = time.perf_counter()
    r = epsilon(alpha="3/2", gamma="1/2", omega=many, tol=tol)
    rows.append((tol, r.method, r.error_bound, (time.perf_counter() - t0) / many.size))
for tol, method, bound, cost in rows:
    print(f"tol {tol:7.0e}  ->  {method:12s} bound {bound:.1e}  {cost:.1e} s per point")

# %% [markdown]
# Once the master curve for these exponents is built (the first request that pays for it builds it,
# and it is cached), it meets every tolerance down to its own bound at the same cost: more digits
# cost nothing until the tolerance passes that bound, and then the integrators take over.
#
# Forcing a method (`method=...`, with `tol=None` to take its own bound) shows the whole menu the
# chooser picks from: the fitted uniform approximation, the master curve, the compiled integrator and scipy's
# reference integration, on 200 speeds.

# %%
forced = {}
for method in ("uniform", "master", "integrator", "reference"):
    epsilon(alpha="3/2", gamma="1/2", omega=omega, method=method, tol=None)   # builds, if any
    t0 = time.perf_counter()
    r = epsilon(alpha="3/2", gamma="1/2", omega=omega, method=method, tol=None)
    forced[method] = (r, (time.perf_counter() - t0) / omega.size)
    print(f"{method:12s} bound {r.error_bound:.1e}  {forced[method][1]:.1e} s per point")
ref = forced["reference"][0].eps
for method, (r, _) in forced.items():
    print(f"{method:12s} largest difference from the reference: {np.max(np.abs(r.eps / ref - 1)):.1e}")

# %%
fig, ax = plt.subplots(figsize=(6, 3.6))
for method, (r, cost) in forced.items():
    ax.loglog([cost], [r.error_bound], "o", label=method)
ax.set_xlabel("seconds per point (this build)")
ax.set_ylabel("stated relative error bound")
ax.set_title("The menu: cost against stated accuracy")
ax.legend(fontsize=8)
fig.tight_layout()

# %% [markdown]
# `make bench` measures the same trade against an mpmath reference at 25 digits for every method;
# its recorded table is in [Accuracy and speed](../explanation/accuracy.md).

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
# # A scene: the cheapest model for every pair
#
# A DEM simulation has several materials, particle sizes, walls, a range of impact speeds and a
# restitution wanted per material pair (a constant, or a measured e(v)). A scene file says this
# once; `restitution scene` answers for every contact the scene can have: the cheapest contact model
# whose eps stays within the tolerance over the whole speed range, its setting in the code's own
# conventions, a time step, and the input lines to paste.
#
# The repository's `scenes/small.yaml`: glass, steel and rubber in two sizes each (six atom types,
# 21 type pairs), a steel wall, LAMMPS with Hertz contact from E and nu, speeds 0.05-5 m/s,
# tolerance 0.01 on eps. The glass-steel target is a measured table; the others are constants.

# %%
import json
import os
import subprocess
import sys
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

ROOT = Path(os.environ.get("RESTITUTION_DOCS_ROOT", Path.cwd().parents[1]))
scene_file = ROOT / "scenes" / "small.yaml"
print(scene_file.read_text())

# %% [markdown]
# Run it (`--json` for the plot below; without it a table):

# %%
exe = str(Path(sys.executable).with_name("restitution"))
proc = subprocess.run([exe, "scene", str(scene_file)], capture_output=True, text=True)
print(proc.stdout)
answer = json.loads(subprocess.run([exe, "scene", str(scene_file), "--json"], capture_output=True, text=True,
                                   check=True).stdout)

# %% [markdown]
# Every model tried per material pair, against the target and the tolerance band. A constant target
# is met by `coeff_restitution` damping, whose eps does not depend on speed; the glass-steel table,
# which falls with speed, needs a damping whose eps does (`viscoelastic`).

# %%
curves = answer["curves"]
fig, axes = plt.subplots(2, 3, figsize=(9, 5), sharex=True)
tol = answer["tolerance"]
for ax, curve in zip(axes.flat, curves):
    v, target = np.array(curve["speeds"]), np.array(curve["target"])
    ax.fill_between(v, target - tol, target + tol, color="0.85", label="target +- tolerance")
    for model in curve["models"]:
        ax.semilogx(v, model["eps"], "-" if model["accepted"] else ":",
                    label=model["name"] + ("" if model["accepted"] else " (rejected)"))
    ax.set_title(" - ".join(curve["pair"]), fontsize=9)
    ax.legend(fontsize=6)
for ax in axes[-1]:
    ax.set_xlabel("impact speed (m/s)")
for ax in axes[:, 0]:
    ax.set_ylabel("eps")
fig.tight_layout()

# %% [markdown]
# The lines to paste into the LAMMPS input (the first few; `--out DIR` writes them all to
# `DIR/input.lammps`):

# %%
print("\n".join(answer["input_lines"][:8]))
print(f"... {len(answer['input_lines'])} lines in all")

# %% [markdown]
# Each contact also gets a time step from a velocity-Verlet study, its largest overlap against the
# limit where the code's geometry breaks, and the eps recomputed from the number as the line prints
# it (`round_trip`). `make scene SCENE=scenes/small.yaml` runs the same as a pipeline step and adds
# an HTML report. The file's fields: [the scene file](../reference/_generated/scene.md); how the
# model is chosen: [Scenes](../howto/scenes.md).

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
# # What my LAMMPS or LIGGGHTS deck really gives
#
# A deck sets its damping through options whose effect on the coefficient of restitution the
# engines' manuals do not state: LAMMPS' `damping tsuji` takes an e that is not the eps it produces,
# unlike types are mixed, and without `limit_damping` contact lasts until the overlap is back to
# zero. `restitution deck FILE --g SPEEDS` has the engine read the deck and prints, for every
# type pair and every flat wall, the eps it gives, and the line that would give the typed e exactly.
#
# Here is a small LAMMPS deck: glass (type 1) and steel (type 2) spheres with Hertz contact from
# E and nu and tsuji damping, an explicit glass-steel pair with `damping viscoelastic`, and a steel
# floor. The e of type 1 comes through a variable, as decks often do.

# %%
import json
import os
import subprocess
import sys
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

deck = """\
units           si
atom_style      sphere
comm_modify     vel yes
boundary        p p f
region          box block 0 0.1 0 0.1 0 0.2
create_box      2 box
create_atoms    1 single 0.05 0.05 0.05
create_atoms    2 single 0.05 0.05 0.10
set             type 1 diameter 0.002
set             type 1 density 2500
set             type 2 diameter 0.004
set             type 2 density 7800
variable        e equal 0.5
pair_style      granular
pair_coeff      1 1 hertz/material 6.3e10 ${e} 0.22 damping tsuji tangential linear_nohistory 0 0
pair_coeff      2 2 hertz/material 2.0e11 0.8 0.29 damping tsuji tangential linear_nohistory 0 0
pair_coeff      1 2 hertz/material 9.5e10 2.0e10 0.25 damping viscoelastic tangential linear_nohistory 0 0
fix             floor all wall/gran granular hertz/material 2.0e11 0.8 0.29 damping tsuji tangential linear_nohistory 0 0 zplane 0.0 NULL
fix             integrate all nve/sphere
timestep        1e-7
run             1000
"""
with open("in.small", "w") as f:      # a statement: the notebook shows no count of characters written
    f.write(deck)

# %% [markdown]
# The audit, as a table (what a person reads) for four impact speeds:

# %%
exe = str(Path(sys.executable).with_name("restitution"))
speeds = ["0.01", "0.1", "1", "10"]
table = subprocess.run([exe, "deck", "in.small", "--g", *speeds], capture_output=True, text=True)
print(table.stdout)
print(table.stderr)     # notes: lines that play no part in a head-on contact, version caveats

# %% [markdown]
# and as JSON, to plot: every pair's eps against speed, with the e each line typed.

# %%
audit = json.loads(subprocess.run([exe, "deck", "in.small", "--g", *np.geomspace(0.01, 10, 13).astype(str),
                                   "--json"], capture_output=True, text=True, check=True).stdout)
fig, ax = plt.subplots(figsize=(6, 3.8))
for item in audit["pairs"] + audit["walls"]:
    label = (f"types {item['types'][0]}-{item['types'][1]}" if "wall" not in item
             else f"type {item['types'][0]} on wall {item['wall']}")
    (line,) = ax.semilogx(item["speeds"], item["eps"], "o-", ms=3, label=label)
    if item["typed_e"] is not None:
        ax.axhline(item["typed_e"], color=line.get_color(), ls=":", lw=1)
ax.set_xlabel("impact speed (m/s)")
ax.set_ylabel("eps the deck gives")
ax.set_title("dotted: the e typed in the deck")
ax.legend(fontsize=8)
fig.tight_layout()

# %% [markdown]
# What the audit shows:
#
# - tsuji's eps does not depend on the speed (Hertz with delta^(1/4) damping is the exact family
#   alpha = 2 gamma + 1), but it is not the e typed: 0.5 gives about 0.616 without `limit_damping`;
# - the wall's line is the steel pair's, so both sphere types get the same eps from it;
# - the glass-steel line with `damping viscoelastic` gives an eps that falls with speed.
#
# The lines that fix it: each tsuji pair's `exact_line` carries the e that gives the typed value.

# %%
# one wall line serves both sphere types: print each line once
for line in dict.fromkeys(item["exact_line"] for item in audit["pairs"] + audit["walls"] if item["exact_line"]):
    print(line)

# %% [markdown]
# ## A LIGGGHTS deck
#
# The same command reads LIGGGHTS input. This deck is laid out as LIGGGHTS' tutorials are: type 1
# is the particles' material, type 2 the floor's, which no particle has; materials come from
# `fix property/global`, 200 spheres are inserted and fall under gravity. Between particles
# `limitForce on` ends contact where the force vanishes, so the typed coefficientRestitution is not
# the eps; the floor's own `fix wall/gran` line leaves it at LIGGGHTS' default, `limitForce off`,
# which gives the typed e exactly.

# %%
Path("in.liggghts").write_text("""\
atom_style      granular
atom_modify     map array
communicate     single vel yes
newton          off
units           si
boundary        f f f
region          box block 0 0.1 0 0.1 0 0.1
create_box      2 box
neighbor        0.001 bin
fix             m1 all property/global youngsModulus peratomtype 5.e7 1.e8
fix             m2 all property/global poissonsRatio peratomtype 0.3 0.29
fix             m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.7 0.7 0.9
fix             m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.3 0.3 0.2
pair_style      gran model hertz tangential history limitForce on
pair_coeff      * *
timestep        5e-6
fix             gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix             floor all wall/gran model hertz tangential history primitive type 2 zplane 0.0
fix             pts all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.001
fix             dist all particledistribution/discrete 32452843 1 pts 1.0
region          fill block 0.01 0.09 0.01 0.09 0.05 0.09 units box
fix             ins all insert/pack seed 49979687 distributiontemplate dist insert_every once &
                overlapcheck yes all_in yes particles_in_region 200 region fill
fix             integrate all nve/sphere
run             20000
""")
ligg = subprocess.run([exe, "deck", "in.liggghts", "--g", "0.1", "1"], capture_output=True, text=True)
print(ligg.stdout)
print(ligg.stderr)

# %% [markdown]
# LIGGGHTS itself read the deck (its runs cut to no step, in a scratch copy): the audit knows the
# inserted spheres' size from what LIGGGHTS inserted, and it says three things a reader of the deck
# alone would miss:
#
# - type 2 has no particle, so its sphere pairs cannot happen and are not reported; it matters only
#   as the floor's material;
# - gravity acts during a contact with the floor, which moves the eps the engine measures a little
#   away from the contact's own, by an amount computed for each speed;
# - at the deck's time step a contact lasts only 20 to 30 steps, and the eps the engine gives then
#   depends on where in a step the contact starts; the note gives the time step that keeps eps
#   within 0.001 of its dt -> 0 value.

# %% [markdown]
# Paste the printed lines over the deck's own: the LAMMPS `pair_coeff` and `fix wall/gran` lines
# above (or use `damping coeff_restitution`, whose e is the eps under LAMMPS' default end rule), the
# LIGGGHTS `coefficientRestitution` line here. The
# [LAMMPS page](../howto/lammps.md#what-does-my-deck-really-give) says what the audit takes from
# the engine's reading, what it names without auditing, and what it refuses.

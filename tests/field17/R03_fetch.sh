#!/bin/sh
# Field round 17: put back R03's deck (not committed: the project holds only its developers' text).
# Source: github.com/SueHeir/dirt (MIT OR Apache-2.0), commit 03fcc61be6eda53e0d73e47b94bbecec1b392b32,
# examples/SPH_glass_sphere_calibration/07_column_collapse/sweep_mu0.1/a1/in.lammps (a LAMMPS column collapse the
# DIRT project runs to compare with its own DEM: 220 glass spheres, hertz/material tsuji, rolling sds, four walls,
# the gate unfixed between two runs, write_dump to an absolute path on its author's machine).
# usage: sh tests/field17/R03_fetch.sh CLONE_GIT_DIR   (from the worktree; a clone of that repository)
git --git-dir="$1" show 03fcc61be6eda53e0d73e47b94bbecec1b392b32:examples/SPH_glass_sphere_calibration/07_column_collapse/sweep_mu0.1/a1/in.lammps \
  > tests/field17/decks/R03_dirt_column_collapse/in.deck

#!/bin/sh
# Field round 16, R01: the research deck is not committed (the project holds only what its developers wrote);
# this puts it back beside its audit. It is LIGGGHTS-Basics/granudrum.sim and its two meshes from the public
# repository uob-positron-imaging-centre/ACCES-GranuDrum-Calibration (commit e5c6dd0, GPL-3.0), read from a git
# clone of it, and makes in.engine_short (SetupTime 0.002, RunTime 0.001, 300 grains) for the shortened engine run.
# usage (from the worktree): sh tests/field16/r01_fetch.sh CLONE_GIT_DIR
g=$1; d=tests/field16/decks/R01_granudrum_liggghts_basics
mkdir -p $d/mesh
git --git-dir="$g" show e5c6dd0:LIGGGHTS-Basics/granudrum.sim > $d/in.granudrum
git --git-dir="$g" show e5c6dd0:LIGGGHTS-Basics/mesh/inface.stl > $d/mesh/inface.stl
git --git-dir="$g" show e5c6dd0:LIGGGHTS-Basics/mesh/rotating_drum.stl > $d/mesh/rotating_drum.stl
sed -e 's/^variable SetupTime .*/variable SetupTime      equal 0.002/' -e 's/^variable RunTime .*/variable RunTime        equal 0.001/' \
    -e 's/^variable NumParticles .*/variable NumParticles   equal 300/' $d/in.granudrum > $d/in.engine_short

#!/bin/sh
# Field round 18: put back R01's deck (not committed: the project holds only its developers' text) and write R01b,
# the same deck with its loop cut to 20 passes and its last run to 2000 steps (so the engine can run it to its end).
# Source: github.com/simongravelle/lammps-input-files, inputs/pouring-granular/input.lammps (a public LAMMPS tutorial
# deck: a 10000-pass loop that redefines four fix pour each pass, a wall/gran/region hooke/history on the box,
# spherical gravity, a dump). usage: sh tests/field18/R01_fetch.sh GIT_DIR COMMIT   (from the worktree)
git --git-dir="$1" show "$2":inputs/pouring-granular/input.lammps > tests/field18/decks/R01_gravelle_pouring/in.deck
sed -e 's/loop 10000/loop 20/' -e 's/^run 2000000/run 2000/' tests/field18/decks/R01_gravelle_pouring/in.deck \
  > tests/field18/decks/R01b_gravelle_pouring_short/in.deck

#!/bin/sh
# Field round 21: run round 13's referee over deck folders that have a spec.json, one at a time, niced
# usage (from the worktree): sh tests/field21/referee_all.sh DECKDIR ...
. tests/field21/env.sh
for d in "$@"; do
  echo "### $d"; nice -n 10 python tests/field21/referee21.py "$d" 2>&1 | tail -12
done

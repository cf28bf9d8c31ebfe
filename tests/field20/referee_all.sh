#!/bin/sh
# Field round 20: run round 13's referee over deck folders that have a spec.json, one at a time, niced
# usage (from the worktree): sh tests/field20/referee_all.sh DECKDIR ...
. tests/field20/env.sh
for d in "$@"; do
  echo "### $d"; nice -n 10 python tests/field20/referee20.py "$d" 2>&1 | tail -12
done

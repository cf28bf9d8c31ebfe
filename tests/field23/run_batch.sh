#!/bin/sh
# Field round 23: for each deck folder, run it in its engine (engine.sh) then audit it (audit.sh), niced.
# usage (from the worktree): sh tests/field23/run_batch.sh DECKDIR ...
. tests/field23/env.sh
for d in "$@"; do
  nice -n 10 sh tests/field23/engine.sh "$d" > /dev/null 2>&1
  nice -n 10 sh tests/field23/audit.sh "$d"
done

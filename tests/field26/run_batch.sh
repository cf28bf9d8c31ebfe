#!/bin/sh
# Field round 26: for each deck folder, run it in its engine (engine.sh) then audit it (audit.sh), niced.
# usage (from the worktree): sh tests/field26/run_batch.sh DECKDIR ...
. tests/field26/env.sh
for d in "$@"; do
  nice -n 10 sh tests/field26/engine.sh "$d" > /dev/null 2>&1
  nice -n 10 sh tests/field26/audit.sh "$d"
done

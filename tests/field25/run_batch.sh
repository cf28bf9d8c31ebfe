#!/bin/sh
# Field round 25: for each deck folder, run it in its engine (engine.sh) then audit it (audit.sh), niced.
# usage (from the worktree): sh tests/field25/run_batch.sh DECKDIR ...
. tests/field25/env.sh
for d in "$@"; do
  nice -n 10 sh tests/field25/engine.sh "$d" > /dev/null 2>&1
  nice -n 10 sh tests/field25/audit.sh "$d"
done

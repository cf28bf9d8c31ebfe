#!/bin/sh
# The field rounds' batch: for each deck folder, run it in its engine (the round's engine.sh) then audit it (its audit.sh), niced.
# usage (from the worktree): ROUND=NN sh tests/fieldkit/run_batch.sh DECKDIR ...   (each round's run_batch.sh sets ROUND)
: "${ROUND:?set ROUND to the field round's number}"
. tests/fieldkit/env.sh
for d in "$@"; do
  nice -n 10 sh tests/field$ROUND/engine.sh "$d" > /dev/null 2>&1
  nice -n 10 sh tests/field$ROUND/audit.sh "$d"
done

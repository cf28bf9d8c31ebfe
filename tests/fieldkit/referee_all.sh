#!/bin/sh
# The field rounds' spec referee over deck folders that have a spec.json, one at a time, niced: the last 12 lines of each.
# usage (from the worktree): REFEREE=tests/fieldNN/refereeNN.py sh tests/fieldkit/referee_all.sh DECKDIR ...
: "${REFEREE:?set REFEREE to the round's referee script}"
. tests/fieldkit/env.sh
for d in "$@"; do
  [ -f "$d/spec.json" ] || continue
  echo "### $d"; nice -n 10 python "$REFEREE" "$d" 2>&1 | tail -12
done

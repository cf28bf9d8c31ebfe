#!/bin/sh
# Field round 30: audit (audit.sh) or referee (live30.py) a list of deck folders; run from the worktree.
# usage: tests/field30/batch.sh audit|live LOG DECKDIR ...
. tests/field30/env.sh
what=$1; log=$2; shift 2
for d in "$@"; do
  if [ "$what" = audit ]; then timeout 600 nice -n 10 sh tests/field30/audit.sh "$d" >> "$log" 2>&1
  elif [ -f "$d/LIVE" ]; then timeout 900 nice -n 10 python tests/field30/live30.py "$d" >> "$log" 2>&1; fi
done
echo DONE >> "$log"

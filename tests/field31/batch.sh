#!/bin/sh
# Field round 30: audit (audit.sh) or referee (live31.py) a list of deck folders; run from the worktree.
# usage: tests/field31/batch.sh audit|live LOG DECKDIR ...
. tests/field31/env.sh
what=$1; log=$2; shift 2
for d in "$@"; do
  if [ "$what" = audit ]; then timeout 600 nice -n 10 sh tests/field31/audit.sh "$d" >> "$log" 2>&1
  elif [ -f "$d/LIVE" ]; then timeout 900 nice -n 10 python tests/field31/live31.py "$d" >> "$log" 2>&1; fi
done
echo DONE >> "$log"

#!/bin/sh
# Field round 33: audit (audit.sh, QUICK) or referee (live33.py) a list of deck folders, one at a time, nice 10; run
# from the worktree.  usage: tests/field33/batch.sh audit|live LOG DECKDIR ...
. tests/field33/env.sh
what=$1; log=$2; shift 2
for d in "$@"; do
  if [ "$what" = audit ]; then QUICK=1 timeout 600 nice -n 10 sh tests/field33/audit.sh "$d" >> "$log" 2>&1
  elif [ -f "$d/LIVE" ]; then timeout 900 nice -n 10 python tests/field33/live33.py "$d" >> "$log" 2>&1; fi
done
echo DONE >> "$log"

#!/bin/sh
# Field round 40: audit (the kit's audit.sh, QUICK) or referee (round 37's live37.py) a list of deck folders, one at a
# time, nice 10; run from the worktree.  usage: tests/field40/batch.sh audit|live LOG DECKDIR ...
. tests/field37/env.sh
what=$1; log=$2; shift 2
for d in "$@"; do
  if [ "$what" = audit ]; then QUICK=1 ROUND=40 timeout 600 nice -n 10 sh tests/fieldkit/audit.sh "$d" >> "$log" 2>&1
  else timeout 900 nice -n 10 python tests/field37/live37.py "$d" >> "$log" 2>&1; fi
done
echo DONE >> "$log"

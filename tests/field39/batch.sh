#!/bin/sh
# Field round 39: audit (audit.sh, QUICK) or referee (round 37's live37.py: links and hard links kept) a list of deck
# folders, one at a time, nice 10; run from the worktree.  usage: tests/field39/batch.sh audit|live LOG DECKDIR ...
. tests/field37/env.sh
what=$1; log=$2; shift 2
for d in "$@"; do
  if [ "$what" = audit ]; then QUICK=1 timeout 600 nice -n 10 sh tests/field39/audit.sh "$d" >> "$log" 2>&1
  else timeout 1800 nice -n 10 python tests/field37/live37.py "$d" >> "$log" 2>&1; fi
done
echo DONE >> "$log"

#!/bin/sh
# Field round 47b: the referee first (round 37's live37.py, 1 process), the audit later (the kit's audit.sh, ROUND=47,
# QUICK, one core, PYTHONPATH the worktree's src).
#   sh batch.sh         live1.log: every folder make_decks47b.py writes, before any audit
#   sh batch.sh audit   batch1.log
cd "$(dirname "$0")/../.."
. tests/fieldkit/env.sh
export PYTHONPATH=$PWD/src
D=tests/field47b/decks
if [ "$1" = audit ]; then
  QUICK=1 ROUND=47 sh tests/fieldkit/audit.sh $D/* > tests/field47b/batch1.log 2>&1
else
  python tests/field37/live37.py $D/* > tests/field47b/live1.log 2>&1
fi

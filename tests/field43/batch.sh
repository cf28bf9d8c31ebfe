#!/bin/sh
# Field round 43: the referee (round 37's live37.py, 1 process) first, over every deck folder; the audit (the kit's
# audit.sh, ROUND=43, QUICK, one core) later, with main's code of 01:50 UTC or after (`sh batch.sh audit`).
cd "$(dirname "$0")/../.."
. tests/fieldkit/env.sh
export PYTHONPATH=$PWD/src
if [ "$1" = audit ]; then
  QUICK=1 ROUND=43 sh tests/fieldkit/audit.sh tests/field43/decks/* > tests/field43/batch1.log 2>&1
elif [ "$1" = set4 ]; then
  # the fourth set (B93-B95: the reach of two silently wrong classes), made after the audit: referee then audit
  python tests/field37/live37.py tests/field43/decks/B9[3-5]* > tests/field43/live4.log 2>&1
  QUICK=1 ROUND=43 sh tests/fieldkit/audit.sh tests/field43/decks/B9[3-5]* > tests/field43/batch2.log 2>&1
else
  python tests/field37/live37.py tests/field43/decks/* > tests/field43/live1.log 2>&1
  # the second set (B80-B82, H51-H53), made after the first ran
  python tests/field37/live37.py tests/field43/decks/B8[0-2]* tests/field43/decks/H5[1-3]* > tests/field43/live2.log 2>&1
  # the third set (B83-B92), made after the second
  python tests/field37/live37.py tests/field43/decks/B8[3-9]* tests/field43/decks/B9* > tests/field43/live3.log 2>&1
fi

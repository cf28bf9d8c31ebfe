#!/bin/sh
# Field round 41: the referee (round 37's live37.py, 1 process) then the kit's audit (QUICK, one core), one after the other.
cd "$(dirname "$0")/../.."
python tests/field37/live37.py tests/field41/decks/* > tests/field41/live1.log 2>&1
QUICK=1 ROUND=41 sh tests/fieldkit/audit.sh tests/field41/decks/* > tests/field41/batch1.log 2>&1

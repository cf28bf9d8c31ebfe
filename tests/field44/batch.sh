#!/bin/sh
# Field round 44: the referee (round 37's live37.py, 1 process) first, over every deck folder; the audit (the kit's
# audit.sh, ROUND=44, QUICK, one core) later, with main's code of 02:55 UTC or after (`sh batch.sh audit`).
cd "$(dirname "$0")/../.."
. tests/fieldkit/env.sh
export PYTHONPATH=$PWD/src
if [ "$1" = audit ]; then
  QUICK=1 ROUND=44 sh tests/fieldkit/audit.sh tests/field44/decks/* > tests/field44/batch1.log 2>&1
elif [ "$1" = set4 ]; then
  # the fourth set (K23 K24: the reach of K18), made after the audit: referee then audit
  python tests/field37/live37.py tests/field44/decks/K2[34]* > tests/field44/live4.log 2>&1
  QUICK=1 ROUND=44 sh tests/fieldkit/audit.sh tests/field44/decks/K2[34]* > tests/field44/batch2.log 2>&1
elif [ "$1" = set5 ]; then
  # the fifth set (V22 V23: the reach of V09), made after the audit: referee then audit
  python tests/field37/live37.py tests/field44/decks/V2[23]* > tests/field44/live5.log 2>&1
  QUICK=1 ROUND=44 sh tests/fieldkit/audit.sh tests/field44/decks/V2[23]* > tests/field44/batch3.log 2>&1
else
  python tests/field37/live37.py tests/field44/decks/* > tests/field44/live1.log 2>&1
  # the second set (V03 made runnable with an atom map, V17-V19, W13, H27-H29), made after the first ran
  python tests/field37/live37.py tests/field44/decks/V03* tests/field44/decks/V1[789]* tests/field44/decks/W13* tests/field44/decks/H2[789]* > tests/field44/live2.log 2>&1
  # the third set (V20 V21 X01 X02 G18 H30)
  python tests/field37/live37.py tests/field44/decks/V2[01]* tests/field44/decks/X0* tests/field44/decks/G18* tests/field44/decks/H30* > tests/field44/live3.log 2>&1
fi

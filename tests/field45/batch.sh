#!/bin/sh
# Field round 45: the referee first (round 37's live37.py for B/O/H/M, 1 process; pubref45.py for the public R decks and
# M01-M03, whose own print says PUB45), the audit later (the kit's audit.sh, ROUND=45, QUICK, one core).
#   sh batch.sh            live1.log: B O H of the first set (120 folders, written before any audit)
#   sh batch.sh pub        live2.log: R01-R39 (pubdecks45.py wrote them)
#   sh batch.sh audit      batch1.log: every folder of the first 172 (B O H R), on 51acc06e
#   sh batch.sh sets       the later sets, each referee log then its audit log, as they were made:
#     live3/batch2 (O61-O65 B25 B31-B38, the engine-runnable forms of O20 O22 O24 O31 O34 O59 and more B; set 2 B39-B42
#     O66-O69 H31-H33 in live5/live6), live4 (R33-R36 again: seeds made prime), live7 (B43-B46), live8/live9/batch3
#     (M01-M06 B47-B49 O70), live10/batch4 (M07-M09), live11/batch5 (M10 M11), live12/batch6 (M12 M13), live13/batch7
#     (R40), live14/batch8 (B50-B53), live15/batch9 (B54 B55), live16/batch10 (B56 B57), live17/batch11 (B58-B62),
#     live18/batch12 (B63 B64), live19/batch13 (B65-B68 O71 O72), live20/batch14 (B69 B70), live21/batch15 (O73-O78),
#     live22/batch16 (O79 O80), live23/batch17 (B71-B74), live24/batch18 (M14 M15), live25/batch19 (B75-B78), live26/batch20 (B79), live27/batch21 (B80 B81)
cd "$(dirname "$0")/../.."
. tests/fieldkit/env.sh
export PYTHONPATH=$PWD/src
D=tests/field45/decks
if [ "$1" = audit ]; then
  QUICK=1 ROUND=45 sh tests/fieldkit/audit.sh $D/[BHOR]* > tests/field45/batch1.log 2>&1
elif [ "$1" = pub ]; then
  python tests/field45/pubref45.py $D/R* > tests/field45/live2.log 2>&1
elif [ "$1" = sets ]; then
  for p in "O6[1-9] B25 B3[1-9] B4[0-2] H3[1-3]" "B4[3-9] O70" "M0[4-9] M1[0-5]" "B5[0-9] B6[0-9] B7[0-9] B8[01] O7[1-9] O80"; do
    python tests/field37/live37.py $(for x in $p; do ls -d $D/$x* 2>/dev/null; done) >> tests/field45/live-sets.log 2>&1
    QUICK=1 ROUND=45 sh tests/fieldkit/audit.sh $(for x in $p; do ls -d $D/$x* 2>/dev/null; done) >> tests/field45/batch-sets.log 2>&1
  done
  python tests/field45/pubref45.py $D/M0[123]* $D/R40* >> tests/field45/live-sets.log 2>&1
  QUICK=1 ROUND=45 sh tests/fieldkit/audit.sh $D/M0[123]* $D/R40* >> tests/field45/batch-sets.log 2>&1
else
  python tests/field37/live37.py $D/[BOH]* > tests/field45/live1.log 2>&1
fi

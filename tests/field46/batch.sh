#!/bin/sh
# Field round 46: the referee first (round 37's live37.py, 1 process; pubref46.py for the public P decks), the audit
# later (the kit's audit.sh, ROUND=46, QUICK, one core, PYTHONPATH the worktree's src).
#   sh batch.sh            live1.log: every generated folder (G T W I D V L H), written before any audit
#   sh batch.sh pub        live2.log: the public P folders (pubdecks46.py wrote them)
#   sh batch.sh audit      batch1.log: every folder of the first set (G T W I D V L H P)
#   sh batch.sh sets       the later sets, as they were run: live3.log (13 first-set folders rewritten after the engine
#     stopped on the writer's mistakes, before any audit), live4/batch2 (X01-X33, written while batch1 ran; X31-X33
#     after the engine stopped on X24 X26 X27), live5/batch3 (Y01-Y11: binary STL meshes, after reading P06's audit),
#     live6/batch4 (Z01-Z07: data files that look like commands; Z08-Z18 appended after reading Z04 and Z13),
#     live7/batch5 (S01-S14, hidden), live8/batch6 (Q01-Q10, hidden)
cd "$(dirname "$0")/../.."
. tests/fieldkit/env.sh
export PYTHONPATH=$PWD/src
D=tests/field46/decks
if [ "$1" = audit ]; then
  QUICK=1 ROUND=46 sh tests/fieldkit/audit.sh $D/[GTWIDVLHP]* > tests/field46/batch1.log 2>&1
elif [ "$1" = sets ]; then
  python tests/field37/live37.py $D/G02* $D/G10* $D/H08* $D/W03* $D/W11* $D/W18* $D/T19* $D/L10* $D/I01* $D/I04* $D/I06* $D/I07* $D/H05* > tests/field46/live3.log 2>&1
  for s in "X:live4:batch2" "Y:live5:batch3" "Z:live6:batch4" "S:live7:batch5" "Q:live8:batch6"; do
    f=${s%%:*}; r=${s#*:}; l=${r%%:*}; b=${r#*:}
    python tests/field37/live37.py $D/$f* > tests/field46/$l.log 2>&1
    QUICK=1 ROUND=46 sh tests/fieldkit/audit.sh $D/$f* > tests/field46/$b.log 2>&1
  done
elif [ "$1" = pub ]; then
  python tests/field46/pubref46.py $D/P* > tests/field46/live2.log 2>&1
else
  python tests/field37/live37.py $D/[GTWIDVLH]* > tests/field46/live1.log 2>&1
fi

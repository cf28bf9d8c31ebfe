#!/bin/sh
# Field round 21: the types 1 1 head-on eps LAMMPS gives (probe21.py, 4 mm 2500 kg/m3, g 1) beside the audit's last-stage
# types 1 1 row at g = 1, for LAMMPS deck folders whose audit answered. usage (from the worktree): sh tests/field21/probe_all21.sh DECKDIR ...
. tests/field21/env.sh
for d in "$@"; do
  [ -f "$d/LIGGGHTS" ] && continue
  [ "$(cat $d/audit.rc)" = 0 ] || continue
  a=$(python -c "
import json,sys
a=json.load(open(sys.argv[1])); st=(a.get('stages') or [a])[-1]
r=[p for p in st.get('pairs',[]) if p['types']==[1,1] and not p.get('sizes')]
print('%.6f' % r[0]['eps'][[abs(x-1) for x in r[0]['speeds']].index(min(abs(x-1) for x in r[0]['speeds']))] if r and r[0]['eps'][0] is not None else 'none')" $d/audit.json 2>/dev/null)
  e=$(nice -n 10 python tests/field21/probe21.py $d 1 1 0.004 2500 0.004 2500 | grep -o "eps [-0-9.]*" | cut -d' ' -f2)
  echo "$(basename $d) audit $a engine ${e:-none}"
done

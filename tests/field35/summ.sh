#!/bin/sh
# Field round 35: one line per audited deck folder: rc, the rows of its pair in every stage, the refusal's last line
# usage (from tests/field35): sh summ.sh decks/PREFIX*
for d in "$@"; do [ -f $d/audit.rc ] || continue; echo "$(basename $d) rc=$(cat $d/audit.rc) $(cd .. && python3 -c "
import sys, os; sys.path.insert(0,'.')
from fieldkit import rows
d='field35/$d'; p=open(d+'/PAIR').read().strip() if os.path.exists(d+'/PAIR') else 'types 1 2'
print(rows.stages(d,p))") $( [ $(cat $d/audit.rc) != 0 ] && tail -1 $d/audit.err | cut -c1-300)"; done

#!/bin/sh
# Field round 28: the public and example decks: audit (audit.sh), then the engine (publive28.py where the deck's own
# pair is refereed, engine.sh otherwise). usage: tests/field28/batchx.sh LOG DECKDIR ...
. tests/field28/env.sh
log=$1; shift
for d in "$@"; do
  timeout 900 nice -n 10 sh tests/field28/audit.sh "$d" >> "$log" 2>&1
  if [ -f "$d/PUBLIVE" ]; then timeout 1800 nice -n 10 python tests/field28/publive28.py "$d" >> tests/field28/publive.log 2>&1
  else timeout 1800 nice -n 10 sh tests/field28/engine.sh "$d" > /dev/null 2>&1; echo "$(basename $d) $(head -1 $d/ENGINE.txt)" >> tests/field28/engineX.log; fi
done
echo DONE >> "$log"

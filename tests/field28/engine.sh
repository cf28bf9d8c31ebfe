#!/bin/sh
# Field round 28 (round 13's script, names changed): run a deck folder to its end in its own engine (scratch copy under /tmp/field28-*),
# print rc, runs, errors/warnings and the tail of the screen; ENGINE.txt keeps it beside the deck.
d=${1%/}
deck=$(cat "$d/DECK" 2>/dev/null || (cd "$d" && ls in.* | head -1))
top=$(mktemp -d /tmp/field28-eng.XXXXXX); tmp=$top/a/b/c; mkdir -p $tmp; cp -r "$d"/. "$tmp"/   # nested: ../ and shell cd .. stay inside
if [ -f "$d/LIGGGHTS" ]; then
  (cd "$tmp" && timeout 600 liggghts -in "$deck" -log none > screen.txt 2>&1); rc=$?
else
  (cd "$tmp" && LD_LIBRARY_PATH=$LD_LIBRARY_PATH timeout 600 lmp -in "$deck" -log none > screen.txt 2>&1); rc=$?
fi
{ echo "engine rc=$rc; $(grep -c 'Loop time' $tmp/screen.txt) runs"
  grep -E "ERROR|WARNING" "$tmp/screen.txt" | sort | uniq -c | head -5
  grep -E "^(PROBE|print)|^  *[0-9]+ +[0-9]" "$tmp/screen.txt" | tail -3 | cut -c1-200
  grep -E "^PROBE" "$tmp/screen.txt" | head -20; } | tee "$d/ENGINE.txt"
rm -rf "$top"

#!/bin/sh
# Run a deck folder in the engine itself (in a scratch copy) to check it runs to its end.
# usage: engine_check.sh DECKDIR  -> prints rc and the last lines of the engine's screen
d=${1%/}
deck=$(cat "$d/DECK" 2>/dev/null || (cd "$d" && ls in.* | head -1))
tmp=$(mktemp -d); cp -r "$d"/. "$tmp"/
if [ -f "$d/LIGGGHTS" ]; then
  (cd "$tmp" && timeout 300 liggghts -in "$deck" -log none > screen.txt 2>&1); rc=$?
else
  (cd "$tmp" && timeout 300 lmp -in "$deck" -log none > screen.txt 2>&1); rc=$?
fi
grep -E "ERROR|WARNING" "$tmp/screen.txt" | sort | uniq -c | head -5
echo "engine rc=$rc; $(grep -c 'Loop time' $tmp/screen.txt) runs"; rm -rf "$tmp"

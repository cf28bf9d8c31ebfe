#!/bin/sh
# Field round 26: a traceback by a race: a deck with `shell cd ..` makes the audit copy the folder above the deck's
# folder; when another process deletes files there while it copies, the audit ends with a Python traceback
# (FileNotFoundError / shutil.Error, rc 1). Reproduction: P02's deck in a scratch folder whose parent another loop
# fills and empties. usage (from the worktree, venv on PATH): sh tests/field26/race26.sh [TRIES]
n=${1:-5}
top=$(mktemp -d /tmp/field26-race.XXXXXX); mkdir -p "$top/par"; cp -r tests/field26/decks/P02_shell_cd_back "$top/par/dk"
( i=1; while [ $i -le 3000 ]; do mkdir -p "$top/par/churn$i"; echo x > "$top/par/churn$i/f"; rm -rf "$top/par/churn$((i-1))"; i=$((i+1)); done ) &
ch=$!
k=1
while [ $k -le $n ]; do
  restitution deck "$top/par/dk/in.deck" --g 1 > "$top/o.txt" 2> "$top/e.txt"; rc=$?
  echo "try $k rc $rc: $(grep -c Traceback $top/e.txt) traceback(s); $(tail -1 $top/e.txt | cut -c1-160)"
  k=$((k+1))
done
kill $ch 2>/dev/null; wait $ch 2>/dev/null
rm -rf "$top"

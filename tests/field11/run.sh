#!/bin/sh
# Field round 11: audit one deck folder (or all), then referee it where it has a spec.json.
# usage: tests/field10/run.sh [DECKDIR ...]   (from the worktree, venv active, LD_LIBRARY_PATH set)
here=$(dirname "$0")
[ $# -eq 0 ] && set -- "$here"/decks/*/
for d in "$@"; do
  d=${d%/}
  deck=$(cat "$d/DECK" 2>/dev/null || (cd "$d" && ls in.* | head -1))
  g=$(cat "$d/G" 2>/dev/null || echo 1)
  extra=$(cat "$d/ARGS" 2>/dev/null)
  restitution deck "$d/$deck" --g $g $extra > "$d/audit.out" 2> "$d/audit.err"; echo $? > "$d/audit.rc"
  restitution deck "$d/$deck" --g $g $extra --json > "$d/audit.json" 2>/dev/null
  echo "== $d rc=$(cat $d/audit.rc)"
  [ -f "$d/spec.json" ] && [ "$(cat $d/audit.rc)" = 0 ] && [ -z "$NOREF" ] && python "$here/referee.py" "$d" > /dev/null
  [ -f "$d/referee.txt" ] && tail -1 "$d/referee.txt"
done

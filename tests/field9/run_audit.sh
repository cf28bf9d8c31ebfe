#!/bin/sh
# Runs `restitution deck` on each case folder given (default: all), keeping stdout, stderr and
# exit status in the folder (audit.out, audit.err, audit.rc) and the --json answer (audit.json).
# Usage (from the worktree): sh tests/field9/run_audit.sh [decks/CASE ...]; G=speed (default 1).
cd "$(dirname "$0")" || exit 1
G=${G:-1}
for d in ${*:-decks/*}; do
  f=$(ls "$d"/in.* 2>/dev/null | head -1)
  [ -n "$f" ] || continue
  extra=$(cat "$d/args" 2>/dev/null)
  restitution deck "$f" --g $G $extra > "$d/audit.out" 2> "$d/audit.err"; echo $? > "$d/audit.rc"
  restitution deck "$f" --g $G $extra --json > "$d/audit.json" 2>/dev/null
  echo "== $d rc=$(cat $d/audit.rc)"; cat "$d/audit.err"; cat "$d/audit.out"
done

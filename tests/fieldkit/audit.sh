#!/bin/sh
# The field rounds' audit of deck folders (text and --json), watching for files written outside the scratch copy.
# usage (from the worktree; venv on PATH, LD_LIBRARY_PATH set): ROUND=NN [CANARY=GLOB] [QUICK=1] sh tests/fieldkit/audit.sh DECKDIR ...
# Each round's tests/fieldNN/audit.sh calls this with its number. ROUND names the stamp file (/tmp/fieldNN-stamp.*) and the
# round's own deck folders, whose audit.* files are not escapes. Writes DECKDIR/audit.{out,err,rc,json,time} and
# DECKDIR/escape.txt: files newer than a stamp made just before the audit: any file two levels deep under /, the worktree's
# parent, /home, /root; anything new in /dev/shm; under /tmp, this worktree and /root the names a deck or an engine may write
# (/tmp to depth 4, the worktree and /root to depth 3): the decks' canary names (CANARY, default f[12][0-9]*: the rounds
# name them fNN_*), log.lammps, log.liggghts, log.*, atoms.dump, audit*, restart files, x; any new file in the deck's folder
# or its parent. QUICK=1 leaves out the two widest searches (/ to depth 2 and /tmp), for a quick re-audit.
: "${ROUND:?set ROUND to the field round's number}"
canary=${CANARY:-'f[12][0-9]*'}
for d in "$@"; do
  d=${d%/}
  deck=$(cat "$d/DECK" 2>/dev/null || (cd "$d" && ls in.* | head -1))
  g=$(cat "$d/G" 2>/dev/null || echo 1)
  extra=$(cat "$d/ARGS" 2>/dev/null)
  stamp=$(mktemp /tmp/field$ROUND-stamp.XXXXXX); sleep 1
  s0=$(date +%s.%N)
  restitution deck "$d/$deck" --g $g $extra > "$d/audit.out" 2> "$d/audit.err"; echo $? > "$d/audit.rc"
  s1=$(date +%s.%N)
  restitution deck "$d/$deck" --g $g $extra --json > "$d/audit.json" 2>/dev/null
  echo "$s0 $s1" | awk '{printf "%.1f s\n", $2-$1}' > "$d/audit.time"
  { [ -n "$QUICK" ] || find / "$(dirname "$(pwd)")" /home /root -maxdepth 2 -newer "$stamp" -type f 2>/dev/null
    find /dev/shm -newer "$stamp" 2>/dev/null
    [ -n "$QUICK" ] || find /tmp -maxdepth 4 -newer "$stamp" -type f \( -name "$canary" -o -name 'log.lammps' -o -name 'log.liggghts' -o -name 'x' \) 2>/dev/null
    find "$(pwd)" /root -maxdepth 3 -newer "$stamp" -type f \( -name "$canary" -o -name 'log.lammps' -o -name 'log.liggghts' \
       -o -name 'atoms.dump' -o -name 'audit*' -o -name 'log.*' -o -name '*restart*' -o -name 'x' \) \
       -not -path "*/field$ROUND/decks/*/audit.*" 2>/dev/null
    find "$d" "$d/.." -maxdepth 1 -newer "$stamp" -type f -not -name 'audit.*' -not -name escape.txt 2>/dev/null; } | grep -v -e "/logs/" -e "field$ROUND-stamp" -e "^/dev/shm$" | sort -u > "$d/escape.txt"
  rm -f "$stamp"
  echo "== $d rc=$(cat $d/audit.rc) $(cat $d/audit.time) escape=$(wc -l < $d/escape.txt)"
done

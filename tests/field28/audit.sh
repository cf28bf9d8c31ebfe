#!/bin/sh
# Field round 28 (round 13's script, names changed): audit deck folders (text and --json), watching for files written outside the scratch copy.
# usage: tests/field28/audit.sh DECKDIR ...  (from the worktree; venv on PATH, LD_LIBRARY_PATH set)
# Writes DECKDIR/audit.{out,err,rc,json} and DECKDIR/escape.txt: files newer than a stamp made just before
# the audit: any file two levels deep under /, the worktree's parent, /home, /root; under /tmp, this worktree and /root the
# names a deck or an engine may write (/tmp to depth 4, the worktree and /root to depth 3) (the decks' canary names f16*, log.lammps, log.liggghts, log.*,
# atoms.dump, audit*, restart files, x); any new file in the deck's folder or its parent.
for d in "$@"; do
  d=${d%/}
  deck=$(cat "$d/DECK" 2>/dev/null || (cd "$d" && ls in.* | head -1))
  g=$(cat "$d/G" 2>/dev/null || echo 1)
  extra=$(cat "$d/ARGS" 2>/dev/null)
  stamp=$(mktemp /tmp/field28-stamp.XXXXXX); sleep 1
  s0=$(date +%s.%N)
  restitution deck "$d/$deck" --g $g $extra > "$d/audit.out" 2> "$d/audit.err"; echo $? > "$d/audit.rc"
  s1=$(date +%s.%N)
  restitution deck "$d/$deck" --g $g $extra --json > "$d/audit.json" 2>/dev/null
  echo "$s0 $s1" | awk '{printf "%.1f s\n", $2-$1}' > "$d/audit.time"
  { find / "$(dirname "$(pwd)")" /home /root -maxdepth 2 -newer "$stamp" -type f 2>/dev/null
    find /dev/shm -newer "$stamp" 2>/dev/null
    find /tmp -maxdepth 4 -newer "$stamp" -type f \( -name 'f[12][0-9]*' -o -name 'log.lammps' -o -name 'log.liggghts' -o -name 'x' \) 2>/dev/null
    find "$(pwd)" /root -maxdepth 3 -newer "$stamp" -type f \( -name 'f[12][0-9]*' -o -name 'log.lammps' -o -name 'log.liggghts' \
       -o -name 'atoms.dump' -o -name 'audit*' -o -name 'log.*' -o -name '*restart*' -o -name 'x' \) \
       -not -path "*/field28/decks/*/audit.*" 2>/dev/null
    find "$d" "$d/.." -maxdepth 1 -newer "$stamp" -type f -not -name 'audit.*' -not -name escape.txt 2>/dev/null; } | grep -v -e "/logs/" -e "field28-stamp" -e "^/dev/shm$" | sort -u > "$d/escape.txt"
  rm -f "$stamp"
  echo "== $d rc=$(cat $d/audit.rc) $(cat $d/audit.time) escape=$(wc -l < $d/escape.txt)"
done

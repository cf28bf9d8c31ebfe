#!/bin/sh
# Field round 26: a differential test: `clear` (or the lines in PREFIX, e.g. "echo both\\nnewton off\\n") as a deck's first lines changes nothing in LAMMPS (it starts from the
# same empty state), so the audit's rc and rows must not change (stage headers cite line numbers, shifted by one,
# and are left out). For each deck folder given, a scratch copy with
# `clear` prepended to its deck is audited; folders whose rc or stdout differ are listed with the first differing line.
# usage (from the worktree, venv on PATH): sh tests/field26/cleartest26.sh DECKDIR ...
for d in "$@"; do
  d=${d%/}; deck=$(cat "$d/DECK"); g=$(cat "$d/G")
  [ -f "$d/LIGGGHTS" ] && continue
  t=$(mktemp -d /tmp/field26-clear.XXXXXX); cp -r "$d"/. "$t"/
  { printf "%b" "${PREFIX:-clear\n}"; cat "$d/$deck"; } > "$t/$deck"
  restitution deck "$t/$deck" --g $g > "$t/c.out" 2>/dev/null; rc=$?
  grep -E '^(types|type) |^  g ' "$d/audit.out" | sed 's/ (stage [^)]*)//' > "$t/a.rows"; grep -E '^(types|type) |^  g ' "$t/c.out" | sed 's/ (stage [^)]*)//' > "$t/c.rows"
  if [ "$rc" != "$(cat $d/audit.rc)" ] || ! cmp -s "$t/a.rows" "$t/c.rows"; then
    echo "DIFF $(basename $d) rc $(cat $d/audit.rc) -> $rc: $(diff "$t/a.rows" "$t/c.rows" | grep '^[<>]' | head -2 | tr '\n' ' ' | cut -c1-250)"
  else
    echo "same $(basename $d)"
  fi
  rm -rf "$t"
done

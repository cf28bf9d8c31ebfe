#!/bin/sh
# Field round 26: a differential test: the deck file (and every *.in file beside it) rewritten with CRLF line ends
# (a deck edited on Windows). LAMMPS reads a trailing CR as white space, so the audit's rc and rows must not change.
# usage (from the worktree, venv on PATH): sh tests/field26/crlftest26.sh DECKDIR ...
rows() { grep -E '^(types|type) |^  g ' "$1" | sed 's/ (stage [^)]*)//'; }
for d in "$@"; do
  d=${d%/}; deck=$(cat "$d/DECK"); g=$(cat "$d/G")
  [ -f "$d/LIGGGHTS" ] && continue
  t=$(mktemp -d /tmp/field26-crlf.XXXXXX); cp -r "$d"/. "$t"/
  for f in "$t/$deck" "$t"/*.in; do [ -f "$f" ] && sed -i 's/$/\r/' "$f"; done
  (cd "$t" && restitution deck "$deck" --g $g > c.out 2> c.err); rc=$?
  rows "$d/audit.out" > "$t/a.rows"; rows "$t/c.out" > "$t/c.rows"
  if [ "$rc" != "$(cat $d/audit.rc)" ] || ! cmp -s "$t/a.rows" "$t/c.rows"; then
    echo "DIFF $(basename $d) rc $(cat $d/audit.rc) -> $rc: $(diff "$t/a.rows" "$t/c.rows" | grep '^[<>]' | head -2 | tr '\n' ' ' | cut -c1-200) | $(tail -1 $t/c.err | cut -c1-200)"
  else
    echo "same $(basename $d)"
  fi
  rm -rf "$t"
done

#!/bin/sh
# Field round 26: a differential test: a deck run through a wrapper file that only opens it (MODE include: `include
# DECK`; ifinclude: `if 1 then "include DECK"`; jump: `jump DECK`) is the same simulation in LAMMPS, so the audit's rc
# and its rows (the lines naming pairs and walls and their g lines; stage headers cite line numbers and are left out)
# must not change. usage (from the worktree, venv on PATH): sh tests/field26/wraptest26.sh MODE DECKDIR ...
mode=$1; shift
rows() { grep -E '^(types|type) |^  g ' "$1" | sed 's/ (stage [^)]*)//'; }
for d in "$@"; do
  d=${d%/}; deck=$(cat "$d/DECK"); g=$(cat "$d/G")
  [ -f "$d/LIGGGHTS" ] && continue
  t=$(mktemp -d /tmp/field26-wrap.XXXXXX); cp -r "$d"/. "$t"/
  case $mode in
    include) echo "include $deck" > "$t/in.wrap";;
    ifinclude) echo "if 1 then \"include $deck\"" > "$t/in.wrap";;
    jump) echo "jump $deck" > "$t/in.wrap";;
  esac
  (cd "$t" && restitution deck in.wrap --g $g > c.out 2> c.err); rc=$?
  rows "$d/audit.out" > "$t/a.rows"; rows "$t/c.out" > "$t/c.rows"
  if [ "$rc" != "$(cat $d/audit.rc)" ] || ! cmp -s "$t/a.rows" "$t/c.rows"; then
    echo "DIFF $(basename $d) rc $(cat $d/audit.rc) -> $rc: $(diff "$t/a.rows" "$t/c.rows" | grep '^[<>]' | head -2 | tr '\n' ' ' | cut -c1-200) | $(tail -1 $t/c.err | cut -c1-200)"
  else
    echo "same $(basename $d)"
  fi
  rm -rf "$t"
done

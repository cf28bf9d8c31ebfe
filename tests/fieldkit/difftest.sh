#!/bin/sh
# The field rounds' differential audit tests (round 26): each deck folder given (LAMMPS decks) is copied to a scratch
# folder, changed in a way that is the same simulation for LAMMPS, and audited again; the audit's rc and its rows (the
# lines naming pairs and walls and their g lines; stage headers cite line numbers and are left out) must not change.
# Folders whose rc or rows differ are listed with the first differing lines.
# usage (from the worktree, venv on PATH): sh tests/fieldkit/difftest.sh MODE DECKDIR ...   MODE:
#   clear      `clear` (or the lines in PREFIX, e.g. "echo both\\nnewton off\\n") put before the deck's first line
#   crlf       the deck file and every *.in file beside it rewritten with CRLF line ends (a deck edited on Windows)
#   include | ifinclude | jump   a wrapper file that only opens the deck (`include DECK`, `if 1 then "include DECK"`, `jump DECK`)
# ROUND (default 26) names the scratch folders /tmp/fieldROUND-MODE.*
mode=$1; shift
rows() { grep -E '^(types|type) |^  g ' "$1" | sed 's/ (stage [^)]*)//'; }
case $mode in clear) tag=clear;; crlf) tag=crlf;; *) tag=wrap;; esac
for d in "$@"; do
  d=${d%/}; deck=$(cat "$d/DECK"); g=$(cat "$d/G")
  [ -f "$d/LIGGGHTS" ] && continue
  t=$(mktemp -d /tmp/field${ROUND:-26}-$tag.XXXXXX); cp -r "$d"/. "$t"/
  case $mode in
    clear)
      { printf "%b" "${PREFIX:-clear\n}"; cat "$d/$deck"; } > "$t/$deck"
      restitution deck "$t/$deck" --g $g > "$t/c.out" 2>/dev/null; rc=$?;;
    crlf)
      for f in "$t/$deck" "$t"/*.in; do [ -f "$f" ] && sed -i 's/$/\r/' "$f"; done
      (cd "$t" && restitution deck "$deck" --g $g > c.out 2> c.err); rc=$?;;
    *)
      case $mode in
        include) echo "include $deck" > "$t/in.wrap";;
        ifinclude) echo "if 1 then \"include $deck\"" > "$t/in.wrap";;
        jump) echo "jump $deck" > "$t/in.wrap";;
      esac
      (cd "$t" && restitution deck in.wrap --g $g > c.out 2> c.err); rc=$?;;
  esac
  rows "$d/audit.out" > "$t/a.rows"; rows "$t/c.out" > "$t/c.rows"
  if [ "$rc" != "$(cat $d/audit.rc)" ] || ! cmp -s "$t/a.rows" "$t/c.rows"; then
    if [ "$mode" = clear ]; then
      echo "DIFF $(basename $d) rc $(cat $d/audit.rc) -> $rc: $(diff "$t/a.rows" "$t/c.rows" | grep '^[<>]' | head -2 | tr '\n' ' ' | cut -c1-250)"
    else
      echo "DIFF $(basename $d) rc $(cat $d/audit.rc) -> $rc: $(diff "$t/a.rows" "$t/c.rows" | grep '^[<>]' | head -2 | tr '\n' ' ' | cut -c1-200) | $(tail -1 $t/c.err | cut -c1-200)"
    fi
  else
    echo "same $(basename $d)"
  fi
  rm -rf "$t"
done

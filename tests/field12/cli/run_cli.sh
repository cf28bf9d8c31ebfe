#!/bin/sh
# Field round 12: command-line misuse of `restitution deck`. Run from this folder with the venv on PATH.
# Each case prints its command, exit status and the first lines of stdout/stderr (cli.out).
ok=../decks/a13_nve_on_type_group_plus_nvesphere_other/in.deck
scratch=$(mktemp -d)
printf '\000\001\002\377\376binary\000' > "$scratch/binary.in"
: > "$scratch/empty.in"
cp "$ok" "$scratch/unreadable.in"; chmod 000 "$scratch/unreadable.in"
mkdir "$scratch/adir"
cp "$ok" "$scratch/with space.in"
cp "$ok" "$scratch/-dash.in"
run() {
  echo "### $*"
  sh -c "$*" > "$scratch/o" 2> "$scratch/e"; rc=$?
  echo "rc=$rc"; head -c 400 "$scratch/o" | head -3 | sed 's/^/  out: /'; head -c 600 "$scratch/e" | head -4 | sed 's/^/  err: /'
  grep -c Traceback "$scratch/e" | sed 's/^/  tracebacks: /'
}
run "restitution deck $ok --g abc"
run "restitution deck $ok --g 0"
run "restitution deck $ok --g -1"
run "restitution deck $ok --g nan"
run "restitution deck $ok --g inf"
run "restitution deck $ok --g 1e400"
run "restitution deck $ok"
run "restitution deck /nonexistent/in.deck --g 1"
run "restitution deck $scratch/adir --g 1"
run "restitution deck $scratch/binary.in --g 1"
run "restitution deck $scratch/empty.in --g 1"
run "restitution deck $scratch/unreadable.in --g 1"
run "restitution deck '$scratch/with space.in' --g 1"
run "restitution deck --g 1 -- '$scratch/-dash.in'"
run "cd $scratch && restitution deck --g 1 -- -dash.in"
run "restitution deck $ok --g 1 --radius 1=abc"
run "restitution deck $ok --g 1 --radius =0.1"
run "restitution deck $ok --g 1 --radius 1=-0.1"
run "restitution deck $ok --g 1 --radius 9=0.1"
run "restitution deck $ok --g 1 --budget 0"
run "restitution deck $ok --g 1 --budget -5"
run "restitution deck $ok --g 1 >&-"
run "restitution deck $ok --g 1 --json >&-"
run "restitution deck $ok --g 1 > /dev/full"
run "restitution deck ../decks/a01_gravity_one_type/in.deck --g 1 2>&- >/dev/null; echo stderr-closed-rc=\$?"
run "restitution deck $ok --g 1 | head -1"
chmod 600 "$scratch/unreadable.in"; rm -rf "$scratch"

#!/bin/sh
# Field round 14, x10 (see README). usage: sh run_x10.sh   (from the worktree, venv on PATH)
here=$(cd "$(dirname "$0")" && pwd)
F=$(mktemp -d /tmp/field14-x10.XXXXXX); mkdir -p "$F/tmp" "$F/sub"
cp "$here/../p01_star_after_jkr_overrides/in.deck" "$F/in.deck"; cp "$F/in.deck" "$F/sub/in.deck"
TMPDIR="$F/tmp" restitution deck "$F/in.deck" --g 1 > "$F/out" 2> "$F/err"; echo "deck beside TMPDIR: rc=$?"
grep -c Traceback "$F/err" | sed 's/^/  tracebacks: /'; grep -o "shutil.Error: \[('[^']\{0,80\}" "$F/err" | head -1 | sed 's/^/  /'
grep -o "Errno 36\] File name too long" "$F/err" | head -1 | sed 's/^/  /'
TMPDIR="$F/tmp" restitution deck "$F/sub/in.deck" --g 1 > "$F/out2" 2> "$F/err2"; echo "deck one folder down: rc=$?"
rm -rf "$F"

#!/bin/sh
# Field round 14, x11 (see README). usage: sh run_x11.sh   (from the worktree, venv on PATH)
here=$(cd "$(dirname "$0")" && pwd)
for kind in fifo socket; do
  F=$(mktemp -d /tmp/field14-x11.XXXXXX); cp "$here/../p01_star_after_jkr_overrides/in.deck" "$F/in.deck"
  if [ $kind = fifo ]; then mkfifo "$F/pipe"; else python3 -c "import socket, sys; socket.socket(socket.AF_UNIX).bind(sys.argv[1])" "$F/sock"; fi
  timeout 300 restitution deck "$F/in.deck" --g 1 > "$F/out" 2> "$F/err"; echo "$kind: rc=$?, tracebacks $(grep -c Traceback "$F/err")"
  tail -1 "$F/err" | sed "s#$F#F#g; s#/tmp/restitution-deck-[a-z0-9_]*#SCRATCH#g" | cut -c1-200 | sed 's/^/  /'
  rm -rf "$F"
done

#!/bin/sh
# Field round 37: audit the deck folders not audited yet (batchN.log), then referee those with no line in any live*.log
# (liveN.log); one at a time. usage (from the worktree): sh tests/field37/rest.sh N
n=$1
H=tests/field37
A=$(for d in $H/decks/*/; do [ -f $d/audit.rc ] || echo $d; done)
[ -n "$A" ] && sh $H/batch.sh audit $H/batch$n.log $A
V=$(for d in $H/decks/*/; do grep -q "^$(basename $d) " $H/live*.log 2>/dev/null || echo $d; done)
[ -n "$V" ] && sh $H/batch.sh live $H/live$n.log $V

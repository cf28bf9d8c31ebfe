#!/bin/sh
# Field round 20: run this round's copy of round 13's referee over deck folders that have a spec.json, one at a time, niced
# (tests/fieldkit/referee_all.sh). usage (from the worktree): sh tests/field20/referee_all.sh DECKDIR ...
REFEREE=tests/field20/referee20.py exec sh tests/fieldkit/referee_all.sh "$@"

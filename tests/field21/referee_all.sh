#!/bin/sh
# Field round 21: run this round's copy of round 13's referee over deck folders that have a spec.json, one at a time, niced
# (tests/fieldkit/referee_all.sh). usage (from the worktree): sh tests/field21/referee_all.sh DECKDIR ...
REFEREE=tests/field21/referee21.py exec sh tests/fieldkit/referee_all.sh "$@"

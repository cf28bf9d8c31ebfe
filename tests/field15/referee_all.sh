#!/bin/sh
# Field round 15: run round 13's referee over deck folders that have a spec.json, one at a time, niced
# (tests/fieldkit/referee_all.sh). usage (from the worktree): sh tests/field15/referee_all.sh DECKDIR ...
REFEREE=tests/field13/referee13.py exec sh tests/fieldkit/referee_all.sh "$@"

#!/bin/sh
# Field round 15: for each deck folder, run it in its engine (engine.sh) then audit it (audit.sh), niced (tests/fieldkit/run_batch.sh).
# usage (from the worktree): sh tests/field15/run_batch.sh DECKDIR ...
ROUND=15 exec sh tests/fieldkit/run_batch.sh "$@"

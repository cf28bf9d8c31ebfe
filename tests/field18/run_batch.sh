#!/bin/sh
# Field round 18: for each deck folder, run it in its engine (engine.sh) then audit it (audit.sh), niced (tests/fieldkit/run_batch.sh).
# usage (from the worktree): sh tests/field18/run_batch.sh DECKDIR ...
ROUND=18 exec sh tests/fieldkit/run_batch.sh "$@"

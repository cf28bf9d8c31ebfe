#!/bin/sh
# Field round 21: for each deck folder, run it in its engine (engine.sh) then audit it (audit.sh), niced (tests/fieldkit/run_batch.sh).
# usage (from the worktree): sh tests/field21/run_batch.sh DECKDIR ...
ROUND=21 exec sh tests/fieldkit/run_batch.sh "$@"

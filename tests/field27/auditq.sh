#!/bin/sh
# Field round 27: the quick audit (tests/fieldkit/audit.sh with QUICK=1: no search of / to depth 2 nor of /tmp).
# usage: tests/field27/auditq.sh DECKDIR ...  (from the worktree; venv on PATH, LD_LIBRARY_PATH set)
ROUND=27 QUICK=1 exec sh "$(dirname "$0")/../fieldkit/audit.sh" "$@"

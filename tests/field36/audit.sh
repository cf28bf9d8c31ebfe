#!/bin/sh
# Field round 36: audit deck folders, watching for escapes (the tool: tests/fieldkit/audit.sh, with this round's names).
# usage: tests/field36/audit.sh DECKDIR ...  (from the worktree; venv on PATH, LD_LIBRARY_PATH set)
ROUND=36 exec sh "$(dirname "$0")/../fieldkit/audit.sh" "$@"

#!/bin/sh
# Field round 35: audit deck folders, watching for escapes (the tool: tests/fieldkit/audit.sh, with this round's names).
# usage: tests/field35/audit.sh DECKDIR ...  (from the worktree; venv on PATH, LD_LIBRARY_PATH set)
ROUND=35 exec sh "$(dirname "$0")/../fieldkit/audit.sh" "$@"

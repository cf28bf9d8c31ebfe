#!/bin/sh
# Field round 20: audit deck folders, watching for escapes (the tool: tests/fieldkit/audit.sh, with this round's names).
# usage: tests/field20/audit.sh DECKDIR ...  (from the worktree; venv on PATH, LD_LIBRARY_PATH set)
ROUND=20 CANARY='f[12][06789]*' exec sh "$(dirname "$0")/../fieldkit/audit.sh" "$@"

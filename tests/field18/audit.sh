#!/bin/sh
# Field round 18: audit deck folders, watching for escapes (the tool: tests/fieldkit/audit.sh, with this round's names).
# usage: tests/field18/audit.sh DECKDIR ...  (from the worktree; venv on PATH, LD_LIBRARY_PATH set)
ROUND=18 CANARY='f1[678]*' exec sh "$(dirname "$0")/../fieldkit/audit.sh" "$@"

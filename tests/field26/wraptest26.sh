#!/bin/sh
# Field round 26: a differential test: a deck run through a wrapper file that only opens it (MODE include, ifinclude,
# jump) must not change the audit's rc and rows (the tool: tests/fieldkit/difftest.sh).
# usage (from the worktree, venv on PATH): sh tests/field26/wraptest26.sh MODE DECKDIR ...
exec sh "$(dirname "$0")/../fieldkit/difftest.sh" "$@"

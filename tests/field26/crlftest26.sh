#!/bin/sh
# Field round 26: a differential test: the deck file (and every *.in file beside it) rewritten with CRLF line ends
# must not change the audit's rc and rows (the tool: tests/fieldkit/difftest.sh, mode crlf).
# usage (from the worktree, venv on PATH): sh tests/field26/crlftest26.sh DECKDIR ...
exec sh "$(dirname "$0")/../fieldkit/difftest.sh" crlf "$@"

#!/bin/sh
# Field round 26: a differential test: `clear` (or the lines in PREFIX) as a deck's first lines changes nothing in LAMMPS,
# so the audit's rc and rows must not change (the tool: tests/fieldkit/difftest.sh, mode clear).
# usage (from the worktree, venv on PATH): sh tests/field26/cleartest26.sh DECKDIR ...
exec sh "$(dirname "$0")/../fieldkit/difftest.sh" clear "$@"

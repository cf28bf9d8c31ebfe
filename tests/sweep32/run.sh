#!/bin/sh
# Sweep 32: re-audit every deck folder of field rounds 27-31 with the current code, on a copy (the committed audit.*
# files stay as their round's record), then set the rounds' engine values beside the new rows.
# usage (from the worktree; venv on PATH, LD_LIBRARY_PATH and PYTHONPATH=src set): sh tests/sweep32/run.sh COPYDIR
# One audit at a time, niced (the machine is shared); about 3 s a folder, an hour for the ~1200 folders.
set -e
C=${1:?copy folder}
mkdir -p "$C"
for r in 27 28 29 30 31; do [ -d "$C/field$r" ] || cp -a tests/field$r "$C/"; done
ln -sfn "$(pwd)/tests/fieldkit" "$C/fieldkit"
cd "$C"
for r in 31 30 29 28 27; do
  for d in field$r/decks/*/; do ROUND=$r QUICK=1 OMP_NUM_THREADS=1 nice -n 10 sh fieldkit/audit.sh "$d"; done > audit$r.log 2>&1
done
cd - >/dev/null
for r in 31 30 29 28 27; do python tests/sweep32/sweep.py tests "$C" $r > "$C/sweep$r.tsv"; done
python tests/sweep32/summarize.py "$C"/sweep3[01].tsv "$C"/sweep2[789].tsv > "$C/outcome.txt"
python tests/sweep32/changed.py "$C"/sweep3[01].tsv "$C"/sweep2[789].tsv > "$C/changed.txt"

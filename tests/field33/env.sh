# Field round 33: source from the worktree (the venv on PATH and LAMMPS' library found: tests/fieldkit/env.sh; the
# worktree's own source first on the import path)
. tests/fieldkit/env.sh
export PYTHONPATH=$PWD/src

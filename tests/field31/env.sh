# Field round 31: source from the worktree (the venv on PATH and LAMMPS' library found: tests/fieldkit/env.sh)
. tests/fieldkit/env.sh

#!/bin/sh
# Field round 26: referee26 for the decks in units other than si: PROBE_ARGS = G Z XC DT in each deck's own units
# (G the speed audited, Z/XC a place far from the walls, DT small against the contact's duration).
cd "$(dirname "$0")"
r() { d=$1; shift; PROBE_ARGS="$*" python3 referee26.py decks/$d; }
r U01_cgs_hooke_g100 100 5 2 1e-8
r U02_cgs_hertzmat_g100_loop 100 5 2 1e-8
r U03_lj_hooke_g05 0.5 10 5 1e-6
r U04_micro_hertzmat 1 500 200 1e-6
r U05_nano_hooke 1 500 200 1e-5
r U06_cgs_dt_coarse_g100 100 5 2 1e-8
r U07_lj_if_include_kn 1 10 5 1e-6
r U08_micro_hooke_wall 2 500 200 1e-4
r U09_nano_hertzmat 1 500 200 1e-6
r U10_cgs_clear_si 1 0.05 0.02 1e-8
r R02_clear_then_cgs 100 5 2 1e-8
r Z01_cgs_wall_gravity_g100 100 5 2 1e-8
r Z02_lj_format_kn 1 10 5 1e-6
r Z03_micro_include_if_dt 1 500 200 1e-6
r Z04_cgs_tsuji_g_list 100 5 2 1e-8
PROBE_PRE="unfix p" r Z05_lj_pour_range 1 10 5 1e-6

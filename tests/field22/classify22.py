"""Field round 22: the outcome of each deck folder (by the prefix of its name), checked to cover every folder once.
usage: python classify22.py   (prints the table rows for FINDINGS.md)"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import classify  # noqa: E402

C = {
 "correct, engine-checked (state22: the engine's atoms at the deck's end; probe22: head-on pair at dt 1e-8 s; abs(audit - engine) <= 2e-5)":
    "t19 t23 t24 t25 t21 q01 q04 q05 q06 q08 q12 q14 q17 x07 x10 x11 w01 w07 w09 y03 y04 y06 y07 y08 y10 y12 z01 z02 z04 z05 t14 t15 t17 t20 t28 t29 t32 t33 x08 x09 x12 v02 z07",
 "correct by the engine's PROBE print (kn it ends with) and the audit's eps for that kn elsewhere in this round":
    "t01 t03 t05 t08 t10 t11 t12 t18 t30 t31 t34 q03 q07 q09 q11 q13 q18 x01 x02 x03 x06 q15 w08 w10 w11",
 "correct, LIGGGHTS typed e (engine's PROBE e where printed)": "N01 N03 N04 N05 N06 N07 N08 N09 N10 N11 N12 N13 N15 N16 N18 z03",
 "correct, LIGGGHTS engine-checked (lprobe22: head-on pair in LIGGGHTS at dt 1e-7 s, types 1 1 and 1 2; abs(audit - engine) <= 2e-5)": "N17",
 "effect named fairly": "x04",
 "SILENTLY WRONG E1: `set group` on a dynamic group after a run: the audit uses the membership at definition, the engine the one at the run's end":
    "t16 w02 w04 w05 y13",
 "SILENTLY WRONG E2: atoms lost in a run (thermo_modify lost ignore) kept by the audit: phantom sizes in ranges, pairs that cannot happen, atom ids shifted":
    "t13 w06 w12 z06 v01",
 "SILENTLY WRONG E3: a lone CR (no LF) ends a line for the audit, not for the engine (deck, include, LIGGGHTS; v04: a deck LAMMPS stops at, answered)": "q02 y01 y02 y05 y14 y15 y16 v04",
 "WRONG REFUSAL (false word): 'LAMMPS stops here' where LAMMPS runs the deck to its end (y11: E1, delete_atoms of a dynamic group the run emptied; v03: E3, a lone CR inside a pair_coeff)": "y11 v03",
 "WRONG EPS next to only 'line N not understood: reset_atoms id' (E2: fix evaporate deleted atom 1 in the run; the engine renumbers, set atom 1 hits the other type)": "z08",
 "answers pairs of a type whose only atom the run lost, no note (mild: the numbers are the settings' own)": "y09",
 "fair refusal (run ... every with commands; or the engine itself stops on the deck)":
    "t02 t06 t07 t35 t36 x05 t04 t09 t22 t26 t27 q10 q16 N02 N14 w03",
}
classify.by_prefix(C, os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks"))  # the check and the table: tests/fieldkit/classify.py

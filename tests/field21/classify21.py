"""Field round 21: the outcome of each deck folder (by the prefix of its name), checked to cover every folder once.
usage: python classify21.py   (prints the table rows for FINDINGS.md)"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import classify  # noqa: E402

C = {
 "correct, engine-checked (probe21/wprobe21: the deck run to its end in LAMMPS, then a head-on pair or a floor drop at dt 1e-8 s; |audit - engine| <= 2e-5)":
    "a01 a02 a03 a04 a06 a07 a08 a09 a11 a14 a15 a16 a18 a23 a26 c07 c08 c10 c12 c13 c16 c17 d01 d02 d04 d05 d06 d08 d10 "
    "f07 f13 f16 k01 k02 k03 k04 k05 k06 k07 k08 k10 k11 k12 k13 l02 l03 l04 l05 l06 l07 l08 r01 r02 r03 r04 r07 r08 r09 r10 r11 "
    "r13 r14 r15 r18 u07 u08 u09 v02 v03 v05 v06 v07 v08 v09 v10 v11 v12 v13 v16 v17 v18 v19 v20 v21 v22 l01 r24 r26 r28 u01 u02 u04 u05",
 "correct otherwise (the engine's PROBE prints, its end state, typed e of LIGGGHTS, stage structure, eps unchanged by the edit)":
    "N02 N05 N06 N07 N08 N09 N13 N14 N15 N16 N18 N19 N20 N21 N22 N23 N24 N25 N28 N29 N30 N31 N32 R01 R04 "
    "c01 c02 c03 c04 c06 c18 c31 c32 a20 l09 r06 r17 u03 u06",
 "effect named fairly": "N04 N10 N17 f01 f02 f03 f04 f05 f06 f08 f09 f10 f11 f12 f15",
 "SILENTLY WRONG D1: an `if` written with typographic quotes (LAMMPS makes them ASCII and runs the branch; the audit keeps the old contact)":
    "a05 a12 a13 a17 a21 a22 a28 a29 a30",
 "SILENTLY WRONG D2: random() draws made by thermo output during runs, not made in the audit's pass, shift a later ${r}": "r19 r25 r27 N40",
 "WRONG EPS with a false word D2: draws made by print / fix print / shell / $() in print, said to have 'no part in a contact'": "r16 r20 r21 r22 r23 N39",
 "SILENTLY WRONG D3: `quit` quoted inside an if branch of `run N every M` (alone, with other commands, in else, with a status) not seen; the stage after it reported": "c27 c28 c29 c30 c33 N42 R02",
 "WRONG NUMBER, nothing said: `timestep` in a typographic-quote if not seen (steps per contact at the old dt; D1)": "a19",
 "left class: run-time failures (fix halt error hard)": "c05",
 "answers for a deck the engine stops at (geturl, no libcurl in this LAMMPS), with 'no part in a contact' (mild)": "k09",
 "AVOIDABLE REFUSAL: a LIGGGHTS deck whose LIGGGHTS-only lines sit in an include is run in LAMMPS": "N01",
 "AVOIDABLE REFUSAL (mild, deliberate-looking): a command whose name comes from a string variable": "a24 a25 c19 c20 c21 c22 c23 N26 N27 N33 N34 N35 N36 N38",
 "fair refusal (run ... every with include/variable/if-quit; or the engine itself stops on the deck)":
    "c09 c14 c15 c25 c26 c34 c35 c36 c37 a27 N41 R03 N03 N11 N12 N37 a10 c11 c24 d03 d07 d09 f14 r05 r12 v01 v04 v14 v15",
}
classify.by_prefix(C, os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks"))  # the check and the table: tests/fieldkit/classify.py

"""Field round 23: the outcome of each deck folder (by the prefix of its name), checked to cover every folder once.
usage: python classify23.py   (prints the table rows for FINDINGS.md)"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit import classify  # noqa: E402

C = {
 "correct, engine-checked (LAMMPS: referee23/probe23 head-on pairs of the engine's end-state sizes at dt 1e-8 s, wprobe23 for walls where named in FINDINGS; abs(audit - engine) <= 2e-5; pairs the audit leaves out as excluded measured -1 = no contact)":
    "R01 R02 R03 R06 R07 R08 R09 R10 R13 R14 R16 R18 a01 a02 a03 a04 a05 a06 a07 a08 a09 a10 a11 a12 a13 b02 b04 b05 b06 b08 b09 "
    "d01 d02 d03 d04 d05 d08 d09 d10 d11 d12 d13 d14 d15 d16 d17 d18 d19 d20 d21 d22 d23 d27 d28 d31 "
    "e01 e02 e03 e04 e07 e08 e10 e11 e13 e14 e15 e16 f06 h01 h02 h03 h04 h05 h06 h07 h08 h09 h10 h11 "
    "k01 k02 k03 k04 k05 k06 k08 k09 k10 k11 k12 k13 k15 k16 k17 k18 k19 k20 m01 m02 m03 m04 m05 m06 m07 "
    "n01 n02 n03 n06 n07 n08 n10 n16 p01 p02 p03 p05 p06 p07 r01 r02 r03 r04 r06 r07 r08 r09 r12 r13 r14 r15 r17 r18 r20 "
    "v02 v03 v04 v05 v06 v07 v08 v09 v10 v11 v12 v13 v14 v16 v18 v19 w01 w03 w05 w06 w08 w09 w10 w11 x02 x04 "
    "z01 z02 z03 z04 z05 u01 u03 u04 u06 k24 k25 e19 e20 e22 e23 e24",
 "correct otherwise (Q25 Q28 Q32 Q34: pair_write, a missing plugin, group2ndx, restart with two file names run in LAMMPS, base kn 5000 rows; Q17: info only warns; Q07 dump image (this LAMMPS has it), R24 (kn 8000 last), L41 (LIGGGHTS takes run 1e3): rows whose values are engine-checked in other decks; e05 e06: quit before the change, rows = the base deck's, engine-checked in R03; z06-z13: writes outside the folder, base rows; n04: static groups of the deck's own two atoms; x01 x03 u05 m05-like: the engine's pair still in contact after 0.03 s or within its step error, as the audit's sticks / ~0 / ~1; x05: one type poured, base row)":
    "Q25 Q28 Q32 Q34 Q17 Q07 R24 L41 e21 e05 e06 z06 z07 z08 z09 z10 z11 z12 z13 n04 x01 x03 u05 x05",
 "correct, LIGGGHTS engine-checked (lprobe23: head-on pair in LIGGGHTS at dt 1e-7 s; abs(audit - engine) <= 2e-5 (hooke: 9e-5, its step error); L16's excluded 1 2 measured -1)":
    "L01 L02 L03 L04 L05 L08 L09 L10 L13 L14 L15 L16 L17 L18 L19 L20 L22 L24 L25 L27 L28 L29 L31 L33 L34 L35 L39",
 "effect named fairly (the row is the contact's, a note names what changes it, with the engine's number where the note gives one: f01 0.362983 vs engine 0.362979, f02 0.464962 vs 0.464963, f11 0.333809 vs 0.333806, f14 0.386754 vs 0.386754, L45 (LIGGGHTS fix viscous) 0.597665 vs LIGGGHTS at separation 0.597652; or the pair is left out with its reason)":
    "L44 L45 L46 L47 L49 R04 R05 f01 f02 f03 f04 f05 f07 f08 f09 f11 f12 f13 f14 f15 w02 w04 n12 n13 n14 L07",
 "SILENTLY WRONG U: a non-SI deck (units cgs): g is read in the deck's speed unit (cm/s), the rows say only 'g 1'; at --g 1 the audit gives the eps at 1 cm/s (u02 0.7533136 = engine at 1 cm/s; engine at 1 m/s 0.497208); u08 (real: A/fs) the same for its push-through notes":
    "u02 u07 u08",
 "SILENTLY WRONG S: LAMMPS (or LIGGGHTS with lost error) stops inside a run (Lost atoms; fix halt error hard); the audit answers the later stages, which the engine never reaches, no note":
    "r22 r23 R11 L40",
 "answered where the engine stops inside the run being audited, or after the last run (S/R, milder: the rows are those of the run that stops or completed; no note, or only 'not understood: read_dump'; R22: run 100 upto after step 200, the deck's last line)":
    "r16 r19 r24 R22",
 "SILENTLY WRONG R: LAMMPS stops at an illegal run command (run 1e2, run -100, every 0, pre maybe, start/stop/upto out of order); the audit's pass never checks it and answers the settings of a run LAMMPS never makes, no note":
    "R23 R25 R26 R27 R28 R29 R30 L50 L51",
 "WRONG EPS next to a note that does not explain it, X: LAMMPS stops at a command the audit does not execute (print of an undefined variable or into a missing folder, dump/dump_modify/undump/write_dump/fix print/timer/log/echo/restart/fix ave/time file with arguments LAMMPS refuses); the only note: 'not executed ... it has no part in a contact'":
    "Q01 Q02 Q03 Q04 Q05 Q06 Q08 Q09 Q10 Q13 Q14 Q15 Q16 Q21 Q24 L42 L43 Q26 Q27 Q29 Q30 Q31 Q35 Q36",
 "WRONG EPS next to a note that does not explain it, H by a real timeout: timer timeout 1 s ends a long run, LAMMPS skips the later one; note: 'the audit takes each run to make all its steps'":
    "R21",
 "SILENTLY WRONG H: fix halt ... error soft (or tlimit) ends a run and LAMMPS skips every later run; the audit reports the later runs' settings":
    "R12 R17 R19 R20",
 "SILENTLY WRONG E2L: LIGGGHTS loses an atom in a run without an error; the audit keeps it (a later set atom hits it; phantom sizes in ranges; a 2 2 pair LIGGGHTS cannot have)":
    "L37",
 "answers pairs of a type whose only atom LIGGGHTS lost, no note (E2L, mild: the numbers are the settings' own; L38's 1 2 engine-checked 0.881478)":
    "L36 L38",
 "fair refusal (the engine itself stops on the deck; or the contact is not mapped: dmt/jkr with cohesion, hybrid/scaled, hybrid/overlay; or an earlier round's deliberate refusal: timer timeout 0, random() draws, a lone CR; d24: coeff_restitution 0, LAMMPS' positions become NaN)":
    "L06 L11 L12 L21 L23 L26 L30 L32 b01 b03 b07 d06 d07 d25 d26 e17 e18 f10 h12 k07 k14 n05 n11 n15 p04 r05 r10 r11 r21 v01 v15 v17 v20 w07 n09 n19 d29 d30 n17 n18 R15 e09 e12 d24 Q11 Q12 Q18 Q19 Q20 Q22 Q23 L48 Q33 k21 k22 k23",
}
classify.by_prefix(C, os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks"))  # the check and the table: tests/fieldkit/classify.py

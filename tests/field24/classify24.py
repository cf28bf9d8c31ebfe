"""Field round 24: the outcome table of FINDINGS.md, and a check that it names every deck folder exactly once.
usage: python classify24.py"""
import os, sys
D = os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks")
T = [
 ("correct, engine-checked (LAMMPS: referee24/probe24 head-on pairs of the engine's end-state sizes at dt 1e-8 s, "
  "referee_all.log, uref.log, vref.log; abs(audit - engine) <= 2e-5; U decks in their own units; curved walls by "
  "wcprobe24, wcref.log; LIGGGHTS: lprobe24 at dt 1e-7 s, lref.log, within its step error 9e-5)",
  "H04 H05 H07 H09 H10 K02 N01 N02 N03 N06 N07 N08 N09 N13 R01 R03 R05 R07 R10 R11 R13 R15 R16 R17 R19 R21 R23 R28 R29 "
  "R30 S01 S03 S11 V08 V09 V14 V38 V40 V41 U13 W01 W02 W03 W05 U01 U02 U03 U04 U05 U08 E01 E03 E05 E08 E09 N11 N14 R26 R27 U06 W06 U12"),
 ("correct otherwise (rows = the base law's engine-checked values for the sizes the engine holds: N05 N12 (2 2 = "
  "4 on 6 mm, 0.414918), S06 S12 S13 S14 V02-V06 V11 V15 V17 V24 V27 V30 V35 W04 B02 (special_bonds lj 1 1 1: the bonded pair meets); E02 E06 LIGGGHTS typed e "
  "with the lost type's rows gone; U07: engine still in contact after 0.03 s = audit 'sticks'; U11 LIGGGHTS cgs sticks, LIGGGHTS 1e-4 after 2 ms; V34 = V35; N15-N17 a deposit, pour or create_atoms of a type 2 template: not lone, base rows)",
  "N05 N12 S06 S12 S13 S14 V02 V03 V04 V06 V11 V15 V17 V24 V27 V30 V34 V35 W04 B02 E02 E06 U07 U11 N15 N16 N17"),
 ("effect named fairly (a note names the cause: runs too long to make, S03-like: S04 E04 E07 H14, S26 (3000 atoms, 300000 steps; audited only, the engine not run); neighbor lists "
  "rebuilt blind, K01 'found late'; thermostats T01 T02 T03 T07, T05 fix momentum on walls; pairs left out with their "
  "reason: T04 nve/noforce, B01 B03 bonded atoms, G01 rigid body (over-broad: type 2, in no body, also left out))",
  "S04 S26 E04 E07 H14 K01 T01 T02 T03 T05 T07 T04 B01 B03 G01"),
 ("fair refusal (the engine itself stops on the deck: Lost atoms S02 S08 S09 S10 S15 S19 S22 S23 S24; halt met H06 "
  "H11 H12 H13 H18; illegal runs R02 R04 R09 R12 R14 R18 R20 R25 V32; G02 G03 N04 S07 T06 V05 V20 at set-up)",
  "R33 S02 S08 S09 S10 S15 S19 S22 S23 S24 H06 H11 H12 H13 H18 R02 R04 R09 R12 R14 R18 R20 R25 V32 G02 G03 N04 S07 T06 V05 V20"),
 ("SILENTLY WRONG H: fix halt error soft with `message no` (LAMMPS prints no 'condition met' line): LAMMPS makes no "
  "step after it; the audit answers the later run's kn 5000 rows, no note", "H01 H15"),
 ("WRONG next to a note that does not explain it, H: any timer command (timer full, timer timeout off before the halt, "
  "timer normal after it) turns the soft-halt check off; only note: 'timer ... not executed'", "H02 H03 H08"),
 ("SILENTLY WRONG S: an error inside a run (a thermo or fix ave/time variable LAMMPS/LIGGGHTS cannot evaluate) in a "
  "box with no f face and no fix halt: no run is made for real; the later stage is answered", "S16 S17 S18 S20"),
 ("SILENTLY WRONG S/H under --run-budget 0: a sphere lost (S21 = r22), a hard (H17) or soft (H16) halt: rc 0, the "
  "later stage's rows, no note (the budget's own note appears only where a budget runs out)", "S21 H16 H17"),
 ("SILENTLY WRONG S: the f face of a box read_restart restores (no boundary command in the deck): a sphere lost in run 1, LAMMPS stops; the later stage answered, no note", "S25"),
 ("SILENTLY WRONG R: after read_restart (step 1000) `run 500 upto` / `run 100 start 1500 stop 2000`: LAMMPS stops; "
  "the audit checks them against step 0 and answers", "R06 R08"),
 ("SILENTLY WRONG V: commands of a file an include or jump inside an if's quoted commands opens are not read: "
  "pair_coeff (V01 V07 V10 V12 V13 V16 V18 V23), the stage's run in it (V22), a jump (V21), a wall (V19), a soft halt "
  "(V25), units metal (U09: eps 0.99993 for 0.997257), neigh_modify exclude (V36: a row for a pair that never meets), "
  "fix viscous (V37: 0.414916 for 0.413598), the only wall (V29: no wall row); LIGGGHTS `if 1 then \"jump e.in\"` (V42: e 0.5 for 0.29998); `boundary p p f` (S27: a sphere lost in run 1, LAMMPS stops, the kn 5000 stage answered)",
  "V01 V07 V10 V12 V13 V16 V18 V19 V21 V22 V23 V25 U09 V29 V36 V37 V42 S27"),
 ("WRONG note, V: the speed unit said (lj) for a cgs deck whose units line is in an if's include (U10, eps right); the "
  "time-step note at dt 1e-5 for a deck whose timestep 1e-4 is in an if's include (V26: engine at 1e-4 0.385627)",
  "U10 V26"),
 ("false refusal ('LAMMPS stops here / in this run' where LAMMPS runs the deck): `stop $(step+100)` after a run expanded at step 0 (R22); a soft halt, then `clear` and a new simulation (H19); `run 50 start 0 stop 120` / `run 80 upto` after a run a halt with error continue ended at step 60 (R31, R32: the audit takes step 100); `run 2000000 upto` after a `timer timeout 0:00:01` ended a 3e6-step run at step 1885700 (R34)",
  "R22 H19 R31 R32 R34"),
 ("avoidable refusal (the engine runs the deck, the contact is mapped): the pair_style restored by read_restart, pair_coeff given after it (V33; V31 the read_restart in an if); pair_style only in an if's include (V28) and in the common `if \"${restart} == 1\" then \"read_restart ...\" else \"include init.in\"` (V39); LIGGGHTS read_restart of a given file with the contact fully re-specified after it (E10); `run 100 every 50 \"variable x equal 1\"`, a command that changes no contact (R24)",
  "V33 V31 V28 V39 E10 R24"),
 ("answered where the engine stops inside the run being audited (mild, the run's own settings): S05 (sphere thrown "
  "out in the only run), N10 (deposited default-size atoms lost: Lost atoms)", "S05 N10"),
]
names = sorted(os.listdir(D))
short = {n.split("_")[0]: n for n in names}
seen = {}
for _, decks in T:
    for k in decks.split():
        seen[k] = seen.get(k, 0) + 1
missing = [k for k in short if k not in seen]
twice = [k for k, v in seen.items() if v > 1]
unknown = [k for k in seen if k not in short]
print("| outcome | n | decks |\n|---|---|---|")
for what, decks in T:
    print(f"| {what} | {len(decks.split())} | {decks} |")
print(f"| total | {sum(len(d.split()) for _, d in T)} | |")
if missing or twice or unknown:
    sys.exit(f"missing {missing} twice {twice} unknown {unknown}")

"""Field round 34: write decks/NAME/in.deck (and the files a deck reads) for the referee live34.py and the audit.

The live pair as in rounds 32 and 33: type 1 of 4 mm (group lv1) and type 2 of 6 mm (group lv2), 2500 kg/m3, LAMMPS
hooke kn 2000 damping 3000 mass_velocity, dt 1e-6 s, approaching at 1 m/s (momentum zero) from a gap timed so that
they meet in the run named in the folder's LIVE file (gap 0.1 mm: 0.1 ms into the first run; 1.1 mm: in the part or
run after the first 1000 steps). A WALL deck: one type 1 sphere (lv1) falling onto the floor z = 0 with speed 1 m/s at
touching. LIGGGHTS decks: hertz with typed e (1 2: 0.5, 1 on the wall of type 3: 0.7).
Folder files: DECK (the deck's name), G (the --g), LIVE (where they meet, or WALL), AXIS (the axis they meet along,
default x), NP (the process counts the referee runs, default "1 2"), LIGGGHTS, PAIR (the audit's row to compare,
default "types 1 2" or "type 1 on wall floor"), SEP (the touching distance, default 0.005).
Prefixes: P several processes; E run every with step-dependent commands; A fix adapt; D atoms made by data, dump,
replicate, create_atoms, velocity; L LIGGGHTS; O ordinary modeller decks (their sources in FINDINGS.md).
usage: python make_decks34.py [NAME-PREFIX ...]"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
DECKS = {}

HK = "hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
HK5 = "hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
WHK = "granular " + HK


def BASE(boundary="p p f", nt=2, pstyle="pair_style granular\n", coeff="pair_coeff * * " + HK + "\n", head="", box="0 0.04 0 0.04 0 0.1",
         wall=True, integ=True):
    return (head + "units si\natom_style sphere 1\nboundary " + boundary + "\ncomm_modify vel yes\n"
            f"region box block {box} units box\ncreate_box {nt} box\n" + pstyle + coeff +
            "fix grav all gravity 9.81 vector 0 0 -1\n" +
            ("fix floor all wall/gran " + WHK + " zplane 0 NULL\n" if wall else "") +
            ("fix integ all nve/sphere\n" if integ else "") + "timestep 1e-6\n")


V1, V2 = 216 / 280, -64 / 280      # momentum zero: m1 : m2 = 4^3 : 6^3


def IN(gap, xc=0.02, y=0.02, z=0.05, t1=1, t2=2, ax="x"):
    """The live pair inside the box, along `ax`, its touching point at xc (x) or z (z)."""
    s = 0.005 + gap
    if ax == "x":
        a, b = f"{xc - 0.002 - gap / 2:.6f} {y} {z}", f"{xc + 0.003 + gap / 2:.6f} {y} {z}"
        va, vb = f"{V1:.10f} 0 0", f"{V2:.10f} 0 0"
    else:
        a, b = f"{xc} {y} {z - 0.002 - gap / 2:.6f}", f"{xc} {y} {z + 0.003 + gap / 2:.6f}"
        va, vb = f"0 0 {V1:.10f}", f"0 0 {V2:.10f}"
    return (f"create_atoms {t1} single {a}\ncreate_atoms {t2} single {b}\nset atom 1 diameter 0.004 density 2500\n"
            f"set atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
            f"velocity lv1 set {va} units box\nvelocity lv2 set {vb} units box\n")


def PER(gap):
    """The live pair across the periodic x boundary of the 0.04 box (round 33's PER)."""
    x2 = 0.00355 - (0.0011 - gap) / 2
    x1 = 0.03745 + (0.0011 - gap) / 2
    return (f"create_atoms 1 single {x1:.6f} 0.02 0.05\ncreate_atoms 2 single {x2:.6f} 0.02 0.05\n"
            "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
            f"velocity lv1 set {V1:.10f} 0 0 units box\nvelocity lv2 set {V2:.10f} 0 0 units box\n")


H0 = 1e-4


def WALLP(h=H0, x=0.02, y=0.02):
    """One type 1 sphere falling onto the floor, 1 m/s at touching."""
    v = math.sqrt(1 - 2 * 9.81 * h)
    return (f"create_atoms 1 single {x} {y} {0.002 + h:.6f}\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\n"
            f"velocity lv1 set 0 0 {-v:.10f} units box\n")


def L(name, desc, body, pre=None, pair=None, live="last run", data=None, **meta):
    """A LAMMPS deck: # desc, `pre` (BASE()), `pair` (IN(0.1e-3)), `body`."""
    pre = BASE() if pre is None else pre
    pair = IN(0.1e-3) if pair is None else pair
    DECKS[name] = ("# " + desc + "\n" + pre + pair + body, live, data or {}, meta)


def RAW(name, desc, text, live="last run", data=None, **meta):
    DECKS[name] = ("# " + desc + "\n" + text, live, data or {}, meta)


# ---------------------------------------------------------------- LIGGGHTS base (round 33's LPB, the pair inside the box)
def LBASE(boundary="p f f", nt=3, e="0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8", head="", model="hertz", wall=True, extra=""):
    return (head + "atom_style granular\natom_modify map array\nboundary " + boundary + "\nnewton off\ncommunicate single vel yes\n"
            "units si\nregion reg block -0.05 0.05 -0.05 0.05 -0.01 0.15 units box\n" + f"create_box {nt} reg\n" +
            "neighbor 0.002 bin\nneigh_modify delay 0\n" +
            f"fix m1 all property/global youngsModulus peratomtype {' '.join(['5e6'] * nt)}\n"
            f"fix m2 all property/global poissonsRatio peratomtype {' '.join(['0.3'] * nt)}\n"
            f"fix m7 all property/global coefficientFriction peratomtypepair {nt} {' '.join(['0.5'] * nt * nt)}\n"
            f"fix m3 all property/global coefficientRestitution peratomtypepair {nt} {e}\n" + extra +
            f"pair_style gran model {model} tangential history\npair_coeff * *\n" +
            (f"fix wprim all wall/gran model {model} tangential history primitive type {nt} zplane 0.0\n" if wall else "") +
            "timestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n")


def LIN(gap, z=0.1, xc=0.0, t1=1, t2=2):
    s = 0.005 + gap
    return (f"create_atoms {t1} single {xc - s / 2:.6f} 0 {z} units box\ncreate_atoms {t2} single {xc + s / 2:.6f} 0 {z} units box\n"
            "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
            f"velocity lv1 set {V1:.10f} 0 0\nvelocity lv2 set {V2:.10f} 0 0\n")


def LWALL(h=H0, x=0.0, t=1):
    v = math.sqrt(1 - 2 * 9.81 * h)
    return (f"create_atoms {t} single {x} 0 {0.002 + h:.6f} units box\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\n"
            f"velocity lv1 set 0 0 {-v:.10f}\n")


def LG(name, desc, body, pre=None, pair=None, live="last run", data=None, **meta):
    pre = LBASE() if pre is None else pre
    pair = LIN(0.1e-3) if pair is None else pair
    meta.setdefault("LIGGGHTS", "")
    DECKS[name] = ("# " + desc + "\n" + pre + pair + body, live, data or {}, meta)


G11 = 1.1e-3
VZ = dict(AXIS="z")
WALL = dict(PAIR="type 1 on wall floor")
NP4 = dict(NP="1 4")
NP1 = dict(NP="1")

# ================================================================ P: several processes (the referee runs NP 1 and 2, or 4)
L("P01_inside_default_grid", "control: the pair inside the box at z 0.05 (2 processes split z there), run 3000", "run 3000\n")
L("P02_processors_211_pair_on_border", "processors 2 1 1 (fails on 1 process); the pair across x = 0.02, the sub-domain border",
  "run 3000\n", pre=BASE(head="processors 2 1 1\n"), NP="2")
L("P03_processors_211_periodic", "processors 2 1 1; the pair across the periodic x boundary (meets after 1000 steps)", "run 1000\nrun 3000\n",
  pre=BASE(head="processors 2 1 1\n"), pair=PER(G11), NP="2")
L("P04_processors_112_vertical", "processors 1 1 2; the pair along z across z = 0.05", "run 3000\n", pre=BASE(head="processors 1 1 2\n"),
  pair=IN(0.1e-3, ax="z"), NP="2", **VZ)
L("P05_processors_221_np4", "processors 2 2 1 on 4 processes; the pair at the corner x = y = 0.02", "run 3000\n", pre=BASE(head="processors 2 2 1\n"),
  NP="4")
L("P06_processors_star_star_1", "processors * * 1 (any count); the pair across x = 0.02", "run 3000\n", pre=BASE(head="processors * * 1\n"), NP="1 2 4")
L("P07_balance_between_runs", "run 1000; balance 1.0 shift x 5 1.05; run 3000 (the pair on the border, meets in run 2)",
  "run 1000\nbalance 1.0 shift x 5 1.05\nrun 3000\n", pre=BASE(head="processors * 1 1\n"), pair=IN(G11))
L("P08_balance_then_pre_no_inside", "run 1000; balance 1.0 x uniform; run 3000 pre no (inside the box: on 1 process on time)",
  "run 1000\nbalance 1.0 x uniform\nrun 3000 pre no\n", pre=BASE(head="processors * 1 1\n"), pair=IN(G11))
L("P09_balance_shift_then_pre_no_inside", "run 1000; balance 1.0 shift x 10 1.0; run 3000 pre no", "run 1000\nbalance 1.0 shift x 10 1.0\nrun 3000 pre no\n",
  pre=BASE(head="processors * 1 1\n"), pair=IN(G11) + "create_atoms 2 single 0.005 0.02 0.02\ncreate_atoms 2 single 0.008 0.01 0.02\nset atom 3*4 diameter 0.006 density 2500\n")
L("P10_every_balance_pre_no_inside", "run 4000 pre no every 1000 \"balance 1.0 x uniform\"; inside the box (round 33 G25 on 1 process: on time)",
  'run 4000 pre no every 1000 "balance 1.0 x uniform"\n', pre=BASE(head="processors * 1 1\n"), pair=IN(G11), live="part 2")
L("P11_fix_balance_during_run", "fix balance 100 1.0 shift x 5 1.05 during the run; the pair on the border", "fix bal all balance 100 1.0 shift x 5 1.05\nrun 3000\n",
  pre=BASE(head="processors * 1 1\n"), pair=IN(0.1e-3) + "create_atoms 2 single 0.005 0.02 0.02\ncreate_atoms 2 single 0.008 0.01 0.02\nset atom 3*4 diameter 0.006 density 2500\n")
L("P12_fix_balance_then_pre_no", "fix balance 500 1.0 shift x 5 1.05; run 1000; run 3000 pre no", "fix bal all balance 500 1.0 shift x 5 1.05\nrun 1000\nrun 3000 pre no\n",
  pre=BASE(head="processors * 1 1\n"), pair=IN(G11) + "create_atoms 2 single 0.005 0.02 0.02\ncreate_atoms 2 single 0.008 0.01 0.02\nset atom 3*4 diameter 0.006 density 2500\n")
L("P13_displace_then_pre_no_inside", "run 1000; displace_atoms all move 0 0 0; run 3000 pre no (round 33 G16 on 1 process: on time, left out)",
  "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 3000 pre no\n", pre=BASE(head="processors * 1 1\n"), pair=IN(G11))
L("P14_restart_written_read_two_procs", "run 1000; write_restart; clear; read_restart; pair_style and pair_coeff given again; run 3000",
  "run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst\ncomm_modify vel yes\npair_style granular\npair_coeff * * " + HK + "\n"
  "fix grav all gravity 9.81 vector 0 0 -1\nfix floor all wall/gran " + WHK + " zplane 0 NULL\nfix integ all nve/sphere\nrun 3000\n",
  pre=BASE(head="processors * 1 1\n"), pair=IN(G11))
L("P15_restart_periodic_two_procs", "P14 with the pair across the periodic x boundary",
  "run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst\ncomm_modify vel yes\npair_style granular\npair_coeff * * " + HK + "\n"
  "fix grav all gravity 9.81 vector 0 0 -1\nfix floor all wall/gran " + WHK + " zplane 0 NULL\nfix integ all nve/sphere\nrun 3000\n",
  pre=BASE(head="processors * 1 1\n"), pair=PER(G11))
L("P16_change_box_then_pre_no_inside", "run 1000; change_box all x final 0 0.04 units box; run 3000 pre no", "run 1000\nchange_box all x final 0 0.04 units box\nrun 3000 pre no\n",
  pre=BASE(head="processors * 1 1\n"), pair=IN(G11))
L("P17_neigh_every_10_check_no", "neigh_modify every 10 delay 0 check no, the pair on the border", "neigh_modify every 10 delay 0 check no\nrun 3000\n",
  pre=BASE(head="processors * 1 1\n"))
L("P18_neighbor_small_skin_border", "neighbor 0.00005 bin, the pair on the border", "neighbor 0.00005 bin\nrun 3000\n", pre=BASE(head="processors * 1 1\n"))
L("P19_newton_on_border", "newton on, the pair on the border", "run 3000\n", pre=BASE(head="newton on\nprocessors * 1 1\n"))
L("P20_newton_off_border", "newton off, the pair on the border", "run 3000\n", pre=BASE(head="newton off\nprocessors * 1 1\n"))
L("P21_comm_cutoff_border", "comm_modify cutoff 0.02, the pair on the border", "comm_modify cutoff 0.02\nrun 3000\n", pre=BASE(head="processors * 1 1\n"))
L("P22_global_cutoff_small_border", "pair_style granular 0.0055 (a global cutoff just above the touching distance); the pair on the border",
  "run 3000\n", pre=BASE(head="processors * 1 1\n", pstyle="pair_style granular 0.0055\n"))
L("P23_set_diameter_grow_then_pre_no_border", "run 1000; set atom 2 diameter 0.008; run 3000 pre no (contact distance 6 mm: SEP 0.006)",
  "run 1000\nset atom 2 diameter 0.008\nrun 3000 pre no\n", pre=BASE(head="processors * 1 1\n"), pair=IN(G11 + 0.001), SEP="0.006")
L("P24_wall_on_two_procs", "a sphere falling on the floor, 2 processes split z", "run 2000\n", pair=WALLP(), **WALL)
L("P25_processors_grid_numa", "processors * * * grid numa; the pair on the border", "run 3000\n", pre=BASE(head="processors * * * grid numa\n"))
L("P26_velocity_loop_local_crowd", "a crowd made by create_atoms random (seed), velocity all create loop local; then the live pair's velocities set; run",
  "run 3000\n", pre=BASE(head="processors * 1 1\n"), pair="region low block 0.002 0.038 0.002 0.038 0.005 0.03 units box\ncreate_atoms 2 random 20 4711 low overlap 0.006 maxtry 200\n"
  "set type 2 diameter 0.006 density 2500\nvelocity all create 1e-6 87 loop local\n" + IN(0.1e-3).replace("set atom 1 ", "set atom 21 ").replace("set atom 2 ", "set atom 22 ")
  .replace("group lv1 id 1", "group lv1 id 21").replace("group lv2 id 2", "group lv2 id 22"))
L("P27_comm_style_tiled_rcb", "comm_style tiled; balance 1.0 rcb; run 3000 (the pair inside)", "comm_style tiled\nbalance 1.0 rcb\nrun 3000\n")
L("P28_comm_style_tiled_rcb_pre_no", "comm_style tiled; run 1000; balance 1.0 rcb; run 3000 pre no", "comm_style tiled\nrun 1000\nbalance 1.0 rcb\nrun 3000 pre no\n", pair=IN(G11))
L("P29_restart_then_pre_no_np", "run 1000; write_restart; clear; read_restart; given again; run 0; run 3000 pre no",
  "run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst\ncomm_modify vel yes\npair_style granular\npair_coeff * * " + HK + "\n"
  "fix grav all gravity 9.81 vector 0 0 -1\nfix floor all wall/gran " + WHK + " zplane 0 NULL\nfix integ all nve/sphere\nrun 0\nrun 3000 pre no\n",
  pre=BASE(head="processors * 1 1\n"), pair=IN(G11))
L("P30_fix_balance_rcb_tiled", "comm_style tiled; fix balance 200 1.0 rcb; the pair on the border", "comm_style tiled\nfix bal all balance 200 1.0 rcb\nrun 3000\n",
  pair=IN(0.1e-3) + "create_atoms 2 single 0.005 0.02 0.02\ncreate_atoms 2 single 0.008 0.01 0.02\nset atom 3*4 diameter 0.006 density 2500\n")

# ================================================================ E: run every with step-dependent commands (meets in part 2: gap 1.1 mm)
PC12 = "pair_coeff 1 2 hooke {k} 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
L("E01_every_pair_coeff_immediate_step", "run 4000 every 1000 \"pair_coeff 1 2 hooke $(2000+step) ...\" (kn 3000 in part 2)",
  'run 4000 every 1000 "' + PC12.format(k="$(2000+step)") + '"\n', pair=IN(G11), live="part 2")
L("E02_every_pair_coeff_equal_var", "variable kn equal 2000+step; run 4000 every 1000 \"pair_coeff 1 2 hooke ${kn} ...\"",
  'variable kn equal 2000+step\nrun 4000 every 1000 "' + PC12.format(k="${kn}") + '"\n', pair=IN(G11), live="part 2")
L("E03_every_pair_coeff_step_pre_no", "E01 with pre no", 'run 4000 pre no every 1000 "' + PC12.format(k="$(2000+step)") + '"\n', pair=IN(G11), live="part 2")
L("E04_every_pair_coeff_time_var", "variable kt equal 2000+1e6*time; every \"pair_coeff 1 2 hooke ${kt} ...\"",
  'variable kt equal 2000+1e6*time\nrun 4000 every 1000 "' + PC12.format(k="${kt}") + '"\n', pair=IN(G11), live="part 2")
L("E05_every_pair_coeff_elapsed", "variable ke equal 2000+3*elapsed; every \"pair_coeff 1 2 hooke ${ke} ...\" (elapsed: steps since the run's start; 5000 in part 2)",
  'run 500\nvariable ke equal 2000+3*elapsed\nrun 4000 every 1000 "' + PC12.format(k="${ke}") + '"\n', pair=IN(G11 + 0.5e-3), live="part 2")
L("E06_every_pair_coeff_part3", "E01 meeting in part 3 (kn 4000)", 'run 4000 every 1000 "' + PC12.format(k="$(2000+step)") + '"\n', pair=IN(2.1e-3), live="part 3")
L("E07_every_neigh_exclude", "run 4000 every 1000 \"neigh_modify exclude type 1 2\" (part 2 on: the pair not seen)",
  'run 4000 every 1000 "neigh_modify exclude type 1 2"\n', pair=IN(G11), live="part 2")
L("E08_every_neigh_exclude_pre_no", "E07 with pre no", 'run 4000 pre no every 1000 "neigh_modify exclude type 1 2"\n', pair=IN(G11), live="part 2")
L("E09_every_neigh_modify_every", "every \"neigh_modify every 1 delay 0 check yes\" (inert)", 'run 4000 every 1000 "neigh_modify every 1 delay 0 check yes"\n',
  pair=IN(G11), live="part 2")
L("E10_every_set_density_step", "every \"set type 2 density $(2500+step)\" (3500 in part 2)", 'run 4000 every 1000 "set type 2 density $(2500+step)"\n',
  pair=IN(G11), live="part 2")
L("E11_every_set_density_step_pre_no", "E10 with pre no", 'run 4000 pre no every 1000 "set type 2 density $(2500+step)"\n', pair=IN(G11), live="part 2")
L("E12_every_set_diameter_var", "variable d equal 0.006+step*1e-6; every \"set atom 2 diameter ${d}\" (7 mm in part 2; SEP 0.0055)",
  'variable d equal 0.006+step*1e-6\nrun 4000 every 1000 "set atom 2 diameter ${d}"\n', pair=IN(G11 + 0.0005), live="part 2", SEP="0.0055")
L("E13_every_wall_refix_step", "WALL: every \"fix floor all wall/gran granular hooke $(2000+step) ...\" (kn 3000 in part 2)",
  'run 4000 every 1000 "fix floor all wall/gran granular hooke $(2000+step) 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL"\n',
  pair=WALLP(0.0011), live="part 2", **WALL)
L("E14_every_wall_unfix_refix_pre_no", "WALL: every \"unfix floor\" \"fix floor ... hooke $(2000+step) ...\" pre no",
  'run 4000 pre no every 1000 "unfix floor" "fix floor all wall/gran granular hooke $(2000+step) 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL"\n',
  pair=WALLP(0.0011), live="part 2", **WALL)
L("E15_every_if_step", "every 'if \"$(step) >= 1000\" then \"pair_coeff 1 2 hooke 5000 ...\"'",
  'run 4000 every 1000 \'if "$(step) >= 1000" then "' + PC12.format(k="5000") + '"\'\n', pair=IN(G11), live="part 2")
L("E16_every_if_step_not_taken", "every 'if \"$(step) >= 3000\" then ...' (meets in part 2: not yet)",
  'run 4000 every 1000 \'if "$(step) >= 3000" then "' + PC12.format(k="5000") + '"\'\n', pair=IN(G11), live="part 2")
L("E17_every_upto", "run 1000; run 5000 upto every 1000 \"pair_coeff 1 2 hooke $(2000+step) ...\" (parts end at 2000..5000; meets in the first part: kn 2000)",
  'run 1000\nrun 5000 upto every 1000 "' + PC12.format(k="$(2000+step)") + '"\n', pair=IN(G11), live="part 1")
L("E18_every_upto_part2", "E17 meeting in part 2 of the upto run (kn 4000)", 'run 1000\nrun 5000 upto every 1000 "' + PC12.format(k="$(2000+step)") + '"\n',
  pair=IN(2.1e-3), live="part 2")
L("E19_every_pair_style_again", "every \"pair_style granular\" \"pair_coeff * * hooke 5000 ...\"", 'run 4000 every 1000 "pair_style granular" "pair_coeff * * ' + HK5 + '"\n',
  pair=IN(G11), live="part 2")
L("E20_every_pair_style_again_pre_no", "E19 with pre no", 'run 4000 pre no every 1000 "pair_style granular" "pair_coeff * * ' + HK5 + '"\n', pair=IN(G11), live="part 2")
L("E21_every_set_type_retype", "pair_coeff 1 1 kn 5000; every \"set atom 2 type 1\" (the pair is 1 1 from part 2 on; diameter kept)",
  "pair_coeff 1 1 " + HK5 + '\nrun 4000 every 1000 "set atom 2 type 1"\n', pair=IN(G11), live="part 2", PAIR="types 1 1")
L("E22_every_timestep_step", "every \"timestep $(1e-6*(1+step/2000))\" (dt 1.5e-6 in part 2)", 'run 4000 every 1000 "timestep $(1e-6*(1+step/2000))"\n',
  pair=IN(G11), live="part 2")
L("E23_every_variable_redefined", "variable kn equal 2000; every \"variable kn equal 5000\" \"pair_coeff 1 2 hooke ${kn} ...\"",
  'variable kn equal 2000\nrun 4000 every 1000 "variable kn equal 5000" "' + PC12.format(k="${kn}") + '"\n', pair=IN(G11), live="part 2")
L("E24_every_dollar_outside_quotes", "variable kn equal 2000+step; run 4000 every 1000 pair_coeff given as 'pair_coeff 1 2 hooke ${kn} ...' in single quotes",
  "variable kn equal 2000+step\nrun 4000 every 1000 '" + PC12.format(k="${kn}") + "'\n", pair=IN(G11), live="part 2")
L("E25_every_triple_quotes", "every \"\"\"pair_coeff 1 2 hooke $(2000+step) ...\"\"\"", 'run 4000 every 1000 """' + PC12.format(k="$(2000+step)") + '"""\n', pair=IN(G11), live="part 2")
L("E26_every_fix_adapt_like_set_v", "every \"set type 2 density ${rho}\" with rho equal 2500*(1+step/1000) and pre no, meets in part 3",
  'variable rho equal 2500*(1+step/1000)\nrun 4000 pre no every 1000 "set type 2 density ${rho}"\n', pair=IN(2.1e-3), live="part 3")
L("E27_every_neigh_exclude_none_after", "neigh_modify exclude type 1 2 before; every \"neigh_modify exclude none\" (seen from part 2)",
  'neigh_modify exclude type 1 2\nrun 4000 every 1000 "neigh_modify exclude none"\n', pair=IN(G11), live="part 2")
L("E28_every_neigh_exclude_none_pre_no", "E27 with pre no", 'neigh_modify exclude type 1 2\nrun 4000 pre no every 1000 "neigh_modify exclude none"\n', pair=IN(G11), live="part 2")

# ================================================================ A: fix adapt
L("A01_adapt_pair_granular", "fix adapt 1 pair granular kn 1 2 v_k (LAMMPS: not supported)", "variable k equal 3000\nfix ad all adapt 1 pair granular kn 1 2 v_k\nrun 3000\n")
L("A02_adapt_pair_gran_hooke", "pair gran/hooke/history; fix adapt 1 pair gran/hooke/history kn * * v_k", "variable k equal 3000\nfix ad all adapt 1 pair gran/hooke/history kn * * v_k\nrun 3000\n",
  pre=BASE(pstyle="pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 0\n", coeff="pair_coeff * *\n"))
L("A03_adapt_diameter_scale_yes", "fix adapt 1 atom diameter v_s scale yes (s 1.2: 4.8 and 7.2 mm, mass with it; SEP 0.006)",
  "variable s equal 1.2\nfix ad all adapt 1 atom diameter v_s scale yes\nrun 3000\n", pair=IN(0.1e-3 + 0.001), SEP="0.006")
L("A04_adapt_diameter_scale_yes_mass_no", "A03 with mass no", "variable s equal 1.2\nfix ad all adapt 1 atom diameter v_s scale yes mass no\nrun 3000\n", pair=IN(0.1e-3 + 0.001), SEP="0.006")
L("A05_adapt_diameter_scale_no_lv2", "fix adapt on lv2: atom diameter v_d (0.008) scale no (SEP 0.006)", "variable d equal 0.008\nfix ad lv2 adapt 1 atom diameter v_d\nrun 3000\n",
  pair=IN(0.1e-3 + 0.001), SEP="0.006")
L("A06_adapt_diameter_reset_yes_then_run", "run 1000 with fix adapt diameter scale yes reset yes (1.2); unfix; run 3000 (the pair meets at the first diameters)",
  "variable s equal 1.2\nfix ad all adapt 1 atom diameter v_s scale yes reset yes\nrun 500\nunfix ad\nrun 3000\n", pair=IN(G11 + 0.5e-3))
L("A07_adapt_diameter_reset_no_then_run", "A06 with reset no (the adapted diameters stay; SEP 0.006)",
  "variable s equal 1.2\nfix ad all adapt 1 atom diameter v_s scale yes reset no\nrun 500\nunfix ad\nrun 3000\n", pair=IN(G11 + 0.5e-3), SEP="0.006")
L("A08_adapt_diameter_time_ramp", "fix adapt 1 atom diameter v_s scale yes, s = 1+100*time (1.1 at meeting)", "variable s equal 1+100*time\nfix ad all adapt 1 atom diameter v_s scale yes\nrun 3000\n",
  pair=IN(G11), SEP="0.0055")
L("A09_adapt_fep_diameter", "fix adapt/fep 1 atom diameter 2 v_d (type 2: 8 mm; SEP 0.006)", "variable d equal 0.008\nfix ad all adapt/fep 1 atom diameter 2 v_d\nrun 3000\n",
  pair=IN(0.1e-3 + 0.001), SEP="0.006")
L("A10_adapt_diameter_lig", "LAMMPS fix adapt diameter, scale yes, s 0.8 (3.2 and 4.8 mm; SEP 0.004)", "variable s equal 0.8\nfix ad all adapt 1 atom diameter v_s scale yes\nrun 3000\n",
  pair=IN(0.1e-3 - 0.0001 + 0.0), SEP="0.004")
L("A11_adapt_diameter_wall", "WALL: fix adapt diameter scale yes 1.5 on the falling sphere (6 mm, touches at z 0.003)",
  "variable s equal 1.5\nfix ad all adapt 1 atom diameter v_s scale yes\nrun 3000\n", pair=WALLP(0.0011), RAD="0.003", **WALL)
L("A12_adapt_pair_granular_every", "fix adapt 0 (set at set-up only) atom diameter scale yes 1.0 (identity)", "variable s equal 1.0\nfix ad all adapt 0 atom diameter v_s scale yes\nrun 3000\n")

# ================================================================ D: atoms made by data, dump, replicate, create_atoms; velocity
DATA_HEAD = "# f34 data\n\n{n} atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\n"
x1, x2 = 0.02 - 0.002 - 0.00005, 0.02 + 0.003 + 0.00005
ATOMS = f"Atoms # sphere\n\n1 1 0.004 2500 {x1:.6f} 0.02 0.05\n2 2 0.006 2500 {x2:.6f} 0.02 0.05\n"
VELS = f"\nVelocities\n\n1 {V1:.10f} 0 0 0 0 0\n2 {V2:.10f} 0 0 0 0 0\n"
RD = ("units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data d.data\npair_style granular\n")
TAIL = ("fix grav all gravity 9.81 vector 0 0 -1\nfix floor all wall/gran " + WHK + " zplane 0 NULL\nfix integ all nve/sphere\ntimestep 1e-6\ngroup lv1 id 1\ngroup lv2 id 2\n")
RAW("D01_read_data_velocities", "read_data with a Velocities section (the pair's approach)", RD + "pair_coeff * * " + HK + "\n" + TAIL + "run 3000\n",
    data={"d.data": DATA_HEAD.format(n=2) + ATOMS + VELS})
RAW("D02_read_data_pairij_coeffs", "read_data with a PairIJ Coeffs section for pair granular (pair_style before read_data)",
    "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\npair_style granular\nread_data d.data\n" + TAIL + "run 3000\n",
    data={"d.data": DATA_HEAD.format(n=2) + "PairIJ Coeffs # granular\n\n1 1 " + HK + "\n1 2 " + HK5 + "\n2 2 " + HK + "\n\n" + ATOMS + VELS})
RAW("D03_read_data_pair_coeffs", "read_data with a Pair Coeffs section (kn 5000 for all) for pair granular",
    "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\npair_style granular\nread_data d.data\n" + TAIL + "run 3000\n",
    data={"d.data": DATA_HEAD.format(n=2) + "Pair Coeffs # granular\n\n1 " + HK5 + "\n2 " + HK5 + "\n\n" + ATOMS + VELS})
RAW("D04_read_data_pairij_then_coeff", "D02 then pair_coeff 1 2 kn 2000 after the read (the deck's own line wins)",
    "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\npair_style granular\nread_data d.data\npair_coeff 1 2 " + HK + "\n" + TAIL + "run 3000\n",
    data={"d.data": DATA_HEAD.format(n=2) + "PairIJ Coeffs # granular\n\n1 1 " + HK5 + "\n1 2 " + HK5 + "\n2 2 " + HK5 + "\n\n" + ATOMS + VELS})
RAW("D05_write_data_read_back_coeffs", "write_data (with coeffs) after pair_coeff 1 2 kn 5000; clear; read_data; run",
    BASE() + IN(G11) + "pair_coeff 1 2 " + HK5 + "\nrun 1000\nwrite_data w.data\nclear\n" + RD.replace("read_data d.data", "read_data w.data").replace("pair_style granular\n", "") +
    "pair_style granular\n" + TAIL + "run 3000\n")
RAW("D06_write_data_pair_style_first", "D05 with pair_style granular before read_data (coeffs from the file's PairIJ section)",
    BASE() + IN(G11) + "pair_coeff 1 2 " + HK5 + "\nrun 1000\nwrite_data w.data pair ij\nclear\nunits si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\n"
    "pair_style granular\nread_data w.data\n" + TAIL + "run 3000\n")
RAW("D07_read_data_types_3_map", "read_data with 3 types; the pair types 1 and 3 (PAIR types 1 3); pair_coeff 1 3 kn 5000",
    "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data d.data\npair_style granular\npair_coeff * * " + HK + "\npair_coeff 1 3 " + HK5 + "\n" + TAIL + "run 3000\n",
    data={"d.data": DATA_HEAD.format(n=2).replace("2 atom types", "3 atom types") + ATOMS.replace("\n2 2 0.006", "\n2 3 0.006") + VELS}, PAIR="types 1 3")
RAW("D08_read_data_extra_types_offset", "read_data add append offset 1 0 0 0 0 of the pair file into a 3-type box (types 2 and 3)",
    "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.1 units box\ncreate_box 3 box\n"
    "read_data d.data add append offset 1 0 0 0 0\npair_style granular\npair_coeff * * " + HK + "\npair_coeff 2 3 " + HK5 + "\n" + TAIL + "run 3000\n",
    data={"d.data": DATA_HEAD.format(n=2) + ATOMS + VELS}, PAIR="types 2 3")
L("D09_replicate_211_pair", "replicate 2 1 1 of the box holding the pair (two pairs; the first's ids 1 2)", "replicate 2 1 1\nrun 3000\n",
  pre=BASE(wall=False), pair=IN(0.1e-3))
L("D10_replicate_then_retype_copy", "replicate 2 1 1; the copy's type 2 sphere (id 4) set to type 1... pair 1 2 unchanged", "replicate 2 1 1\nset atom 4 type 1\nrun 3000\n",
  pre=BASE(wall=False), pair=IN(0.1e-3))
RAW("D11_read_dump_positions", "write_dump of the pair at rest 1.1 mm apart then read_dump x y z vx vy vz (box no) of a file the deck does not write (made here)",
    BASE() + "create_atoms 1 single 0.01 0.02 0.05\ncreate_atoms 2 single 0.03 0.02 0.05\nset atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\n"
    "group lv1 id 1\ngroup lv2 id 2\nread_dump p.dump 0 x y z vx vy vz box no\nrun 3000\n",
    data={"p.dump": f"ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n0 0.04\n0 0.04\n0 0.1\nITEM: ATOMS id x y z vx vy vz\n"
          f"1 {x1:.6f} 0.02 0.05 {V1:.10f} 0 0\n2 {x2:.6f} 0.02 0.05 {V2:.10f} 0 0\n"})
RAW("D12_read_dump_replace_type", "read_dump with type: the dump makes id 2 of type 1 (so the pair is 1 1)",
    BASE() + "pair_coeff 1 1 " + HK5 + "\ncreate_atoms 1 single 0.01 0.02 0.05\ncreate_atoms 2 single 0.03 0.02 0.05\nset atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\n"
    "group lv1 id 1\ngroup lv2 id 2\nread_dump p.dump 0 x y z vx vy vz type box no\nrun 3000\n",
    data={"p.dump": f"ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n0 0.04\n0 0.04\n0 0.1\nITEM: ATOMS id type x y z vx vy vz\n"
          f"1 1 {x1:.6f} 0.02 0.05 {V1:.10f} 0 0\n2 1 {x2:.6f} 0.02 0.05 {V2:.10f} 0 0\n"}, PAIR="types 1 1")
RAW("D13_read_dump_add_yes", "read_dump add yes: the pair made by the dump (ids 1 2, types 1 2), diameters set after",
    BASE() + "read_dump p.dump 0 x y z vx vy vz type add yes box no\nset atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\nrun 3000\n",
    data={"p.dump": f"ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp ff\n0 0.04\n0 0.04\n0 0.1\nITEM: ATOMS id type x y z vx vy vz\n"
          f"1 1 {x1:.6f} 0.02 0.05 {V1:.10f} 0 0\n2 2 {x2:.6f} 0.02 0.05 {V2:.10f} 0 0\n"})
L("D14_create_atoms_random_crowd", "create_atoms 2 random 30 in a low region (overlap 0.006), set; then the live pair (ids 31 32)", "run 3000\n",
  pair="region low block 0.002 0.038 0.002 0.038 0.005 0.03 units box\ncreate_atoms 2 random 30 4711 low overlap 0.006 maxtry 200\nset type 2 diameter 0.006 density 2500\n" +
  IN(0.1e-3).replace("set atom 1 ", "set atom 31 ").replace("set atom 2 ", "set atom 32 ").replace("group lv1 id 1", "group lv1 id 31").replace("group lv2 id 2", "group lv2 id 32"))
L("D15_create_atoms_single_remap", "the pair made by create_atoms single ... remap yes, x outside the box (wrapped)", "run 3000\n",
  pair=IN(0.1e-3).replace(f"create_atoms 1 single {x1:.6f} 0.02 0.05", f"create_atoms 1 single {x1 + 0.04:.6f} 0.02 0.05 remap yes"))
L("D16_delete_atoms_overlap", "a third sphere overlapping lv2, delete_atoms overlap 0.004 all all (deletes one of them: lv2 kept as id 2?)", "delete_atoms overlap 0.004 all all\nrun 3000\n",
  pair=IN(0.1e-3) + "create_atoms 2 single 0.023 0.02 0.053\nset atom 3 diameter 0.006 density 2500\n", GROUPS="lv1 lv2")
L("D17_delete_atoms_then_create_new_ids", "delete_atoms group lv2 compress yes; create_atoms 2 single again (new id 2), set, velocity; run",
  "delete_atoms group lv2 compress yes\ncreate_atoms 2 single " + f"{x2:.6f}" + " 0.02 0.05\nset atom 2 diameter 0.006 density 2500\ngroup lv3 id 2\n"
  f"velocity lv3 set {V2:.10f} 0 0 units box\nrun 3000\n", GROUPS="lv1 lv3")
L("D18_velocity_loop_all_crowd", "velocity all create 0.01 4711 loop all on a crowd, the pair set after", "run 3000\n",
  pair="region low block 0.002 0.038 0.002 0.038 0.005 0.03 units box\ncreate_atoms 2 random 10 4711 low overlap 0.006 maxtry 200\nset type 2 diameter 0.006 density 2500\n"
  "velocity all create 0.0001 4711 loop all\n" +
  IN(0.1e-3).replace("set atom 1 ", "set atom 11 ").replace("set atom 2 ", "set atom 12 ").replace("group lv1 id 1", "group lv1 id 11").replace("group lv2 id 2", "group lv2 id 12"))
L("D19_velocity_loop_geom", "velocity all create ... loop geom on the crowd and the pair, then the pair's set", "velocity all create 0.0001 4711 loop geom\n"
  f"velocity lv1 set {V1:.10f} 0 0 units box\nvelocity lv2 set {V2:.10f} 0 0 units box\nrun 3000\n")
L("D20_velocity_ramp_pair", "velocity all ramp vx 0.7714 -0.2286 x x1 x2 (the pair's approach by ramp)", "velocity all ramp vx "
  f"{V1:.10f} {V2:.10f} x {x1:.6f} {x2:.6f} units box\nrun 3000\n")
L("D21_create_atoms_single_types_3", "three types; the pair 1 3 with pair_coeff 1 3 kn 5000, type 2 unused", "run 3000\n",
  pre=BASE(nt=3) + "pair_coeff 1 3 " + HK5 + "\n", pair=IN(0.1e-3, t2=3), PAIR="types 1 3")
L("D22_read_data_velocities_then_zero", "read_data velocities then velocity all set 0 0 0 and the pair set again", "run 3000\n",
  pre="", pair="")
DECKS["D22_read_data_velocities_then_zero"] = ("# read_data velocities then velocity all set 0 0 0, then the pair set again by velocity\n" + RD + "pair_coeff * * " + HK + "\n" + TAIL +
                                              f"velocity all set 0 0 0 units box\nvelocity lv1 set {V1:.10f} 0 0 units box\nvelocity lv2 set {V2:.10f} 0 0 units box\nrun 3000\n",
                                              "last run", {"d.data": DATA_HEAD.format(n=2) + ATOMS + VELS.replace(f"{V1:.10f}", "0.1")}, {})
RAW("D23_read_data_add_merge_two_files", "two read_data (the second add append) each holding one sphere",
    "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data a.data\nread_data b.data add append\npair_style granular\npair_coeff * * " + HK + "\n" + TAIL + "run 3000\n",
    data={"a.data": DATA_HEAD.format(n=1) + f"Atoms # sphere\n\n1 1 0.004 2500 {x1:.6f} 0.02 0.05\n\nVelocities\n\n1 {V1:.10f} 0 0 0 0 0\n",
          "b.data": DATA_HEAD.format(n=1) + f"Atoms # sphere\n\n1 2 0.006 2500 {x2:.6f} 0.02 0.05\n\nVelocities\n\n1 {V2:.10f} 0 0 0 0 0\n"})
RAW("D24_read_data_density_zero_like", "read_data with densities 1250 (the pair lighter: eps of the masses)",
    RD + "pair_coeff * * " + HK + "\n" + TAIL + "run 3000\n", data={"d.data": DATA_HEAD.format(n=2) + ATOMS.replace(" 2500 ", " 1250 ") + VELS})

# ================================================================ L: LIGGGHTS
LG("L01_lig_control", "LIGGGHTS control: the pair inside the box (e 0.5)", "run 3000\n")
LG("L02_lig_restart_read", "write_restart; clear; read_restart; material fixes and pair given again; run",
   "run 500\nwrite_restart a.rst\nclear\natom_style granular\natom_modify map array\ncommunicate single vel yes\nnewton off\nread_restart a.rst\nneighbor 0.002 bin\nneigh_modify delay 0\n"
   "fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3\n"
   "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"
   "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.9 0.7 0.9 0.4 0.45 0.7 0.45 0.8\n"
   "pair_style gran model hertz tangential history\npair_coeff * *\ntimestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\ngroup lv1 id 1\ngroup lv2 id 2\nrun 3000\n",
   pair=LIN(G11))
LG("L03_lig_restart_e_changed", "L02 reading back with e 1 2 = 0.9 (the new fix m3 after the read)", "", pair=LIN(G11))
LG("L04_lig_insert_pack_two_templates", "insert/pack with two templates (2 and 3 mm, types 1 and 2) far below the pair; the pair 1 2 (e 0.5)",
   "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\n"
   "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 2500 radius constant 0.003\n"
   "fix pdd all particledistribution/discrete 32452843 2 pts1 0.5 pts2 0.5\nregion ins block -0.04 0.04 -0.04 0.04 0.01 0.04 units box\n"
   "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes all_in yes particles_in_region 20 region ins\nrun 3000\n")
LG("L05_lig_insert_pack_range", "insert/pack with a template of radius uniform 0.0015 0.0035 (type 1)",
   "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius distribution uniform 0.0015 0.0035\n"
   "fix pdd all particledistribution/discrete 32452843 1 pts1 1.0\nregion ins block -0.04 0.04 -0.04 0.04 0.01 0.04 units box\n"
   "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes all_in yes particles_in_region 20 region ins\nrun 3000\n")
LG("L06_lig_insert_pack_gaussian_type3", "insert/pack of type 3 (radius gaussian 0.002 0.0002); the wall's type 3 taken by particles",
   "fix pts1 all particletemplate/sphere 15485863 atom_type 3 density constant 2500 radius distribution gaussian 0.002 0.0002\n"
   "fix pdd all particledistribution/discrete 32452843 1 pts1 1.0\nregion ins block -0.04 0.04 -0.04 0.04 0.01 0.04 units box\n"
   "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes all_in yes particles_in_region 20 region ins\nrun 3000\n")
LG("L07_lig_insert_stream_mesh_face", "insert/stream from a mesh face (a plane made by an STL here) far from the pair",
   "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\n"
   "fix pdd all particledistribution/discrete 32452843 1 pts1 1.0\nfix inface all mesh/surface file face.stl type 3\n"
   "fix ins all insert/stream seed 32452867 distributiontemplate pdd nparticles 10 massrate 0.1 insert_every 10000 overlapcheck yes vel constant 0 0 -1.0 insertion_face inface\nrun 3000\n",
   data={"face.stl": "solid face\nfacet normal 0 0 -1\nouter loop\nvertex -0.04 -0.04 0.05\nvertex 0.04 -0.04 0.05\nvertex 0.04 0.04 0.05\nendloop\nendfacet\n"
         "facet normal 0 0 -1\nouter loop\nvertex -0.04 -0.04 0.05\nvertex 0.04 0.04 0.05\nvertex -0.04 0.04 0.05\nendloop\nendfacet\nendsolid face\n"})
LG("L08_lig_wall_xplane_primitive", "a wall/gran primitive xplane of type 3 at x = 0.0045; lv1 (type 1) moving onto it (e 0.7; WALL via x)",
   "fix xw all wall/gran model hertz tangential history primitive type 3 xplane 0.0045\nrun 3000\n",
   pair=f"create_atoms 1 single 0.0024 0 0.1 units box\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 1 0 0\n",
   PAIR="type 1 on wall xw", WALLX="0.0045")
LG("L09_lig_wall_zcylinder", "a wall/gran primitive zcylinder (radius 0.02) of type 3; lv1 moving outward onto it along x (e 0.7)",
   "fix cyl all wall/gran model hertz tangential history primitive type 3 zcylinder 0.02 0 0\nrun 3000\n",
   pair=f"create_atoms 1 single 0.0179 0 0.1 units box\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 1 0 0\n",
   PAIR="type 1 on wall cyl", WALLX="0.018")
LG("L10_lig_wall_type_only_wall", "4 types: type 4 only the floor's (e 1 4 = 0.55); WALL", "run 3000\n",
   pre=LBASE(nt=4, e="0.6 0.5 0.7 0.55 0.5 0.4 0.45 0.5 0.7 0.45 0.8 0.5 0.55 0.5 0.5 0.5"), pair=LWALL(), PAIR="type 1 on wall wprim", LWALLZ="1")
LG("L11_lig_e_one", "e 1 2 = 1.0 (and every e 1.0)", "run 3000\n", pre=LBASE(e="1.0 1.0 1.0 1.0 1.0 1.0 1.0 1.0 1.0"))
LG("L12_lig_run_upto", "run 1000; run 4000 upto (meets in the second)", "run 1000\nrun 4000 upto\n", pair=LIN(G11))
LG("L13_lig_neigh_delay_5", "neigh_modify delay 5 (check yes) given after the base; the pair meets in run 2", "neigh_modify delay 5\nrun 1000\nrun 3000\n", pair=LIN(G11))
LG("L14_lig_neigh_every_20_check_no", "neigh_modify every 20 delay 0 check no", "neigh_modify every 20 delay 0 check no\nrun 3000\n", pair=LIN(G11))
LG("L15_lig_wall_floor", "WALL: lv1 on the primitive zplane floor of type 3 (e 0.7)", "run 3000\n", pair=LWALL(), PAIR="type 1 on wall wprim", LWALLZ="1")
LG("L16_lig_np2_processors_211", "processors 2 1 1 (2 processes), the pair on the x = 0 border", "run 3000\n", pre=LBASE(head="processors 2 1 1\n"), NP="2")
LG("L17_lig_restart_pair_across_border_np2", "L02 on 2 processes (processors 2 1 1 in both halves)",
   DECKS["L02_lig_restart_read"][0].split("run 500\n", 1)[1].replace("clear\n", "clear\nprocessors 2 1 1\n"), pre=LBASE(head="processors 2 1 1\n"),
   pair=LIN(G11) + "run 500\n", NP="2")
LG("L18_lig_hooke_e_half", "model hooke (typed e 0.5; characteristicVelocity 1)", "run 3000\n", pre=LBASE(model="hooke", extra="fix m6 all property/global characteristicVelocity scalar 1.0\n"))
LG("L19_lig_change_e_between_runs", "fix m3 given again between runs with e 1 2 = 0.8 (meets in run 2)",
   "run 1000\nfix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.8 0.7 0.8 0.4 0.45 0.7 0.45 0.8\nrun 3000\n", pair=LIN(G11))
LG("L20_lig_run_every", "run 4000 every 1000 \"fix m3 ... e 1 2 0.8\" (LIGGGHTS run every; meets in part 2)",
   'run 4000 every 1000 "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.8 0.7 0.8 0.4 0.45 0.7 0.45 0.8"\n', pair=LIN(G11), live="part 2")
LG("L21_lig_mesh_wall_plane", "a mesh/surface floor (STL at z = 0, type 3) through wall/gran mesh; WALL", "fix mf all mesh/surface file floor.stl type 3\n"
   "fix mw all wall/gran model hertz tangential history mesh n_meshes 1 meshes mf\nrun 3000\n",
   pre=LBASE(wall=False), pair=LWALL(), PAIR="type 1 on wall mw", LWALLZ="1",
   data={"floor.stl": "solid f\nfacet normal 0 0 1\nouter loop\nvertex -0.05 -0.05 0\nvertex 0.05 -0.05 0\nvertex 0.05 0.05 0\nendloop\nendfacet\n"
         "facet normal 0 0 1\nouter loop\nvertex -0.05 -0.05 0\nvertex 0.05 0.05 0\nvertex -0.05 0.05 0\nendloop\nendfacet\nendsolid f\n"})
LG("L22_lig_region_wall_fix_wall_region", "fix wall/region on a block region (LJ-free: wall/region of the gran kind does not exist in LIGGGHTS); the pair",
   "region wr block -0.045 0.045 -0.045 0.045 -0.005 0.145 units box\nfix wreg all wall/region wr harmonic 1 0 0.001\nrun 3000\n")
LG("L23_lig_set_type_wall_type", "set atom 2 type 3 (lv2 takes the wall's type 3: e 1 3 = 0.7)", "set atom 2 type 3\nrun 3000\n", PAIR="types 1 3")
LG("L24_lig_insert_pack_then_restart", "insert/pack; run 500; write_restart; clear; read_restart; given again; run (the pair 1 2 across)",
   "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\n"
   "fix pdd all particledistribution/discrete 32452843 1 pts1 1.0\nregion ins block -0.04 0.04 -0.04 0.04 0.01 0.04 units box\n"
   "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes all_in yes particles_in_region 10 region ins\n" +
   DECKS["L02_lig_restart_read"][0].split("run 500\n", 1)[1].replace("0.6 0.9 0.7 0.9", "0.6 0.5 0.7 0.5"), pair=LIN(G11) + "run 500\n")
LG("L25_lig_hertz_stiffness", "pair gran model hooke/stiffness with kn/kt/gamman peratomtypepair", "run 3000\n",
   pre=LBASE(model="hooke/stiffness", extra="fix m8 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\n"
             "fix m9 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000\n"
             "fix m10 all property/global gamman peratomtypepair 3 3000 3000 3000 3000 3000 3000 3000 3000 3000\n"
             "fix m11 all property/global gammat peratomtypepair 3 0 0 0 0 0 0 0 0 0\n"))
LG("L26_lig_e_one_wall", "WALL: e 1 3 = 1.0", "run 3000\n", pre=LBASE(e="0.6 0.5 1.0 0.5 0.4 0.45 1.0 0.45 0.8"), pair=LWALL(), PAIR="type 1 on wall wprim", LWALLZ="1")
LG("L27_lig_run_upto_every", "run 1000; run 5000 upto every 1000 \"fix m3 ... e 1 2 0.8\" (meets in part 1 of the upto run: e 0.5)",
   'run 1000\nrun 5000 upto every 1000 "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.8 0.7 0.8 0.4 0.45 0.7 0.45 0.8"\n', pair=LIN(G11), live="part 1")
del DECKS["L03_lig_restart_e_changed"]

# ================================================================ O: ordinary modeller decks (odecks/*.in; their sources in FINDINGS.md and in each deck's head)
def stl_plane(name, a, b, c, d):
    f = lambda p: "vertex " + " ".join(f"{x:.6g}" for x in p)
    tri = lambda p, q, r: f"facet normal 0 0 1\nouter loop\n{f(p)}\n{f(q)}\n{f(r)}\nendloop\nendfacet\n"
    return f"solid {name}\n" + tri(a, b, c) + tri(a, c, d) + f"endsolid {name}\n"


OD = os.path.join(HERE, "odecks")
t12 = math.tan(math.radians(12))
DECKS["O01_pour_loop_simongravelle"] = (open(os.path.join(OD, "O01.in")).read(), "pass 1 of the loop", {}, {"SEP": "1.0"})
DECKS["O02_lig_random_diameter_drop_caesar"] = (open(os.path.join(OD, "O02.in")).read(), "last run",
                                                {"1x1m-ground.stl": stl_plane("ground", (0, 0, 0.21), (1, 0, 0), (1, 1, 0), (0, 1, 0.21))},
                                                {"LIGGGHTS": "", "SEP": "0.01", "PAIR": "types 1 1"})
DECKS["O03_lig_simple_drop_caesar"] = (open(os.path.join(OD, "O03.in")).read(), "last run",
                                       {"10x10m-ground.stl": stl_plane("ground", (0, 0, 0), (10, 0, 0), (10, 10, 0), (0, 10, 0))},
                                       {"LIGGGHTS": "", "SEP": "0.5", "PAIR": "types 1 1"})

# ---- round 34, second wave: several processes where one process is on time; every commands the audit may accept
PB = BASE(head="processors 2 1 1\n")
L("P31_balance_in_include_pre_no_inside", "processors 2 1 1; run 1000; include holding balance 1.0 x uniform; run 3000 pre no", "run 1000\ninclude b.in\nrun 3000 pre no\n",
  pre=PB, pair=IN(G11), data={"b.in": "balance 1.0 x uniform\n"}, NP="2")
L("P32_balance_pre_no_pair_one_side", "processors 2 1 1; the pair inside x < 0.02 (one sub-domain); run 1000; balance 1.0 x uniform; run 3000 pre no",
  "run 1000\nbalance 1.0 x uniform\nrun 3000 pre no\n", pre=PB, pair=IN(G11, xc=0.01), NP="2")
L("P33_displace_pre_no_pair_one_side", "processors 2 1 1; the pair inside x < 0.02; run 1000; displace_atoms all move 0 0 0; run 3000 pre no",
  "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 3000 pre no\n", pre=PB, pair=IN(G11, xc=0.01), NP="2")
L("P34_reset_atoms_id_pre_no", "run 1000; reset_atoms id; run 3000 pre no (the pair on the border, 1 and 2 processes)",
  "run 1000\nreset_atoms id\nrun 3000 pre no\n", pre=BASE(head="processors * 1 1\n"), pair=IN(G11))
L("P35_delete_far_pre_no_two_procs", "run 1000; delete_atoms of a far sphere (id 3); run 3000 pre no (round 32/33: right on 1 process)",
  "group v3 id 3\nrun 1000\ndelete_atoms group v3\nrun 3000 pre no\n", pre=BASE(head="processors * 1 1\n"),
  pair=IN(G11) + "create_atoms 2 single 0.005 0.01 0.012\nset atom 3 diameter 0.006 density 2500\n")
L("P36_create_far_pre_no_two_procs", "run 1000; create_atoms 2 single far; set; run 3000 pre no", "run 1000\ncreate_atoms 2 single 0.005 0.01 0.012\nset atom 3 diameter 0.006 density 2500\nrun 3000 pre no\n",
  pre=BASE(head="processors * 1 1\n"), pair=IN(G11))
L("P37_set_x_across_border_pre_no", "run 1000; set atom 2 x moved 0.1 mm (lv2 stays right of the border); run 3000 pre no", "run 1000\nset atom 2 x $(x[2]+0.0001)\nrun 3000 pre no\n",
  pre=BASE(head="atom_modify map array\nprocessors * 1 1\n"), pair=IN(G11 + 0.1e-3))
L("P38_write_restart_pre_no_two_procs", "run 1000; write_restart (no clear); run 3000 pre no", "run 1000\nwrite_restart a.rst\nrun 3000 pre no\n",
  pre=BASE(head="processors * 1 1\n"), pair=IN(G11))
L("P39_change_box_boundary_pre_no_two_procs", "f f f box; run 1000; change_box all boundary p f f; run 3000 pre no (the pair inside, on the border)",
  "run 1000\nchange_box all boundary p f f\nrun 3000 pre no\n", pre=BASE(head="processors * 1 1\n", boundary="f f f"), pair=IN(G11))
L("P40_balance_pre_no_vertical_default_grid", "no processors command (2 processes split z at 0.05); the pair along z across 0.05; run 1000; balance 1.0 z uniform; run 3000 pre no",
  "run 1000\nbalance 1.0 z uniform\nrun 3000 pre no\n", pair=IN(G11, ax="z"), **VZ)
L("P41_every_displace_pre_no_inside", "processors * 1 1; run 4000 pre no every 1000 \"displace_atoms all move 0 0 0\" (inside the box)",
  'run 4000 pre no every 1000 "displace_atoms all move 0 0 0 units box"\n', pre=BASE(head="processors * 1 1\n"), pair=IN(G11), live="part 2")
L("P42_balance_then_run_then_pre_no", "run 1000; balance 1.0 x uniform; run 0; run 3000 pre no (the set-up of run 0 rebuilds)",
  "run 1000\nbalance 1.0 x uniform\nrun 0\nrun 3000 pre no\n", pre=BASE(head="processors * 1 1\n"), pair=IN(G11))
L("P43_balance_pre_no_wall", "WALL: processors 1 1 2; run 1000; balance 1.0 z uniform; run 3000 pre no (the sphere and the floor in one sub-domain)",
  "run 1000\nbalance 1.0 z uniform\nrun 3000 pre no\n", pre=BASE(head="processors 1 1 2\n"), pair=WALLP(0.0011), NP="2", **WALL)
LG("P44_lig_change_box_pre_no_np2", "LIGGGHTS processors 2 1 1; run 1000; change_box all x final -0.05 0.05; run 3000 pre no (round 33 G14 on 1 process: on time)",
   "run 1000\nchange_box all x final -0.05 0.05 units box\nrun 3000 pre no\n", pre=LBASE(head="processors 2 1 1\n"), pair=LIN(G11), NP="2")
LG("P45_lig_displace_pre_no_np2", "LIGGGHTS processors 2 1 1; run 1000; displace_atoms 0; run 3000 pre no", "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 3000 pre no\n",
   pre=LBASE(head="processors 2 1 1\n"), pair=LIN(G11), NP="2")
L("P46_balance_pre_no_nsq", "neighbor 0.001 nsq; processors * 1 1; run 1000; balance 1.0 x uniform; run 3000 pre no", "run 1000\nbalance 1.0 x uniform\nrun 3000 pre no\n",
  pre=BASE(head="processors * 1 1\n") + "neighbor 0.001 nsq\n", pair=IN(G11))

W3 = BASE(nt=3) + "pair_coeff 1 3 " + HK5 + "\n"
L("E29_every_wall_constant", "WALL: every \"fix floor all wall/gran granular hooke 5000 ...\" (constant; kn 5000 from part 2)",
  'run 4000 every 1000 "fix floor all wall/gran granular ' + HK5 + ' zplane 0 NULL"\n', pair=WALLP(0.0011), live="part 2", **WALL)
L("E30_every_pair_coeff_constant", "every \"pair_coeff 1 2 hooke 5000 ...\" (constant)", 'run 4000 every 1000 "' + PC12.format(k="5000") + '"\n', pair=IN(G11), live="part 2")
L("E31_every_unfix_wall", "WALL: every 'if \"$(step) == 1000\" then \"unfix floor\"' (no floor from part 2: the sphere leaves the box)", 'run 4000 every 1000 \'if "$(step) == 1000" then "unfix floor"\'\n', pair=WALLP(0.0011), live="part 2", **WALL)
L("E32_every_pair_coeff_other_pair", "every \"pair_coeff 1 1 hooke 5000 ...\" (not the live pair)", 'run 4000 every 1000 "pair_coeff 1 1 ' + HK5 + '"\n', pair=IN(G11), live="part 2")
L("E33_every_set_type_step", "3 types, pair_coeff 1 3 kn 5000; every \"set atom 2 type $(2+(step>=2000))\" (type 2 after part 1, 3 after parts 2 and 3; meets in part 3)",
  'run 4000 every 1000 "set atom 2 type $(2+(step>=2000))"\n', pre=W3, pair=IN(2.1e-3), live="part 3", PAIR="types 1 3")
L("E34_every_set_type_var", "E33 with variable t equal 2+(step>=2000) and \"set atom 2 type ${t}\"",
  'variable t equal 2+(step>=2000)\nrun 4000 every 1000 "set atom 2 type ${t}"\n', pre=W3, pair=IN(2.1e-3), live="part 3", PAIR="types 1 3")
L("E35_every_if_set_type", "E33 with 'if \"$(step) >= 2000\" then \"set atom 2 type 3\"'", 'run 4000 every 1000 \'if "$(step) >= 2000" then "set atom 2 type 3"\'\n',
  pre=W3, pair=IN(2.1e-3), live="part 3", PAIR="types 1 3")
L("E36_every_set_type_step_part2", "E33 meeting in part 2 (still type 2)", 'run 4000 every 1000 "set atom 2 type $(2+(step>=2000))"\n', pre=W3, pair=IN(G11), live="part 2")
L("E37_every_set_type_pre_no", "E33 with pre no", 'run 4000 pre no every 1000 "set atom 2 type $(2+(step>=2000))"\n', pre=W3, pair=IN(2.1e-3), live="part 3", PAIR="types 1 3")
L("E38_every_group_command", "every \"group lvx id 1\" (harmless)", 'run 4000 every 1000 "group lvx id 1"\n', pair=IN(G11), live="part 2")
L("E39_every_print_step", "every \"print 'step $(step)'\" (harmless)", "run 4000 every 1000 \"print 'step $(step)'\"\n", pair=IN(G11), live="part 2")
L("E40_every_set_type_retype_back", "every \"set atom 2 type $(3-floor(step/1000)%2)\": type 2 after part 1 (step 1000: 3-1), type 3 after part 2; meets in part 2 (type 2)",
  'run 4000 every 1000 "set atom 2 type $(3-floor(step/1000)%2)"\n', pre=W3, pair=IN(G11), live="part 2")

FB = BASE(head="processors * 1 1\n", boundary="f f f")
L("P47_fff_balance_pre_no_border", "f f f box, processors * 1 1; the pair across x = 0.02; run 1000; balance 1.0 x uniform; run 3000 pre no",
  "run 1000\nbalance 1.0 x uniform\nrun 3000 pre no\n", pre=FB, pair=IN(G11))
L("P48_fff_displace_pre_no_border", "P47 with displace_atoms all move 0 0 0", "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 3000 pre no\n", pre=FB, pair=IN(G11))
L("P49_fff_every_balance_pre_no", "f f f box; run 4000 pre no every 1000 \"balance 1.0 x uniform\"", 'run 4000 pre no every 1000 "balance 1.0 x uniform"\n', pre=FB, pair=IN(G11), live="part 2")
L("P50_fff_change_box_pre_no", "f f f box; run 1000; change_box all x final 0 0.04; run 3000 pre no", "run 1000\nchange_box all x final 0 0.04 units box\nrun 3000 pre no\n", pre=FB, pair=IN(G11))
L("P51_fff_balance_pre_no_one_side", "P47 with the pair inside x < 0.02 (processors 2 1 1)", "run 1000\nbalance 1.0 x uniform\nrun 3000 pre no\n",
  pre=BASE(head="processors 2 1 1\n", boundary="f f f"), pair=IN(G11, xc=0.01), NP="2")
L("P52_fff_tiled_rcb_pre_no", "f f f box; comm_style tiled; run 1000; balance 1.0 rcb; run 3000 pre no", "comm_style tiled\nrun 1000\nbalance 1.0 rcb\nrun 3000 pre no\n", pre=FB, pair=IN(G11))
L("P53_fff_balance_pre_no_vertical", "f f f box, no processors command (2 split z); the pair along z across 0.05; balance 1.0 z uniform; run 3000 pre no",
  "run 1000\nbalance 1.0 z uniform\nrun 3000 pre no\n", pre=BASE(boundary="f f f"), pair=IN(G11, ax="z"), **VZ)
L("P54_fff_every_displace_pre_no", "f f f box; run 4000 pre no every 1000 \"displace_atoms all move 0 0 0\"", 'run 4000 pre no every 1000 "displace_atoms all move 0 0 0 units box"\n',
  pre=FB, pair=IN(G11), live="part 2")
L("P55_fff_balance_in_include_pre_no", "f f f box; balance in an include then pre no", "run 1000\ninclude b.in\nrun 3000 pre no\n", pre=FB, pair=IN(G11), data={"b.in": "balance 1.0 x uniform\n"})
L("P56_fff_balance_no_pre_no_control", "P47 without pre no (control)", "run 1000\nbalance 1.0 x uniform\nrun 3000\n", pre=FB, pair=IN(G11))
L("P57_fff_balance_pre_no_wall", "WALL: f f f box, processors 1 1 2; balance 1.0 z uniform; run 3000 pre no", "run 1000\nbalance 1.0 z uniform\nrun 3000 pre no\n",
  pre=BASE(head="processors 1 1 2\n", boundary="f f f"), pair=WALLP(0.0011), NP="2", **WALL)
L("P58_fff_balance_pre_no_nsq", "f f f box; neighbor 0.001 nsq; balance 1.0 x uniform; run 3000 pre no", "run 1000\nbalance 1.0 x uniform\nrun 3000 pre no\n",
  pre=FB + "neighbor 0.001 nsq\n", pair=IN(G11))

LG("L28_lig_insert_pack_three_types_wall_type", "insert/pack with three templates (radius 1.5, 2.5, 3.5 mm; types 1, 2 and 3, the wall's type); the pair 1 2",
   "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.0015\n"
   "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 2500 radius constant 0.0025\n"
   "fix pts3 all particletemplate/sphere 32452867 atom_type 3 density constant 2500 radius constant 0.0035\n"
   "fix pdd all particledistribution/discrete 32452843 3 pts1 0.3 pts2 0.3 pts3 0.4\nregion ins block -0.04 0.04 -0.04 0.04 0.01 0.04 units box\n"
   "fix ins all insert/pack seed 49979687 distributiontemplate pdd insert_every once overlapcheck yes all_in yes particles_in_region 20 region ins\nrun 3000\n")
LG("L29_lig_insert_pack_numberbased", "particledistribution/discrete/numberbased with two templates", 
   "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\n"
   "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 2500 radius constant 0.003\n"
   "fix pdd all particledistribution/discrete/numberbased 32452843 2 pts1 0.5 pts2 0.5\nregion ins block -0.04 0.04 -0.04 0.04 0.01 0.04 units box\n"
   "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes all_in yes particles_in_region 20 region ins\nrun 3000\n")
LG("L30_lig_restart_nothing_given_again", "write_restart; clear; read_restart; nothing but pair and fixes given again with the SAME e (0.5); meets after", 
   DECKS["L02_lig_restart_read"][0].split("run 500\n", 1)[1].replace("0.6 0.9 0.7 0.9", "0.6 0.5 0.7 0.5"), pair=LIN(G11) + "run 500\n")
LG("L31_lig_wall_type_changed_between_runs", "WALL: run 500; the primitive floor given again with type 2 (e 1 2 = 0.5); run 3000", 
   "run 500\nunfix wprim\nfix wprim all wall/gran model hertz tangential history primitive type 2 zplane 0.0\nrun 3000\n", pair=LWALL(0.0006), PAIR="type 1 on wall wprim", LWALLZ="1")

L("E41_every_exclude_step_part3", "every \"neigh_modify exclude type 1 $(1+floor(step/2000))\": excludes 1 1 after part 1, 1 2 after part 2; meets in part 3 (passes)",
  'run 4000 every 1000 "neigh_modify exclude type 1 $(1+floor(step/2000))"\n', pair=IN(2.1e-3), live="part 3")
L("E42_every_exclude_step_part2", "E41 meeting in part 2 (only 1 1 excluded then: collides)", 'run 4000 every 1000 "neigh_modify exclude type 1 $(1+floor(step/2000))"\n',
  pair=IN(G11), live="part 2")
L("E43_every_exclude_var_part3", "E41 with variable t equal 1+floor(step/2000) and ${t}", 'variable t equal 1+floor(step/2000)\nrun 4000 every 1000 "neigh_modify exclude type 1 ${t}"\n',
  pair=IN(2.1e-3), live="part 3")
L("E44_every_if_exclude_part3", "every 'if \"$(step) >= 2000\" then \"neigh_modify exclude type 1 2\"'; meets in part 3 (passes)",
  'run 4000 every 1000 \'if "$(step) >= 2000" then "neigh_modify exclude type 1 2"\'\n', pair=IN(2.1e-3), live="part 3")
L("E45_every_if_exclude_part2", "E44 meeting in part 2 (not yet excluded: collides)", 'run 4000 every 1000 \'if "$(step) >= 2000" then "neigh_modify exclude type 1 2"\'\n',
  pair=IN(G11), live="part 2")
L("E46_every_exclude_step_upto", "run 1000; run 5000 upto every 1000 \"neigh_modify exclude type 1 $(1+floor(step/3000))\" (1 2 excluded after step 3000); meets at step 2100 (collides)",
  'run 1000\nrun 5000 upto every 1000 "neigh_modify exclude type 1 $(1+floor(step/3000))"\n', pair=IN(2.1e-3), live="part 2")

RST = ("run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst\ncomm_modify vel yes\n{again}"
       "fix grav all gravity 9.81 vector 0 0 -1\nfix floor all wall/gran " + WHK + " zplane 0 NULL\nfix integ all nve/sphere\nrun 3000\n")
L("P59_fff_bare_restart_border", "f f f box, processors * 1 1, the pair across x = 0.02; run 1000; write_restart; clear; read_restart (bare); fixes; run 3000",
  RST.format(again=""), pre=FB, pair=IN(G11))
L("P60_fff_restart_given_again_border", "P59 with pair_style granular and pair_coeff given again after the read", RST.format(again="pair_style granular\npair_coeff * * " + HK + "\n"),
  pre=FB, pair=IN(G11))
L("P61_fff_nsq_border", "f f f box, neighbor 0.001 nsq, processors * 1 1, the pair across x = 0.02", "neighbor 0.001 nsq\nrun 3000\n", pre=FB)
L("P62_fff_bare_restart_vertical_default_grid", "P59 with no processors command and the pair along z across 0.05", RST.format(again=""), pre=BASE(boundary="f f f"),
  pair=IN(G11, ax="z"), **VZ)
L("D25_read_data_pairij_style_given_again", "pair_style granular; read_data with PairIJ Coeffs (kn 5000 for 1 2); pair_style granular given again; run",
  "", pre="", pair="")
DECKS["D25_read_data_pairij_style_given_again"] = ("# pair_style granular; read_data with PairIJ Coeffs (1 2 kn 5000); pair_style granular given again (same style); run\n"
    "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\npair_style granular\nread_data d.data\npair_style granular\n" + TAIL + "run 3000\n", "last run",
    {"d.data": DATA_HEAD.format(n=2) + "PairIJ Coeffs # granular\n\n1 1 " + HK + "\n1 2 " + HK5 + "\n2 2 " + HK + "\n\n" + ATOMS + VELS}, {})
HK8 = "hooke 8000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
L("D26_mixed_pair_from_like_pairs", "pair_coeff 1 1 kn 2000 and 2 2 kn 8000 only (1 2 mixed by LAMMPS)", "run 3000\n",
  pre=BASE(coeff="pair_coeff 1 1 " + HK + "\npair_coeff 2 2 " + HK8 + "\n"))
DECKS["D27_read_data_pair_coeffs_mixed"] = ("# read_data with a Pair Coeffs section: 1 kn 2000, 2 kn 8000 (1 2 mixed)\n" +
    "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\npair_style granular\nread_data d.data\n" + TAIL + "run 3000\n", "last run",
    {"d.data": DATA_HEAD.format(n=2) + "Pair Coeffs # granular\n\n1 " + HK + "\n2 " + HK8 + "\n\n" + ATOMS + VELS}, {})
L("D28_mixed_pair_damping_differs", "pair_coeff 1 1 hooke 2000 damping 1000; 2 2 hooke 2000 damping 5000 (1 2 mixed)", "run 3000\n",
  pre=BASE(coeff="pair_coeff 1 1 hooke 2000 1000 damping mass_velocity tangential linear_nohistory 1 0.3\npair_coeff 2 2 hooke 2000 5000 damping mass_velocity tangential linear_nohistory 1 0.3\n"))
L("D29_replicate_periodic_pair", "the pair across the periodic x boundary; replicate 2 1 1; run (ids 1 2 now inside the doubled box?)", "replicate 2 1 1\nrun 1000\nrun 3000\n",
  pre=BASE(wall=False), pair=PER(G11))
LG("L32_lig_cohesion_sjkr", "model hertz tangential history cohesion sjkr, cohesionEnergyDensity 1e4 (the pair 1 2, e 0.5)", "run 3000\n",
   pre=LBASE(extra="fix m6 all property/global cohesionEnergyDensity peratomtypepair 3 1e4 1e4 1e4 1e4 1e4 1e4 1e4 1e4 1e4\n").replace(
   "pair_style gran model hertz tangential history\n", "pair_style gran model hertz tangential history cohesion sjkr\n"))
LG("L33_lig_restitution_given_twice_other_id", "coefficientRestitution given by fix m3 (e 1 2 0.5) and again by fix m3b (e 1 2 0.8): which one is read",
   "run 3000\n", pre=LBASE(extra="fix m3b all property/global coefficientRestitution peratomtypepair 3 0.6 0.8 0.7 0.8 0.4 0.45 0.7 0.45 0.8\n"))
LG("L34_lig_restitution_other_id_between_runs", "run 1000; fix m3b coefficientRestitution (e 1 2 0.8) added beside m3; run 3000 (meets in run 2)",
   "run 1000\nfix m3b all property/global coefficientRestitution peratomtypepair 3 0.6 0.8 0.7 0.8 0.4 0.45 0.7 0.45 0.8\nrun 3000\n", pair=LIN(G11))
LG("L35_lig_unfix_m3_refix_other_id", "run 1000; unfix m3; fix m3b coefficientRestitution (e 1 2 0.8); run 3000",
   "run 1000\nunfix m3\nfix m3b all property/global coefficientRestitution peratomtypepair 3 0.6 0.8 0.7 0.8 0.4 0.45 0.7 0.45 0.8\nrun 3000\n", pair=LIN(G11))

DECKS["O04_lig_snow_slope_kunwar"] = (open(os.path.join(OD, "O04.in")).read(), "last run",
                                      {"slope.stl": stl_plane("slope", (0, -150, 240), (150, -150, 240), (600, 150, 0), (0, 150, 240)).replace(
                                          "vertex 600 150 0", "vertex 150 150 240")},
                                      {"LIGGGHTS": "", "SEP": "0.01", "PAIR": "types 1 1"})
DECKS["O05_lig_screw_conveyor_ortiz"] = (open(os.path.join(OD, "O05.in")).read(), "run 1",
                                         {"case_remesh.stl": stl_plane("case", (-0.01, -0.01, 0), (0.42, -0.01, 0), (0.42, 0.05, 0), (-0.01, 0.05, 0)),
                                          "screw_simplified.stl": stl_plane("screw", (0.15, 0.017, 0.0115), (0.25, 0.017, 0.0115), (0.25, 0.021, 0.0115), (0.15, 0.021, 0.0115)),
                                          "feed.stl": stl_plane("feed", (0.0, 0.0, 0.05), (0.05, 0.0, 0.05), (0.05, 0.04, 0.05), (0.0, 0.04, 0.05)),
                                          "outlet_1.stl": stl_plane("outlet", (0.38, 0.0, 0.001), (0.42, 0.0, 0.001), (0.42, 0.04, 0.001), (0.38, 0.04, 0.001))},
                                         {"LIGGGHTS": "", "SEP": "0.001", "PAIR": "types 1 1"})

L("E47_every_pair_coeff_constant_pre_no", "every \"pair_coeff 1 2 hooke 5000 ...\" (constant) with pre no", 'run 4000 pre no every 1000 "' + PC12.format(k="5000") + '"\n', pair=IN(G11), live="part 2")
L("E48_every_set_type_constant_pre_no", "pair_coeff 1 1 kn 5000; every \"set atom 2 type 1\" with pre no (the pair 1 1 from part 2)",
  "pair_coeff 1 1 " + HK5 + '\nrun 4000 pre no every 1000 "set atom 2 type 1"\n', pair=IN(G11), live="part 2", PAIR="types 1 1")
L("E49_every_wall_constant_pre_no", "WALL: every \"fix floor all wall/gran ... hooke 5000 ...\" (constant, same ID) with pre no",
  'run 4000 pre no every 1000 "fix floor all wall/gran granular ' + HK5 + ' zplane 0 NULL"\n', pair=WALLP(0.0011), live="part 2", **WALL)
L("E50_every_set_density_constant", "every \"set type 2 density 3500\" (constant)", 'run 4000 every 1000 "set type 2 density 3500"\n', pair=IN(G11), live="part 2")
L("E51_every_set_density_constant_pre_no", "E50 with pre no", 'run 4000 pre no every 1000 "set type 2 density 3500"\n', pair=IN(G11), live="part 2")
L("E52_every_pair_coeff_other_pair_pre_no", "every \"pair_coeff 1 1 hooke 5000 ...\" with pre no (not the live pair)", 'run 4000 pre no every 1000 "pair_coeff 1 1 ' + HK5 + '"\n',
  pair=IN(G11), live="part 2")
L("E53_every_exclude_constant_part3_pre_no", "every \"neigh_modify exclude type 1 2\" pre no, meets in part 3", 'run 4000 pre no every 1000 "neigh_modify exclude type 1 2"\n',
  pair=IN(2.1e-3), live="part 3")

L("P63_fff_displace_pre_no_no_processors", "the plainest SW-NP deck: f f f box, no processors command (2 processes split z at 0.05), the pair along z across 0.05; run 1000; displace_atoms all move 0 0 0; run 3000 pre no",
  "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 3000 pre no\n", pre=BASE(boundary="f f f"), pair=IN(G11, ax="z"), **VZ)

LG("P64_lig_fff_displace_pre_no_np2", "LIGGGHTS f f f box, processors 2 1 1, the pair across x = 0; run 1000; displace_atoms 0; run 3000 pre no",
   "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 3000 pre no\n", pre=LBASE(head="processors 2 1 1\n", boundary="f f f"), pair=LIN(G11), NP="2")
LG("P65_lig_fff_change_box_pre_no_np2", "LIGGGHTS f f f box, processors 2 1 1; run 1000; change_box all x final -0.05 0.05; run 3000 pre no",
   "run 1000\nchange_box all x final -0.05 0.05 units box\nrun 3000 pre no\n", pre=LBASE(head="processors 2 1 1\n", boundary="f f f"), pair=LIN(G11), NP="2")
LG("P66_lig_fff_displace_pre_no_default_grid", "LIGGGHTS f f f box, no processors command (2 processes), the pair along x at x = 0; displace_atoms; run 3000 pre no (1 and 2 processes)",
   "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 3000 pre no\n", pre=LBASE(boundary="f f f"), pair=LIN(G11))

L("P67_fff_delete_far_pre_no", "f f f box, processors * 1 1, the pair across x = 0.02; run 1000; delete_atoms of a far sphere; run 3000 pre no",
  "group v3 id 3\nrun 1000\ndelete_atoms group v3\nrun 3000 pre no\n", pre=FB, pair=IN(G11) + "create_atoms 2 single 0.005 0.01 0.012\nset atom 3 diameter 0.006 density 2500\n")
L("P68_fff_create_far_pre_no", "f f f box, processors * 1 1; run 1000; create_atoms 2 single far; set; run 3000 pre no",
  "run 1000\ncreate_atoms 2 single 0.005 0.01 0.012\nset atom 3 diameter 0.006 density 2500\nrun 3000 pre no\n", pre=FB, pair=IN(G11))
L("P69_fff_read_data_add_pre_no", "f f f box, processors * 1 1; run 1000; read_data far.data add append; run 3000 pre no",
  "run 1000\nread_data far.data add append\nrun 3000 pre no\n", pre=FB, pair=IN(G11),
  data={"far.data": "# far\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 2 0.006 2500 0.005 0.01 0.012\n"})
L("P70_fff_set_x_across_border_pre_no", "f f f box, processors * 1 1, map array; lv1 left of x = 0.02; run 1000; set atom 1 x +0.1 mm; run 3000 pre no",
  "run 1000\nset atom 1 x $(x[1]+0.0001)\nrun 3000 pre no\n", pre=BASE(head="atom_modify map array\nprocessors * 1 1\n", boundary="f f f"), pair=IN(G11 + 0.1e-3))
L("P71_fff_write_restart_pre_no", "f f f box, processors * 1 1; run 1000; write_restart; run 3000 pre no", "run 1000\nwrite_restart a.rst\nrun 3000 pre no\n", pre=FB, pair=IN(G11))
L("P72_fff_delete_overlap_far_pre_no", "f f f box; run 1000; delete_atoms overlap 0.001 of two far spheres; run 3000 pre no",
  "run 1000\ndelete_atoms overlap 0.001 v34 v34\nrun 3000 pre no\n", pre=FB,
  pair=IN(G11) + "create_atoms 2 single 0.005 0.01 0.012\ncreate_atoms 2 single 0.0055 0.01 0.012\nset atom 3*4 diameter 0.006 density 2500\ngroup v34 id 3 4\n")

L("D30_labelmap_pair_coeff_labels", "labelmap atom 1 small 2 big; pair_coeff small big hooke 5000 ... (type labels)", "run 3000\n",
  pre=BASE().replace("pair_coeff * * " + HK + "\n", "labelmap atom 1 small 2 big\npair_coeff * * " + HK + "\npair_coeff small big " + HK5 + "\n"))
L("D31_labelmap_swapped_order", "labelmap atom 2 small 1 big (label 'small' is type 2); pair_coeff big big kn 5000 (types 1 1), pair_coeff small big kn 8000 (1 2)", "run 3000\n",
  pre=BASE().replace("pair_coeff * * " + HK + "\n", "labelmap atom 2 small 1 big\npair_coeff * * " + HK + "\npair_coeff big big " + HK5 + "\npair_coeff small big " + HK8 + "\n"))
DECKS["D32_read_data_type_labels"] = ("# read_data with an Atom Type Labels section (1 small, 2 big) and a PairIJ-free deck: pair_coeff big small kn 5000 after\n" +
    "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data d.data\npair_style granular\npair_coeff * * " + HK + "\npair_coeff big small " + HK5 + "\n" + TAIL + "run 3000\n", "last run",
    {"d.data": DATA_HEAD.format(n=2) + "Atom Type Labels\n\n1 small\n2 big\n\n" + ATOMS.replace("\n1 1 0.004", "\n1 small 0.004").replace("\n2 2 0.006", "\n2 big 0.006") + VELS}, {})
L("D33_create_atoms_by_label", "labelmap atom 1 small 2 big; the pair made by create_atoms small/big; pair_coeff 1 2 kn 5000 by number", "run 3000\n",
  pre=BASE().replace("pair_coeff * * " + HK + "\n", "labelmap atom 1 small 2 big\npair_coeff * * " + HK + "\npair_coeff 1 2 " + HK5 + "\n"),
  pair=IN(0.1e-3).replace("create_atoms 1 single", "create_atoms small single").replace("create_atoms 2 single", "create_atoms big single"))
L("D34_fix_freeze_lv2", "fix freeze on lv2 (the 6 mm sphere held still); lv1 at 1 m/s onto it (relative speed 1)", "unfix integ\ngroup mob subtract all lv2\nfix integ mob nve/sphere\nfix fr lv2 freeze\nrun 3000\n",
  pair=IN(0.1e-3).replace(f"velocity lv1 set {V1:.10f} 0 0", "velocity lv1 set 1 0 0").replace(f"velocity lv2 set {V2:.10f} 0 0", "velocity lv2 set 0 0 0"))
L("D35_setforce_lv2_zero", "fix setforce 0 0 0 on lv2 beside nve/sphere on all (lv2 keeps its velocity)", "fix sf lv2 setforce 0 0 0\nrun 3000\n")

L("P73_replicate_111_pre_no_no_wall", "no wall fix; run 1000; replicate 1 1 1; run 3000 pre no (the pair across the periodic x boundary)", "run 1000\nreplicate 1 1 1\nrun 3000 pre no\n",
  pre=BASE(wall=False), pair=PER(G11))
L("P74_fff_replicate_111_pre_no_no_wall", "f f f box, no wall fix, processors * 1 1, the pair across x = 0.02; run 1000; replicate 1 1 1; run 3000 pre no",
  "run 1000\nreplicate 1 1 1\nrun 3000 pre no\n", pre=BASE(wall=False, boundary="f f f", head="processors * 1 1\n"), pair=IN(G11))
L("P75_replicate_111_pre_no_inside_no_wall", "p p f box, no wall fix; the pair inside; run 1000; replicate 1 1 1; run 3000 pre no", "run 1000\nreplicate 1 1 1\nrun 3000 pre no\n",
  pre=BASE(wall=False, head="processors * 1 1\n"), pair=IN(G11))

L("P76_replicate_pre_no_plain", "the plainest: no wall fix, no processors command; the pair inside; run 1000; replicate 1 1 1; run 3000 pre no (LAMMPS moves no atom in that run)",
  "run 1000\nreplicate 1 1 1\nrun 3000 pre no\n", pre=BASE(wall=False), pair=IN(G11))
L("P77_replicate_211_pre_no", "no wall fix; the pair inside; run 1000; replicate 2 1 1; run 3000 pre no", "run 1000\nreplicate 2 1 1\nrun 3000 pre no\n",
  pre=BASE(wall=False), pair=IN(G11))
L("P78_replicate_run0_pre_no", "P76 with run 0 between the replicate and the pre-no run (set up again: right)", "run 1000\nreplicate 1 1 1\nrun 0\nrun 3000 pre no\n",
  pre=BASE(wall=False), pair=IN(G11))
L("P79_replicate_pre_no_then_run", "P76 then run 3000 (no pre no): the pair meets in the last run (gap 3.1 mm: after the frozen run)", "run 1000\nreplicate 1 1 1\nrun 1000 pre no\nrun 3000\n",
  pre=BASE(wall=False), pair=IN(G11 + 1e-3))
L("P80_replicate_pre_no_wall_sphere_only", "WALL: f f f box... no: a wall deck without a wall/gran per-atom history (fix wall/gran granular hooke with linear_nohistory); run 500; replicate 1 1 1; run 3000 pre no",
  "run 500\nreplicate 1 1 1\nrun 3000 pre no\n", pair=WALLP(0.0011), **WALL)

# ---- Q: fixes removed, added or replaced before `run N pre no` (after SW-RP: a run that is not set up may not integrate)
L("Q01_unfix_gravity_pre_no", "run 1000; unfix grav; run 3000 pre no", "run 1000\nunfix grav\nrun 3000 pre no\n", pair=IN(G11))
L("Q02_fix_viscous_zero_added_pre_no", "run 1000; fix vz all viscous 0.0; run 3000 pre no", "run 1000\nfix vz all viscous 0.0\nrun 3000 pre no\n", pair=IN(G11))
L("Q03_integrator_replaced_pre_no", "run 1000; unfix integ; fix integ all nve/sphere; run 3000 pre no", "run 1000\nunfix integ\nfix integ all nve/sphere\nrun 3000 pre no\n", pair=IN(G11))
L("Q04_wall_replaced_same_id_pre_no", "WALL: run 500; fix floor all wall/gran ... hooke 5000 (same ID, replaced); run 3000 pre no",
  "run 500\nfix floor all wall/gran granular " + HK5 + " zplane 0 NULL\nrun 3000 pre no\n", pair=WALLP(0.0011), **WALL)
L("Q05_unfix_wall_pre_no", "run 1000; unfix floor; run 3000 pre no (the pair far above the floor)", "run 1000\nunfix floor\nrun 3000 pre no\n", pair=IN(G11))
L("Q06_unfix_wall_refix_pre_no", "WALL: run 500; unfix floor; fix floor ... hooke 5000; run 3000 pre no",
  "run 500\nunfix floor\nfix floor all wall/gran granular " + HK5 + " zplane 0 NULL\nrun 3000 pre no\n", pair=WALLP(0.0011), **WALL)
L("Q07_second_gravity_added_pre_no", "run 1000; fix g2 all gravity 9.81 vector 0 0 -1; run 3000 pre no", "run 1000\nfix g2 all gravity 9.81 vector 0 0 -1\nrun 3000 pre no\n", pair=IN(G11))
L("Q08_integrator_added_other_group_pre_no", "integrator on lv1 only at first (fix i1 lv1, fix i2 lv2); run 1000; unfix i2; fix i2 lv2 nve/sphere; run 3000 pre no",
  "unfix integ\nfix i1 lv1 nve/sphere\nfix i2 lv2 nve/sphere\nrun 1000\nunfix i2\nfix i2 lv2 nve/sphere\nrun 3000 pre no\n", pair=IN(G11))
L("Q09_unfix_gravity_pre_no_wall", "WALL: run 500; unfix grav; run 3000 pre no (no gravity: the sphere keeps 1 m/s)", "run 500\nunfix grav\nrun 3000 pre no\n", pair=WALLP(0.0011), **WALL)
L("Q10_compute_added_pre_no", "run 1000; compute ke all ke/atom; run 3000 pre no (harmless)", "run 1000\ncompute kea all ke/atom\nrun 3000 pre no\n", pair=IN(G11))
LG("Q11_lig_unfix_gravity_pre_no", "LIGGGHTS: run 1000; unfix gravi; run 3000 pre no", "run 1000\nunfix gravi\nrun 3000 pre no\n", pair=LIN(G11))
LG("Q12_lig_integrator_replaced_pre_no", "LIGGGHTS: run 1000; unfix integr; fix integr all nve/sphere; run 3000 pre no", "run 1000\nunfix integr\nfix integr all nve/sphere\nrun 3000 pre no\n", pair=LIN(G11))

FAR = "create_atoms 2 single 0.005 0.01 0.012\nset atom 1 diameter 0.006 density 2500\n"
NEWPAIR = IN(0.1e-3).replace("set atom 1 ", "set atom 2 ").replace("set atom 2 diameter 0.006", "set atom 3 diameter 0.006").replace("group lv1 id 1", "group lv1 id 2").replace("group lv2 id 2", "group lv2 id 3")
L("Q13_pair_created_after_run_pre_no", "a far sphere; run 1000; the live pair created (ids 2 3), set, velocity; run 3000 pre no", "run 1000\n" + NEWPAIR + "run 3000 pre no\n", pair=FAR)
L("Q14_all_deleted_pair_created_pre_no", "the pair; run 1000; delete_atoms group all; the pair created again (ids 1 2 after compress), velocity; run 3000 pre no",
  "run 1000\ndelete_atoms group all compress yes\n" + IN(0.1e-3).replace("group lv1 id 1\ngroup lv2 id 2\n", "group lv1 id 1\ngroup lv2 id 2\n") + "run 3000 pre no\n", pair=IN(0.1e-3, y=0.01))
L("Q15_pair_created_after_run_no_pre_no", "Q13 without pre no (control)", "run 1000\n" + NEWPAIR + "run 3000\n", pair=FAR)
L("Q16_read_data_add_pair_pre_no", "a far sphere; run 1000; read_data pair.data add append (the live pair, ids 2 3, with Velocities); run 3000 pre no",
  "run 1000\nread_data pair.data add append\ngroup lv1 id 2\ngroup lv2 id 3\nrun 3000 pre no\n", pair=FAR, data={"pair.data": DATA_HEAD.format(n=2) + ATOMS + VELS})


# ================================================================ write
def write(only=()):
    for name, (text, live, data, meta) in sorted(DECKS.items()):
        if only and not any(name.startswith(p) for p in only):
            continue
        d = os.path.join(D, name)
        os.makedirs(d, exist_ok=True)
        open(os.path.join(d, "in.deck"), "w").write(text)
        open(os.path.join(d, "DECK"), "w").write("in.deck\n")
        open(os.path.join(d, "G"), "w").write("1\n")
        open(os.path.join(d, "LIVE"), "w").write(("WALL " if "PAIR" in meta and "wall" in meta["PAIR"] else "") + live + "\n")
        for k, v in meta.items():
            open(os.path.join(d, k), "w").write(v + "\n")
        for f, t in data.items():
            p = os.path.join(d, f)
            os.makedirs(os.path.dirname(p), exist_ok=True)
            open(p, "w").write(t)
    print(len(DECKS), "decks")


if __name__ == "__main__":
    write(sys.argv[1:])

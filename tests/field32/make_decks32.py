"""Field round 32: write decks/NAME/in.deck with rounds 30-31's helpers (make_decks31.py, make_decks30.py: kn 2000,
dt 1e-6, the live pair 4 mm type 1 / 6 mm type 2 meeting at 1 m/s), refereed by live32.py (the deck run as written;
a GROUPS file names the two groups printed where the deck makes a sphere again under another group, an AXIS file the
axis the pair meets along). Prefixes: L LIGGGHTS spheres made again or grown before run pre no; P LAMMPS spheres made,
moved or renumbered before pre no (IDs reused, compress, read_data add merge, delete_atoms overlap, molecules, pours);
N new spheres near the live one before pre no (in the box, across the periodic boundary); A fix adapt (several groups,
index and ramp variables, unfix and re-add, dynamic groups, a pair coefficient); R RL RP RZ restart round trips (global
cutoff, hybrid, omp, what a restart keeps, a pair across a periodic boundary or across a bin face in the box); PB a
pair across a periodic boundary with a command between runs and pre no; PC set-up checks made before pre no; Q LQ
quoted file names; F I H PX a modeller's other commands (integrators twice or on subsets, motion fixes, units, 2d,
damping options, timestep); S atom_style sphere 0; W moving walls; LX LIGGGHTS ghost velocities.
usage: python make_decks32.py [NAME ...]"""
import os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field31"))
import make_decks31 as p31  # noqa: E402

p = p31.p
m, q = p.m, p.q
m.DECKS.clear(); p.LIVE.clear(); p.EXTRA.clear()
m.D = os.path.join(HERE, "decks")
E, Ld, vic, extra, BL, B3, HK, hk, K = p.E, p.Ld, p.vic, p.extra, p.BL, p.B3, p.HK, p.hk, p.K
g11, g31, g41 = p.g11, p.g31, p.g41
V26, MAP, X5, CA, LV = p31.V26, p31.MAP, p31.X5, p31.CA, p.LV
W = p.W


def groups(name, a="lv1", b="lvn"):
    extra(name, GROUPS=f"{a} {b}")


# ------------------------------------------------------------ L: LIGGGHTS, a sphere made again or grown before pre no
# victims (LV): IDs 3 (12 mm) and 4 (6 mm), type 2; lv2 deleted with compress no and made again at its place (ID 5)
LRE = lambda d, run="run 3000 pre no\n", make=None: (
    LV + "run 1000\nvariable xx equal x[2]\nvariable zz equal z[2]\nvariable vz equal vz[2]\nvariable x0 equal ${xx}\n"
    "variable z0 equal ${zz}\nvariable v0 equal ${vz}\ndelete_atoms group lv2 compress no\n"
    + (make or f"create_atoms 2 single ${{x0}} 0 ${{z0}} units box\nset atom 5 diameter {d} density 2500\n")
    + "group lvn id 5\nvelocity lvn set -0.2285714286 0 ${v0}\n" + run)
Ld("L01_lig_new_id_12mm_victims_pre_no", "LIGGGHTS SW-G: victims 12, 6 mm; lv2 deleted (compress no), made again 12 mm at a new ID (5); run 3000 pre no",
   LRE(0.012), gap=g41, sep=0.008)
Ld("L02_lig_new_id_12mm_control", "L01 without pre no", LRE(0.012, run="run 3000\n"), gap=g41, sep=0.008)
Ld("L03_lig_new_id_6mm_pre_no", "L01 with the new sphere 6 mm (no growth)", LRE(0.006), gap=g11)
Ld("L04_lig_new_id_12mm_no_victims_pre_no", "L01 without victims: LIGGGHTS gives the new sphere ID 2 again (the largest ID + 1), 12 mm", LRE(0.012).replace(LV, "").replace("set atom 5", "set atom 2").replace("id 5", "id 2"),
   gap=g41, sep=0.008)
Ld("L05_lig_grow_loop_victims_pre_no", "LIGGGHTS victims 12, 6 mm; loop 2 x run 500, lv2 grows in pass 2 (if); run 3000 pre no",
   LV + 'variable i loop 2\nlabel l\nrun 500\nif "${i} == 2" then "set group lv2 diameter 0.012"\nnext i\njump SELF l\nrun 3000 pre no\n', gap=g41, sep=0.008)
LINSB = ("fix pts9 all particletemplate/sphere 15485863 atom_type 2 density constant 2500 radius constant 0.006\n"
         "fix pdd9 all particledistribution/discrete 32452843 1 pts9 1.0\n"
         "variable xa equal ${x0}-1e-5\nvariable xb equal ${x0}+1e-5\nvariable za equal ${z0}-1e-5\nvariable zb equal ${z0}+1e-5\n"
         "region nb block ${xa} ${xb} -1e-5 1e-5 ${za} ${zb} units box\n"
         "fix ins all insert/pack seed 49979687 distributiontemplate pdd9 vel constant -0.2285714286 0 ${v0} insert_every once overlapcheck yes all_in no particles_in_region 1 region nb\n")
Ld("L06_lig_insert_pack_at_lv2_pre_no", "LIGGGHTS victims 12, 6 mm; lv2 deleted, insert/pack puts one 12 mm type 2 at its place (moving as lv2 did); run 3000 pre no; group after",
   LRE(0.012, make=LINSB, run="run 3000 pre no\ngroup lvn id 5\n").replace("group lvn id 5\nvelocity lvn set -0.2285714286 0 ${v0}\n", ""), gap=g41, sep=0.008)
Ld("L07_lig_insert_pack_at_lv2_control", "L06 without pre no",
   LRE(0.012, make=LINSB, run="run 3000\ngroup lvn id 5\n").replace("group lvn id 5\nvelocity lvn set -0.2285714286 0 ${v0}\n", ""), gap=g41, sep=0.008)
for n in ("L01_lig_new_id_12mm_victims_pre_no", "L02_lig_new_id_12mm_control", "L03_lig_new_id_6mm_pre_no", "L04_lig_new_id_12mm_no_victims_pre_no",
          "L06_lig_insert_pack_at_lv2_pre_no", "L07_lig_insert_pack_at_lv2_control"):
    groups(n)
Ld("L08_lig_victims_grow_region_pre_no", "LIGGGHTS victims 12, 6 mm; set region (a block around lv2) diameter 0.012; run 3000 pre no",
   LV + "region rg block 0.002 0.02 -0.005 0.005 0.09 0.11 units box\nrun 1000\nset region rg diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)

# ------------------------------------------------------------ P: LAMMPS, spheres made, moved or renumbered before pre no (by ID the sizes look unchanged)
PRE = "variable xx equal $(x[2])\nvariable zz equal $(z[2])\nvariable vz equal $(vz[2])\n"
E("P01_overlap_delete_new_in_old_slot_pre_no", "victims 12, 6 mm; a 12 mm type 2 made at lv2's place (ID 5), then delete_atoms overlap removes lv2 (its slot takes the new atom); run 3000 pre no",
  V26 + "run 1000\n" + PRE + CA + "set atom 5 diameter 0.012 density 2500\ngroup lvn id 5\nvelocity lvn set -0.2285714286 0 ${vz} units box\n"
  "delete_atoms overlap 0.0001 lv2 all compress no\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=MAP)
E("P02_compress_id_reused_same_size_pre_no", "victims 12 (ID 3), 6 mm (ID 4); lv2 and the 12 mm victim deleted (compress yes): the 6 mm takes ID 2; the new 12 mm at lv2's place takes ID 3 (held 12 mm); run 3000 pre no",
  V26 + "group v3 id 3\nrun 1000\n" + PRE + "delete_atoms group lv2\ndelete_atoms group v3\n" + CA + "set atom 3 diameter 0.012 density 2500\ngroup lvn id 3\nvelocity lvn set -0.2285714286 0 ${vz} units box\nrun 3000 pre no\n",
  gap=g41, sep=0.008, pre=MAP)
E("P03_compress_id_reused_control", "P02 without pre no",
  V26 + "group v3 id 3\nrun 1000\n" + PRE + "delete_atoms group lv2\ndelete_atoms group v3\n" + CA + "set atom 3 diameter 0.012 density 2500\ngroup lvn id 3\nvelocity lvn set -0.2285714286 0 ${vz} units box\nrun 3000\n",
  gap=g41, sep=0.008, pre=MAP)
RDM = ("# ID 3 again\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n"
       "3 2 0.012 2500 0.024821 0.02 0.049995095\n\nVelocities\n\n3 -0.2285714286 0 -0.00981 0 0 0\n")
E("P04_read_data_merge_id3_same_size_pre_no", "victims 12 (ID 3), 6 mm; lv2 and the 12 mm victim deleted (compress no); read_data add merge of ID 3, 12 mm, at lv2's place; run 3000 pre no",
  V26 + "group v3 id 3\nrun 1000\ndelete_atoms group lv2 compress no\ndelete_atoms group v3 compress no\nread_data r3.data add merge\ngroup lvn id 3\nrun 3000 pre no\n",
  gap=g41, sep=0.008, pre=MAP, data={"r3.data": RDM})
E("P05_move_victim_into_place_pre_no", "victims 12 (ID 3), 6 mm; lv2 deleted (compress no); the 12 mm victim moved to lv2's place with its velocity (set atom 3 x y z); run 3000 pre no",
  V26 + "run 1000\n" + PRE + "delete_atoms group lv2 compress no\nset atom 3 x ${xx} y 0.02 z ${zz}\ngroup lvn id 3\nvelocity lvn set -0.2285714286 0 ${vz} units box\nrun 3000 pre no\n",
  gap=g41, sep=0.008, pre=MAP)
E("P06_swap_places_pre_no", "victims 12 (ID 3), 6 mm; lv2 and the 12 mm victim swap places and velocities (no size changes); run 3000 pre no",
  V26 + "run 1000\n" + PRE + "set atom 2 x 0.01 y 0.01 z 0.012\nvelocity lv2 set 0 0 0 units box\nset atom 3 x ${xx} y 0.02 z ${zz}\ngroup lvn id 3\nvelocity lvn set -0.2285714286 0 ${vz} units box\nrun 3000 pre no\n",
  gap=g41, sep=0.008, pre=MAP)
E("P07_displace_lv2_within_half_skin_grown_pre_no", "no victims; lv2 grows 6 -> 6.8 mm (within the skin) and is displaced 0.3 mm toward lv1; run 3000 pre no",
  "run 1000\nset group lv2 diameter 0.0068\ndisplace_atoms lv2 move -0.0003 0 0 units box\nrun 3000 pre no\n", gap=g11 + 0.7e-3, sep=0.0054)
E("P08_new_id_type_held_none_then_pre_no_twice", "X05 with run 0 pre no between (no set-up; new 12 mm at new ID)", X5(CA).replace("run 3000 pre no", "run 0 pre no\nrun 3000 pre no"),
  gap=g41, sep=0.008, pre=MAP)
E("P09_pour_12mm_then_new_id_pre_no", "pour of one 12 mm type 2 during run 1000 (none at its set-up); lv2 deleted and made 12 mm at a new ID; run 3000 pre no",
  q.POUR12 + "run 1000\n" + PRE + "delete_atoms group lv2 compress no\n" + CA + "set atom 4 diameter 0.012 density 2500\ngroup lvn id 4\nvelocity lvn set -0.2285714286 0 ${vz} units box\nrun 3000 pre no\n",
  gap=g41, sep=0.008, pre=MAP)
E("P10_create_molecule_two_atoms_new_ids_pre_no", "victims 12, 6 mm; lv2 deleted; a two-sphere molecule (12 mm at lv2's place, 6 mm far off) made at new IDs; run 3000 pre no",
  V26 + "run 1000\n" + PRE + "delete_atoms group lv2 compress no\nmolecule m2 two.mol\ncreate_atoms 0 single ${xx} 0.02 ${zz} mol m2 4711 units box\ngroup lvn id 5\nvelocity lvn set -0.2285714286 0 ${vz} units box\n"
  "run 3000 pre no\n", gap=g41, sep=0.008, pre=MAP,
  data={"two.mol": "# two\n\n2 atoms\n\nCoords\n\n1 0 0 0\n2 0 0.015 -0.03\n\nTypes\n\n1 2\n2 2\n\nDiameters\n\n1 0.012\n2 0.006\n\nMasses\n\n1 0.0022619467\n2 0.00028274334\n"})
for n in ("P01_overlap_delete_new_in_old_slot_pre_no", "P02_compress_id_reused_same_size_pre_no", "P03_compress_id_reused_control", "P04_read_data_merge_id3_same_size_pre_no",
          "P05_move_victim_into_place_pre_no", "P06_swap_places_pre_no", "P09_pour_12mm_then_new_id_pre_no", "P10_create_molecule_two_atoms_new_ids_pre_no"):
    groups(n)

# ------------------------------------------------------------ A: fix adapt
DD = "variable dd equal 0.012\n"
E("A01_adapt_index_next_between_runs", "variable dd index 0.006 0.012; fix adapt lv2 v_dd reset no; run 1000; next dd; run 3000 (12 mm at the set-up, pair 0.1 mm apart)",
  "variable dd index 0.006 0.012\nfix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 1000\nnext dd\nrun 3000\n", gap=g41, sep=0.008)
E("A02_adapt_unfix_readd_same_size", "fix adapt lv2 12 mm over run 1000 (grown at its set-up, far); unfix; fix adapt again 12 mm; run 3000 (no growth at this set-up)",
  DD + "fix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 1000\nunfix ad\nfix ad2 lv2 adapt 1 atom diameter v_dd reset no\nrun 3000\n", gap=g41 + 3e-3, sep=0.008)
E("A03_adapt_two_groups_one_shrinks", "fix adapt lv1 4 -> 2 mm (shrink) and lv2 6 -> 12 mm (a far victim group v, type 2) from the first run; live pair 1 2 shrunk lv1",
  vic(2, 0.006, 0.006) + "group v id 3\nvariable d1 equal 0.002\n" + DD + "fix a1 lv1 adapt 1 atom diameter v_d1 reset no\nfix a2 v adapt 1 atom diameter v_dd reset no\nrun 4000\n",
  gap=g31 + 1e-3, sep=0.004)
E("A04_adapt_ramp_start_stop", "fix adapt lv2 v_dd = ramp(0.006,0.012); run 1000 start 0 stop 1000 (12 mm at its end); run 3000 (the ramp starts again: 6 -> 12 mm in the meeting run)",
  "variable dd equal ramp(0.006,0.012)\nfix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 1000 start 0 stop 1000\nrun 3000\n", gap=g41, sep=0.008)
E("A05_adapt_group_redefined", "fix adapt on group g (a far victim, 12 mm); run 1000; group g clear + group g id 2 (lv2); run 3000 (lv2 grown at set-up, pair 0.1 mm apart)",
  vic(2, 0.006, 0.006) + "group g id 3\n" + DD + "fix ad g adapt 1 atom diameter v_dd reset no\nrun 1000\ngroup g clear\ngroup g id 2\nrun 3000\n", gap=g41, sep=0.008)
E("A06_adapt_pair_granular_kn", "fix adapt 1 pair granular kn 1 2 v_k (LAMMPS: not supported)", "variable k equal 5000\nfix ad all adapt 1 pair granular kn 1 2 v_k\nrun 3000\n", gap=0.1e-3)
E("A07_adapt_mass_no_shrink", "fix adapt lv2 6 -> 4 mm mass no (its mass kept) from the start; pair meets after", "variable dd equal 0.004\nfix ad lv2 adapt 1 atom diameter v_dd reset no mass no\nrun 6000\n",
  gap=g31 + 1e-3, sep=0.004)
E("A08_adapt_scale_yes", "fix adapt lv2 atom diameter v_s scale yes (s = 2: 12 mm) from the start, pair 2.1 mm apart after", "variable s equal 2\nfix ad lv2 adapt 1 atom diameter v_s scale yes reset no\nrun 5000\n",
  gap=5.1e-3, sep=0.008)
E("A09_adapt_unfix_then_pre_no_readd", "fix adapt lv2 12 mm over run 1000; unfix; run 100; fix adapt again (12 mm, no growth); run 3000 pre no",
  DD + "fix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 1000\nunfix ad\nrun 100\nfix ad2 lv2 adapt 1 atom diameter v_dd reset no\nrun 3000 pre no\n", gap=g41 + 3e-3 + 0.1e-3, sep=0.008)
E("A10_adapt_every_large_then_var_changes", "fix adapt lv2 every 100000 v_dd (6 mm); run 1000; variable dd equal 0.012; run 3000 (grown at the set-up)",
  "variable dd equal 0.006\nfix ad lv2 adapt 100000 atom diameter v_dd reset no\nrun 1000\nvariable dd equal 0.012\nrun 3000\n", gap=g41, sep=0.008)

# ------------------------------------------------------------ R: restart round trips
RS = lambda after="", before="": (before + "run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst\ncomm_modify vel yes\n" + after + m.GRAV + q.r.FL() + q.r.TAILL.replace("timestep 1e-6\n", "") + "run 3000\n")
GCUT = lambda c: BL().replace("pair_style granular\n", f"pair_style granular {c}\n")
E("R01_restart_global_cutoff_0p02", "pair_style granular 0.02; write_restart; clear; read_restart; run (pair 0.1 mm apart after)", RS(), gap=g11, pre=GCUT(0.02))
E("R02_restart_global_cutoff_small", "pair_style granular 0.001 (skin 0.001); restart; run: the pair 1.1 mm apart at the restart", RS(), gap=g11 + 1e-3, pre=GCUT(0.001))
PER = lambda gap: (f"create_atoms 1 single {0.04 - 0.002 - gap / 2 + 0.0:.9g} 0.02 0.05\ncreate_atoms 2 single {0.003 + gap / 2:.9g} 0.02 0.05\n"
                   "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
                   "velocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\n")
E("R03_restart_periodic_pair_global_cutoff", "pair across the periodic x boundary; pair_style granular 0.02; restart; run", RS(), gap=g11, pre=GCUT(0.02), pair=PER(g11))
E("R04_restart_periodic_pair_plain", "pair across the periodic x boundary; pair_style granular; restart; run", RS(), gap=g11, pair=PER(g11))
E("R05_restart_pair_coeff_regiven", "restart; pair_coeff 1 2 kn 5000 given after read_restart", RS(after=p.P5() + "\n"), gap=g11)
E("R06_restart_hybrid", "pair_style hybrid granular granular (1 2 kn 5000 by instance 2); restart; run", RS(), gap=g11,
  pre=q.r.head(2) + "pair_style hybrid granular granular\npair_coeff * * granular 1 " + HK + "\npair_coeff 1 2 granular 2 " + hk(5000) + "\n" + m.GRAV + q.r.FL() + q.r.TAILL)
E("R07_restart_gran_hooke_omp", "suffix omp; pair_style gran/hooke/history (omp) 2000 NULL 3000 NULL 0.3 0; restart; run", RS(), gap=g11,
  pre=q.r.head(2).replace("units si\n", "units si\npackage omp 1\nsuffix omp\n") + "pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 0\npair_coeff * *\n" + m.GRAV
  + "fix floor all wall/gran hooke/history 2000 NULL 3000 NULL 0.3 0 zplane 0 NULL\n" + q.r.TAILL)
E("R08_restart_grow_then_pre_no", "lv2 grown to 12 mm before write_restart; clear; read_restart; run 3000 pre no (first run after a read: set up anyway)",
  "run 1000\nset group lv2 diameter 0.012\nwrite_restart a.rst\nclear\nread_restart a.rst\n" + m.GRAV + q.r.FL() + q.r.TAILL + "run 3000 pre no\n", gap=g41, sep=0.008)
E("R09_restart_timestep_kept", "timestep 2e-5 before write_restart; after read_restart none given (the file's dt); run 200", "timestep 2e-5\nrun 50\nwrite_restart a.rst\nclear\nread_restart a.rst\n"
  + m.GRAV + q.r.FL() + "fix integ all nve/sphere\nrun 400\n", gap=g11)
E("R10_restart_neighbor_lost_small_cutoff", "pair_style granular 0.001, neighbor 0.005 bin before the restart (not kept by it: skin 0.001 after); pair 2 mm apart at the read",
  RS(before="neighbor 0.005 bin\n"), gap=g11 + 2e-3, pre=GCUT(0.001))

# ------------------------------------------------------------ Q: quoted file names
E("Q01_restart_two_spaces", 'write_restart "a  a.rst"; clear; read_restart "a  a.rst" (pair_coeff 1 2 kn 5000 before)', RS().replace("a.rst", '"a  a.rst"').replace("run 1000\n", p.P5() + "\nrun 1000\n"), gap=g11)
E("Q02_write_read_data_tab", 'write_data "w\tw.data"; clear; read_data "w\tw.data" (kn 5000 in its PairIJ)',
  p.P5() + "\nrun 1000\nwrite_data \"w\tw.data\" pair ij\nclear\n" + q.r.head(2).split("region box")[0] + "pair_style granular\nread_data \"w\tw.data\"\ngroup lv1 id 1\ngroup lv2 id 2\n" + m.GRAV + q.r.FL() + q.r.TAILL + "run 3000\n", gap=g11)
E("Q03_atomfile_two_spaces_grow_pre_no", 'variable a atomfile "d  d.txt" (lv2 12 mm; "d d.txt" 6 mm); run 1000; set group lv2 diameter v_a; run 3000 pre no',
  'variable a atomfile "d  d.txt"\nrun 1000\nset group lv2 diameter v_a\nrun 3000 pre no\n', gap=g41, sep=0.008,
  data={"d  d.txt": "# d\n1\n2 0.012\n", "d d.txt": "# d\n1\n2 0.006\n"})
E("Q04_atomfile_two_spaces_grow", "Q03 without pre no", 'variable a atomfile "d  d.txt"\nrun 1000\nset group lv2 diameter v_a\nrun 3000\n', gap=g41, sep=0.008,
  data={"d  d.txt": "# d\n1\n2 0.012\n", "d d.txt": "# d\n1\n2 0.006\n"})
E("Q05_file_var_next_two_spaces", 'variable k file "k  k.txt" (2000, 5000); run 1000; next k; pair_coeff 1 2 hooke ${k}; run 3000',
  'variable k file "k  k.txt"\nrun 1000\nnext k\npair_coeff 1 2 hooke ${k} 3000 ' + K + "\nrun 3000\n", gap=g11, data={"k  k.txt": "2000\n5000\n", "k k.txt": "8000\n8000\n"})
E("Q06_include_else_tab_in_loop", 'loop 2: if i == 2 then print else include "k\tk.in" (kn 5000 in pass 1)',
  'variable i loop 2\nlabel l\nif "${i} == 2" then "print two" else "include \'k\tk.in\'"\nrun 500\nnext i\njump SELF l\nrun 3000\n', gap=g11 + 1e-3,
  data={"k\tk.in": p.P5() + "\n", "k k.in": p.P8() + "\n"})
E("Q07_jump_label_two_spaces", 'jump "j  j.in" go (the file: skip, label go, kn 5000, run)', 'jump "j  j.in" go\n', gap=g11,
  data={"j  j.in": "pair_coeff 1 2 " + hk(8000) + "\nlabel go\n" + p.P5() + "\nrun 3000\n", "j j.in": "label go\n" + p.P8() + "\nrun 3000\n"})
E("Q08_read_data_add_pair_coeffs_two_spaces", 'read_data "v  v.data" add append (a far victim; its PairIJ Coeffs 1 2 kn 5000); run 3000',
  'read_data "v  v.data" add append\nrun 3000\n', gap=g11,
  data={"v  v.data": "# victim\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nPairIJ Coeffs # granular\n\n1 1 " + HK + "\n1 2 " + hk(5000) + "\n2 2 " + HK
        + "\n\nAtoms # sphere\n\n1 2 0.006 2500 0.01 0.01 0.012\n",
        "v v.data": "# victim\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nPairIJ Coeffs # granular\n\n1 1 " + HK + "\n1 2 " + hk(8000) + "\n2 2 " + HK
        + "\n\nAtoms # sphere\n\n1 2 0.006 2500 0.01 0.01 0.012\n"})

# ------------------------------------------------------------ F: a modeller's other commands
E("F01_velocity_set_mid_contact", "run 1000 stops mid-contact (0.15 ms in); velocity lv2 set 0 (it stops); run 3000", "run 1150\nvelocity lv2 set 0 0 0 units box\nrun 3000\n", gap=g11 + 0.0e-3)
E("F02_fix_viscous_all", "fix viscous all 0.001 (the drag beside the contact)", "fix visc all viscous 0.001\nrun 3000\n", gap=0.1e-3)
E("F03_freeze_lv2", "fix freeze lv2; lv1 at 1 m/s onto it (the live print: v2 - v1 = -v1 after)", "fix fr lv2 freeze\nvelocity lv1 set 1 0 0 units box\nvelocity lv2 set 0 0 0 units box\nrun 3000\n", gap=0.1e-3)
E("F04_nve_sphere_lv1_only", "integrator on lv1 only (fix integ lv1); lv2 still, no velocity", "unfix integ\nfix integ lv1 nve/sphere\nvelocity lv1 set 1 0 0 units box\nvelocity lv2 set 0 0 0 units box\nrun 3000\n", gap=0.1e-3)
E("F05_newton_off", "newton off", "run 3000\n", gap=0.1e-3, pre=BL().replace("comm_modify vel yes\n", "comm_modify vel yes\nnewton off\n"))
E("F06_limit_damping_heavy", "hooke 2000 damping 6000 with limit_damping (the attraction cut)", "run 3000\n", gap=0.1e-3,
  pre=BL("hooke 2000 6000 damping mass_velocity tangential linear_nohistory 1 0.3 limit_damping"))
E("F07_tsuji_hertz_material", "hertz/material 1e7 e 0.5 damping tsuji", "run 3000\n", gap=0.1e-3,
  pre=BL("hertz/material 1e7 0.5 0.3 damping tsuji tangential linear_nohistory 1 0.3"))
E("F08_coeff_restitution_hooke_limit", "hooke 2000 e 0.5 damping coeff_restitution limit_damping", "run 3000\n", gap=0.1e-3,
  pre=BL("hooke 2000 0.5 damping coeff_restitution tangential linear_nohistory 1 0.3 limit_damping"))
E("F09_replicate_before_pre_no", "run 1000; replicate 1 1 2 (a copy of the pair above); run 3000 pre no", "run 1000\nreplicate 1 1 2\nrun 3000 pre no\n", gap=g11)
E("F10_timestep_in_loop_include", "loop 2 of run 500 with include dt.in (timestep 2e-5 in pass 2); run 400", 'variable i loop 2\nlabel l\nrun 500\nif "${i} == 2" then "include dt.in"\nnext i\njump SELF l\nrun 400\n',
  gap=g11 + 0.0, data={"dt.in": "timestep 2e-5\n"})
E("F11_run_start_stop_timestep_var", "pair_coeff kn from a ramp over run start/stop (v_k = ramp(2000,8000) read at the run's start by $() ? no: by pair_coeff ${k} after run 1000 start 0 stop 4000)",
  "variable k equal ramp(2000,8000)\nrun 1000 start 0 stop 4000\npair_coeff 1 2 hooke ${k} 3000 " + K + "\nrun 3000\n", gap=g11)
W("F12_wall_tsuji_limit", "floor: hertz/material 1e7 e 0.5 damping tsuji limit_damping", "run 4000\n", gap=2.1e-3,
  pre=BL().replace("fix floor all wall/gran granular " + HK, "fix floor all wall/gran granular hertz/material 1e7 0.5 0.3 damping tsuji tangential linear_nohistory 1 0.3 limit_damping"))
E("F13_nve_sphere_twice_subset", "a second nve/sphere on lv2 only (lv2 integrated twice)", "fix integ2 lv2 nve/sphere\nrun 3000\n", gap=0.1e-3)
E("R11_restart_no_comm_vel_after", "R04 (pair across the periodic x boundary) without comm_modify vel yes after read_restart", RS().replace("comm_modify vel yes\n", ""), gap=g11, pair=PER(g11))
E("F14_no_comm_vel", "comm_modify vel yes left out (pair granular needs it)", "run 3000\n", gap=0.1e-3, pre=BL().replace("comm_modify vel yes\n", ""))

# ============================================================ wave 2
# ------------------------------------------------------------ RP: restart round trips with a pair across a periodic boundary (R04's class) and what a restart keeps
E("RP01_periodic_restart_pair_style_regiven", "R04 with pair_style granular and pair_coeff * * given again after read_restart", RS(after="pair_style granular\npair_coeff * * " + HK + "\n"), gap=g11, pair=PER(g11))
E("RP02_periodic_restart_pair_coeff_12_regiven", "R04 with pair_coeff 1 2 (kn 2000) given again after read_restart", RS(after="pair_coeff 1 2 " + HK + "\n"), gap=g11, pair=PER(g11))
E("RP03_periodic_restart_comm_cutoff", "R04 with comm_modify cutoff 0.01 after read_restart", RS(after="comm_modify cutoff 0.01\n"), gap=g11, pair=PER(g11))
E("RP04_periodic_restart_neighbor_big", "R04 with neighbor 0.01 bin after read_restart", RS(after="neighbor 0.01 bin\n"), gap=g11, pair=PER(g11))
E("RP05_periodic_restart_gran_hooke_history", "R04 with pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 0", RS(), gap=g11, pair=PER(g11),
  pre=q.r.head(2) + "pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 0\npair_coeff * *\n" + m.GRAV + "fix floor all wall/gran hooke/history 2000 NULL 3000 NULL 0.3 0 zplane 0 NULL\n" + q.r.TAILL)
PER11 = lambda gap: (f"create_atoms 1 single {0.04 - 0.002 - gap / 2:.9g} 0.02 0.05\ncreate_atoms 1 single {0.002 + gap / 2:.9g} 0.02 0.05\n"
                     "create_atoms 2 single 0.01 0.01 0.012\nset atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.004 density 2500\nset atom 3 diameter 0.006 density 2500\n"
                     "group lv1 id 1\ngroup lv2 id 2\nvelocity lv1 set 0.5 0 0 units box\nvelocity lv2 set -0.5 0 0 units box\n")
E("RP06_periodic_restart_pair11", "R04 with a type 1 1 pair (4 mm each, 1 m/s) across the boundary; a 6 mm type 2 far", RS(), gap=g11, pair=PER11(g11), sep=0.004)
extra("RP06_periodic_restart_pair11", PAIR="types 1 1")
E("RP07_periodic_restart_run0_first", "R04 with run 0 after read_restart, then run 3000", RS().replace("run 3000\n", "run 0\nrun 3000\n"), gap=g11, pair=PER(g11))
E("RP08_periodic_restart_pair_cutoff_kw", "R04 with pair_coeff * * ... cutoff 0.01 (per pair) before the restart", RS(), gap=g11, pair=PER(g11), pre=BL(HK + " cutoff 0.01"))
E("RP09_periodic_restart_hybrid_one", "R04 with pair_style hybrid granular (one instance)", RS(), gap=g11, pair=PER(g11),
  pre=q.r.head(2) + "pair_style hybrid granular\npair_coeff * * granular " + HK + "\n" + m.GRAV + q.r.FL() + q.r.TAILL)
E("RP10_periodic_restart_newton_off", "R04 with newton off (given again after the read)", RS(after="newton off\n"), gap=g11, pair=PER(g11), pre=BL().replace("comm_modify vel yes\n", "comm_modify vel yes\nnewton off\n"))
E("RP11_periodic_pair_made_after_read", "victims only before the restart; the live pair made after read_restart across the boundary; run 3000",
  "run 100\nwrite_restart a.rst\nclear\nread_restart a.rst\ncomm_modify vel yes\n" + PER(0.1e-3).replace("id 1\n", "id 3\n").replace("id 2\n", "id 4\n").replace("set atom 1 ", "set atom 3 ").replace("set atom 2 ", "set atom 4 ")
  + m.GRAV + q.r.FL() + "fix integ all nve/sphere\nrun 3000\n", pair="create_atoms 2 single 0.01 0.01 0.012\ncreate_atoms 2 single 0.03 0.03 0.012\nset type 2 diameter 0.006 density 2500\n", gap=0.1e-3)
E("RP12_periodic_write_read_data_control", "R04 with write_data / clear / read_data (pair style and coefficients given before the read)",
  "run 1000\nwrite_data w.data nocoeff\nclear\n" + q.r.head(2).split("region box")[0] + "pair_style granular\nread_data w.data\npair_coeff * * " + HK + "\ngroup lv1 id 1\ngroup lv2 id 2\n" + m.GRAV + q.r.FL() + q.r.TAILL + "run 3000\n",
  gap=g11, pair=PER(g11))
E("RP13_periodic_restart_pair_inside_too", "R04 with a second type 1 2 pair inside the box meeting too (the live pair is the boundary one)", RS(), gap=g11,
  pair=PER(g11) + "create_atoms 1 single 0.01795 0.02 0.03\ncreate_atoms 2 single 0.02355 0.02 0.03\nset atom 3 diameter 0.004 density 2500\nset atom 4 diameter 0.006 density 2500\n")
RL = lambda model: dict(pre=BL(model), gap=g11)
E("RL01_restart_limit_damping", "hooke 2000 6000 limit_damping; restart; run (is limit_damping kept?)", RS(), **RL("hooke 2000 6000 damping mass_velocity tangential linear_nohistory 1 0.3 limit_damping"))
E("RL02_restart_tsuji_hooke", "hooke 2000 e 0.5 damping tsuji; restart; run", RS(), **RL("hooke 2000 0.5 damping tsuji tangential linear_nohistory 1 0.3"))
E("RL03_restart_coeff_restitution", "hertz/material 1e7 e 0.5 damping coeff_restitution; restart; run", RS(), **RL("hertz/material 1e7 0.5 0.3 damping coeff_restitution tangential linear_nohistory 1 0.3"))
E("RL04_restart_mixed_pair", "pair_coeff 1 1 kn 2000, 2 2 kn 8000 (1 2 mixed); restart; run", RS(), gap=g11,
  pre=q.r.head(2) + "pair_style granular\npair_coeff 1 1 " + HK + "\npair_coeff 2 2 " + hk(8000) + "\n" + m.GRAV + q.r.FL() + q.r.TAILL)
E("RL05_restart_12_explicit_then_22_changed", "pair_coeff * * kn 2000, 1 2 kn 5000; restart; pair_coeff 2 2 kn 8000 after the read (1 2 stays 5000?)", RS(after="pair_coeff 2 2 " + hk(8000) + "\n"), gap=g11,
  pre=BL() .replace("pair_coeff * * " + HK + "\n", "pair_coeff * * " + HK + "\npair_coeff 1 2 " + hk(5000) + "\n"))
E("RL06_restart_11_changed_mixed", "pair_coeff 1 1 kn 2000, 2 2 kn 2000 (1 2 mixed); restart; pair_coeff 1 1 kn 8000 after the read (1 2 mixed again?)", RS(after="pair_coeff 1 1 " + hk(8000) + "\n"), gap=g11,
  pre=q.r.head(2) + "pair_style granular\npair_coeff 1 1 " + HK + "\npair_coeff 2 2 " + HK + "\n" + m.GRAV + q.r.FL() + q.r.TAILL)

# ------------------------------------------------------------ F: integrators and frozen partners by type
E("F15_nve_twice_type_group", "a second nve/sphere on group t2 (type 2)", "group t2 type 2\nfix integ2 t2 nve/sphere\nrun 3000\n", gap=0.1e-3)
E("F16_nve_twice_region_group", "a second nve/sphere on a group by region (lv2's side)", "region rr block 0.021 0.04 0 0.04 0 0.1 units box\ngroup gr region rr\nfix integ2 gr nve/sphere\nrun 3000\n", gap=0.1e-3)
E("F17_nve_type1_only_still_partner", "integrator on type 1 only (group t1 type 1); lv2 still; lv1 at 1 m/s", "group t1 type 1\nunfix integ\nfix integ t1 nve/sphere\nvelocity lv1 set 1 0 0 units box\nvelocity lv2 set 0 0 0 units box\nrun 3000\n", gap=0.1e-3)
E("F18_freeze_type2", "fix freeze on type 2 (group t2); lv1 at 1 m/s onto lv2", "group t2 type 2\nfix fr t2 freeze\nvelocity lv1 set 1 0 0 units box\nvelocity lv2 set 0 0 0 units box\nrun 3000\n", gap=0.1e-3)
E("F19_tsuji_hooke_limit", "hooke 2000 e 0.5 damping tsuji limit_damping", "run 3000\n", gap=0.1e-3, pre=BL("hooke 2000 0.5 damping tsuji tangential linear_nohistory 1 0.3 limit_damping"))
E("F20_nve_twice_type_group_after_run", "run 1000; a second nve/sphere on type 2 (group t2) added; run 3000 (the pair meets in it)", "run 1000\ngroup t2 type 2\nfix integ2 t2 nve/sphere\nrun 3000\n", gap=g11)
E("F21_nve_twice_id_group_after_run", "F20 with the group by id (lv2)", "run 1000\nfix integ2 lv2 nve/sphere\nrun 3000\n", gap=g11)

# ------------------------------------------------------------ A: fix adapt (wave 1's timing mended; dynamic groups)
E("A11_adapt_unfix_readd_same_size_t", "A02 timed: fix adapt lv2 12 mm at run 1000's set-up (1.1 mm apart then); unfix; fix adapt again 12 mm; run 3000",
  DD + "fix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 1000\nunfix ad\nfix ad2 lv2 adapt 1 atom diameter v_dd reset no\nrun 3000\n", gap=g41, sep=0.008)
E("A12_adapt_two_groups_one_shrinks_t", "A03 timed (run 6000)", vic(2, 0.006, 0.006) + "group v id 3\nvariable d1 equal 0.002\n" + DD + "fix a1 lv1 adapt 1 atom diameter v_d1 reset no\nfix a2 v adapt 1 atom diameter v_dd reset no\nrun 6000\n",
  gap=g31, sep=0.004)
E("A13_adapt_unfix_run_readd_pre_no_t", "A09 timed: 12 mm at run 1000's set-up; unfix; run 100; fix adapt again (12 mm); run 3000 pre no",
  DD + "fix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 1000\nunfix ad\nrun 100\nfix ad2 lv2 adapt 1 atom diameter v_dd reset no\nrun 3000 pre no\n", gap=g41 + 0.1e-3, sep=0.008)
E("A14_adapt_dynamic_region_group", "fix adapt 12 mm (constant) on a dynamic group (region x < 0.02485): lv2 enters it 0.9 ms into the run, 3.2 mm from lv1",
  "region rr block 0 0.02485 0 0.04 0 0.1 units box\ngroup dg dynamic all region rr\n" + DD + "fix ad dg adapt 1 atom diameter v_dd reset no\nrun 4000\n", gap=g41, sep=0.008,
  pre=BL().replace("create_box 2 box\n", "create_box 2 box\n"))
E("A15_adapt_dynamic_var_group", "fix adapt 12 mm (constant) on group dynamic lv2 var (time > 0.0009): lv2 joins 0.9 ms into the run",
  "variable in atom time>0.0009\ngroup dg dynamic lv2 var in\n" + DD + "fix ad dg adapt 1 atom diameter v_dd reset no\nrun 4000\n", gap=g41, sep=0.008)
E("A16_adapt_two_fixes_same_group", "fix adapt lv2 12 mm and a second fix adapt lv2 6 mm after it (the second sizes last) from the start", DD + "variable d6 equal 0.006\nfix a1 lv2 adapt 1 atom diameter v_dd reset no\nfix a2 lv2 adapt 1 atom diameter v_d6 reset no\nrun 3000\n",
  gap=g11)
E("A17_adapt_dynamic_group_far", "A14 with lv2 entering the region 2.6 mm further (the pair then 5.8 mm apart: met on time?)",
  "region rr block 0 0.0246 0 0.04 0 0.1 units box\ngroup dg dynamic all region rr\n" + DD + "fix ad dg adapt 1 atom diameter v_dd reset no\nrun 6000\n", gap=g41 + 4e-3, sep=0.008)

# ------------------------------------------------------------ Q: quoted names (wave 1's atomfile mended; more places)
QA = {"d  d.txt": "# d\n1\n2 0.012\n", "d d.txt": "# d\n1\n2 0.006\n"}
E("Q09_atomfile_two_spaces_grow_pre_no_map", 'Q03 with atom_modify map array', 'variable a atomfile "d  d.txt"\nrun 1000\nset group lv2 diameter v_a\nrun 3000 pre no\n', gap=g41, sep=0.008, data=QA, pre=MAP)
E("Q10_atomfile_two_spaces_grow_map", 'Q04 with atom_modify map array', 'variable a atomfile "d  d.txt"\nrun 1000\nset group lv2 diameter v_a\nrun 3000\n', gap=g41, sep=0.008, data=QA, pre=MAP)
E("Q11_restart_tab", 'write_restart "a\ta.rst"; clear; read_restart "a\ta.rst" (kn 5000 before)', RS().replace("a.rst", '"a\ta.rst"').replace("run 1000\n", p.P5() + "\nrun 1000\n"), gap=g11)
E("Q12_include_folder_two_spaces", 'include "sub  dir/k.in" (kn 5000; "sub dir/k.in" kn 8000)', 'include "sub  dir/k.in"\nrun 3000\n', gap=0.1e-3,
  data={"sub  dir/k.in": p.P5() + "\n", "sub dir/k.in": p.P8() + "\n"})
E("Q13_include_hash_in_quotes", 'include "k#1.in" (kn 5000; "k" with kn 8000)', 'include "k#1.in"\nrun 3000\n', gap=0.1e-3, data={"k#1.in": p.P5() + "\n", "k": p.P8() + "\n"})
E("Q14_string_var_two_spaces_quoted", 'variable f string "k  k.in"; include "${f}"', 'variable f string "k  k.in"\ninclude "${f}"\nrun 3000\n', gap=0.1e-3,
  data={"k  k.in": p.P5() + "\n", "k k.in": p.P8() + "\n"})
E("Q15_if_read_restart_two_spaces_after_run", 'write_restart "a  a.rst" (kn 5000); clear; if "1 > 0" then "read_restart \'a  a.rst\'"',
  RS().replace("write_restart a.rst", 'write_restart "a  a.rst"').replace("read_restart a.rst", 'if "1 > 0" then "read_restart \'a  a.rst\'"').replace("run 1000\n", p.P5() + "\nrun 1000\n"), gap=g11)
RD2 = lambda d2, k: ("# the pair\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nPairIJ Coeffs # granular\n\n1 1 " + HK + "\n1 2 " + hk(k) + "\n2 2 " + HK
                     + f"\n\nAtoms # sphere\n\n1 1 0.004 2500 0.01745 0.02 0.05\n2 2 {d2} 2500 {0.02 + d2 / 2 + 0.00055:.9g} 0.02 0.05\n\nVelocities\n\n1 0.7714285714 0 0 0 0 0\n2 -0.2285714286 0 0 0 0 0\n")
E("Q16_read_data_main_two_spaces", 'read_data "d  d.data" (the pair, PairIJ 1 2 kn 5000); "d d.data" beside it (lv2 12 mm, kn 8000)',
  "run 3000\n", pre="units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\npair_style granular\nread_data \"d  d.data\"\n" + m.GRAV + q.r.FL() + q.r.TAILL,
  pair="group lv1 id 1\ngroup lv2 id 2\n", gap=g11, data={"d  d.data": RD2(0.006, 5000), "d d.data": RD2(0.012, 8000)})

# ------------------------------------------------------------ L: LIGGGHTS (more)
LRE3 = (LV + "group v3 id 3\nrun 1000\nvariable xx equal x[2]\nvariable zz equal z[2]\nvariable vz equal vz[2]\nvariable x0 equal ${xx}\nvariable z0 equal ${zz}\nvariable v0 equal ${vz}\n"
        "delete_atoms group lv2\ndelete_atoms group v3\ncreate_atoms 2 single ${x0} 0 ${z0} units box\nset atom 3 diameter 0.012 density 2500\ngroup lvn id 3\nvelocity lvn set -0.2285714286 0 ${v0}\n")
Ld("L09_lig_compress_id_reused_same_size_pre_no", "LIGGGHTS P02: lv2 and the 12 mm victim deleted (compress yes), a new 12 mm takes ID 3 (held 12 mm) at lv2's place; run 3000 pre no",
   LRE3 + "run 3000 pre no\n", gap=g41, sep=0.008)
Ld("L10_lig_compress_id_reused_control", "L09 without pre no", LRE3 + "run 3000\n", gap=g41, sep=0.008)
Ld("L11_lig_nve_twice_lv2", "LIGGGHTS a second nve/sphere on lv2", "fix integr2 lv2 nve/sphere\nrun 3000\n", gap=0.1e-3)
Ld("L12_lig_grow_include_loop_victims_pre_no", "LIGGGHTS victims 12, 6 mm; loop 2 of run 500 with include g.in in pass 2 (lv2 12 mm); run 3000 pre no",
   LV + 'variable i loop 2\nlabel l\nrun 500\nif "${i} == 2" then "include g.in"\nnext i\njump SELF l\nrun 3000 pre no\n', gap=g41, sep=0.008, data={"g.in": "set group lv2 diameter 0.012\n"})
for n in ("L09_lig_compress_id_reused_same_size_pre_no", "L10_lig_compress_id_reused_control"):
    groups(n)

# ------------------------------------------------------------ P: LAMMPS (more)
MOL2 = "# two\n\n2 atoms\n\nCoords\n\n1 0 0 0\n2 0 0.015 -0.03\n\nTypes\n\n1 2\n2 2\n\nDiameters\n\n1 0.012\n2 0.006\n\nMasses\n\n1 0.0022619467\n2 0.00028274334\n"
E("P11_create_molecule_two_atoms_rotate0_pre_no", "P10 mended: the molecule's centre placed so its 12 mm atom sits at lv2's place, rotate 0; run 3000 pre no",
  V26 + "run 1000\n" + PRE + "delete_atoms group lv2 compress no\nmolecule m2 two.mol\ncreate_atoms 0 single ${xx} 0.0275 $(v_zz-0.015) mol m2 4711 rotate 0 1 0 0 units box\ngroup lvn id 5\n"
  "velocity lvn set -0.2285714286 0 ${vz} units box\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=MAP, data={"two.mol": MOL2})
E("P12_create_molecule_two_atoms_rotate0_control", "P11 without pre no",
  V26 + "run 1000\n" + PRE + "delete_atoms group lv2 compress no\nmolecule m2 two.mol\ncreate_atoms 0 single ${xx} 0.0275 $(v_zz-0.015) mol m2 4711 rotate 0 1 0 0 units box\ngroup lvn id 5\n"
  "velocity lvn set -0.2285714286 0 ${vz} units box\nrun 3000\n", gap=g41, sep=0.008, pre=MAP, data={"two.mol": MOL2})
E("P13_new_id_same_size_sort_off_pre_no", "round 31 Y03 (a 6 mm new ID, printed) with atom_modify sort 0 0", X5(CA, d=0.006), gap=g11, pre=MAP.replace("atom_modify map array\n", "atom_modify map array sort 0 0\n"))
E("P14_new_id_same_size_no_victim_deleted_pre_no", "victims 12, 6 mm; the 6 mm victim deleted too (compress no); lv2 made again 6 mm at a new ID; run 3000 pre no",
  X5(CA, d=0.006).replace("delete_atoms group lv2 compress no\n", "delete_atoms group lv2 compress no\ngroup v4 id 4\ndelete_atoms group v4 compress no\n"), gap=g11, pre=MAP)
for n in ("P11_create_molecule_two_atoms_rotate0_pre_no", "P12_create_molecule_two_atoms_rotate0_control"):
    groups(n)

# ============================================================ wave 3
# ------------------------------------------------------------ N: a new sphere (a new ID) of a size its type held, made near the live sphere before pre no (no deletion, nothing moved)
NEWP = ("create_atoms 1 single 0.01795 0.02 0.05\ncreate_atoms 2 single 0.03 0.035 0.05\nset atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\n"
        "group lv1 id 1\nvelocity lv1 set 0.7714285714 0 0 units box\n")
NEWM = lambda d=0.006, run="run 3000 pre no\n", t=2, idn=5: (
    "run 1000\ncreate_atoms %d single $(x[1]+0.002+%g+0.0001) 0.02 $(z[1]) units box\nset atom %d diameter %g density 2500\ngroup lvn id %d\n"
    "velocity lvn set -0.2285714286 0 $(vz[1]) units box\n" % (t, d / 2, idn, d, idn) + run)
E("N01_new_same_size_near_pre_no", "victims 12, 6 mm (type 2), lv2 far; run 1000; a new 6 mm type 2 (ID 5, a size type 2 holds) made 0.1 mm from lv1, moving at it; run 3000 pre no",
  V26 + NEWM(), pair=NEWP, pre=MAP, gap=g11)
E("N02_new_same_size_near_control", "N01 without pre no", V26 + NEWM(run="run 3000\n"), pair=NEWP, pre=MAP, gap=g11)
E("N03_new_same_size_near_no_victims_pre_no", "N01 without victims (type 2: lv2's 6 mm only; the new one ID 3)", NEWM(idn=3), pair=NEWP, pre=MAP, gap=g11)
E("N04_new_smaller_near_pre_no", "N01 with the new sphere 4 mm (smaller than any type 2 held)", V26 + NEWM(d=0.004), pair=NEWP, pre=MAP, gap=g11, sep=0.004)
E("N05_new_type1_near_pre_no", "N01 with the new sphere of type 1, 4 mm (lv1's size; pair 1 1)", V26 + NEWM(d=0.004, t=1), pair=NEWP, pre=MAP, gap=g11, sep=0.004)
extra("N05_new_type1_near_pre_no", PAIR="types 1 1")
for n in ("N01_new_same_size_near_pre_no", "N02_new_same_size_near_control", "N03_new_same_size_near_no_victims_pre_no", "N04_new_smaller_near_pre_no", "N05_new_type1_near_pre_no"):
    groups(n)

E("N06_delete_far_victim_new_same_size_near_pre_no", "N01 with the 12 mm victim (ID 3) deleted first (compress no): the new 6 mm made near lv1 at ID 5",
  V26 + "group v3 id 3\n" + NEWM().replace("run 1000\n", "run 1000\ndelete_atoms group v3 compress no\n"), pair=NEWP, pre=MAP, gap=g11)
E("N07_delete_lv2far_new_same_size_near_pre_no", "N01 with the far 6 mm lv2 (ID 2) deleted first (compress no)",
  V26 + "group far id 2\n" + NEWM().replace("run 1000\n", "run 1000\ndelete_atoms group far compress no\n"), pair=NEWP, pre=MAP, gap=g11)
for n in ("N06_delete_far_victim_new_same_size_near_pre_no", "N07_delete_lv2far_new_same_size_near_pre_no"):
    groups(n)

# ------------------------------------------------------------ I: second integrators and motion fixes on groups the audit cannot type (F13's class)
E("I01_second_nve_all", "a second integrator of another style: fix integ2 all nve", "fix integ2 all nve\nrun 3000\n", gap=0.1e-3)
E("I02_second_nve_lv2", "fix integ2 lv2 nve (by id)", "fix integ2 lv2 nve\nrun 3000\n", gap=0.1e-3)
E("I03_second_nve_limit_lv2", "fix integ2 lv2 nve/limit 1.0 (a cap far above the step's move)", "fix integ2 lv2 nve/limit 1.0\nrun 3000\n", gap=0.1e-3)
E("I04_second_nve_sphere_before_pre_no", "run 1000; fix integ2 lv2 nve/sphere added; run 3000 pre no (is a fix added before pre no set up?)", "run 1000\nfix integ2 lv2 nve/sphere\nrun 3000 pre no\n", gap=g11)
E("I05_move_linear_lv2", "fix move lv2 linear (its approach speed), lv2 integrated by nve/sphere too", "fix mv lv2 move linear -0.2285714286 0 0 units box\nrun 3000\n", gap=0.1e-3)
E("I06_addforce_lv2", "fix addforce lv2 -0.001 0 0 (a push of 1 mN toward lv1)", "fix af lv2 addforce -0.001 0 0\nrun 3000\n", gap=0.1e-3)
E("I07_setforce_lv2_x0", "fix setforce lv2 0.0 NULL NULL (lv2 keeps its x velocity)", "fix sf lv2 setforce 0.0 NULL NULL\nrun 3000\n", gap=0.1e-3)
E("I08_freeze_before_pre_no", "run 1000; fix freeze lv2 added; velocity lv2 0; run 3000 pre no", "run 1000\nfix fr lv2 freeze\nvelocity lv2 set 0 0 0 units box\nrun 3000 pre no\n", gap=g11)
W("I09_wall_added_before_pre_no", "wall live: the floor unfixed before run 1000 and added again before run 3000 pre no (sphere falls onto it in that run)",
  "unfix floor\nrun 1000\nfix floor all wall/gran granular " + HK + " zplane 0 NULL\nrun 4000 pre no\n", gap=2.1e-3 + 1e-3)
E("I10_second_nve_sphere_lv1_only_plus_type2", "control: lv1 by its own nve/sphere (by id), type 2 by another (by type): each sphere integrated once",
  "unfix integ\ngroup t2 type 2\nfix i1 lv1 nve/sphere\nfix i2 t2 nve/sphere\nrun 3000\n", gap=0.1e-3)
Ld("I11_lig_second_nve_all", "LIGGGHTS fix integr2 all nve/sphere (every sphere twice)", "fix integr2 all nve/sphere\nrun 3000\n", gap=0.1e-3)
E("I12_rigid_single_lv2", "fix rg lv2 rigid single (lv2 also under nve/sphere)", "fix rg lv2 rigid single\nrun 3000\n", gap=0.1e-3)

# ------------------------------------------------------------ A: fix adapt whose variable holds step but is constant in the meeting run
E("A18_adapt_step_saturating", "fix adapt lv2 v_dd = 0.006+0.006*(step>=500) (grows mid run 1, far); run 3000 meets at 12 mm (no growth at its set-up)",
  "variable dd equal 0.006+0.006*(step>=500)\nfix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 1000\nrun 3000\n", gap=g41 + 1e-3, sep=0.008)
E("A19_adapt_lv1_grows_lv2_kept", "fix adapt lv1 4 -> 8 mm at run 1000's set-up (far), run 3000 meets (no growth at its set-up)",
  "variable d1 equal 0.008\nfix a1 lv1 adapt 1 atom diameter v_d1 reset no\nrun 1000\nrun 3000\n", gap=g31 + 1e-3, sep=0.007)

# ------------------------------------------------------------ RP: more restart round trips
E("RP14_periodic_restart_pair_coeff_all_regiven", "R04 with pair_coeff * * given again after read_restart (no pair_style)", RS(after="pair_coeff * * " + HK + "\n"), gap=g11, pair=PER(g11))
E("RP15_periodic_restart_by_restart_cmd", "R04 with the file written by restart 1000 r.rst during run 1000 (no write_restart)",
  RS().replace("run 1000\nwrite_restart a.rst\n", "restart 1000 r.rst\nrun 1000\n").replace("read_restart a.rst", "read_restart r.rst"), gap=g11, pair=PER(g11))
E("RP16_inside_restart_by_restart_cmd", "RP15 with the pair inside the box (R01's)", RS().replace("run 1000\nwrite_restart a.rst\n", "restart 1000 r.rst\nrun 1000\n").replace("read_restart a.rst", "read_restart r.rst"), gap=g11)
LPER = lambda gap: (f"create_atoms 1 single {0.05 - 0.002 - gap / 2:.9g} 0 0.1 units box\ncreate_atoms 2 single {-0.05 + 0.003 + gap / 2:.9g} 0 0.1 units box\n"
                    "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
                    "velocity lv1 set 0.7714285714 0 0\nvelocity lv2 set -0.2285714286 0 0\n")
LREST = ("run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst\ncommunicate single vel yes\nneighbor 0.002 bin\nneigh_modify delay 0\n" + m.MAT3 + m.E3
         + "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0\ntimestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 3000\n")
m.L("RP17_lig_periodic_restart", "# LIGGGHTS: the live pair across the periodic x boundary; write_restart, clear, read_restart; run 3000\n"
    + m.lhead(bnd="p f f") + m.MAT3 + m.E3 + m.HERTZ + m.WALL3 + LPER(g11) + "timestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n" + LREST, g=1)
p.LIVE["RP17_lig_periodic_restart"] = "last run"
m.L("RP18_lig_periodic_norestart_control", "# LIGGGHTS: RP17 without the restart (run 4000)\n"
    + m.lhead(bnd="p f f") + m.MAT3 + m.E3 + m.HERTZ + m.WALL3 + LPER(g11) + "timestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 4000\n", g=1)
p.LIVE["RP18_lig_periodic_norestart_control"] = "last run"
E("RP19_periodic_restart_two_stage_files", "R04 as a modeller's two files: in.deck writes the restart and includes stage2.in (clear, read_restart, run)",
  "run 1000\nwrite_restart a.rst\ninclude stage2.in\n", gap=g11, pair=PER(g11),
  data={"stage2.in": "clear\nread_restart a.rst\ncomm_modify vel yes\n" + m.GRAV + q.r.FL() + "fix integ all nve/sphere\nrun 3000\n"})

# ------------------------------------------------------------ Q: more quoted names
E("Q17_read_restart_var_two_spaces", 'variable f string "a  a.rst"; write_restart "${f}"; clear; read_restart "${f}" (kn 5000)',
  'variable f string "a  a.rst"\n' + p.P5() + '\nrun 1000\nwrite_restart "${f}"\nclear\nvariable f string "a  a.rst"\nread_restart "${f}"\ncomm_modify vel yes\n' + m.GRAV + q.r.FL() + "fix integ all nve/sphere\nrun 3000\n", gap=g11)
E("Q18_include_dotdot_path", 'include "sub dir/../k  k.in" (the folder exists; kn 5000)', 'include "sub dir/../k  k.in"\nrun 3000\n', gap=0.1e-3,
  data={"k  k.in": p.P5() + "\n", "k k.in": p.P8() + "\n", "sub dir/x.txt": "x\n"})
E("Q19_file_var_tab", 'variable k file "k\tv.txt" (5000); pair_coeff 1 2 hooke ${k}', 'variable k file "k\tv.txt"\npair_coeff 1 2 hooke ${k} 3000 ' + K + "\nrun 3000\n", gap=0.1e-3,
  data={"k\tv.txt": "5000\n", "k v.txt": "8000\n"})
E("Q20_if_jump_two_spaces", "if \"1 > 0\" then 'jump \"j  j.in\"' (the file: kn 5000, run)", "if \"1 > 0\" then 'jump \"j  j.in\"'\n", gap=0.1e-3,
  data={"j  j.in": p.P5() + "\nrun 3000\n", "j j.in": p.P8() + "\nrun 3000\n"})
E("Q21_write_data_nocoeff_two_spaces", 'write_data "w  w.data" nocoeff; clear; read_data "w  w.data"; pair_coeff * * (kn 2000) and 1 2 kn 5000 after',
  "run 1000\nwrite_data \"w  w.data\" nocoeff\nclear\n" + q.r.head(2).split("region box")[0] + "pair_style granular\nread_data \"w  w.data\"\npair_coeff * * " + HK + "\n" + p.P5()
  + "\ngroup lv1 id 1\ngroup lv2 id 2\n" + m.GRAV + q.r.FL() + q.r.TAILL + "run 3000\n", gap=g11)

# ------------------------------------------------------------ F: units cgs, exclusion by groups changed before pre no
CGS = (m.head(2, box="0 4 0 4 0 10", units="cgs") + "pair_style granular\npair_coeff * * hooke 2e6 3000 " + K + "\nfix grav all gravity 981 vector 0 0 -1\n"
       "fix floor all wall/gran granular hooke 2e6 3000 " + K + " zplane 0 NULL\nfix integ all nve/sphere\ntimestep 1e-6\n")
CGSP = ("create_atoms 1 single 1.795 2 5\ncreate_atoms 2 single 2.305 2 5\nset atom 1 diameter 0.4 density 2.5\nset atom 2 diameter 0.6 density 2.5\n"
        "group lv1 id 1\ngroup lv2 id 2\nvelocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\n")
E("F22_units_cgs", "units cgs, kn 2e6 dyne/cm, 4 and 6 mm (0.4, 0.6 cm), approaching at 1 cm/s from 0.01 cm; run 11000", "run 11000\n", pre=CGS, pair=CGSP, gap=0.1e-3, sep=0.5)
E("F23_exclude_groups_cleared_pre_no", "neigh_modify exclude group lv1 lv2; run 1000; group lv2 clear (the exclusion no longer holds the pair); run 3000 pre no",
  "neigh_modify exclude group lv1 lv2\nrun 1000\ngroup lv2 clear\ngroup lv2 id 2\nrun 3000 pre no\n", gap=g11)
E("F24_exclude_groups_cleared_control", "F23 without pre no", "neigh_modify exclude group lv1 lv2\nrun 1000\ngroup lv2 clear\ngroup lv2 id 2\nrun 3000\n", gap=g11)
E("F25_exclude_groups_joined_pre_no", "neigh_modify exclude group ga gb (ga holds lv1, gb empty); run 1000; group gb id 2 (lv2 joins: now excluded); run 3000 pre no",
  "group ga id 1\ngroup gb empty\nneigh_modify exclude group ga gb\nrun 1000\ngroup gb id 2\nrun 3000 pre no\n", gap=g11)

# ============================================================ wave 4
# ------------------------------------------------------------ PB: the pair across the periodic boundary, a command between runs that reshuffles atoms or ghosts, then pre no (no size changed)
PBV = "create_atoms 2 single 0.01 0.01 0.012\ncreate_atoms 2 single 0.03 0.03 0.012\nset atom 3 diameter 0.006 density 2500\nset atom 4 diameter 0.006 density 2500\ngroup v3 id 3\n"
PB = lambda mid, run="run 3000 pre no\n": dict(lines=PBV + "run 1000\n" + mid + run)
E("PB01_periodic_delete_far_victim_pre_no", "pair across the periodic x boundary; victims 6, 6 mm far; run 1000; delete the victim ID 3 (compress no); run 3000 pre no",
  gap=g11, pair=PER(g11), pre=MAP, **PB("delete_atoms group v3 compress no\n"))
E("PB02_periodic_delete_far_victim_control", "PB01 without pre no", gap=g11, pair=PER(g11), pre=MAP, **PB("delete_atoms group v3 compress no\n", run="run 3000\n"))
E("PB03_periodic_create_far_victim_pre_no", "PB01 with a far 6 mm type 2 made (ID 5) instead of a deletion", gap=g11, pair=PER(g11), pre=MAP,
  **PB("create_atoms 2 single 0.02 0.03 0.012\nset atom 5 diameter 0.006 density 2500\n"))
E("PB04_periodic_write_restart_pre_no", "PB01 with write_restart a.rst (no clear) instead of a deletion", gap=g11, pair=PER(g11), pre=MAP, **PB("write_restart a.rst\n"))
E("PB05_periodic_write_data_pre_no", "PB01 with write_data w.data instead of a deletion", gap=g11, pair=PER(g11), pre=MAP, **PB("write_data w.data\n"))
E("PB06_periodic_displace_zero_pre_no", "PB01 with displace_atoms all move 0 0 0 instead of a deletion", gap=g11, pair=PER(g11), pre=MAP, **PB("displace_atoms all move 0 0 0 units box\n"))
E("PB07_periodic_delete_compress_yes_pre_no", "PB01 with compress yes (the victim ID 4 becomes 3)", gap=g11, pair=PER(g11), pre=MAP, **PB("delete_atoms group v3\n"))
E("PB08_inside_delete_far_victim_pre_no", "PB01 with the pair inside the box", gap=g11, pre=MAP, **PB("delete_atoms group v3 compress no\n"))
E("PB09_periodic_shrink_far_victim_pre_no", "PB01 with the victim shrunk to 4 mm instead (a shrink: audited)", gap=g11, pair=PER(g11), pre=MAP, **PB("set atom 3 diameter 0.004\n"))
E("PB10_periodic_nothing_pre_no", "PB01 with nothing between the runs (control)", gap=g11, pair=PER(g11), pre=MAP, **PB(""))
E("PB11_periodic_delete_overlap_far_pre_no", "PB01 with delete_atoms overlap of a far victim pair (a 6 mm made on the victim ID 4)", gap=g11, pair=PER(g11), pre=MAP,
  **PB("create_atoms 2 single 0.03 0.03 0.012\nset atom 5 diameter 0.006 density 2500\ngroup v5 id 5\ndelete_atoms overlap 0.0001 v5 all compress no\n"))
E("PB12_periodic_delete_far_victim_run0_pre_no", "PB01 with run 0 pre no between (no set-up either)", gap=g11, pair=PER(g11), pre=MAP,
  **PB("delete_atoms group v3 compress no\nrun 0 pre no\n"))
Ld("PB13_lig_periodic_delete_far_victim_pre_no", "LIGGGHTS: the pair across the periodic x boundary; victims far; run 1000; delete a victim; run 3000 pre no", "", gap=g11)
L13 = m.DECKS["PB13_lig_periodic_delete_far_victim_pre_no"]
m.DECKS["PB13_lig_periodic_delete_far_victim_pre_no"] = ("# LIGGGHTS: the pair across the periodic x boundary; victims 6, 6 mm far; run 1000; delete victim ID 3; run 3000 pre no\n"
    + m.lhead(bnd="p f f") + m.MAT3 + m.E3 + m.HERTZ + m.WALL3 + LPER(g11) + "timestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n"
    + "create_atoms 2 single 0.03 0.03 0.02 units box\ncreate_atoms 2 single -0.03 -0.03 0.02 units box\nset atom 3 diameter 0.006 density 2500\nset atom 4 diameter 0.006 density 2500\ngroup v3 id 3\n"
    + "run 1000\ndelete_atoms group v3 compress no\nrun 3000 pre no\n",) + L13[1:]
m.L("RP20_lig_periodic_restart_newton_off", "# LIGGGHTS: RP17 with newton off given again after read_restart\n"
    + m.lhead(bnd="p f f") + m.MAT3 + m.E3 + m.HERTZ + m.WALL3 + LPER(g11) + "timestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n"
    + LREST.replace("communicate single vel yes\n", "newton off\ncommunicate single vel yes\n"), g=1)
p.LIVE["RP20_lig_periodic_restart_newton_off"] = "last run"
E("RP21_periodic_restart_hertz_material", "R04 with hertz/material 1e7 viscoelastic (pair and floor)", RS(), gap=g11, pair=PER(g11), pre=BL(p.q.HM))

# ------------------------------------------------------------ F: a proper referee of fix viscous (run ends just after the contact), 2d, set mass
E("F26_viscous_short_run", "fix viscous all 0.001; the run ends 0.1 ms after the contact (drag outside it small)", "fix visc all viscous 0.001\nrun 800\n", gap=0.1e-3)
D2 = ("units si\ndimension 2\natom_style sphere 1\nboundary p f p\ncomm_modify vel yes\nregion box block 0 0.04 0 0.1 -0.001 0.001 units box\ncreate_box 2 box\n"
      "pair_style granular\npair_coeff * * " + HK + "\nfix grav all gravity 9.81 vector 0 -1 0\nfix floor all wall/gran granular " + HK + " yplane 0 NULL\n"
      "fix e2d all enforce2d\nfix integ all nve/sphere\ntimestep 1e-6\n")
D2P = lambda dens="density 2500", va=0.7714285714, vb=-0.2285714286: (
    f"create_atoms 1 single 0.01795 0.05 0\ncreate_atoms 2 single 0.02305 0.05 0\nset atom 1 diameter 0.004 {dens}\nset atom 2 diameter 0.006 {dens}\n"
    f"group lv1 id 1\ngroup lv2 id 2\nvelocity lv1 set {va} 0 0 units box\nvelocity lv2 set {vb} 0 0 units box\n")
E("F27_2d_density", "dimension 2, set density 2500 (LAMMPS: a sphere's mass in 2d too?)", "run 3000\n", pre=D2, pair=D2P(), gap=0.1e-3)
E("F28_2d_density_disc", "dimension 2, set density/disc 2500 (mass of a disc of unit thickness: r^2); run 30000 (a long contact)", "run 30000\n", pre=D2, pair=D2P("density/disc 2500", 9 / 13, -4 / 13), gap=0.1e-3)
E("F29_set_mass_lv2", "set atom 2 mass 5e-4 after its diameter (heavier than 6 mm at 2500: 2.83e-4)", "set atom 2 mass 5e-4\nvelocity lv1 set 0.8561643836 0 0 units box\nvelocity lv2 set -0.1438356164 0 0 units box\nrun 3000\n", gap=0.1e-3)

# ------------------------------------------------------------ I: SW-I's edges
E("I13_second_nve_group_subtract", "fix integ2 on group g subtract all lv1 (lv2 and a far victim)", vic(2, 0.006, 0.006) + "group g subtract all lv1\nfix integ2 g nve/sphere\nrun 3000\n", gap=0.1e-3)
E("I14_second_nve_lv1", "fix integ2 lv1 nve/sphere (type 1's one sphere, by id)", "fix integ2 lv1 nve/sphere\nrun 3000\n", gap=0.1e-3)
E("I15_integ_split_by_id_groups", "unfix integ; fix i1 lv1 nve/sphere; fix i2 lv2 nve/sphere (each once, by id: control)", "unfix integ\nfix i1 lv1 nve/sphere\nfix i2 lv2 nve/sphere\nrun 3000\n", gap=0.1e-3)

# ============================================================ wave 5: PB06's class (displace_atoms before pre no, a pair across a periodic boundary)
E("PB14_periodic_displace_far_victim_pre_no", "PB06 with displace_atoms v3 move 0.001 0 0 (a far victim only)", gap=g11, pair=PER(g11), pre=MAP, **PB("displace_atoms v3 move 0.001 0 0 units box\n"))
E("PB15_inside_displace_zero_pre_no", "PB06 with the pair inside the box", gap=g11, pre=MAP, **PB("displace_atoms all move 0 0 0 units box\n"))
E("PB16_periodic_displace_lv1_zero_pre_no", "PB06 with displace_atoms lv1 move 0 0 0", gap=g11, pair=PER(g11), pre=MAP, **PB("displace_atoms lv1 move 0 0 0 units box\n"))
E("PB17_periodic_change_box_same_pre_no", "PB06 with change_box all x final 0 0.04 units box (the box as it was)", gap=g11, pair=PER(g11), pre=MAP, **PB("change_box all x final 0 0.04 units box\n"))
E("PB18_periodic_set_x_far_victim_pre_no", "PB06 with set atom 3 x 0.015 (a far victim moved by set)", gap=g11, pair=PER(g11), pre=MAP, **PB("set atom 3 x 0.015\n"))
E("PB19_periodic_displace_zero_control", "PB06 without pre no", gap=g11, pair=PER(g11), pre=MAP, **PB("displace_atoms all move 0 0 0 units box\n", run="run 3000\n"))
E("PB20_periodic_displace_no_victims_pre_no", "PB06 without victims", "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 3000 pre no\n", gap=g11, pair=PER(g11))
E("PB21_periodic_displace_in_include_pre_no", "PB06 with the displace_atoms in an include", gap=g11, pair=PER(g11), pre=MAP, **PB("include d.in\n"), data={"d.in": "displace_atoms all move 0 0 0 units box\n"})
E("PB22_periodic_displace_random_zero_pre_no", "PB06 with displace_atoms all random 0 0 0 4711", gap=g11, pair=PER(g11), pre=MAP, **PB("displace_atoms all random 0 0 0 4711 units box\n"))
E("PB23_periodic_change_box_remap_pre_no", "PB06 with change_box all x final 0 0.04 remap units box", gap=g11, pair=PER(g11), pre=MAP, **PB("change_box all x final 0 0.04 remap units box\n"))
E("PB24_periodic_balance_pre_no", "PB06 with balance 1.0 x uniform (one processor)", gap=g11, pair=PER(g11), pre=MAP, **PB("balance 1.0 x uniform\n"))
Ld("PB25_lig_periodic_displace_zero_pre_no", "LIGGGHTS PB06 (periodic x, displace_atoms all move 0 0 0, pre no)", "", gap=g11)
m.DECKS["PB25_lig_periodic_displace_zero_pre_no"] = (m.DECKS["PB13_lig_periodic_delete_far_victim_pre_no"][0].replace("delete_atoms group v3 compress no\n", "displace_atoms all move 0 0 0 units box\n")
    .replace("delete victim ID 3", "displace_atoms all move 0 0 0"),) + m.DECKS["PB25_lig_periodic_displace_zero_pre_no"][1:]
E("PB26_periodic_y_displace_zero_pre_no", "PB06 with the box periodic in x only (f p f)? no: p f f and the pair across x", gap=g11, pair=PER(g11), pre=MAP.replace("boundary p p f", "boundary p f f"),
  **PB("displace_atoms all move 0 0 0 units box\n"))

# ============================================================ wave 6
E("PB27_inside_reset_atoms_id_sort_pre_no", "the pair inside the box, victims; run 1000; reset_atoms id sort yes; run 3000 pre no", gap=g11, pre=MAP, **PB("reset_atoms id sort yes\n"))
E("PB28_periodic_reset_atoms_id_pre_no", "PB06 with reset_atoms id instead", gap=g11, pair=PER(g11), pre=MAP, **PB("reset_atoms id\n"))
E("PB29_periodic_reset_timestep_pre_no", "PB06 with reset_timestep 0 instead", gap=g11, pair=PER(g11), pre=MAP, **PB("reset_timestep 0\n"))
E("PB30_periodic_change_box_boundary_same_pre_no", "PB06 with change_box all boundary p p f (as it was) instead", gap=g11, pair=PER(g11), pre=MAP, **PB("change_box all boundary p p f\n"))
RDV = ("# a far victim\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 2 0.006 2500 0.02 0.03 0.012\n")
E("PB31_periodic_read_data_add_pre_no", "PB06 with read_data v.data add append (a far victim) instead", gap=g11, pair=PER(g11), pre=MAP, data={"v.data": RDV}, **PB("read_data v.data add append\n"))
E("PB32_inside_reset_atoms_id_sort_victims_between", "PB27 with the victims between lv1 and lv2 in ID order (lv1 ID 1, victims 2 3, lv2 ID 4)", "run 1000\nreset_atoms id sort yes\nrun 3000 pre no\n", gap=g11, pre=MAP,
  pair=q.r.lvi(g11, ids=(1, 4)).replace("create_atoms 2 single", "create_atoms 2 single 0.01 0.01 0.012\ncreate_atoms 2 single 0.03 0.03 0.012\ncreate_atoms 2 single", 1)
  .replace("set atom 1 diameter", "set atom 2 diameter 0.006 density 2500\nset atom 3 diameter 0.006 density 2500\nset atom 1 diameter"))
E("PB33_periodic_displace_zero_then_run0", "PB06 with run 0 (a set-up) after the displace: control", gap=g11, pair=PER(g11), pre=MAP, **PB("displace_atoms all move 0 0 0 units box\nrun 0\n"))
E("PB34_periodic_displace_hertz_material_pre_no", "PB06 with hertz/material 1e7 viscoelastic", gap=g11, pair=PER(g11), pre=BL(p.q.HM).replace("atom_style sphere 1\n", "atom_style sphere 1\natom_modify map array\n"),
  **PB("displace_atoms all move 0 0 0 units box\n"))

# ------------------------------------------------------------ PX: fixes replaced before pre no; omp styles; walls with keywords
E("PX01_unfix_refix_integ_pre_no", "run 1000; unfix integ; fix integ all nve/sphere (the same again); run 3000 pre no", "run 1000\nunfix integ\nfix integ all nve/sphere\nrun 3000 pre no\n", gap=g11)
E("PX02_timestep_before_pre_no", "run 1000; timestep 2e-6; run 1500 pre no (met at dt 2e-6)", "run 1000\ntimestep 2e-6\nrun 1500 pre no\n", gap=g11)
E("PX03_suffix_omp_gran_hooke_history", "package omp 1, suffix omp, pair_style gran/hooke/history (no restart)", "run 3000\n", gap=0.1e-3,
  pre=q.r.head(2).replace("units si\n", "units si\npackage omp 1\nsuffix omp\n") + "pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 0\npair_coeff * *\n" + m.GRAV
  + "fix floor all wall/gran hooke/history 2000 NULL 3000 NULL 0.3 0 zplane 0 NULL\n" + q.r.TAILL)
E("PX04_explicit_gran_hooke_history_omp", "pair_style gran/hooke/history/omp named", "run 3000\n", gap=0.1e-3,
  pre=q.r.head(2) + "pair_style gran/hooke/history/omp 2000 NULL 3000 NULL 0.3 0\npair_coeff * *\n" + m.GRAV
  + "fix floor all wall/gran hooke/history 2000 NULL 3000 NULL 0.3 0 zplane 0 NULL\n" + q.r.TAILL)
E("PX05_unfix_grav_pre_no", "run 1000; unfix grav; run 3000 pre no (the pair far above the floor)", "run 1000\nunfix grav\nrun 3000 pre no\n", gap=g11)
W("PX06_wall_coeff_restitution_hooke", "floor: hooke 2000 e 0.5 damping coeff_restitution", "run 4000\n", gap=2.1e-3,
  pre=BL().replace("fix floor all wall/gran granular " + HK, "fix floor all wall/gran granular hooke 2000 0.5 damping coeff_restitution tangential linear_nohistory 1 0.3"))
W("PX07_wall_hertz_material_limit", "floor: hertz/material 1e7 viscoelastic with limit_damping", "run 4000\n", gap=2.1e-3,
  pre=BL().replace("fix floor all wall/gran granular " + HK, "fix floor all wall/gran granular hertz/material 1e7 1.4e7 0.3 damping viscoelastic tangential linear_nohistory 1 0.3 limit_damping"))
W("PX08_wall_restart_periodic_box", "wall live after write_restart / clear / read_restart (no list for walls)", "run 500\nwrite_restart a.rst\nclear\nread_restart a.rst\ncomm_modify vel yes\n" + m.GRAV + q.r.FL() + "fix integ all nve/sphere\nrun 4000\n", gap=2.1e-3)

# ============================================================ wave 7
MIC = ("units micro\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nregion box block 0 40000 0 40000 0 100000 units box\ncreate_box 2 box\n"
       "pair_style granular\npair_coeff * * hooke 2e6 0.003 " + K + "\nfix grav all gravity 9.81e-6 vector 0 0 -1\n"
       "fix floor all wall/gran granular hooke 2e6 0.003 " + K + " zplane 0 NULL\nfix integ all nve/sphere\ntimestep 1\n")
MICP = ("create_atoms 1 single 17950 20000 50000\ncreate_atoms 2 single 23050 20000 50000\nset atom 1 diameter 4000 density 2.5\nset atom 2 diameter 6000 density 2.5\n"
        "group lv1 id 1\ngroup lv2 id 2\nvelocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\n")
E("F30_units_micro", "units micro (um, us, pg): kn 2e6 (2000 N/m), gamma 0.003 per us, 4000 and 6000 um at 2.5 pg/um3, 1 um/us, dt 1 us", "run 3000\n", pre=MIC, pair=MICP, gap=0.1e-3, sep=5000)
E("F31_units_lj", "units lj with the si deck's numbers (kn 2000, gamma 3000, 0.004/0.006, density 2500, dt 1e-6, 1 sigma/tau)", "run 3000\n", pre=BL().replace("units si", "units lj"), gap=0.1e-3)
E("RP22_periodic_restart_nsq", "R04 with neighbor 0.001 nsq after read_restart", RS(after="neighbor 0.001 nsq\n"), gap=g11, pair=PER(g11))
E("RP23_periodic_restart_first_run_pre_no", "R04 with run 3000 pre no as the first run after the read (LAMMPS sets it up anyway)", RS().replace("run 3000\n", "run 3000 pre no\n"), gap=g11, pair=PER(g11))
E("RP24_periodic_restart_pair_style_regiven_later", "R04 with run 100 after the read, then pair_style granular and pair_coeff * * again, run 3000 (the pair meets in the last)",
  RS().replace("run 3000\n", "run 100\npair_style granular\npair_coeff * * " + HK + "\nrun 3000\n"), gap=g11 + 0.1e-3, pair=PER(g11 + 0.1e-3))
E("PB35_periodic_displace_lv2_small_pre_no", "PB20 with displace_atoms lv2 move -0.0001 0 0 (toward lv1 across the boundary)", "run 1000\ndisplace_atoms lv2 move -0.0001 0 0 units box\nrun 3000 pre no\n",
  gap=g11 + 0.1e-3, pair=PER(g11 + 0.1e-3))
E("PB36_periodic_displace_then_run_pre_no_twice", "PB20 with run 100 pre no after the displace, the pair meeting in the run 3000 pre no after it",
  "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 100 pre no\nrun 3000 pre no\n", gap=g11 + 0.1e-3, pair=PER(g11 + 0.1e-3))
POURL = ("region ins block 0.005 0.035 0.005 0.035 0.07 0.095 units box\nfix p all pour 2 2 4767 region ins diam one 0.012 dens 2500 2500\n")
E("P15_pour_loop_pre_no", "a pour of 12 mm type 2 running through a loop of run 500 pre no (after a first run 500); lv2 6 mm meets lv1 in the third pass, parts in the fourth",
  POURL + 'run 500\nvariable i loop 4\nlabel l\nrun 500 pre no\nnext i\njump SELF l\n', gap=g11 + 0.5e-3, live="last run")
Ld("LQ01_lig_include_tab", "LIGGGHTS include \"k\tk.in\" (e 1 2 0.9; \"k k.in\" 0.2)", 'include "k\tk.in"\nrun 3000\n', gap=0.1e-3,
   data={"k\tk.in": p.E3x(0.9) + "\n", "k k.in": p.E3x(0.2) + "\n"})
Ld("LQ02_lig_variable_file_two_spaces", "LIGGGHTS variable e file \"e  e.txt\" (0.9); the e 1 2 entry ${e}", 'variable e file "e  e.txt"\n' + p.E3x("${e}") + "\nrun 3000\n", gap=0.1e-3,
   data={"e  e.txt": "0.9\n", "e e.txt": "0.2\n"})
Ld("LQ03_lig_read_restart_two_spaces", "LIGGGHTS write_restart \"a  a.rst\", clear, read_restart \"a  a.rst\" (inside the box; newton off again)", "", gap=g11)
m.DECKS["LQ03_lig_read_restart_two_spaces"] = ("# LIGGGHTS: write_restart \"a  a.rst\"; clear; read_restart \"a  a.rst\"; the pair inside the box\n" + m.DECKS["LQ03_lig_read_restart_two_spaces"][0].split("\n", 1)[1]
    + LREST.replace("a.rst", '"a  a.rst"').replace("communicate single vel yes\n", "newton off\ncommunicate single vel yes\n"),) + m.DECKS["LQ03_lig_read_restart_two_spaces"][1:]

# ============================================================ wave 8: LIGGGHTS ghost velocities
LPB = lambda comm="communicate single vel yes\n", bnd="p f f", extra_="": ("# LIGGGHTS: the pair across the periodic x boundary; " + ("no communicate line" if not comm else comm.strip()) + "\n"
    + m.lhead(bnd=bnd).replace("communicate single vel yes\n", comm) + extra_ + m.MAT3 + m.E3 + m.HERTZ + m.WALL3 + LPER(g11)
    + "timestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 3000\n")
m.L("LX01_lig_periodic_no_comm_vel", LPB(comm=""), g=1); p.LIVE["LX01_lig_periodic_no_comm_vel"] = "last run"
m.L("LX02_lig_periodic_comm_vel_no", LPB(comm="communicate single vel no\n"), g=1); p.LIVE["LX02_lig_periodic_comm_vel_no"] = "last run"
m.L("LX03_lig_periodic_comm_vel_yes_control", LPB(), g=1); p.LIVE["LX03_lig_periodic_comm_vel_yes_control"] = "last run"
Ld("LX04_lig_inside_no_comm_vel", "LIGGGHTS the pair inside the box, no communicate line", "run 3000\n", gap=0.1e-3, head_=m.LB().replace("communicate single vel yes\n", ""))
m.L("LX05_lig_periodic_hooke_no_comm_vel", LPB(comm="").replace(m.HERTZ, m.HOOKE).replace("model hertz tangential history primitive", "model hooke tangential history primitive"), g=1)
p.LIVE["LX05_lig_periodic_hooke_no_comm_vel"] = "last run"

# ============================================================ wave 9: a new sphere made across the periodic boundary from lv1 before pre no
NEWPB = ("create_atoms 1 single 0.03745 0.02 0.05\ncreate_atoms 2 single 0.02 0.035 0.05\nset atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\n"
         "group lv1 id 1\nvelocity lv1 set 0.7714285714 0 0 units box\n")
NEWMB = lambda run="run 3000 pre no\n", idn=3, how=None: (
    "run 1000\n" + (how or "create_atoms 2 single $(x[1]+0.005+0.0001-0.04) 0.02 $(z[1]) units box\nset atom %d diameter 0.006 density 2500\n" % idn)
    + "group lvn id %d\nvelocity lvn set -0.2285714286 0 $(vz[1]) units box\n" % idn + run)
E("N08_new_across_boundary_pre_no", "lv1 near the upper x face; run 1000; a new 6 mm type 2 (ID 3; type 2 holds 6 mm) made across the periodic x boundary 0.1 mm from it; run 3000 pre no",
  NEWMB(), pair=NEWPB, pre=MAP, gap=g11)
E("N09_new_across_boundary_control", "N08 without pre no", NEWMB(run="run 3000\n"), pair=NEWPB, pre=MAP, gap=g11)
E("N10_new_across_boundary_victims_pre_no", "N08 with victims 12, 6 mm of type 2 (new ID 5)", V26.replace("atom 3", "atom 3").replace("atom 4", "atom 4") + NEWMB(idn=5).replace("set atom 5", "set atom 5"),
  pair=NEWPB, pre=MAP, gap=g11)
RDB1 = ("# one sphere across the boundary\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 2 0.006 2500 0.00355 0.02 0.049995095\n\n"
        "Velocities\n\n1 -0.2285714286 0 -0.00981 0 0 0\n")
E("N11_read_data_add_across_boundary_pre_no", "N08 with the new sphere by read_data n.data add append (ID 3)", "run 1000\nread_data n.data add append\ngroup lvn id 3\nrun 3000 pre no\n",
  pair=NEWPB, pre=MAP, gap=g11, data={"n.data": RDB1})
E("N12_move_across_boundary_pre_no", "N08 with lv2 (far, 6 mm) moved across the boundary by set atom 2 x y z and given its velocity (no new atom)", NEWMB(idn=2, how="set atom 2 x $(x[1]+0.005+0.0001-0.04) y 0.02 z $(z[1])\n"),
  pair=NEWPB, pre=MAP, gap=g11)
Ld("N13_lig_new_across_boundary_pre_no", "LIGGGHTS N08 (p f f; a new 6 mm type 2 made across the boundary; run 3000 pre no)", "", gap=g11)
m.DECKS["N13_lig_new_across_boundary_pre_no"] = ("# LIGGGHTS: lv1 near the upper x face; run 1000; a new 6 mm type 2 made across the periodic x boundary 0.1 mm from it; run 3000 pre no\n"
    + m.lhead(bnd="p f f") + m.MAT3 + m.E3 + m.HERTZ + m.WALL3
    + "create_atoms 1 single 0.04745 0 0.1 units box\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 0.7714285714 0 0\n"
    + "timestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 1000\nvariable xa equal x[1]\nvariable za equal z[1]\nvariable va equal vz[1]\n"
    + "variable xb equal ${xa}+0.0051-0.1\nvariable zb equal ${za}\nvariable vb equal ${va}\ncreate_atoms 2 single ${xb} 0 ${zb} units box\nset atom 2 diameter 0.006 density 2500\ngroup lvn id 2\n"
    + "velocity lvn set -0.2285714286 0 ${vb}\nrun 3000 pre no\n",) + m.DECKS["N13_lig_new_across_boundary_pre_no"][1:]
for n in ("N08_new_across_boundary_pre_no", "N09_new_across_boundary_control", "N10_new_across_boundary_victims_pre_no", "N11_read_data_add_across_boundary_pre_no", "N12_move_across_boundary_pre_no",
          "N13_lig_new_across_boundary_pre_no"):
    groups(n)
groups("N12_move_across_boundary_pre_no", "lv1", "lvn")

# ============================================================ wave 10: SW-P inside run ... every (LAMMPS sets up only the first part)
E("PB37_periodic_every_balance", "the pair across the periodic x boundary; run 3000 every 1000 \"balance 1.0 x uniform\" (meets in part 2)", 'run 3000 every 1000 "balance 1.0 x uniform"\n',
  gap=g11, pair=PER(g11), live="part 2")
E("PB38_periodic_every_print_control", "PB37 with print instead of balance", 'run 3000 every 1000 "print hi"\n', gap=g11, pair=PER(g11), live="part 2")
E("PB39_periodic_every_displace_zero", "PB37 with displace_atoms all move 0 0 0 units box", 'run 3000 every 1000 "displace_atoms all move 0 0 0 units box"\n', gap=g11, pair=PER(g11), live="part 2")
E("PB40_periodic_loop_balance_pre_no", "the pair across the boundary; run 500; loop 4 of balance 1.0 x uniform and run 500 pre no (meets in pass 2)",
  'run 500\nvariable i loop 4\nlabel l\nbalance 1.0 x uniform\nrun 500 pre no\nnext i\njump SELF l\n', gap=g11 + 0.5e-3, pair=PER(g11 + 0.5e-3))
E("PB41_periodic_every_change_box_same", "PB37 with change_box all x final 0 0.04 units box", 'run 3000 every 1000 "change_box all x final 0 0.04 units box"\n', gap=g11, pair=PER(g11), live="part 2")

E("I16_move_linear_type2_group", "fix move on group t2 (type 2) at lv2's approach speed, lv2 integrated by nve/sphere too", "group t2 type 2\nfix mv t2 move linear -0.2285714286 0 0 units box\nrun 3000\n", gap=0.1e-3)
E("I17_move_linear_type2_not_integrated", "fix move on group t2 (type 2), nve/sphere on type 1 only (a driven partner, the modeller's way)",
  "group t1 type 1\ngroup t2 type 2\nunfix integ\nfix integ t1 nve/sphere\nfix mv t2 move linear -0.2285714286 0 0 units box\nrun 3000\n", gap=0.1e-3)
E("I18_move_linear_lv2_not_integrated", "I17 with the groups by id (fix integ lv1, fix move lv2)",
  "unfix integ\nfix integ lv1 nve/sphere\nfix mv lv2 move linear -0.2285714286 0 0 units box\nrun 3000\n", gap=0.1e-3)

# ============================================================ wave 11: fixes that act on the motion, by id (the hedges), short runs
E("H01_spring_self_lv2", "fix spring/self lv2 10 (a tether on lv2); the run ends 0.2 ms after the contact", "fix ss lv2 spring/self 10\nrun 900\n", gap=0.1e-3)
E("H02_temp_rescale_all", "fix temp/rescale 1 on all (T 1e15 to 1e15 window 1e14: rescales each step the velocities)", "compute tt all temp\nfix tr all temp/rescale 1 5e17 5e17 1e17 1.0\nrun 900\n", gap=0.1e-3)
E("H03_aveforce_lv2_zero", "fix aveforce lv2 0 0 0 on a one-atom group (the force set to its own average: no change)", "fix af lv2 aveforce 0.0 0.0 0.0\nrun 900\n", gap=0.1e-3)
E("H04_viscous_lv2_short", "fix viscous lv2 0.001 (by id); the run ends 0.2 ms after the contact", "fix visc lv2 viscous 0.001\nrun 900\n", gap=0.1e-3)
E("H05_lineforce_lv2_x", "fix lineforce lv2 1 0 0 (the force along the line of centres kept)", "fix lf lv2 lineforce 1 0 0\nrun 900\n", gap=0.1e-3)
E("H06_nve_noforce_lv2", "fix nve/noforce on lv2 beside the nve/sphere on all (positions stepped twice, velocities once)", "fix nf lv2 nve/noforce\nrun 900\n", gap=0.1e-3)
E("H07_momentum_all", "fix momentum 1 linear 1 1 1 on all (the pair's momentum is zero: no change)", "fix mo all momentum 1 linear 1 1 1\nrun 900\n", gap=0.1e-3)
E("H08_langevin_zero_lv2", "fix langevin lv2 0 0 0.001 4711 (a drag of damp 1 ms, no noise at T 0)", "fix lg lv2 langevin 0.0 0.0 0.001 4711\nrun 900\n", gap=0.1e-3)

# ============================================================ wave 12: atom_style sphere 0 (radii fixed in a run), growth between full set-ups
S0 = lambda: BL().replace("atom_style sphere 1\n", "atom_style sphere 0\n")
E("S01_sphere0_grow_24mm_between_runs", "atom_style sphere 0; run 1000; set group lv2 diameter 0.024; run 3000 (a full set-up)", "run 1000\nset group lv2 diameter 0.024\nrun 3000\n", gap=g11 + 9e-3, sep=0.014, pre=S0())
E("S02_sphere1_grow_24mm_control", "S01 with atom_style sphere 1", "run 1000\nset group lv2 diameter 0.024\nrun 3000\n", gap=g11 + 9e-3, sep=0.014)
E("S03_sphere0_grow_12mm_between_runs", "atom_style sphere 0; run 1000; set group lv2 diameter 0.012; run 3000", "run 1000\nset group lv2 diameter 0.012\nrun 3000\n", gap=g41, sep=0.008, pre=S0())
E("S04_sphere0_new_big_atom_between_runs", "atom_style sphere 0; run 1000; lv2 deleted, a 24 mm type 2 made in its place (new ID); run 3000",
  "run 1000\nvariable xx equal $(x[2])\nvariable zz equal $(z[2])\nvariable vz equal $(vz[2])\ndelete_atoms group lv2\ncreate_atoms 2 single $(v_xx+0.009) 0.02 ${zz} units box\n"
  "set atom 2 diameter 0.024 density 2500\ngroup lv2 id 2\nvelocity lv2 set -0.2285714286 0 ${vz} units box\nrun 3000\n", gap=g11, sep=0.014, pre=S0().replace("atom_style sphere 0\n", "atom_style sphere 0\natom_modify map array\n"))
E("S05_sphere0_fix_adapt", "atom_style sphere 0 with fix adapt of lv2's diameter (LAMMPS may refuse)", DD + "fix ad lv2 adapt 1 atom diameter v_dd reset no\nrun 4000\n", gap=g31 + 2e-3, sep=0.008, pre=S0())

# ============================================================ wave 13: SW-R in the box: after read_restart LAMMPS bins by the box's x extent with a stencil of
# one bin, so a pair meeting along z across a bin face (z = 0.0333 in a 0.04 x 0.04 x 0.1 box) is not in the lists
VZ = lambda gap, zc=0.1 / 3, x=0.02: (f"create_atoms 1 single {x} 0.02 {zc - 0.002 - gap / 2:.9g}\ncreate_atoms 2 single {x} 0.02 {zc + 0.003 + gap / 2:.9g}\n"
                                      "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
                                      "velocity lv1 set 0 0 0.7714285714 units box\nvelocity lv2 set 0 0 -0.2285714286 units box\n")
E("RZ01_restart_vertical_pair_across_bin_face", "the live pair along z meeting at z = 0.0333 (inside the p p f box); write_restart, clear, read_restart; run 3000", RS(), gap=g11, pair=VZ(g11))
E("RZ02_vertical_pair_no_restart_control", "RZ01 without the restart (run 4000)", "run 4000\n", gap=g11, pair=VZ(g11))
E("RZ03_restart_vertical_pair_mid_bin", "RZ01 with the pair meeting at z = 0.05 (the middle of a bin after the read)", RS(), gap=g11, pair=VZ(g11, zc=0.05))
E("RZ04_restart_vertical_pair_fff", "RZ01 in an f f f box", RS(), gap=g11, pair=VZ(g11), pre=p.FFF(BL()))
E("RZ05_restart_vertical_pair_pair_style_regiven", "RZ01 with pair_style granular and pair_coeff * * given again after the read", RS(after="pair_style granular\npair_coeff * * " + HK + "\n"), gap=g11, pair=VZ(g11))
E("RZ06_restart_vertical_pair_hertz_material", "RZ01 with hertz/material viscoelastic", RS(), gap=g11, pair=VZ(g11), pre=BL(p.q.HM))
E("RZ07_restart_fall_on_resting_sphere", "a 6 mm sphere resting on a 6 mm sphere's top? no: lv1 (4 mm) falls at 1 m/s onto lv2 (6 mm) held by fix freeze? no: both free, lv2 below at rest; restart; run",
  RS(), gap=g11, pair=VZ(g11).replace("velocity lv1 set 0 0 0.7714285714", "velocity lv1 set 0 0 1.0").replace("velocity lv2 set 0 0 -0.2285714286", "velocity lv2 set 0 0 0"))
del m.DECKS["RZ07_restart_fall_on_resting_sphere"]
for n in ("RZ01_restart_vertical_pair_across_bin_face", "RZ02_vertical_pair_no_restart_control", "RZ03_restart_vertical_pair_mid_bin", "RZ04_restart_vertical_pair_fff",
          "RZ05_restart_vertical_pair_pair_style_regiven", "RZ06_restart_vertical_pair_hertz_material"):
    extra(n, AXIS="z")

E("RZ07_restart_vertical_pair_mid_fff", "RZ03 (meeting at z = 0.05) in an f f f box", RS(), gap=g11, pair=VZ(g11, zc=0.05), pre=p.FFF(BL()))
E("RZ08_restart_vertical_pair_mid_hertz_material", "RZ03 with hertz/material viscoelastic", RS(), gap=g11, pair=VZ(g11, zc=0.05), pre=BL(p.q.HM))
E("RZ09_restart_vertical_pair_mid_pair_style_regiven", "RZ03 with pair_style granular and pair_coeff * * given again after the read", RS(after="pair_style granular\npair_coeff * * " + HK + "\n"),
  gap=g11, pair=VZ(g11, zc=0.05))
E("RZ10_restart_vertical_pair_mid_z0455", "RZ03 with the pair meeting at z = 0.0455 (both centres below 0.05)", RS(), gap=g11, pair=VZ(g11, zc=0.0455))
YB = lambda: BL().replace("region box block 0 0.04 0 0.04 0 0.1", "region box block 0 0.04 0 0.1 0 0.1")
VY = lambda gap, yc=0.05: (f"create_atoms 1 single 0.02 {yc - 0.002 - gap / 2:.9g} 0.05\ncreate_atoms 2 single 0.02 {yc + 0.003 + gap / 2:.9g} 0.05\n"
                           "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
                           "velocity lv1 set 0 0.7714285714 0 units box\nvelocity lv2 set 0 -0.2285714286 0 units box\n")
E("RZ11_restart_y_pair_mid_box", "a 0.04 x 0.1 x 0.1 box; the live pair along y meeting at y = 0.05; restart; run 3000", RS(), gap=g11, pair=VY(g11), pre=YB())
E("RZ12_y_pair_mid_box_control", "RZ11 without the restart", "run 4000\n", gap=g11, pair=VY(g11), pre=YB())
for n in ("RZ07_restart_vertical_pair_mid_fff", "RZ08_restart_vertical_pair_mid_hertz_material", "RZ09_restart_vertical_pair_mid_pair_style_regiven", "RZ10_restart_vertical_pair_mid_z0455"):
    extra(n, AXIS="z")
for n in ("RZ11_restart_y_pair_mid_box", "RZ12_y_pair_mid_box_control"):
    extra(n, AXIS="y")

GHH = (q.r.head(2) + "pair_style gran/hooke/history 2000 NULL 3000 NULL 0.3 0\npair_coeff * *\n" + m.GRAV
       + "fix floor all wall/gran hooke/history 2000 NULL 3000 NULL 0.3 0 zplane 0 NULL\n" + q.r.TAILL)
E("RZ13_restart_vertical_pair_mid_gran_hooke_history", "RZ03 with pair_style gran/hooke/history", RS(), gap=g11, pair=VZ(g11, zc=0.05), pre=GHH)
extra("RZ13_restart_vertical_pair_mid_gran_hooke_history", AXIS="z")
LVZ = lambda gap, zc=0.07: (f"create_atoms 1 single 0 0 {zc - 0.002 - gap / 2:.9g} units box\ncreate_atoms 2 single 0 0 {zc + 0.003 + gap / 2:.9g} units box\n"
                            "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
                            "velocity lv1 set 0 0 0.7714285714\nvelocity lv2 set 0 0 -0.2285714286\n")
for zc, tag in ((0.07, "mid"), (0.0455, "low")):
    nm = f"RZ{14 if tag == 'mid' else 15}_lig_restart_vertical_pair_{tag}"
    m.L(nm, f"# LIGGGHTS: the live pair along z meeting at z = {zc} inside the f f f box; write_restart, clear, read_restart (newton off again); run 3000\n"
        + m.lhead() + m.MAT3 + m.E3 + m.HERTZ + m.WALL3 + LVZ(g11, zc) + "timestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n"
        + LREST.replace("communicate single vel yes\n", "newton off\ncommunicate single vel yes\n"), g=1)
    p.LIVE[nm] = "last run"
    extra(nm, AXIS="z")

# ============================================================ wave 14: run_style respa, comm_style tiled
E("F32_run_style_respa", "run_style respa 2 2 (pair at the outer level, nve/sphere)", "run_style respa 2 2\nrun 3000\n", gap=0.1e-3)
E("F33_comm_tiled_periodic_pair", "comm_style tiled; the pair across the periodic x boundary; run 4000", "run 4000\n", gap=g11, pair=PER(g11), pre=BL().replace("comm_modify vel yes\n", "comm_style tiled\ncomm_modify vel yes\n"))
E("F34_comm_tiled_periodic_displace_pre_no", "F33 with displace_atoms all move 0 0 0 and run 3000 pre no after run 1000", "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 3000 pre no\n", gap=g11, pair=PER(g11),
  pre=BL().replace("comm_modify vel yes\n", "comm_style tiled\ncomm_modify vel yes\n"))

# ============================================================ wave 15: LAMMPS walls that move (wiggle, shear) and a moving region wall
FLW = lambda kw: BL().replace("fix floor all wall/gran granular " + HK + " zplane 0 NULL", "fix floor all wall/gran granular " + HK + " zplane 0 NULL " + kw)
W("W01_wall_wiggle_z", "floor wiggle z 0.0002 0.002 (amplitude 0.2 mm, period 2 ms: the floor accelerates under the sphere)", "run 4000\n", gap=2.1e-3, pre=FLW("wiggle z 0.0002 0.002"))
W("W02_wall_shear_x", "floor shear x 0.5 (the floor slides; head-on normal contact)", "run 4000\n", gap=2.1e-3, pre=FLW("shear x 0.5"))
W("W03_wall_region_move", "a wall/gran/region block whose region moves up at 0.1 m/s (region move v_)",
  "variable zz equal 0.1*time\nregion up block INF INF INF INF -0.01 0 move NULL NULL v_zz units box\nfix rw all wall/gran/region granular " + HK + " region up\nrun 4000\n",
  gap=2.1e-3, pre=BL().replace("fix floor all wall/gran granular " + HK + " zplane 0 NULL\n", ""))

E("RZ16_restart_binsize_user_x_pair", "R01's pair along x inside the box (p p f); neigh_modify binsize 0.004 after read_restart (bins narrower than the pair)",
  RS(after="neigh_modify binsize 0.004\n"), gap=g11)
E("RZ17_binsize_user_x_pair_control", "RZ16 without the restart (neigh_modify binsize 0.004, run 4000)", "neigh_modify binsize 0.004\nrun 4000\n", gap=g11)

# ============================================================ wave 17: ghost velocities switched off before pre no
E("PC01_periodic_comm_vel_no_pre_no", "the pair across the periodic x boundary; run 1000; comm_modify vel no; run 3000 pre no (no set-up: LAMMPS' check not made)",
  "run 1000\ncomm_modify vel no\nrun 3000 pre no\n", gap=g11, pair=PER(g11))
E("PC02_periodic_comm_vel_no_control", "PC01 without pre no (LAMMPS stops: granular needs ghost velocities)", "run 1000\ncomm_modify vel no\nrun 3000\n", gap=g11, pair=PER(g11))
E("PC03_inside_comm_vel_no_pre_no", "PC01 with the pair inside the box", "run 1000\ncomm_modify vel no\nrun 3000 pre no\n", gap=g11)

E("PC04_adapt_dynamic_group_before_pre_no", "run 1000; a dynamic group and a fix adapt on it (LAMMPS refuses that at a set-up); run 3000 pre no",
  "run 1000\nregion rr block 0 0.04 0 0.04 0 0.1 units box\ngroup dg dynamic all region rr\n" + DD + "fix ad dg adapt 1 atom diameter v_dd reset no\nrun 3000 pre no\n", gap=g11)
E("PC05_inside_comm_vel_no_pre_no_far", "PC03 with the pair 2 mm apart (met in the pre-no run at 2 ms)", "run 1000\ncomm_modify vel no\nrun 3000 pre no\n", gap=g11 + 1e-3)


def write_all(names):
    m.write_live(names, p.LIVE, p.EXTRA)


if __name__ == "__main__":
    write_all(sys.argv[1:] or list(m.DECKS))
    print(len(m.DECKS), "decks")

"""Field round 33 (spot check of main's answers to round 32's SW-R, SW-P, SW-I): write decks/NAME/in.deck with round
32's helpers (make_decks32.py: kn 2000, dt 1e-6, the live pair 4 mm type 1 / 6 mm type 2 meeting at 1 m/s in the last
run), refereed by live33.py (the deck run as written). Prefixes: R restart edges (read in an include, an if, twice,
omp, hybrid, nsq, a cutoff given after, pair_style given again before pre no); G ghost atoms made anew (replicate,
change_box boundary, run every ... pre no, set x, LIGGGHTS change_box); M moving fixes beside an untyped group (retype,
group type logic, brownian, nve/limit, rigid); C a global cutoff changed before pre no; Q file names (above the
folder, absolute with spaces, sub dir/..); O ordinary modeller decks.
usage: python make_decks33.py [NAME ...]"""
import os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field32"))
import make_decks32 as p32  # noqa: E402

p = p32.p
m, q = p.m, p.q
m.DECKS.clear(); p.LIVE.clear(); p.EXTRA.clear()
m.D = os.path.join(HERE, "decks")
E, Ld, extra, BL, HK, hk, K = p.E, p.Ld, p.extra, p.BL, p.HK, p.hk, p.K
g11, g31, g41 = p.g11, p.g31, p.g41
RS, PER, VZ, GCUT, PB, MAP = p32.RS, p32.PER, p32.VZ, p32.GCUT, p32.PB, p32.MAP
FL, GRAV = q.r.FL(), m.GRAV
FIX = GRAV + FL + "fix integ all nve/sphere\n"
READ = "clear\nread_restart a.rst\ncomm_modify vel yes\n"
FFF = p.FFF


def z(n):
    extra(n, AXIS="z")


# ============================================================ R: restart edges (pair across the periodic x boundary: PER; along z across a bin face: VZ zc 0.05)
E("R01_restart_read_in_include", "R04 (round 32) with clear + read_restart in an include", "run 1000\nwrite_restart a.rst\ninclude r.in\n" + FIX + "run 3000\n",
  gap=g11, pair=PER(g11), data={"r.in": READ})
E("R02_restart_read_in_if", "R04 with clear + read_restart in an if's commands", 'run 1000\nwrite_restart a.rst\nif "1 > 0" then "clear" "read_restart a.rst" "comm_modify vel yes"\n' + FIX + "run 3000\n",
  gap=g11, pair=PER(g11))
E("R03_restart_twice_second_bare", "restart; pair_style granular + pair_coeff given again; run 500; write_restart b.rst; clear; read_restart b.rst (not given again); run 3000",
  "run 500\nwrite_restart a.rst\n" + READ + "pair_style granular\npair_coeff * * " + HK + "\n" + FIX + "run 500\nwrite_restart b.rst\nclear\nread_restart b.rst\ncomm_modify vel yes\n" + FIX + "run 3000\n",
  gap=g11, pair=PER(g11))
E("R04_restart_twice_first_bare_second_given", "R03 reversed: first read bare, second read with pair_style given again (right)",
  "run 500\nwrite_restart a.rst\n" + READ + FIX + "run 500\nwrite_restart b.rst\nclear\nread_restart b.rst\ncomm_modify vel yes\npair_style granular\npair_coeff * * " + HK + "\n" + FIX + "run 3000\n",
  gap=g11, pair=PER(g11))
E("R05_restart_hybrid_single", "pair_style hybrid granular (one sub-style); restart; run", RS(), gap=g11, pair=PER(g11),
  pre=q.r.head(2) + "pair_style hybrid granular\npair_coeff * * granular " + HK + "\n" + FIX + "timestep 1e-6\n")
E("R06_restart_granular_omp_explicit", "package omp 1; pair_style granular/omp; restart; run", RS(), gap=g11, pair=PER(g11),
  pre=BL().replace("units si\n", "package omp 1\nunits si\n").replace("pair_style granular\n", "pair_style granular/omp\n"))
E("R07_restart_suffix_omp", "package omp 1; suffix omp; pair_style granular; restart; run", RS(), gap=g11, pair=PER(g11),
  pre=BL().replace("units si\n", "package omp 1\nsuffix omp\nunits si\n"))
E("R08_restart_other_style_then_back", "restart; pair_style gran/hooke 2000 NULL 3000 NULL 0.3 0 given, then pair_style granular and pair_coeff * * back; run",
  RS(after="pair_style gran/hooke 2000 NULL 3000 NULL 0.3 0\npair_coeff * *\npair_style granular\npair_coeff * * " + HK + "\n"), gap=g11, pair=PER(g11))
E("R09_restart_read_data_add_after", "restart; read_data add append of a far sphere; run", RS(after="read_data far.data add append\n"), gap=g11, pair=PER(g11),
  data={"far.data": "# far\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 2 0.006 2500 0.02 0.03 0.012\n"})
E("R10_restart_nsq_before_write_fff", "f f f box, vertical pair across z = 0.05; neighbor 0.001 nsq BEFORE write_restart (a restart stores no neighbor settings); restart; run",
  RS(before="neighbor 0.001 nsq\n"), gap=g11, pair=VZ(g11, zc=0.05), pre=FFF(BL()))
z("R10_restart_nsq_before_write_fff")
E("R11_restart_nsq_after_read_fff", "f f f box, vertical pair across z = 0.05; neighbor 0.001 nsq after the read (the rule's exception)",
  RS(after="neighbor 0.001 nsq\n"), gap=g11, pair=VZ(g11, zc=0.05), pre=FFF(BL()))
z("R11_restart_nsq_after_read_fff")
E("R12_restart_multi_after_read_fff", "R11 with neighbor 0.001 multi", RS(after="neighbor 0.001 multi\n"), gap=g11, pair=VZ(g11, zc=0.05), pre=FFF(BL()))
z("R12_restart_multi_after_read_fff")
E("R13_restart_run_then_style_pre_no", "restart; run 500 (set up with no cutoff); pair_style granular given again; run 3000 pre no (LAMMPS keeps the set-up's lists)",
  "run 500\nwrite_restart a.rst\n" + READ + FIX + "run 500\npair_style granular\npair_coeff * * " + HK + "\nrun 3000 pre no\n", gap=g11, pair=PER(g11))
E("R14_restart_run_then_style_pre_no_vertical", "R13 with the vertical pair across z = 0.05 (inside the p p f box)",
  "run 500\nwrite_restart a.rst\n" + READ + FIX + "run 500\npair_style granular\npair_coeff * * " + HK + "\nrun 3000 pre no\n", gap=g11, pair=VZ(g11, zc=0.05))
z("R14_restart_run_then_style_pre_no_vertical")
E("R15_restart_like_cutoff_after_read", "restart; pair_coeff 1 1 ... cutoff 0.01 given after the read (the live pair 1 2 across the boundary)",
  RS(after="pair_coeff 1 1 " + HK + " cutoff 0.01\n"), gap=g11, pair=PER(g11))
E("R16_restart_all_cutoff_after_read", "restart; pair_coeff * * ... cutoff 0.01 given after the read", RS(after="pair_coeff * * " + HK + " cutoff 0.01\n"), gap=g11, pair=PER(g11))
E("R17_restart_pair_made_after_read_style_given", "restart; pair_style given again; then the live pair made (right)",
  "run 1000\nwrite_restart a.rst\n" + READ + "pair_style granular\npair_coeff * * " + HK + "\n" + FIX + PER(g11).replace("group lv1 id 1", "group lv1 id 3").replace("group lv2 id 2", "group lv2 id 4")
  .replace("set atom 1 ", "set atom 3 ").replace("set atom 2 ", "set atom 4 ") + "run 4000\n",
  gap=g11, pair="create_atoms 2 single 0.01 0.01 0.012\ncreate_atoms 2 single 0.03 0.03 0.012\nset atom 1 diameter 0.006 density 2500\nset atom 2 diameter 0.006 density 2500\n")
E("R18_restart_delete_far_then_run", "restart; delete_atoms of a far victim after the read; run (rule fires)", RS(after="group v3 id 3\ndelete_atoms group v3\n"), gap=g11,
  pair=PER(g11) + "create_atoms 2 single 0.01 0.01 0.012\nset atom 3 diameter 0.006 density 2500\n")
E("R19_restart_in_loop", "a loop of 2 passes: run 500, write_restart, clear, read_restart, fixes; then run 3000 (bare read before the meeting run)",
  'variable i loop 2\nlabel l\nrun 500\nwrite_restart a.rst\nclear\nread_restart a.rst\ncomm_modify vel yes\n' + FIX + "next i\njump SELF l\nrun 3000\n",
  gap=g11, pair=PER(g11))
E("R20_restart_hertz_material_vertical_ffn_nsq", "R11 (f f f, nsq after the read) with hertz/material", RS(after="neighbor 0.001 nsq\n"), gap=g11, pair=VZ(g11, zc=0.05), pre=FFF(BL(p.q.HM)))
z("R20_restart_hertz_material_vertical_ffn_nsq")

# ============================================================ G: ghost atoms made anew before pre no (pair across the periodic x boundary)
E("G01_replicate_111_pre_no", "run 1000; replicate 1 1 1; run 3000 pre no", "run 1000\nreplicate 1 1 1\nrun 3000 pre no\n", gap=g11, pair=PER(g11))
E("G02_replicate_111_inside_pre_no", "G01 with the pair inside the box", "run 1000\nreplicate 1 1 1\nrun 3000 pre no\n", gap=g11)
PERF = PER(g11)
E("G03_fff_to_periodic_change_box_pre_no", "f f f box, the pair 1.1 mm apart across x = 0.04 (each inside); run 1000; change_box all boundary p f f; run 3000 pre no",
  "run 1000\nchange_box all boundary p f f\nrun 3000 pre no\n", gap=g11, pair=PERF, pre=FFF(BL()))
E("G04_fff_to_periodic_change_box_control", "G03 without pre no", "run 1000\nchange_box all boundary p f f\nrun 3000\n", gap=g11, pair=PERF, pre=FFF(BL()))
E("G05_every_displace_pre_no", "run 4000 every 1000 \"displace_atoms all move 0 0 0 units box\" pre no (parts after the first not set up); pair meets in part 2",
  'run 4000 pre no every 1000 "displace_atoms all move 0 0 0 units box"\n', gap=g11, pair=PER(g11))
E("G06_every_displace_pre_no_part3", "G05 meeting in part 3 (gap 2.1 mm)", 'run 4000 pre no every 1000 "displace_atoms all move 0 0 0 units box"\n', gap=2.1e-3, pair=PER(2.1e-3))
E("G07_every_balance_pre_no", "run 4000 every 1000 \"balance 1.0 x uniform\" pre no; meets in part 2", 'run 4000 pre no every 1000 "balance 1.0 x uniform"\n', gap=g11, pair=PER(g11))
E("G08_set_x_lv1_pre_no", "run 1000; set atom 1 x at its own position (no re-ghosting?); run 3000 pre no", "run 1000\nset atom 1 x $(x[1])\nrun 3000 pre no\n", gap=g11, pair=PER(g11), pre=MAP)
E("G09_set_x_lv1_wrap_pre_no", "run 1000; set atom 1 x moved 0.1 mm toward the boundary; run 3000 pre no",
  "run 1000\nset atom 1 x $(x[1]+0.0001)\nrun 3000 pre no\n", gap=g11 + 0.1e-3, pair=PER(g11 + 0.1e-3), pre=MAP)
E("G10_displace_then_run0_pre_no_then_pre_no", "run 1000; displace_atoms 0; run 0 pre no; run 3000 pre no", "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 0 pre no\nrun 3000 pre no\n", gap=g11, pair=PER(g11))
E("G11_comm_modify_cutoff_pre_no", "run 1000; comm_modify cutoff 0.02; run 3000 pre no (not a re-ghosting)", "run 1000\ncomm_modify cutoff 0.02\nrun 3000 pre no\n", gap=g11, pair=PER(g11))
E("G12_delete_atoms_far_compress_pre_no", "victims; run 1000; delete_atoms of a far victim; run 3000 pre no (round 32: right)", "group v3 id 3\nrun 1000\ndelete_atoms group v3\nrun 3000 pre no\n",
  gap=g11, pair=PER(g11) + "create_atoms 2 single 0.01 0.01 0.012\nset atom 3 diameter 0.006 density 2500\n")
E("G13_change_box_in_include_if_pre_no", "run 1000; if then include holding change_box all x final 0 0.04; run 3000 pre no",
  'run 1000\nif "1 > 0" then "include cb.in"\nrun 3000 pre no\n', gap=g11, pair=PER(g11), data={"cb.in": "change_box all x final 0 0.04 units box\n"})
p.LIVE["G05_every_displace_pre_no"] = "part 2"
p.LIVE["G06_every_displace_pre_no_part3"] = "part 3"
p.LIVE["G07_every_balance_pre_no"] = "part 2"
LPB = p32.LPB
m.L("G14_lig_change_box_pre_no", LPB().replace("run 3000\n", "run 1000\nchange_box all x final -0.05 0.05 units box\nrun 3000 pre no\n"), g=1)
p.LIVE["G14_lig_change_box_pre_no"] = "last run"
m.L("G15_lig_displace_pre_no", LPB().replace("run 3000\n", "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 3000 pre no\n"), g=1)
p.LIVE["G15_lig_displace_pre_no"] = "last run"

# ============================================================ M: moving fixes beside a group the audit may type wrongly
B3 = BL(nt=3)
E("M01_group_type3_retyped_lv2_integ2", "3 types; lv2 made type 3, group g type 3, set atom 2 type 2; fix i2 g nve/sphere (g holds lv2 of type 2)",
  "group g type 3\nset atom 2 type 2\nfix i2 g nve/sphere\nrun 3000\n", gap=0.1e-3, pre=B3, pair=p.lv(0.1e-3, 1, 3))
E("M02_group_type_ge2_integ2", "fix i2 g nve/sphere on group g type >= 2 (lv2)", "group g type >= 2\nfix i2 g nve/sphere\nrun 3000\n", gap=0.1e-3)
E("M03_group_type_ne1_integ2", "group g type != 1", "group g type != 1\nfix i2 g nve/sphere\nrun 3000\n", gap=0.1e-3)
E("M04_group_type_range_integ2", "group g type 2:3 (3 types)", "group g type 2:3\nfix i2 g nve/sphere\nrun 3000\n", gap=0.1e-3, pre=B3)
E("M05_group_type_between_integ2", "group g type <> 2 3 (3 types)", "group g type <> 2 3\nfix i2 g nve/sphere\nrun 3000\n", gap=0.1e-3, pre=B3)
E("M06_brownian_sphere_lv2", "fix brownian/sphere on lv2 (T 1e-20, gamma_t 1) beside nve/sphere on all", "fix br lv2 brownian/sphere 1e-20 4711 gamma_t 1 gamma_r 1\nrun 3000\n", gap=0.1e-3)
E("M07_brownian_sphere_type2", "fix brownian/sphere on group t2 (type 2) beside nve/sphere on all", "group t2 type 2\nfix br t2 brownian/sphere 1e-20 4711 gamma_t 1 gamma_r 1\nrun 3000\n", gap=0.1e-3)
E("M09_nve_limit_lv2", "fix nve/limit on lv2 beside nve/sphere on all (round 32 I03: a note)", "fix lim lv2 nve/limit 0.01\nrun 3000\n", gap=0.1e-3)
E("M10_group_type1_append_lv2_integ2", "group g type 1; group g id 2 (appends lv2); fix i2 g nve/sphere (both stepped twice)", "group g type 1\ngroup g id 2\nfix i2 g nve/sphere\nrun 3000\n", gap=0.1e-3)
E("M11_group_type3_empty_then_retype", "3 types; group g type 3 (none); set atom 2 type 3 later; fix i2 g nve/sphere: g holds nothing (right: printed as the law)",
  "group g type 3\nset atom 2 type 3\nfix i2 g nve/sphere\nrun 3000\n", gap=0.1e-3, pre=B3)
extra("M11_group_type3_empty_then_retype", PAIR="types 1 3")
E("M12_lid_region_move_mobile_subtract", "modeller: a lid of two type-2 spheres by region moved by fix move; the rest integrated by group mobile subtract all lid",
  "region top block INF INF INF INF 0.08 0.1 units box\ngroup lid region top\ngroup mobile subtract all lid\nunfix integ\nfix integ mobile nve/sphere\nfix mv lid move linear 0 0 -0.01 units box\nrun 3000\n",
  gap=0.1e-3, pair=p.lv(0.1e-3) + "create_atoms 2 single 0.01 0.01 0.09\ncreate_atoms 2 single 0.03 0.03 0.09\nset atom 3 diameter 0.006 density 2500\nset atom 4 diameter 0.006 density 2500\n")
E("M13_dynamic_group_integ2", "fix i2 on a dynamic group (region around the pair) beside nve/sphere on all", "region mid block INF INF INF INF 0.04 0.06 units box\ngroup dg dynamic all region mid\nfix i2 dg nve/sphere\nrun 3000\n", gap=0.1e-3)
E("M14_group_retype_after_type_group_lig", "group g type 2 holds lv2; set atom 2 type 3; 1 3 as 1 2; fix i2 g nve/sphere (g still holds lv2, now type 3)",
  "group g type 2\nset atom 2 type 3\nfix i2 g nve/sphere\nrun 3000\n", gap=0.1e-3, pre=B3)
extra("M14_group_retype_after_type_group_lig", PAIR="types 1 3")

# ============================================================ C: a global cutoff given again before pre no (pair inside the box, meets 0.1 ms into the last run)
PSG = lambda c: f"pair_style granular {c}\n".replace("granular \n", "granular\n")
E("C01_global_cutoff_small_to_big_pre_no", "pair_style granular 0.001; run 1000; pair_style granular 0.02; run 3000 pre no", "run 1000\n" + PSG(0.02) + "run 3000 pre no\n", gap=g11, pre=GCUT(0.001))
E("C02_global_cutoff_small_to_big_control", "C01 without pre no", "run 1000\n" + PSG(0.02) + "run 3000\n", gap=g11, pre=GCUT(0.001))
E("C03_global_cutoff_none_to_small_pre_no", "pair_style granular; run 1000; pair_style granular 0.001; run 3000 pre no", "run 1000\n" + PSG(0.001) + "run 3000 pre no\n", gap=g11)
E("C04_global_cutoff_small_to_none_pre_no", "pair_style granular 0.001; run 1000; pair_style granular; run 3000 pre no", "run 1000\n" + PSG("") + "run 3000 pre no\n", gap=g11, pre=GCUT(0.001))
E("C05_global_cutoff_small_to_big_coeff_regiven_pre_no", "C01 with pair_coeff * * given again after the new pair_style", "run 1000\n" + PSG(0.02) + "pair_coeff * * " + HK + "\nrun 3000 pre no\n", gap=g11, pre=GCUT(0.001))
E("C06_global_cutoff_small_to_big_periodic_pre_no", "C01 with the pair across the periodic boundary", "run 1000\n" + PSG(0.02) + "run 3000 pre no\n", gap=g11, pre=GCUT(0.001), pair=PER(g11))

# ============================================================ Q: file names
E("Q01_include_above_two_spaces", 'include "../q01  m.in" (pair_coeff 1 2 kn 5000, a file above the deck folder)', 'include "../q01  m.in"\nrun 3000\n', gap=0.1e-3,
  data={"../q01  m.in": p.P5() + "\n", "../q01 m.in": q.P8() + "\n"})
E("Q02_include_subdir_dotdot", 'include "sub dir/../k  k.in"', 'include "sub dir/../k  k.in"\nrun 3000\n', gap=0.1e-3,
  data={"k  k.in": p.P5() + "\n", "k k.in": q.P8() + "\n", "sub dir/x.txt": "x\n"})
E("Q03_restart_above_two_spaces", 'write_restart "../q03  r.rst"; clear; read_restart "../q03  r.rst"; pair_style given again',
  'run 1000\nwrite_restart "../q03  r.rst"\nclear\nread_restart "../q03  r.rst"\ncomm_modify vel yes\npair_style granular\npair_coeff * * ' + HK + "\n" + p.P5() + "\n" + FIX + "run 3000\n", gap=g11)
E("Q04_write_data_abs_space_read_back", 'write_data "/tmp/f33 q04/d  d.data" nocoeff between runs (pair_coeff 1 2 kn 5000 after)',
  'run 1000\nwrite_data "/tmp/f33 q04/d  d.data" nocoeff\n' + p.P5() + "\nrun 3000\n", gap=g11)
E("Q05_variable_file_above_tab", 'variable k file "../q05\tk.txt" (5000); pair_coeff 1 2 hooke ${k}', 'variable k file "../q05\tk.txt"\npair_coeff 1 2 hooke ${k} 3000 ' + K + "\nrun 3000\n", gap=0.1e-3,
  data={"../q05\tk.txt": "5000\n", "../q05 k.txt": "8000\n"})

# ============================================================ O: ordinary modeller decks
POUR = ("region ins block 0.005 0.035 0.005 0.035 0.005 0.03 units box\nfix p all pour 6 2 4767 region ins diam one 0.006 dens 2500 2500\n")
E("O01_pour_settle_collide", "a pour of 6 type-2 spheres low in the box; run 1000; unfix pour; run 3000 (the pair meets)", POUR + "run 1000\nunfix p\nrun 3000\n", gap=g11)
E("O02_continuation_restart_periodic", "a continuation deck: restart, pair_style granular and pair_coeff * * given again, fixes, run (pair across the periodic boundary)",
  RS(after="pair_style granular\npair_coeff * * " + HK + "\n"), gap=g11, pair=PER(g11))
E("O03_continuation_restart_vertical", "O02 with the vertical pair across z = 0.05", RS(after="pair_style granular\npair_coeff * * " + HK + "\n"), gap=g11, pair=VZ(g11, zc=0.05))
z("O03_continuation_restart_vertical")
E("O04_thermo_dump_neighbor", "neighbor 0.002 bin, neigh_modify delay 0, thermo, dump; run 1000; run 3000", "neighbor 0.002 bin\nneigh_modify delay 0 every 1 check yes\nthermo 500\nrun 1000\nrun 3000\n", gap=g11)
E("O05_displace_before_first_run", "displace_atoms all move 0 0 0 before the first run; run 1000; run 3000 pre no (no re-ghosting since the set-up)",
  "displace_atoms all move 0 0 0 units box\nrun 1000\nrun 3000 pre no\n", gap=g11, pair=PER(g11))
E("O06_balance_before_first_run_periodic", "balance 1.0 x uniform before the first run; run 4000", "balance 1.0 x uniform\nrun 4000\n", gap=g11, pair=PER(g11))
E("O07_loop_runs_pre_no_post_no", "a loop of 4 x run 1000 pre no post no after a first run 100 (pair across the periodic boundary)",
  'run 100\nvariable i loop 4\nlabel l\nrun 1000 pre no post no\nnext i\njump SELF l\n', gap=1.6e-3, pair=PER(1.6e-3))
E("O08_freeze_region_base", "a base of two type-2 spheres frozen by a region group; run 4000", "region low block INF INF INF INF 0 0.01 units box\ngroup base region low\nfix fz base freeze\nrun 4000\n",
  gap=g11, pair=p.lv(g11) + "create_atoms 2 single 0.01 0.01 0.003\ncreate_atoms 2 single 0.03 0.03 0.003\nset atom 3 diameter 0.006 density 2500\nset atom 4 diameter 0.006 density 2500\n")
E("O09_mobile_subtract_one_integrator", "the integrator on group mobile (subtract all base) only, base frozen? no: base not integrated (held still); run 4000",
  "region low block INF INF INF INF 0 0.01 units box\ngroup base region low\ngroup mobile subtract all base\nunfix integ\nfix integ mobile nve/sphere\nrun 4000\n",
  gap=g11, pair=p.lv(g11) + "create_atoms 2 single 0.01 0.01 0.003\ncreate_atoms 2 single 0.03 0.03 0.003\nset atom 3 diameter 0.006 density 2500\nset atom 4 diameter 0.006 density 2500\n")
E("O10_change_box_z_before_first_run", "change_box all z final 0 0.2 before the first run; run 4000 (periodic x, y)", "change_box all z final 0 0.2 units box\nrun 4000\n", gap=g11, pair=PER(g11))
E("O11_restart_continuation_pre_no_after_full", "restart, pair_style given again, run 1000 (set up), run 3000 pre no (the pair meets there, across the boundary)",
  "run 500\nwrite_restart a.rst\n" + READ + "pair_style granular\npair_coeff * * " + HK + "\n" + FIX + "run 500\nrun 3000 pre no\n", gap=g11, pair=PER(g11))
E("O12_two_integrators_typed", "fix integ t1 nve/sphere (type 1) and fix integ2 t2 nve/sphere (type 2): each sphere once", "group t1 type 1\ngroup t2 type 2\nunfix integ\nfix i1 t1 nve/sphere\nfix i2 t2 nve/sphere\nrun 3000\n", gap=0.1e-3)
Ld("O13_lig_pour_like_collide", "LIGGGHTS: neighbor, thermo; run 1000; run 3000", "thermo 500\nrun 1000\nrun 3000\n", gap=g11)

# ============================================================ wave 2
E("G16_inside_displace_pre_no", "run 1000; displace_atoms all move 0 0 0; run 3000 pre no; the pair inside the p p f box (round 32 PB15: LAMMPS on time)",
  "run 1000\ndisplace_atoms all move 0 0 0 units box\nrun 3000 pre no\n", gap=g11)
E("G17_write_restart_no_clear_pre_no", "run 1000; write_restart a.rst (no clear); run 3000 pre no; the pair across the periodic boundary (round 32 PB04: right)",
  "run 1000\nwrite_restart a.rst\nrun 3000 pre no\n", gap=g11, pair=PER(g11))
E("R21_restart_style_given_in_include", "restart; pair_style granular and pair_coeff * * given again in an include", RS(after="include ps.in\n"), gap=g11, pair=PER(g11),
  data={"ps.in": "pair_style granular\npair_coeff * * " + HK + "\n"})
E("R22_restart_style_given_in_if", "restart; pair_style granular given again in an if", RS(after='if "1 > 0" then "pair_style granular" "pair_coeff * * ' + HK + '"\n'), gap=g11, pair=PER(g11))
E("R23_restart_style_given_in_if_else_not_taken", "restart; pair_style granular given in an if whose test fails (LAMMPS keeps the read's style)",
  RS(after='if "1 < 0" then "pair_style granular" "pair_coeff * * ' + HK + '"\n'), gap=g11, pair=PER(g11))

# ============================================================ wave 3
E("C07_global_cutoff_big_to_small_no_pre_no", "pair_style granular 0.02; run 1000; pair_style granular 0.001 (no pre no: LAMMPS sets it up)", "run 1000\n" + PSG(0.001) + "run 3000\n", gap=g11, pre=GCUT(0.02))
E("C08_global_cutoff_none_to_small_no_pre_no", "pair_style granular; run 1000; pair_style granular 0.001; run 3000", "run 1000\n" + PSG(0.001) + "run 3000\n", gap=g11)
E("G18_every_change_box_pre_no", "run 4000 pre no every 1000 \"change_box all x final 0 0.04 units box\"; meets in part 2", 'run 4000 pre no every 1000 "change_box all x final 0 0.04 units box"\n', gap=g11, pair=PER(g11))
E("G19_balance_in_include_pre_no", "run 1000; include holding balance 1.0 x uniform; run 3000 pre no", "run 1000\ninclude b.in\nrun 3000 pre no\n", gap=g11, pair=PER(g11), data={"b.in": "balance 1.0 x uniform\n"})
E("G20_balance_in_if_pre_no", "run 1000; if then balance 1.0 x uniform; run 3000 pre no", 'run 1000\nif "1 > 0" then "balance 1.0 x uniform"\nrun 3000 pre no\n', gap=g11, pair=PER(g11))
E("G21_every_comm_style_pre_no", "run 4000 pre no every 1000 \"comm_style brick\"; meets in part 2", 'run 4000 pre no every 1000 "comm_style brick"\n', gap=g11, pair=PER(g11))
for n in ("G18_every_change_box_pre_no", "G21_every_comm_style_pre_no"):
    p.LIVE[n] = "part 2"

# ============================================================ wave 4: the global cutoff given again; balance inside run every
E("C09_global_cutoff_big_to_small_coeff_regiven", "C07 with pair_coeff * * given again after pair_style granular 0.001", "run 1000\n" + PSG(0.001) + "pair_coeff * * " + HK + "\nrun 3000\n", gap=g11, pre=GCUT(0.02))
E("C10_coeff_cutoff_big_to_small", "pair_coeff * * ... cutoff 0.02; run 1000; pair_coeff * * ... cutoff 0.001; run 3000", "run 1000\npair_coeff * * " + HK + " cutoff 0.001\nrun 3000\n", gap=g11,
  pre=BL(HK + " cutoff 0.02"))
E("C11_global_cutoff_big_to_small_periodic", "C07 with the pair across the periodic x boundary", "run 1000\n" + PSG(0.001) + "run 3000\n", gap=g11, pre=GCUT(0.02), pair=PER(g11))
E("C12_global_cutoff_big_to_small_in_include", "C07 with pair_style granular 0.001 in an include", "run 1000\ninclude c.in\nrun 3000\n", gap=g11, pre=GCUT(0.02), data={"c.in": PSG(0.001)})
E("C13_global_cutoff_big_to_none", "pair_style granular 0.02; run 1000; pair_style granular (no cutoff: from the radii); run 3000", "run 1000\n" + PSG("") + "run 3000\n", gap=g11, pre=GCUT(0.02))
E("C14_global_cutoff_first_stage_big_to_small_nsq_fff", "C07 in an f f f box with neighbor 0.001 nsq (no bins: every pair listed)", "neighbor 0.001 nsq\nrun 1000\n" + PSG(0.001) + "run 3000\n", gap=g11, pre=FFF(GCUT(0.02)))
E("G22_every_balance_no_pre_no", "G07 without pre no (every part set up: right)", 'run 4000 every 1000 "balance 1.0 x uniform"\n', gap=g11, pair=PER(g11))
E("G23_every_include_balance_pre_no", "run 4000 pre no every 1000 \"include b.in\" (balance in the file)", 'run 4000 pre no every 1000 "include b.in"\n', gap=g11, pair=PER(g11), data={"b.in": "balance 1.0 x uniform\n"})
E("G24_every_balance_shift_pre_no", "run 4000 pre no every 1000 \"balance 1.1 shift x 5 1.05\"", 'run 4000 pre no every 1000 "balance 1.1 shift x 5 1.05"\n', gap=g11, pair=PER(g11))
E("G25_every_balance_inside_box_pre_no", "G07 with the pair inside the box (LAMMPS: on time? conservative if left out)", 'run 4000 pre no every 1000 "balance 1.0 x uniform"\n', gap=g11)
for n in ("G22_every_balance_no_pre_no", "G23_every_include_balance_pre_no", "G24_every_balance_shift_pre_no", "G25_every_balance_inside_box_pre_no"):
    p.LIVE[n] = "part 2"

# ============================================================ wave 5
E("G26_read_dump_pre_no", "run 1000; write_dump all custom d.dump id type x y z vx vy vz; read_dump d.dump 1000 x y z vx vy vz; run 3000 pre no (pair across the boundary)",
  "run 1000\nwrite_dump all custom d.dump id type x y z vx vy vz\nread_dump d.dump 1000 x y z vx vy vz\nrun 3000 pre no\n", gap=g11, pair=PER(g11))
E("G27_reset_atoms_image_pre_no", "run 1000; reset_atoms image all; run 3000 pre no (pair across the boundary)", "run 1000\nreset_atoms image all\nrun 3000 pre no\n", gap=g11, pair=PER(g11))
E("R24_restart_nsq_between_clear_and_read_fff", "f f f, vertical pair across z = 0.05; write_restart; clear; neighbor 0.001 nsq; read_restart (LAMMPS keeps nsq)",
  "run 1000\nwrite_restart a.rst\nclear\nneighbor 0.001 nsq\nread_restart a.rst\ncomm_modify vel yes\n" + FIX + "run 3000\n", gap=g11, pair=VZ(g11, zc=0.05), pre=FFF(BL()))
z("R24_restart_nsq_between_clear_and_read_fff")
E("R25_restart_bin_between_clear_and_read_nsq_before", "f f f, vertical pair across z = 0.05; neighbor 0.001 nsq; write_restart; clear; neighbor 0.001 bin; read_restart",
  "neighbor 0.001 nsq\nrun 1000\nwrite_restart a.rst\nclear\nneighbor 0.001 bin\nread_restart a.rst\ncomm_modify vel yes\n" + FIX + "run 3000\n", gap=g11, pair=VZ(g11, zc=0.05), pre=FFF(BL()))
z("R25_restart_bin_between_clear_and_read_nsq_before")
E("M15_lv1_made_type3_group_retyped_integ2", "3 types; lv1 made type 3; group g type 3; set atom 1 type 1; fix i2 g nve/sphere (lv1 stepped twice)",
  "group g type 3\nset atom 1 type 1\nfix i2 g nve/sphere\nrun 3000\n", gap=0.1e-3, pre=B3, pair=p.lv(0.1e-3, 3, 2))

# ============================================================ wave 6: other fixes that act on the motion
E("M16_damping_cundall_all", "fix damping/cundall all 0.3 0.3 (Cundall's local damping, a DEM modeller's settling aid) left on in the meeting run",
  "fix cd all damping/cundall 0.3 0.3\nrun 3000\n", gap=0.1e-3)
E("M17_nvk_lv2", "fix nvk on lv2 beside nve/sphere on all", "fix k2 lv2 nvk\nrun 3000\n", gap=0.1e-3)
E("M18_nvk_type2_group", "fix nvk on group t2 (type 2) beside nve/sphere on all", "group t2 type 2\nfix k2 t2 nvk\nrun 3000\n", gap=0.1e-3)
E("M19_damping_cundall_settle_then_unfix", "modeller: damping/cundall during a settling run 1000, unfixed before the meeting run 3000 (right)",
  "fix cd all damping/cundall 0.3 0.3\nrun 1000\nunfix cd\nrun 3000\n", gap=g11)

# ============================================================ wave 7: the global cutoff given again after a restart
E("R26_restart_cutoff_big_then_small_given", "pair_style granular 0.02; restart; pair_style granular 0.001 given after the read (its coefficients kept); run",
  RS(after=PSG(0.001)), gap=g11, pre=GCUT(0.02))
E("R27_restart_cutoff_small_then_big_given", "pair_style granular 0.001 (pair 1.1 mm apart at the write); restart; pair_style granular 0.02 given after the read; run",
  RS(after=PSG(0.02)), gap=g11, pre=GCUT(0.001))
E("R28_restart_plain_then_small_given", "pair_style granular; restart; pair_style granular 0.001 given after the read; run", RS(after=PSG(0.001)), gap=g11)

# ============================================================ wave 8: the same older style given again with other settings
GHH = p32.GHH
E("C15_gran_hooke_history_regiven_kn5000", "pair_style gran/hooke/history 2000 ...; run 1000; pair_style gran/hooke/history 5000 NULL 3000 NULL 0.3 0 (same style, new kn); run 3000",
  "run 1000\npair_style gran/hooke/history 5000 NULL 3000 NULL 0.3 0\nrun 3000\n", gap=g11, pre=GHH)
E("C16_granular_regiven_then_coeff_cutoff_nsq", "pair_style granular 0.02; run 1000; pair_style granular 0.001; neighbor 0.001 nsq (p p f box); run 3000", "run 1000\n" + PSG(0.001) + "neighbor 0.001 nsq\nrun 3000\n",
  gap=g11, pre=GCUT(0.02))
E("C17_global_cutoff_big_to_small_every", "pair_style granular 0.02; run 4000 every 1000 \"pair_style granular 0.001\" (meets in part 2)", 'run 4000 every 1000 "pair_style granular 0.001"\n', gap=g11, pre=GCUT(0.02))
p.LIVE["C17_global_cutoff_big_to_small_every"] = "part 2"

# ============================================================ wave 9: a like pair's own cutoff before pre no (round 32's answer to Q58)
BC = BL(HK + " cutoff 0.02")
E("K01_like_cutoff_same_pre_no", "pair_coeff * * ... cutoff 0.02; run 1000; pair_coeff 1 1 ... cutoff 0.02 again (unchanged); run 3000 pre no", "run 1000\npair_coeff 1 1 " + HK + " cutoff 0.02\nrun 3000 pre no\n", gap=g11, pre=BC)
E("K02_like_kn_changed_same_cutoff_pre_no", "K01 with pair_coeff 1 1 kn 5000 (a like pair's law; the live pair 1 2 has its own line)", "run 1000\npair_coeff 1 1 " + hk(5000) + " cutoff 0.02\nrun 3000 pre no\n", gap=g11, pre=BC)
E("K03_like_cutoff_small_pre_no", "K01 with pair_coeff 2 2 ... cutoff 0.001 (others keep 0.02)", "run 1000\npair_coeff 2 2 " + HK + " cutoff 0.001\nrun 3000 pre no\n", gap=g11, pre=BC)
E("K04_like_cutoff_small_no_pre_no", "K03 without pre no (the other pairs' 0.02 keep the lists' reach)", "run 1000\npair_coeff 2 2 " + HK + " cutoff 0.001\nrun 3000\n", gap=g11, pre=BC)

# ============================================================ wave 10: LIGGGHTS analogue of SW-PE
m.L("G28_lig_every_balance_pre_no", LPB().replace("run 3000\n", 'run 4000 pre no every 1000 "balance x uniform"\n'), g=1)
p.LIVE["G28_lig_every_balance_pre_no"] = "part 2"
m.L("G29_lig_balance_pre_no", LPB().replace("run 3000\n", "run 1000\nbalance x uniform\nrun 3000 pre no\n"), g=1)
p.LIVE["G29_lig_balance_pre_no"] = "last run"


def write_all(names):
    m.write_live(names, p.LIVE, p.EXTRA)


if __name__ == "__main__":
    os.makedirs("/tmp/f33 q04", exist_ok=True)   # Q04 writes its data file there (an absolute name with a space)
    write_all(sys.argv[1:] or list(m.DECKS))
    print(len(m.DECKS), "decks")

"""Field round 24: write the decks as decks/NAME/in.deck with G, extra files and a LIGGGHTS marker, with round 23's
helpers (now tests/fieldkit/decks.py). Prefixes: U units (speed unit line), S stops inside a run (f faces, lost atoms,
runs the audit cannot make), H fix halt error soft, R run arguments after reset_timestep/read_restart/loops, E LIGGGHTS
f faces and inserts, N lone types, W curved walls (zcylinder, region cylinder/sphere), G rigid bodies (clumps).
usage: python make_decks24.py [NAME ...]"""
import os, subprocess, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
from fieldkit import decks as m  # noqa: E402  (round 23's helpers, tests/fieldkit/decks.py)

m.D = os.path.join(HERE, "decks")
deck, L, BASE, TWO, hk, K, TL, HK = m.deck, m.L, m.BASE, m.TWO, m.hk, m.K, m.TL, m.HK
rr = lambda name, comment, lines, **kw: deck(name, "# " + comment + "\n" + BASE() + TWO + lines, g=1, **kw)
K5 = "pair_coeff * * " + hk(5000) + "\n"
K8 = "pair_coeff * * " + hk(8000) + "\n"
HALT = lambda style, extra="": f"variable t equal time\nfix h all halt 10 v_t > 0.0005 error {style}{extra}\n"
PREP = {}  # folder -> LAMMPS deck run in it before the round (writes a restart file the deck reads)

# ---------------------------------------------------------------- H: fix halt error soft
rr("H01_soft_message_no", "fix halt error soft message no (LAMMPS prints no 'condition met' line): run 2 (kn 5000) skipped?",
   HALT("soft", " message no") + "run 100\nunfix h\n" + K5 + "run 100\nprint \"PROBE step $(step)\"\n")
rr("H02_timer_full_before_soft", "timer full at the top (no timeout), then a soft halt met in run 1, kn 5000 run 2 (skipped by LAMMPS?)",
   "timer full\n" + HALT("soft") + "run 100\nunfix h\n" + K5 + "run 100\nprint \"PROBE step $(step)\"\n")
rr("H03_timeout_off_before_soft", "timer timeout off BEFORE the soft halt (it does not reset the forced timeout after): run 2 skipped?",
   "timer timeout off\n" + HALT("soft") + "run 100\nunfix h\n" + K5 + "run 100\nprint \"PROBE step $(step)\"\n")
rr("H04_soft_never_met_timer_full", "soft halt never met (v_t > 1), timer full: answered as usual (kn 5000)",
   "timer full\nvariable t equal time\nfix h all halt 10 v_t > 1.0 error soft\nrun 100\nunfix h\n" + K5 + "run 100\n")
rr("H05_soft_then_timeout_hour", "soft halt met in run 1, then timer timeout 1:00:00 (resets the timeout): run 2 kn 5000 made",
   HALT("soft") + "run 100\nunfix h\ntimer timeout 1:00:00\n" + K5 + "run 100\nprint \"PROBE step $(step)\"\n")
rr("H06_soft_met_in_run2_of_3", "kn 2000 run 1 (halt not yet defined), kn 5000 + soft halt met in run 2, kn 8000 run 3 skipped",
   "run 100\n" + K5 + "variable t equal time\nfix h all halt 10 v_t > 0.0015 error soft\nrun 100\nunfix h\n" + K8 + "run 100\nprint \"PROBE step $(step)\"\n")
rr("H07_soft_never_met", "soft halt never met (v_t > 1.0): answered (kn 5000)", "variable t equal time\nfix h all halt 10 v_t > 1.0 error soft\nrun 100\nunfix h\n" + K5 + "run 100\n")
rr("H08_soft_timer_normal_after", "soft halt met, then timer normal (not a timeout reset): run 2 still skipped?",
   HALT("soft") + "run 100\nunfix h\ntimer normal\n" + K5 + "run 100\nprint \"PROBE step $(step)\"\n")
rr("H09_soft_then_timeout_off", "soft halt met, then timer timeout off: run 2 made (R16 variant with kn 8000 and a third run)",
   HALT("soft") + "run 100\nunfix h\ntimer timeout off\n" + K5 + "run 100\n" + K8 + "run 100\nprint \"PROBE step $(step)\"\n")
rr("H10_soft_redefined_continue", "fix h redefined from soft to continue before run 1 (continue: later runs go on, kn 5000)",
   HALT("soft") + "fix h all halt 10 v_t > 0.0005 error continue\nrun 100\nunfix h\n" + K5 + "run 100\nprint \"PROBE step $(step)\"\n")
rr("H11_hard_message_no", "fix halt error hard message no: LAMMPS still exits? kn 5000 after",
   HALT("hard", " message no") + "run 100\nunfix h\n" + K5 + "run 100\n")
rr("H12_soft_in_loop", "soft halt met in pass 1 of a 2-pass loop, kn 5000 after the loop",
   HALT("soft") + "variable i loop 2\nlabel l\nrun 50\nnext i\njump SELF l\nunfix h\n" + K5 + "run 100\nprint \"PROBE step $(step)\"\n")
rr("H13_soft_count_condition", "fix halt on count: v_n < 2 error soft, a sphere thrown out under lost ignore; later runs skipped",
   "thermo_modify lost ignore\ngroup t2 type 2\nvelocity t2 set 0 0 200\nvariable n equal count(all)\nfix h all halt 10 v_n < 2 error soft\nrun 1000\nunfix h\n" + K5 + "run 100\nprint \"PROBE step $(step)\"\n")

# ---------------------------------------------------------------- S: stops inside a run; f faces kept
SB = lambda bnd, lines: m.head(2, bnd=bnd) + m.G1(HK) + m.GRAV + m.FLOOR + m.TAIL + TWO + lines
deck("S01_fff_kept_two_runs", "# f f f box, spheres rest on the floor: two runs (kn 2000, kn 5000) keep every sphere: answered\n"
     + SB("f f f", "run 1000\n" + K5 + "run 100\n"), g=1)
deck("S02_thrown_out_y_face", "# p f f box: type 2 thrown along y at 200 m/s, LAMMPS stops (Lost atoms) in run 1\n"
     + SB("p f f", "group t2 type 2\nvelocity t2 set 0 200 0\nrun 1000\n" + K5 + "run 100\n"), g=1)
deck("S03_huge_run_kept", "# p p f, a run of 2e7 steps (over the 1e7-step limit of runs made for real), spheres kept, then kn 5000\n"
     + SB("p p f", "run 20000000\n" + K5 + "run 100\n"), g=1)
deck("S04_huge_run_thrown", "# r22 with a first run of 2e7 steps: the sphere is lost at once; the audit cannot make the run\n"
     + SB("p p f", "group t2 type 2\nvelocity t2 set 0 0 200\nrun 20000000\n" + K5 + "run 100\n"), g=1)
deck("S05_lost_in_last_run", "# the type 2 sphere lost in the deck's last (only) run, kn 5000 set before it\n"
     + SB("p p f", K5 + "group t2 type 2\nvelocity t2 set 0 0 200\nrun 1000\n"), g=1)
deck("S06_lost_ignore_then_new", "# thermo_modify lost ignore: the type 2 sphere lost, run 2 (kn 5000) has only type 1 (two of them)\n"
     + SB("p p f", "create_atoms 1 single 0.03 0.03 0.01\nset type 1 diameter 0.004 density 2500\nthermo_modify lost ignore\ngroup t2 type 2\nvelocity t2 set 0 0 200\nrun 1000\n" + K5 + "run 100\n"), g=1)
deck("S07_change_box_to_f", "# p p p box (no floor loss), run 1, change_box all boundary p p f, sphere thrown up in run 2: lost, kn 8000 after\n"
     + m.head(2, bnd="p p p") + m.G1(HK) + m.GRAV + m.FLOOR + m.TAIL + TWO + "run 100\nchange_box all boundary p p f\ngroup t2 type 2\nvelocity t2 set 0 0 200\n" + K5 + "run 1000\n" + K8 + "run 100\n", g=1)
deck("S08_wall_reflect_kept", "# p p f box with fix wall/reflect zhi: the thrown sphere bounces back, kept: answered (kn 5000)\n"
     + SB("p p f", "fix top all wall/reflect zhi EDGE\ngroup t2 type 2\nvelocity t2 set 0 0 20\nrun 1000\n" + K5 + "run 100\n"), g=1)
deck("S09_lost_run2_of_3", "# kn 2000 run 1 kept, sphere thrown in run 2 (kn 5000), LAMMPS stops; kn 8000 run 3 never reached\n"
     + SB("p p f", "run 100\n" + K5 + "group t2 type 2\nvelocity t2 set 0 0 200\nrun 1000\n" + K8 + "run 100\n"), g=1)
deck("S10_fall_through_no_floor", "# p p f box with no floor wall: both spheres fall out of the bottom in a long run 1 (Lost atoms), kn 5000 after\n"
     + m.head(2, bnd="p p f") + m.G1(HK) + m.GRAV + m.TAIL + TWO + "run 20000\n" + K5 + "run 100\n", g=1)
deck("S11_many_atoms_long", "# 3000 spheres (lattice) in a p p f box, runs of 30000 steps: can the audit make them? kn 5000 after\n"
     + m.head(2, bnd="p p f", box="0 0.1 0 0.1 0 0.2") + m.G1(HK) + m.GRAV + m.FLOOR + m.TAIL
     + "lattice sc 0.0065\nregion fill block 0 0.1 0 0.1 0.005 0.05 units box\ncreate_atoms 1 region fill\nset type 1 diameter 0.004 density 2500\nset group all type/ratio 2 0.5 12345\nset type 2 diameter 0.006 density 2500\nrun 30000\n" + K5 + "run 100\n", g=1)
deck("S12_many_atoms_plain_types", "# S11 with types by region (no random draws)\n"
     + m.head(2, bnd="p p f", box="0 0.1 0 0.1 0 0.2") + m.G1(HK) + m.GRAV + m.FLOOR + m.TAIL
     + "lattice sc 0.0065\nregion fill block 0 0.1 0 0.1 0.005 0.05 units box\ncreate_atoms 1 region fill\nregion half block 0 0.05 INF INF INF INF units box\nset region half type 2\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 30000\n" + K5 + "run 100\n", g=1)
deck("S13_run_budget_zero", "# S01 audited with --run-budget 0 (its f faces unchecked): said?\n" + SB("f f f", "run 1000\n" + K5 + "run 100\n"), g=1, data={"ARGS": "--run-budget 0\n"})
deck("S14_hard_never_met_fff", "# f f f, fix halt hard never met, three runs kn 2000/5000/8000: answered (kn 8000)\n"
     + SB("f f f", "variable t equal time\nfix h all halt 10 v_t > 1.0\nrun 100\n" + K5 + "run 100\n" + K8 + "run 100\n"), g=1)
deck("S15_lost_warn_then_error", "# thermo_modify lost warn, run 1 keeps all, thermo_modify lost error, run 2 throws type 2 out (LAMMPS stops), kn 8000 after\n"
     + SB("p p f", "thermo_modify lost warn\nrun 100\nthermo_modify lost error\n" + K5 + "group t2 type 2\nvelocity t2 set 0 0 200\nrun 1000\n" + K8 + "run 100\n"), g=1)

# ---------------------------------------------------------------- R: run arguments against the step
rr("R01_reset_then_upto_legal", "run 200, reset_timestep 1000, kn 5000, run 1200 upto (200 steps: legal)", "run 200\nreset_timestep 1000\n" + K5 + "run 1200 upto\n")
rr("R02_reset_then_upto_illegal", "reset_timestep 1000, kn 5000, run 500 upto (illegal: LAMMPS stops)", "reset_timestep 1000\n" + K5 + "run 500 upto\n")
rr("R03_reset_start_stop_legal", "reset_timestep 500, kn 5000, run 100 start 500 stop 600 (legal)", "reset_timestep 500\n" + K5 + "run 100 start 500 stop 600\n")
rr("R04_reset_start_stop_illegal", "reset_timestep 500, kn 5000, run 100 start 0 stop 550 (stop before the end at 600: illegal)", "reset_timestep 500\n" + K5 + "run 100 start 0 stop 550\n")
RST = "read_restart base.restart\n" + "pair_style granular\npair_coeff * * " + HK + "\n"
RHEAD = "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\n"
RT = lambda lines: RHEAD + RST + m.GRAV + m.FLOOR + m.TAIL + lines
rp = "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.1 units box\ncreate_box 2 box\n" + m.G1(HK) + m.GRAV + m.FLOOR + m.TAIL + TWO + "run 1000\nwrite_restart base.restart\n"
for n, c, l in (("R05_restart_upto_legal", "read_restart (step 1000), kn 5000, run 1500 upto (legal)", K5 + "run 1500 upto\n"),
                ("R06_restart_upto_illegal", "read_restart (step 1000), kn 5000, run 500 upto (illegal)", K5 + "run 500 upto\n"),
                ("R07_restart_start_stop_legal", "read_restart (step 1000), kn 5000, run 100 start 0 stop 2000 (legal)", K5 + "run 100 start 0 stop 2000\n"),
                ("R08_restart_start_after", "read_restart (step 1000), kn 5000, run 100 start 1500 stop 2000 (start after the run's start: illegal)", K5 + "run 100 start 1500 stop 2000\n")):
    deck(n, "# " + c + "\n" + RT(l), g=1)
    PREP[n] = rp
rr("R09_loop_stop_pass2", "loop of 2 passes of run 100 start 0 stop 150: pass 2 (100 -> 200) passes the stop: LAMMPS stops; kn 5000 after",
   "variable i loop 2\nlabel l\nrun 100 start 0 stop 150\nnext i\njump SELF l\n" + K5 + "run 100\n")
rr("R10_leading_zero", "run 0100 (leading zero: engine says)", K5 + "run 0100\n")
rr("R11_plus_sign", "run +100 (engine says)", K5 + "run +100\n")
rr("R12_string_var_1e2", "variable n string 1e2, run ${n} (illegal as run 1e2)", "variable n string 1e2\n" + K5 + "run ${n}\n")
rr("R13_equal_var_1e2", "variable n equal 1e2, run ${n} (the engine formats 100: legal)", "variable n equal 1e2\n" + K5 + "run ${n}\n")
rr("R14_decimal_point", "run 100.0 (engine says)", K5 + "run 100.0\n")
rr("R15_every_null", "run 100 every 10 NULL (legal)", K5 + "run 100 every 10 NULL\n")
rr("R16_upto_first", "run 100 upto at step 0 (legal)", K5 + "run 100 upto\n")
rr("R17_reset_zero_upto", "run 200, reset_timestep 0, kn 5000, run 100 upto (legal)", "run 200\nreset_timestep 0\n" + K5 + "run 100 upto\n")
rr("R18_start_after_stop", "run 100 start 100 stop 50 (illegal)", K5 + "run 100 start 100 stop 50\n")
rr("R19_reset_time_upto", "reset_timestep 50 time 0.0005, kn 5000, run 100 upto (50 steps, legal)", "reset_timestep 50 time 0.0005\n" + K5 + "run 100 upto\n")
rr("R20_dollar_paren_float", "run $(100/3) (33.3333: engine says)", K5 + "run $(100/3)\n")
rr("R21_dollar_paren_int_fmt", "run $(100/3:%.0f) (33: legal)", K5 + "run $(100/3:%.0f)\n")
rr("R22_stop_var_step", "run 100 start 0 stop $(step+100) after run 200 (stop 300 = end: legal)", "run 200\n" + K5 + "run 100 start 0 stop $(step+100)\n")
rr("R23_pre_no_first", "run 100 pre no as the first run (engine says)", K5 + "run 100 pre no post no\n")
rr("R24_every_var_no_contact", "run 100 every 50 \"variable x equal 1\" (legal; no contact change): kn 5000", K5 + "run 100 every 50 \"variable x equal 1\"\n")
L("R25_liggghts_reset_upto_illegal", "# LIGGGHTS reset_timestep 1000, e 0.3, run 500 upto (engine says)\n" + m.LB() + m.ATOMS + m.LRUN + "reset_timestep 1000\n" + m.E3b(0.3) + "run 500 upto\n")
L("R26_liggghts_reset_upto_legal", "# LIGGGHTS reset_timestep 1000, e 0.3, run 1500 upto (legal)\n" + m.LB() + m.ATOMS + m.LRUN + "reset_timestep 1000\n" + m.E3b(0.3) + "run 1500 upto\n")
L("R27_liggghts_run_float", "# LIGGGHTS run 100.0 (engine says), e 0.3\n" + m.LB() + m.ATOMS + m.LRUN + m.E3b(0.3) + "run 100.0\n")

# ---------------------------------------------------------------- E: LIGGGHTS f faces, inserts, losses
LINS = (m.PTS + "fix ins all insert/pack seed 32452867 distributiontemplate pdd1 insert_every once overlapcheck yes all_in yes particles_in_region 20 region bc\n")
L("E01_fff_insert_kept", "# LIGGGHTS f f f box, insert/pack 20 spheres, floor primitive: runs keep every sphere; e 0.3 after run 1\n"
  + m.LB() + m.LRUN + LINS + "run 2000\n" + m.E3b(0.3) + "run 100\n")
L("E02_fall_out_bottom", "# LIGGGHTS f f f box with no wall: the two spheres fall out of the bottom in run 1 (lost silently); e 0.3 after, then create_atoms 1 and run\n"
  + m.lhead() + m.MAT3 + m.E3 + m.HERTZ + m.ATOMS + m.LRUN + "run 20000\n" + m.E3b(0.3) + "create_atoms 1 single 0 0 0.05 units box\nset atom 3 diameter 0.004 density 2500\nrun 100\n")
L("E03_insert_then_lose_type2", "# LIGGGHTS: two spheres (ids 1, 2) + insert/pack 20 more; type 2 sphere id 2 thrown out in run 1; e 0.3 after\n"
  + m.LB() + m.ATOMS + m.LRUN + LINS + "group up id 2\nvelocity up set 0 0 200\nrun 1000\n" + m.E3b(0.3) + "run 100\n")
L("E04_huge_run_liggghts", "# LIGGGHTS: run 20000000 (too long to make), type 2 thrown out in it, e 0.3 after\n"
  + m.LB() + m.ATOMS + m.LRUN.replace("run 1000\n", "") + "group up type 2\nvelocity up set 0 0 200\nrun 20000000\n" + m.E3b(0.3) + "run 100\n")
L("E05_insert_stream_fff", "# LIGGGHTS insert/stream from a region face over 5000 steps in an f f f box (kept), e 0.3 after\n"
  + m.LB() + m.LRUN + m.PTS
  + "fix ins all insert/rate/region seed 32452867 distributiontemplate pdd1 nparticles 30 particlerate 3000 insert_every 500 overlapcheck yes region bc ntry_mc 1000\nrun 5000\n" + m.E3b(0.3) + "run 100\n")
L("E06_lost_only_type2_pp", "# LIGGGHTS p p f box: type 2 thrown up out of the top (lost), e 0.3 after: 1 2 / 2 2 rows?\n"
  + m.LB().replace("boundary f f f", "boundary p p f") + m.ATOMS + m.LRUN + "group up type 2\nvelocity up set 0 0 200\nrun 1000\n" + m.E3b(0.3) + "run 100\n")
L("E07_lost_error_big_run", "# LIGGGHTS thermo_modify lost error, sphere thrown in a 2e7-step run (stop), e 0.3 after\n"
  + m.LB() + m.ATOMS + m.LRUN.replace("run 1000\n", "") + "thermo_modify lost error\ngroup up type 2\nvelocity up set 0 0 200\nrun 20000000\n" + m.E3b(0.3) + "run 100\n")

# ---------------------------------------------------------------- N: lone types
rr("N01_lone_type2", "two type 1 spheres, one type 2: 2 2 marked lone", "create_atoms 1 single 0.03 0.03 0.01\nset type 1 diameter 0.004 density 2500\nrun 100\n")
rr("N02_lone_then_second", "one type 2 in run 1, a second type 2 created before run 2 (kn 5000): not lone in stage 2",
   "run 100\ncreate_atoms 2 single 0.03 0.03 0.01\nset type 2 diameter 0.006 density 2500\n" + K5 + "run 100\n")
rr("N03_lone_pour_same_type", "one type 2 sphere and a fix pour of type 2: not lone",
   "region pr block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix p all pour 5 2 4767548 region pr diam one 0.006 dens 2500 2500\nrun 100\n")
rr("N04_lone_replicate", "one type 2 sphere, replicate 2 1 1: two type 2 spheres: not lone", "replicate 2 1 1\nrun 100\n")
rr("N05_set_atom_type", "set atom 1 type 2 (the type 1 sphere becomes type 2, size kept 4 mm): two type 2, no type 1", "set atom 1 type 2\nrun 100\n")
rr("N06_delete_to_lone", "three type 2 spheres (6 mm), delete two by id: 2 2 lone",
   "create_atoms 2 single 0.03 0.03 0.01\ncreate_atoms 2 single 0.03 0.01 0.01\nset type 2 diameter 0.006 density 2500\ngroup gone id 3 4\ndelete_atoms group gone\nrun 100\n")
rr("N07_two_type2_different_sizes", "two type 2 spheres of 6 mm and 8 mm: 2 2 is a real pair (6 on 8), not lone",
   "create_atoms 2 single 0.03 0.03 0.01\nset atom 3 diameter 0.008 density 2500\nrun 100\n")
rr("N08_lone_after_lost", "thermo_modify lost ignore, one of two type 2 spheres thrown out in run 1: stage 2 (kn 5000) 2 2 lone",
   "create_atoms 2 single 0.03 0.03 0.01\nset type 2 diameter 0.006 density 2500\nthermo_modify lost ignore\ngroup up id 3\nvelocity up set 0 0 200\nrun 1000\n" + K5 + "run 100\n")
rr("N09_lone_create_in_loop", "one type 2 then a loop creating two more type 2 spheres: not lone",
   "variable i loop 2\nlabel l\ncreate_atoms 2 single $(0.005+0.01*v_i) 0.03 0.01\nnext i\njump SELF l\nset type 2 diameter 0.006 density 2500\nrun 100\n")
rr("N10_lone_then_deposit", "one type 2, fix deposit of type 2 over the run: not lone",
   "region dp block 0.005 0.035 0.005 0.035 0.05 0.09 units box\nfix dep all deposit 3 2 100 12345 region dp near 0.006 vz -1 -1\nset type 2 diameter 0.006 density 2500\nrun 400\n")
L("N11_lone_liggghts", "# LIGGGHTS: one type 1, one type 2, plus another type 1: 2 2 lone\n" + m.LB() + m.ATOMS + "create_atoms 1 single 0.02 0 0.01 units box\nset atom 3 diameter 0.004 density 2500\n" + m.RUN)
rr("N12_lone_set_region_type", "set region r type 2 turns the type 1 sphere at (0.02,0.02) into type 2: two type 2 (4 and 6 mm)",
   "region r sphere 0.02 0.02 0.01 0.001 units box\nset region r type 2\nrun 100\n")
rr("N13_lone_delete_overlap", "a type 2 sphere created over the type 1 one, delete_atoms overlap: which stays? engine says",
   "create_atoms 2 single 0.0201 0.02 0.01\nset atom 3 diameter 0.006 density 2500\ndelete_atoms overlap 0.003 all all\nrun 100\n")

# ---------------------------------------------------------------- U: units and size-dependent laws
HMu = lambda E, eta: f"hertz/material {E} {eta} 0.3 damping viscoelastic {TL}"
deck("U01_nano_hertz_material", "# units nano (nm, ag, ns; nm/ns = m/s): hertz/material E 1e7 Pa = 1e-2, eta_n0 1.4e7 1/(m s) = 1.4e-11, 40/60 nm, 2.5e-3 ag/nm3\n"
     + m.ubase("nano", HMu("1e-2", "1.4e-11"), "0 400 0 400 0 1000", (40, 60, 2.5e-3, 2.5e-3)) + "timestep 1e-2\nrun 100\n", g=1)
deck("U02_lj_hertz_material", "# units lj: hertz/material E 1000 eta 3 nu 0.3, d 1/1.5, density 1\n"
     + m.ubase("lj", HMu("1000", "3"), "0 10 0 10 0 20", (1, 1.5, 1, 1)) + "timestep 1e-4\nrun 100\n", g=1)
deck("U03_cgs_radius_override", "# units cgs hertz/material (u02 of round 23) with --radius 2=0.5 (cm) and --g 100\n"
     + m.ubase("cgs", m.CGS_HM, "0 4 0 4 0 10", (0.4, 0.6, 2.5, 2.5)) + "timestep 1e-5\nrun 100\n", g=100, data={"ARGS": "--radius 2=0.5\n"})
deck("U04_metal_hertz_material", "# units metal: hertz/material E 1 (bar*? engine units), eta 0.01, 4/6 A, 2.5 g/cm3\n"
     + m.ubase("metal", HMu("1e4", "1e-3"), "0 40 0 40 0 100", (4, 6, 2.5, 2.5)) + "timestep 1e-3\nrun 100\n", g=1)
deck("U05_micro_hertz_material", "# units micro: hertz/material E 1e4 (=1e7 Pa), eta_n0 1.4e-5, 40/60 um, 2.5e-6 pg/um3, g 0.1 1\n"
     + m.ubase("micro", HMu("1e4", "1.4e-5"), "0 400 0 400 0 1000", (40, 60, 2.5e-6, 2.5e-6)) + "timestep 1e-3\nrun 100\n", g="0.1 1")
L("U06_liggghts_cgs_hertz", "# LIGGGHTS units cgs, hertz with e matrix: speed unit said?\n"
  + m.lhead(units="cgs", box="-5 5 -5 5 -1 15") + m.MAT3.replace("5e6", "5e7") + m.E3 + m.HERTZ
  + "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0\ncreate_atoms 1 single 1 0 1 units box\ncreate_atoms 2 single -1 0 1 units box\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 1.5\ntimestep 1e-5\nfix gravi all gravity 981 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 1000\n")
deck("U07_cgs_hertz_mass_velocity", "# units cgs: granular hertz 1e6 (dyne/cm2) damping mass_velocity 3000: size- and speed-dependent\n"
     + m.ubase("cgs", f"hertz 1e6 3000 {m.K}", "0 4 0 4 0 10", (0.4, 0.6, 2.5, 2.5)) + "timestep 1e-5\nrun 100\n", g=1)
deck("U08_real_hertz_material", "# units real (A/fs): hertz/material, speed unit said?\n"
     + m.ubase("real", HMu("1e-1", "1e-3"), "0 40 0 40 0 100", (4, 6, 2.5, 2.5)) + "timestep 0.1\nrun 100\n", g=1)

# ---------------------------------------------------------------- W: curved walls
HM = m.HM
WB = lambda wall, extra="": (m.head(2, box="-0.02 0.02 -0.02 0.02 0 0.1", bnd="f f f") + m.G1(HM) + m.GRAV
                             + f"fix floor all wall/gran granular {HM} zplane 0 NULL\n" + wall + m.TAIL
                             + "create_atoms 1 single 0.005 0 0.01\ncreate_atoms 2 single -0.005 0 0.01\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n" + extra + "run 100\n")
deck("W01_zcylinder_hertz", "# wall/gran zcylinder radius 0.01 with hertz/material: the wall is concave (LAMMPS uses its curvature in Reff?)\n"
     + WB(f"fix cyl all wall/gran granular {HM} zcylinder 0.01\n"), g=1)
deck("W02_region_cylinder_hertz", "# wall/gran/region on a cylinder region of radius 0.01 with hertz/material\n"
     + WB(f"region cy cylinder z 0 0 0.01 -1 1 side in units box\nfix cyl all wall/gran/region granular {HM} region cy\n"), g=1)
deck("W03_region_sphere_hertz", "# wall/gran/region on a sphere region of radius 0.012 centred at z 0.012 with hertz/material (concave)\n"
     + WB(f"region sp sphere 0 0 0.012 0.012 side in units box\nfix sw all wall/gran/region granular {HM} region sp\n"), g=1)
deck("W04_zcylinder_hooke", "# wall/gran zcylinder with hooke mass_velocity (no size in the law): unchanged by curvature\n"
     + WB(f"fix cyl all wall/gran granular {HK} zcylinder 0.01\n").replace(HM, HK), g=1)
deck("W05_region_sphere_out_hertz", "# wall/gran/region on a sphere region side out (a convex ball of radius 0.004 at the centre) with hertz/material\n"
     + WB(f"region sp sphere 0 0 0.05 0.004 side out units box\nfix sw all wall/gran/region granular {HM} region sp\n"), g=1)
L("W06_liggghts_zcylinder", "# LIGGGHTS primitive zcylinder radius 0.03 of type 3 with hertz (e 0.7 for 1 3)\n"
  + m.lhead() + m.MAT3 + m.E3 + m.HERTZ + "fix wcyl all wall/gran model hertz tangential history primitive type 3 zcylinder 0.03 0 0\n" + m.ATOMS + m.RUN)

# ---------------------------------------------------------------- G: rigid bodies
GB = lambda fixes: (m.head(2) + m.G1(HK) + m.GRAV + m.FLOOR + "timestep 1e-5\n"
                    + "create_atoms 1 single 0.02 0.02 0.01\ncreate_atoms 1 single 0.024 0.02 0.01\ncreate_atoms 2 single 0.01 0.01 0.01\ncreate_atoms 1 single 0.03 0.03 0.01\n"
                    + "set type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\ngroup clump id 1 2\ngroup free subtract all clump\n" + fixes + "run 100\n")
deck("G01_rigid_clump", "# ids 1 2 (type 1) one rigid body (fix rigid single); the rest nve/sphere: a sphere of the clump collides with twice its mass\n"
     + GB("fix rb clump rigid single\nfix integ free nve/sphere\n"), g=1)
deck("G02_rigid_small_clump", "# as G01 with fix rigid/small and molecule ids by set (atom_style sphere has none: engine says)\n"
     + GB("fix rb clump rigid/small molecule\nfix integ free nve/sphere\n"), g=1)
deck("G03_rigid_one_sphere", "# a rigid body of the type 2 sphere alone: its mass is its own\n"
     + GB("group t2 type 2\nfix rb t2 rigid single\ngroup rest subtract all t2\nfix integ rest nve/sphere\n"), g=1)

# ---------------------------------------------------------------- S (more): errors inside a run in a box with no f face (no trigger)
PB = lambda lines: m.head(2, bnd="p p p") + m.G1(HK) + m.TAIL + TWO + lines
deck("S16_thermo_div0_ppp", "# p p p box, no gravity: thermo_style custom step v_x, x = 1/(step-50), thermo 10: LAMMPS errors at step 50 of run 1; kn 5000 after\n"
     + PB("variable x equal 1/(step-50)\nthermo_style custom step v_x\nthermo 10\nrun 100\n" + K5 + "run 100\n"), g=1)
deck("S17_thermo_sqrt_neg_ppp", "# p p p: thermo_style custom step v_x, x = sqrt(50-step): LAMMPS errors at step 60 of run 1; kn 5000 after\n"
     + PB("variable x equal sqrt(50-step)\nthermo_style custom step v_x\nthermo 10\nrun 100\n" + K5 + "run 100\n"), g=1)
deck("S18_fix_ave_time_div0_ppp", "# p p p: fix ave/time 10 1 10 v_x (x = 1/(step-50)): LAMMPS errors at step 50; kn 5000 after\n"
     + PB("variable x equal 1/(step-50)\nfix av all ave/time 10 1 10 v_x\nrun 100\n" + K5 + "run 100\n"), g=1)
deck("S19_thermo_div0_ppf", "# S16 in the base p p f box (its f face makes the audit run it for real)\n"
     + SB("p p f", "variable x equal 1/(step-50)\nthermo_style custom step v_x\nthermo 10\nrun 100\n" + K5 + "run 100\n"), g=1)
L("S20_liggghts_thermo_div0", "# LIGGGHTS p p p box: thermo_style custom step v_x, x = 1/(step-50), thermo 10: LIGGGHTS errors at step 50; e 0.3 after\n"
  + m.lhead(bnd="p p p") + m.MAT3 + m.E3 + m.HERTZ + m.ATOMS + "timestep 1e-5\nfix integr all nve/sphere\nvariable x equal 1/(step-50)\nthermo_style custom step v_x\nthermo 10\nrun 100\n" + m.E3b(0.3) + "run 100\n")
rr("H14_soft_long_unmakeable", "soft halt met at step 60 of a 2e7-step run (too long for the audit to make), kn 5000 after",
   HALT("soft") + "run 20000000\nunfix h\n" + K5 + "run 100\nprint \"PROBE step $(step)\"\n")
rr("H15_soft_tlimit_message_no", "fix halt 10 tlimit > 0.0 error soft message no (wall clock, met at once, silent): kn 5000 run skipped",
   "fix h all halt 10 tlimit > 0.0 error soft message no\nrun 100\nunfix h\n" + K5 + "run 100\nprint \"PROBE step $(step)\"\n")
L("E08_liggghts_stiffness_lose_big", "# LIGGGHTS hooke/stiffness (eps depends on masses): two type 2 spheres, 6 mm (id 2) and 10 mm (id 3); id 3 thrown out in run 1; 1 2 rows after\n"
  + m.lhead() + m.MAT3 + m.HS + m.ATOMS + "create_atoms 2 single -0.03 0 0.01 units box\nset atom 3 diameter 0.010 density 1500\n" + m.LRUN + "group up id 3\nvelocity up set 0 0 200\nrun 1000\nrun 100\n")

# ---------------------------------------------------------------- budgets: --run-budget 0 on decks the engine stops
deck("S21_thrown_out_budget0", "# round 23's r22 (type 2 thrown out of the p p f box: LAMMPS stops, Lost atoms) audited with --run-budget 0\n"
     + SB("p p f", "group t2 type 2\nvelocity t2 set 0 0 200\nthermo 100\nrun 1000\n" + K5 + "run 100\n"), g=1, data={"ARGS": "--run-budget 0\n"})
rr("H16_soft_budget0", "round 23's R12 (soft halt met in run 1, kn 5000 run 2 skipped) audited with --run-budget 0",
   HALT("soft") + "run 100\nunfix h\n" + K5 + "run 100\nprint \"PROBE step $(step)\"\n", data={"ARGS": "--run-budget 0\n"})
rr("H17_hard_budget0", "round 23's R11 (halt hard met in run 1) audited with --run-budget 0",
   HALT("hard") + "run 100\nunfix h\n" + K5 + "run 100\n", data={"ARGS": "--run-budget 0\n"})

# ---------------------------------------------------------------- T: integrators and thermostats that change a collision
TB = lambda integ: (m.head(2) + m.G1(HK) + m.GRAV + m.FLOOR + integ + "timestep 1e-5\n" + TWO + "run 100\n")
deck("T01_nvt_sphere", "# fix nvt/sphere temp 300 300 1e-3 instead of nve/sphere (a Nose-Hoover thermostat on the spheres)\n" + TB("fix integ all nvt/sphere temp 300 300 1e-3\n"), g=1)
deck("T02_temp_berendsen", "# nve/sphere + fix temp/berendsen 0 0 1e-4 (rescales velocities every step toward T = 0)\n" + TB("fix integ all nve/sphere\nfix tb all temp/berendsen 0.0 0.0 1e-4\n"), g=1)
deck("T03_temp_rescale", "# nve/sphere + fix temp/rescale 1 0 0 1e-30 1.0 (velocities rescaled to T = 0 every step)\n" + TB("fix integ all nve/sphere\nfix tr all temp/rescale 1 0.0 0.0 1e-30 1.0\n"), g=1)
deck("T04_nve_noforce", "# fix nve/noforce instead of nve/sphere (positions follow velocities, forces never act)\n" + TB("fix integ all nve/noforce\n"), g=1)
deck("T05_momentum", "# nve/sphere + fix momentum 1 linear 1 1 1 (zeroes the total momentum each step: no effect on a head-on pair at rest centre)\n" + TB("fix integ all nve/sphere\nfix mom all momentum 1 linear 1 1 1\n"), g=1)
deck("T06_nph_sphere", "# fix nph/sphere (barostat) on the spheres, p p f box: engine says\n" + TB("fix integ all nph/sphere x 0 0 1e-3\n"), g=1)
deck("T07_temp_csvr", "# nve/sphere + fix temp/csvr 0 0 1e-4 seed (stochastic rescale to T = 0)\n" + TB("fix integ all nve/sphere\nfix tc all temp/csvr 0.0 0.0 1e-4 54321\n"), g=1)

# ---------------------------------------------------------------- K: neighbor settings that miss contacts
deck("K01_skin_tiny_every_1000", "# neighbor 1e-6 bin, neigh_modify every 1000 check no: a pair approaching from apart is found late (deep overlap) or never\n"
     + m.head(2, extra="neighbor 1e-6 bin\nneigh_modify delay 0 every 1000 check no\n") + m.G1(HK) + m.GRAV + m.FLOOR + m.TAIL + TWO + "run 100\n", g=1)
deck("K02_skin_tiny_check_yes", "# neighbor 1e-6 bin with the default every 1 check yes: contacts found\n"
     + m.head(2, extra="neighbor 1e-6 bin\n") + m.G1(HK) + m.GRAV + m.FLOOR + m.TAIL + TWO + "run 100\n", g=1)

# ---------------------------------------------------------------- B: bonded spheres (special_bonds: a bonded pair is left out of the neighbor list)
BOND = ("units si\natom_style hybrid sphere bond\nboundary p p f\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.1 units box\n"
        "create_box 2 box bond/types 1 extra/bond/per/atom 1 extra/special/per/atom 1\n" + m.G1(HK) + "bond_style harmonic\nbond_coeff 1 0.0 0.01\n"
        + m.GRAV + m.FLOOR + m.TAIL + TWO)
deck("B01_bonded_only_pair", "# the type 1 and the type 2 sphere bonded (bond_style harmonic of stiffness 0): special_bonds lj 0 0 0 (default) leaves them out of each other's list: the 1 2 pair cannot meet\n"
     + BOND + "create_bonds single/bond 1 1 2\nrun 100\n", g=1)
deck("B02_bonded_special_one", "# B01 with special_bonds lj 1 1 1 (bonded pairs kept in the list): the 1 2 pair meets\n"
     + BOND + "special_bonds lj 1 1 1\ncreate_bonds single/bond 1 1 2\nrun 100\n", g=1)
deck("B03_bonded_plus_free", "# B01 plus a free type 2 sphere (id 3): 1 2 meets through id 3\n"
     + BOND + "create_atoms 2 single 0.03 0.03 0.01\nset type 2 diameter 0.006 density 2500\ncreate_bonds single/bond 1 1 2\nrun 100\n", g=1)

# ---------------------------------------------------------------- more S, E, N, R, V
deck("S22_fs_thrown_down", "# boundary p p fs: the type 2 sphere thrown down at 200 m/s through the floor wall, out of the fixed bottom face: Lost atoms; kn 5000 after\n"
     + SB("p p fs", "group t2 type 2\nvelocity t2 set 0 0 -200\nrun 1000\n" + K5 + "run 100\n"), g=1)
deck("S23_sf_thrown_up", "# boundary p p sf (shrink-wrapped bottom, fixed top): the type 2 sphere thrown up out of the top: Lost atoms; kn 5000 after\n"
     + m.head(2, bnd="p p sf") + m.G1(HK) + m.GRAV + m.TAIL + TWO + "group t2 type 2\nvelocity t2 set 0 0 200\nrun 1000\n" + K5 + "run 100\n", g=1)
deck("S24_change_box_f_no_wall", "# p p p box, no gravity or wall: run 1, change_box all boundary p p f, type 2 thrown up: lost in run 2; kn 8000 for run 3\n"
     + m.head(2, bnd="p p p") + m.G1(HK) + m.TAIL + TWO + "run 100\nchange_box all boundary p p f\ngroup t2 type 2\nvelocity t2 set 0 0 200\n" + K5 + "run 1000\n" + K8 + "run 100\n", g=1)
L("E09_liggghts_lost_then_insert", "# LIGGGHTS hooke/stiffness: the type 2 sphere (6 mm, 1500) thrown out in run 1, then insert/pack of 10 type 2 spheres of 8 mm rho 1500 (pts only 2): 1 2 rows at 8 mm only\n"
  + m.lhead() + m.MAT3 + m.HS + m.ATOMS + m.LRUN + "group up type 2\nvelocity up set 0 0 200\nrun 1000\n"
  + "fix pts3 all particletemplate/sphere 15485863 atom_type 2 density constant 1500 radius constant 0.004\nfix pdd2 all particledistribution/discrete 32452843 1 pts3 1.0\nregion bc block -0.03 0.03 -0.03 0.03 0.02 0.1 units box\n"
  + "fix ins all insert/pack seed 32452867 distributiontemplate pdd2 insert_every once overlapcheck yes all_in yes particles_in_region 10 region bc\nrun 100\n")
L("N14_liggghts_lone_insert_later", "# LIGGGHTS: one type 2 sphere, insert/pack of type 2 (pts2) with start 500 in a later run: not lone in that run\n"
  + m.LB() + m.ATOMS + m.LRUN + m.PTS.replace("pts1 0.5 pts2 0.5", "pts2 1.0").replace("discrete 32452843 2", "discrete 32452843 1")
  + "run 100\nfix ins all insert/pack seed 32452867 distributiontemplate pdd1 insert_every once overlapcheck yes all_in yes particles_in_region 10 region bc\nrun 200\n")
rr("R28_every_print", "run 100 every 50 \"print hi\" (no contact change): kn 5000", K5 + "run 100 every 50 \"print hi\"\n")
rr("R29_every_thermo_style", "run 100 every 50 \"thermo_style one\" (no contact change)", K5 + "run 100 every 50 \"thermo_style one\"\n")
rr("R30_loop_upto", "a loop of 3 passes of run 300 upto (step 300, then 0-step runs: legal), kn 5000 before", K5 + "variable i loop 3\nlabel l\nrun 300 upto\nnext i\njump SELF l\n")
rr("V01_is_file_present", "if $(is_file(kn.txt)) then include kn.txt (kn 5000 in it; present)",
   "if $(is_file(kn.in)) then \"include kn.in\" else \"pair_coeff * * " + hk(8000) + "\"\nrun 100\n", data={"kn.in": K5})
rr("V02_is_file_absent", "if $(is_file(nofile.in)) then ... else kn 8000", "if $(is_file(nofile.in)) then \"include nofile.in\" else \"pair_coeff * * " + hk(8000) + "\"\nrun 100\n")
rr("V03_is_os", "if $(is_os(^Linux)) then kn 5000 else kn 8000", "if $(is_os(^Linux)) then \"pair_coeff * * " + hk(5000) + "\" else \"pair_coeff * * " + hk(8000) + "\"\nrun 100\n")
rr("V04_extract_setting", "variable n equal extract_setting(world_size): kn $(1000*v_n+4000) = 5000 in serial", "variable n equal extract_setting(world_size)\npair_coeff * * hooke $(1000*v_n+4000) 3000 " + K + "\nrun 100\n")
rr("V05_is_available_pair", "if $(is_available(pair_style,granular)) then kn 5000", "if $(is_available(pair_style,granular)) then \"pair_coeff * * " + hk(5000) + "\"\nrun 100\n")
rr("V06_version_check", "variable v equal version; kn 5000 if version >= 20250722", "variable v equal version\nif \"${v} >= 20250722\" then \"pair_coeff * * " + hk(5000) + "\"\nrun 100\n")

# ---------------------------------------------------------------- V: include through if branches and jumps
KN = {"kn.in": K5}
rr("V07_if_one_include", "if 1 then include kn.in (kn 5000 in it)", "if 1 then \"include kn.in\"\nrun 100\n", data=KN)
rr("V08_is_file_direct_pair", "if $(is_file(kn.in)) then pair_coeff kn 5000 directly, else kn 8000", "if $(is_file(kn.in)) then \"pair_coeff * * " + hk(5000) + "\" else \"pair_coeff * * " + hk(8000) + "\"\nrun 100\n", data=KN)
rr("V09_is_file_var", "variable f equal is_file(kn.in); kn $(2000+3000*v_f) = 5000", "variable f equal is_file(kn.in)\npair_coeff * * hooke $(2000+3000*v_f) 3000 " + K + "\nrun 100\n", data=KN)
rr("V10_is_file_include_no_else", "if $(is_file(kn.in)) then include kn.in (no else)", "if $(is_file(kn.in)) then \"include kn.in\"\nrun 100\n", data=KN)
rr("V11_jump_file", "jump kn2.in (kn2.in: kn 5000 and run 100; the deck's lines after the jump never run)", "jump kn2.in\npair_coeff * * " + hk(8000) + "\nrun 100\n", data={"kn2.in": K5 + "run 100\n"})
rr("V12_if_index_include", "variable a index 1; if \"${a} == 1\" then \"include kn.in\"", "variable a index 1\nif \"${a} == 1\" then \"include kn.in\"\nrun 100\n", data=KN)
rr("V13_include_nested_in_if", "if 1 then include outer.in; outer.in includes kn.in", "if 1 then \"include outer.in\"\nrun 100\n", data={"outer.in": "include kn.in\n", **KN})
rr("V14_if_include_sizes", "if 1 then include sizes.in (set type 2 density 7800): sizes, not contact settings", "if 1 then \"include sizes.in\"\nrun 100\n", data={"sizes.in": "set type 2 density 7800\n"})
rr("V15_include_in_loop", "a 2-pass loop whose body includes kn.in then runs 50 steps", "variable i loop 2\nlabel l\ninclude kn.in\nrun 50\nnext i\njump SELF l\n", data=KN)
rr("V16_if_include_then_run", "if 1 then \"include kn.in\" \"run 100\" (the run inside the branch)", "if 1 then \"include kn.in\" \"run 100\"\n", data=KN)
rr("V17_include_plain", "include kn.in (no if): control", "include kn.in\nrun 100\n", data=KN)
rr("V18_if_else_include", "if 0 then pair_coeff kn 8000 else include kn.in", "if 0 then \"pair_coeff * * " + hk(8000) + "\" else \"include kn.in\"\nrun 100\n", data=KN)
rr("V19_if_include_wall", "if 1 then include wall.in (unfix floor, new floor wall with kn 5000)", "if 1 then \"include wall.in\"\nrun 100\n",
   data={"wall.in": "unfix floor\nfix floor all wall/gran granular " + hk(5000) + " zplane 0 NULL\n"})
L("V20_liggghts_if_include", "# LIGGGHTS: if 1 then include e.in (e 0.3 for every pair)\n" + m.LB() + m.ATOMS + m.LRUN + "if 1 then \"include e.in\"\nrun 100\n", data={"e.in": m.E3b(0.3)})

rr("V21_if_jump_file", "if 1 then jump kn2.in (kn2.in: kn 5000, run 100)", "if 1 then \"jump kn2.in\"\npair_coeff * * " + hk(8000) + "\nrun 100\n", data={"kn2.in": K5 + "run 100\n"})
rr("V22_if_include_with_run", "if 1 then include stage.in (stage.in: kn 5000, run 100), then kn 8000 run 100", "if 1 then \"include stage.in\"\n" + K8 + "run 100\n", data={"stage.in": K5 + "run 100\n"})
rr("V23_if_include_by_var", "variable f string kn.in; if 1 then \"include ${f}\"", "variable f string kn.in\nif 1 then \"include ${f}\"\nrun 100\n", data=KN)
rr("V24_if_read_data_add", "if 1 then read_data add.data add append (a type 2 sphere of 10 mm rho 7800)", "if 1 then \"read_data add.data add append\"\nrun 100\n",
   data={"add.data": "# one sphere\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 2 0.010 7800 0.03 0.03 0.02\n"})
rr("V25_if_include_fix_halt", "if 1 then include halt.in (fix halt soft met in run 1), kn 5000 run 2 skipped by LAMMPS",
   "if 1 then \"include halt.in\"\nrun 100\nunfix h\n" + K5 + "run 100\nprint \"PROBE step $(step)\"\n", data={"halt.in": HALT("soft")})
rr("V26_if_include_timestep", "if 1 then include dt.in (timestep 1e-4: 5 steps per contact)", "if 1 then \"include dt.in\"\nrun 100\n", data={"dt.in": "timestep 1e-4\n"})

rr("H18_if_fix_halt_soft", "if 1 then \"fix h all halt ... error soft\" (the halt in an if's quoted command): run 2 skipped",
   "variable t equal time\nif 1 then \"fix h all halt 10 v_t > 0.0005 error soft\"\nrun 100\nunfix h\n" + K5 + "run 100\nprint \"PROBE step $(step)\"\n")
U04 = m.ubase("metal", HMu("1e4", "1e-3"), "0 40 0 40 0 100", (4, 6, 2.5, 2.5)) + "timestep 1e-3\nrun 100\n"
deck("U09_metal_units_in_if_include", "# U04 (units metal, hertz/material) with its units line moved into units.in, included by an if\n"
     + U04.replace("units metal\n", "if 1 then \"include units.in\"\n"), g=1, data={"units.in": "units metal\n"})
deck("U10_cgs_units_in_if_include", "# round 23's u02 (units cgs hertz/material) with its units line in units.in, included by an if\n"
     + (m.ubase("cgs", m.CGS_HM, "0 4 0 4 0 10", (0.4, 0.6, 2.5, 2.5)) + "timestep 1e-5\nrun 100\n").replace("units cgs\n", "if 1 then \"include units.in\"\n"), g=1, data={"units.in": "units cgs\n"})
PAIRIN = {"pair.in": m.G1(HK).replace("hooke 2000", "hooke 5000")}
deck("V28_if_include_pair_style", "# pair_style granular and its pair_coeff (kn 5000) only in pair.in, included by an if\n"
     + m.head(2) + "if 1 then \"include pair.in\"\n" + m.GRAV + m.FLOOR + m.TAIL + TWO + "run 100\n", g=1, data=PAIRIN)
deck("V29_if_include_only_wall", "# the only floor wall (kn 5000) made in wall.in, included by an if\n"
     + m.head(2) + m.G1(HK) + m.GRAV + "if 1 then \"include wall.in\"\n" + m.TAIL + TWO + "run 100\n", g=1,
     data={"wall.in": "fix floor all wall/gran granular " + hk(5000) + " zplane 0 NULL\n"})

rr("V30_if_jump_skip_block", "if 1 then \"jump SELF skip\" over a kn 8000 pair_coeff: LAMMPS keeps kn 2000",
   "if 1 then \"jump SELF skip\"\npair_coeff * * " + hk(8000) + "\nlabel skip\nrun 100\n")
deck("V31_if_read_restart", "# if 1 then read_restart base.restart (step 1000, kn 2000 stored in it); kn 5000 after; run 1500 upto (legal)\n"
     + RHEAD.replace("units si\natom_style sphere 1\n", "") + "if 1 then \"read_restart base.restart\"\n" + m.GRAV + m.FLOOR + m.TAIL + K5 + "run 1500 upto\n", g=1)
PREP["V31_if_read_restart"] = rp
deck("V32_if_read_restart_upto_illegal", "# if 1 then read_restart base.restart (step 1000); kn 5000; run 500 upto (illegal)\n"
     + RHEAD.replace("units si\natom_style sphere 1\n", "") + "if 1 then \"read_restart base.restart\"\n" + m.GRAV + m.FLOOR + m.TAIL + K5 + "run 500 upto\n", g=1)
PREP["V32_if_read_restart_upto_illegal"] = rp

rr("H19_soft_then_clear", "soft halt met in run 1, then clear and the whole deck again with kn 5000 (clear makes a new timer: its run is made)",
   HALT("soft") + "run 100\nclear\n" + BASE() + TWO + K5 + "run 100\nprint \"PROBE step $(step)\"\n")
deck("V34_if_include_dimension2", "# dimension 2 (discs: masses of discs) set in dim.in, included by an if; 2d box, hooke mass_velocity\n"
     + "units si\nif 1 then \"include dim.in\"\natom_style sphere 1\nboundary p f p\ncomm_modify vel yes\nregion box block 0 0.04 0 0.1 -0.001 0.001 units box\ncreate_box 2 box\n"
     + m.G1(HK) + "fix grav all gravity 9.81 vector 0 -1 0\nfix floor all wall/gran granular " + HK + " yplane 0 NULL\nfix integ all nve/sphere\nfix 2d all enforce2d\ntimestep 1e-5\n"
     + "create_atoms 1 single 0.02 0.01 0\ncreate_atoms 2 single 0.01 0.01 0\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g=1, data={"dim.in": "dimension 2\n"})
deck("V35_dimension2_plain_control", "# control of V34: dimension 2 written plainly\n"
     + "units si\ndimension 2\natom_style sphere 1\nboundary p f p\ncomm_modify vel yes\nregion box block 0 0.04 0 0.1 -0.001 0.001 units box\ncreate_box 2 box\n"
     + m.G1(HK) + "fix grav all gravity 9.81 vector 0 -1 0\nfix floor all wall/gran granular " + HK + " yplane 0 NULL\nfix integ all nve/sphere\nfix 2d all enforce2d\ntimestep 1e-5\n"
     + "create_atoms 1 single 0.02 0.01 0\ncreate_atoms 2 single 0.01 0.01 0\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 100\n", g=1)
rr("V36_if_include_exclude", "if 1 then include ex.in (neigh_modify exclude type 1 2): the 1 2 pair cannot meet", "if 1 then \"include ex.in\"\nrun 100\n", data={"ex.in": "neigh_modify exclude type 1 2\n"})
rr("V37_if_include_viscous", "if 1 then include vis.in (fix vis all viscous 0.001): a drag during every contact", "if 1 then \"include vis.in\"\nrun 100\n", data={"vis.in": "fix vis all viscous 0.001\n"})
rr("V38_viscous_plain_control", "control of V37: fix vis all viscous 0.001 written plainly", "fix vis all viscous 0.001\nrun 100\n")

INIT = {"init.in": "region box block 0 0.04 0 0.04 0 0.1 units box\ncreate_box 2 box\n" + m.G1(HK).replace("hooke 2000", "hooke 5000") + TWO}
deck("V39_restart_or_init_pattern", "# the common pattern: variable restart index 0; if restart then read_restart else include init.in (box, pair_style kn 5000, atoms)\n"
     + RHEAD + "variable restart index 0\nif \"${restart} == 1\" then \"read_restart base.restart\" else \"include init.in\"\n" + m.GRAV
     + "fix floor all wall/gran granular " + hk(5000) + " zplane 0 NULL\n" + m.TAIL + "run 100\n", g=1, data=INIT)
PREP["V39_restart_or_init_pattern"] = rp

rr("V40_if_ampersand_lines", "if 1 then & over lines, two quoted commands: variable and pair_coeff kn 5000", "if 1 then &\n  \"variable k equal 5000\" &\n  \"pair_coeff * * hooke ${k} 3000 " + K + "\"\nrun 100\n")
rr("V41_if_triple_quotes", "if 1 then \"\"\"...\"\"\" (a triple-quoted command: pair_coeff kn 5000)", "if 1 then \"\"\"pair_coeff * * " + hk(5000) + "\"\"\"\nrun 100\n")

MOL2 = {"m2.mol": m.MOL(2, 0.006, m.mass(0.006, 2500))}
rr("N15_lone_deposit_mol", "one type 2 sphere (6 mm) + fix deposit of a one-sphere type 2 template (6 mm, 2500): not lone",
   "molecule m2 m2.mol\nregion ins block 0.005 0.035 0.005 0.035 0.05 0.08 units box\nfix dep all deposit 3 0 20 4711 region ins near 0.01 mol m2 vz -1 -1\nrun 200\n", data=MOL2)
rr("N16_lone_pour_mol", "one type 2 sphere (6 mm) + fix pour of a one-sphere type 2 template: not lone",
   "molecule m2 m2.mol\nregion ins block 0.005 0.035 0.005 0.035 0.05 0.08 units box\nfix p all pour 3 0 4711 region ins mol m2\nrun 200\n", data=MOL2)
rr("N17_lone_create_mol", "one type 2 sphere + create_atoms 0 single ... mol m2 (a second type 2 sphere from a template): not lone",
   "molecule m2 m2.mol\ncreate_atoms 0 single 0.03 0.03 0.01 mol m2 1234\nrun 100\n", data=MOL2)

HScgs = m.HS.replace("2000 2000 2000 2000 2000 2000 2000 2000 2000", "2e6 2e6 2e6 2e6 2e6 2e6 2e6 2e6 2e6").replace("500 500 500 500 500 500 500 500 500", "5e5 5e5 5e5 5e5 5e5 5e5 5e5 5e5 5e5")
L("U11_liggghts_cgs_stiffness", "# LIGGGHTS units cgs, hooke/stiffness kn 2e6 dyne/cm gamman 5e5 g/s (= the SI 2000 N/m, 500 kg/s): eps depends on masses; speeds in cm/s\n"
  + m.lhead(units="cgs", box="-5 5 -5 5 -1 15") + m.MAT3.replace("5e6", "5e7") + HScgs
  + "create_atoms 1 single 1 0 1 units box\ncreate_atoms 2 single -1 0 1 units box\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 1.5\ntimestep 1e-5\nfix gravi all gravity 981 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 1000\n", g=100)

HScgs2 = m.HS.replace("2000 2000 2000 2000 2000 2000 2000 2000 2000", "2e6 2e6 2e6 2e6 2e6 2e6 2e6 2e6 2e6")
L("U12_liggghts_cgs_stiffness_gamma", "# U11 with gamman 500 left as in SI (LIGGGHTS hooke/stiffness gamman is per mass: 1/s): eps as E08's in SI; speeds in cm/s\n"
  + m.lhead(units="cgs", box="-5 5 -5 5 -1 15") + m.MAT3.replace("5e6", "5e7") + HScgs2
  + "create_atoms 1 single 1 0 1 units box\ncreate_atoms 2 single -1 0 1 units box\nset type 1 diameter 0.4 density 2.5\nset type 2 diameter 0.6 density 1.5\ntimestep 1e-5\nfix gravi all gravity 981 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 1000\n", g=100)

deck("S25_restart_f_face_thrown", "# no boundary command: read_restart base.restart restores the p p f box; pair_style again; the type 2 sphere thrown up: Lost atoms in run 1; kn 5000 after\n"
     + "read_restart base.restart\ncomm_modify vel yes\npair_style granular\npair_coeff * * " + HK + "\n" + m.GRAV + m.FLOOR + m.TAIL
     + "group t2 type 2\nvelocity t2 set 0 0 200\nrun 1000\n" + K5 + "run 100\n", g=1)
PREP["S25_restart_f_face_thrown"] = rp
CONT = "variable t equal time\nfix h all halt 10 v_t > 0.0005 error continue\nrun 100\nunfix h\n"
rr("R31_continue_then_stop_legal", "fix halt error continue ends run 1 at step 60; kn 5000; run 50 start 0 stop 120 (LAMMPS: 60 -> 110, legal)",
   CONT + K5 + "run 50 start 0 stop 120\nprint \"PROBE step $(step)\"\n")
rr("R32_continue_then_upto_legal", "halt continue at step 60; kn 5000; run 80 upto (LAMMPS: 60 -> 80, legal)",
   CONT + K5 + "run 80 upto\nprint \"PROBE step $(step)\"\n")

LPREP = {}  # folder -> LIGGGHTS deck run in it before the round (writes the restart file the deck reads)
lrp = (m.lhead() + m.MAT3 + m.HS + m.ATOMS + "create_atoms 2 single -0.03 0 0.01 units box\nset atom 3 diameter 0.010 density 1500\n" + m.LRUN + "run 100\nwrite_restart lbase.restart\n")
L("E10_liggghts_restart_f_lost", "# LIGGGHTS: read_restart lbase.restart (f f f box, ids 1 type 1 4 mm, 2 type 2 6 mm, 3 type 2 10 mm; no boundary command), id 3 thrown out in run 1 (lost silently), run 100: 1 2 rows over 6 mm only?\n"
  + "atom_style granular\natom_modify map array\ncommunicate single vel yes\nnewton off\nread_restart lbase.restart\nneighbor 0.002 bin\nneigh_modify delay 0\n" + m.MAT3 + m.HS + m.LRUN + "group up id 3\nvelocity up set 0 0 200\nrun 1000\nrun 100\n")
LPREP["E10_liggghts_restart_f_lost"] = lrp

deck("S26_many_atoms_over_budget", "# S12 with runs of 300000 steps (more than the 60 s budget of runs made for real): what is said? (audited only; the engine not run: minutes)\n"
     + m.head(2, bnd="p p f", box="0 0.1 0 0.1 0 0.2") + m.G1(HK) + m.GRAV + m.FLOOR + m.TAIL
     + "lattice sc 0.0065\nregion fill block 0 0.1 0 0.1 0.005 0.05 units box\ncreate_atoms 1 region fill\nregion half block 0 0.05 INF INF INF INF units box\nset region half type 2\nset type 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\nrun 300000\n" + K5 + "run 100\n", g=1)
L("V42_liggghts_if_jump", "# LIGGGHTS: if 1 then jump e.in (e.in: e 0.3 for all pairs, run 100; the deck's lines after never run)\n" + m.LB() + m.ATOMS + m.LRUN + "if 1 then \"jump e.in\"\n" + m.E3b(0.9) + "run 100\n", data={"e.in": m.E3b(0.3) + "run 100\n"})
rr("R33_every_include", "run 100 every 50 \"include kn.in\" (kn 5000 in it: changes the contact from the second part on; deliberate refusal)", "run 100 every 50 \"include kn.in\"\n", data=KN)

U04m = HMu("1e4", "1e-3")
deck("U13_metal_from_restart", "# units metal restored by read_restart (no units line; the LAMMPS manual: units is in the restart file), pair_style and pair_coeff re-given: hertz/material as U04\n"
     + "read_restart metal.restart\ncomm_modify vel yes\npair_style granular\npair_coeff * * " + U04m + "\nfix floor all wall/gran granular " + U04m + " zplane 0 NULL\nfix integ all nve/sphere\ntimestep 1e-3\nrun 100\n", g=1)
PREP["U13_metal_from_restart"] = U04.replace("run 100\n", "run 10\nwrite_restart metal.restart\n")

deck("S27_if_include_boundary_lost", "# boundary p p f set in bnd.in, included by an if; the type 2 sphere thrown up: Lost atoms in run 1; kn 5000 after\n"
     + m.head(2).replace("boundary p p f\n", "if 1 then \"include bnd.in\"\n") + m.G1(HK) + m.GRAV + m.FLOOR + m.TAIL + TWO
     + "group t2 type 2\nvelocity t2 set 0 0 200\nrun 1000\n" + K5 + "run 100\n", g=1, data={"bnd.in": "boundary p p f\n"})
rr("R34_timeout_then_upto", "timer timeout 0:00:01 every 100 ends a 3e6-step run early (at step ~1e6 or so); timer timeout off; kn 5000; run 2000000 upto (legal only if the step is below 2e6: engine says)",
   "timer timeout 0:00:01 every 100\nrun 3000000\ntimer timeout off\n" + K5 + "run 2000000 upto\nprint \"PROBE step $(step)\"\n")


def write(name):
    m.write(name)
    d = os.path.join(m.D, name)
    if name in PREP:
        open(os.path.join(d, "prep.in"), "w").write(PREP[name])
        subprocess.run(["lmp", "-in", "prep.in", "-log", "none"], cwd=d, capture_output=True)
        os.remove(os.path.join(d, "prep.in"))
    if name in LPREP:
        open(os.path.join(d, "prep.in"), "w").write(LPREP[name])
        subprocess.run(["liggghts", "-in", "prep.in", "-log", "none"], cwd=d, capture_output=True)
        os.remove(os.path.join(d, "prep.in"))
    args = os.path.join(d, "ARGS")
    if os.path.exists(args):
        pass


if __name__ == "__main__":
    for n in (sys.argv[1:] or m.DECKS):
        write(n)
    print(len(m.DECKS), "decks")

"""Field round 25: write the decks as decks/NAME/in.deck with G, extra files and a LIGGGHTS marker, with round 23's
helpers (now tests/fieldkit/decks.py). Prefixes: M multi-run decks the engine runs to the end (outputs, slow or
file-writing fixes, pours across runs, run N every M, loops), I commands of a file an if includes (groups, regions,
region walls, pours, change_box, labelmap, variables, nested ifs, includes by an if inside the included file, LIGGGHTS),
X the engines' own example decks (copied by copy_examples below).
usage: python make_decks25.py [NAME ...]"""
import os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
from fieldkit import decks as m  # noqa: E402  (round 23's helpers, tests/fieldkit/decks.py)

m.D = os.path.join(HERE, "decks")
deck, L, BASE, TWO, hk, HK = m.deck, m.L, m.BASE, m.TWO, m.hk, m.HK
rr = lambda name, comment, lines, **kw: deck(name, "# " + comment + "\n" + BASE() + TWO + lines, g=1, **kw)
K5 = "pair_coeff * * " + hk(5000) + "\n"
K8 = "pair_coeff * * " + hk(8000) + "\n"
KN5 = {"kn.in": K5}
POUR = ("region ins block 0.005 0.035 0.005 0.035 0.06 0.09 units box\n"
        "fix p all pour 3 2 4767548 region ins diam one 0.006 dens 2500 2500\n")

# ---------------------------------------------------------------- M: multi-run decks LAMMPS runs to the end
rr("M01_two_runs_plain", "two runs, kn 5000 between: answered (kn 5000)", "run 1000\n" + K5 + "run 1000\n")
rr("M02_fix_print_file", "fix print to a file every 10 steps across two runs", "variable t equal time\nfix pr all print 10 \"$t\" file pr.txt screen no\nrun 500\n" + K5 + "run 500\n")
rr("M03_ave_time_file", "fix ave/time writing a file across runs", "compute ke all ke\nfix av all ave/time 10 5 50 c_ke file ke.txt\nrun 500\n" + K5 + "run 500\n")
rr("M04_dump_every", "dump custom every 10 across three runs", "dump d all custom 10 atoms.dump id type x y z\nrun 300\n" + K5 + "run 300\nundump d\n" + K8 + "run 300\n")
rr("M05_run_every_print", "run 1000 every 100 \"print ...\", then kn 5000 run", "run 1000 every 100 \"print 'step $(step)'\"\n" + K5 + "run 100\n")
rr("M06_loop_five_runs", "loop of 5 runs of 200 steps, kn 5000 after", "variable i loop 5\nlabel l\nrun 200\nnext i\njump SELF l\n" + K5 + "run 100\n")
rr("M07_pour_across_runs", "fix pour of type 2 across three runs (3 spheres), kn 5000 last", POUR + "run 2000\nrun 2000\n" + K5 + "run 1000\n")
rr("M08_write_restart_between", "write_restart between runs and restart every 100", "restart 100 r.*.bin\nrun 300\nwrite_restart mid.bin\n" + K5 + "run 300\n")
rr("M09_thermo_var_runs", "thermo_style custom with a variable over counts and kinetic energy across runs", "variable n equal count(all)\nvariable k equal ke\nthermo_style custom step v_n v_k\nthermo 50\nrun 500\n" + K5 + "run 500\n")
rr("M10_run_every_dump", "run 600 every 200 \"write_dump all atom d.$(step)\"", "run 600 every 200 \"write_dump all atom d.$(step).txt\"\n" + K5 + "run 100\n")
rr("M11_halt_never_met_loop", "fix halt error hard never met (v_t > 1) in a loop of runs", "variable t equal time\nfix h all halt 10 v_t > 1.0 error hard\nvariable i loop 3\nlabel l\nrun 200\nnext i\njump SELF l\n" + K5 + "run 100\n")
rr("M12_long_runs_kept", "three runs of 20000 steps (0.6 s), spheres settle, kn 5000 last", "run 20000\nrun 20000\n" + K5 + "run 20000\n")
rr("M13_pre_post_no", "run 200 pre no post no between runs", "run 200\nrun 200 pre no post no\n" + K5 + "run 200 pre no\n")
rr("M14_start_stop_series", "run 100 start 0 stop 300 three times (legal)", "run 100 start 0 stop 300\nrun 100 start 0 stop 300\n" + K5 + "run 100 start 0 stop 300\n")
rr("M15_upto_series", "run 100 upto / run 300 upto / run 500 upto", "run 100 upto\nrun 300 upto\n" + K5 + "run 500 upto\n")
rr("M16_viscous_then_unfix", "fix viscous in run 1, unfixed for run 2", "fix v all viscous 0.0001\nrun 500\nunfix v\n" + K5 + "run 500\n")
rr("M17_compute_reduce_ave", "compute reduce + fix ave/time vector file mode across runs", "compute vz all property/atom vz\ncompute mx all reduce max c_vz\nfix av all ave/time 1 10 10 c_mx file mx.txt\nrun 300\n" + K5 + "run 300\n")
rr("M18_print_append", "print ... append every loop pass", "variable i loop 4\nlabel l\nrun 100\nprint \"p $i $(step)\" append log.txt screen no\nnext i\njump SELF l\n" + K5 + "run 100\n")
rr("M19_pour_p_p_f_loop", "fix pour inside a loop of runs", POUR + "variable i loop 4\nlabel l\nrun 1000\nnext i\njump SELF l\n" + K5 + "run 100\n")
rr("M20_run_every_null_many", "run 1000 every 10 NULL then more runs", "run 1000 every 10 NULL\nrun 100\n" + K5 + "run 100\n")
rr("M21_run_every_pair_coeff", "run 200 every 100 \"pair_coeff * * hooke 5000 ...\": the contact changed between chunks", "run 200 every 100 \"" + K5.strip() + "\"\nrun 100\n")
rr("M22_timer_timeout_off_runs", "timer timeout 1:00:00 and several runs (no halt)", "timer timeout 1:00:00 every 100\nrun 500\n" + K5 + "run 500\n")
rr("M23_velocity_set_runs", "velocities set between runs (spheres thrown at 1 m/s sideways, periodic x y)", "run 100\ngroup t2 type 2\nvelocity t2 set 1 0 0\n" + K5 + "run 1000\n")
rr("M24_fix_store_state_file", "fix store/state + dump of it across runs", "fix ss all store/state 10 x y z\ndump d all custom 50 st.dump id f_ss[1]\nrun 300\n" + K5 + "run 300\n")

# ---------------------------------------------------------------- I: what a file an if includes sets
rr("I01_group_exclude", "group g2 type 2 in an if's include; neigh_modify exclude type 1 2 on groups in the deck",
   "if 1 then \"include grp.in\"\nneigh_modify exclude group g1 g2\nrun 100\n", data={"grp.in": "group g1 type 1\ngroup g2 type 2\n"})
rr("I02_exclude_in_include", "neigh_modify exclude group g1 g2 inside the included file; groups in deck",
   "group g1 type 1\ngroup g2 type 2\nif 1 then \"include ex.in\"\nrun 100\n", data={"ex.in": "neigh_modify exclude group g1 g2\n"})
rr("I03_region_create_atoms", "region + create_atoms of a third 6 mm sphere of type 1 in an include",
   "if 1 then \"include reg.in\"\nset type 1 diameter 0.004 density 2500\n" + K5 + "run 100\n",
   data={"reg.in": "region r block 0.025 0.035 0.025 0.035 0.02 0.03 units box\ncreate_atoms 1 single 0.03 0.03 0.025\n"})
rr("I04_region_wall", "fix wall/gran/region in an include (kn 5000 region wall), deck's floor kept",
   "if 1 then \"include rw.in\"\nrun 100\n",
   data={"rw.in": "region cyl cylinder z 0.02 0.02 0.019 0 0.1 side in units box\nfix rw all wall/gran/region granular " + hk(5000) + " region cyl\n"})
rr("I05_pour_in_include", "a fix pour of type 2 at 3 mm diameter in an include, run for the spheres to land",
   "if 1 then \"include pour.in\"\nrun 5000\n",
   data={"pour.in": "region ins block 0.005 0.035 0.005 0.035 0.06 0.09 units box\nfix p all pour 3 2 4767548 region ins diam one 0.003 dens 2500 2500\n"})
rr("I06_change_box_in_include", "change_box all boundary p p p in an include (floor still there)",
   "if 1 then \"include cb.in\"\n" + K5 + "run 100\n", data={"cb.in": "change_box all z final 0 0.2 units box\n"})
rr("I07_labelmap_in_include", "labelmap in an include; pair_coeff small big kn 8000 in the deck",
   "if 1 then \"include lm.in\"\npair_coeff small big " + hk(8000) + "\nrun 100\n", data={"lm.in": "labelmap atom 1 small 2 big\n"})
rr("I08_variable_in_include", "variable kn equal 5000 in an include; pair_coeff with ${kn} in the deck",
   "if 1 then \"include var.in\"\npair_coeff * * hooke ${kn} 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n",
   data={"var.in": "variable kn equal 5000\n"})
rr("I09_nested_if", "if 1 then 'if 1 then \"include kn.in\"'", "if 1 then 'if 1 then \"include kn.in\"'\nrun 100\n", data=KN5)
rr("I10_include_with_if_include", "the included file itself includes by an if", "if 1 then \"include a.in\"\nrun 100\n",
   data={"a.in": "if 1 then \"include kn.in\"\n", **KN5})
rr("I11_plain_include_with_if_include", "plain include of a file whose if includes kn.in", "include a.in\nrun 100\n",
   data={"a.in": "variable u equal 1\nif \"${u} == 1\" then \"include kn.in\"\n", **KN5})
rr("I12_else_branch", "if 0 then \"print no\" else \"include kn.in\"", "if 0 then \"print no\" else \"include kn.in\"\nrun 100\n", data=KN5)
rr("I13_elif_branch", "if 0 then ... elif 1 \"include kn.in\"", "if 0 then \"print no\" elif 1 \"include kn.in\" else \"print no2\"\nrun 100\n", data=KN5)
rr("I14_if_include_in_loop", "include kn.in by an if on pass 2 of a loop, a run per pass",
   "variable i loop 3\nlabel l\nif \"$i == 2\" then \"include kn.in\"\nrun 100\nnext i\njump SELF l\n", data=KN5)
rr("I15_viscous_group_in_include", "group + fix viscous on type 2 in an include",
   "if 1 then \"include v.in\"\nrun 100\n", data={"v.in": "group g2 type 2\nfix v g2 viscous 0.0005\n"})
rr("I16_pair_12_and_run", "include sets pair_coeff 1 2 kn 8000 and runs; main continues with a run",
   "if 1 then \"include p.in\"\nrun 100\n", data={"p.in": "pair_coeff 1 2 " + hk(8000) + "\nrun 100\n"})
rr("I17_delete_type2_in_include", "the include deletes the type 2 sphere and creates a 4 mm type 1 sphere",
   "if 1 then \"include d.in\"\nset type 1 diameter 0.004 density 2500\nrun 100\n",
   data={"d.in": "group g2 type 2\ndelete_atoms group g2\ncreate_atoms 1 single 0.03 0.03 0.01\n"})
rr("I18_if_include_variable_index", "variable f index kn.in redefined? include ${f} in an if", "variable f index kn.in\nif 1 then \"include ${f}\"\nrun 100\n", data=KN5)
rr("I19_wall_replaced_in_include", "unfix floor + fix floor kn 8000 in an include", "if 1 then \"include w.in\"\nrun 100\n",
   data={"w.in": "unfix floor\nfix floor all wall/gran granular " + hk(8000) + " zplane 0 NULL\n"})
rr("I20_include_kn_then_if_clear", "include by an if, then the included file's law replaced back in the deck", "if 1 then \"include kn.in\"\n" + K8 + "run 100\n", data=KN5)
rr("I21_if_include_two_files", "if 1 then \"include a.in\" \"include b.in\" (kn 5000 then 1 2 kn 8000)", "if 1 then \"include a.in\" \"include b.in\"\nrun 100\n",
   data={"a.in": K5, "b.in": "pair_coeff 1 2 " + hk(8000) + "\n"})
rr("I22_if_include_set_density", "set type 2 density 7800 in an include", "if 1 then \"include s.in\"\nrun 100\n", data={"s.in": "set type 2 density 7800\n"})

# ---------------------------------------------------------------- L: LIGGGHTS forms
LW = m.lhead() + m.MAT3
L("I23_liggghts_if_include_e", "# LIGGGHTS: e matrix (0.3) in an include by an if\n" + LW + "if 1 then \"include e.in\"\n" + m.HERTZ + m.WALL3 + m.ATOMS + m.RUN,
  g=1, data={"e.in": m.E3b(0.3)})
L("I24_liggghts_if_include_e_override", "# LIGGGHTS: e 0.6.. matrix in deck, then e 0.3 in an include by an if before the run\n" + LW + m.E3 + m.HERTZ + m.WALL3 + m.ATOMS + "if 1 then \"include e.in\"\n" + m.RUN,
  g=1, data={"e.in": "fix m3 all property/global coefficientRestitution peratomtypepair 3 " + " ".join(["0.3"] * 9) + "\n"})
L("I25_liggghts_include_runs", "# LIGGGHTS: multi-run, e changed between runs (0.6.. then 0.3)\n" + m.LB() + m.ATOMS + m.RUN + m.E3b(0.3) + "run 1000\n", g=1)
L("I26_liggghts_insert_across_runs", "# LIGGGHTS: insertion of type 2 across two runs (f f f box)\n" + m.LB() +
  "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 2500 radius constant 0.003\n"
  "fix pdd all particledistribution/discrete 32452843 1 pts2 1.0\n"
  "region ins block -0.03 0.03 -0.03 0.03 0.08 0.12 units box\n"
  "fix ins all insert/pack seed 86028157 distributiontemplate pdd insert_every 2000 overlapcheck yes all_in yes particles_in_region 3 region ins\n"
  + m.ATOMS + m.LRUN + "run 2000\nrun 2000\n" + m.E3b(0.3) + "run 1000\n", g=1)

# ---------------------------------------------------------------- second set (added mid-round)
rr("M25_run_every_variable", "run 1000 every 100 \"variable x equal $(step)\" (round 24's R24: no contact change)", "run 1000 every 100 \"variable x equal $(step)\"\n" + K5 + "run 100\n")
rr("M26_loop_break_if", "loop of runs broken by an if jump on pass 3", "variable i loop 10\nlabel l\nrun 100\nif \"$i == 3\" then \"jump SELF done\"\nnext i\njump SELF l\nlabel done\n" + K5 + "run 100\n")
rr("M27_run_zero_series", "run 0 three times then kn 5000 run 0", "run 0\nrun 0\n" + K5 + "run 0\n")
rr("M28_deposit_across_runs", "fix deposit of type 2 (diameter set by a molecule-free set after) across runs",
   "region ins block 0.005 0.035 0.005 0.035 0.06 0.09 units box\nfix dp all deposit 2 2 500 12345 region ins near 0.007 vz -0.1 -0.1\n"
   "run 1000\nset type 2 diameter 0.006 density 2500\nrun 1000\n" + K5 + "run 100\n")
rr("M29_run_every_two_cmds", "run 300 every 100 \"print a\" \"variable y equal 2\" then kn 5000", "run 300 every 100 \"print a\" \"variable y equal 2\"\n" + K5 + "run 100\n")
rr("I27_include_jump_loop", "an if includes a file that loops runs with jump SELF", "if 1 then \"include loop.in\"\n" + K5 + "run 100\n",
   data={"loop.in": "variable j loop 3\nlabel lj\nrun 100\nnext j\njump SELF lj\n"})
rr("I28_include_if_pair_coeff", "include a file whose if sets pair_coeff directly", "include a.in\nrun 100\n", data={"a.in": "if 1 then \"" + K5.strip() + "\"\n"})
rr("I29_if_include_pair_style", "pair_style gran/hooke 5000 ... in an if's include", "if 1 then \"include ps.in\"\nrun 100\n",
   data={"ps.in": "pair_style gran/hooke 5000 NULL 3000 NULL 0 0\npair_coeff * *\n"})
rr("I30_if_include_region_wall_region_in_deck", "region in the deck, wall/gran/region kn 8000 in the include", "region cyl cylinder z 0.02 0.02 0.019 0 0.1 side in units box\nif 1 then \"include rw.in\"\nrun 100\n",
   data={"rw.in": "fix rw all wall/gran/region granular " + hk(8000) + " region cyl\n"})
rr("I31_if_include_run_every", "an if includes a file with run 200 every 100 \"print x\" then kn 5000", "if 1 then \"include re.in\"\n" + K5 + "run 100\n",
   data={"re.in": "run 200 every 100 \"print x\"\n"})
rr("I32_if_include_timestep", "timestep 2e-5 in an if's include, then runs", "if 1 then \"include ts.in\"\nrun 100\n", data={"ts.in": "timestep 2e-5\n"})

# ---------------------------------------------------------------- third set
rr("M30_halt_continue_met", "fix halt error continue met in run 1, later runs go on (kn 5000)", "variable t equal time\nfix h all halt 10 v_t > 0.0005 error continue\nrun 100\nunfix h\n" + K5 + "run 100\n")
rr("M31_timeout_not_hit", "timer timeout 0:10:00 every 10 over several short runs", "timer timeout 0:10:00 every 10\nrun 200\nrun 200\n" + K5 + "run 200\n")
rr("M32_ave_histo_correlate", "fix ave/histo and ave/correlate writing files across runs", "compute vz all property/atom vz\nfix hi all ave/histo 10 5 50 -1 1 10 c_vz mode vector file h.txt\nvariable k equal vcm(all,z)\nfix co all ave/correlate 10 5 50 v_k file c.txt\nrun 300\n" + K5 + "run 300\n")
rr("M33_many_atoms_runs", "300 type 1 spheres of 2 mm in a lattice-free random fill, three runs of 5000 steps", "region fill block 0.002 0.038 0.002 0.038 0.02 0.09 units box\ncreate_atoms 1 random 300 4242 fill overlap 0.0021\nset type 1 diameter 0.004 density 2500\nrun 5000\nrun 5000\n" + K5 + "run 5000\n")
rr("M34_unfix_integ_between", "no integrator in run 2 (unfix integ), refixed for run 3", "run 100\nunfix integ\nrun 100\nfix integ all nve/sphere\n" + K5 + "run 100\n")
rr("M35_velocity_create_between", "velocity all create between runs (random, p p f)", "run 100\nvelocity all create 0.0 4928 units box\nvelocity all set 0.1 0.1 0 sum yes units box\n" + K5 + "run 500\n")
rr("M36_shell_between", "shell echo between runs", "run 100\nshell echo hello\n" + K5 + "run 100\n")
rr("M37_if_on_state", "an if on the centre-of-mass speed after run 1 (falling spheres: kn 5000, else kn 8000)", "run 300\nvariable v equal vcm(all,z)\nif \"${v} < -0.01\" then \"" + K5.strip() + "\" else \"" + K8.strip() + "\"\nrun 100\n")
rr("M38_if_on_step", "an if on $(step) after two runs", "run 100\nrun 100\nif \"$(step) >= 200\" then \"" + K8.strip() + "\"\nrun 100\n")
rr("M39_include_per_pass", "a loop including kn${i}.in on each pass", "variable i loop 2\nlabel l\ninclude kn$i.in\nrun 100\nnext i\njump SELF l\n",
   data={"kn1.in": K5, "kn2.in": K8})
rr("M40_delete_overlap_between", "delete_atoms overlap between runs (no overlap: nothing deleted)", "run 100\ndelete_atoms overlap 0.0001 all all\n" + K5 + "run 100\n")
rr("I33_exclude_then_none", "neigh_modify exclude type 1 2 in an if's include, exclude none in the deck", "if 1 then \"include ex.in\"\nneigh_modify exclude none\nrun 100\n", data={"ex.in": "neigh_modify exclude type 1 2\n"})
rr("I34_freeze_group_in_include", "fix freeze on type 2 in an if's include", "if 1 then \"include fr.in\"\nrun 100\n", data={"fr.in": "group g2 type 2\nfix fz g2 freeze\n"})
rr("I35_random_atoms_in_include", "create_atoms random 5 of type 2 (3 mm via set in include) in an if's include", "if 1 then \"include ra.in\"\nrun 100\n",
   data={"ra.in": "region top block 0.005 0.035 0.005 0.035 0.05 0.09 units box\ncreate_atoms 2 random 5 777 top\nset type 2 diameter 0.003 density 2500\n"})
rr("I36_restart_or_include", "if \"${restart} == 1\" then \"read_restart x\" else \"include kn.in\" with restart 0", "variable restart index 0\nif \"${restart} == 1\" then \"read_restart x.bin\" else \"include kn.in\"\nrun 100\n", data=KN5)
rr("I37_if_include_quoted_triple", "if with triple-quoted commands containing include", "if 1 then \"\"\"include kn.in\"\"\"\nrun 100\n", data=KN5)
rr("I38_if_include_semicolon_like_two", "if 1 then \"include kn.in\" \"pair_coeff 1 1 hooke 8000 ...\"", "if 1 then \"include kn.in\" \"pair_coeff 1 1 " + hk(8000) + "\"\nrun 100\n", data=KN5)
rr("I39_if_include_group_wall", "a wall on group g1 only (group and wall in the include)", "unfix floor\nif 1 then \"include gw.in\"\nrun 100\n",
   data={"gw.in": "group g1 type 1\nfix floor g1 wall/gran granular " + hk(5000) + " zplane 0 NULL\n"})
L("I40_liggghts_plain_include_if_direct", "# LIGGGHTS: a plain include whose if sets e 0.3 directly\n" + LW + m.E3 + "include e.in\n" + m.HERTZ + m.WALL3 + m.ATOMS + m.RUN,
  g=1, data={"e.in": "if 1 then \"fix m3 all property/global coefficientRestitution peratomtypepair 3 " + " ".join(["0.3"] * 9) + "\"\n"})
L("I41_liggghts_if_jump_label", "# LIGGGHTS: if 1 then \"jump e.in lab\", e.in sets e 0.3 after a label and jumps back\n" + LW + m.E3 + "if 1 then \"jump e.in lab\"\nlabel back\n" + m.HERTZ + m.WALL3 + m.ATOMS + m.RUN,
  g=1, data={"e.in": "print skipped\nlabel lab\nfix m3 all property/global coefficientRestitution peratomtypepair 3 " + " ".join(["0.3"] * 9) + "\njump in.deck back\n"})

# ---------------------------------------------------------------- fourth set: what a run writes, read back later by the deck
REST = lambda: BASE().replace("create_box 2 box\n", "create_box 2 box\n")
rr("M41_print_file_subdir", "fix print into out/ (a folder of the deck) across runs", "variable t equal time\nfix pr all print 10 \"$t\" file out/pr.txt screen no\nrun 300\n" + K5 + "run 300\n", data={"out/keep.txt": "x\n"})
rr("M42_read_dump_of_run", "a dump written in run 1 read back (read_dump) before run 2", "dump d all custom 100 a.dump id type x y z vx vy vz\nrun 100\nundump d\nread_dump a.dump 100 x y z vx vy vz\n" + K5 + "run 100\n")
rr("M43_include_file_fix_print_wrote", "fix print writes a pair_coeff line in run 1; the deck includes that file before run 2",
   "fix pr all print 100 \"" + K5.strip() + "\" file gen.in screen no\nrun 100\nunfix pr\ninclude gen.in\nrun 100\n")
rr("M44_variable_file_print_wrote", "a print ... file writes 5000 after run 1; variable file reads it; pair_coeff ${k}",
   "run 100\nprint \"5000\" file k.txt screen no\nvariable k file k.txt\npair_coeff * * hooke ${k} 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n")
rr("M45_restart_during_run_read_back", "restart 100 r.bin written during run 1; clear; read_restart r.bin; kn 5000",
   "restart 100 r.bin\nrun 200\nclear\nread_restart r.bin\ncomm_modify vel yes\npair_coeff * * " + hk(5000) + "\nfix grav all gravity 9.81 vector 0 0 -1\nfix floor all wall/gran granular " + hk(5000) + " zplane 0 NULL\nfix integ all nve/sphere\ntimestep 1e-5\nrun 100\n")
rr("M46_fix_ave_time_file_read_as_variable", "fix ave/time of step writes a file; after the run a variable file reads it (not a number: engine decides)",
   "variable s equal step\nfix av all ave/time 100 1 100 v_s file s.txt\nrun 100\nunfix av\nvariable st file s.txt\nprint \"read ${st}\"\n" + K5 + "run 100\n")
rr("M47_write_data_read_data_add", "write_data between runs, delete all, read_data of it", "run 100\nwrite_data w.data\ndelete_atoms group all\nread_data w.data add append\n" + K5 + "run 100\n")
rr("M48_include_log_of_print_append", "print ... append each pass writes pair_coeff lines; the deck includes the file after the loop",
   "variable i loop 2\nlabel l\nrun 100\nprint \"" + K5.strip() + "\" append gen.in screen no\nnext i\njump SELF l\ninclude gen.in\nrun 100\n")
rr("M49_dump_then_rerun", "dump written in run 1, rerun of it (rerun re-reads the dump) then a run", "dump d all custom 50 a.dump id type x y z\nrun 100\nundump d\nrerun a.dump dump x y z\n" + K5 + "run 100\n")

# ---------------------------------------------------------------- fifth set: LIGGGHTS multi-run decks it runs to the end
LG = lambda: m.LB() + m.ATOMS + m.LRUN
L("M50_liggghts_loop_runs", "# LIGGGHTS: a loop of 4 runs, e 0.3 after\n" + LG() + "variable i loop 4\nlabel l\nrun 200\nnext i\njump SELF l\n" + m.E3b(0.3) + "run 100\n", g=1)
L("M51_liggghts_print_dump_files", "# LIGGGHTS: fix print file and dump every 50 across runs, e 0.3 after\n" + LG()
  + "variable t equal time\nfix pr all print 50 \"$t\" file pr.txt screen no\ndump d all custom 50 a.dump id type x y z\nrun 300\n" + m.E3b(0.3) + "run 300\n", g=1)
L("M52_liggghts_upto_series", "# LIGGGHTS: run 100 upto, run 300 upto, e 0.3, run 500 upto\n" + LG() + "run 100 upto\nrun 300 upto\n" + m.E3b(0.3) + "run 500 upto\n", g=1)
L("M53_liggghts_ave_time_file", "# LIGGGHTS: fix ave/time file across runs\n" + LG() + "compute ke all ke\nfix av all ave/time 10 5 50 c_ke file ke.txt\nrun 300\n" + m.E3b(0.3) + "run 300\n", g=1)
L("M54_liggghts_long_runs", "# LIGGGHTS: three runs of 20000 steps, e 0.3 last\n" + LG() + "run 20000\nrun 20000\n" + m.E3b(0.3) + "run 20000\n", g=1)
L("M55_liggghts_halt_never", "# LIGGGHTS: fix halt never met, multi-run\n" + LG() + "variable t equal time\nfix h all halt 10 v_t > 1.0 error hard\nrun 300\n" + m.E3b(0.3) + "run 300\n", g=1)

# ---------------------------------------------------------------- sixth set: more of what an if's include can do
rr("I42_if_include_quit", "run 1, an if's include quits, kn 5000 never reached", "run 100\nif 1 then \"include q.in\"\n" + K5 + "run 100\n", data={"q.in": "quit\n"})
rr("I43_if_include_jump_to_label", "an if's include jumps to a label in the deck, skipping kn 5000", "if 1 then \"include j.in\"\n" + K5 + "label skip\nrun 100\n", data={"j.in": "jump in.deck skip\n"})
rr("I44_index_not_redefined", "variable kn index 2000 in the deck; the if's include says index 5000 (LAMMPS keeps 2000)",
   "variable kn index 2000\nif 1 then \"include v.in\"\npair_coeff * * hooke ${kn} 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n", data={"v.in": "variable kn index 5000\n"})
rr("I45_delete_redefine", "variable kn equal 2000; the if's include deletes it and sets 5000", "variable kn equal 2000\nif 1 then \"include v.in\"\npair_coeff * * hooke ${kn} 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 100\n",
   data={"v.in": "variable kn delete\nvariable kn equal 5000\n"})
rr("I46_continuation_no_newline", "the included file: pair_coeff with & continuation, no final newline", "if 1 then \"include kn.in\"\nrun 100\n",
   data={"kn.in": "pair_coeff * * hooke 5000 3000 &\n  damping mass_velocity tangential linear_nohistory 1 0.3"})
rr("I47_immediate_count", "the included file: pair_coeff hooke $(2500*count(all))", "if 1 then \"include kn.in\"\nrun 100\n",
   data={"kn.in": "pair_coeff * * hooke $(2500*count(all)) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n"})
rr("I48_if_include_clear_rebuild", "an if's include clears and rebuilds the whole deck with kn 5000", "run 100\nif 1 then \"include new.in\"\nrun 100\n",
   data={"new.in": "clear\n" + BASE().replace(HK, hk(5000)) + TWO})
rr("I49_if_include_log", "an if's include opens a log file (log sub.log append)", "if 1 then \"include lg.in\"\n" + K5 + "run 100\n", data={"lg.in": "log sub.log append\n"})
rr("I50_if_include_in_jumped_file", "jump to a file whose if includes kn.in", "jump j.in\n", data={"j.in": "if 1 then \"include kn.in\"\nrun 100\n", **KN5})

# ---------------------------------------------------------------- seventh set: slow multi-run decks
rr("M56_many_atoms_slow_runs", "3267 spheres of 1 mm on a lattice (type 1), two runs of 3000 steps, kn 5000 last run",
   "region lay block 0 0.04 0 0.04 0.02 0.0236 units box\nlattice sc 0.0012\ncreate_atoms 1 region lay\nset type 1 diameter 0.001 density 2500\n"
   "run 3000\nrun 3000\n" + K5 + "run 100\n")
rr("M57_dump_image_runs", "dump image every 50 across runs", "dump im all image 50 img.*.ppm type type\nrun 200\n" + K5 + "run 200\n")

# ---------------------------------------------------------------- eighth set: outputs into a folder a shell command makes
rr("M58_shell_mkdir_fix_print", "shell mkdir out, then fix print into out/ across runs", "shell mkdir out\nvariable t equal time\nfix pr all print 10 \"$t\" file out/pr.txt screen no\nrun 100\n" + K5 + "run 100\n")
rr("M59_shell_mkdir_dump", "shell mkdir post, dump into post/ across runs", "shell mkdir post\ndump d all custom 10 post/a.*.dump id type x y z\nrun 100\n" + K5 + "run 100\n")
rr("M60_shell_mkdir_ave_time", "shell mkdir out, fix ave/time into out/ across runs", "shell mkdir out\ncompute ke all ke\nfix av all ave/time 10 5 50 c_ke file out/ke.txt\nrun 100\n" + K5 + "run 100\n")
L("M61_liggghts_shell_mkdir_dump", "# LIGGGHTS: shell mkdir post, dump into post/ across runs\n" + m.LB() + m.ATOMS + m.LRUN
  + "shell mkdir post\ndump d all custom 50 post/a.*.dump id type x y z\nrun 300\n" + m.E3b(0.3) + "run 300\n", g=1)
rr("M62_shell_mkdir_restart", "shell mkdir rs, restart files into rs/ across runs", "shell mkdir rs\nrestart 50 rs/r.*.bin\nrun 100\n" + K5 + "run 100\n")

# ---------------------------------------------------------------- ninth set: paths, many passes, variables in conditions
rr("M63_loop_2000_runs", "a loop of 2000 runs of 10 steps, kn 5000 after", "variable i loop 2000\nlabel l\nrun 10\nnext i\njump SELF l\n" + K5 + "run 10\n")
rr("I51_include_subdir_chain", "if 1 then \"include sub/a.in\", sub/a.in includes sub/b.in (paths from the working folder)", "if 1 then \"include sub/a.in\"\nrun 100\n",
   data={"sub/a.in": "include sub/b.in\n", "sub/b.in": K5})
rr("I52_include_relative_to_cwd", "sub/a.in says include b.in: LAMMPS opens ./b.in (kn 8000), not sub/b.in (kn 5000)", "if 1 then \"include sub/a.in\"\nrun 100\n",
   data={"sub/a.in": "include b.in\n", "sub/b.in": K5, "b.in": K8})
rr("I53_variable_in_condition", "the if's include sets use5 = 1; a later if on it sets kn 5000", "if 1 then \"include v.in\"\nif \"${use5} == 1\" then \"" + K5.strip() + "\"\nrun 100\n",
   data={"v.in": "variable use5 equal 1\n"})
rr("I54_if_include_sets_loop_count", "the if's include sets the loop count n = 3; each pass includes kn$i.in? no: pass 3 sets kn 8000", "if 1 then \"include n.in\"\nvariable i loop ${n}\nlabel l\nif \"$i == 3\" then \"" + K8.strip() + "\"\nrun 50\nnext i\njump SELF l\n",
   data={"n.in": "variable n equal 3\n"})

rr("I55_labelmap_include_pour_label", "labelmap in an if's include; fix pour of type big (3 mm) in the deck", "if 1 then \"include lm.in\"\nregion ins block 0.005 0.035 0.005 0.035 0.06 0.09 units box\nfix p all pour 3 big 4767548 region ins diam one 0.003 dens 2500 2500\nrun 5000\n",
   data={"lm.in": "labelmap atom 1 small 2 big\n"})
rr("I56_labelmap_include_set_label", "labelmap in an if's include; set type big density 7800 in the deck", "if 1 then \"include lm.in\"\nset type big density 7800\nrun 100\n",
   data={"lm.in": "labelmap atom 1 small 2 big\n"})

# ---------------------------------------------------------------- tenth set: absolute output paths across runs (escape and refusal)
rr("M64_abs_fix_print", "shell mkdir -p /tmp/f25abs, fix print into it across runs", "shell mkdir -p /tmp/f25abs\nvariable t equal time\nfix pr all print 10 \"$t\" file /tmp/f25abs/pr.txt screen no\nrun 100\n" + K5 + "run 100\n")
rr("M65_abs_dump_restart", "dump and restart files under /tmp/f25abs2 (made by shell) across runs", "shell mkdir -p /tmp/f25abs2\ndump d all atom 10 /tmp/f25abs2/a.dump\nrestart 50 /tmp/f25abs2/r.*.bin\nrun 100\nwrite_restart /tmp/f25abs2/w.bin\n" + K5 + "run 100\n")

L("M66_liggghts_run_every_print", "# LIGGGHTS: run 300 every 100 \"print hi\", e 0.3, run 100\n" + m.LB() + m.ATOMS + m.LRUN + "run 300 every 100 \"print hi\"\n" + m.E3b(0.3) + "run 100\n", g=1)
L("M67_liggghts_loop_if_e", "# LIGGGHTS: loop of 3 runs; pass 2 sets e 0.3 by an if\n" + m.LB() + m.ATOMS + m.LRUN + "variable i loop 3\nlabel l\nif \"$i == 2\" then \"" + m.E3b(0.3).strip() + "\"\nrun 100\nnext i\njump SELF l\n", g=1)


def copy_examples():
    m.copy_examples([("X01_lammps_pour_drum", "granular", "in.pour.drum"), ("X02_lammps_pour", "pour", "in.pour"),
                     ("X03_lammps_pour_flatwall", "granular", "in.pour.flatwall"),
                     ("X04_lammps_granregion_box", "granregion", "in.granregion.box"),
                     ("X05_lammps_granregion_funnel", "granregion", "in.granregion.funnel"),
                     ("X06_lammps_granregion_mixer", "granregion", "in.granregion.mixer")],
                    [("packing", "in.packing"), ("insert_stream", "in.insert_stream"), ("cohesion", "in.cohesion"),
                     ("hysteresis", "in.hysteresis"), ("contactModels", "in.newModels"), ("conveyor", "in.conveyor"),
                     ("insert_stream", "in.insert_stream_reset_timestep"), ("cohesion", "in.noCohesion"),
                     ("contactModels", "in.oldModels"), ("hysteresis", "in.noHysteresis"),
                     ("movingMeshGran", "in.movingMeshGran"), ("chute_wear", "in.chute_wear")])


if __name__ == "__main__":
    for n in (sys.argv[1:] or m.DECKS):
        m.write(n)
    if not sys.argv[1:]:
        copy_examples()
    print(len(m.DECKS), "decks")

"""Field round 25: write the decks as decks/NAME/in.deck with G, extra files and a LIGGGHTS marker, with round 23's
helpers (make_decks23.py, imported). Prefixes: M multi-run decks the engine runs to the end (outputs, slow or
file-writing fixes, pours across runs, run N every M, loops), I commands of a file an if includes (groups, regions,
region walls, pours, change_box, labelmap, variables, nested ifs, includes by an if inside the included file, LIGGGHTS),
X the engines' own example decks (copied by copy_examples below).
usage: python make_decks25.py [NAME ...]"""
import os, shutil, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field23"))
import make_decks23 as m  # noqa: E402

m.DECKS.clear()
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


def copy_examples():
    ex = [("X01_lammps_pour_drum", "/usr/share/lammps/examples/granular", "in.pour.drum", False),
          ("X02_lammps_pour", "/usr/share/lammps/examples/pour", "in.pour", False),
          ("X03_lammps_pour_flatwall", "/usr/share/lammps/examples/granular", "in.pour.flatwall", False)]
    T = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public"
    for t, f in (("packing", "in.packing"), ("insert_stream", "in.insert_stream"), ("cohesion", "in.cohesion"),
                 ("hysteresis", "in.hysteresis"), ("contactModels", "in.newModels"), ("conveyor", "in.conveyor")):
        ex.append(("X_lig_" + t + "_" + f[3:], os.path.join(T, t), f, True))
    for name, src, f, lig in ex:
        d = os.path.join(m.D, name)
        if os.path.exists(d):
            continue
        if lig:
            shutil.copytree(src, d)
            open(os.path.join(d, "LIGGGHTS"), "w").write("")
        else:
            os.makedirs(d)
            shutil.copy(os.path.join(src, f), d)
            for extra in os.listdir(src):
                if extra.startswith("molecule") or extra.endswith(".mol"):
                    shutil.copy(os.path.join(src, extra), d)
        open(os.path.join(d, "DECK"), "w").write(f + "\n")
        open(os.path.join(d, "G"), "w").write("1\n")


if __name__ == "__main__":
    for n in (sys.argv[1:] or m.DECKS):
        m.write(n)
    if not sys.argv[1:]:
        copy_examples()
    print(len(m.DECKS), "decks")

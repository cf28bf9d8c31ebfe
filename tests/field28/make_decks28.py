"""Field round 28: write the decks as decks/NAME/in.deck (G, LIVE, SEP, extra files, LIGGGHTS marker), with round 27's
helpers (base: kn 2000 everywhere, dt 1e-6; the LIVE pair: two spheres far above the floor approaching at 1 m/s, timed to
meet in the run named in LIVE, refereed by live28.py running the deck as written).
Prefixes: V run N every M with variables of the step/time and $(dt), D types emptied or refilled between runs (and
position-dependent commands after skipped runs), Q run pre no, N neighbour reach, H hybrid, C clear / lost / restart,
O older classes mixed in, L LIGGGHTS.   usage: python make_decks28.py [NAME ...]"""
import os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field27"))
import make_decks27 as r  # noqa: E402

m = r.m
m.DECKS.clear(); r.LIVE.clear()
m.D = os.path.join(HERE, "decks")
deck, hk, HK, K, TL, head, GRAV, HM = m.deck, m.hk, m.HK, m.K, m.TL, m.head, m.GRAV, m.HM
LIVE = r.LIVE
BL, FL, E, P5, P8, R3, lv, lvw, W, Ll, E3x = r.BL, r.FL, r.E, r.P5, r.P8, r.R3, r.lv, r.lvw, r.W, r.Ll, r.E3x
TAILL = r.TAILL
P3 = lambda i="1", j="2": P5(i, j, 3000)
EXTRA = {}


def lvi(gap, ids=(3, 4), ta=1, tb=2, da=0.004, db=0.006, x0=0.02, z=0.05, remap=""):
    """the live pair made after other atoms: ids (ia, ib); ta on the left; approaching at 1 m/s from gap"""
    xa, xb = x0 - da / 2 - gap / 2, x0 + db / 2 + gap / 2
    va, vb = db ** 3 / (da ** 3 + db ** 3), -da ** 3 / (da ** 3 + db ** 3)
    ia, ib = ids
    return (f"create_atoms {ta} single {xa:.9g} 0.02 {z}{remap}\ncreate_atoms {tb} single {xb:.9g} 0.02 {z}{remap}\n"
            f"set atom {ia} diameter {da} density 2500\nset atom {ib} diameter {db} density 2500\n"
            f"group lv1 id {ia}\ngroup lv2 id {ib}\nvelocity lv1 set {va:.10f} 0 0 units box\nvelocity lv2 set {vb:.10f} 0 0 units box\n")


VIC = ("create_atoms 1 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.03 0.03 0.01\n"
       "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\n")
XA0 = lambda gap: 0.02 - 0.002 - gap / 2           # lv1's centre x at the start
XA1 = lambda gap, t=1e-3: XA0(gap) + t * 216 / 280  # after t seconds
IFS = lambda cond: f'if "{cond}" then "{P5()}" else "{P8()}"\n'

# ------------------------------------------------------------ V: every with step/time variables and $(dt)
VS = R3.format("variable s equal $(step)")
E("V01_step_if_elif", "every variable s equal $(step); if s==1000 kn 8000 elif s==3000 kn 5000 else kn 1000; run 1000",
  VS + f'if "${{s}} == 1000" then "{P8()}" elif "${{s}} == 3000" "{P5()}" else "{P5("1", "2", 1000)}"\nrun 1000\n', gap=3.1e-3)
E("V02_step_loop_after", "every variable s; n = s/1000; loop i 1..n: pair_coeff 1 2 kn 1000*i+2000 (last 5000); run 1000",
  VS + "variable n equal ${s}/1000\nvariable i loop ${n}\nlabel l\npair_coeff 1 2 hooke $(1000*v_i+2000) 3000 " + K + "\nnext i\njump SELF l\nrun 1000\n", gap=3.1e-3)
E("V03_time_dtchange_hi", "every timestep 5e-7 + variable t equal $(time) (LAMMPS t 2e-3); if t > 0.0025 kn 8000 else 5000; run 2000",
  'run 3000 every 1000 "timestep 5e-7" "variable t equal $(time)"\n' + f'if "${{t}} > 0.0025" then "{P8()}" else "{P5()}"\n' + "run 2000\n", gap=2.1e-3)
E("V04_time_dtchange_lo", "as V03 with if t > 0.0017 then kn 5000 else 8000 (LAMMPS t 2e-3: kn 5000)",
  'run 3000 every 1000 "timestep 5e-7" "variable t equal $(time)"\n' + IFS("${t} > 0.0017") + "run 2000\n", gap=2.1e-3)
E("V05_index_not_redefined", "every variable s index $(step): an index variable is not redefined (s stays 1000); if s==1000 kn 5000 else 8000",
  R3.format("variable s index $(step)") + IFS("${s} == 1000") + "run 1000\n", gap=3.1e-3)
E("V06_string_step", "every variable s string $(step) (3000); if s==3000 kn 5000 else 8000",
  R3.format("variable s string $(step)") + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
E("V07_internal_step", "every variable s internal $(step) (3000); if s==3000 kn 5000 else 8000",
  R3.format("variable s internal $(step)") + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
E("V08_not_multiple_step", "run 2500 every 1000 variable s equal $(step) (2500 at the end); if s==2500 kn 5000 else 8000",
  'run 2500 every 1000 "variable s equal $(step)"\n' + IFS("${s} == 2500") + "run 1000\n", gap=2.6e-3)
E("V09_start_stop_step", "run 3000 start 0 stop 5000 every 1000 variable s; if s==3000 kn 5000 else 8000",
  'run 3000 start 0 stop 5000 every 1000 "variable s equal $(step)"\n' + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
E("V10_reset_timestep_step", "reset_timestep 5000; every variable s (8000); if s==8000 kn 5000 else 8000",
  "reset_timestep 5000\n" + VS + IFS("${s} == 8000") + "run 1000\n", gap=3.1e-3)
E("V11_after_run_step", "run 1000 then every variable s (4000); if s==4000 kn 5000 else 8000",
  "run 1000\n" + VS + IFS("${s} == 4000") + "run 1000\n", gap=4.1e-3)
E("V12_step_to_kn", "every variable k equal $(step+2000) (5000); pair_coeff 1 2 hooke ${k}; run 1000",
  R3.format("variable k equal $(step+2000)") + "pair_coeff 1 2 hooke ${k} 3000 " + K + "\nrun 1000\n", gap=3.1e-3)
E("V13_lazy_second_var", "every variable s; variable b equal v_s*2 (6000); if b==6000 kn 5000 else 8000",
  VS + "variable b equal v_s*2\n" + IFS("${b} == 6000") + "run 1000\n", gap=3.1e-3)
E("V14_print_other_vars", "variable k equal 5000; every print with ${k} $(v_k) $(step) and pair_coeff 1 2 kn 5000",
  "variable k equal 5000\n" + 'run 3000 every 1000 \'print "k ${k} $(v_k) $(step)"\' "' + P5() + '"\n')
E("V15_triple_quote", "every with a triple-quoted pair_coeff and a single-quoted print", 'run 3000 every 1000 """' + P5() + '""" \'print "x y"\'\n')
E("V16_dt_after_timestep_same_every", "every timestep 5e-7 then pair_coeff 1 2 hooke $(dt*1e10) (kn 5000: the dt just set)",
  'run 3000 every 1000 "timestep 5e-7" "pair_coeff 1 2 hooke $(dt*1e10) 3000 ' + K + '"\n', gap=1.55e-3)
E("V17_dt_before_timestep_same_every", "every pair_coeff 1 2 hooke $(dt*5e9) then timestep $(dt*0.5): kn 5000, 2500 (part 3: 2500); run 4000 after",
  'run 3000 every 1000 "pair_coeff 1 2 hooke $(dt*5e9) 3000 ' + K + '" "timestep $(dt*0.5)"\nrun 16000\n', gap=1.76e-3)
E("V18_dt_density", "every set type 2 density $(dt*7.8e9) (7800)", R3.format("set type 2 density $(dt*7.8e9)"))
W("V19_dt_wall", "wall live: every fix floor kn $(dt*8e9) (8000)", R3.format("fix floor all wall/gran granular hooke $(dt*8e9) 3000 " + K + " zplane 0 NULL"))
E("V20_dollar_brace_step_var", "every variable s equal $(step) then pair_coeff 1 2 hooke ${s} (part 3: kn 2000)",
  'run 3000 every 1000 "variable s equal $(step)" "pair_coeff 1 2 hooke ${s} 3000 ' + K + '"\n')
E("V21_quoted_step_var", 'every variable s equal "$(step) + 0" (quoted expression); if s==3000 kn 5000 else 8000',
  "run 3000 every 1000 'variable s equal \"$(step) + 0\"'\n" + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
W("V22_step_var_wall", "wall live: every variable s; fix floor kn $(v_s+5000) (8000); run 1000 (hits there)",
  VS + "fix floor all wall/gran granular hooke $(v_s+5000) 3000 " + K + " zplane 0 NULL\nrun 1000\n", gap=3.1e-3)
E("V23_step_var_density", "every variable s; set type 2 density ${s} (3000); run 1000", VS + "set type 2 density ${s}\nrun 1000\n", gap=3.1e-3)
E("V24_step_var_clear", "every variable s; clear (variables stay); base, live pair, pair_coeff 1 2 kn $(v_s+2000) (5000), run",
  VS + "clear\n" + BL() + lv(0.1e-3) + "pair_coeff 1 2 hooke $(v_s+2000) 3000 " + K + "\nrun 3000\n", live="the run after clear")
E("V25_time_var_kn", "every variable t equal $(time) (3e-3); pair_coeff 1 2 hooke $(v_t*1e6+2000) (5000)",
  R3.format("variable t equal $(time)") + "pair_coeff 1 2 hooke $(v_t*1e6+2000) 3000 " + K + "\nrun 1000\n", gap=3.1e-3)
E("V26_time_var_after_dt_change", "run 1000 (dt 1e-6), timestep 5e-7, every variable t equal $(time) (2.5e-3); kn $(v_t*2e6) (5000); run 2000",
  "run 1000\ntimestep 5e-7\n" + R3.format("variable t equal $(time)") + "pair_coeff 1 2 hooke $(v_t*2e6) 3000 " + K + "\nrun 2000\n", gap=2.6e-3)
E("V27_plain_time_after_runs", "no every: run 1000, timestep 5e-7, run 3000, if $(time) > 0.0022 kn 5000 else 8000 (LAMMPS time 2.5e-3)",
  "run 1000\ntimestep 5e-7\nrun 3000\n" + IFS("$(time) > 0.0022") + "run 2000\n", gap=2.6e-3)
E("V28_plain_step_after_runs", "no every: run 3000; if $(step) == 3000 kn 5000 else 8000", "run 3000\n" + IFS("$(step) == 3000") + "run 1000\n", gap=3.1e-3)
E("V29_lazy_step_var_after_runs", "variable s equal step (lazy, no every); run 3000; if ${s} == 3000 kn 5000 else 8000",
  "variable s equal step\nrun 3000\n" + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
E("V30_run0_every1_step", "run 0 every 1 variable s equal $(step) (0); if s == 0 kn 5000 else 8000", 'run 0 every 1 "variable s equal $(step)"\n' + IFS("${s} == 0") + "run 3000\n", gap=0.1e-3)
E("V31_one_part_step", "run 1000 every 1000 variable s (1000); if s == 1000 kn 5000 else 8000; run 2000",
  'run 1000 every 1000 "variable s equal $(step)"\n' + IFS("${s} == 1000") + "run 2000\n", gap=1.1e-3)
E("V32_step_var_include_if", "every variable s in an include; if in a second include", "include a.in\ninclude b.in\nrun 1000\n", gap=3.1e-3,
  data={"a.in": VS, "b.in": IFS("${s} == 3000")})
E("V33_step_format", "every variable s; pair_coeff 1 2 hooke $(v_s*5/3:%.0f) (5000)", VS + "pair_coeff 1 2 hooke $(v_s*5/3:%.0f) 3000 " + K + "\nrun 1000\n", gap=3.1e-3)
E("V34_step_two_every_runs", "two every runs each defining s; if s==6000 kn 5000 else 8000", VS + VS + IFS("${s} == 6000") + "run 1000\n", gap=6.1e-3)
E("V35_step_var_jump_skip", "every variable s; if s == 3000 jump SELF skip; kn 8000; label skip; kn 5000 ... (LAMMPS jumps: kn 2000)",
  VS + 'if "${s} == 3000" then "jump SELF skip"\n' + P8() + "\nlabel skip\nrun 1000\n", gap=3.1e-3)
E("V36_step_var_pre_no_run", "every variable s; if s==3000 kn 5000; run 1000 (then pre no run where the pair meets)",
  VS + IFS("${s} == 3000") + "run 1000\nrun 2000 pre no\n", gap=4.1e-3)
E("V37_every_timestep_and_kn_part2", "every timestep 5e-7 + pair_coeff 1 2 kn 5000; live pair meets in part 2",
  'run 3000 every 1000 "timestep 5e-7" "' + P5() + '"\n', gap=1.1e-3, live="part 2")
E("V38_every_NULL_after_change", "pair_coeff 1 2 kn 5000; run 3000 every 1000 NULL", P5() + "\nrun 3000 every 1000 NULL\n", gap=2.1e-3)
E("V39_every_pre_no_start", "run 3000 every 1000 post no pre yes with a step variable", 'run 3000 pre yes post no every 1000 "variable s equal $(step)"\n' + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
E("V40_step_var_then_step_plain", "every variable s; if $(step) == 3000 (plain, not the variable) kn 5000 else 8000", VS + IFS("$(step) == 3000") + "run 1000\n", gap=3.1e-3)
E("V41_step_var_loop_every", "loop 3: run 1000 every 500 variable s; if s == 3000 then kn 5000 (only last pass)", 'variable i loop 3\nlabel l\nrun 1000 every 500 "variable s equal $(step)"\n'
  + f'if "${{s}} == 3000" then "{P5()}"\nnext i\njump SELF l\nrun 1000\n', gap=3.1e-3)
E("V42_every_wall_kn_part1", "every fix floor kn 8000; live pair (no wall) in part 1 (kn 2000 pair)", R3.format("fix floor all wall/gran granular " + hk(8000) + " zplane 0 NULL"), gap=0.1e-3, live="part 1")
E("V43_step_density_via_var", "every variable d equal $(2500+step) (5500); set type 2 density ${d}; run 1000", R3.format("variable d equal $(2500+step)") + "set type 2 density ${d}\nrun 1000\n", gap=3.1e-3)

# ------------------------------------------------------------ D: types emptied or refilled; position-dependent commands after skipped runs
DB = lambda: BL(nt=3) + VIC


def Dk(name, comment, lines, gap=1.1e-3, live="run after the change", ids=(3, 4), **kw):
    E(name, comment, lines, gap=gap, live=live, pre=DB(), pair=lvi(gap, ids), **kw)


g11 = 1.1e-3
E("D01_static_type_group", "group a type 1 made before the live pair; run; delete_atoms group a (the live type-1 sphere stays)", "run 1000\ndelete_atoms group a\nrun 3000\n",
  gap=g11, pre=DB() + "group a type 1\n", pair=lvi(g11))
E("D02_static_id_range_group", "group a id 1:2 (victims); delete after run 1000", "run 1000\ndelete_atoms group a\nrun 3000\n", gap=g11, pre=DB() + "group a id 1:2\n", pair=lvi(g11))
E("D03_region_initial_place", "delete_atoms region around lv1's START place after run 1000 (it has moved 0.77 mm: LAMMPS keeps it)",
  f"region r sphere {XA0(g11):.9g} 0.02 0.05 0.0003 units box\nrun 1000\ndelete_atoms region r\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("D04_region_later_place", "delete_atoms region around where lv1 IS after run 1000 (LAMMPS deletes it: no contact)",
  f"region r sphere {XA1(g11):.9g} 0.02 0.05 0.0003 units box\nrun 1000\ndelete_atoms region r\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("D05_set_region_initial_place", "set region (lv1's start place) type 3 after run 1000 (LAMMPS: lv1 has left; stays type 1); pair_coeff 2 3 kn 8000",
  f"region r sphere {XA0(g11):.9g} 0.02 0.05 0.0003 units box\n" + P8("2", "3") + "\nrun 1000\nset region r type 3\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("D06_set_region_later_place", "set region (where lv1 is after run 1000) type 3; pair_coeff 2 3 kn 8000 (LAMMPS: lv1 becomes type 3)",
  f"region r sphere {XA1(g11):.9g} 0.02 0.05 0.0003 units box\n" + P8("2", "3") + "\nrun 1000\nset region r type 3\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("D07_group_region_after_run", "group a region (lv1's later place) made after run 1000; set group a type 3; 2 3 kn 8000",
  f"region r sphere {XA1(g11):.9g} 0.02 0.05 0.0003 units box\n" + P8("2", "3") + "\nrun 1000\ngroup a region r\nset group a type 3\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("D08_variable_atom_group_after_run", "variable v atom x > (lv1's start + 0.5 mm) and type 1; group a variable v after run 1000; set group a type 3",
  f"variable v atom x>{XA0(g11) + 0.0005:.9g}&&type==1\n" + P8("2", "3") + "\nrun 1000\ngroup a variable v\nset group a type 3\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("D09_evaporate_lv1", "fix evaporate in a region around lv1's start (deleted at step 1 by LAMMPS); run 1000; unfix; run 3000 (no 1 2 contact)",
  f"region r sphere {XA0(g11):.9g} 0.02 0.05 0.0003 units box\nfix ev all evaporate 1 1 r 4767\nrun 1000\nunfix ev\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("D10_evaporate_elsewhere", "fix evaporate in an empty region (deletes nothing); run 1000; unfix; run 3000 (1 2 contact)",
  "region r sphere 0.035 0.035 0.09 0.001 units box\nfix ev all evaporate 1 1 r 4767\nrun 1000\nunfix ev\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("D11_evaporate_victim_type3", "the only type-3 sphere evaporated in run 1000; live pair 1 2 (control of a type emptied by a fix)",
  "create_atoms 3 single 0.01 0.01 0.08\nset atom 3 diameter 0.004 density 2500\nregion r sphere 0.01 0.01 0.08 0.001 units box\nfix ev all evaporate 1 1 r 4767\nrun 1000\nunfix ev\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("D12_dynamic_group_delete", "group a dynamic all region (lv1's later place); run 1000; delete_atoms group a (LAMMPS: membership from the run)",
  f"region r sphere {XA1(g11):.9g} 0.02 0.05 0.0003 units box\ngroup a dynamic all region r\nrun 1000\ndelete_atoms group a\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("D13_delete_overlap_after_move", "a fixed type-3 sphere 3.2 mm behind lv1's start; after run 1000 delete_atoms overlap 0.0035 lv1 g3 (LAMMPS: lv1 is 3.97 mm away, kept)",
  f"create_atoms 3 single {XA0(g11) - 0.0032:.9g} 0.02 0.05\nset atom 3 diameter 0.002 density 2500\ngroup g3 id 3\nfix fr3 g3 setforce 0 0 0\nrun 1000\ndelete_atoms overlap 0.0035 lv1 g3\nrun 3000\n",
  gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("D14_lost_during_run", "lost ignore; lv2 shot up at 200 m/s in run 1 (leaves the top, lost); run 3000 (no 1 2 contact)",
  "thermo_modify lost ignore\nvelocity lv2 set 0 0 200 units box\nrun 1000\nrun 3000\n", gap=g11)
E("D15_lost_type3_during_run", "lost ignore; the only type-3 sphere shot out in run 1; live 1 2 (rows for 3 after)",
  "thermo_modify lost ignore\ncreate_atoms 3 single 0.01 0.01 0.08\nset atom 3 diameter 0.004 density 2500\ngroup g3 id 3\nvelocity g3 set 0 0 300 units box\nrun 1000\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
Dk("D16_delete_type_then_create_random", "delete_atoms group of type 1 (victim + lv1?) no: victims id 1; delete id 1; create_atoms 1 random 1 in a far region",
   "group a id 1\nrun 1000\ndelete_atoms group a\nregion far block 0.005 0.01 0.005 0.01 0.08 0.09 units box\ncreate_atoms 1 random 1 4767 far\nset atom 5 diameter 0.004 density 2500\nrun 3000\n")
E("D17_delete_all_type1_read_data_add", "all type-1 atoms deleted (victim group type 1 before lv); read_data add append brings the live type-1 sphere",
  "group a type 1\nrun 1000\ndelete_atoms group a\nread_data lv1.data add append group lv1\nset group lv1 diameter 0.004 density 2500\nvelocity lv1 set 0.7714285714 0 0 units box\nrun 3000\n",
  gap=0.1e-3, pre=BL(nt=3) + VIC, pair="create_atoms 2 single {:.9g} 0.02 0.05\nset atom 3 diameter 0.006 density 2500\ngroup lv2 id 3\nvelocity lv2 set -0.2285714286 0 0 units box\n".format(0.02 + 0.003 + 0.00005 + 0.00077142857),
  data={"lv1.data": "# the live type-1 sphere\n\n1 atoms\n3 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n10 1 0.004 2500 {:.9g} 0.02 0.049995095\n".format(0.02 - 0.002 - 0.00005 + 0.00077142857 - 0.00077142857)})
Dk("D18_set_type_then_back", "run; set atom 3 type 3 (lv1); run 100; set atom 3 type 1 (back); run 3000",
   "run 1000\nset atom 3 type 3\nrun 100\nset atom 3 type 1\nrun 3000\n", gap=1.2e-3)
Dk("D19_pour_unfixed_then_delete", "fix pour of 2 type-3 spheres (inserted in run 1), unfix pour, delete type-3 by group, run; live 1 2",
   "region ins block 0.005 0.035 0.005 0.035 0.08 0.095 units box\nfix p all pour 2 3 4767 region ins diam one 0.003 dens 2500 2500\nrun 1000\nunfix p\ngroup g3 type 3\ndelete_atoms group g3\nrun 3000\n")
Dk("D20_pour_after_delete", "delete victims by id; fix pour type 1 defined after; run; live 1 2", "group a id 1\nrun 1000\ndelete_atoms group a\nregion ins block 0.005 0.035 0.005 0.035 0.08 0.095 units box\nfix p all pour 2 1 4767 region ins diam one 0.003 dens 2500 2500\nrun 3000\n")
Dk("D21_porosity", "delete_atoms porosity in a region holding victims only, fraction 1.0", "region vr block 0 0.04 0 0.04 0 0.02 units box\nrun 1000\ndelete_atoms porosity vr 1.0 4767\nrun 3000\n")
Dk("D22_delete_region_leaves_some", "delete_atoms region around the victims only (lives stay)", "region vr block 0 0.04 0 0.04 0 0.02 units box\nrun 1000\ndelete_atoms region vr\nrun 3000\n")
Dk("D23_group_clear_delete", "group a type 1; group a clear; delete_atoms group a (nothing)", "group a type 1\ngroup a clear\nrun 1000\ndelete_atoms group a\nrun 3000\n")
Dk("D24_group_redefine_union", "group a id 1 then group a type 2 (a union: ids 1,2,4); delete_atoms group a after the run (lv2 gone)",
   "group a id 1\ngroup a type 2\nrun 1000\ndelete_atoms group a\nrun 3000\n")
Dk("D25_set_type_lv1_to_3", "run; set group lv1 type 3 (lv1 now type 3); pair_coeff 2 3 kn 8000; run (live 3 2)", "run 1000\nset group lv1 type 3\n" + P8("2", "3") + "\nrun 3000\n")
Dk("D26_delete_lv1_mol", "delete_atoms group lv1 mol no compress yes after run; then create_atoms 1 single at lv1's place with its speed (type 1 refilled)",
   "run 1000\ndelete_atoms group lv1 compress yes\n" + f"create_atoms 1 single {XA1(g11):.9g} 0.02 0.049995095\nvariable n equal count(all)\ngroup lvn id $(count(all))\nset group lvn diameter 0.004 density 2500\nvelocity lvn set 0.7714285714 0 0 units box\ngroup lv1 delete\ngroup lv1 union lvn\nrun 3000\n")
W("D27_wall_type_emptied_by_region", "wall live: delete_atoms region around the falling sphere's START after run 1000 (it fell 1 mm: LAMMPS keeps it)",
  "region r sphere 0.02 0.02 {:.9g} 0.0003 units box\nrun 1000\ndelete_atoms region r\nrun 3000\n".format(0.002 + 1.1e-3), gap=1.1e-3)

# ------------------------------------------------------------ Q: run pre no after a change
g41 = 4.1e-3
E("Q01_diam_up_pre_no", "run 1000; set type 2 diameter 0.012 (contact 8 mm, stale list); run 3000 pre no", "run 1000\nset type 2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
E("Q02_diam_up_control", "Q01 without pre no", "run 1000\nset type 2 diameter 0.012\nrun 3000\n", gap=g41, sep=0.008)
E("Q03_diam_up_pre_no_skin", "Q01 with neighbor 0.01 bin from the start", "run 1000\nset type 2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=BL() + "neighbor 0.01 bin\n")
E("Q04_diam_huge_pre_no", "run 1000; set type 2 diameter 0.030 (contact 17 mm); run 3000 pre no", "run 1000\nset type 2 diameter 0.030\nrun 3000 pre no\n", gap=0.0131, sep=0.017)
E("Q05_diam_huge_control", "Q04 without pre no", "run 1000\nset type 2 diameter 0.030\nrun 3000\n", gap=0.0131, sep=0.017)
E("Q06_diam_up_hertz_pre_no", "hertz/material; run 1000; set type 2 diameter 0.012; run 3000 pre no", "run 1000\nset type 2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=BL(HM))
E("Q07_mass_pre_no", "run 1000; set type 2 density 7800 (mass_velocity damping reads mass); run 3000 pre no", "run 1000\nset type 2 density 7800\nrun 3000 pre no\n", gap=1.1e-3)
E("Q08_mass_set_pre_no", "run 1000; set type 2 mass 5e-4; run 3000 pre no", "run 1000\nset type 2 mass 5e-4\nrun 3000 pre no\n", gap=1.1e-3)
E("Q09_diam_every_pre_no", "run 3000 pre no every 1000 set type 2 diameter 0.008 (grows after part 1)", 'run 3000 pre no every 1000 "set type 2 diameter 0.008"\n', gap=3.1e-3, sep=0.006)
E("Q10_pre_no_after_skin", "run 1000; neighbor 0.0001 bin; run 3000 pre no", "run 1000\nneighbor 0.0001 bin\nrun 3000 pre no\n", gap=1.1e-3)
E("Q11_pre_no_after_neigh_modify", "run 1000; neigh_modify every 100 delay 0 check no; run 3000 pre no", "run 1000\nneigh_modify every 100 delay 0 check no\nrun 3000 pre no\n", gap=1.1e-3)
E("Q12_pre_no_after_timestep_change_kn_same", "run 1000; timestep 2e-6; run 2000 pre no", "run 1000\ntimestep 2e-6\nrun 2000 pre no\n", gap=1.1e-3)
E("Q13_like_change_explicit_unlike", "* * (1 2 explicit); run 1000; pair_coeff 1 1 kn 8000; run 3000 pre no (1 2 stays 2000)", "run 1000\n" + P8("1", "1") + "\nrun 3000 pre no\n", gap=1.1e-3)
E("Q14_like_change_live_11", "run 1000; pair_coeff 1 1 kn 8000; run pre no; live pair 1 1", "run 1000\n" + P8("1", "1") + "\nrun 3000 pre no\n", gap=1.1e-3, pair=lv(1.1e-3, 1, 1, 0.004, 0.004), sep=0.004)
E("Q15_first_run_pre_no_diam", "set type 2 diameter 0.012 then the first run pre no", "set type 2 diameter 0.012\nrun 3000 pre no\n", gap=0.1e-3 + 0.003, sep=0.008)
W("Q16_wall_pre_no", "wall live: run 1000; fix floor kn 8000 (same id); run 3000 pre no", "run 1000\n" + FL(hk(8000)) + "run 3000 pre no\n", gap=1.1e-3)
W("Q17_wall_unfix_fix_pre_no", "wall live: run 1000; unfix floor; fix floor2 kn 8000; run 3000 pre no", "run 1000\nunfix floor\nfix floor2 all wall/gran granular " + hk(8000) + " zplane 0 NULL\nrun 3000 pre no\n", gap=1.1e-3)
E("Q18_mixed_like_change_no_unlike_atoms", "1 1, 2 2 only (1 2 mixed); live pair 1 1; run 1000; pair_coeff 1 1 kn 8000; run pre no", "run 1000\n" + P8("1", "1") + "\nrun 3000 pre no\n", pre=r.MIX, pair=lv(1.1e-3, 1, 1, 0.004, 0.004), gap=1.1e-3, sep=0.004)
E("Q19_diam_down_pre_no", "run 1000; set type 2 diameter 0.004; run pre no", "run 1000\nset type 2 diameter 0.004\nrun 3000 pre no\n", gap=1.1e-3, sep=0.004)
E("Q20_every_diam_up_no_pre", "run 3000 every 1000 set type 2 diameter 0.012 (parts set up)", R3.format("set type 2 diameter 0.012"), gap=2.1e-3 + 0.003, sep=0.008)
E("Q21_diam_up_pre_no_cutoff", "per-pair cutoff 0.02 for * *; run 1000; set type 2 diameter 0.012; run pre no", "run 1000\nset type 2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=BL(HK + " cutoff 0.02"))

# ------------------------------------------------------------ N: neighbour reach
CU = lambda c: BL(HK + f" cutoff {c}")
E("N01_nsq_small_cutoff", "every cutoff 0.001, neighbor 0.001 nsq (all pairs checked)", "neighbor 0.001 nsq\nrun 3000\n", pre=CU(0.001), gap=0.1e-3)
E("N02_nsq_small_cutoff_periodic", "N01 with the pair across the periodic x boundary", "neighbor 0.001 nsq\nrun 3000\n", pre=CU(0.001), pair=lvi(0.1e-3, (1, 2), x0=0.0, remap=" remap yes"), gap=0.1e-3)
E("N16_bin_small_cutoff_periodic_comm", "every cutoff 0.001, bin, comm_modify cutoff 0.02, pair across the periodic x boundary", "neighbor 0.001 bin\ncomm_modify cutoff 0.02\nrun 3000\n", pre=CU(0.001), pair=lvi(0.1e-3, (1, 2), x0=0.0, remap=" remap yes"), gap=0.1e-3)
E("N17_default_periodic", "default cutoffs, pair across the periodic x boundary (control)", "run 3000\n", pair=lvi(0.1e-3, (1, 2), x0=0.0, remap=" remap yes"), gap=0.1e-3)
E("N03_multi_small_cutoff", "every cutoff 0.001, neighbor 0.001 multi", "neighbor 0.001 multi\nrun 3000\n", pre=CU(0.001), gap=0.1e-3)
E("N04_bin_zero_skin", "default cutoffs, neighbor 0.0 bin", "neighbor 0.0 bin\nrun 3000\n", gap=0.1e-3)
E("N05_exclude_11_live12", "neigh_modify exclude type 1 1; live 1 2 (collides)", "neigh_modify exclude type 1 1\nrun 3000\n", gap=0.1e-3)
E("N06_exclude_group_lv1_all", "neigh_modify exclude group lv1 all (passes)", "neigh_modify exclude group lv1 all\nrun 3000\n", gap=0.1e-3)
E("N07_exclude_then_none_then_22", "exclude type 1 2, exclude none, exclude type 2 2 (1 2 collides)", "neigh_modify exclude type 1 2\nneigh_modify exclude none\nneigh_modify exclude type 2 2\nrun 3000\n", gap=0.1e-3)
E("N08_bin_0035_big_sphere", "every cutoff 0.0035, default skin; pair 4 mm / 20 mm (contact 12 mm)", "run 3000\n", pre=CU(0.0035), pair=lv(0.1e-3, 1, 2, 0.004, 0.02), sep=0.012, gap=0.1e-3)
E("N09_multi_big_small", "neighbor 0.001 multi; pair 4 mm / 20 mm default cutoffs", "neighbor 0.001 multi\nrun 3000\n", pair=lv(0.1e-3, 1, 2, 0.004, 0.02), sep=0.012, gap=0.1e-3)
E("N10_exclude_type_range", "neigh_modify exclude type 1 2 given as type 2 1", "neigh_modify exclude type 2 1\nrun 3000\n", gap=0.1e-3)
E("N11_comm_cutoff_small_cutoffs_nsq", "every cutoff 0.001, nsq, comm_modify cutoff 0.02", "neighbor 0.001 nsq\ncomm_modify cutoff 0.02\nrun 3000\n", pre=CU(0.001), gap=0.1e-3)
E("N12_exclude_every_then_run", "run 3000 every 1000 neigh_modify exclude type 1 2 then run 1000 (still excluded)", R3.format("neigh_modify exclude type 1 2") + "run 2000\n", gap=3.1e-3)
E("N13_one_cutoff_11_small_others_default_nsq", "pair_coeff 1 1 cutoff 0.0001 only, nsq (1 2 default)", "neighbor 0.001 nsq\nrun 3000\n", pre=BL() + "pair_coeff 1 1 " + HK + " cutoff 0.0001\n", gap=0.1e-3)
E("N14_global_cutoff_small_nsq", "pair_style granular 0.001 (global), nsq", "neighbor 0.001 nsq\nrun 3000\n", pre=head(2) + "pair_style granular 0.001\npair_coeff * * " + HK + "\n" + GRAV + FL() + TAILL, gap=0.1e-3)
E("N15_small_cutoff_big_skin_every", "every cutoff 0.001; run 1000; neighbor 0.01 bin; run 3000", "run 1000\nneighbor 0.01 bin\nrun 3000\n", pre=CU(0.001), gap=1.1e-3)

# ------------------------------------------------------------ H: hybrid
HYB = lambda style, lines: head(2) + f"pair_style {style}\n" + lines + GRAV + FL() + TAILL
GG = "pair_coeff * * granular " + HK + "\n"
E("H01_hybrid_scaled_half", "pair_style hybrid/scaled 0.5 granular (forces halved)", "run 3000\n", pre=HYB("hybrid/scaled 0.5 granular", GG), gap=0.1e-3)
E("H02_hybrid_zero_12", "hybrid granular zero 0.01; pair_coeff 1 2 zero (passes)", "run 3000\n", pre=HYB("hybrid granular zero 0.01", GG + "pair_coeff 1 2 zero\n"), gap=0.1e-3)
E("H03_hybrid_lj_eps0_12", "hybrid granular lj/cut 0.001; pair_coeff 1 2 lj/cut 0 0.001 (passes)", "run 3000\n", pre=HYB("hybrid granular lj/cut 0.001", GG + "pair_coeff 1 2 lj/cut 0 0.001\n"), gap=0.1e-3)
E("H04_hybrid_zero_back", "hybrid granular zero; 1 2 zero then 1 2 granular kn 5000", "run 3000\n", pre=HYB("hybrid granular zero 0.01", GG + "pair_coeff 1 2 zero\npair_coeff 1 2 granular " + hk(5000) + "\n"), gap=0.1e-3)
E("H05_overlay_zero", "hybrid/overlay granular zero 0.01; 1 2 zero as well (granular still acts)", "run 3000\n", pre=HYB("hybrid/overlay granular zero 0.01", GG + "pair_coeff 1 2 zero\n"), gap=0.1e-3)
E("H06_star_none_then_12", "hybrid granular; * * none; pair_coeff 1 2 granular (only 1 2)", "run 3000\n", pre=HYB("hybrid granular", "pair_coeff * * none\npair_coeff 1 2 granular " + HK + "\n"), gap=0.1e-3)
E("H07_none_11_live12", "hybrid granular; * * granular; 1 1 none; live 1 2", "run 3000\n", pre=HYB("hybrid granular", GG + "pair_coeff 1 1 none\n"), gap=0.1e-3)
E("H08_scaled_var", "hybrid/scaled v_s granular with variable s equal 0.5", "run 3000\n", pre="variable s equal 0.5\n" + HYB("hybrid/scaled v_s granular", GG), gap=0.1e-3)
E("H09_two_sub_none_back_to_1", "hybrid granular granular; 1 2 granular 2 kn 5000; 1 2 none; 1 2 granular 1 (kn 2000)", "run 3000\n",
  pre=HYB("hybrid granular granular", "pair_coeff * * granular 1 " + HK + "\npair_coeff 2 2 granular 2 " + HK + "\npair_coeff 1 2 granular 2 " + hk(5000) + "\npair_coeff 1 2 none\npair_coeff 1 2 granular 1 " + HK + "\n"), gap=0.1e-3)
E("H10_mix_arithmetic", "1 1 kn 1000, 2 2 kn 8000 only (1 2 mixed); pair_modify mix arithmetic", "run 3000\n",
  pre=head(2) + "pair_style granular\npair_coeff 1 1 " + hk(1000) + "\npair_coeff 2 2 " + hk(8000) + "\npair_modify mix arithmetic\n" + GRAV + FL() + TAILL, gap=0.1e-3)
E("H11_mix_geometric_control", "1 1 kn 1000, 2 2 kn 8000 only (1 2 mixed)", "run 3000\n",
  pre=head(2) + "pair_style granular\npair_coeff 1 1 " + hk(1000) + "\npair_coeff 2 2 " + hk(8000) + "\n" + GRAV + FL() + TAILL, gap=0.1e-3)
E("H12_scaled_two_granular", "hybrid/scaled 0.5 granular 0.5 granular: same law twice on 1 2? (engine decides)", "run 3000\n",
  pre=HYB("hybrid/scaled 1.0 granular", GG), gap=0.1e-3)
E("H13_hybrid_zero_none_mixed", "hybrid granular zero: 1 1 granular kn 1000, 2 2 granular kn 8000 only, 1 2 never set (mixed within granular)", "run 3000\n",
  pre=HYB("hybrid granular zero 0.01", "pair_coeff 1 1 granular " + hk(1000) + "\npair_coeff 2 2 granular " + hk(8000) + "\n"), gap=0.1e-3)
E("H14_hybrid_zero_every", "hybrid granular zero; every pair_coeff 1 2 zero (passes in part 3)", R3.format("pair_coeff 1 2 zero"), pre=HYB("hybrid granular zero 0.01", GG))
E("H15_hybrid_one_none_range", "hybrid granular; pair_coeff 1*2 2 none, then 1 2 granular kn 5000 (2 2 none)", "run 3000\n", pre=HYB("hybrid granular", GG + "pair_coeff 1*2 2 none\npair_coeff 1 2 granular " + hk(5000) + "\n"), gap=0.1e-3)

# ------------------------------------------------------------ C: clear, restart, lost
CB = lambda: BL()
E("C01_restart_keeps_coeff", "pair_coeff 1 2 kn 5000; write_restart; clear; read_restart (no pair_coeff: the restart's); walls and integrator again; run",
  P5() + "\nwrite_restart a.rst\nclear\nread_restart a.rst\n" + GRAV + FL() + TAILL + "run 3000\n", gap=0.1e-3)
E("C02_restart_mixed_then_like", "1 1, 2 2 only; write_restart; clear; read_restart; pair_coeff 1 1 kn 8000 (1 2 re-mixed at set-up); run",
  "write_restart a.rst\nclear\nread_restart a.rst\n" + P8("1", "1") + "\n" + GRAV + FL() + TAILL + "run 3000\n", pre=r.MIX, gap=0.1e-3)
E("C03_restart_file_from_run", "restart 1000 r.*; run 1000; clear; read_restart r.1000 (the file only a made run writes)",
  "restart 1000 r.*\nrun 1000\nclear\nread_restart r.1000\n" + P5() + "\n" + GRAV + FL() + TAILL + "run 3000\n", gap=1.1e-3)
E("C04_restart_after_run_velocity", "run 1000; write_restart; clear; read_restart; pair_coeff 1 2 kn 5000; run 3000 (pair meets in it)",
  "run 1000\nwrite_restart a.rst\nclear\nread_restart a.rst\n" + P5() + "\n" + GRAV + FL() + TAILL + "run 3000\n", gap=1.1e-3)
E("C05_clear_lost_ignore_then_data", "thermo_modify lost ignore; clear; base; read live pair; run", "clear\n" + BL() + "thermo_modify lost ignore\n" + lv(0.1e-3) + "run 3000\n", live="the run after clear")
E("C06_restart_hybrid", "hybrid granular zero, 1 2 zero; write_restart; clear; read_restart (the hybrid's none/zero kept)",
  "write_restart a.rst\nclear\nread_restart a.rst\n" + GRAV + FL() + TAILL + "run 3000\n", pre=HYB("hybrid granular zero 0.01", GG + "pair_coeff 1 2 zero\n"), gap=0.1e-3)
E("C07_restart_excluded", "neigh_modify exclude type 1 2; write_restart; clear; read_restart (exclusions are not in a restart)",
  "neigh_modify exclude type 1 2\nwrite_restart a.rst\nclear\nread_restart a.rst\n" + GRAV + FL() + TAILL + "run 3000\n", gap=0.1e-3)
E("C08_restart_cutoff_small", "every cutoff 0.001 with neighbor 0.001 bin; restart; read; run", "neighbor 0.001 bin\nwrite_restart a.rst\nclear\nread_restart a.rst\n" + GRAV + FL() + TAILL + "run 3000\n", pre=CU(0.001), gap=0.1e-3)
E("C09_lost_warn_lv2_out", "lost warn; lv2 shot through the top in run 1; run 3000", "thermo_modify lost warn\nvelocity lv2 set 0 0 200 units box\nrun 1000\nrun 3000\n", gap=1.1e-3)
E("C10_clear_every_step", "every variable s; clear; base; if s == 3000 kn 5000 else 8000 (variables survive a clear)",
  VS + "clear\n" + BL() + lv(0.1e-3) + IFS("${s} == 3000") + "run 3000\n", live="the run after clear")
E("C11_restart_timestep", "timestep 5e-7 before write_restart; read_restart keeps dt", "timestep 5e-7\nwrite_restart a.rst\nclear\nread_restart a.rst\n" + P5() + "\n" + GRAV + FL() + "fix integ all nve/sphere\nrun 6000\n", gap=0.1e-3)

# ------------------------------------------------------------ O: older classes mixed in
E("O01_format_kn", "pair_coeff 1 2 hooke $(5000.4:%.0f)", "pair_coeff 1 2 hooke $(5000.4:%.0f) 3000 " + K + "\nrun 3000\n", gap=0.1e-3)
E("O02_format_var", "variable k format x %.0f with x 4999.6", "variable x equal 4999.6\nvariable k format x %.0f\npair_coeff 1 2 hooke ${k} 3000 " + K + "\nrun 3000\n", gap=0.1e-3)
E("O03_range_star2_every", "every pair_coeff * 2 kn 5000 (1 2, 2 2)", R3.format(P5("*", "2")))
E("O04_labels_every_step_var", "labelmap; every variable s; if s==3000 pair_coeff small big kn 5000", "labelmap atom 1 small 2 big\n" + VS + f'if "${{s}} == 3000" then "{P5("small", "big")}"\nrun 1000\n', gap=3.1e-3)
E("O05_set_order_every", "every set type 2 density 7800 then set type 2 diameter 0.008 (mass by 7800 at 8 mm)", 'run 3000 every 1000 "set type 2 density 7800" "set type 2 diameter 0.008"\n', sep=0.006)
E("O06_set_order_every_rev", "every set type 2 diameter 0.008 then density 7800", 'run 3000 every 1000 "set type 2 diameter 0.008" "set type 2 density 7800"\n', sep=0.006)
E("O07_loop_next_jump_every_kn", "loop i 2: run 1500 every 500 pair_coeff 1 2 hooke $(dt*5e9); next; jump", 'variable i loop 2\nlabel l\nrun 1500 every 500 "pair_coeff 1 2 hooke $(dt*5e9) 3000 ' + K + '"\nnext i\njump SELF l\n')
E("O08_include_every_delete", "include with every deleting victims (types 3)", "create_atoms 3 single 0.01 0.01 0.08\nset atom 3 diameter 0.004 density 2500\ngroup g3 id 3\ninclude d.in\n", pre=BL(nt=3), data={"d.in": R3.format("delete_atoms group g3")})
E("O09_if_step_formatted", "every variable s; if $(v_s:%.3f) == 3000.000 kn 5000", VS + IFS("$(v_s:%.3f) == 3000.000") + "run 1000\n", gap=3.1e-3)
E("O10_15g", "variable k equal 5000/3*3 (15g); pair_coeff hooke ${k}", "variable k equal 5000/3*3\npair_coeff 1 2 hooke ${k} 3000 " + K + "\nrun 3000\n", gap=0.1e-3)
E("O11_star_star_after_every_pre_no", "every pair_coeff 1 2 kn 5000; then run 1000 pre no (no change since)", R3.format(P5()) + "run 1000 pre no\n", gap=3.1e-3)
E("O12_label_type_range_every", "labelmap; every pair_coeff small* big kn 5000? (range from a label is LAMMPS' call)", "labelmap atom 1 small 2 big\n" + R3.format(P5("*", "big")))

# ------------------------------------------------------------ L: LIGGGHTS
LH = lambda style="hertz", extra_pair="", e="0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8": (m.lhead() + m.MAT3 + f"fix m3 all property/global coefficientRestitution peratomtypepair 3 {e}\n"
      + f"pair_style gran model {style} tangential history{extra_pair}\npair_coeff * *\n" + m.WALL3)
Ll("L01_e_one", "LIGGGHTS hertz, e = 1.0 everywhere", "run 3000\n", gap=0.1e-3, head_=LH(e=" ".join(["1.0"] * 9)))
Ll("L02_limitForce_hooke", "LIGGGHTS hooke limitForce on (e 1 2 = 0.5)", "run 3000\n", gap=0.1e-3, head_=LH("hooke", " limitForce on").replace("pair_style", "fix m10 all property/global characteristicVelocity scalar 1.0\npair_style"))
Ll("L03_limitForce_hertz", "LIGGGHTS hertz limitForce on", "run 3000\n", gap=0.1e-3, head_=LH("hertz", " limitForce on"))
Ll("L04_no_history", "LIGGGHTS hertz tangential no_history", "run 3000\n", gap=0.1e-3, head_=LH().replace("tangential history\n", "tangential no_history\n"))
Ll("L05_step_var_if", "LIGGGHTS every variable s equal $(step); if s==3000 e 1 2 0.9", R3.format("variable s equal $(step)") + f'if "${{s}} == 3000" then "{E3x(0.9)}" else "{E3x(0.2)}"\nrun 1000\n', gap=3.1e-3)
Ll("L06_region_delete_initial", "LIGGGHTS delete_atoms region around lv1's start after run 1000 (moved: stays)", "region r sphere {:.9g} 0 0.1 0.0003 units box\nrun 1000\ndelete_atoms region r\nrun 3000\n".format(-0.002 - 1.1e-3 / 2), gap=1.1e-3)
Ll("L07_hooke_e_one", "LIGGGHTS hooke e = 1.0", "run 3000\n", gap=0.1e-3, head_=LH("hooke", e=" ".join(["1.0"] * 9)).replace("pair_style", "fix m10 all property/global characteristicVelocity scalar 1.0\npair_style"))
Ll("L08_hooke_stiffness", "LIGGGHTS hooke/stiffness kn 2000 kt 1000 gamman 0 (no damping: 1.0)", "run 3000\n", gap=0.1e-3,
   head_=m.lhead() + m.MAT3 + "fix m4 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000\nfix m5 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000\n"
   "fix m6 all property/global gamman peratomtypepair 3 0 0 0 0 0 0 0 0 0\nfix m8 all property/global gammat peratomtypepair 3 0 0 0 0 0 0 0 0 0\npair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"
   "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0\n")
Ll("L09_every_dt_e", "LIGGGHTS every timestep 5e-7 then e 1 2 0.9", 'run 3000 every 1000 "timestep 5e-7" "' + E3x(0.9) + '"\nrun 4000\n', gap=1.55e-3)
Ll("L10_group_type_delete_then_create", "LIGGGHTS group a type 1 (lv1); a second type-1 sphere made after; delete a; pair 1 2 with the new one? (no: live gone)",
   "run 1000\nset atom 1 type 3\nrun 3000\n", gap=1.1e-3)
Ll("L11_exclude_type", "LIGGGHTS neigh_modify exclude type 1 2", "neigh_modify exclude type 1 2\nrun 3000\n", gap=0.1e-3)
Ll("L12_rolling_cdt", "LIGGGHTS hertz rolling_friction cdt (coefficientRollingFriction 0.1)", "run 3000\n", gap=0.1e-3,
   head_=LH().replace("tangential history\n", "tangential history rolling_friction cdt\n").replace(m.WALL3, "fix m9 all property/global coefficientRollingFriction peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\n" + m.WALL3))


# ------------------------------------------------------------ R (batch 2): values the runs change that the clocked pass may not follow,
# position- or order-dependent picks the audit's list may not hold, files the runs write
DTR = "fix dtr all dt/reset 1 NULL 5e-7 0.001 units box\n"
E("R01_dtreset_if_dt", "fix dt/reset caps dt at 5e-7 in run 1; unfix; if $(dt) < 8e-7 kn 5000 else 8000 (LAMMPS: 5000)",
  DTR + "run 1000\nunfix dtr\n" + IFS("$(dt) < 8e-7") + "run 4000\n", gap=0.6e-3)
E("R02_dtreset_if_time", "fix dt/reset caps dt at 5e-7 in run 1 (time 5e-4); unfix; if $(time) < 8e-4 kn 5000 else 8000",
  DTR + "run 1000\nunfix dtr\n" + IFS("$(time) < 8e-4") + "run 4000\n", gap=0.6e-3)
E("R03_dtreset_every_dt", "fix dt/reset (dt 5e-7); run 3000 every 1000 pair_coeff 1 2 hooke $(dt*1e10) (LAMMPS kn 5000)",
  DTR + R3.format("pair_coeff 1 2 hooke $(dt*1e10) 3000 " + K), gap=1.05e-3)
E("R04_dtreset_every_time_var", "fix dt/reset (dt 5e-7); every variable t equal $(time) (1.5e-3); if t < 2e-3 kn 5000 else 8000; run 4000",
  DTR + R3.format("variable t equal $(time)") + "unfix dtr\n" + IFS("${t} < 2e-3") + "run 4000\n", gap=1.6e-3)
E("R05_dtreset_timestep_after", "fix dt/reset (dt 5e-7) in run 1; unfix; timestep $(dt*2) (LAMMPS 1e-6); if $(dt) > 8e-7 kn 5000 else 8000",
  DTR + "run 1000\nunfix dtr\ntimestep $(dt*2)\n" + IFS("$(dt) > 8e-7") + "run 3000\n", gap=0.6e-3)

XB0 = 0.023 + 0.00005 + 0.2285714286e-3
E("R10_create_overlap_blocked_at_start", "a tiny type-2 blocker at the place lv1 is made, falling at 10 m/s; after run 1000 create_atoms 1 single there overlap 0.005 (LAMMPS: blocker 10 mm away, made)",
  "create_atoms 2 single 0.01795 0.02 0.05\nset atom 2 diameter 0.0002 density 2500\ngroup blk id 2\nvelocity blk set 0 0 -10 units box\nrun 1000\n"
  "create_atoms 1 single 0.01795 0.02 0.05 overlap 0.005\nset type 1 diameter 0.004 density 2500\ngroup lv1 type 1\nvelocity lv1 set 0.7714285714 0 0 units box\nrun 3000\n",
  pair=f"create_atoms 2 single {XB0:.9g} 0.02 0.05\nset atom 1 diameter 0.006 density 2500\ngroup lv2 id 1\nvelocity lv2 set -0.2285714286 0 0 units box\n", gap=0)
E("R11_create_overlap_made_at_start", "lv1 moving; after run 1000 create_atoms 2 single 5.6 mm ahead of lv1's start, overlap 0.005 (LAMMPS: lv1 4.83 mm away, not made)",
  f"run 1000\ncreate_atoms 2 single {XA0(0) + 0.0056:.9g} 0.02 0.05 overlap 0.005\nset type 2 diameter 0.006 density 2500\ngroup lv2 type 2\nvelocity lv2 set -0.2285714286 0 0 units box\nrun 3000\n",
  pair=f"create_atoms 1 single {XA0(0):.9g} 0.02 0.05\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 0.7714285714 0 0 units box\n", gap=0)
for seed in (1, 2, 3, 4, 5, 6):
    E(f"R2{seed}_type_fraction_seed{seed}", f"after run 1000: set group lv1 type/fraction 3 0.5 {seed} (LAMMPS seeds each atom's draw by its position); 2 3 kn 8000",
      "run 1000\nset group lv1 type/fraction 3 0.5 " + str(seed) + "\n" + P8("2", "3") + "\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
for seed in (11, 12, 13, 14):
    E(f"R3{seed - 10}_delete_random_seed{seed}", f"victim type-1 sphere (id 1) and lv1 (id 3) in group t1; after run 1000 delete_atoms random count 1 yes t1 NULL {seed}",
      "group t1 type 1\nrun 1000\ndelete_atoms random count 1 yes t1 NULL " + str(seed) + "\nrun 3000\n", gap=g11, pre=DB(), pair=lvi(g11))
E("R40_read_dump", "dump every 1000 steps; run 1000; read_dump of step 1000 (x y z vx vy vz); run 3000",
  "dump d all custom 1000 pos.dump id type x y z vx vy vz\nrun 1000\nundump d\nread_dump pos.dump 1000 x y z vx vy vz\nrun 3000\n", gap=g11)
E("R41_fix_print_include", "fix print writes a pair_coeff line (kn 5000) to kn.in at step 1000; include kn.in; run 3000",
  'fix fp all print 1000 "' + P5() + '" file kn.in screen no\nrun 1000\nunfix fp\ninclude kn.in\nrun 3000\n', gap=g11)
E("R42_fix_print_variable_file", "fix print writes $(2000+step*3) (5000 at step 1000) to kn.txt; variable k file kn.txt; pair_coeff 1 2 hooke ${k}",
  'fix fp all print 1000 "$(2000+step*3)" file kn.txt screen no\nrun 1000\nunfix fp\nvariable k file kn.txt\npair_coeff 1 2 hooke ${k} 3000 ' + K + "\nrun 3000\n", gap=g11)
E("R43_restart_file_no_clear_data", "restart 1000 r.*; run 1000; write nothing else; clear; read_restart r.1000; run 3000 (C03 without a change)",
  "restart 1000 r.*\nrun 1000\nclear\nread_restart r.1000\n" + GRAV + FL() + TAILL + "run 3000\n", gap=g11)
E("R50_evaporate_last_run", "fix evaporate in a region around lv1's start, in the deck's only run (LAMMPS deletes lv1 at step 1: no contact)",
  f"region r sphere {XA0(0.1e-3):.9g} 0.02 0.05 0.0003 units box\nfix ev all evaporate 1 1 r 4767\nrun 3000\n", gap=0.1e-3, pre=BL(nt=3), pair=lvi(0.1e-3, (1, 2)))
E("R51_evaporate_last_run_after_run", "run 1000; then fix evaporate around lv1's place then; run 3000 (deleted in the last run)",
  f"run 1000\nregion r sphere {XA1(g11):.9g} 0.02 0.05 0.0003 units box\nfix ev all evaporate 1 1 r 4767\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("R52_evaporate_type_last_run", "fix evaporate 1 1 of group lv1 in a region the size of the box, in the last run", "region all2 block 0 0.04 0 0.04 0 0.1 units box\nfix ev lv1 evaporate 1 1 all2 4767\nrun 3000\n",
  gap=0.1e-3)
POUR3 = "region ins block 0.005 0.035 0.005 0.035 0.07 0.095 units box\nfix p all pour 1 3 4767 region ins diam one 0.004 dens 2500 2500\n"
HD = "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\n"
AFTER = (GRAV + FL() + TAILL + "group lv1 type 3\ngroup lv2 type 2\nset group lv1 x 0.01795 y 0.02 z 0.05\nset group lv2 x 0.02305 y 0.02 z 0.05\n"
         "set group lv1 diameter 0.004 density 2500\nvelocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\nrun 3000\n")
E("R60_pour_write_data_read", "pour of one type-3 sphere in run 1000; write_data; clear; read_data; the poured sphere made the live partner (3 2) by set x y z",
  POUR3 + "run 1000\nunfix p\nwrite_data d.data\nclear\n" + HD + "read_data d.data\npair_style granular\npair_coeff * * " + HK + "\n" + AFTER,
  pre=BL(nt=3), pair="create_atoms 2 single 0.023 0.02 0.05\nset atom 1 diameter 0.006 density 2500\n", gap=0)
E("R61_pour_write_restart_read", "R60 with write_restart / read_restart", POUR3 + "run 1000\nunfix p\nwrite_restart d.rst\nclear\nread_restart d.rst\n" + AFTER,
  pre=BL(nt=3), pair="create_atoms 2 single 0.023 0.02 0.05\nset atom 1 diameter 0.006 density 2500\n", gap=0)
E("R62_pour_set_xyz_live", "no clear: pour one type-3 sphere in run 1000, unfix, then make it the live partner by set x y z (3 2)",
  POUR3 + "run 1000\nunfix p\n" + AFTER.replace(GRAV + FL() + TAILL, ""), pre=BL(nt=3), pair="create_atoms 2 single 0.023 0.02 0.05\nset atom 1 diameter 0.006 density 2500\n", gap=0)
for nme in ("R60_pour_write_data_read", "R61_pour_write_restart_read", "R62_pour_set_xyz_live"):
    EXTRA[nme] = {"PAIR": "types 2 3"}
E("R63_every_delete_region_later", "run 3000 every 1000 delete_atoms region (lv1's place at step 1000): LAMMPS deletes it after part 1",
  f"region r sphere {XA1(2.1e-3):.9g} 0.02 0.05 0.0003 units box\n" + R3.format("delete_atoms region r"), pre=BL(nt=3), pair=lvi(2.1e-3, (1, 2)), gap=2.1e-3)
E("R64_every_set_fraction", "run 3000 every 1000 set group lv1 type/fraction 3 0.5 7 (position-seeded draw each part); 2 3 kn 8000",
  P8("2", "3") + "\n" + R3.format("set group lv1 type/fraction 3 0.5 7"), pre=BL(nt=3), pair=lvi(2.1e-3, (1, 2)), gap=2.1e-3)
E("R65_set_fraction_before_run", "control: set group lv1 type/fraction 3 0.5 1 before any run; 2 3 kn 8000", "set group lv1 type/fraction 3 0.5 1\n" + P8("2", "3") + "\nrun 3000\n",
  gap=0.1e-3, pre=BL(nt=3), pair=lvi(0.1e-3, (1, 2)))
E("R66_type_ratio", "after run 1000: set type 1 type/ratio 3 0.5 9 with the victim and lv1 of type 1", "run 1000\nset type 1 type/ratio 3 0.5 9\n" + P8("2", "3") + "\nrun 3000\n", gap=g11, pre=DB(), pair=lvi(g11))
E("R67_type_subset", "after run 1000: set type 1 type/subset 3 1 9 (one of the victim and lv1)", "run 1000\nset type 1 type/subset 3 1 9\n" + P8("2", "3") + "\nrun 3000\n", gap=g11, pre=DB(), pair=lvi(g11))
E("R68_create_random_overlap", "after run 1000: create_atoms 1 random 1 4767 r overlap 0.004 maxtry 1 in a tiny region at lv1's start (LAMMPS: lv1 left, made)",
  f"run 1000\nregion r sphere {XA0(g11):.9g} 0.02 0.05 0.00001 units box\ncreate_atoms 3 random 1 4767 r overlap 0.004 maxtry 1\nset type 3 diameter 0.002 density 2500\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("R69_displace_then_region_set", "run 1000; displace_atoms lv1 move 0.005 0 0; set region (lv1's start + 5 mm) type 3 (the displacement is known; the run's move not)",
  f"run 1000\ndisplace_atoms lv1 move 0 0.005 0 units box\nregion r sphere {XA0(g11):.9g} 0.025 0.05 0.0003 units box\nset region r type 3\n" + P8("2", "3") + "\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))

# ------------------------------------------------------------ batch 2: more every / pre no / neighbour / LIGGGHTS
E("N18_skin_after_run_first_touch", "every cutoff 0.001; run 1000; neighbor 0.004 bin (reach 0.005); run 3000 (N15 at the edge)", "run 1000\nneighbor 0.004 bin\nrun 3000\n", pre=CU(0.001), gap=1.1e-3)
E("N19_skin_big_then_small", "every cutoff 0.001; neighbor 0.01 bin; run 1000; neighbor 0.001 bin; run 3000 (reach 0.002 in the last run)", "neighbor 0.01 bin\nrun 1000\nneighbor 0.001 bin\nrun 3000\n", pre=CU(0.001), gap=1.1e-3)
E("N20_skin_in_include", "every cutoff 0.001; neighbor 0.01 bin in an include before the run", "include nb.in\nrun 3000\n", pre=CU(0.001), gap=0.1e-3, data={"nb.in": "neighbor 0.01 bin\n"})
E("N21_skin_every_part2", "every cutoff 0.001; run 3000 every 1000 neighbor 0.01 bin; live pair in part 3", R3.format("neighbor 0.01 bin"), pre=CU(0.001), gap=2.1e-3)
E("N22_skin_by_variable", "every cutoff 0.001; variable s equal 0.01; neighbor ${s} bin", "variable s equal 0.01\nneighbor ${s} bin\nrun 3000\n", pre=CU(0.001), gap=0.1e-3)
E("N23_cutoff_changed_after_run", "cutoff 0.001 for * * with skin 0.001; run 1000; pair_coeff * * default (no cutoff); run 3000", "run 1000\npair_coeff * * " + HK + "\nrun 3000\n", pre=CU(0.001), gap=1.1e-3)
E("N24_cutoff_set_after_run", "default; run 1000; pair_coeff * * cutoff 0.001 (skin 0.001); run 3000", "run 1000\npair_coeff * * " + HK + " cutoff 0.001\nrun 3000\n", gap=1.1e-3)
E("N25_nsq_after_run", "every cutoff 0.001; run 1000; neighbor 0.001 nsq; run 3000", "run 1000\nneighbor 0.001 nsq\nrun 3000\n", pre=CU(0.001), gap=1.1e-3)
E("N26_skin_pre_no", "every cutoff 0.001; run 1000; neighbor 0.01 bin; run 3000 pre no (no new set-up: the old lists' reach?)", "run 1000\nneighbor 0.01 bin\nrun 3000 pre no\n", pre=CU(0.001), gap=1.1e-3)
E("N27_clear_skin", "neighbor 0.01 bin; clear; base with cutoff 0.001 (skin back to 0.001)", "neighbor 0.01 bin\nclear\n" + CU(0.001) + lv(0.1e-3) + "run 3000\n", pre=BL(), live="the run after clear")
W("N28_wall_small_cutoff", "wall live: every cutoff 0.001 for pairs (walls have no list)", "run 3000\n", pre=CU(0.001), gap=0.1e-3)
E("V44_every_dt_neighbor", "every timestep $(dt*0.5) and pair_coeff 1 2 hooke $(dt*5e9) (after part 2: dt 2.5e-7 first then kn 1250)", 'run 3000 every 1000 "timestep $(dt*0.5)" "pair_coeff 1 2 hooke $(dt*5e9) 3000 ' + K + '"\nrun 16000\n', gap=1.76e-3)
E("V45_every_step_var_then_if_pair_none_hybrid", "hybrid granular zero; every variable s; if s==3000 pair_coeff 1 2 zero else nothing (passes)", VS + 'if "${s} == 3000" then "pair_coeff 1 2 zero"\nrun 1000\n',
  pre=HYB("hybrid granular zero 0.01", GG + "pair_coeff 1 1 zero\n"), gap=3.1e-3)
E("V46_every_start_stop_time", "run 3000 start 0 stop 10000 every 1000 variable t equal $(time); if t == 0.003 kn 5000 else 8000", 'run 3000 start 0 stop 10000 every 1000 "variable t equal $(time)"\n' + IFS("${t} == 0.003") + "run 1000\n", gap=3.1e-3)
E("V47_every_elapsed", "run 3000 every 1000 variable e equal $(elapsed) (1000 after each part?); if e == 1000 kn 5000 else 8000", R3.format("variable e equal $(elapsed)") + IFS("${e} == 1000") + "run 1000\n", gap=3.1e-3)
E("V48_every_elaplong", "run 3000 every 1000 variable e equal $(elaplong) (3000 at the end); if e == 3000 kn 5000 else 8000", R3.format("variable e equal $(elaplong)") + IFS("${e} == 3000") + "run 1000\n", gap=3.1e-3)
E("V49_plain_elapsed_after_run", "run 3000; if $(elapsed) == 3000 kn 5000 else 8000", "run 3000\n" + IFS("$(elapsed) == 3000") + "run 1000\n", gap=3.1e-3)
E("V50_every_step_equal_not_immediate", "run 3000 every 1000 variable s equal step (no $: lazy); if ${s} == 3000 kn 5000 else 8000", R3.format("variable s equal step") + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
E("V51_every_string_time_fmt", "every variable t string $(time:%.4f); if ${t} == 0.0030", R3.format("variable t string $(time:%.4f)") + IFS("${t} == 0.0030") + "run 1000\n", gap=3.1e-3)
E("V52_every_step_var_run_length", "every variable s; run $(v_s/3) (run 1000 where LAMMPS is); the pair meets in it; then pair_coeff kn 8000 and run 0",
  VS + "run $(v_s/3)\n" + P8() + "\nrun 0\n", gap=3.1e-3, live="run $(v_s/3)")
E("V53_every_step_var_loop_count", "every variable s; variable i loop $(v_s/1000); loop sets kn 1000*i+2000 with run 0 between", VS + "variable i loop $(v_s/1000)\nlabel l\npair_coeff 1 2 hooke $(1000*v_i+2000) 3000 " + K + "\nrun 0\nnext i\njump SELF l\nrun 1000\n", gap=3.1e-3)
E("V54_every_step_reset_timestep_after", "every variable s; reset_timestep 0; if ${s} == 3000 kn 5000 else 8000", VS + "reset_timestep 0\n" + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
E("V55_every_step_in_fix_halt", "fix halt at step > 2500 (error continue) then every variable s: the run stops at 2501; if s == 2501 or not", "variable st equal step\nfix h all halt 1 v_st > 2500 error continue\n" + 'run 3000 every 1000 "variable s equal $(step)"\n'
  + "unfix h\n" + IFS("${s} == 2000") + "run 2000\n", gap=2.6e-3)
Q = lambda *a, **k: E(*a, **k)
Q("Q22_like_change_pre_no_diam", "run 1000; set type 1 diameter 0.005 and pair_coeff 1 1 kn 8000 (1 2 explicit); run 3000 pre no", "run 1000\nset type 1 diameter 0.005\n" + P8("1", "1") + "\nrun 3000 pre no\n", gap=2.1e-3, sep=0.0055)
Q("Q23_pre_no_after_exclude_none", "neigh_modify exclude type 1 1; run 1000; exclude none; run pre no (live 1 2)", "neigh_modify exclude type 1 1\nrun 1000\nneigh_modify exclude none\nrun 3000 pre no\n", gap=1.1e-3)
Q("Q24_pre_no_every_timestep", "run 3000 pre no every 1000 timestep 5e-7, then run 2000 (the contact ends there)", 'run 3000 pre no every 1000 "timestep 5e-7"\nrun 2000\n', gap=1.55e-3)
Q("Q25_pre_no_hertz_mass", "hertz/material; run 1000; set type 2 density 7800; run 3000 pre no", "run 1000\nset type 2 density 7800\nrun 3000 pre no\n", gap=1.1e-3, pre=BL(HM))
Q("Q26_pre_no_like_hertz_unlike_mixed", "hertz/material 1 1, 2 2 only; run 1000; pair_coeff 2 2 E 3e7; run pre no; live pair 2 2", "run 1000\npair_coeff 2 2 hertz/material 3e7 1.4e7 0.3 damping viscoelastic " + TL + "\nrun 3000 pre no\n",
  pre=r.MIXHM, pair=lv(1.1e-3, 2, 2, 0.006, 0.006), gap=1.1e-3, sep=0.006)
EXTRA["Q26_pre_no_like_hertz_unlike_mixed"] = {"PAIR": "types 2 2"}
Q("Q27_pre_no_diam_up_hertz_material_control", "Q06 without pre no", "run 1000\nset type 2 diameter 0.012\nrun 3000\n", gap=g41, sep=0.008, pre=BL(HM))
Q("Q28_pre_no_diam_grow_small", "run 1000; set type 2 diameter 0.0064 (radius +0.2 mm, below the skin); run 3000 pre no", "run 1000\nset type 2 diameter 0.0064\nrun 3000 pre no\n", gap=1.3e-3, sep=0.0052)
Q("Q29_pre_no_diam_grow_1mm", "run 1000; set type 2 diameter 0.008 (+1 mm radius); run 3000 pre no", "run 1000\nset type 2 diameter 0.008\nrun 3000 pre no\n", gap=2.1e-3, sep=0.006)
Q("Q30_pre_no_diam_grow_2mm", "run 1000; set type 2 diameter 0.010 (+2 mm radius); run 3000 pre no", "run 1000\nset type 2 diameter 0.010\nrun 3000 pre no\n", gap=3.1e-3, sep=0.007)
Q("Q31_pre_no_diam_lv1_grow", "run 1000; set type 1 diameter 0.010 (+3 mm radius of the 4 mm sphere); run 3000 pre no", "run 1000\nset type 1 diameter 0.010\nrun 3000 pre no\n", gap=4.1e-3, sep=0.008)
Q("Q32_pre_no_diam_group", "run 1000; set group lv2 diameter 0.012; run 3000 pre no", "run 1000\nset group lv2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
Q("Q33_every_pre_no_diam_big", "run 3000 pre no every 1000 set type 2 diameter 0.012 (live pair in part 3)", 'run 3000 pre no every 1000 "set type 2 diameter 0.012"\n', gap=5.1e-3, sep=0.008)
W("Q34_wall_pre_no_diam", "wall live: run 1000; set type 1 diameter 0.012; run 3000 pre no (walls have no list)", "run 1000\nset type 1 diameter 0.012\nrun 3000 pre no\n", gap=1.1e-3 + 0.004)
Ll("L13_pre_no_diam_up", "LIGGGHTS run 1000; set type 2 diameter 0.012; run 3000 pre no", "run 1000\nset type 2 diameter 0.012\nrun 3000 pre no\n", gap=4.1e-3)
Ll("L14_every_step_var_e", "LIGGGHTS every variable s equal $(step); e 1 2 by if (s == 3000: 0.9)", R3.format("variable s equal $(step)") + f'if "${{s}} == 3000" then "{E3x(0.9)}" else "{E3x(0.2)}"\nrun 1000\n', gap=3.1e-3)
Ll("L15_limitForce_hooke_e05", "LIGGGHTS hooke limitForce on (characteristicVelocity set)", "run 3000\n", gap=0.1e-3, head_=LH("hooke", " limitForce on").replace("pair_style", "fix m10 all property/global characteristicVelocity scalar 1.0\npair_style"))
Ll("L16_hooke_plain", "LIGGGHTS hooke (characteristicVelocity set), e 1 2 0.5", "run 3000\n", gap=0.1e-3, head_=LH("hooke").replace("pair_style", "fix m10 all property/global characteristicVelocity scalar 1.0\npair_style"))
Ll("L17_neighbor_skin_after", "LIGGGHTS run 1000; neighbor 0.0001 bin; run 3000", "run 1000\nneighbor 0.0001 bin\nrun 3000\n", gap=1.1e-3)
Ll("L18_dtreset_every", "LIGGGHTS every timestep $(dt*0.5) and e 1 2 0.9", 'run 3000 every 1000 "timestep $(dt*0.5)" "' + E3x(0.9) + '"\nrun 6000\n', gap=1.76e-3)
Ll("L19_delete_region_later_place", "LIGGGHTS delete_atoms region where lv1 is after run 1000 (deleted: no contact)", "region r sphere {:.9g} 0 0.1 0.0003 units box\nrun 1000\ndelete_atoms region r\nrun 3000\n".format(-0.002 - 1.1e-3 / 2 + 0.7714285714e-3), gap=1.1e-3)

# ------------------------------------------------------------ batch 3: around SW1 (pre no, sizes), SW2 (lists after the first run), SW3
Q("Q35_pre_no_diam_include", "Q01 with the set in an include", "run 1000\ninclude g.in\nrun 3000 pre no\n", gap=g41, sep=0.008, data={"g.in": "set type 2 diameter 0.012\n"})
Q("Q36_pre_no_diam_variable", "Q01 with the diameter from a variable", "variable d equal 0.012\nrun 1000\nset type 2 diameter ${d}\nrun 3000 pre no\n", gap=g41, sep=0.008)
Q("Q37_pre_no_diam_then_run0", "Q01 with run 0 before the pre no run (set up again)", "run 1000\nset type 2 diameter 0.012\nrun 0\nrun 3000 pre no\n", gap=g41, sep=0.008)
Q("Q38_pre_no_diam_two_pre_no", "run 1000; set diameter 0.012; run 100 pre no; run 3000 pre no (still stale?)", "run 1000\nset type 2 diameter 0.012\nrun 100 pre no\nrun 3000 pre no\n", gap=g41 + 0.1e-3, sep=0.008)
Q("Q39_pre_no_diam_labels", "labels; run 1000; set type big diameter 0.012; run 3000 pre no", "labelmap atom 1 small 2 big\nrun 1000\nset type big diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
Q("Q40_pre_no_diam_first_run_then", "set diameter 0.012 BEFORE run 1000 (set up), then run 3000 pre no (nothing changed)", "set type 2 diameter 0.012\nrun 1000\nrun 3000 pre no\n", gap=1.1e-3 + 0.003, sep=0.008)
Q("Q41_pre_no_create_near", "run 1000; create lv2 (type 2) 0.1 mm ahead of lv1; run 3000 pre no (a new atom, no set-up)",
  "run 1000\ncreate_atoms 2 single {:.9g} 0.02 0.05\nset atom 2 diameter 0.006 density 2500\ngroup lv2 id 2\nvelocity lv2 set -0.2285714286 0 0 units box\nrun 3000 pre no\n".format(XA0(0) + 0.00077142857 + 0.002 + 0.0001 + 0.003),
  pair=f"create_atoms 1 single {XA0(0):.9g} 0.02 0.05\nset atom 1 diameter 0.004 density 2500\ngroup lv1 id 1\nvelocity lv1 set 0.7714285714 0 0 units box\n", gap=0)
Q("Q42_pre_no_displace_close", "run 1000 (pair 10 mm apart); displace_atoms lv2 to 0.1 mm from lv1; run 3000 pre no", "run 1000\ndisplace_atoms lv2 move -0.0099 0 0 units box\nrun 3000 pre no\n", gap=0.0111)
Q("Q43_pre_no_mass_and_diam_hertz", "hertz/material; run 1000; set type 2 diameter 0.008 density 7800; run 3000 pre no", "run 1000\nset type 2 diameter 0.008 density 7800\nrun 3000 pre no\n", gap=2.1e-3, sep=0.006, pre=BL(HM))
Q("Q44_pre_no_diam_every_first_part", "run 3000 pre no every 1000 set type 2 diameter 0.012; the pair meets in part 2 (just after the growth)", 'run 3000 pre no every 1000 "set type 2 diameter 0.012"\n', gap=4.1e-3, sep=0.008, live="part 2")
Q("Q45_pre_no_diam_neigh_every10", "neigh_modify every 10 delay 0 check yes; Q01", "neigh_modify every 10 delay 0 check yes\nrun 1000\nset type 2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
Ll("L20_pre_no_diam_hooke", "LIGGGHTS hooke; run 1000; set type 2 diameter 0.012; run 3000 pre no", "run 1000\nset type 2 diameter 0.012\nrun 3000 pre no\n", gap=4.1e-3,
   head_=LH("hooke").replace("pair_style", "fix m10 all property/global characteristicVelocity scalar 1.0\npair_style"))
Ll("L21_pre_no_diam_control", "LIGGGHTS L13 without pre no", "run 1000\nset type 2 diameter 0.012\nrun 3000\n", gap=4.1e-3)
for nme in ("L13_pre_no_diam_up", "L20_pre_no_diam_hooke", "L21_pre_no_diam_control"):
    EXTRA.setdefault(nme, {})["SEP"] = "0.008"
E("N29_neigh_once", "neigh_modify once yes; the pair 2.1 mm apart at the start (beyond the skin): never in a list", "neigh_modify once yes\nrun 3000\n", gap=2.1e-3)
E("N30_neigh_every2000_nocheck", "neigh_modify every 2000 delay 0 check no; gap 1.5 mm: missed until step 2000", "neigh_modify every 2000 delay 0 check no\nrun 3000\n", gap=1.5e-3)
E("N31_neigh_once_after_run", "run 1000; neigh_modify once yes; run 3000 (gap 2.1 mm at its start)", "run 1000\nneigh_modify once yes\nrun 3000\n", gap=3.1e-3)
E("N32_neigh_delay_big", "neigh_modify delay 2000 every 1 check yes; gap 1.5 mm", "neigh_modify delay 2000 every 1 check yes\nrun 3000\n", gap=1.5e-3)
E("N33_neigh_once_close", "neigh_modify once yes; the pair 0.1 mm apart at the start (inside the skin: listed)", "neigh_modify once yes\nrun 3000\n", gap=0.1e-3)
E("N34_skin_after_run_big_cutoffs", "default cutoffs; run 1000; neighbor 0.0 bin; run 3000 (reach = radii: first touch?)", "run 1000\nneighbor 0.0 bin\nrun 3000\n", gap=1.1e-3)
E("N35_skin_small_then_big_include", "every cutoff 0.001; neighbor 0.01 bin; run 1000; include with neighbor 0.001 bin; run 3000 (N19 via include)", "neighbor 0.01 bin\nrun 1000\ninclude nb.in\nrun 3000\n", pre=CU(0.001), gap=1.1e-3, data={"nb.in": "neighbor 0.001 bin\n"})
E("N36_skin_big_then_small_every", "every cutoff 0.001; neighbor 0.01 bin; run 3000 every 1000 neighbor 0.001 bin (parts 2, 3 reach 0.002)", "neighbor 0.01 bin\n" + R3.format("neighbor 0.001 bin"), pre=CU(0.001), gap=2.1e-3)
E("N37_skin_big_then_small_hertz", "hertz/material, every cutoff 0.001; neighbor 0.01; run; neighbor 0.001; run", "neighbor 0.01 bin\nrun 1000\nneighbor 0.001 bin\nrun 3000\n", pre=BL(HM + " cutoff 0.001"), gap=1.1e-3)
E("N38_skin_then_clear_loop", "loop 2: clear, base with cutoff 0.001, neighbor 0.01 in pass 1 only; run (pass 2 reach 0.002)", "", pair="", live="pass 2",
  pre='variable i loop 2\nlabel l\nclear\n' + CU(0.001) + 'if "$i == 1" then "neighbor 0.01 bin"\n' + lv(0.1e-3) + "run 3000\nnext i\njump SELF l\n")
E("N39_global_cutoff_skin_after", "pair_style granular 0.001; neighbor 0.01 bin; run 1000; neighbor 0.001 bin; run 3000", "neighbor 0.01 bin\nrun 1000\nneighbor 0.001 bin\nrun 3000\n",
  pre=head(2) + "pair_style granular 0.001\npair_coeff * * " + HK + "\n" + GRAV + FL() + TAILL, gap=1.1e-3)
DB2 = lambda: BL(nt=3) + ("create_atoms 1 single 0.01 0.01 0.01\ncreate_atoms 2 single 0.03 0.03 0.01\nset atom 1 diameter 0.002 density 2500\nset atom 2 diameter 0.006 density 2500\n")
for seed in (12, 13, 14, 11):
    E(f"R3{seed - 6}_delete_random_small_victim{seed}", f"a 2 mm type-1 victim (id 1) and lv1 (4 mm, id 3) in group t1; after run 1000 delete_atoms random count 1 yes t1 NULL {seed}",
      "group t1 type 1\nrun 1000\ndelete_atoms random count 1 yes t1 NULL " + str(seed) + "\nrun 3000\n", gap=g11, pre=DB2(), pair=lvi(g11))
E("R39_delete_random_small_control", "control for R35-R38: the 2 mm victim and a live 2 mm type-1 sphere against lv2 (6 mm), no delete", "run 3000\n", gap=0.1e-3, pre=BL(nt=3), pair=lvi(0.1e-3, (1, 2), da=0.002), sep=0.004)
E("R70_type_fraction_include", "R22 with the set in an include", "run 1000\ninclude t.in\n" + P8("2", "3") + "\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)), data={"t.in": "set group lv1 type/fraction 3 0.5 2\n"})
E("R71_type_fraction_type_style", "after run 1000: set type 1 type/fraction 3 0.5 2 (by type, not group)", "run 1000\nset type 1 type/fraction 3 0.5 2\n" + P8("2", "3") + "\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("R72_type_fraction_seed5_atom", "after run 1000: set atom 1 type/fraction 3 0.5 5", "run 1000\nset atom 1 type/fraction 3 0.5 5\n" + P8("2", "3") + "\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
for nme in ("R70_type_fraction_include", "R71_type_fraction_type_style", "R72_type_fraction_seed5_atom"):
    EXTRA[nme] = {"PAIR": "types 1 2"}
Ll("L22_type_fraction_after_run", "LIGGGHTS run 1000; set group lv1 type/fraction 3 0.5 2; run 3000", "run 1000\nset group lv1 type/fraction 3 0.5 2\nrun 3000\n", gap=1.1e-3)
Ll("L23_skin_big_then_small", "LIGGGHTS neighbor 0.01 bin; run 1000; neighbor 0.0001 bin; run 3000", "neighbor 0.01 bin\nrun 1000\nneighbor 0.0001 bin\nrun 3000\n", gap=1.1e-3)

# ------------------------------------------------------------ batch 4: edges of SW1-SW3, the segfault refusal (V23)
E("N40_neigh_every2000_after_run", "run 1000; neigh_modify every 2000 delay 0 check no; run 3000 (gap 2.5 mm at its start: missed until a build)", "run 1000\nneigh_modify every 2000 delay 0 check no\nrun 3000\n", gap=2.5e-3)
E("N41_neigh_every2000_then_default", "neigh_modify every 2000 check no; run 1000; neigh_modify every 1 delay 0 check yes; run 3000 (fresh lists in the last run)", "neigh_modify every 2000 delay 0 check no\nrun 1000\nneigh_modify every 1 delay 0 check yes\nrun 3000\n", gap=1.1e-3)
E("N42_nsq_then_bin_after_run", "every cutoff 0.001; neighbor 0.001 nsq; run 1000; neighbor 0.001 bin; run 3000", "neighbor 0.001 nsq\nrun 1000\nneighbor 0.001 bin\nrun 3000\n", pre=CU(0.001), gap=1.1e-3)
E("N43_skin_big_then_small_pre_no", "every cutoff 0.001; neighbor 0.01 bin; run 1000; neighbor 0.001 bin; run 3000 pre no", "neighbor 0.01 bin\nrun 1000\nneighbor 0.001 bin\nrun 3000 pre no\n", pre=CU(0.001), gap=1.1e-3)
E("N44_skin_big_small_big", "every cutoff 0.001; neighbor 0.01; run 1000; neighbor 0.001; run 1000; neighbor 0.01; run 3000 (the pair meets in the last)", "neighbor 0.01 bin\nrun 1000\nneighbor 0.001 bin\nrun 1000\nneighbor 0.01 bin\nrun 3000\n", pre=CU(0.001), gap=2.1e-3)
E("N45_skin_small_big_small", "every cutoff 0.001; neighbor 0.001; run 1000; neighbor 0.01; run 1000 (the pair meets in it); neighbor 0.001; run 1000", "run 1000\nneighbor 0.01 bin\nrun 1000\nneighbor 0.001 bin\nrun 1000\n", pre=CU(0.001), gap=1.1e-3, live="the second run")
E("N46_skin_cutoff_0035_after", "every cutoff 0.0035; neighbor 0.01 bin; run 1000; neighbor 0.0005 bin; run 3000 (reach 0.004 < 0.005)", "neighbor 0.01 bin\nrun 1000\nneighbor 0.0005 bin\nrun 3000\n", pre=CU(0.0035), gap=1.1e-3)
Ll("L24_skin_after_run_small_cutoff_hertz", "LIGGGHTS neighbor 0.01 bin; run 1000; neighbor 0.00001 bin; run 3000 (sizes-based lists)", "neighbor 0.01 bin\nrun 1000\nneighbor 0.00001 bin\nrun 3000\n", gap=1.1e-3)
Q("Q46_pre_no_diam_big_skin_after", "run 1000; neighbor 0.005 bin; set type 2 diameter 0.012; run 3000 pre no (skin 5 mm > growth, but not set up)", "run 1000\nneighbor 0.005 bin\nset type 2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008)
Q("Q47_pre_no_diam_skin5_from_start", "neighbor 0.005 bin from the start; run 1000; set type 2 diameter 0.012; run 3000 pre no (control of the edge)", "run 1000\nset type 2 diameter 0.012\nrun 3000 pre no\n", gap=g41, sep=0.008, pre=BL() + "neighbor 0.005 bin\n")
Q("Q48_pre_no_diam_growth_0p4", "run 1000; set type 2 diameter 0.0068 (radius +0.4 mm, below the skin 1 mm); run 3000 pre no", "run 1000\nset type 2 diameter 0.0068\nrun 3000 pre no\n", gap=1.5e-3, sep=0.0054)
Q("Q49_pre_no_diam_growth_0p8", "run 1000; set type 2 diameter 0.0076 (radius +0.8 mm); run 3000 pre no", "run 1000\nset type 2 diameter 0.0076\nrun 3000 pre no\n", gap=1.9e-3, sep=0.0058)
Q("Q50_pre_no_diam_in_loop", "loop 2: run 500; set type 2 diameter 0.012 in pass 2 then run 3000 pre no", 'variable i loop 2\nlabel l\nrun 500\nnext i\njump SELF l\nset type 2 diameter 0.012\nrun 3000 pre no\n', gap=g41, sep=0.008)
E("R73_type_fraction_one", "after run 1000: set group lv1 type/fraction 3 1.0 2 (every atom: no draw matters)", "run 1000\nset group lv1 type/fraction 3 1.0 2\n" + P8("2", "3") + "\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
EXTRA["R73_type_fraction_one"] = {"PAIR": "types 2 3"}
E("R74_type_fraction_zero", "after run 1000: set group lv1 type/fraction 3 0.0 2 (no atom)", "run 1000\nset group lv1 type/fraction 3 0.0 2\n" + P8("2", "3") + "\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("R75_type_fraction_lv2", "after run 1000: set group lv2 type/fraction 3 0.5 2 (the 6 mm sphere); 1 3 kn 8000", "run 1000\nset group lv2 type/fraction 3 0.5 2\n" + P8("1", "3") + "\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("R76_type_fraction_lv2_seed9", "as R75 with seed 9", "run 1000\nset group lv2 type/fraction 3 0.5 9\n" + P8("1", "3") + "\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("R77_type_fraction_every", "run 3000 every 1000 set group lv1 type/fraction 3 0.5 2; 2 3 kn 8000 (live pair in part 3)", P8("2", "3") + "\n" + R3.format("set group lv1 type/fraction 3 0.5 2"), pre=BL(nt=3), pair=lvi(2.1e-3, (1, 2)), gap=2.1e-3)
E("V56_step_density_plus_one", "every variable s; set type 2 density $(v_s+1) (V23 without a zero in a pass at step 0)", VS + "set type 2 density $(v_s+1)\nrun 1000\n", gap=3.1e-3)
E("V57_step_diameter", "every variable s; set type 2 diameter $(0.006+v_s*1e-7) (6.3 mm)", VS + "set type 2 diameter $(0.006+v_s*1e-7)\nrun 1000\n", gap=3.1e-3 + 0.00015, sep=0.00515)
E("V58_step_mass_zero_guard", "every variable s; set type 2 mass $(v_s*1e-7) (3e-4 kg; 0 at step 0)", VS + "set type 2 mass $(v_s*1e-7)\nrun 1000\n", gap=3.1e-3)

# ------------------------------------------------------------ batch 5: commands that write or run outside the deck (canaries under /tmp, named f28_*), next in an every
CAN = "/tmp/f28_canary_"
E("S01_shell_top", "shell touch a canary at the top level (LAMMPS runs it; the audit must not)", f"shell touch {CAN}S01\nrun 3000\n", gap=0.1e-3)
E("S02_shell_every", "shell touch in an every", R3.format(f"shell touch {CAN}S02"))
E("S03_log_abs", "log to an absolute path", f"log {CAN}S03.log\nrun 3000\n", gap=0.1e-3)
E("S04_print_file_top", "print to an absolute file", f'print "x" file {CAN}S04.txt\nrun 3000\n', gap=0.1e-3)
E("S05_print_append_every", "print append to an absolute file in an every", "run 3000 every 1000 'print \"x\" append " + CAN + "S05.txt'\n")
E("S06_write_dump_after_run", "write_dump after a run (runs made for real: a step read later)", f"run 1000\nwrite_dump all atom {CAN}S06.dump\n" + IFS("$(step) == 1000") + "run 3000\n", gap=1.1e-3)
E("S07_fix_print_file", "fix print to an absolute file during the runs, a step read later (runs made for real)", f'fix fp all print 100 "x" file {CAN}S07.txt screen no\nrun 1000\n' + IFS("$(step) == 1000") + "run 3000\n", gap=1.1e-3)
E("S08_write_restart_abs", "write_restart to an absolute path", f"write_restart {CAN}S08.rst\nrun 3000\n", gap=0.1e-3)
E("S09_restart_every_abs", "restart 500 to an absolute path; a step read later (runs made for real)", f"restart 500 {CAN}S09.*\nrun 1000\n" + IFS("$(step) == 1000") + "run 3000\n", gap=1.1e-3)
E("S10_dump_abs_made_runs", "dump to an absolute path; runs made for real (a set by region after a run)", f"dump d all atom 100 {CAN}S10.dump\nregion far block 0 0.04 0 0.04 0.09 0.1 units box\nrun 1000\nset region far density 3000\nrun 3000\n", gap=1.1e-3)
E("S11_write_data_every_abs", "write_data in an every to an absolute path", R3.format(f"write_data {CAN}S11.data"))
E("S12_shell_cd", "shell cd .. then write_data x (relative to the changed cwd)", "shell cd ..\nwrite_data f28_canary_S12.data\nrun 3000\n", gap=0.1e-3)
E("V59_every_next", "variable i loop 5; run 3000 every 1000 next i (i = 4 after); if i == 4 kn 5000 else 8000", "variable i loop 5\n" + R3.format("next i") + IFS("${i} == 4") + "run 1000\n", gap=3.1e-3)
E("V60_every_variable_delete", "variable s equal 1; run 3000 every 1000 variable s delete + variable s equal $(step)", "variable s equal 1\n" + 'run 3000 every 1000 "variable s delete" "variable s equal $(step)"\n' + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
E("V61_every_label_var_print", "every print with a format of the step: print $(step:%08d)", R3.format("print $(step:%08d)") + P5() + "\nrun 1000\n", gap=3.1e-3)

# ------------------------------------------------------------ batch 6: around V60 (a step variable deleted and made again in an every)
E("V62_every_delete_define_no_prior", "no prior s; run 3000 every 1000 variable s delete + variable s equal $(step); if s == 3000 kn 5000 else 8000", 'run 3000 every 1000 "variable s delete" "variable s equal $(step)"\n' + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
E("V63_prior_def_every_define", "variable s equal 1 first; run 3000 every 1000 variable s equal $(step) (no delete); if s == 3000", "variable s equal 1\n" + VS + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
E("V64_prior_string_every_string", "variable s string x first; every variable s string $(step); if s == 3000", "variable s string x\n" + R3.format("variable s string $(step)") + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
E("V65_delete_after_every", "every variable s; variable s delete; variable s equal $(step) outside (3000); if s == 3000", VS + "variable s delete\nvariable s equal $(step)\n" + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
E("V66_every_define_then_delete", "every variable t equal $(step) + variable s equal ${t}? no: every variable s equal $(step) + variable s delete + variable s equal $(2*step)", 'run 3000 every 1000 "variable s equal $(step)" "variable s delete" "variable s equal $(2*step)"\n' + IFS("${s} == 6000") + "run 1000\n", gap=3.1e-3)
E("V67_prior_equal_step_lazy_every_delete", "variable s equal step (lazy) first; every variable s delete + variable s equal $(step)", "variable s equal step\n" + 'run 3000 every 1000 "variable s delete" "variable s equal $(step)"\n' + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
E("V68_prior_def_delete_kn", "variable k equal 8000 first; every variable k delete + variable k equal $(step+2000); pair_coeff 1 2 hooke ${k}", "variable k equal 8000\n" + 'run 3000 every 1000 "variable k delete" "variable k equal $(step+2000)"\n' + "pair_coeff 1 2 hooke ${k} 3000 " + K + "\nrun 1000\n", gap=3.1e-3)
E("V69_every_delete_only_then_define", "variable s equal 1; run 3000 every 1000 variable s delete; variable s equal $(step) after", "variable s equal 1\n" + R3.format("variable s delete") + "variable s equal $(step)\n" + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)

# ------------------------------------------------------------ batch 7: SW4 reach (where the prior definition comes from, how it is read later)
E("V70_prior_def_include", "variable s equal 1 in an include; every variable s equal $(step); if s == 3000", "include v.in\n" + VS + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3, data={"v.in": "variable s equal 1\n"})
E("V71_prior_def_lazy_use", "variable s equal 1; every variable s equal $(step); variable b equal v_s*2; if b == 6000", "variable s equal 1\n" + VS + "variable b equal v_s*2\n" + IFS("${b} == 6000") + "run 1000\n", gap=3.1e-3)
E("V72_prior_def_density", "variable s equal 2500; every variable s equal $(step+2000) (5000); set type 2 density ${s}", "variable s equal 2500\n" + R3.format("variable s equal $(step+2000)") + "set type 2 density ${s}\nrun 1000\n", gap=3.1e-3)
E("V73_prior_def_wall_time", "variable t equal 0; every variable t equal $(time) (3e-3); if t > 0.002 kn 5000 else 8000", "variable t equal 0\n" + R3.format("variable t equal $(time)") + IFS("${t} > 0.002") + "run 1000\n", gap=3.1e-3)
E("V74_prior_def_after_run", "run 1000; variable s equal 1; every variable s equal $(step) (4000); if s == 4000", "run 1000\nvariable s equal 1\n" + VS + IFS("${s} == 4000") + "run 1000\n", gap=4.1e-3)
E("V75_prior_def_loop_style", "variable s loop 3 (a loop variable); every variable s delete + variable s equal $(step); if s == 3000", "variable s loop 3\n" + 'run 3000 every 1000 "variable s delete" "variable s equal $(step)"\n' + IFS("${s} == 3000") + "run 1000\n", gap=3.1e-3)
E("V76_prior_def_step_part2", "variable s equal 1; run 3000 every 1000 variable s + pair_coeff 1 2 kn 5000 (the if after the run; pair meets in part 3)", "variable s equal 1\n" + 'run 3000 every 1000 "variable s equal $(step)" "' + P5() + '"\n' + f'if "${{s}} == 3000" then "{P8()}"\nrun 1000\n', gap=3.1e-3)
W("V77_prior_def_wall", "wall live: variable s equal 1; every variable s equal $(step); fix floor kn $(v_s+5000) (8000); run 1000", "variable s equal 1\n" + VS + "fix floor all wall/gran granular hooke $(v_s+5000) 3000 " + K + " zplane 0 NULL\nrun 1000\n", gap=3.1e-3)
Ll("L25_prior_def_every_step", "LIGGGHTS variable s equal 1; every variable s equal $(step); if s == 3000 e 1 2 0.9 else 0.2", "variable s equal 1\n" + R3.format("variable s equal $(step)") + f'if "${{s}} == 3000" then "{E3x(0.9)}" else "{E3x(0.2)}"\nrun 1000\n', gap=3.1e-3)
E("N47_neigh_delay_then_default", "neigh_modify delay 2000; run 1000; neigh_modify delay 0 every 1 check yes; run 3000 (fresh lists in the last run)", "neigh_modify delay 2000 every 1 check yes\nrun 1000\nneigh_modify delay 0 every 1 check yes\nrun 3000\n", gap=1.1e-3)
E("N48_neigh_once_then_no", "neigh_modify once yes; run 1000; neigh_modify once no; run 3000", "neigh_modify once yes\nrun 1000\nneigh_modify once no\nrun 3000\n", gap=1.1e-3)

# ------------------------------------------------------------ batch 8: X07's crash (a region wall whose region is deleted and made again, then run pre no)
RW = "region cyl cylinder z 0.02 0.02 0.019 0 0.1 side in units box\nfix rw all wall/gran/region granular " + HK + " region cyl\n"
E("Q51_region_redefined_pre_no", "region wall; run 1000; region cyl delete + made again (same shape); run 3000 pre no", "run 1000\nregion cyl delete\nregion cyl cylinder z 0.02 0.02 0.019 0 0.1 side in units box\nrun 3000 pre no\n", pre=BL() + RW, gap=1.1e-3)
E("Q52_region_redefined_run", "Q51 without pre no (control)", "run 1000\nregion cyl delete\nregion cyl cylinder z 0.02 0.02 0.019 0 0.1 side in units box\nrun 3000\n", pre=BL() + RW, gap=1.1e-3)
E("Q53_region_redefined_every", "region wall; run 3000 every 1000 region cyl delete + made again", 'run 3000 every 1000 "region cyl delete" "region cyl cylinder z 0.02 0.02 0.019 0 0.1 side in units box"\n', pre=BL() + RW, gap=2.1e-3)
E("Q54_region_redefined_pre_no_every", "region wall; run 3000 pre no every 1000 region cyl delete + made again", 'run 3000 pre no every 1000 "region cyl delete" "region cyl cylinder z 0.02 0.02 0.019 0 0.1 side in units box"\n', pre=BL() + RW, gap=2.1e-3)

E("Q55_region_rotating_redefined_pre_no", "region wall; run 1000; region cyl delete + made again rotating by a variable of the step (X07's form); run 3000 pre no",
  "run 1000\nregion cyl delete\nvariable th equal (step-1000)*1e-3\nregion cyl cylinder z 0.02 0.02 0.019 0 0.1 side in units box rotate v_th 0.02 0.02 0 0 0 1\nrun 3000 pre no\n", pre=BL() + RW, gap=1.1e-3)
E("Q56_region_rotating_redefined_run", "Q55 without pre no (control)",
  "run 1000\nregion cyl delete\nvariable th equal (step-1000)*1e-3\nregion cyl cylinder z 0.02 0.02 0.019 0 0.1 side in units box rotate v_th 0.02 0.02 0 0 0 1\nrun 3000\n", pre=BL() + RW, gap=1.1e-3)

# ------------------------------------------------------------ batch 9: files the deck writes outside runs and reads back; random draws the runs consume
E("T01_print_file_include", "print a pair_coeff line (kn 5000) to kn.in at the top level; include kn.in", 'print "' + P5() + '" file kn.in screen no\ninclude kn.in\nrun 3000\n', gap=0.1e-3)
E("T02_print_file_variable_file", "print 5000 to kn.txt; variable k file kn.txt; pair_coeff 1 2 hooke ${k}", 'print "5000" file kn.txt screen no\nvariable k file kn.txt\npair_coeff 1 2 hooke ${k} 3000 ' + K + "\nrun 3000\n", gap=0.1e-3)
E("T03_print_append_include", "print append two lines (kn 5000 then kn 8000) to kn.in; include kn.in (kn 8000)", 'print "' + P5() + '" append kn.in screen no\nprint "' + P8() + '" append kn.in screen no\ninclude kn.in\nrun 3000\n', gap=0.1e-3)
E("T04_write_coeff_include", "write_coeff c.txt (the coefficients kn 5000); pair_coeff * * kn 2000; include c.txt (kn 5000 back)", P5() + "\nwrite_coeff c.txt\npair_coeff * * " + HK + "\ninclude c.txt\nrun 3000\n", gap=0.1e-3)
E("T05_print_file_after_run_include", "run 1000; print kn 5000 to kn.in; include kn.in; run 3000", 'run 1000\nprint "' + P5() + '" file kn.in screen no\ninclude kn.in\nrun 3000\n', gap=1.1e-3)
E("T06_write_data_pair_ij_read", "pair_coeff 1 2 kn 5000; write_data d.data pair ij; clear; read_data (the data file's PairIJ Coeffs)", P5() + "\nwrite_data d.data pair ij\nclear\n" + m.RD("d.data").replace("timestep 1e-5", "timestep 1e-6").replace("pair_coeff * * " + HK + "\n", "") + "group lv1 id 1\ngroup lv2 id 2\nrun 3000\n", gap=0.1e-3)
for k, seed in enumerate((4767, 1234, 99, 31337, 2024, 7)):
    E(f"T1{k}_random_thermo_seed{seed}", f"variable r equal random(0,1,{seed}) printed by thermo every 100 steps in run 1000 (11 draws); if $(v_r) > 0.5 kn 5000 else 8000",
      f"variable r equal random(0,1,{seed})\nthermo_style custom step v_r\nthermo 100\nrun 1000\n" + IFS("$(v_r) > 0.5") + "run 3000\n", gap=g11)
E("T16_random_no_thermo", "control: random(0,1,4767) read first after the run (no draw in it); if > 0.5 kn 5000 else 8000", "variable r equal random(0,1,4767)\nrun 1000\n" + IFS("$(v_r) > 0.5") + "run 3000\n", gap=g11)
E("T17_random_fix_print", "fix print of v_r every 100 steps in run 1000; if $(v_r) > 0.5", 'variable r equal random(0,1,1234)\nfix fp all print 100 "r ${r}" screen no\nrun 1000\nunfix fp\n' + IFS("$(v_r) > 0.5") + "run 3000\n", gap=g11)

# ------------------------------------------------------------ batch 10: a like pair's cutoff changed under pre no (kept by the audit; LAMMPS' lists and bins not set up again)
L11 = lambda: lv(1.1e-3, 1, 1, 0.004, 0.004)
Q("Q57_pre_no_like_cutoff_small", "run 1000; pair_coeff 1 1 ... cutoff 0.001 (skin 0.001: reach 0.002 < 0.004); run 3000 pre no; live pair 1 1", "run 1000\npair_coeff 1 1 " + HK + " cutoff 0.001\nrun 3000 pre no\n", gap=1.1e-3, pair=L11(), sep=0.004)
Q("Q58_pre_no_like_cutoff_back", "* * cutoff 0.001 (reach 0.002); run 1000; pair_coeff 1 1 without cutoff; run 3000 pre no; live pair 1 1", "run 1000\npair_coeff 1 1 " + HK + "\nrun 3000 pre no\n", gap=1.1e-3, pair=L11(), sep=0.004, pre=CU(0.001))
Q("Q59_like_cutoff_back_control", "Q58 without pre no", "run 1000\npair_coeff 1 1 " + HK + "\nrun 3000\n", gap=1.1e-3, pair=L11(), sep=0.004, pre=CU(0.001))
Q("Q60_like_cutoff_small_control", "Q57 without pre no", "run 1000\npair_coeff 1 1 " + HK + " cutoff 0.001\nrun 3000\n", gap=1.1e-3, pair=L11(), sep=0.004)
for nme in ("Q57_pre_no_like_cutoff_small", "Q58_pre_no_like_cutoff_back", "Q59_like_cutoff_back_control", "Q60_like_cutoff_small_control"):
    EXTRA[nme] = {"PAIR": "types 1 1"}

# ------------------------------------------------------------ batch 11: type/ratio, type/subset with a 2 mm victim (which atom is drawn shows in the sizes)
for k, (kw, seed) in enumerate((("type/ratio 3 0.5", 9), ("type/subset 3 1", 9), ("type/ratio 3 0.5", 3), ("type/subset 3 1", 4))):
    tag = kw.split()[0].replace("/", "_")
    E(f"R8{k}_{tag}_seed{seed}_small_victim", f"a 2 mm type-1 victim and lv1 (4 mm); after run 1000 set type 1 {kw} {seed}; pair_coeff 2 3 kn 8000",
      f"run 1000\nset type 1 {kw} {seed}\n" + P8("2", "3") + "\nrun 3000\n", gap=g11, pre=DB2(), pair=lvi(g11))

# ------------------------------------------------------------ batch 12: a type emptied after its inserting fix has finished (still defined)
E("D28_pour_done_then_delete", "fix pour of 1 type-3 sphere (made at the first step); run 1000; delete the type-3 atoms (group by type made after); run 3000 with the pour still defined",
  POUR3 + "run 1000\ngroup g3 type 3\ndelete_atoms group g3\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("D29_deposit_done_then_delete", "fix deposit of 1 type-3 sphere at step 1 (N 1, every 100000); run 1000; delete it; run 3000",
  "region ins block 0.005 0.035 0.005 0.035 0.07 0.095 units box\nfix dep all deposit 1 3 100000 4767 region ins near 0.004\nrun 1000\ngroup g3 type 3\ndelete_atoms group g3\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("D30_pour_done_live_type3", "fix pour of 1 type-3 sphere made in run 1000; the live pair 1 2; state at the end: one type-3 sphere (control of D28)", POUR3 + "run 1000\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))

# ------------------------------------------------------------ batch 13: a step variable set in an every read by commands the audit does not watch (include, jump, label names)
KF = {"k3000.in": P5() + "\n", "k0.in": P8() + "\n", "k1000.in": P8() + "\n", "k2000.in": P8() + "\n"}
E("V78_every_step_include_name", "every variable s; include k${s}.in (k3000.in: kn 5000; k0.in: kn 8000)", VS + "include k${s}.in\nrun 1000\n", gap=3.1e-3, data=KF)
E("V79_every_step_jump_label", "every variable s; jump SELF L${s}; label L0: kn 8000; label L3000: kn 5000", VS + "jump SELF L${s}\nlabel L0\n" + P8() + "\njump SELF end\nlabel L3000\n" + P5() + "\nlabel end\nrun 1000\n", gap=3.1e-3)
E("V80_every_step_jump_file", "every variable s; jump k${s}.in (the deck goes on in that file: kn then run 1000)", VS + "jump j${s}.in\n", gap=3.1e-3,
  data={"j3000.in": P5() + "\nrun 1000\n", "j0.in": P8() + "\nrun 1000\n"})
E("V81_plain_step_include_name", "no every: run 3000; include k$(step).in", "run 3000\ninclude k$(step).in\nrun 1000\n", gap=3.1e-3, data=KF)
E("V82_every_time_include_name", "every variable t equal $(time*1e6:%.0f) -> 3000; include k${t}.in", R3.format("variable t equal $(time*1e6)") + "include k$(v_t:%.0f).in\nrun 1000\n", gap=3.1e-3, data=KF)
E("V83_every_step_next_loop_count", "every variable s; variable n loop ${s} (3000 passes? no: a loop of ${s}/1000 via label jump) - if-free branch by loop count", VS + "variable n loop $(v_s/1000)\nlabel l\n" + P3() + "\nnext n\njump SELF l\nrun 1000\n", gap=3.1e-3)

E("V84_plain_step_group_id", "no every: run 3000; group g id $(step/1500) (id 2, lv2); set group g type 3; 1 3 kn 8000; run 1000", "run 3000\ngroup g id $(step/1500)\nset group g type 3\n" + P8("1", "3") + "\nrun 1000\n", gap=3.1e-3, pre=BL(nt=3), pair=lvi(3.1e-3, (1, 2)))
EXTRA["V84_plain_step_group_id"] = {"PAIR": "types 1 3"}
E("V85_plain_step_jump_label", "no every: run 3000; jump SELF L$(step); label L0 kn 8000; label L3000 kn 5000", "run 3000\njump SELF L$(step)\nlabel L0\n" + P8() + "\njump SELF end\nlabel L3000\n" + P5() + "\nlabel end\nrun 1000\n", gap=3.1e-3)
E("V86_plain_time_include", "no every: run 3000; include k$(time*1e6:%.0f).in", "run 3000\ninclude k$(time*1e6:%.0f).in\nrun 1000\n", gap=3.1e-3, data=KF)
E("V87_plain_step_include_then_if", "V81 plus a watched read after it (if $(step) > 0 print): does the clocked pass come back?", "run 3000\ninclude k$(step).in\nif \"$(step) > 0\" then \"print yes\"\nrun 1000\n", gap=3.1e-3, data=KF)

E("V88_plain_step_include_only_real_file", "V81 with only k3000.in present (the file the deck's run reaches)", "run 3000\ninclude k$(step).in\nrun 1000\n", gap=3.1e-3, data={"k3000.in": P5() + "\n"})

E("V89_plain_step_delete_group_name", "group g0 id 1 (lv1), group g3000 id 3 (a far type-1 victim); run 3000; delete_atoms group g$(step) (LAMMPS: the victim)",
  "create_atoms 1 single 0.01 0.01 0.08\nset atom 3 diameter 0.004 density 2500\ngroup g0 id 1\ngroup g3000 id 3\nrun 3000\ndelete_atoms group g$(step)\nrun 1000\n", gap=3.1e-3, pre=BL(nt=3), pair=lvi(3.1e-3, (1, 2)))
E("V90_count_after_pour_include", "pour of 2 type-3 spheres in run 1000; include k$(count(all)).in (LAMMPS 4 atoms: k4.in kn 5000; 2 atoms: k2.in kn 8000)",
  POUR3.replace("pour 1 3", "pour 2 3") + "run 1000\ninclude k$(count(all)).in\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)), data={"k4.in": P5() + "\n", "k2.in": P8() + "\n", "k3.in": P3() + "\n"})
E("V91_xcm_jump_label", "run 1000; jump SELF L$(xcm(lv1,x)>0.018) (lv1 has moved past 0.018: L1 kn 5000; at its start: L0 kn 8000)",
  "run 1000\njump SELF L$(xcm(lv1,x)>0.018)\nlabel L0\n" + P8() + "\njump SELF end\nlabel L1\n" + P5() + "\nlabel end\nrun 3000\n", gap=g11)

LKF = {"k3000.in": E3x(0.9) + "\n", "k0.in": E3x(0.2) + "\n", "k1.in": E3x(0.2) + "\n", "k3.in": E3x(0.2) + "\n"}
Ll("L26_plain_step_include_name", "LIGGGHTS run 3000; include k$(step).in (k3000.in: e 1 2 0.9; others 0.2)", "run 3000\ninclude k$(step).in\nrun 1000\n", gap=3.1e-3)
m.DECKS["L26_plain_step_include_name"] = (m.DECKS["L26_plain_step_include_name"][0], 1, LKF, True, "in.deck")
Ll("L27_plain_step_include_only_real", "LIGGGHTS L26 with only k3000.in", "run 3000\ninclude k$(step).in\nrun 1000\n", gap=3.1e-3)
m.DECKS["L27_plain_step_include_only_real"] = (m.DECKS["L27_plain_step_include_only_real"][0], 1, {"k3000.in": E3x(0.9) + "\n"}, True, "in.deck")
Ll("L28_plain_step_if", "LIGGGHTS run 3000; if $(step) == 3000 e 1 2 0.9 else 0.2 (a watched read)", "run 3000\n" + f'if "$(step) == 3000" then "{E3x(0.9)}" else "{E3x(0.2)}"\nrun 1000\n', gap=3.1e-3)

E("R78_type_fraction_region", "R22 by a region holding the whole box (a pick by position: runs made for real?)", "region box2 block 0 0.04 0 0.04 0 0.1 units box\nrun 1000\nset region box2 type/fraction 3 0.5 2\n" + P8("2", "3") + "\nrun 3000\n", gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))
E("R79_type_fraction_made_runs", "R22 with a step read after it (if $(step) > 0 print): runs made for real", "run 1000\nset group lv1 type/fraction 3 0.5 2\n" + P8("2", "3") + '\nif "$(step) > 0" then "print yes"\nrun 3000\n', gap=g11, pre=BL(nt=3), pair=lvi(g11, (1, 2)))

def write_all(names):
    m.write_live(names, LIVE, EXTRA)


if __name__ == "__main__":
    write_all(sys.argv[1:] or list(m.DECKS))
    print(len(m.DECKS), "decks")

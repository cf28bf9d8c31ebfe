"""Field round 41: write decks/NAME/ (in.deck and the files it reads) for the referee (round 37's live37.py) and the
audit. An adversarial round on main 4f03c967, which notes a law changed between stages, atoms kicked between runs,
walls redefined or removed between runs, and deform remap x. Families:
- V: run-time state in the audit's pass (runs skipped: the atoms do not move): `if` on a sphere's place or velocity,
  `$(...)` and equal-style variables of places in pair_coeff/timestep/set, loops that end on a place, fix halt, a
  run's every with such an if;
- P: `run ... pre no` after a change (explicit 1 2 coefficients, coeff_restitution, hertz/material, a like pair's
  mix, timestep, a redefined gravity or wall, an integrator added, a type changed; LIGGGHTS e and youngsModulus);
- M: mid-contact changes not in the notes' lists (the integrator redefined as nve/limit, stopped 100 steps, fixes
  present from the start unfixed mid-contact, dt/reset, temp/rescale, oneway, adapt diameter, nve/noforce, langevin,
  drag, neighbor and neigh_modify every, a sphere created at the contact, pair_style zero/none mid-contact, type
  labels, run every M not dividing N, loops of 1- and 10-step runs, dynamic groups, a LIGGGHTS move/mesh added);
- X: the reader of the executed stream: a file written by fix print during a run and then included, log none,
  echo none, print of a command's text, a command built from a string variable, & continuations, triple quotes.
Helpers are rounds 35-39's (make_decks39.py imported; its decks are not written). LAMMPS controls (round 37): kn 2000
0.413435, 5000 0.578975; the floor 0.361743; LIGGGHTS e 0.5 0.499928, the wall e 0.7 0.699141.
usage: python make_decks41.py [NAME-PREFIX ...]"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field39"))
import make_decks39 as m9  # noqa: E402

m7 = m9.m7
m7.DECKS.clear(); m7.LINKS.clear(); m7.HARD.clear()
m7.D = os.path.join(HERE, "decks")
L, LG = m7.L, m7.LG
PCs, PC5, LE, LEe, IN, LIN, HK, HKk, RB = m7.PCs, m7.PC5, m7.LE, m7.LEe, m7.IN, m7.LIN, m7.HK, m7.HKk, m7.RB
m = m7.m
BASE, LBASE, LWALL, WALLP, WALL = m.BASE, m.LBASE, m.LWALL, m.WALLP, m.WALL
DECKS = m7.DECKS
LW = dict(PAIR="type 1 on wall wprim")

S = lambda name, desc, X, **kw: L(name, desc, "run 300\n" + X + "run 2000\n", live="run 1 (and run 2)", **kw)
B = lambda name, desc, X, **kw: L(name, desc, "run 50\n" + X + "run 3000\n", live="run 2", **kw)      # before the meeting
SW = lambda name, desc, X, pre=None, **kw: L(name, "WALL: " + desc, "run 300\n" + X + "run 2000\n", pre=pre or BASE(), pair=WALLP(),
                                             live="run 1 (and run 2)", **WALL, **kw)
BW = lambda name, desc, X, pre=None, **kw: L(name, "WALL: " + desc, "run 50\n" + X + "run 3000\n", pre=pre or BASE(), pair=WALLP(),
                                             live="run 2", **WALL, **kw)
SG = lambda name, desc, X, **kw: LG(name, "LIGGGHTS: " + desc, "run 300\n" + X + "run 2000\n", live="run 1 (and run 2)", **kw)
BG = lambda name, desc, X, **kw: LG(name, "LIGGGHTS: " + desc, "run 50\n" + X + "run 3000\n", live="run 2", **kw)
CR = lambda k, e=0.5: f"hooke {k} {e} damping coeff_restitution tangential linear_nohistory 1 0.3"
RBCR = BASE(wall=False, coeff="pair_coeff * * " + CR(2000) + "\n")
HM = lambda E, e=0.5: f"hertz/material {E} {e} 0.3 damping tsuji tangential linear_nohistory 1 0.3"
RBHM = BASE(wall=False, coeff="pair_coeff * * " + HM("1e7") + "\n")
PC5s = PCs(5000)
IFX = lambda cmds, op=">", thr="0.0181": f'if "$(xcm(lv1,x)) {op} {thr}" then ' + " ".join(f'"{c}"' for c in cmds) + "\n"
XK = "$(2000+1e8*(xcm(lv1,x)-0.01795))"          # 2000 in the audit's pass (lv1 still at 0.01795); 5857 after run 50
IFZ = lambda cmds: 'if "$(xcm(lv1,z)) < 0.002" then ' + " ".join(f'"{c}"' for c in cmds) + "\n"   # the floor sphere in contact
FLOOR = lambda k=2000, z="0": f"fix floor all wall/gran granular {HKk(k)} zplane {z} NULL"

# ================================================================ V: run-time state in the pass
S("V01_if_place_pc5", "run 300; if x(lv1) > 0.0181 (true in the engine, mid-contact; false where the atoms do not move) then pc 5000", IFX([PC5s]))
S("V02_if_place_pc5_reverse", "run 300; if x(lv1) < 0.0181 (false in the engine, true in a pass with still atoms) then pc 5000 (engine: 0.413)", IFX([PC5s], "<"))
S("V03_if_step_pc5", "run 300; if step >= 300 then pc 5000 (mid-contact)", 'if "$(step) >= 300" then "' + PC5s + '"\n')
S("V04_if_velocity_pc5", "run 300; if vcm(lv1,x) < 0.7 (the contact has slowed lv1) then pc 5000", 'if "$(vcm(lv1,x)) < 0.7" then "' + PC5s + '"\n')
B("V05_pc_kn_from_place", "run 50; pc 1 2 kn $(2000+1e8*(x(lv1)-0.01795)) (5857 in the engine, 2000 in a still pass); run 3000 (meets in run 2)",
  f"pair_coeff 1 2 hooke {XK} 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
B("V06_pc_kn_from_step", "run 50; pc 1 2 kn $(2000+60*step) (5000 after 50 steps); run 3000", "pair_coeff 1 2 hooke $(2000+60*step) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
B("V07_pc_kn_from_time", "run 50; pc 1 2 kn $(2000+6e7*time) (5000 after 50 us); run 3000", "pair_coeff 1 2 hooke $(2000+6e7*time) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
B("V08_pc_kn_equal_var", "run 50; variable k equal 2000+1e8*(xcm(lv1,x)-0.01795); pc 1 2 kn ${k}; run 3000",
  "variable k equal 2000+1e8*(xcm(lv1,x)-0.01795)\npair_coeff 1 2 hooke ${k} 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
B("V09_pc_kn_from_velocity", "run 50; pc 1 2 kn $(2000+3000*(vcm(lv1,x)>0.5)) (5000 in both: control)", "pair_coeff 1 2 hooke $(2000+3000*(vcm(lv1,x)>0.5)) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
B("V10_pc_kn_from_ke", "run 50; pc 1 2 kn $(2000+3000*(ke>0)) (5000 in both if ke is computed: control)", "pair_coeff 1 2 hooke $(2000+3000*(ke>0)) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
L("V11_loop_until_place", "label lp; run 50; if x(lv1) < 0.0181 then jump SELF lp (6 passes in the engine: 300 steps; endless in a still pass); pc 5000; run 2000",
  "label lp\nrun 50\nif \"$(xcm(lv1,x)) < 0.0181\" then \"jump SELF lp\"\n" + PC5s + "\nrun 2000\n", live="pass 2 (and on)")
L("V12_loop_bounded_exit_on_place", "i loop 20: run 50; exit when x(lv1) > 0.0181 (pass 6 in the engine, mid-contact; 20 passes still); pc 5000; run 2000",
  "variable i loop 20\nlabel lp\nrun 50\nif \"$(xcm(lv1,x)) > 0.0181\" then \"jump SELF out\"\nnext i\njump SELF lp\nlabel out\n" + PC5s + "\nrun 2000\n", live="pass 2 (and on)")
L("V13_halt_then_pc5", "fix halt on x(lv1) > 0.0181 ends run 3000 at ~step 300 (mid-contact); unfix; pc 5000; run 2000",
  "variable hx equal xcm(lv1,x)\nfix ht all halt 10 v_hx > 0.0181 error continue\nrun 3000\nunfix ht\n" + PC5s + "\nrun 2000\n", live="run 1 (and run 2)")
L("V14_every_if_place", "run 2300 every 300 \"if x(lv1) > 0.0181 then pc 5000\" (true after part 1, mid-contact)",
  "run 2300 every 300 \"if '$(xcm(lv1,x)) > 0.0181' then '" + PC5s + "'\"\n", live="part 1")
S("V15_if_place_kick", "run 300; if x(lv1) > 0.0181 then velocity lv2 set 0 0 0 (engine only)", IFX(["velocity lv2 set 0 0 0 units box"]))
S("V16_if_place_set_type", "pc 1 2 kn 5000; run 300; if x(lv1) > 0.0181 then set atom 2 type 1 (engine only)", IFX(["set atom 2 type 1"]), pair=IN(0.1e-3) + PC5)
S("V17_if_place_integrator", "run 300; if x(lv1) > 0.0181 then unfix integ, fix i1 lv1 nve/sphere", IFX(["unfix integ", "fix i1 lv1 nve/sphere"]))
S("V18_if_place_setforce", "run 300; if x(lv1) > 0.0181 then fix sf lv2 setforce 0 0 0", IFX(["fix sf lv2 setforce 0.0 0.0 0.0"]))
S("V19_if_place_timestep", "run 300; if x(lv1) > 0.0181 then timestep 5e-5; run 200", IFX(["timestep 5e-5"]))
S("V20_if_place_include", "run 300; if x(lv1) > 0.0181 then include k.in (pc 5000)", IFX(["include k.in"]), data={"k.in": PC5})
SW("V21_if_floor_moved", "run 300; if z(lv1) < 0.002 (in contact) then floor redefined at zplane 0.0001", IFZ([FLOOR(2000, "0.0001")]))
SW("V22_if_floor_unfixed", "run 300; if z(lv1) < 0.002 then unfix floor (the sphere goes on down)", IFZ(["unfix floor"]))
SW("V23_if_floor_stiffer", "run 300; if z(lv1) < 0.002 then floor kn 5000", IFZ([FLOOR(5000)]))
B("V24_set_density_from_place", "run 50; set atom 2 density $(2500+1e8*(x(lv1)-0.01795)) (6357 in the engine, before the meeting)",
  "set atom 2 density $(2500+1e8*(xcm(lv1,x)-0.01795))\n")
B("V25_timestep_from_place", "run 50; timestep $(1e-6+1e-2*(x(lv1)-0.01795)) (3.9e-5 in the engine: ~15 steps a contact; 1e-6 still)",
  "timestep $(1e-6+1e-2*(xcm(lv1,x)-0.01795))\n")
BW("V26_floor_kn_from_place", "run 50; floor redefined kn $(2000+1e8*(0.0021-z(lv1))) (~6800 in the engine, 2000 still; before touching)",
   "fix floor all wall/gran granular hooke $(2000+1e8*(0.0021-xcm(lv1,z))) 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL\n")
B("V27_if_place_else", "run 50; if x(lv1) > 0.01798 then pc 5000 else pc 3000 (engine 5000, still 3000)",
  'if "$(xcm(lv1,x)) > 0.01798" then "' + PC5s + '" else "' + PCs(3000) + '"\n')
B("V28_pc_kn_count_region", "run 50; region R x > 0.01797; pc kn $(2000+3000*count(all,R)/2)... engine 2 in R, still 1 in R",
  "region R block 0.01797 0.04 0 0.04 0 0.1 units box\npair_coeff 1 2 hooke $(2000+3000*(count(all,R)-1)) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
L("V29_loop_exit_on_contact_kn_each", "i loop 30: pc 1 2 kn $(2000+100*v_i); run 20; exit when x(lv1) > 0.01803 (engine: pass 6; still: 30 passes); run 3000",
  "variable i loop 30\nlabel lp\npair_coeff 1 2 hooke $(2000+100*v_i) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 20\nif \"$(xcm(lv1,x)) > 0.01803\" then \"jump SELF out\"\nnext i\njump SELF lp\nlabel out\nrun 3000\n", live="last run")

# ================================================================ P: pre no
B("P01_pre_no_pc12_cr", "coeff_restitution 0.5 kn 2000; run 50; pc 1 2 coeff_restitution e 0.8 kn 5000; run 3000 pre no", "pair_coeff 1 2 " + CR(5000, 0.8) + "\n",
  pre=RBCR)
DECKS["P01_pre_no_pc12_cr"] = (DECKS["P01_pre_no_pc12_cr"][0].replace("run 3000\n", "run 3000 pre no\n"),) + DECKS["P01_pre_no_pc12_cr"][1:]
PRENO = []


def BN(name, desc, X, **kw):
    B(name, desc + " (run 3000 pre no)", X, **kw)
    t = DECKS[name]
    DECKS[name] = (t[0].replace("run 3000\n", "run 3000 pre no\n"),) + t[1:]


def BWN(name, desc, X, **kw):
    BW(name, desc + " (run 3000 pre no)", X, **kw)
    t = DECKS[name]
    DECKS[name] = (t[0].replace("run 3000\n", "run 3000 pre no\n"),) + t[1:]


def BGN(name, desc, X, **kw):
    BG(name, desc + " (run 3000 pre no)", X, **kw)
    t = DECKS[name]
    DECKS[name] = (t[0].replace("run 3000\n", "run 3000 pre no\n"),) + t[1:]


del DECKS["P01_pre_no_pc12_cr"]
BN("P01_pre_no_pc12_cr", "coeff_restitution e 0.5 kn 2000; run 50; pc 1 2 coeff_restitution e 0.8 kn 5000", "pair_coeff 1 2 " + CR(5000, 0.8) + "\n", pre=RBCR)
BN("P02_pre_no_pc11_cr", "coeff_restitution; run 50; pc 1 1 e 0.8 kn 5000 (the mix 1 2 the last set-up's)", "pair_coeff 1 1 " + CR(5000, 0.8) + "\n", pre=RBCR)
BN("P03_pre_no_pc12_hm", "hertz/material E 1e7 tsuji e 0.5; run 50; pc 1 2 E 1e8 e 0.8", "pair_coeff 1 2 " + HM("1e8", 0.8) + "\n", pre=RBHM)
BN("P04_pre_no_pc11_hm", "hertz/material; run 50; pc 1 1 E 1e8 e 0.8 (mixed 1 2)", "pair_coeff 1 1 " + HM("1e8", 0.8) + "\n", pre=RBHM)
BN("P05_pre_no_pc12_hooke", "hooke; run 50; pc 1 2 kn 5000", PC5)
BN("P06_pre_no_timestep", "run 50; timestep 4e-5", "timestep 4e-5\n")
BN("P07_pre_no_set_density", "run 50; set atom 2 density 5000", "set atom 2 density 5000\n")
BN("P08_pre_no_restyle", "run 50; pair_style granular; pc * * kn 5000", "pair_style granular\npair_coeff * * " + HKk(5000) + "\n")
BN("P09_pre_no_star_star", "pc 1 2 explicit kn 3000 at set-up; run 50; pc * * kn 5000", "pair_coeff * * " + HKk(5000) + "\n", pair=IN(0.1e-3) + PCs(3000) + "\n")
BN("P10_pre_no_damping_change", "run 50; pc 1 2 damping viscoelastic 3000? (mass_velocity -> velocity 0.2)",
   "pair_coeff 1 2 hooke 2000 0.2 damping velocity tangential linear_nohistory 1 0.3\n")
BWN("P11_pre_no_floor_redefined", "run 50; floor redefined kn 5000", FLOOR(5000) + "\n")
BWN("P12_pre_no_gravity_redefined", "run 50; gravity 500 redefined", "fix grav all gravity 500 vector 0 0 -1\n")
BN("P13_pre_no_integrator_lv1", "run 50; unfix integ; fix i1 lv1 nve/sphere", "unfix integ\nfix i1 lv1 nve/sphere\n")
BN("P14_pre_no_set_type", "pc 1 2 kn 5000; run 50; set atom 2 type 1 (1 1 kn 2000)", "set atom 2 type 1\n", pair=IN(0.1e-3) + PC5)
BN("P15_pre_no_pc22_hooke", "run 50; pc 2 2 kn 8000 (mixed 1 2 of hooke: geometric? the last set-up's)", "pair_coeff 2 2 " + HKk(8000) + "\n")
BN("P16_pre_no_exclude", "run 50; neigh_modify exclude type 1 2", "neigh_modify exclude type 1 2\n")
BN("P17_pre_no_viscous_added", "run 50; fix vis lv2 viscous 0.05", "fix vis lv2 viscous 0.05\n")
BN("P18_pre_no_pc12_hm_same_e", "hertz/material; run 50; pc 1 2 E 1e8 e 0.5 (same e)", "pair_coeff 1 2 " + HM("1e8") + "\n", pre=RBHM)
BGN("P19_lig_pre_no_e", "run 50; e 1 2 0.8", LEe(0.8))
BGN("P20_lig_pre_no_young", "run 50; youngsModulus 5e7", "fix m1 all property/global youngsModulus peratomtype 5e7 5e7 5e7\n")
BGN("P21_lig_pre_no_timestep", "run 50; timestep 4e-5", "timestep 4e-5\n")
L("P22_pre_no_mid_contact_pc12", "run 300; pc 1 2 kn 5000; run 2000 pre no (mid-contact)", "run 300\n" + PC5 + "run 2000 pre no\n", live="run 1 (and run 2)")
L("P23_pre_no_mid_contact_pc11_cr", "coeff_restitution: run 300; pc 1 1 e 0.8; run 2000 pre no (mixed unchanged: no change for 1 2)",
  "run 300\npair_coeff 1 1 " + CR(2000, 0.8) + "\nrun 2000 pre no\n", pre=RBCR, live="run 1 (and run 2)")

# ================================================================ M: mid-contact changes not in the lists
S("M01_integ_as_nve_limit", "run 300; fix integ all nve/limit 1e-8 (same ID; 0.01 m/s a step at most)", "fix integ all nve/limit 1e-8\n")
S("M02_integ_as_nve", "run 300; fix integ all nve (same ID; no rotation: head-on, the same)", "fix integ all nve\n")
L("M03_integ_off_100_steps", "run 300; unfix integ; run 100; fix integ all nve/sphere; run 2000 (frozen 100 steps mid-contact)",
  "run 300\nunfix integ\nrun 100\nfix integ all nve/sphere\nrun 2000\n", live="run 1 (and 2, 3)")
S("M04_unfix_setforce_mid", "fix sf lv2 setforce 0 NULL NULL from the start; run 300; unfix sf", "unfix sf\n", pair=IN(0.1e-3) + "fix sf lv2 setforce 0.0 NULL NULL\n")
S("M05_unfix_viscous_mid", "fix vis lv2 viscous 0.05 from the start; run 300; unfix vis", "unfix vis\n", pair=IN(0.1e-3) + "fix vis lv2 viscous 0.05\n")
S("M06_unfix_freeze_mid", "fix fz lv2 freeze from the start; run 300; unfix fz", "unfix fz\n", pair=IN(0.1e-3) + "fix fz lv2 freeze\n")
L("M07_dt_reset_start", "fix dt/reset 1 NULL 1e-4 5e-5 (dt ~6.5e-5 s: ~9 steps a contact)", "fix dtr all dt/reset 1 NULL 1e-4 5e-5 units box\nrun 200\n")
S("M08_dt_reset_mid", "run 300; fix dt/reset 1 NULL 1e-4 5e-5 (coarse dt mid-contact); run 200", "fix dtr all dt/reset 1 NULL 1e-4 5e-5 units box\n")
L("M09_temp_rescale", "fix temp/rescale 1 0 0 1e-30 1.0 on all from the start (velocities scaled to 0)", "fix tr all temp/rescale 1 0.0 0.0 1e-30 1.0\nrun 3000\n")
L("M10_oneway_lv2", "region R (all); fix oneway lv2 x (lv2 may move only to +x: its -x approach reversed)",
  "region R block 0 0.04 0 0.04 0 0.1 units box\nfix ow lv2 oneway 1 R x\nrun 3000\n")
L("M11_adapt_diameter_start", "variable dd equal 0.007; fix adapt 1 atom diameter v_dd on lv2 (7 mm from the set-up, mass too)",
  "variable dd equal 0.007\nfix ad lv2 adapt 1 atom diameter v_dd\nrun 3000\n")
S("M12_adapt_diameter_mid", "run 300; fix adapt 1 atom diameter 0.0062 on lv2 (mid-contact growth)", "variable dd equal 0.0062\nfix ad lv2 adapt 1 atom diameter v_dd\n")
L("M13_adapt_diameter_ramp", "fix adapt 1 atom diameter ramp 6 -> 7 mm over the run on lv2", "variable dd equal ramp(0.006,0.007)\nfix ad lv2 adapt 1 atom diameter v_dd\nrun 3000\n")
L("M14_adapt_diameter_mass_no", "fix adapt 1 atom diameter 0.007 mass no on lv2 (radius only)", "variable dd equal 0.007\nfix ad lv2 adapt 1 atom diameter v_dd mass no\nrun 3000\n")
L("M15_nve_noforce_lv2", "unfix integ; fix i1 lv1 nve/sphere; fix i2 lv2 nve/noforce (lv2 ignores forces)", "unfix integ\nfix i1 lv1 nve/sphere\nfix i2 lv2 nve/noforce\nrun 3000\n")
S("M16_langevin_mid", "run 300; fix langevin 0 0 1e-4 on lv2 (a drag, damp 100 us)", "fix lg lv2 langevin 0.0 0.0 1e-4 12345\n")
L("M17_drag_start", "fix drag lv2 toward a point (delta 0)", "fix dr lv2 drag 0.04 0.02 0.05 0.05 0.0\nrun 3000\n")
L("M18_neighbor_every_1000", "neighbor 0 bin; neigh_modify every 1000 check no (the pair not in the list until step 1000)",
  "neighbor 0.0 bin\nneigh_modify every 1000 delay 0 check no\nrun 3000\n")
S("M19_neighbor_mid", "run 300; neighbor 0 bin; neigh_modify every 1000 check no (mid-contact)", "neighbor 0.0 bin\nneigh_modify every 1000 delay 0 check no\n")
L("M20_neighbor_skin_small_every_50", "neighbor 1e-6 bin; neigh_modify every 50 check no (the pair found at step 50? 100)",
  "neighbor 1e-6 bin\nneigh_modify every 150 delay 0 check no\nrun 3000\n")
S("M21_create_atoms_at_contact", "run 300; create_atoms a 4 mm type 1 sphere touching lv2's far side overlapping 0.1 mm (pushes lv2)",
  "create_atoms 1 single 0.028010 0.02 0.05 units box\nset atom 3 diameter 0.004 density 2500\n")
S("M22_create_atoms_far", "run 300; create_atoms a third sphere far away (control 0.413)", "create_atoms 1 single 0.005 0.02 0.02 units box\nset atom 3 diameter 0.004 density 2500\n")
S("M23_pair_style_zero_mid", "run 300; pair_style zero 0.01 (no contact force mid-contact: the pair passes)", "pair_style zero 0.01\npair_coeff * *\n")
S("M24_pair_style_none_mid", "run 300; pair_style none", "pair_style none\n")
L("M25_labels_pc", "labelmap atom 1 small 2 big; pair_coeff small big kn 5000 (0.579)", "labelmap atom 1 small 2 big\npair_coeff small big " + HKk(5000) + "\nrun 3000\n")
S("M26_labels_set_type_mid", "labelmap; pc 1 2 kn 5000; run 300; set atom 2 type small (mid-contact)", "set atom 2 type small\n",
  pair=IN(0.1e-3) + "labelmap atom 1 small 2 big\npair_coeff small big " + HKk(5000) + "\n")
L("M27_every_700_of_2300", "run 2300 every 700 \"pc 5000\" (M does not divide N; the change at step 700)", "run 2300 every 700 \"" + PC5s + "\"\n", pair=IN(0.35e-3), live="part 1")
L("M28_every_200_of_2300", "run 2300 every 200 \"pc 5000\" (at step 200, mid-contact)", "run 2300 every 200 \"" + PC5s + "\"\n", live="part 1")
L("M29_loop_1step_kn", "i loop 700: pc 1 2 kn 2000+5*i; run 1 (1-step runs through the contact)",
  "variable i loop 700\nlabel lp\npair_coeff 1 2 hooke $(2000+5*v_i) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\nrun 1\nnext i\njump SELF lp\n", live="pass 100")
L("M30_loop_10step_alt", "i loop 80: pc kn 2000 or 5000 alternately; run 10", "variable i loop 80\nlabel lp\nif \"$(v_i%2) == 0\" then \"" + PC5s + "\" else \"" + PCs(2000) +
  "\"\nrun 10\nnext i\njump SELF lp\nrun 2000\n", live="pass 10")
L("M31_dynamic_group_integrator", "group mv dynamic all region R (x < 0.0181) every 1; fix integ on mv (lv1 leaves it mid-contact)",
  "region R block 0 0.0181 0 0.04 0 0.1 units box\ngroup mv dynamic all region R every 1\nunfix integ\nfix integ mv nve/sphere\nrun 3000\n")
L("M32_dynamic_group_setforce", "group sfg dynamic all region R (x > 0.0181) every 1; fix setforce 0 0 0 on it (lv1 enters mid-contact)",
  "region R block 0.0181 0.0205 0 0.04 0 0.1 units box\ngroup sfg dynamic all region R every 1\nfix sf sfg setforce 0.0 0.0 0.0\nrun 3000\n")
S("M33_group_region_after_run", "run 300; group gr region R (x > 0.0181: lv1 in the engine, none still); fix sf gr setforce 0 0 0",
  "region R block 0.0181 0.0205 0 0.04 0 0.1 units box\ngroup gr region R\nfix sf gr setforce 0.0 0.0 0.0\n")
S("M34_set_region_type_after_run", "pc 1 2 kn 5000; run 300; set region R type 2 (x > 0.0181: lv1 in the engine)", "region R block 0.0181 0.0205 0 0.04 0 0.1 units box\nset region R type 2\n",
  pair=IN(0.1e-3) + PC5)
S("M35_pc_changed_back_one_stage", "run 300; pc 5000; pc 2000 (back: no change, control)", PC5 + PCs(2000) + "\n")
S("M36_two_integrators_mid", "run 300; fix i2 lv2 nve/sphere (lv2 integrated twice mid-contact)", "fix i2 lv2 nve/sphere\n")
S("M37_fix_nve_sphere_lv2_replace", "run 300; unfix integ; fix integ lv2 nve/sphere (lv1 stops mid-contact)", "unfix integ\nfix integ lv2 nve/sphere\n")
S("M38_neigh_exclude_then_none", "run 300; neigh_modify exclude type 1 2; neigh_modify exclude none (control 0.413)", "neigh_modify exclude type 1 2\nneigh_modify exclude none\n")
S("M39_delete_third_sphere", "a third sphere resting far off; run 300; delete_atoms group g3 (control 0.413)", "delete_atoms group g3\n",
  pair=IN(0.1e-3) + "create_atoms 1 single 0.005 0.02 0.02 units box\nset atom 3 diameter 0.004 density 2500\ngroup g3 id 3\n")
S("M40_read_data_add_overlap", "run 300; read_data add append of a sphere overlapping lv2's far side", "read_data t.data add append\n",
  data={"t.data": "# one sphere\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.028010 0.02 0.05\n"})
S("M41_fix_addforce_variable_step", "run 300; fix af lv2 addforce v_f 0 0, f = -0.5*(step<400) (100 steps)", "variable f equal -0.5*(step<400)\nfix af lv2 addforce v_f 0.0 0.0\n")
L("M42_viscous_start_region", "fix viscous on a group by region made at the set-up (empty: lv2 enters later): control of the named fix",
  "region R block 0.0231 0.04 0 0.04 0 0.1 units box\ngroup gv region R\nfix vis gv viscous 0.05\nrun 3000\n")
SW("M43_floor_wiggle_redefined", "run 300; floor redefined with wiggle z 1e-4 0.001 (mid-contact)", FLOOR(2000) + " wiggle z 1e-4 0.001\n")
SW("M44_floor_zplane_to_region", "run 300; unfix floor; fix floor2 wall/gran/region on a plane region at z 0 (the same floor)",
   "unfix floor\nregion fl plane 0 0 0 0 0 1 units box\nfix floor2 all wall/gran/region granular " + HK + " region fl\n")
SW("M45_unfix_grav_mid", "run 300; unfix grav (mid-contact; the referee's h term assumes g)", "unfix grav\n")
S("M46_velocity_via_fix_set", "run 300; fix st lv2 setforce? no: fix move lv2 variable NULL.. (fix move variable, vx 0)", "fix mv lv2 move variable NULL NULL NULL v_z v_z v_z\n",
  pair=IN(0.1e-3) + "variable z equal 0.0\n")
S("M47_kspace_style_none", "run 300; comm_modify cutoff 0.01; atom_modify sort 0 0 (no effect, control)", "comm_modify cutoff 0.01\natom_modify sort 0 0.0\n")
S("M48_run_style_respa", "run 300; run_style respa 2 2 (pair at level 2)", "run_style respa 2 2 pair 2\n")
L("M49_respa_start", "run_style respa 2 4 (inner steps)", "run_style respa 2 4\nrun 3000\n")

# ================================================================ LIGGGHTS
SG("G01_lig_if_place_e", "run 300; variable xx equal xcm(lv1,x); if ${xx} > -0.0024 (engine only) then e 0.8",
   "variable xx equal xcm(lv1,x)\nif \"${xx} > -0.0024\" then \"" + LE.format(e="0.8") + "\"\n")
BG("G02_lig_e_from_place", "run 50; variable ee equal 0.5+1e3*(xcm(lv1,x)+0.00255) (0.54 in the engine); e ${ee}",
   "variable ee equal 0.5+1e4*(xcm(lv1,x)+0.00255)\n" + LE.format(e="${ee}") + "\n")
SG("G03_lig_if_place_kick", "run 300; if ${xx} > -0.0024 then velocity lv2 set 0 0 0", "variable xx equal xcm(lv1,x)\nif \"${xx} > -0.0024\" then \"velocity lv2 set 0 0 0\"\n")
SG("G04_lig_integ_nve_limit", "run 300; unfix integr; fix integr all nve/limit absolute 1e-8", "unfix integr\nfix integr all nve/limit absolute 1e-8\n")
SG("G05_lig_unfix_freeze_mid", "freeze lv2 from the start; run 300; unfix fz", "unfix fz\n", pair=LIN(0.1e-3) + "fix fz lv2 freeze\n")
L41MESH = ("fix cad all mesh/surface file floor.stl type 3\nfix walls all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n")
LG("G06_lig_move_mesh_added_mid", "LIGGGHTS WALL: mesh floor; run 300; fix move/mesh linear 0 0 0.3 (mid-contact)",
   L41MESH + "run 300\nfix mm all move/mesh mesh cad linear 0 0 0.3\nrun 2000\n", pre=m9.LB(wall=False), pair=LWALL(1e-4),
   live="run 1 (and run 2)", data={"floor.stl": m9.STLP()}, PAIR="type 1 on wall walls", LWALLZ="1")
LG("G07_lig_move_mesh_before_touch", "LIGGGHTS WALL: mesh floor; run 50; fix move/mesh linear 0 0 0.3 (before touching)",
   L41MESH + "run 50\nfix mm all move/mesh mesh cad linear 0 0 0.3\nrun 3000\n", pre=m9.LB(wall=False), pair=LWALL(1e-4),
   live="run 2", data={"floor.stl": m9.STLP()}, PAIR="type 1 on wall walls", LWALLZ="1")
LG("G08_lig_loop_1step_e", "LIGGGHTS: i loop 400: e 0.5+0.0005*i; run 1", "variable i loop 400\nlabel lp\nvariable ee equal 0.5+0.0005*v_i\n" + LE.format(e="${ee}") +
   "\nrun 1\nnext i\njump SELF lp\n", live="pass 100")
SG("G09_lig_integ_off_mid", "run 300; unfix integr; run 100; fix integr all nve/sphere", "unfix integr\nrun 100\nfix integr all nve/sphere\n")
LG("G10_lig_every_kick", "LIGGGHTS run 2300 every 300 \"set atom 2 type 3\" (e 1 3 0.7 mid-contact)", "run 2300 every 300 \"set atom 2 type 3\"\n", live="part 1")

LG("G11_lig_move_mesh_still_added_mid", "LIGGGHTS WALL: mesh floor; run 300; fix move/mesh linear 0 0 0 (mid-contact; still: control 0.699)",
   L41MESH + "run 300\nfix mm all move/mesh mesh cad linear 0 0 0\nrun 2000\n", pre=m9.LB(wall=False), pair=LWALL(1e-4),
   live="run 1 (and run 2)", data={"floor.stl": m9.STLP()}, PAIR="type 1 on wall walls", LWALLZ="1")
LG("G12_lig_move_mesh_unfixed_mid", "LIGGGHTS WALL: mesh floor moving down at 0.1 m/s from the start; run 300; unfix mm (the mesh stops mid-contact)",
   L41MESH + "fix mm all move/mesh mesh cad linear 0 0 -0.1\nrun 300\nunfix mm\nrun 2000\n", pre=m9.LB(wall=False), pair=LWALL(1e-4),
   live="run 1 (and run 2)", data={"floor.stl": m9.STLP()}, PAIR="type 1 on wall walls", LWALLZ="1")
TD = lambda x: ("# one sphere\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n"
                f"1 1 0.004 2500 {x} 0.02 0.05\n")
S("M50_read_data_add_far", "run 300; read_data add append of a sphere far off (control 0.413)", "read_data t.data add append\n", data={"t.data": TD("0.005")})
L("M51_read_data_add_before_meet_far", "read_data add append of a far sphere before the meeting (control 0.413)", "read_data t.data add append\nrun 3000\n", data={"t.data": TD("0.005")})
S("M52_read_data_add_lv1_side", "run 300; read_data add append of a sphere overlapping lv1's far side by 0.1 mm (pushes lv1 into the contact)",
  "read_data t.data add append\n", data={"t.data": TD("0.013990")})

S("M53_read_data_add_overlap_now", "run 300; read_data add append of a 4 mm sphere overlapping lv2's far side by 0.1 mm at once (center 0.0279)",
  "read_data t.data add append\n", data={"t.data": TD("0.027900")})

RW = lambda vz: (f"variable z equal {vz}\nregion fl plane 0.02 0.02 0 0 0 1 move NULL NULL v_z units box\n"
                 "fix floor all wall/gran/region granular " + HK + " region fl\n")
L("W01_region_floor_moving_up", "WALL: wall/gran/region on a plane region moving up at 0.3 m/s from the start (region move v_z)", RW("0.3*time") + "run 3000\n",
  pre=BASE(wall=False), pair=WALLP(), **WALL)
L("W02_region_floor_starts_mid", "WALL: the plane region starts moving up at 0.3 m/s at step 300 (mid-contact), one run", RW("(step>300)*0.3*(time-3e-4)") + "run 3000\n",
  pre=BASE(wall=False), pair=WALLP(), **WALL)
L("W03_region_floor_move_zero", "WALL: the plane region with move v_z = 0 (control 0.3617)", RW("0.0") + "run 3000\n", pre=BASE(wall=False), pair=WALLP(), **WALL)
L("W04_region_floor_jumps_mid", "WALL: the plane region jumps up 0.1 mm at step 300 (mid-contact), one run", RW("(step>300)*1e-4") + "run 3000\n",
  pre=BASE(wall=False), pair=WALLP(), **WALL)
B("M54_read_data_add_before_meet_overlap", "run 50; read_data add append of a sphere pressed 0.1 mm into lv2's far side (before the meeting)",
  "read_data t.data add append\n", data={"t.data": TD("0.027940")})

LG("G13_lig_move_mesh_wiggle", "LIGGGHTS WALL: mesh floor wiggling in z (amplitude 0.05 mm, period 1 ms) from the start",
   L41MESH + "fix mm all move/mesh mesh cad wiggle amplitude 0 0 5e-5 period 1e-3\nrun 3000\n", pre=m9.LB(wall=False), pair=LWALL(1e-4),
   data={"floor.stl": m9.STLP()}, PAIR="type 1 on wall walls", LWALLZ="1")
S("M55_read_data_add_overlap_lv1", "run 300; read_data add append of a 4 mm sphere overlapping lv1's far side 0.1 mm at once (center 0.01425)",
  "read_data t.data add append\n", data={"t.data": TD("0.014250")})

LG("G14_lig_move_mesh_variable_step", "LIGGGHTS WALL: mesh floor under move/mesh linear/variable with vz = 0.3 from step 300 (mid-contact), one run",
   L41MESH + "variable vz equal (step>300)*0.3\nvariable v0 equal 0\nfix mm all move/mesh mesh cad linear/variable v_v0 v_v0 v_vz\nrun 3000\n", pre=m9.LB(wall=False), pair=LWALL(1e-4),
   data={"floor.stl": m9.STLP()}, PAIR="type 1 on wall walls", LWALLZ="1")
LG("G15_lig_mesh_wall_unfixed_mid", "LIGGGHTS WALL: mesh floor; run 300; unfix walls (mid-contact: the sphere goes on down)",
   L41MESH + "run 300\nunfix walls\nrun 2000\n", pre=m9.LB(wall=False), pair=LWALL(1e-4),
   live="run 1 (and run 2)", data={"floor.stl": m9.STLP()}, PAIR="type 1 on wall walls", LWALLZ="1")

# ================================================================ X: the reader of the executed stream
PF = lambda n: f'fix fp all print {n} "{PC5s}" file k.in screen no title "# written"\n'
L("X01_fix_print_include_mid", "fix print 300 writes k.in (pc 5000) at step 300; run 300; include k.in (the folder's k.in: pc 2000); run 2000",
  PF(300) + "run 300\nunfix fp\ninclude k.in\nrun 2000\n", data={"k.in": PCs(2000) + "\n"}, live="run 1 (and run 2)")
L("X02_fix_print_include_before", "fix print 50 writes k.in (pc 5000); run 50; include k.in (the folder's: pc 2000); run 3000 (the engine: 5000 all contact)",
  PF(50) + "run 50\nunfix fp\ninclude k.in\nrun 3000\n", data={"k.in": PCs(2000) + "\n"}, live="run 2")
L("X03_fix_print_include_nofile", "fix print 50 writes k.in (pc 5000); run 50; include k.in (no k.in in the folder); run 3000",
  PF(50) + "run 50\nunfix fp\ninclude k.in\nrun 3000\n", live="run 2")
L("X04_print_file_state_include", "run 50; print \"pc kn $(2000+1e8*(x-...))\" file k.in; include k.in; run 3000 (5857 in the engine)",
  "run 50\nprint \"pair_coeff 1 2 hooke " + XK + " 3000 damping mass_velocity tangential linear_nohistory 1 0.3\" file k.in\ninclude k.in\nrun 3000\n", live="run 2")
L("X05_log_none_then_pc5", "log none; pc 5000; run 3000", "log none\n" + PC5 + "run 3000\n")
L("X06_echo_none_then_pc5", "echo none; pc 5000; run 3000", "echo none\n" + PC5 + "run 3000\n")
L("X07_log_other_then_pc5", "log other.log; pc 5000; run 3000", "log other.log\n" + PC5 + "run 3000\n")
L("X08_print_command_text", "print \"pair_coeff 1 2 hooke 5000 ...\" (text only; 0.413)", "print \"" + PC5s + "\"\nrun 3000\n")
L("X09_print_run_text", "print \"run 100\" then pc 5000 then run 3000 (0.579)", "print \"run 100\"\n" + PC5 + "run 3000\n")
L("X10_string_var_command", "variable s string \"pair_coeff 1 2 hooke 5000 ...\"; ${s}; run 3000 (0.579)", "variable s string \"" + PC5s + "\"\n${s}\nrun 3000\n")
L("X11_ampersand_continuation", "pair_coeff 1 2 hooke 5000 3000 & (next line) damping ... (0.579)",
  "pair_coeff 1 2 hooke 5000 3000 &\n  damping mass_velocity tangential linear_nohistory 1 0.3\nrun 3000\n")
L("X12_triple_quote_print", "print \"\"\"...pair_coeff 1 2 hooke 5000 ... run 100\"\"\" (a text; 0.413)", 'print """\n' + PC5s + "\nrun 100\n\"\"\"\nrun 3000\n")
L("X13_hash_in_quotes", "pc 5000 via variable with # in a quoted string; print \"# x\" (0.579)", "print \"# not a comment; " + PC5s + "\"\n" + PC5 + "run 3000\n")
L("X14_echo_log_both", "echo both; log none; pc 5000; log log2.txt append; run 3000", "echo both\nlog none\n" + PC5 + "log log2.txt append\nrun 3000\n")
L("X15_thermo_print_mimic", "thermo_style with a print of a pair_coeff line each thermo (0.413)",
  "thermo 100\nrun 3000 every 1000 \"print '" + PC5s.replace("5000", "9000") + "'\"\n")
L("X16_fix_print_mimic", "fix print 100 \"pair_coeff 1 2 hooke 9000 ...\" (screen text only; 0.413)", 'fix fp all print 100 "' + PC5s.replace("5000", "9000") + '"\nrun 3000\n')
L("X17_include_written_by_print_state_mid", "run 300; print \"pc kn $(2000+1e7*(x-...))\" file k.in; include k.in; run 2000 (mid-contact 4310)",
  "run 300\nprint \"pair_coeff 1 2 hooke $(2000+1e7*(xcm(lv1,x)-0.01795)) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\" file k.in\ninclude k.in\nrun 2000\n",
  live="run 1 (and run 2)")

L("X18_write_coeff_include", "pc 5000; write_coeff c.txt; pc 2000; include c.txt (kn 5000 back); run 3000", PC5 + "write_coeff c.txt\n" + PCs(2000) + "\ninclude c.txt\nrun 3000\n")

NP2 = ["G06", "G12", "M40", "M53"]
if __name__ == "__main__":
    names = sys.argv[1:]
    m7.write(names)
    for n in m7.DECKS:
        if not names or any(n.startswith(p) for p in names):
            open(os.path.join(m7.D, n, "NP"), "w").write("1 2\n" if any(n.startswith(p) for p in NP2) else "1\n")

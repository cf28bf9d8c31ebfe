"""Field round 44: write decks/NAME/ (in.deck and the files it reads) for the referee (round 37's live37.py) and the
audit. An adversarial round against main's between-runs rule (what is not on the list of the harmless is named): what
on that list, or among its exceptions, can still change a contact under way. The pair meets at step 100 and a contact
lasts about 580 steps, so `run 300; X; run 2000` makes X mid-contact and `run 50; X; run 3000` before the meeting.
Families:
- K: harmless-listed commands and fix styles with an option that matters (neighbor skin 0 with no rebuilds,
  neigh_modify include, pair_coeff limit_damping or another damping mid-contact, pair_modify with compute not first,
  the integrator or gravity fix defined again on another group, timestep, replicate, set with a two-valued keyword
  before a kicking one);
- V: a variable, compute or region a force fix reads through a path not followed (a group a compute reads, a compute
  reading a variable, an atom-style variable indexed, reset_timestep under a step-based formula, `${}` captured in a
  definition repeated in the same words, include and if between runs, a region in lattice units given again in the
  same words after `lattice`);
- W: within a run: a region wall or setforce region moved by a step-based or swiggle formula, commands of a run's
  every;
- G: LIGGGHTS: characteristicVelocity under hooke, poissonsRatio, a second property/global of the restitution,
  cohesion, rolling friction, fix adapt unfixed, move/mesh by a variable, neighbor skin 0, the integrator regrouped;
- H: harmless controls that must not get the note.
Helpers are rounds 35-43's (make_decks43.py imported; its decks are not written). LAMMPS controls (round 37): kn 2000
0.413435, the floor 0.361743, a plane at x 0.0259 behind lv2 from step 300 0.364747; LIGGGHTS e 0.5 0.499928.
usage: python make_decks44.py [NAME-PREFIX ...]"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field43"))
import make_decks43 as m43  # noqa: E402

m7, m41 = m43.m7, m43.m41
m7.DECKS.clear(); m7.LINKS.clear(); m7.HARD.clear()
m7.D = os.path.join(HERE, "decks")
L, LG, DECKS = m7.L, m7.LG, m7.DECKS
S, B, SW, BW, SG, BG = m41.S, m41.B, m41.SW, m41.BW, m41.SG, m41.BG
PCs, HKk, IN, LIN, HK = m41.PCs, m41.HKk, m41.IN, m41.LIN, m7.HK
BASE, WALLP, WALL, LBASE, LWALL = m41.BASE, m41.WALLP, m41.WALL, m41.LBASE, m41.LWALL
RB, WG, LWK, SWG, stl_z = m43.RB, m43.WG, m43.LWK, m43.SWG, m43.stl_z
P = IN(0.1e-3)
# a plane wall behind lv2 (x < 0.035, far) that moves by v_dx; dx -0.0091 puts it at x 0.0259, lv2's far side 0.08 mm in
PWALL = lambda dx, extra="": (P + extra + f"variable dx equal {dx}\nregion a plane 0.035 0 0 -1 0 0 move v_dx NULL NULL units box\n"
                              "fix w2 all wall/gran/region " + WG + " region a\n")
# the floor a wall/gran/region plane moved by v_dz
RMV = lambda dz, extra="": (BASE(wall=False) + extra + f"variable dz equal {dz}\nregion fl plane 0 0 0 0 0 1 move NULL NULL v_dz units box\n"
                            "fix floor all wall/gran/region " + WG + " region fl\n")
HKL = HK + " limit_damping"

# ================================================================ K: harmless-listed commands with an option that matters
B("K01_skin0_no_rebuild_before", "run 50; neighbor 0.0 bin; neigh_modify every 100000 check no (the pair 0.05 mm apart: never listed, they pass)",
  "neighbor 0.0 bin\nneigh_modify every 100000 delay 0 check no\n")
S("K02_skin0_no_rebuild_mid", "run 300; neighbor 0.0 bin; neigh_modify every 100000 check no (the pair overlaps: listed at setup)",
  "neighbor 0.0 bin\nneigh_modify every 100000 delay 0 check no\n")
B("K03_no_rebuild_before", "run 50; neigh_modify every 100000 check no (skin 1 mm: the pair listed; control)", "neigh_modify every 100000 delay 0 check no\n")
B("K04_neigh_include_empty_before", "run 50; group gx id 5 (empty); atom_modify first gx; neigh_modify include gx (no atom listed: they pass)",
  "group gx id 5\natom_modify first gx\nneigh_modify include gx\n")
S("K05_limit_damping_mid", "run 300; pair_coeff * * the same with limit_damping (the pull at the end clipped)", "pair_coeff * * " + HKL + "\n")
L("K06_limit_damping_control", "pair_coeff * * hooke ... limit_damping from the start (one run: control of K05)", "run 3000\n",
  pre=BASE(wall=False, coeff="pair_coeff * * " + HKL + "\n"))
S("K07_cutoff_keyword_mid", "run 300; pair_coeff * * the same with cutoff 0.01 (a neighbor cutoff only: control)", "pair_coeff * * " + HK + " cutoff 0.01\n")
S("K08_pair_modify_shift_then_compute_no", "run 300; pair_modify shift yes compute no (compute not the first keyword)", "pair_modify shift yes compute no\n")
S("K09_pair_modify_compute_tally_no", "run 300; pair_modify compute/tally no (control)", "pair_modify compute/tally no\n")
S("K10_damping_velocity_mid", "run 300; pair_coeff * * hooke 2000 3000 damping velocity (mass_velocity before)",
  "pair_coeff * * hooke 2000 3000 damping velocity tangential linear_nohistory 1 0.3\n")
S("K11_integrator_regrouped_lv1", "run 300; fix integ lv1 nve/sphere (the integrator defined again on lv1: lv2 stops)", "fix integ lv1 nve/sphere\n")
S("K12_integrator_split_control", "run 300; unfix integ; fix integ lv1 nve/sphere; fix i2 lv2 nve/sphere (both still moved: control)",
  "unfix integ\nfix integ lv1 nve/sphere\nfix i2 lv2 nve/sphere\n")
S("K13_gravity_regrouped_lv2", "run 300; fix grav lv2 gravity 1000 vector -1 0 0 (the gravity fix defined again on lv2 only)", "fix grav lv2 gravity 1000 vector -1 0 0\n")
S("K14_gravity_all_x_redefined", "run 300; fix grav all gravity 1000 vector -1 0 0 (the same on both: control)", "fix grav all gravity 1000 vector -1 0 0\n")
S("K15_timestep_mid", "run 300; timestep 2e-6 (mid-contact)", "timestep 2e-6\n")
S("K16_replicate_2_mid", "run 300; replicate 2 1 1 (a copy of the pair 0.04 further: control)", "replicate 2 1 1\n")
S("K17_comm_vel_no_mid", "run 300; comm_modify vel no (1 process, nothing across a boundary: control)", "comm_modify vel no\n")
L("K18_set_dipole_random_then_density", "atom_style hybrid sphere dipole; run 300; set atom 2 dipole/random 4321 1.0 density 5000 (lv2 heavier mid-contact)",
  "run 300\nset atom 2 dipole/random 4321 1.0 density 5000\nrun 2000\n", pre=RB.replace("atom_style sphere 1", "atom_style hybrid sphere dipole"),
  pair=P, live="run 1 (and run 2)")
L("K19_set_density_hybrid_control", "atom_style hybrid sphere dipole; run 300; set atom 2 density 5000 (named as a kick: the reach of K18)",
  "run 300\nset atom 2 density 5000\nrun 2000\n", pre=RB.replace("atom_style sphere 1", "atom_style hybrid sphere dipole"), pair=P, live="run 1 (and run 2)")
S("K20_pair_style_granular_again_limit", "run 300; pair_style granular; pair_coeff * * with limit_damping", "pair_style granular\npair_coeff * * " + HKL + "\n")
S("K21_neigh_include_empty_mid", "run 300; group gx id 5 (empty); atom_modify first gx; neigh_modify include gx", "group gx id 5\natom_modify first gx\nneigh_modify include gx\n")
B("K22_skin0_every_rebuild_before", "run 50; neighbor 0.0 bin (rebuilt every step: the pair met; control)", "neighbor 0.0 bin\nneigh_modify every 1 delay 0 check yes\n")

# ================================================================ V: paths a force fix reads, not followed
S("V01_group_read_by_compute", "wall plane a move v_dx, dx = -0.0091*(c_cc>0), cc = reduce sum mass of group gg (empty); run 300; group gg id 1",
  "group gg id 1\n", pair=PWALL("-0.0091*(c_cc>0)", "compute pm all property/atom mass\ngroup gg id 5\ncompute cc gg reduce sum c_pm\n"))
S("V02_compute_reads_variable", "dx = -0.0091*c_cr, cr = reduce max v_va, va atom v_k, k 0; run 300; variable k equal 1",
  "variable k equal 1.0\n", pair=PWALL("-0.0091*c_cr", "variable k equal 0.0\nvariable va atom v_k\ncompute cr all reduce max v_va\n"))
S("V03_atom_variable_indexed", "dx = -0.0091*v_va[1], va atom v_k, k 0; run 300; variable k equal 1",
  "variable k equal 1.0\n", pre=BASE(wall=False, head="atom_modify map array\n"),
  pair=PWALL("-0.0091*v_va[1]", "variable k equal 0.0\nvariable va atom v_k\n"))
S("V04_reset_timestep_step_formula", "dx = -0.0091*(step>=100000); run 300; reset_timestep 100000 (the wall jumps to lv2 mid-contact)",
  "reset_timestep 100000\n", pair=PWALL("-0.0091*(step>=100000)"))
SW("V05_floor_reset_timestep_step_formula", "floor region fl move v_dz, dz = 2e-4*(step>=100000); run 300; reset_timestep 100000 (floor up 0.2 mm)",
   "reset_timestep 100000\n", pre=RMV("2e-4*(step>=100000)"))
S("V06_captured_same_words", "variable d equal 0; variable dx equal ${d}; run 300; variable d equal -0.0091; variable dx equal ${d} (the same words, -0.0091)",
  "variable d equal -0.0091\nvariable dx equal ${d}\n", pair=P + "variable d equal 0.0\nvariable dx equal ${d}\n"
  "region a plane 0.035 0 0 -1 0 0 move v_dx NULL NULL units box\nfix w2 all wall/gran/region " + WG + " region a\n")
S("V07_include_region_moved", "wall on plane a (x < 0.035); run 300; include ch.in (region a delete; a at x 0.0259)", "include ch.in\n",
  pair=P + "region a plane 0.035 0 0 -1 0 0 units box\nfix w2 all wall/gran/region " + WG + " region a\n",
  data={"ch.in": "region a delete\nregion a plane 0.0259 0 0 -1 0 0 units box\n"})
S("V08_if_new_wall", "run 300; if \"1 > 0\" then \"fix w2 all wall/gran ... zplane 0.0475 NULL\" (lv2 0.5 mm into it)",
  'if "1 > 0" then "fix w2 all wall/gran ' + WG + ' zplane 0.0475 NULL"\n')
S("V09_lattice_region_same_words", "lattice sc 0.01; plane a at 3.5 lattice (x 0.035); run 300; lattice sc 0.0074; region a delete; the same words (x 0.0259)",
  "lattice sc 0.0074\nregion a delete\nregion a plane 3.5 0 0 -1 0 0\n",
  pair=P + "lattice sc 0.01\nregion a plane 3.5 0 0 -1 0 0\nfix w2 all wall/gran/region " + WG + " region a\n")
S("V10_lattice_setforce_region_same_words", "lattice sc 0.01; setforce region R block 3.5 4 0 4 0 10 (far); run 300; lattice sc 0.00615; R again in the same words (over lv2)",
  "lattice sc 0.00615\nregion R delete\nregion R block 3.5 4.0 0 4 0 10\n",
  pair=P + "lattice sc 0.01\nregion R block 3.5 4.0 0 4 0 10\nfix sf all setforce 0.0 0.0 0.0 region R\n")
S("V11_lattice_only_control", "lattice sc 0.01; plane a at 3.5 lattice (far); run 300; lattice sc 0.0074 (the region stays: control)", "lattice sc 0.0074\n",
  pair=P + "lattice sc 0.01\nregion a plane 3.5 0 0 -1 0 0\nfix w2 all wall/gran/region " + WG + " region a\n")
S("V12_captured_d_only_control", "dx = ${d} captured (0); run 300; variable d equal -0.0091 (dx stays 0: control)", "variable d equal -0.0091\n",
  pair=P + "variable d equal 0.0\nvariable dx equal ${d}\nregion a plane 0.035 0 0 -1 0 0 move v_dx NULL NULL units box\n"
  "fix w2 all wall/gran/region " + WG + " region a\n")
S("V13_group_read_by_compute_control", "dx = -0.0091*(c_cc>0) over empty gg; run 300; group gq id 1 (another group: control)", "group gq id 1\n",
  pair=PWALL("-0.0091*(c_cc>0)", "compute pm all property/atom mass\ngroup gg id 5\ncompute cc gg reduce sum c_pm\n"))
S("V14_variable_string_read", "dx equal v_s, s string 0.0; run 300; variable s string -0.0091", "variable s string -0.0091\n",
  pair=P + "variable s string 0.0\nvariable dx equal v_s\nregion a plane 0.035 0 0 -1 0 0 move v_dx NULL NULL units box\n"
  "fix w2 all wall/gran/region " + WG + " region a\n")
S("V15_setforce_var_group_compute", "addforce lv2 v_f, f = -0.5*(c_cc>0), gg empty; run 300; group gg id 1",
  "group gg id 1\n", pair=P + "compute pm all property/atom mass\ngroup gg id 5\ncompute cc gg reduce sum c_pm\nvariable f equal -0.5*(c_cc>0)\n"
  "fix af lv2 addforce v_f 0.0 0.0\n")

# ================================================================ W: within a run
L("W01_wall_step_formula_one_run", "plane a move v_dx, dx = -0.0091*(step>=400); one run 3000 (the wall at lv2 from step 400, mid-contact)", "run 3000\n",
  pair=PWALL("-0.0091*(step>=400)"))
L("W02_floor_step_formula_one_run", "WALL: floor region fl move v_dz, dz = 2e-4*(step>=300); one run 3000", "run 3000\n",
  pre=RMV("2e-4*(step>=300)"), pair=WALLP(), **WALL)
L("W03_floor_swiggle_one_run", "WALL: floor region fl move v_dz, dz = swiggle(0,1e-4,0.0008); one run 3000", "run 3000\n",
  pre=RMV("swiggle(0.0,1e-4,0.0008)"), pair=WALLP(), **WALL)
L("W04_setforce_region_step_one_run", "setforce region R, R move v_dx, dx = -0.0135*(step>=300) (R over lv2 mid-contact); one run", "run 3000\n",
  pair=P + "variable dx equal -0.0135*(step>=300)\nregion R block 0.035 0.04 0 0.04 0 0.1 move v_dx NULL NULL units box\n"
  "fix sf all setforce 0.0 0.0 0.0 region R\n")
L("W05_every_new_wall", "run 2300 every 300 \"fix w2 all wall/gran ... zplane 0.0475 NULL\" (defined at step 300, mid-contact)",
  'run 2300 every 300 "fix w2 all wall/gran ' + WG + ' zplane 0.0475 NULL"\n', live="run 1")
L("W06_every_variable", "plane a move v_dx (dx 0); run 2300 every 300 \"variable dx equal -0.0091\"",
  'run 2300 every 300 "variable dx equal -0.0091"\n', pair=PWALL("0.0"), live="run 1")
L("W07_every_set_density", "run 2300 every 300 \"set atom 2 density 5000\"", 'run 2300 every 300 "set atom 2 density 5000"\n', live="run 1")
L("W08_every_compute_no", "run 2300 every 300 \"pair_modify compute no\"", 'run 2300 every 300 "pair_modify compute no"\n', live="run 1")
L("W09_every_exclude", "run 2300 every 300 \"neigh_modify exclude type 1 2\"", 'run 2300 every 300 "neigh_modify exclude type 1 2"\n', live="run 1")
L("W10_every_print_control", "run 2300 every 300 \"print tick\" (control)", 'run 2300 every 300 "print tick"\n', live="run 1")
L("W11_elapsed_formula", "plane a move v_dx, dx = -0.0091*(elapsed>=300); run 300; run 2000 (in the second run from its step 300: step 600, mid-contact)",
  "run 300\nrun 2000\n", pair=PWALL("-0.0091*(elapsed>=300)"), live="run 1 (and run 2)")
L("W12_every_timestep", "run 2300 every 300 \"timestep 2e-6\"", 'run 2300 every 300 "timestep 2e-6"\n', live="run 1")

# ================================================================ G: LIGGGHTS
LHK = LBASE(model="hooke", extra="fix cv all property/global characteristicVelocity scalar 1.0\n")
SG("G01_lig_charvel_hooke_mid", "hooke, characteristicVelocity 1; run 300; characteristicVelocity 3 (kn up mid-contact)",
   "fix cv all property/global characteristicVelocity scalar 3.0\n", pre=LHK)
LG("G02_lig_hooke_charvel_control", "LIGGGHTS: hooke, characteristicVelocity 1 (one run: control of G01)", "run 3000\n", pre=LHK)
SG("G03_lig_poisson_mid", "run 300; poissonsRatio 0.45 for all types (stiffer mid-contact)", "fix m2 all property/global poissonsRatio peratomtype 0.45 0.45 0.45\n")
SG("G04_lig_e_new_id_mid", "run 300; a second property/global of coefficientRestitution (m3b) with 1 2 0.8",
   "fix m3b all property/global coefficientRestitution peratomtypepair 3 0.6 0.8 0.7 0.8 0.4 0.45 0.7 0.45 0.8\n")
LCO = LBASE(extra="fix ced all property/global cohesionEnergyDensity peratomtypepair 3 0 0 0 0 0 0 0 0 0\n").replace(
    "pair_style gran model hertz tangential history", "pair_style gran model hertz tangential history cohesion sjkr")
LG("G05_lig_cohesion_zero_control", "LIGGGHTS: hertz with cohesion sjkr, cohesionEnergyDensity 0 (control)", "run 3000\n", pre=LCO)
SG("G06_lig_cohesion_mid", "hertz cohesion sjkr, CED 0; run 300; CED 1e5 for all pairs",
   "fix ced all property/global cohesionEnergyDensity peratomtypepair 3 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5\n", pre=LCO)
LRF = LBASE(extra="fix crf all property/global coefficientRollingFriction peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1\n").replace(
    "pair_style gran model hertz tangential history", "pair_style gran model hertz tangential history rolling_friction cdt")
SG("G07_lig_rolling_friction_mid", "rolling_friction cdt 0.1; run 300; 0.5 (head-on: no rolling; control)",
   "fix crf all property/global coefficientRollingFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n", pre=LRF)
LG("G08_lig_adapt_unfix_mid", "LIGGGHTS: variable d 0.0062; fix ad lv2 adapt 1 atom diameter v_d; run 300; unfix ad (reset by default?)",
   "run 300\nunfix ad\nrun 2000\n", pair=LIN(0.1e-3) + "variable d equal 0.0062\nfix ad lv2 adapt 1 atom diameter v_d\n", live="run 1 (and run 2)")
LMM = (LBASE(wall=False) + "fix cad all mesh/surface file wz.stl type 3\n"
       "fix wprim all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"
       "variable vz equal 0.0\nfix mm all move/mesh mesh cad linear/variable v_vz v_vz v_vz\n")
LG("G09_lig_move_mesh_variable_mid", "LIGGGHTS WALL: mesh floor moved by linear/variable v_vz (0); run 300; variable vz equal 0.5",
   "run 300\nvariable vz equal 0.5\nrun 2000\n", pre=LMM, pair=LWALL(1e-4), data={"wz.stl": stl_z(0.0)}, live="run 1 (and run 2)", **LWK)
LG("G10_lig_move_mesh_step_one_run", "LIGGGHTS WALL: mesh floor linear/variable, vz = 0.5*(step>=300)*(step<700); one run", "run 3000\n",
   pre=LMM.replace("variable vz equal 0.0", "variable vz equal 0.5*(step>=300)*(step<700)"), pair=LWALL(1e-4), data={"wz.stl": stl_z(0.0)}, **LWK)
BG("G11_lig_skin_tiny_no_rebuild_before", "run 50; neighbor 1e-6 bin; neigh_modify every 100000 check no (the pair 0.05 mm apart: never listed)",
   "neighbor 1e-6 bin\nneigh_modify every 100000 delay 0 check no\n")
SG("G12_lig_integrator_regrouped", "run 300; fix integr lv1 nve/sphere (lv2 stops)", "fix integr lv1 nve/sphere\n")
SG("G13_lig_timestep_mid", "run 300; timestep 2e-6", "timestep 2e-6\n")
SG("G14_lig_gravity_regrouped", "run 300; fix gravi lv2 gravity 1000 vector -1 0 0", "fix gravi lv2 gravity 1000 vector -1.0 0.0 0.0\n")
SG("G15_lig_young_all_mid", "run 300; youngsModulus 5e7 for every type", "fix m1 all property/global youngsModulus peratomtype 5e7 5e7 5e7\n")
SG("G16_lig_restitution_scalar_style", "run 300; coefficientRestitution peratomtypepair the same values in another spelling (0.50)",
   "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.60 0.50 0.70 0.50 0.40 0.45 0.70 0.45 0.80\n")
SG("G17_lig_set_property_atom_then_density", "fix property/atom pa; run 300; set atom 2 property/atom pa 1.0 density 5000",
   "set atom 2 property/atom pa 1.0 density 5000\n", pre=LBASE(extra="fix pa all property/atom pa scalar yes no no 0.0\n"))

# ================================================================ H: harmless between runs (controls)
HX = [
    ("atom_modify_sort", "atom_modify sort 0 0.0\n"),
    ("comm_cutoff", "comm_modify cutoff 0.02\n"),
    ("neigh_one_page", "neigh_modify one 3000 page 300000\n"),
    ("run_style_verlet", "run_style verlet\n"),
    ("reset_timestep", "reset_timestep 1000\n"),
    ("fix_property_atom", "fix pa all property/atom d_foo\n"),
    ("fix_vector", "fix vv all vector 10 c_thermo_temp\n"),
    ("fix_balance", "fix bal all balance 100 1.0 shift x 5 1.0\n"),
    ("compute_unused", "compute cr all reduce sum vx\n"),
    ("variable_captured_unused", "variable a equal 1.0\nvariable q equal ${a}\n"),
    ("gravity_identical", "fix grav all gravity 9.81 vector 0 0 -1\n"),
    ("integrator_identical", "fix integ all nve/sphere\n"),
    ("lattice_unused", "lattice sc 0.01\n"),
    ("group_type_unused", "group gq type 1\n"),
    ("replicate_111", "replicate 1 1 1\n"),
    ("thermo_modify_norm", "thermo_modify norm no\n"),
    ("neigh_every2", "neigh_modify every 2 delay 0 check yes\n"),
    ("fix_halt_never", "variable hh equal 0\nfix hl all halt 100 v_hh > 1 error continue\n"),
]
for i, (n, x) in enumerate(HX, 1):
    S(f"H{i:02d}_{n}_mid", f"run 300; {x.strip().splitlines()[-1]} (harmless: control)", x)
SW("H19_wall_atom_modify_sort_mid", "run 300; atom_modify sort 0 0.0 (control)", "atom_modify sort 0 0.0\n")
SW("H20_wall_reset_timestep_mid", "run 300; reset_timestep 0 (control)", "reset_timestep 0\n")
SW("H21_wall_region_move_step_far", "floor region fl move v_dz with dz = 2e-4*(step>=100000); run 300; reset_timestep 500 (still 0: control)",
   "reset_timestep 500\n", pre=RMV("2e-4*(step>=100000)"))
SG("H22_lig_check_timestep", "run 300; fix ts all check/timestep/gran 1000 0.1 0.1 (control)", "fix ts all check/timestep/gran 1000 0.1 0.1\n")
SG("H23_lig_charvel_hertz_unused", "run 300; characteristicVelocity 2 under hertz (unused: control)", "fix cv all property/global characteristicVelocity scalar 2.0\n")
SG("H24_lig_neigh_delay_again", "run 300; neigh_modify delay 0 (again: control)", "neigh_modify delay 0\n")
S("H25_group_of_unused_compute", "compute cc gg reduce sum vx (read by nothing); run 300; group gg id 1 (control)", "group gg id 1\n",
  pair=P + "group gg id 5\ncompute cc gg reduce sum vx\n")
S("H26_variable_chain_unread", "dx (read by the wall) = 0; k unread; run 300; variable k equal 1 (control)", "variable k equal 1.0\n",
  pair=PWALL("0.0", "variable k equal 0.0\n"))

S("V17_compute_reads_region", "dx = -0.0091*(c_cr>0), cr = reduce/region R sum of mass, R empty far; run 300; region R delete; R around lv1",
  "region R delete\nregion R block 0.015 0.021 0 0.04 0 0.1 units box\n",
  pair=PWALL("-0.0091*(c_cr>0)", "compute pm all property/atom mass\nregion R block 0.036 0.04 0 0.04 0 0.1 units box\n"
             "compute cr all reduce/region R sum c_pm\n"))
S("V18_group_function_in_formula", "dx = -0.0091*(count(gg)>0), gg empty; run 300; group gg id 1", "group gg id 1\n",
  pair=PWALL("-0.0091*(count(gg)>0)", "group gg id 5\n"))
S("V19_region_function_in_formula", "dx = -0.0091*(count(all,R)>0), R empty far; run 300; region R delete; R around lv1",
  "region R delete\nregion R block 0.015 0.021 0 0.04 0 0.1 units box\n",
  pair=PWALL("-0.0091*(count(all,R)>0)", "region R block 0.036 0.04 0 0.04 0 0.1 units box\n"))
L("W13_every_if_new_wall", "run 2300 every 300 \"if '1 > 0' then 'fix w2 all wall/gran ... zplane 0.0475 NULL'\"",
  'run 2300 every 300 "if \'1 > 0\' then \'fix w2 all wall/gran ' + WG + ' zplane 0.0475 NULL\'"\n', live="run 1")
S("H27_exclude_none_unset", "run 300; neigh_modify exclude none (no exclusion set: control)", "neigh_modify exclude none\n")
S("H28_include_print", "run 300; include pr.in (a print: control)", "include pr.in\n", data={"pr.in": "print hello\n"})
S("H29_timestep_same_by_variable", "variable dtv equal 1e-6; run 300; timestep ${dtv} (the same: control)", "timestep ${dtv}\n",
  pair=P + "variable dtv equal 1e-6\n")

S("V20_is_defined_fix_in_formula", "dx = -0.0091*is_defined(fix,mark); run 300; fix mark all vector 10 c_thermo_temp (a harmless style)",
  "fix mark all vector 10 c_thermo_temp\n", pair=PWALL("-0.0091*is_defined(fix,mark)"))
S("V21_is_defined_variable_in_formula", "dx = -0.0091*is_defined(variable,flag); run 300; variable flag equal 1 (read by no name)",
  "variable flag equal 1\n", pair=PWALL("-0.0091*is_defined(variable,flag)"))
FLW = lambda opt: BASE(wall=False) + "fix floor all wall/gran " + WG + " zplane 0 NULL " + opt + "\n"
L("X01_floor_wiggle", "WALL: the floor wall/gran zplane 0 with wiggle z 1e-4 0.0008 (one run)", "run 3000\n", pre=FLW("wiggle z 1e-4 0.0008"), pair=WALLP(), **WALL)
L("X02_floor_shear_control", "WALL: the floor wall/gran zplane 0 with shear x 0.5 (tangential only: control)", "run 3000\n", pre=FLW("shear x 0.5"), pair=WALLP(), **WALL)
LG("G18_lig_mesh_wiggle", "LIGGGHTS WALL: mesh floor with fix move/mesh wiggle amplitude 0 0 1e-4 period 0.0008 (one run)", "run 3000\n",
   pre=LMM.replace("variable vz equal 0.0\nfix mm all move/mesh mesh cad linear/variable v_vz v_vz v_vz",
                   "fix mm all move/mesh mesh cad wiggle amplitude 0 0 1e-4 period 0.0008"), pair=LWALL(1e-4), data={"wz.stl": stl_z(0.0)}, **LWK)
S("H30_atom_modify_first_all", "run 300; atom_modify first all (control)", "atom_modify first all\n")

# ================================================================ after the audit: the reach of K18
L("K23_set_dipole_random_then_vx", "atom_style hybrid sphere dipole; run 300; set atom 2 dipole/random 4321 1.0 vx 0.5 (lv2 thrown away mid-contact)",
  "run 300\nset atom 2 dipole/random 4321 1.0 vx 0.5\nrun 2000\n", pre=RB.replace("atom_style sphere 1", "atom_style hybrid sphere dipole"),
  pair=P, live="run 1 (and run 2)")
L("K24_set_dipole_random_then_type", "atom_style hybrid sphere dipole; pair_coeff 1 1 kn 5000; run 300; set atom 2 dipole/random 4321 1.0 type 1",
  "run 300\nset atom 2 dipole/random 4321 1.0 type 1\nrun 2000\n", pre=RB.replace("atom_style sphere 1", "atom_style hybrid sphere dipole"),
  pair=P + "pair_coeff 1 1 " + HKk(5000) + "\n", live="run 1 (and run 2)")

# ================================================================ after the audit: the reach of V09
SW("V22_lattice_floor_region_same_words", "floor region fl plane 0 0 1 (lattice sc 1e-9: z ~0); run 300; lattice sc 0.0002; fl deleted and given again in the same words (z 0.0002)",
   "lattice sc 0.0002\nregion fl delete\nregion fl plane 0 0 1 0 0 1\n",
   pre=BASE(wall=False) + "lattice sc 1e-9\nregion fl plane 0 0 1 0 0 1\nfix floor all wall/gran/region " + WG + " region fl\n")
B("V23_lattice_region_same_words_before", "as V09 before the meeting: run 50; lattice sc 0.0074; region a again in the same words (x 0.0259)",
  "lattice sc 0.0074\nregion a delete\nregion a plane 3.5 0 0 -1 0 0\n",
  pair=P + "lattice sc 0.01\nregion a plane 3.5 0 0 -1 0 0\nfix w2 all wall/gran/region " + WG + " region a\n")

if __name__ == "__main__":
    names = sys.argv[1:]
    m7.big = lambda *a, **k: None
    m7.lmp_gen = lambda *a, **k: None
    m7.write(names)
    for n in m7.DECKS:
        if not names or any(n.startswith(p) for p in names):
            open(os.path.join(m7.D, n, "NP"), "w").write("1\n")

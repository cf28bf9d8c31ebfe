"""Field round 40: write decks/NAME/ (in.deck and the files it reads) for the referee (round 37's live37.py) and the
audit. An adversarial round on main ccd545e7, against the notes added there (a law changed while a contact is under
way, atoms kicked between runs, fix wall/region):
- A: changes while a contact is under way (the pair meets at step 100, a contact lasts 586 steps; the deck's first
  run is 300 steps): laws with the same eps but another stiffness, the same law restored, run upto/start/stop,
  minimize, pair_style given again, fix wall/gran redefined, unfix of a wall, exclusions, change_box, fix move,
  setforce, timestep, reset_timestep, kicks through variables, if, include, loops, a run's every, set by group,
  region and type, set type, LIGGGHTS equivalents; several pairs changing in one stage;
- B: pushing fixes: fix wall/region styles, wall/lj93/lj126/colloid/morse/reflect, spring, efield with charges,
  rigid, momentum, recenter, deform, 2d discs, a moving LIGGGHTS mesh;
- C: units (lj cgs micro nano metal real), sphere 0/1, set order, read_data, create_atoms random, lattice, pour;
- D: clear, read_restart with changed settings, loops and nested includes with runs, run 0, pre/post no, short runs.
Helpers are rounds 35-39's (make_decks39.py imported; its decks are not written). LAMMPS controls (round 37): kn 2000
0.413435, 5000 0.578975; the floor 0.361743; LIGGGHTS e 0.5 0.499928, the wall e 0.7 0.699141.
usage: python make_decks40.py [NAME-PREFIX ...]"""
import math
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
V1, V2 = m.V1, m.V2
LW = dict(PAIR="type 1 on wall wprim")
STLP = m9.STLP
DECKS = m7.DECKS


def RAW(name, desc, text, live="last run", data=None, **meta):
    DECKS[name] = ("# " + desc + "\n" + text, live, data or {}, meta)


# a change X between `run 300` (the pair meets at step 100) and `run 2000`: the contact spans both runs
S = lambda name, desc, X, **kw: L(name, desc, "run 300\n" + X + "run 2000\n", live="run 1 (and run 2)", **kw)
SW = lambda name, desc, X, pre=None, **kw: L(name, "WALL: " + desc, "run 300\n" + X + "run 2000\n", pre=pre or BASE(), pair=WALLP(),
                                             live="run 1 (and run 2)", **WALL, **kw)
SG = lambda name, desc, X, **kw: LG(name, "LIGGGHTS: " + desc, "run 300\n" + X + "run 2000\n", live="run 1 (and run 2)", **kw)
CR = lambda k, e=0.5: f"hooke {k} {e} damping coeff_restitution tangential linear_nohistory 1 0.3"
RBCR = BASE(wall=False, coeff="pair_coeff * * " + CR(2000) + "\n")
HM = lambda E, e=0.5: f"hertz/material {E} {e} 0.3 damping tsuji tangential linear_nohistory 1 0.3"
RBHM = BASE(wall=False, coeff="pair_coeff * * " + HM("1e7") + "\n")
VX2 = f"{V2:.10f}"

# ================================================================ A: changes while a contact is under way
S("A01_same_eps_stiffer_cr", "hooke 2000 e 0.5 damping coeff_restitution; mid-contact pc hooke 5000 e 0.5 (each law's eps 0.5; the contact mixes two springs)",
  "pair_coeff 1 2 " + CR(5000) + "\n", pre=RBCR)
S("A02_same_eps_softer_cr", "coeff_restitution 0.5, kn 5000 then mid-contact kn 2000 (same eps)", "pair_coeff 1 2 " + CR(2000) + "\n",
  pre=BASE(wall=False, coeff="pair_coeff * * " + CR(5000) + "\n"))
S("A03_same_eps_hertz_material_E", "hertz/material E 1e7 e 0.5 tsuji; mid-contact E 1e8 (same eps)", "pair_coeff 1 2 " + HM("1e8") + "\n", pre=RBHM)
S("A04_restored_law", "run 300; pc 5000; pc 2000 (the law restored: no change; 0.413)", PC5 + PCs(2000) + "\n")
L("A05_law_for_100_steps_restored", "run 300; pc 5000; run 100; pc 2000; run 2000 (kn 5000 for 100 steps mid-contact)",
  "run 300\n" + PC5 + "run 100\n" + PCs(2000) + "\nrun 2000\n", live="run 1 (and 2, 3)")
L("A06_law_for_1_step", "run 300; pc 50000; run 1; pc 2000; run 2000 (kn 50000 for one step mid-contact)",
  "run 300\n" + PCs(50000) + "\nrun 1\n" + PCs(2000) + "\nrun 2000\n", live="run 1 (and 2, 3)")
L("A07_upto", "run 300 upto; pc 5000; run 2300 upto", "run 300 upto\n" + PC5 + "run 2300 upto\n", live="run 1 (and run 2)")
L("A08_start_stop", "run 300 start 0 stop 2300; pc 5000; run 2000 start 0 stop 2300", "run 300 start 0 stop 2300\n" + PC5 + "run 2000 start 0 stop 2300\n", live="run 1 (and run 2)")
S("A09_minimize_between", "run 300; minimize 0 0 10 10 (moves the overlapping pair); run 2000", "min_style cg\nminimize 0.0 0.0 10 10\n")
S("A10_restyle_new_coeff", "run 300; pair_style granular (given again); pair_coeff * * kn 5000; run 2000", "pair_style granular\npair_coeff * * " + HKk(5000) + "\n")
S("A11_restyle_same_coeff_cr", "coeff_restitution 0.5: run 300; pair_style granular again; pair_coeff * * hooke 5000 e 0.5 (same eps)",
  "pair_style granular\npair_coeff * * " + CR(5000) + "\n", pre=RBCR)
S("A12_pair_modify", "run 300; pair_modify shift yes (no effect on a granular law: 0.413)", "pair_modify shift yes\n")
SW("A13_wall_redefined_stiffer", "run 300; fix floor redefined (same ID) kn 5000; run 2000", "fix floor all wall/gran granular " + HKk(5000) + " zplane 0 NULL\n")
SW("A14_wall_redefined_same_eps_cr", "floor coeff_restitution 0.5 kn 2000; fix floor redefined kn 5000 e 0.5 (same eps)",
   "fix floor all wall/gran granular " + CR(5000) + " zplane 0 NULL\n",
   pre=BASE(wall=False) + "fix floor all wall/gran granular " + CR(2000) + " zplane 0 NULL\n")
SW("A15_unfix_wall_mid", "run 300; unfix floor (mid-contact); run 2000 (the sphere goes on down)", "unfix floor\n")
S("A16_exclude_mid", "run 300; neigh_modify exclude type 1 2 (mid-contact); run 2000 (the pair passes through)", "neigh_modify exclude type 1 2\n")
S("A17_change_box_remap", "run 300; change_box all x scale 1.02 remap (the pair 0.1 mm further apart); run 2000", "change_box all x scale 1.02 remap units box\n")
S("A18_change_box_no_remap", "run 300; change_box all x final 0 0.05 units box (no remap: atoms stay); run 2000 (0.413)", "change_box all x final 0 0.05 units box\n")
S("A19_fix_move_lv2", "run 300; fix mv lv2 move linear 0 0 0 (lv2 held still mid-contact); run 2000", "fix mv lv2 move linear 0 0 0 units box\n")
S("A20_setforce_lv2", "run 300; fix sf lv2 setforce 0 0 0; run 2000", "fix sf lv2 setforce 0.0 0.0 0.0\n")
S("A21_timestep_coarse", "run 300; timestep 5e-5 (a contact of 12 steps); run 200", "timestep 5e-5\n")
S("A22_reset_timestep", "run 300; reset_timestep 0; run 2000 (0.413)", "reset_timestep 0\n")
S("A23_velocity_via_variable", "run 300; variable vv equal -0.5; velocity lv2 set v_vv 0 0 units box; run 2000", "variable vv equal -0.5\nvelocity lv2 set v_vv 0 0 units box\n")
S("A24_velocity_in_if", "run 300; if \"1 > 0\" then \"velocity lv2 set 0 0 0 units box\"; run 2000", 'if "1 > 0" then "velocity lv2 set 0 0 0 units box"\n')
S("A25_velocity_in_include", "run 300; include kick.in (velocity lv2 set 0 0 0); run 2000", "include kick.in\n", data={"kick.in": "velocity lv2 set 0 0 0 units box\n"})
S("A26_velocity_nested_include", "run 300; include a.in (includes b.in: set atom 2 vx 0); run 2000", "include a.in\n",
  data={"a.in": "include b.in\n", "b.in": "set atom 2 vx 0.0\n"})
L("A27_loop_with_kick", "a loop of 3 runs of 150 steps, velocity lv2 set 0 0 0 after each (during the contact); run 2000",
  "variable i loop 3\nlabel lp\nrun 150\nvelocity lv2 set 0 0 0 units box\nnext i\njump SELF lp\nrun 2000\n", live="pass 1 (and after)")
L("A28_every_velocity", "run 2300 every 300 \"velocity lv2 set 0 0 0 units box\" (lv2 stopped at step 300 mid-contact)",
  "run 2300 every 300 \"velocity lv2 set 0 0 0 units box\"\n", live="part 1")
L("A29_every_if_velocity", "run 2300 every 300 \"if '$(step) == 300' then 'velocity lv2 set 0 0 0 units box'\"",
  "run 2300 every 300 \"if '$(step) == 300' then 'velocity lv2 set 0 0 0 units box'\"\n", live="part 1")
S("A30_set_group_vx", "run 300; set group lv2 vx 0.0; run 2000", "set group lv2 vx 0.0\n")
S("A31_set_region_vx", "run 300; region R block 0.021 0.03 0 0.04 0 0.1; set region R vx 0.0 (lv2); run 2000",
  "region R block 0.021 0.03 0 0.04 0 0.1 units box\nset region R vx 0.0\n")
S("A32_set_type_vx", "run 300; set type 2 vx 0.0; run 2000", "set type 2 vx 0.0\n")
S("A33_set_type_omega", "run 300; set type 2 omega 0 0 500 (a spin: head-on, no effect with no tangential slip? linear_nohistory 0.3)", "set type 2 omega 0 0 500\n")
S("A34_set_type_density", "run 300; set type 2 density 5000 (mid-contact mass change); run 2000", "set type 2 density 5000\n")
S("A35_set_type_mass", "run 300; set type 2 mass 5.6549e-4 (doubled); run 2000", "set type 2 mass 5.6549e-4\n")
S("A36_set_type_diameter", "run 300; set type 2 diameter 0.0062 (mid-contact growth); run 2000", "set type 2 diameter 0.0062\n")
S("A37_displace_lv2", "run 300; displace_atoms lv2 move 0.0001 0 0 units box; run 2000", "displace_atoms lv2 move 0.0001 0 0 units box\n")
S("A38_velocity_zero_linear_lv2", "run 300; velocity lv2 zero linear (lv2's momentum zeroed); run 2000", "velocity lv2 zero linear\n")
S("A39_velocity_ramp", "run 300; velocity all ramp vx 0 0.5 x 0.015 0.03 units box; run 2000", "velocity all ramp vx 0 0.5 x 0.015 0.03 units box\n")
S("A40_set_atom_x", "run 300; set atom 2 x 0.0236 (lv2 moved 0.1 mm back? its x then); run 2000", "set atom 2 x 0.0236\n")
S("A41_set_atom_type_change", "pc 1 2 kn 5000; run 300; set atom 2 type 1 (the pair becomes 1 1, kn 2000, mid-contact); run 2000",
  "set atom 2 type 1\n", pair=IN(0.1e-3) + PC5)
S("A42_set_atom_type_change_same_eps", "coeff_restitution 0.5: 1 2 kn 5000, 1 1 kn 2000; run 300; set atom 2 type 1; run 2000",
  "set atom 2 type 1\n", pre=RBCR, pair=IN(0.1e-3) + "pair_coeff 1 2 " + CR(5000) + "\n")
S("A43_set_type_fraction", "pc 1 2 kn 5000; run 300; set type 2 type/fraction 1 1.0 123 (lv2 to type 1 mid-contact); run 2000",
  "set type 2 type/fraction 1 1.0 12345\n", pair=IN(0.1e-3) + PC5)
S("A44_set_atom_image", "run 300; set atom 2 image 0 0 0 (no motion: 0.413)", "set atom 2 image 0 0 0\n")
S("A45_star_star_all_pairs", "run 300; pair_coeff * * kn 5000 (1 1, 1 2, 2 2 change at once); run 2000", "pair_coeff * * " + HKk(5000) + "\n")
S("A46_pc_11_only", "run 300; pair_coeff 1 1 kn 5000 (the 1 2 law unchanged: 0.413)", "pair_coeff 1 1 " + HKk(5000) + "\n")
S("A47_viscous_added", "run 300; fix vis lv2 viscous 0.05; run 2000", "fix vis lv2 viscous 0.05\n")
S("A48_integ_lv1_only", "run 300; unfix integ; fix i1 lv1 nve/sphere (lv2 no longer integrated mid-contact); run 2000", "unfix integ\nfix i1 lv1 nve/sphere\n")
S("A49_reintegrate_same", "run 300; unfix integ; fix integ all nve/sphere (the same: 0.413)", "unfix integ\nfix integ all nve/sphere\n")
L("A50_run0_hidden_law", "run 300; pc 5000; run 0; pc 2000; run 2000 (kn 5000 only in a run of 0 steps: 0.413)",
  "run 300\n" + PC5 + "run 0\n" + PCs(2000) + "\nrun 2000\n", live="run 1 (and 3)")
L("A51_every_pc_then_restore", "run 2300 every 300 \"pc 5000\" \"pc 2000\" (each part ends restored: 0.413)",
  "run 2300 every 300 \"" + PCs(5000) + "\" \"" + PCs(2000) + "\"\n", live="part 1")
L("A52_run300_every300_pc", "run 300 every 300 \"pc 5000\" (at the run's end, mid-contact); run 2000", "run 300 every 300 \"" + PCs(5000) + "\"\nrun 2000\n", live="run 1 (and run 2)")
L("A53_post_no_kick_pre_no", "run 300 post no; velocity lv2 set 0 0 0; run 2000 pre no", "run 300 post no\nvelocity lv2 set 0 0 0 units box\nrun 2000 pre no\n", live="run 1 (and run 2)")
S("A54_set_vx_equal_var", "run 300; variable vv equal 0.1; set atom 2 vx v_vv; run 2000", "variable vv equal 0.1\nset atom 2 vx v_vv\n")
S("A55_velocity_set_loop_var", "run 300; variable v index 0.0; velocity lv2 set ${v} 0 0 units box; run 2000", "variable v index 0.0\nvelocity lv2 set ${v} 0 0 units box\n")
S("A56_dt_smaller", "run 300; timestep 5e-7; run 4000 (the law's eps the same at any dt: 0.413)", "timestep 5e-7\n")
SW("A57_gravity_redefined", "run 300; fix grav all gravity 500 vector 0 0 -1 (same ID, mid-contact); run 2000", "fix grav all gravity 500 vector 0 0 -1\n")
SW("A58_second_floor_added", "run 300; fix floor2 all wall/gran ... zplane 0 (a second floor mid-contact); run 2000",
   "fix floor2 all wall/gran granular " + HK + " zplane 0 NULL\n")
SW("A59_wall_moves_zplane", "run 300; fix floor redefined at zplane 0.0001 (the floor jumps 0.1 mm into the sphere); run 2000",
   "fix floor all wall/gran granular " + HK + " zplane 0.0001 NULL\n")
S("A60_group_redefined_kick", "run 300; group g2 type 2; velocity g2 set 0 0 0 units box; run 2000", "group g2 type 2\nvelocity g2 set 0 0 0 units box\n")
S("A61_fix_set_vx_via_variable_every", "run 300; fix kick lv2 setforce? no: fix aveforce lv2 -5 NULL NULL for the rest", "fix ak lv2 aveforce -0.05 NULL NULL\n")
S("A62_two_changes_pair_and_wall", "a floor too; run 300; pc 5000 and the floor kn 5000 in one stage", PC5 + "fix floor all wall/gran granular " + HKk(5000) + " zplane 0 NULL\n", pre=BASE())
S("A63_kick_and_law_same_stage", "run 300; pc 5000; velocity lv2 set -0.1 0 0; run 2000", PC5 + "velocity lv2 set -0.1 0 0 units box\n")
S("A64_velocity_lv1_only_same", "run 300; velocity lv1 set NULL NULL NULL (no change: 0.413)", "velocity lv1 set NULL NULL NULL units box\n")
S("A65_write_restart_read_same", "run 300; write_restart r.rst; clear; read_restart r.rst; the same settings again; run 2000 (mid-contact restart: 0.413?)",
  "write_restart r.rst\nclear\nread_restart r.rst\npair_style granular\npair_coeff * * " + HK + "\ncomm_modify vel yes\nfix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\n")
S("A66_restart_new_law", "run 300; write_restart r.rst; clear; read_restart r.rst; pair_coeff * * kn 5000; run 2000",
  "write_restart r.rst\nclear\nread_restart r.rst\npair_style granular\npair_coeff * * " + HKk(5000) + "\ncomm_modify vel yes\nfix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\n")
S("A67_write_data_read_data", "run 300; write_data d.data; clear; read_data d.data (velocities kept); same settings; run 2000",
  "write_data d.data\nclear\nunits si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data d.data\npair_style granular\npair_coeff * * " + HK +
  "\nfix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\ngroup lv1 id 1\ngroup lv2 id 2\n")
S("A68_data_nvel", "run 300; write_data d.data nocoeff; clear; read_data; velocities... a pair_coeff kn 5000", 
  "write_data d.data nocoeff\nclear\nunits si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data d.data\npair_style granular\npair_coeff * * " + HKk(5000) +
  "\nfix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\ngroup lv1 id 1\ngroup lv2 id 2\n")
SG("A71_young_stiffer_same_e", "run 300; youngsModulus 5e6 -> 5e7 mid-contact (e unchanged: 0.5 each)", "fix m1 all property/global youngsModulus peratomtype 5e7 5e7 5e7\n")
SG("A72_e_changed", "run 300; e 1 2 0.8 mid-contact; run 2000 (noted?)", LEe(0.8))
SG("A73_velocity_kick", "run 300; velocity lv2 set 0 0 0; run 2000", "velocity lv2 set 0 0 0\n")
SG("A74_set_vx", "run 300; set atom 2 vx 0.0; run 2000", "set atom 2 vx 0.0\n")
SG("A75_set_density", "run 300; set atom 2 density 5000; run 2000", "set atom 2 density 5000\n")
SG("A76_poisson_changed", "run 300; poissonsRatio 0.3 -> 0.45 (stiffness; e unchanged)", "fix m2 all property/global poissonsRatio peratomtype 0.45 0.45 0.45\n")
SG("A77_pair_style_again", "run 300; pair_style gran model hooke tangential history; pair_coeff * * (another model, e 0.5)", "pair_style gran model hooke tangential history\npair_coeff * *\n")
SG("A78_set_type_change", "run 300; set atom 2 type 3 (e 1 3 0.7 mid-contact)", "set atom 2 type 3\n")
SG("A79_displace", "run 300; displace_atoms lv2 move 0.0001 0 0 units box", "displace_atoms lv2 move 0.0001 0 0 units box\n")
SG("A80_timestep_coarse", "run 300; timestep 2e-5; run 200", "timestep 2e-5\n")
LG("A81_lig_every_e", "LIGGGHTS run 2300 every 300 \"fix m3 ... e 0.8\" (from step 300 mid-contact)", "run 2300 every 300 \"" + LE.format(e="0.8") + "\"\n", live="part 1")
LG("A82_lig_every_velocity", "LIGGGHTS run 2300 every 300 \"velocity lv2 set 0 0 0\"", "run 2300 every 300 \"velocity lv2 set 0 0 0\"\n", live="part 1")
LG("A83_lig_wall_e_changed", "LIGGGHTS WALL: run 300; e 1 3 0.9 mid-contact (wall type 3)", "run 300\nfix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.9 0.5 0.4 0.45 0.9 0.45 0.8\nrun 2000\n",
   pair=LWALL(1e-4), live="run 1 (and run 2)", **LW)
LG("A84_lig_wall_young", "LIGGGHTS WALL: run 300; youngsModulus x10 mid-contact (e unchanged)", "run 300\nfix m1 all property/global youngsModulus peratomtype 5e7 5e7 5e7\nrun 2000\n",
   pair=LWALL(1e-4), live="run 1 (and run 2)", **LW)
SG("A85_unfix_integ_lv2", "run 300; unfix integr; fix i1 lv1 nve/sphere (lv2 not integrated)", "unfix integr\nfix i1 lv1 nve/sphere\n")
SG("A86_freeze_lv2", "run 300; fix fz lv2 freeze mid-contact", "fix fz lv2 freeze\n")
S("A87_two_pairs_kick_both", "run 300; velocity all set 0 0 0 (both spheres stopped mid-contact)", "velocity all set 0 0 0 units box\n")
S("A88_set_type_1_and_2_density", "run 300; set type 1 density 5000; set type 2 density 5000 (both heavier: eps of the law the same? 0.37)", "set type 1 density 5000\nset type 2 density 5000\n")
S("A89_damping_only_same_eps_no", "run 300; pc hooke 2000 damping 3000 -> velocity damping (another law)", "pair_coeff 1 2 hooke 2000 0.2 damping velocity tangential linear_nohistory 1 0.3\n")
S("A90_next_jump_kick", "label loop with next/jump: 2 passes of run 150 with a pc in between kn 5000 on the second pass",
  "variable i index 1 2\n", )
DECKS["A90_next_jump_kick"] = ("# a loop: pass 1 run 300; pass 2 pc 5000 (mid-contact) then run 2000\n" + RB + IN(0.1e-3) +
  "variable i loop 2\nlabel lp\nif \"${i} == 2\" then \"" + PCs(5000) + "\"\nrun $(300+1700*(v_i-1))\nnext i\njump SELF lp\n", "pass 1 (and 2)", {}, {})
S("A91_fix_adapt_density_every", "run 300; variable d equal 5000; fix ad lv2 adapt 1 atom density? (not a keyword: diameter with scale no)... use set in fix: fix st all set? skip",
  "")
del DECKS["A91_fix_adapt_density_every"]
L("A92_every_set_type_diameter", "run 2300 every 300 \"set type 2 diameter 0.0061\" (from step 300, mid-contact)", "run 2300 every 300 \"set type 2 diameter 0.0061\"\n", live="part 1")
L("A93_every_variable_kick", "run 2300 every 300 \"variable vv equal 0.0\" \"velocity lv2 set v_vv 0 0 units box\"",
  "run 2300 every 300 \"variable vv equal 0.0\" \"velocity lv2 set v_vv 0 0 units box\"\n", live="part 1")
L("A94_every_include_kick", "run 2300 every 300 \"include k.in\" (k.in: set atom 2 vx 0.0)", "run 2300 every 300 \"include k.in\"\n", live="part 1", data={"k.in": "set atom 2 vx 0.0\n"})
S("A95_neighbor_exclude_group", "run 300; group both id 1 2; neigh_modify exclude group both both mid-contact", "neigh_modify exclude group lv1 lv2\n")
S("A96_delete_bonds_none", "run 300; velocity lv2 set -0.2285714286 0 0 (its approach velocity set back mid-contact)", f"velocity lv2 set {VX2} 0 0 units box\n")
S("A97_hertz_same_eps_damping_E", "hertz/material E 1e7 -> 3e6 (tsuji e 0.5) in a pc of 1 2 only", "pair_coeff 1 2 " + HM("3e6") + "\n", pre=RBHM)
S("A98_cr_kn_same_run_every", "coeff_restitution: run 300 ... no: run 2300 every 300 pc 1 2 kn $(2000+10*step) e 0.5 (same eps each part)", "")
del DECKS["A98_cr_kn_same_run_every"]
L("A98_cr_every_kn_ramp", "coeff_restitution 0.5: run 2300 every 300 \"pc 1 2 hooke $(2000+10*step) 0.5\" (each part's eps 0.5, the spring stiffer mid-contact)",
  "run 2300 every 300 \"pair_coeff 1 2 hooke $(2000+10*step) 0.5 damping coeff_restitution tangential linear_nohistory 1 0.3\"\n", pre=RBCR, live="part 1")
L("A99_cr_loop_kn", "coeff_restitution 0.5: a loop of runs of 200 with kn 2000, 3000, 4000 ... (same eps each)",
  "variable i loop 8\nlabel lp\npair_coeff 1 2 hooke $(1000+1000*v_i) 0.5 damping coeff_restitution tangential linear_nohistory 1 0.3\nrun 200\nnext i\njump SELF lp\n", pre=RBCR, live="pass 1")

# ================================================================ B: pushing fixes
RG = "region cage block 0 0.04 0 0.04 0 0.1 units box\n"
BW = lambda name, desc, fx, **kw: L(name, "WALL: " + desc, fx + "run 3000\n", pre=BASE(), pair=WALLP(), **WALL, **kw)
BW("B01_region_lj126", "fix wall/region cage lj126 1e-4 0.001 0.0025", RG + "fix soft all wall/region cage lj126 1e-4 0.001 0.0025\n")
BW("B02_region_colloid", "fix wall/region cage colloid 1e-4 0.001 0.0025", RG + "fix soft all wall/region cage colloid 1e-4 0.001 0.0025\n")
BW("B03_region_morse", "fix wall/region cage morse 1e-4 100 0.001 0.0025", RG + "fix soft all wall/region cage morse 1e-4 100 0.001 0.0025\n")
BW("B04_region_harmonic_far", "fix wall/region on a region whose faces are far (a cube 0.005-0.035 in z 0.02-0.09): no push at the floor (0.3617)",
   "region far block 0.005 0.035 0.005 0.035 0.02 0.09 units box side out\nfix soft all wall/region far harmonic 20.0 0.0 0.0025\n")
BW("B05_wall_lj93", "fix wall/lj93 zlo EDGE 1e-4 0.001 0.0025", "fix soft all wall/lj93 zlo EDGE 1e-4 0.001 0.0025\n")
BW("B06_wall_lj126", "fix wall/lj126 zlo EDGE 1e-4 0.001 0.0025", "fix soft all wall/lj126 zlo EDGE 1e-4 0.001 0.0025\n")
BW("B07_wall_colloid", "fix wall/colloid zlo EDGE 1e-4 0.001 0.0025", "fix soft all wall/colloid zlo EDGE 1e-4 0.001 0.0025\n")
BW("B08_wall_morse", "fix wall/morse zlo EDGE 1e-4 100 0.001 0.0025", "fix soft all wall/morse zlo EDGE 1e-4 100 0.001 0.0025\n")
BW("B09_wall_reflect_in_contact", "fix wall/reflect zlo 0.0019 (the centre reaches it 0.1 mm into the floor contact: reflected)", "fix wr all wall/reflect zlo 0.0019 units box\n")
BW("B10_wall_reflect_zlo_edge", "fix wall/reflect zlo EDGE (never reached: 0.3617)", "fix wr all wall/reflect zlo EDGE\n")
BW("B11_gran_region_plus_region", "wall/gran/region and wall/region harmonic on one plane region",
   "region pl plane 0 0 0 0 0 1 side in units box\nfix g2 all wall/gran/region granular " + HK + " region pl\nfix soft all wall/region pl harmonic 20.0 0.0 0.0025\n",)
L("B12_spring_tether_lv2", "fix spring tether on lv2 at its start (K 50)", "fix sp lv2 spring tether 50.0 0.02305 0.02 0.05 0.0\nrun 3000\n")
L("B13_spring_self_lv2", "fix spring/self lv2 50", "fix sp lv2 spring/self 50.0\nrun 3000\n")
L("B14_spring_couple", "fix spring couple lv1 lv2 50 (the pair pulled together)", "fix sp lv1 spring couple lv2 50.0 0.0 0.0 0.0 0.005\nrun 3000\n")
CH = BASE(wall=False).replace("atom_style sphere 1", "atom_style hybrid sphere 1 charge")
L("B15_efield", "atom_style hybrid sphere charge; lv2 charge 1e-6; fix efield 1e5 0 0", "set atom 2 charge 1e-6\nfix ef all efield 1e5 0.0 0.0\nrun 3000\n", pre=CH)
L("B16_efield_no_charge", "charges 0 with fix efield (no force: 0.413)", "fix ef all efield 1e5 0.0 0.0\nrun 3000\n", pre=CH)
L("B17_rigid_single_lv2", "unfix integ; nve/sphere lv1; fix rigid single on lv2 (a rigid body of one sphere: 0.413?)",
  "unfix integ\nfix i1 lv1 nve/sphere\nfix rg lv2 rigid single\nrun 3000\n")
L("B18_rigid_small_lv2", "unfix integ; nve/sphere lv1; fix rigid/small on lv2 by its molecule",
  "unfix integ\nfix i1 lv1 nve/sphere\nset atom 2 mol 1\nfix rg lv2 rigid/small molecule\nrun 3000\n",
  pre=BASE(wall=False).replace("atom_style sphere 1", "atom_style hybrid sphere 1 molecular").replace("create_box 2 box", "create_box 2 box"))
L("B19_momentum_pair", "fix momentum 1 linear 1 1 1 (the pair's momentum 0 already: 0.413)", "fix mo all momentum 1 linear 1 1 1\nrun 3000\n")
BW("B20_momentum_floor", "fix momentum 1 linear 1 1 1 on the falling sphere (its momentum zeroed every step)", "fix mo all momentum 1 linear 1 1 1\n")
L("B21_recenter_pair", "fix recenter INIT INIT INIT (both shifted alike: 0.413)", "fix rc all recenter INIT INIT INIT\nrun 3000\n")
BW("B22_recenter_floor", "fix recenter NULL NULL INIT on the falling sphere (its height held)", "fix rc all recenter NULL NULL INIT\n")
L("B23_deform_x_remap", "fix deform 1 x scale 1.05 remap x (the pair's separation stretched)", "fix df all deform 1 x scale 1.05 remap x\nrun 3000\n")
L("B24_deform_remap_v", "fix deform 1 x scale 1.05 remap v", "fix df all deform 1 x scale 1.05 remap v\nrun 3000\n")
L("B25_deform_remap_none_z", "fix deform 1 y scale 1.05 remap none (y only: 0.413)", "fix df all deform 1 y scale 1.05 remap none\nrun 3000\n")
TWOD = ("units si\ndimension 2\natom_style sphere 1\nboundary p p p\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 -0.001 0.001 units box\ncreate_box 2 box\n"
        "pair_style granular\npair_coeff * * " + HK + "\nfix integ all nve/sphere {disc}\nfix e2 all enforce2d\ntimestep 1e-6\n"
        "create_atoms 1 single 0.01795 0.02 0.0\ncreate_atoms 2 single 0.02305 0.02 0.0\nset atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\n"
        f"group lv1 id 1\ngroup lv2 id 2\nvelocity lv1 set {V1:.10f} 0 0 units box\nvelocity lv2 set {V2:.10f} 0 0 units box\nrun 3000\n")
RAW("B26_2d_disc", "dimension 2, nve/sphere disc, enforce2d (discs; 2d density: mass per area)", TWOD.format(disc="disc"))
RAW("B27_2d_sphere", "dimension 2, nve/sphere (spheres in 2d: 3d masses), enforce2d", TWOD.format(disc=""))
RAW("B28_2d_no_enforce", "dimension 2 with nve/sphere disc, no enforce2d (a head-on pair stays in plane)", TWOD.format(disc="disc").replace("fix e2 all enforce2d\n", ""))
LMV = lambda v: ("fix cad all mesh/surface file floor.stl type 3\nfix walls all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"
                 f"fix mm all move/mesh mesh cad linear 0 0 {v}\nrun 3000\n")
LG("B29_lig_mesh_moving_up", "LIGGGHTS WALL: mesh floor moving up at 0.3 m/s (move/mesh linear)", LMV(0.3), pre=m9.LB(wall=False), pair=LWALL(1e-4),
   PAIR="type 1 on wall walls", data={"floor.stl": STLP()})
LG("B30_lig_mesh_moving_zero", "LIGGGHTS WALL: mesh floor with move/mesh linear 0 0 0 (still: 0.7)", LMV(0.0), pre=m9.LB(wall=False), pair=LWALL(1e-4),
   PAIR="type 1 on wall walls", data={"floor.stl": STLP()})
LG("B31_lig_mesh_moving_sideways", "LIGGGHTS WALL: mesh floor moving sideways 0.3 m/s (normal speed 0: 0.7?)", LMV("0").replace("linear 0 0 0", "linear 0.3 0 0"),
   pre=m9.LB(wall=False), pair=LWALL(1e-4), PAIR="type 1 on wall walls", data={"floor.stl": STLP()})
LG("B32_lig_region_wall_harmonic", "LIGGGHTS: fix wall/region harmonic around the pair (cylinder r 4.5 mm)",
   "region cyl cylinder z -0.0005 0 0.0045 -0.01 0.15 units box\nfix soft all wall/region cyl harmonic 5.0 0.0 0.005\nrun 3000\n")
LG("B33_lig_addforce", "LIGGGHTS fix addforce on lv2 -0.05 0 0", "fix af lv2 addforce -0.05 0.0 0.0\nrun 3000\n")
LG("B34_lig_spring_self", "LIGGGHTS fix spring/self on lv2", "fix sp lv2 spring/self 50.0\nrun 3000\n")
BW("B35_wall_harmonic_region_far_side", "fix wall/region side out sphere far from the floor contact (no push: 0.3617)",
   "region obs sphere 0.02 0.02 0.08 0.005 side out units box\nfix soft all wall/region obs harmonic 20.0 0.0 0.002\n")
L("B36_lineforce", "fix lineforce 0 1 0 (x forces zeroed: no contact force along x)", "fix lf all lineforce 0 1 0\nrun 3000\n")
L("B37_planeforce_x", "fix planeforce 1 0 0 (forces kept only in the yz plane: x dropped)", "fix pf all planeforce 1 0 0\nrun 3000\n")
L("B38_nve_sphere_update_dipole", "nve/sphere update dipole? no: nve/sphere extra? nve/sphere on all twice (two integrators)", "fix integ2 all nve/sphere\nrun 3000\n")
L("B39_wall_gran_region_far", "a wall/gran/region cylinder around far (no touch) + the pair (0.413)",
  "region cyl cylinder z 0.02 0.02 0.015 0 0.1 side in units box\nfix cw all wall/gran/region granular " + HK + " region cyl\nrun 3000\n")
L("B40_efield_variable", "efield with an equal-style variable 1e5 on charged lv2", "set atom 2 charge 1e-6\nvariable ex equal 1e5\nfix ef all efield v_ex 0.0 0.0\nrun 3000\n", pre=CH)

# ================================================================ C: units and sizes
FTM = {"metal": 1 / 1.0364269e-4, "real": 1 / 48.88821291 / 48.88821291}


def UNITS(u, scale=True, style="sphere 1", extra=""):
    f = FTM.get(u, 1.0) if scale else 1.0
    k, g = 2000 / f, 3000 / f
    return ("units " + u + "\natom_style " + style + "\nboundary p p f\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.1 units box\ncreate_box 2 box\n"
            f"neighbor 0.001 bin\npair_style granular\npair_coeff * * hooke {k:.10g} {g:.10g} damping mass_velocity tangential linear_nohistory 1 0.3\n"
            "fix integ all nve/sphere\ntimestep 1e-6\n" + extra + IN(0.1e-3) + "run 3000\n")


for u in ("lj", "cgs", "micro", "nano", "metal", "real"):
    RAW(f"C01_units_{u}", f"units {u}: the same numbers (kn and damping divided by LAMMPS' force-to-acceleration factor {FTM.get(u, 1.0):.6g}): 0.413435", UNITS(u))
for u in ("metal", "real"):
    RAW(f"C02_units_{u}_unscaled", f"units {u}: kn 2000 and damping 3000 as given (ftm2v {FTM[u]:.6g}; dt 1e-6)", UNITS(u, scale=False))
RAW("C03_units_metal_gravity", "units metal scaled, with fix gravity 9.81e-4 (eV/A/(g/mol)): the pair along x",
    UNITS("metal", extra="fix grav all gravity 9.81e-4 vector 0 0 -1\n"))
RAW("C04_sphere_no_arg", "atom_style sphere (no 0/1): 0.413", UNITS("si", style="sphere"))
RAW("C05_sphere_0", "atom_style sphere 0: 0.413", UNITS("si", style="sphere 0"))
L("C06_set_density_then_diameter", "set atom 2 density 5000 then set atom 2 diameter 0.006 (the diameter after the density: mass from 5000?)",
  "run 3000\n", pair=IN(0.1e-3).replace("set atom 2 diameter 0.006 density 2500", "set atom 2 density 5000\nset atom 2 diameter 0.006"))
L("C07_one_set_density_first", "set atom 2 density 5000 diameter 0.006 (one set, density first)", "run 3000\n",
  pair=IN(0.1e-3).replace("set atom 2 diameter 0.006 density 2500", "set atom 2 density 5000 diameter 0.006"))
L("C08_set_mass_then_diameter", "set atom 2 mass 5.6549e-4 then diameter 0.006", "run 3000\n",
  pair=IN(0.1e-3).replace("set atom 2 diameter 0.006 density 2500", "set atom 2 mass 5.6549e-4\nset atom 2 diameter 0.006"))
L("C09_set_diameter_then_mass", "set atom 2 diameter 0.006 then mass 5.6549e-4 (lv2 doubled: 0.390)", "run 3000\n",
  pair=IN(0.1e-3).replace("set atom 2 diameter 0.006 density 2500", "set atom 2 diameter 0.006\nset atom 2 mass 5.6549e-4"))
L("C10_set_diameter_only", "set atom 2 diameter 0.006 only (density from the default 1 m sphere of mass 1?)", "run 3000\n",
  pair=IN(0.1e-3).replace("set atom 2 diameter 0.006 density 2500", "set atom 2 diameter 0.006"))
L("C11_set_density_twice", "set atom 2 diameter 0.006 density 2500 then set atom 2 density 5000 (0.390)", "set atom 2 density 5000\nrun 3000\n")
L("C12_set_diameter_after_density_grow", "set atom 2 diameter 0.003 density 2500; set atom 2 diameter 0.006 (density kept: 2500?)", "run 3000\n",
  pair=IN(0.1e-3).replace("set atom 2 diameter 0.006 density 2500", "set atom 2 diameter 0.003 density 2500\nset atom 2 diameter 0.006"))
DATA = (f"# two spheres\n\n2 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n"
        f"1 1 0.004 2500 0.017950 0.02 0.05\n2 2 0.006 {{rho}} 0.023050 0.02 0.05\n\nVelocities\n\n1 {V1:.10f} 0 0 0 0 0\n2 {V2:.10f} 0 0 0 0 0\n")
RDB = ("units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data {f}\npair_style granular\npair_coeff * * " + HK +
       "\nfix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\ngroup lv1 id 1\ngroup lv2 id 2\n")
RAW("C13_read_data_sphere", "read_data with diameters and densities and velocities (0.413)", RDB.format(f="d.data") + "run 3000\n", data={"d.data": DATA.format(rho=2500)})
RAW("C14_read_data_density_5000", "read_data: lv2 density 5000 (0.390)", RDB.format(f="d.data") + "run 3000\n", data={"d.data": DATA.format(rho=5000)})
RAW("C15_read_data_two_files_add", "read_data a.data (lv1) then read_data b.data add append (lv2 5000)", RDB.format(f="a.data").replace("group lv1 id 1\n", "") +
    "read_data b.data add append\ngroup lv1 id 1\ngroup lv2 id 2\nrun 3000\n",
    data={"a.data": f"# a\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 1 0.004 2500 0.017950 0.02 0.05\n\nVelocities\n\n1 {V1:.10f} 0 0 0 0 0\n",
          "b.data": f"# b\n\n1 atoms\n2 atom types\n\n0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # sphere\n\n1 2 0.006 5000 0.023050 0.02 0.05\n\nVelocities\n\n1 {V2:.10f} 0 0 0 0 0\n"})
RAW("C16_read_data_then_set_density", "read_data (2500) then set type 2 density 5000 (0.390)", RDB.format(f="d.data") + "set type 2 density 5000\nrun 3000\n", data={"d.data": DATA.format(rho=2500)})
RAW("C17_read_data_mass_section_ignored", "read_data with a Masses section? (sphere: per-atom; LAMMPS ignores or stops)",
    RDB.format(f="d.data") + "run 3000\n", data={"d.data": DATA.format(rho=2500).replace("Atoms # sphere", "Masses\n\n1 1.0\n2 1.0\n\nAtoms # sphere")})
L("C18_create_atoms_random", "lv2 by create_atoms random 1 in a tiny region at its place (0.390 with density 5000)", "run 3000\n",
  pair=("create_atoms 1 single 0.017950 0.02 0.05\nregion tiny block 0.0230499 0.0230501 0.0199999 0.0200001 0.0499999 0.0500001 units box\n"
        "create_atoms 2 random 1 4321 tiny\nset atom 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 5000\ngroup lv1 id 1\ngroup lv2 id 2\n"
        f"velocity lv1 set {V1:.10f} 0 0 units box\nvelocity lv2 set {V2:.10f} 0 0 units box\n"))
L("C19_lattice_two_sites", "lattice sc 0.0051: two sites (x 0.0204, 0.0255) in a lattice-unit region; set atom 2 type 2", "run 3000\n",
  pair=("lattice sc 0.0051\nregion two block 3.5 5.5 3.5 4.5 9.5 10.5\ncreate_atoms 1 region two\nset atom 2 type 2\n"
        "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
        f"velocity lv1 set {V1:.10f} 0 0 units box\nvelocity lv2 set {V2:.10f} 0 0 units box\n"))
L("C20_lattice_units_velocity", "lattice sc 0.0051 then velocity in lattice units (V/0.0051 lattice units: the same m/s)", "run 3000\n",
  pair=("lattice sc 0.0051\nregion two block 3.5 5.5 3.5 4.5 9.5 10.5\ncreate_atoms 1 region two\nset atom 2 type 2\n"
        "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
        f"velocity lv1 set {V1 / 0.0051:.10f} 0 0\nvelocity lv2 set {V2 / 0.0051:.10f} 0 0\n"))
POURW = lambda spec, dens="dens 2500 2500": (BASE() + "region pr block 0.005 0.035 0.005 0.035 0.05 0.09 units box\n"
        f"fix p all pour 1 1 4767548 region pr diam {spec} {dens}\nrun 1\nunfix p\ngroup lv1 id 1\nset atom 1 z 0.0021\nvelocity lv1 set 0 0 -0.9990 units box\nrun 3000\n")
RAW("C21_pour_one", "WALL: fix pour of one sphere diam one 0.004, then set z and velocity (0.3617)", POURW("one 0.004"), PAIR="type 1 on wall floor")
RAW("C22_pour_range", "WALL: fix pour diam range 0.0039 0.0041 (a drawn size; the floor's eps by mass)", POURW("range 0.0039 0.0041"), PAIR="type 1 on wall floor")
RAW("C23_pour_poly", "WALL: fix pour diam poly 2 0.003 0.5 0.005 0.5", POURW("poly 2 0.003 0.5 0.005 0.5"), PAIR="type 1 on wall floor", RAD="0.002")
RAW("C24_pour_dens_range", "WALL: fix pour diam one 0.004 dens 2000 3000 (a drawn density)", POURW("one 0.004", "dens 2000 3000"), PAIR="type 1 on wall floor")
RAW("C25_deposit_one", "WALL: fix deposit of one type 1 sphere (its default 1 m diameter? set after)",
    BASE() + "region pr block 0.019 0.021 0.019 0.021 0.05 0.06 units box\nfix d all deposit 1 1 1 4767 region pr\nrun 1\nunfix d\ngroup lv1 id 1\n"
    "set atom 1 diameter 0.004 density 2500\nset atom 1 z 0.0021\nvelocity lv1 set 0 0 -0.9990 units box\nrun 3000\n", PAIR="type 1 on wall floor")
RAW("C26_units_cgs_gravity_floor", "WALL: units cgs, the floor deck's numbers (gravity 9.81 cm/s2: a weak gravity; the h term in the referee uses 9.81)",
    BASE().replace("units si", "units cgs").replace("timestep 1e-6\n", "neighbor 0.001 bin\ntimestep 1e-6\n") + WALLP() + "run 3000\n", PAIR="type 1 on wall floor")
RAW("C27_units_lj_floor", "WALL: units lj, the floor deck's numbers", BASE().replace("units si", "units lj").replace("timestep 1e-6\n", "neighbor 0.001 bin\ntimestep 1e-6\n") + WALLP() + "run 3000\n",
    PAIR="type 1 on wall floor")
f = FTM["metal"]
RAW("C28_units_metal_floor", "WALL: units metal, floor and pair scaled by ftm2v, gravity 9.81/ftm2v",
    BASE().replace("units si", "units metal").replace(HK, f"hooke {2000/f:.10g} {3000/f:.10g} damping mass_velocity tangential linear_nohistory 1 0.3")
    .replace("gravity 9.81", f"gravity {9.81/f:.10g}").replace("timestep 1e-6\n", "neighbor 0.001 bin\ntimestep 1e-6\n") + WALLP() + "run 3000\n", PAIR="type 1 on wall floor")

# ================================================================ D: the pass and the reader
L("D01_clear_new_deck", "a first deck (kn 5000, run 100) then clear; the live deck (kn 2000): 0.413", "run 3000\n",
  pre=BASE(wall=False, coeff="pair_coeff * * " + HKk(5000) + "\n") + IN(0.1e-3) + "run 100\nclear\n" + RB)
L("D02_clear_after_meeting", "the live deck run 3000 (kn 2000) then clear and a second deck kn 5000 with its own pair run 3000 (the last: 0.579)",
  "run 3000\nclear\n" + BASE(wall=False, coeff="pair_coeff * * " + HKk(5000) + "\n") + IN(0.1e-3) + "run 3000\n")
L("D03_restart_changed_density", "run 50; write_restart; clear; read_restart; set type 2 density 5000; run 3000 (0.390)",
  "run 50\nwrite_restart r.rst\nclear\nread_restart r.rst\npair_style granular\npair_coeff * * " + HK + "\ncomm_modify vel yes\nfix integ all nve/sphere\ntimestep 1e-6\nset type 2 density 5000\nrun 3000\n")
L("D04_restart_changed_timestep", "run 50; restart; timestep 2e-6 (0.413)",
  "run 50\nwrite_restart r.rst\nclear\nread_restart r.rst\npair_style granular\npair_coeff * * " + HK + "\ncomm_modify vel yes\nfix integ all nve/sphere\ntimestep 2e-6\nrun 2000\n")
L("D05_restart_pair_given_new", "run 50; restart; pair_style granular; pair_coeff * * kn 5000 (0.579)",
  "run 50\nwrite_restart r.rst\nclear\nread_restart r.rst\npair_style granular\npair_coeff * * " + HKk(5000) + "\ncomm_modify vel yes\nfix integ all nve/sphere\ntimestep 1e-6\nrun 3000\n")
L("D06_loop_runs_then_meet", "a loop of 5 runs of 100 (no contact yet); pc 5000; run 3000 (meets in the last: 0.579)",
  "variable i loop 5\nlabel lp\nrun 100\nnext i\njump SELF lp\n" + PC5 + "run 3000\n", pair=IN(0.6e-3))
L("D07_nested_include_runs", "include a.in (run 100; include b.in: pc 5000, run 3000)", "include a.in\n", pair=IN(0.2e-3),
  data={"a.in": "run 100\ninclude b.in\n", "b.in": PC5 + "run 3000\n"})
L("D08_run0_many", "run 0 three times with pc changes, then run 3000 (kn 4000 last)", "run 0\n" + PC5 + "run 0\n" + PCs(3000) + "\nrun 0\n" + PCs(4000) + "\nrun 3000\n")
L("D09_pre_no_post_no_chain", "run 50 pre no post no; run 3000 pre no post no (0.413)", "run 50 pre no post no\nrun 3000 pre no post no\n")
L("D10_short_runs_loop", "30 runs of 100 steps (0.413)", "variable i loop 30\nlabel lp\nrun 100\nnext i\njump SELF lp\n", live="pass 1-7")
L("D11_run_1_loop_pc_same", "10 runs of 1 step; pc 2000 again before each; run 3000 (0.413)",
  "variable i loop 10\nlabel lp\n" + PCs(2000) + "\nrun 1\nnext i\njump SELF lp\nrun 3000\n")
L("D12_jump_skips_pc", "jump SELF over a pc 5000 (not run): 0.413", "jump SELF skip\n" + PC5 + "label skip\nrun 3000\n")
L("D13_if_quit_after", "run 3000; if \"1 > 0\" then quit; pc 5000; run 3000 (never run: 0.413)", "run 3000\nif \"1 > 0\" then quit\n" + PC5 + "run 3000\n")
L("D14_include_with_jump_back", "include a.in whose last line jumps back into the deck's label (loop via files)",
  "variable i loop 2\nlabel lp\ninclude a.in\n", data={"a.in": "run 1500\nnext i\njump in.deck lp\n"}, live="pass 1")
L("D15_clear_then_lig_style", "clear between two decks with different atom styles", "run 3000\n",
  pre=BASE(wall=False).replace("atom_style sphere 1", "atom_style hybrid sphere 1 charge") + "clear\n" + RB)
L("D16_run_every_zero_len", "run 0 every 1 NULL? run 3000 every 3000 \"pc 5000\" (after the run: 0.413)", "run 3000 every 3000 \"" + PCs(5000) + "\"\n")
L("D17_write_restart_every", "restart 1000 r.*; run 3000 (files written: 0.413)", "restart 1000 r.*.rst\nrun 3000\n")
L("D18_label_jump_next_pc", "variable k index 5000 3000; label a; pc ${k}; run 1500; next k; jump SELF a (meets in run 1: 5000)",
  "variable k index 5000 3000\nlabel a\n" + PCs("${k}") + "\nrun 1500\nnext k\njump SELF a\n", live="pass 1")

# ================================================================ F: more changes while a contact is under way (a second batch)
WD0 = "write_dump all custom d0.dump id type x y z vx vy vz\n"
L("F01_read_dump_velocities", "write_dump at step 0; run 300; read_dump d0.dump 0 vx vy vz (the approach velocities back mid-contact); run 2000",
  "run 300\nread_dump d0.dump 0 vx vy vz\nrun 2000\n", pair=IN(0.1e-3) + WD0, live="run 1 (and run 2)")
L("F02_read_dump_positions", "write_dump at step 0; run 300; read_dump d0.dump 0 x y z (the start places back mid-contact: the pair 0.1 mm apart, opening)",
  "run 300\nread_dump d0.dump 0 x y z\nrun 2000\n", pair=IN(0.1e-3) + WD0, live="run 1 (and run 2)")
SG("F03_lig_wall_moved", "WALL: run 300; fix wprim redefined at zplane 0.0001 (same ID) mid-contact",
   "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0001\n", pair=LWALL(1e-4), **LW)
SG("F04_lig_wall_unfixed", "WALL: run 300; unfix wprim mid-contact", "unfix wprim\n", pair=LWALL(1e-4), **LW)
S("F05_change_box_delta_remap", "run 300; change_box all x delta 0 0.0008 remap (lv2 0.1 mm further)", "change_box all x delta 0 0.0008 remap units box\n")
S("F06_deform_added_mid", "run 300; fix deform 1 x scale 1.05 remap x added mid-contact", "fix df all deform 1 x scale 1.05 remap x\n")
S("F07_set_group_type", "pc 1 2 kn 5000; run 300; set group lv2 type 1 mid-contact", "set group lv2 type 1\n", pair=IN(0.1e-3) + PC5)
S("F08_set_region_type", "pc 1 2 kn 5000; run 300; set region R type 1 (lv2) mid-contact",
  "region R block 0.021 0.03 0 0.04 0 0.1 units box\nset region R type 1\n", pair=IN(0.1e-3) + PC5)
SW("F09_wall_wiggle_added", "run 300; fix floor redefined with wiggle z 1e-4 0.001 mid-contact", "fix floor all wall/gran granular " + HK + " zplane 0 NULL wiggle z 1e-4 0.001\n")
S("F10_freeze_added_lv2", "run 300; group t2 type 2; fix fz t2 freeze mid-contact", "group t2 type 2\nfix fz t2 freeze\n")
S("F11_displace_random", "run 300; displace_atoms lv2 random 0.0001 0 0 123 units box", "displace_atoms lv2 random 0.0001 0 0 123 units box\n")
S("F12_nve_limit_added", "run 300; unfix integ; fix integ all nve/limit 1e-7 (mid-contact)", "unfix integ\nfix integ all nve/limit 1e-7\n")
S("F13_wall_same_redefined", "run 300; fix floor all wall/gran same args (no change: 0.413; the pair deck with a floor)", "fix floor all wall/gran granular " + HK + " zplane 0 NULL\n", pre=BASE())
SW("F14_wall_same_redefined_floor", "run 300; fix floor redefined with the same args (history reset only: 0.3617)", "fix floor all wall/gran granular " + HK + " zplane 0 NULL\n")
S("F15_set_same_size_again", "run 300; set atom 2 diameter 0.006 density 2500 (the same: 0.413)", "set atom 2 diameter 0.006 density 2500\n")
SW("F16_wall_hertz_same_eps", "floor hertz/material tsuji e 0.5 E 1e7 -> 1e8 mid-contact (same eps)", "fix floor all wall/gran granular " + HM("1e8") + " zplane 0 NULL\n",
   pre=BASE(wall=False) + "fix floor all wall/gran granular " + HM("1e7") + " zplane 0 NULL\n")
S("F17_region_delete_redefine", "a plane region wall x; run 300; unfix; region delete; a new region at another place; refix",
  "unfix cw\nregion pl delete\nregion pl plane 0.0 0 0 1 0 0 side in units box\nfix cw all wall/gran/region granular " + HK + " region pl\n",
  pre=BASE(wall=False) + "region pl plane 0.001 0 0 1 0 0 side in units box\nfix cw all wall/gran/region granular " + HK + " region pl\n")
S("F18_cr_kn_mid_pair_wall_also", "coeff_restitution pair and a floor: run 300; pair_coeff * * kn 5000 e 0.5; floor stiffer too (same eps everywhere)",
  "pair_coeff * * " + CR(5000) + "\nfix floor all wall/gran granular " + CR(5000) + " zplane 0 NULL\n",
  pre=RBCR + "fix floor all wall/gran granular " + CR(2000) + " zplane 0 NULL\n")
L("F19_every_set_type", "pc 1 2 kn 5000; run 2300 every 300 \"set atom 2 type 1\" (at step 300, mid-contact)", "run 2300 every 300 \"set atom 2 type 1\"\n",
  pair=IN(0.1e-3) + PC5, live="part 1")
L("F20_include_set_type", "pc 1 2 kn 5000; run 300; include t.in (set atom 2 type 1); run 2000", "run 300\ninclude t.in\nrun 2000\n",
  pair=IN(0.1e-3) + PC5, live="run 1 (and run 2)", data={"t.in": "set atom 2 type 1\n"})
S("F21_hertz_material_poisson_same_eps", "hertz/material tsuji e 0.5: nu 0.3 -> 0.45 mid-contact (pair_coeff * *)",
  "pair_coeff * * hertz/material 1e7 0.5 0.45 damping tsuji tangential linear_nohistory 1 0.3\n", pre=RBHM)
S("F22_hooke_velocity_damping_same", "run 300; pc hooke 2000 3000 -> hooke 2000 3000 (the same law given again: 0.413)", PCs(2000) + "\n")
SG("F23_lig_young_type2_only", "LIGGGHTS run 300; youngsModulus type 2 only 5e7 mid-contact (e unchanged)", "fix m1 all property/global youngsModulus peratomtype 5e6 5e7 5e6\n")
SG("F24_lig_e_restored", "LIGGGHTS run 300; e 1 2 0.8; run 100; e 1 2 0.5; run 2000 (0.8 for 100 steps)", "")
del DECKS["F24_lig_e_restored"]
LG("F24_lig_e_restored", "LIGGGHTS: run 300; e 1 2 0.8; run 100; e 1 2 0.5; run 2000 (e 0.8 for 100 steps mid-contact)",
   "run 300\n" + LEe(0.8) + "run 100\n" + LEe(0.5) + "run 2000\n", live="run 1 (and 2, 3)")

D0 = open(os.path.join(HERE, "d0.dump")).read() if os.path.exists(os.path.join(HERE, "d0.dump")) else ""
L("F25_read_dump_given_file", "run 300; read_dump d0.dump 0 vx vy vz of a dump file in the folder (the approach velocities back mid-contact); run 2000",
  "run 300\nread_dump d0.dump 0 vx vy vz\nrun 2000\n", live="run 1 (and run 2)", data={"d0.dump": D0})
L("F26_read_dump_given_before", "read_dump d0.dump 0 x y z vx vy vz of a dump file in the folder, before the first run (the same state: 0.413)",
  "read_dump d0.dump 0 x y z vx vy vz\nrun 3000\n", data={"d0.dump": D0})

L("F27_write_read_dump_before_run", "write_dump d0.dump then read_dump d0.dump 0 x y z vx vy vz before the only run (the same state: 0.413)",
  WD0 + "read_dump d0.dump 0 x y z vx vy vz\nrun 3000\n")

# ================================================================ G: a fix's group filled while a contact is under way
MOLB = BASE(wall=False).replace("atom_style sphere 1", "atom_style hybrid sphere 1 molecular")
S("G01_set_mol_excluded_mid", "molecules 1 and 2, neigh_modify exclude molecule/intra all; run 300; set atom 2 mol 1 (the pair excluded mid-contact)",
  "set atom 2 mol 1\n", pre=MOLB, pair=IN(0.1e-3) + "set atom 1 mol 1\nset atom 2 mol 2\nneigh_modify exclude molecule/intra all\n")
S("G02_exclude_group_filled_mid", "neigh_modify exclude group lv1 gx (gx empty); run 300; group gx id 2 (the pair excluded mid-contact)",
  "group gx id 2\n", pair=IN(0.1e-3) + "group gx empty\nneigh_modify exclude group lv1 gx\n")
S("G03_setforce_group_filled_mid", "fix setforce 0 0 0 on gs (empty); run 300; group gs id 2 (lv2's force zeroed from then)",
  "group gs id 2\n", pair=IN(0.1e-3) + "group gs empty\nfix sf gs setforce 0.0 0.0 0.0\n")
S("G04_freeze_group_filled_mid", "fix freeze on gz (empty); run 300; group gz id 2", "group gz id 2\n", pair=IN(0.1e-3) + "group gz empty\nfix fz gz freeze\n")
S("G05_viscous_group_filled_mid", "fix viscous 0.05 on gv (empty); run 300; group gv id 2", "group gv id 2\n", pair=IN(0.1e-3) + "group gv empty\nfix vis gv viscous 0.05\n")
S("G06_integ_group_emptied_mid", "nve/sphere on gi (both); run 300; group gi clear (no sphere integrated from then)", "group gi clear\n",
  pre=BASE(wall=False, integ=False), pair=IN(0.1e-3) + "group gi id 1 2\nfix integ gi nve/sphere\n")
SG("G07_lig_freeze_group_filled_mid", "fix freeze on gz (empty); run 300; group gz id 2", "group gz id 2\n", pair=LIN(0.1e-3) + "group gz id 99\nfix fz gz freeze\n")
S("G08_addforce_group_filled_mid", "fix addforce -0.05 0 0 on ga (empty); run 300; group ga id 2", "group ga id 2\n", pair=IN(0.1e-3) + "group ga empty\nfix af ga addforce -0.05 0.0 0.0\n")

NP2 = ["A01", "A13", "A14", "A17", "A41", "A59", "A65", "A71", "B09", "B23", "C01_units_metal", "D03"]
if __name__ == "__main__":
    names = sys.argv[1:]
    m7.write(names)
    for n in m7.DECKS:
        if not names or any(n.startswith(p) for p in names):
            open(os.path.join(m7.D, n, "NP"), "w").write("1 2\n" if any(n.startswith(p) for p in NP2) else "1\n")

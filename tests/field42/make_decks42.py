"""Field round 42: write decks/NAME/ (in.deck and the files it reads) for the referee (round 37's live37.py) and the
audit. A quick adversarial round on main's next commit after c884a2a3, which names a law changed between stages, atoms
or the box changed between runs, walls defined again, moved or removed between runs, deform remap x and wall/region.
Families (the pair meets at step 100, a contact lasts about 580 steps; `run 300; X; run 2000` is mid-contact, `run 50;
X; run 3000` before the meeting):
- F: other fixes added, redefined or removed mid-contact (move, setforce, addforce, aveforce, freeze, nve/limit,
  viscous, spring, spring/self, momentum, recenter, gravity on one sphere, the integrator redefined on one group,
  indent, wall/lj93, wall/harmonic);
- R: a group redefined so that a fix's atoms change (`group gx id 2` adding a sphere to a fix's group, `group gi
  clear`), integrator groups;
- N: neighbor lists (exclude added/removed mid-contact and before the meeting, neighbor skin, every), timestep,
  reset_timestep, comm_modify, atom_modify sort, balance, replicate;
- C: clear + read_restart round trips (the law the same, changed, the atoms of another step), clear and a new deck;
- W: walls: two floors (a second wall fix at the same plane, from the start and mid-contact), shear and wiggle added;
- E: changes inside run every, include, jump loops, if;
- G: LIGGGHTS: property/global in a run's every, freeze/setforce/viscous mid, timestep, exclusion, two primitive
  floors, shear added, a group cleared, insertion.
Helpers are rounds 35-41's (make_decks41.py imported; its decks are not written).
usage: python make_decks42.py [NAME-PREFIX ...]"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field41"))
import make_decks41 as m41  # noqa: E402

m7 = m41.m7
m7.DECKS.clear(); m7.LINKS.clear(); m7.HARD.clear()
m7.D = os.path.join(HERE, "decks")
L, LG, DECKS = m7.L, m7.LG, m7.DECKS
S, B, SW, BW, SG, BG = m41.S, m41.B, m41.SW, m41.BW, m41.SG, m41.BG
PCs, PC5, HKk, IN, LIN, LE, LEe = m41.PCs, m41.PC5, m41.HKk, m41.IN, m41.LIN, m41.LE, m41.LEe
BASE, WALLP, WALL, FLOOR, HK = m41.BASE, m41.WALLP, m41.WALL, m41.FLOOR, m7.HK
PC5s = PCs(5000)
EV = lambda X, n=300: L  # placeholder (not used)

# ================================================================ F: fixes mid-contact
S("F01_move_linear_zero_lv2", "run 300; fix mv lv2 move linear 0 0 0 (lv2 held still mid-contact)", "fix mv lv2 move linear 0 0 0\n")
S("F02_move_linear_null_lv2", "run 300; unfix integ; fix i1 lv1 nve/sphere; fix mv lv2 move linear NULL NULL NULL (move integrates: control)",
  "unfix integ\nfix i1 lv1 nve/sphere\nfix mv lv2 move linear NULL NULL NULL\n")
S("F03_setforce_lv2_mid", "run 300; fix sf lv2 setforce 0 0 0 (lv2 keeps its velocity)", "fix sf lv2 setforce 0.0 0.0 0.0\n")
S("F04_addforce_lv2_mid", "run 300; fix af lv2 addforce -0.5 0 0 (pushes lv2 into lv1)", "fix af lv2 addforce -0.5 0.0 0.0\n")
S("F05_aveforce_all_mid", "run 300; fix av all aveforce 0 0 0 (the pair's forces averaged: none)", "fix av all aveforce 0.0 0.0 0.0\n")
S("F06_freeze_lv2_mid", "run 300; fix fz lv2 freeze", "fix fz lv2 freeze\n")
S("F07_nve_limit_lv2_mid", "run 300; unfix integ; fix i1 lv1 nve/sphere; fix i2 lv2 nve/limit 1e-8", "unfix integ\nfix i1 lv1 nve/sphere\nfix i2 lv2 nve/limit 1e-8\n")
S("F08_viscous_lv2_mid", "run 300; fix vis lv2 viscous 0.05", "fix vis lv2 viscous 0.05\n")
S("F09_spring_tether_lv2_mid", "run 300; fix sp lv2 spring tether 50 0.02305 NULL NULL 0", "fix sp lv2 spring tether 50.0 0.02305 NULL NULL 0.0\n")
S("F10_spring_self_lv2_mid", "run 300; fix ss lv2 spring/self 50", "fix ss lv2 spring/self 50.0\n")
S("F11_momentum_lv2_mid", "run 300; fix mo lv2 momentum 1 linear 1 1 1 (lv2's momentum zeroed each step)", "fix mo lv2 momentum 1 linear 1 1 1\n")
S("F12_recenter_lv2_mid", "run 300; fix rc lv2 recenter INIT INIT INIT (lv2 put back each step)", "fix rc lv2 recenter INIT INIT INIT\n")
S("F13_gravity_lv2_x_mid", "run 300; fix g2 lv2 gravity 1000 vector -1 0 0 (lv2 pressed into lv1)", "fix g2 lv2 gravity 1000 vector -1 0 0\n")
S("F14_gravity_redefined_lv1_mid", "run 300; fix grav lv1 gravity 1000 vector 1 0 0 (the same ID on lv1, along the pair)", "fix grav lv1 gravity 1000 vector 1 0 0\n")
S("F15_integ_redefined_lv1_mid", "run 300; fix integ lv1 nve/sphere (the same ID and style on lv1 only: lv2 stops)", "fix integ lv1 nve/sphere\n")
S("F16_indent_mid", "run 300; fix ind all indent 1e4 sphere 0.0265 0.02 0.05 0.001 (pushes lv2)", "fix ind all indent 1e4 sphere 0.0265 0.02 0.05 0.001 units box\n")
S("F17_wall_region_harmonic_mid", "run 300; fix wr lv2 wall/region (x < 0.0262) harmonic 10 0 0.004 (lv2 pushed into lv1)",
  "region RW block INF 0.0262 INF INF INF INF units box\nfix wr lv2 wall/region RW harmonic 10.0 0.0 0.004\n")
L("F18_wall_region_lj93_start", "fix wr lv2 wall/region (x < 0.027) lj93 1e-3 1e-3 0.01 from the start (acts on lv2 in the contact)",
  "region RW block INF 0.027 INF INF INF INF units box\nfix wr lv2 wall/region RW lj93 1e-3 1e-3 0.01\nrun 3000\n")
S("F19_unfix_grav_refix_x", "run 300; unfix grav; fix grav all gravity 9.81 vector 0 0 -1 (the same again: control)", "unfix grav\nfix grav all gravity 9.81 vector 0 0 -1\n")
S("F20_setforce_x_only_lv1", "run 300; fix sf lv1 setforce 0 NULL NULL", "fix sf lv1 setforce 0.0 NULL NULL\n")
L("F21_setforce_region_start", "fix sf all setforce 0 0 0 region R (x > 0.0215: lv2's side) from the start",
  "region R block 0.0215 0.04 0 0.04 0 0.1 units box\nfix sf all setforce 0.0 0.0 0.0 region R\nrun 3000\n")
B("F22_addforce_before_meet", "run 50; fix af lv2 addforce -0.5 0 0; run 3000", "fix af lv2 addforce -0.5 0.0 0.0\n")
B("F23_viscous_before_meet", "run 50; fix vis lv2 viscous 0.05; run 3000", "fix vis lv2 viscous 0.05\n")
S("F24_move_wiggle_lv2_mid", "run 300; unfix integ; fix i1 lv1 nve/sphere; fix mv lv2 move wiggle 1e-4 0 0 1e-3", "unfix integ\nfix i1 lv1 nve/sphere\nfix mv lv2 move wiggle 1e-4 0 0 1e-3\n")

# ================================================================ R: groups redefined
S("R01_group_add_setforce", "fix sf gx setforce 0 0 0 on an empty group gx (id 5) from the start; run 300; group gx id 2 (lv2 now held)",
  "group gx id 2\n", pair=IN(0.1e-3) + "group gx id 5\nfix sf gx setforce 0.0 0.0 0.0\n")
S("R02_group_add_viscous", "fix vis gx viscous 0.05 on empty gx; run 300; group gx id 2", "group gx id 2\n", pair=IN(0.1e-3) + "group gx id 5\nfix vis gx viscous 0.05\n")
S("R03_group_clear_integrator", "integ on group gi (1 2); run 300; group gi clear; group gi id 1 (lv2 not integrated)",
  "group gi clear\ngroup gi id 1\n", pair=IN(0.1e-3) + "group gi id 1 2\nunfix integ\nfix integ gi nve/sphere\n")
S("R04_group_clear_freeze", "fix fz gf freeze on gf (lv2) from the start; run 300; group gf clear (lv2 free mid-contact)",
  "group gf clear\n", pair=IN(0.1e-3) + "group gf id 2\nfix fz gf freeze\n")
B("R05_group_add_addforce_before", "fix af gx addforce -0.5 0 0 on empty gx; run 50; group gx id 2", "group gx id 2\n", pair=IN(0.1e-3) + "group gx id 5\nfix af gx addforce -0.5 0.0 0.0\n")
S("R06_group_add_integrator_twice", "fix i2 gx nve/sphere on empty gx; run 300; group gx id 2 (lv2 integrated twice)", "group gx id 2\n", pair=IN(0.1e-3) + "group gx id 5\nfix i2 gx nve/sphere\n")
S("R07_group_subtract_noop", "run 300; group lv2 subtract all lv1 (lv2 the same: control)", "group lv2 subtract all lv1\n")
S("R08_group_add_gravity", "fix g2 gx gravity 1000 vector -1 0 0 on empty gx; run 300; group gx id 2", "group gx id 2\n", pair=IN(0.1e-3) + "group gx id 5\nfix g2 gx gravity 1000 vector -1 0 0\n")

# ================================================================ N: neighbor lists, timestep, comm, sort, balance, replicate
S("N01_exclude_type_mid", "run 300; neigh_modify exclude type 1 2 (the contact cut mid-way)", "neigh_modify exclude type 1 2\n")
B("N02_exclude_type_before", "run 50; neigh_modify exclude type 1 2 (no contact)", "neigh_modify exclude type 1 2\n")
B("N03_exclude_cleared_before", "exclude type 1 2 from the start; run 50; neigh_modify exclude none (control 0.413)", "neigh_modify exclude none\n",
  pair=IN(0.1e-3) + "neigh_modify exclude type 1 2\n")
S("N04_exclude_cleared_mid", "exclude type 1 2 from the start (passing through); run 300; exclude none (overlapped spheres)", "neigh_modify exclude none\n",
  pair=IN(0.1e-3) + "neigh_modify exclude type 1 2\n")
S("N05_exclude_group_mid", "run 300; neigh_modify exclude group lv1 lv2", "neigh_modify exclude group lv1 lv2\n")
S("N06_exclude_molecule_mid", "run 300; neigh_modify exclude molecule/intra all (no molecules: control)", "neigh_modify exclude molecule/intra all\n")
S("N07_neighbor_zero_mid", "run 300; neighbor 0 bin", "neighbor 0.0 bin\n")
S("N08_neigh_every_400_mid", "run 300; neigh_modify every 400 delay 0 check no", "neigh_modify every 400 delay 0 check no\n")
S("N09_timestep_2e6_mid", "run 300; timestep 2e-6", "timestep 2e-6\n")
S("N10_timestep_1e5_mid", "run 300; timestep 1e-5", "timestep 1e-5\n")
B("N11_timestep_4e6_before", "run 50; timestep 4e-6", "timestep 4e-6\n")
S("N12_timestep_1e5_and_back", "run 300; timestep 1e-5; run 10; timestep 1e-6", "timestep 1e-5\nrun 10\ntimestep 1e-6\n")
S("N13_reset_timestep_mid", "run 300; reset_timestep 0 (control)", "reset_timestep 0\n")
S("N14_reset_timestep_step_force", "fix af lv2 addforce v_f, f = -0.5*(step<400) from the start; run 300; reset_timestep 0 (400 more steps of force)",
  "reset_timestep 0\n", pair=IN(0.1e-3) + "variable f equal -0.5*(step<400)\nfix af lv2 addforce v_f 0.0 0.0\n")
S("N15_comm_vel_no_mid", "run 300; comm_modify vel no", "comm_modify vel no\n")
S("N16_atom_sort_mid", "run 300; atom_modify sort 1 0.001", "atom_modify sort 1 0.001\n")
S("N17_balance_mid", "run 300; balance 1.0 shift x 10 1.0", "balance 1.0 shift x 10 1.0\n")
S("N18_replicate_mid", "run 300; replicate 2 1 1 (the pair copied; the box doubled)", "replicate 2 1 1\n")
L("N19_replicate_start", "replicate 2 1 1 before any run (two pairs)", "replicate 2 1 1\nrun 3000\n")
S("N20_neigh_one_page_mid", "run 300; neigh_modify one 2000 page 100000 (control)", "neigh_modify one 2000 page 100000\n")
S("N21_reset_timestep_time", "fix af lv2 addforce v_f, f = -0.5*(time<4e-4); run 300; reset_timestep 0 time 0",
  "reset_timestep 0 time 0.0\n", pair=IN(0.1e-3) + "variable f equal -0.5*(time<4e-4)\nfix af lv2 addforce v_f 0.0 0.0\n")
S("N22_neighbor_big_skin_mid", "run 300; neighbor 0.01 bin (control)", "neighbor 0.01 bin\n")

# ================================================================ C: clear + restart
HEAD = "units si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\n"
FIX = "fix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\n"
L("C01_restart_roundtrip_mid", "run 300; write_restart r.bin; clear; read_restart r.bin; fixes again; run 2000 (control)",
  "run 300\nwrite_restart r.bin\nclear\nread_restart r.bin\ncomm_modify vel yes\n" + FIX + "run 2000\n", live="run 1 (and run 2)")
L("C02_restart_pc5_mid", "run 300; write_restart; clear; read_restart; pair_coeff 1 2 kn 5000; run 2000 (the law changes across clear)",
  "run 300\nwrite_restart r.bin\nclear\nread_restart r.bin\ncomm_modify vel yes\n" + FIX + PC5 + "run 2000\n", live="run 1 (and run 2)")
L("C03_restart_no_integrator", "run 300; write_restart; clear; read_restart; gravity only (no integrator); run 2000 (the atoms stay)",
  "run 300\nwrite_restart r.bin\nclear\nread_restart r.bin\ncomm_modify vel yes\nfix grav all gravity 9.81 vector 0 0 -1\ntimestep 1e-6\nrun 2000\n", live="run 1 (and run 2)")
L("C04_restart_dt_default", "run 300; write_restart; clear; read_restart; fixes, no timestep (the restart's dt?); run 2000",
  "run 300\nwrite_restart r.bin\nclear\nread_restart r.bin\ncomm_modify vel yes\nfix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\nrun 2000\n", live="run 1 (and run 2)")
L("C05_restart_older_state", "run 50 (before); write_restart r.bin; run 300 (mid); clear; read_restart r.bin (back to step 50); pc 5000; run 3000",
  "run 50\nwrite_restart r.bin\nrun 250\nclear\nread_restart r.bin\ncomm_modify vel yes\n" + FIX + PC5 + "run 3000\n", live="last run")
L("C06_restart_mid_restyle", "run 300; write_restart; clear; read_restart; pair_style granular; pc * * kn 5000; run 2000",
  "run 300\nwrite_restart r.bin\nclear\nread_restart r.bin\ncomm_modify vel yes\n" + FIX + "pair_style granular\npair_coeff * * " + HKk(5000) + "\nrun 2000\n", live="run 1 (and run 2)")
L("C07_clear_new_deck_pc5", "run 300; clear; the whole deck again with kn 5000; run 3000 (a new contact)",
  "run 300\nclear\n" + BASE(wall=False, coeff="pair_coeff * * " + HKk(5000) + "\n") + IN(0.1e-3) + "run 3000\n", live="last run")
L("C08_restart_file_given", "read_restart of a file the deck wrote in an earlier run of the same deck? no: write_restart every 300 (fix-less: restart 300 r.*); run 2300; clear; read_restart r.300; pc 5000; run 2000",
  "restart 300 r.*\nrun 2300\nrestart 0\nclear\nread_restart r.300\ncomm_modify vel yes\n" + FIX + PC5 + "run 2000\n", live="last run")
L("C09_restart_dt_changed", "run 300; write_restart; clear; read_restart; fixes; timestep 1e-5; run 2000",
  "run 300\nwrite_restart r.bin\nclear\nread_restart r.bin\ncomm_modify vel yes\nfix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-5\nrun 2000\n", live="run 1 (and run 2)")
L("C10_write_data_read_data", "run 300; write_data d.txt; clear; read_data d.txt (velocities kept); run 2000 (control)",
  "run 300\nwrite_data d.txt\nclear\n" + HEAD + "read_data d.txt\ngroup lv1 id 1\ngroup lv2 id 2\npair_style granular\npair_coeff * * " + HK + "\n" + FIX + "run 2000\n", live="run 1 (and run 2)")
L("C11_write_data_nocoeff_pc5", "run 300; write_data d.txt nocoeff; clear; read_data; kn 5000; run 2000",
  "run 300\nwrite_data d.txt nocoeff\nclear\n" + HEAD + "read_data d.txt\ngroup lv1 id 1\ngroup lv2 id 2\npair_style granular\npair_coeff * * " + HKk(5000) + "\n" + FIX + "run 2000\n", live="run 1 (and run 2)")

# ================================================================ W: walls
SW("W01_second_floor_mid", "run 300; fix floor2 all wall/gran ... zplane 0 (a second floor at the same plane: twice the force)", FLOOR(2000).replace("fix floor", "fix floor2") + "\n")
L("W02_second_floor_start", "WALL: two identical floors at zplane 0 from the start", FLOOR(2000).replace("fix floor", "fix floor2") + "\nrun 3000\n",
  pre=BASE(), pair=WALLP(), **WALL)
SW("W03_floor_shear_mid", "run 300; floor redefined with shear x 0.1", FLOOR(2000) + " shear x 0.1\n")
L("W04_floor_wiggle_start", "WALL: the floor with wiggle z 1e-4 0.001 from the start", "unfix floor\n" + FLOOR(2000) + " wiggle z 1e-4 0.001\nrun 3000\n",
  pre=BASE(), pair=WALLP(), **WALL)
L("W05_floor_shear_start", "WALL: the floor with shear x 0.1 from the start", "unfix floor\n" + FLOOR(2000) + " shear x 0.1\nrun 3000\n",
  pre=BASE(), pair=WALLP(), **WALL)
SW("W06_second_floor_region_mid", "run 300; a wall/gran/region on a plane at z 0 added (second floor)",
   "region fl plane 0 0 0 0 0 1 units box\nfix floor2 all wall/gran/region granular " + HK + " region fl\n")
SW("W07_floor_zplane_lo_only", "run 300; a second floor fix at zplane NULL 0.09 (the ceiling only: control)", FLOOR(2000, "NULL").replace("zplane NULL NULL", "zplane NULL 0.09").replace("fix floor", "fix ceil") + "\n")
SW("W08_setforce_z_on_sphere_mid", "run 300; fix sf lv1 setforce NULL NULL 0 (the floor sphere's z force zeroed)", "fix sf lv1 setforce NULL NULL 0.0\n")
SW("W09_viscous_floor_sphere_mid", "run 300; fix vis lv1 viscous 0.01", "fix vis lv1 viscous 0.01\n")
SW("W10_group_add_freeze_floor", "fix fz gx freeze on empty gx; run 300; group gx id 1 (the floor sphere frozen mid-contact)", "group gx id 1\n",
   pre=BASE() + "group gx id 5\nfix fz gx freeze\n")
SW("W11_timestep_mid", "run 300; timestep 2e-6", "timestep 2e-6\n")
SW("W12_lj93_floor_mid", "run 300; fix wl all wall/lj93 zlo 0.0 1e-3 1e-3 0.005 (a second wall law at the floor)", "fix wl all wall/lj93 zlo 0.0 1e-3 1e-3 0.005 units box\n")

# ================================================================ E: every, include, jump, if
EVS = lambda name, desc, cmd, **kw: L(name, desc, f"run 2300 every 300 \"{cmd}\"\n", live="part 1", **kw)
EVS("E01_every_setforce", "run 2300 every 300 \"fix sf lv2 setforce 0 0 0\"", "fix sf lv2 setforce 0.0 0.0 0.0")
EVS("E02_every_group_add", "fix sf gx setforce on empty gx; run 2300 every 300 \"group gx id 2\"", "group gx id 2", pair=IN(0.1e-3) + "group gx id 5\nfix sf gx setforce 0.0 0.0 0.0\n")
EVS("E03_every_timestep", "run 2300 every 300 \"timestep 2e-6\"", "timestep 2e-6")
EVS("E04_every_exclude", "run 2300 every 300 \"neigh_modify exclude type 1 2\"", "neigh_modify exclude type 1 2")
EVS("E05_every_freeze", "run 2300 every 300 \"fix fz lv2 freeze\"", "fix fz lv2 freeze")
EVS("E06_every_addforce", "run 2300 every 300 \"fix af lv2 addforce -0.5 0 0\"", "fix af lv2 addforce -0.5 0.0 0.0")
EVS("E07_every_replicate_like_sort", "run 2300 every 300 \"atom_modify sort 1 0.001\" (control)", "atom_modify sort 1 0.001")
EVS("E08_every_move", "run 2300 every 300 \"fix mv lv2 move linear 0 0 0\"", "fix mv lv2 move linear 0 0 0")
EVS("E09_every_integ_lv1", "run 2300 every 300 \"fix integ lv1 nve/sphere\"", "fix integ lv1 nve/sphere")
S("E10_include_setforce", "run 300; include f.in (fix sf lv2 setforce 0 0 0)", "include f.in\n", data={"f.in": "fix sf lv2 setforce 0.0 0.0 0.0\n"})
S("E11_include_group_add", "fix sf on empty gx; run 300; include f.in (group gx id 2)", "include f.in\n", pair=IN(0.1e-3) + "group gx id 5\nfix sf gx setforce 0.0 0.0 0.0\n",
  data={"f.in": "group gx id 2\n"})
L("E12_loop_addforce", "i loop 5: run 100; fix af lv2 addforce -0.1*i 0 0 (redefined each pass mid-contact); run 2000",
  "variable i loop 5\nlabel lp\nrun 100\nfix af lv2 addforce $(-0.1*v_i) 0.0 0.0\nnext i\njump SELF lp\nrun 2000\n", live="pass 2 (and on)")
L("E13_loop_if_viscous", "i loop 5: run 100; if i == 3 then fix vis lv2 viscous 0.05", "variable i loop 5\nlabel lp\nrun 100\nif \"${i} == 3\" then \"fix vis lv2 viscous 0.05\"\nnext i\njump SELF lp\nrun 2000\n",
  live="pass 2 (and on)")
L("E14_loop_timestep", "i loop 5: run 100; timestep 1e-6*(1+i%2) (alternating)", "variable i loop 5\nlabel lp\nrun 100\ntimestep $(1e-6*(1+v_i%2))\nnext i\njump SELF lp\nrun 2000\n",
  live="pass 2 (and on)")
S("E15_if_place_group_add", "fix sf on empty gx; run 300; if x(lv1) > 0.0181 then group gx id 2", m41.IFX(["group gx id 2"]), pair=IN(0.1e-3) + "group gx id 5\nfix sf gx setforce 0.0 0.0 0.0\n")
S("E16_if_place_exclude", "run 300; if x(lv1) > 0.0181 then neigh_modify exclude type 1 2", m41.IFX(["neigh_modify exclude type 1 2"]))
L("E17_every_include", "run 2300 every 300 \"include f.in\" (f.in: fix sf lv2 setforce 0 0 0)", "run 2300 every 300 \"include f.in\"\n", live="part 1",
  data={"f.in": "fix sf lv2 setforce 0.0 0.0 0.0\n"})
L("E18_fix_halt_then_freeze", "fix halt at x(lv1) > 0.0181; unfix halt; fix fz lv2 freeze; run 2000",
  "variable hx equal xcm(lv1,x)\nfix ht all halt 10 v_hx > 0.0181 error continue\nrun 3000\nunfix ht\nfix fz lv2 freeze\nrun 2000\n", live="run 1 (and run 2)")

# ================================================================ G: LIGGGHTS
LGR = "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.8 0.7 0.8 0.4 0.45 0.7 0.45 0.8"
LG("G01_lig_every_prop_e", "LIGGGHTS run 2300 every 300 \"property/global e 0.8\" (mid-contact)", f"run 2300 every 300 \"{LGR}\"\n", live="part 1")
SG("G02_lig_freeze_mid", "run 300; fix fz lv2 freeze", "fix fz lv2 freeze\n")
SG("G03_lig_setforce_mid", "run 300; fix sf lv2 setforce 0 0 0", "fix sf lv2 setforce 0.0 0.0 0.0\n")
SG("G04_lig_viscous_mid", "run 300; fix vis lv2 viscous 0.05", "fix vis lv2 viscous 0.05\n")
SG("G05_lig_timestep_mid", "run 300; timestep 2e-6", "timestep 2e-6\n")
SG("G06_lig_exclude_mid", "run 300; neigh_modify exclude type 1 2", "neigh_modify exclude type 1 2\n")
SG("G07_lig_addforce_mid", "run 300; fix af lv2 addforce -0.5 0 0", "fix af lv2 addforce -0.5 0.0 0.0\n")
SG("G08_lig_group_add_freeze", "fix fz gx freeze on empty gx; run 300; group gx id 2", "group gx id 2\n", pair=LIN(0.1e-3) + "group gx id 5\nfix fz gx freeze\n")
SG("G09_lig_integ_lv1_mid", "run 300; unfix integr; fix integr lv1 nve/sphere", "unfix integr\nfix integr lv1 nve/sphere\n")
LWP = "fix wprim2 all wall/gran model hertz tangential history primitive type 3 zplane 0.0\n"
LG("G10_lig_two_floors_start", "LIGGGHTS WALL: two primitive floors at zplane 0 from the start", LWP + "run 3000\n",
   pre=m41.LBASE(), pair=m41.LWALL(1e-4), PAIR="type 1 on wall wprim", LWALLZ="1")
LG("G11_lig_second_floor_mid", "LIGGGHTS WALL: run 300; a second primitive floor at zplane 0", "run 300\n" + LWP + "run 2000\n",
   pre=m41.LBASE(), pair=m41.LWALL(1e-4), live="run 1 (and run 2)", PAIR="type 1 on wall wprim", LWALLZ="1")
LG("G12_lig_floor_shear_mid", "LIGGGHTS WALL: run 300; the floor redefined with shear x 0.1",
   "run 300\nfix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0 shear x 0.1\nrun 2000\n",
   pre=m41.LBASE(), pair=m41.LWALL(1e-4), live="run 1 (and run 2)", PAIR="type 1 on wall wprim", LWALLZ="1")
LG("G13_lig_floor_e_every", "LIGGGHTS WALL: run 2300 every 300 \"e 1 3 0.3\" (mid-contact)", "run 2300 every 300 \"fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.3 0.5 0.4 0.45 0.3 0.45 0.8\"\n",
   pre=m41.LBASE(), pair=m41.LWALL(1e-4), live="part 1", PAIR="type 1 on wall wprim", LWALLZ="1")
SG("G14_lig_young_mid", "run 300; youngsModulus 5e7 (mid-contact; a new stage)", "fix m1 all property/global youngsModulus peratomtype 5e7 5e7 5e7\n")
SG("G15_lig_momentum_mid", "run 300; fix mo lv2 momentum 1 linear 1 1 1", "fix mo lv2 momentum 1 linear 1 1 1\n")

# ================================================================ K: a second set (fixes within a run, more forces)
S("K01_lineforce_lv2_mid", "run 300; fix lf lv2 lineforce 0 1 0 (lv2 keeps only y forces)", "fix lf lv2 lineforce 0.0 1.0 0.0\n")
S("K02_planeforce_lv2_mid", "run 300; fix pf lv2 planeforce 1 0 0 (control: x kept)", "fix pf lv2 planeforce 1.0 0.0 0.0\n")
S("K03_spring_couple_mid", "run 300; fix sc lv1 spring couple lv2 100 0.005 NULL NULL 0 (the pair pulled together)", "fix sc lv1 spring couple lv2 100.0 0.005 NULL NULL 0.0\n")
S("K04_restrain_bond_mid", "run 300; fix rs all restrain bond 1 2 100 100 0.006 (a spring between the pair)", "fix rs all restrain bond 1 2 100.0 100.0 0.006\n")
L("K05_restrain_bond_start", "fix rs all restrain bond 1 2 100 100 0.006 from the start", "fix rs all restrain bond 1 2 100.0 100.0 0.006\nrun 3000\n")
L("K06_gravity_variable_step", "fix g2 lv2 gravity v_g vector -1 0 0, g = 1000*(step>300) (on lv2 from step 300, one run)",
  "variable g equal 1000*(step>300)\nfix g2 lv2 gravity v_g vector -1 0 0\nrun 3000\n")
L("W13_floor_gravity_variable_step", "WALL: gravity v_g, g = 9.81 + 5e3*(step>300) (the floor sphere pressed mid-contact, one run)",
  "unfix grav\nvariable g equal 9.81+5000*(step>300)\nfix grav all gravity v_g vector 0 0 -1\nrun 3000\n", pre=BASE(), pair=WALLP(), **WALL)
L("K07_setforce_variable_step", "fix sf lv2 setforce v_s NULL NULL, s = 0 when step>300 else NULL? (atom-style: 0 from step 300)",
  "variable s atom 0.0*(step>300)+fx*(step<=300)\nfix sf lv2 setforce v_s NULL NULL\nrun 3000\n")
L("K08_viscous_every_run_start", "fix vis lv2 viscous 0.05 from the start, fix print unrelated (control of a named fix from the start)", "fix vis lv2 viscous 0.05\nrun 3000\n")
L("K09_addforce_every_100", "fix af lv2 addforce -0.5 0 0 every 100 (applied one step in 100)", "fix af lv2 addforce -0.5 0.0 0.0 every 100\nrun 3000\n")
S("K10_nve_sphere_to_nve_lv2", "run 300; unfix integ; fix i1 lv1 nve/sphere; fix i2 lv2 nve (control: head-on)", "unfix integ\nfix i1 lv1 nve/sphere\nfix i2 lv2 nve\n")
S("K11_pair_hybrid_overlay_soft_mid", "run 300; pair_style hybrid/overlay granular soft 0.01; granular coeffs; soft 1 2 A 100",
  "pair_style hybrid/overlay granular soft 0.01\npair_coeff * * granular " + HK + "\npair_coeff * * soft 0.0\npair_coeff 1 2 soft 100.0\n")
L("K12_soft_overlay_start", "pair_style hybrid/overlay granular soft 0.01 from the start, soft 1 2 A 100 (a soft push between the pair)",
  "pair_style hybrid/overlay granular soft 0.01\npair_coeff * * granular " + HK + "\npair_coeff * * soft 0.0\npair_coeff 1 2 soft 100.0\nrun 3000\n")
LINS = ("fix pts9 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\n"
        "fix pdd9 all particledistribution/discrete 32452843 1 pts9 1.0\n"
        "region nb block 0.00739 0.00741 -1e-5 1e-5 0.09999 0.10001 units box\n"
        "fix ins all insert/pack seed 49979687 distributiontemplate pdd9 vel constant 0 0 0 insert_every once overlapcheck no all_in no particles_in_region 1 region nb\n")
SG("G16_lig_insert_at_lv2_mid", "run 300; insert/pack one 4 mm sphere at x 0.0074 (overlapping lv2's far side ~0.1 mm)", LINS)
SG("G17_lig_insert_far_mid", "run 300; insert/pack one 4 mm sphere far off (control)", LINS.replace("0.00739 0.00741", "0.03999 0.04001"))
SG("G18_lig_group_clear_integ", "integr on gi (1 2); run 300; group gi clear; group gi id 1 (lv2 not integrated)", "group gi clear\ngroup gi id 1\n",
   pair=LIN(0.1e-3) + "group gi id 1 2\nunfix integr\nfix integr gi nve/sphere\n")
BG("G19_lig_exclude_before", "run 50; neigh_modify exclude type 1 2 (no contact)", "neigh_modify exclude type 1 2\n")
SG("G20_lig_lineforce_mid", "run 300; fix lf lv2 lineforce 0 1 0", "fix lf lv2 lineforce 0.0 1.0 0.0\n")
LG("G21_lig_gravity_variable_lv2", "LIGGGHTS: fix g2 lv2 gravity v_g vector -1 0 0, g = 1000*(step>300) (one run)",
   "variable g equal 1000*(step>300)\nfix g2 lv2 gravity v_g vector -1 0 0\nrun 3000\n")

# ================================================================ a third set: exclusions lifted while overlapping, restart with a cutoff
S("N23_exclude_group_cleared_mid", "exclude group lv1 lv2 from the start; run 300; neigh_modify exclude none (overlapping 0.2 mm)", "neigh_modify exclude none\n",
  pair=IN(0.1e-3) + "neigh_modify exclude group lv1 lv2\n")
S("N24_exclude_cleared_mid_pc5", "exclude type 1 2 from the start; run 300; exclude none; pc 1 2 kn 5000", "neigh_modify exclude none\n" + PC5,
  pair=IN(0.1e-3) + "neigh_modify exclude type 1 2\n")
L("N25_exclude_cleared_250", "exclude type 1 2 from the start; run 250; exclude none; run 2000 (overlap 0.15 mm)", "run 250\nneigh_modify exclude none\nrun 2000\n",
  pair=IN(0.1e-3) + "neigh_modify exclude type 1 2\n", live="run 1 (and run 2)")
SG("G22_lig_exclude_cleared_mid", "exclude type 1 2 from the start; run 300; neigh_modify exclude none", "neigh_modify exclude none\n",
   pair=LIN(0.1e-3) + "neigh_modify exclude type 1 2\n")
L("C12_restart_cutoff_pc5_mid", "C02 with pair_style granular's cutoff given again (comm_modify cutoff 0.01) after read_restart: pc 1 2 kn 5000",
  "run 300\nwrite_restart r.bin\nclear\nread_restart r.bin\ncomm_modify vel yes cutoff 0.01\n" + FIX + PC5 + "run 2000\n", live="run 1 (and run 2)")
L("C13_restart_pc5_before", "run 50; write_restart; clear; read_restart; pc 1 2 kn 5000; run 3000 (before the meeting: 0.579)",
  "run 50\nwrite_restart r.bin\nclear\nread_restart r.bin\ncomm_modify vel yes\n" + FIX + PC5 + "run 3000\n", live="last run")
L("C14_restart_pc12_same_mid", "run 300; write_restart; clear; read_restart; pc 1 2 kn 2000 again (the same law: control)",
  "run 300\nwrite_restart r.bin\nclear\nread_restart r.bin\ncomm_modify vel yes\n" + FIX + PCs(2000) + "\nrun 2000\n", live="run 1 (and run 2)")
L("C15_restart_set_density_mid", "run 300; write_restart; clear; read_restart; set atom 2 density 5000; run 2000",
  "run 300\nwrite_restart r.bin\nclear\nread_restart r.bin\ncomm_modify vel yes\n" + FIX + "set atom 2 density 5000\nrun 2000\n", live="run 1 (and run 2)")

# ================================================================ a fourth set: the whole contact at a coarse time step between fine ones
L("N26_dt_coarse_contact_only", "run 50; timestep 1e-4; run 12 (1.2 ms: the whole contact, ~6 steps); timestep 1e-6; run 2000",
  "run 50\ntimestep 1e-4\nrun 12\ntimestep 1e-6\nrun 2000\n", live="run 2")
L("N27_dt_5e5_contact_only", "run 50; timestep 5e-5; run 24; timestep 1e-6; run 2000", "run 50\ntimestep 5e-5\nrun 24\ntimestep 1e-6\nrun 2000\n", live="run 2")
L("N28_dt_coarse_wall_contact_only", "WALL: run 50; timestep 1e-4; run 12; timestep 1e-6; run 2000", "run 50\ntimestep 1e-4\nrun 12\ntimestep 1e-6\nrun 2000\n",
  pre=BASE(), pair=WALLP(), live="run 2", **WALL)
L("N29_dt_coarse_contact_pc5_last", "run 50; timestep 1e-4; run 12; timestep 1e-6; pc 5000; run 2000 (a law change too)",
  "run 50\ntimestep 1e-4\nrun 12\ntimestep 1e-6\n" + PC5 + "run 2000\n", live="run 2")
LG("G23_lig_dt_coarse_contact_only", "LIGGGHTS: run 50; timestep 1e-4; run 12; timestep 1e-6; run 2000", "run 50\ntimestep 1e-4\nrun 12\ntimestep 1e-6\nrun 2000\n", live="run 2")

# ================================================================ a fifth set: a fix on a group made before any atom exists, which a group command fills mid-contact
RBG = lambda fx: BASE(wall=False) + "group gx id 5\n" + fx
S("R09_group_before_atoms_setforce", "group gx id 5 and fix sf gx setforce 0 0 0 before the atoms; run 300; group gx id 2", "group gx id 2\n",
  pre=RBG("fix sf gx setforce 0.0 0.0 0.0\n"))
S("R10_group_before_atoms_freeze", "group gx before the atoms, fix fz gx freeze; run 300; group gx id 2", "group gx id 2\n", pre=RBG("fix fz gx freeze\n"))
S("R11_group_before_atoms_viscous", "group gx before the atoms, fix vis gx viscous 0.05; run 300; group gx id 2", "group gx id 2\n", pre=RBG("fix vis gx viscous 0.05\n"))
S("R12_group_before_atoms_addforce", "group gx before the atoms, fix af gx addforce -0.5 0 0; run 300; group gx id 2", "group gx id 2\n", pre=RBG("fix af gx addforce -0.5 0.0 0.0\n"))
B("R13_group_before_atoms_viscous_before_meet", "group gx before the atoms, fix vis gx viscous 0.05; run 50; group gx id 2 (before the meeting)", "group gx id 2\n",
  pre=RBG("fix vis gx viscous 0.05\n"))
L("R14_group_before_atoms_never_filled", "group gx before the atoms, fix vis gx viscous 0.05, never filled (control 0.413)", "run 3000\n", pre=RBG("fix vis gx viscous 0.05\n"))
SW("W14_group_before_atoms_viscous_floor", "group gx before the atoms, fix vis gx viscous 0.01; run 300; group gx id 1", "group gx id 1\n",
   pre=BASE() + "group gx id 5\nfix vis gx viscous 0.01\n")
SG("G24_lig_group_before_atoms_freeze", "group gx before the atoms, fix fz gx freeze; run 300; group gx id 2", "group gx id 2\n",
   pre=m41.LBASE() + "group gx id 5\nfix fz gx freeze\n")

# ================================================================ a sixth set: the group-filled and exclusion-lifted classes' reach
S("R15_group_empty_kw_setforce", "group gx empty (the keyword) and fix sf gx setforce before the atoms; run 300; group gx id 2", "group gx id 2\n",
  pre=BASE(wall=False) + "group gx empty\nfix sf gx setforce 0.0 0.0 0.0\n")
S("R16_group_type_before_atoms_setforce", "group gx type 2 before the atoms (empty then), fix sf gx setforce; run 300; group gx type 2", "group gx type 2\n",
  pre=BASE(wall=False) + "group gx type 2\nfix sf gx setforce 0.0 0.0 0.0\n")
S("R17_group_empty_after_atoms_setforce", "group gx empty after the atoms, fix sf gx setforce; run 300; group gx id 2", "group gx id 2\n",
  pair=IN(0.1e-3) + "group gx empty\nfix sf gx setforce 0.0 0.0 0.0\n")
L("E19_every_exclude_none", "exclude type 1 2 from the start; run 2300 every 300 \"neigh_modify exclude none\" (lifted at step 300, overlapping)",
  "run 2300 every 300 \"neigh_modify exclude none\"\n", pair=IN(0.1e-3) + "neigh_modify exclude type 1 2\n", live="part 1")

# ================================================================ a seventh set: a law change into a stage held back for another reason
S("H01_pc5_with_move_null_mid", "run 300; pc 1 2 kn 5000; unfix integ; fix i1 lv1 nve/sphere; fix mv lv2 move linear NULL NULL NULL (F02: the same motion)",
  PC5 + "unfix integ\nfix i1 lv1 nve/sphere\nfix mv lv2 move linear NULL NULL NULL\n")
S("H02_pc5_with_nve_lv2_mid", "run 300; pc 1 2 kn 5000; unfix integ; fix i1 lv1 nve/sphere; fix i2 lv2 nve (K10: head-on, the same)",
  PC5 + "unfix integ\nfix i1 lv1 nve/sphere\nfix i2 lv2 nve\n")
S("H03_pc5_control_mid", "run 300; pc 1 2 kn 5000 (control: the law note)", PC5)

NP2 = []
if __name__ == "__main__":
    names = sys.argv[1:]
    m7.big = lambda *a, **k: None          # round 37's extra files for its own F20 F21 R07 ... (not ours)
    m7.lmp_gen = lambda *a, **k: None
    m7.write(names)
    for n in m7.DECKS:
        if not names or any(n.startswith(p) for p in names):
            open(os.path.join(m7.D, n, "NP"), "w").write("1 2\n" if any(n.startswith(p) for p in NP2) else "1\n")

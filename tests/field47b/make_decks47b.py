"""Field round 47b ("hidden decks on new ground, LAMMPS side", main eeb2e539): write decks/NAME/ (in.deck and the files
it reads) for the referee (round 37's live37.py: each deck AS WRITTEN, its live pair's eps printed after its last
line) and then the audit. Base lines are round 46's (make_decks46: LAMMPS hooke kn 2000 kt 3000 mass_velocity, the
pair 4 mm / 6 mm at 1 m/s, meeting at step 100, ~586 steps per contact: 0.413435; the floor 0.361743; LIGGGHTS hertz
e 0.5). Families (new ground against rounds 43-46):
- N: neighbour exclusions (type, group, molecule intra/inter with fix property/atom mol, mol 0 for all), exclusion
  made moot by a later `set type`, newton off, no `comm_modify vel yes`, atom_modify map/sort;
- B: box and placement: the pair meeting through a periodic boundary, brought there by change_box, displace_atoms
  (box and lattice units, rotate), delete_atoms overlap/region/group compress, fix deform along and across the pair,
  fix evaporate taking a sphere of the pair;
- F: fixes on one sphere of the pair or both: fix move (linear, NULL, wiggle, variable), nve/noforce, lineforce and
  planeforce across the contact, aveforce over both, spring tether, temp/berendsen, nvt/sphere, recenter, addtorque;
- U: unit styles (lj, real, metal, micro, nano, electron) and dimension 2 (density, density/disc, nve/sphere disc);
- R: run forms (upto after reset_timestep, start/stop, pre/post no, timestep changed between runs, write_restart +
  clear + read_restart, write_data + clear + read_data, print ... file of a pair_coeff with a variable later changed);
- Y: bonds and pair hybrids (atom_style hybrid sphere bond with a bond on a sphere of the pair or elsewhere,
  hybrid granular + `none` on the pair's types);
- G: gravity forms on a floor drop (spherical, chute, a vector not of unit length, upward, `disable`, two fixes);
- E: the shapes of two LAMMPS examples outside examples/granular (multi/in.granular: 2d lj hooke 1.0 0.5, triclinic,
  neighbor multi, deform xy, nph/sphere; rigid/in.rigid.gravity: gran/hooke/history with a hooke/history floor and
  gravity `disable`), written anew here around a head-on pair (SOURCES);
- L: LIGGGHTS with the same constructs.
usage: python make_decks47b.py [NAME-PREFIX ...]"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field46"))
import make_decks46 as m46  # noqa: E402

D = os.path.join(HERE, "decks")
DECKS = {}
RB, IN, HK, HZM, FLOORP, LBASE, LIN, LFLOOR, VZ, H0 = m46.RB, m46.IN, m46.HK, m46.HZM, m46.FLOORP, m46.LBASE, m46.LIN, m46.LFLOOR, m46.VZ, m46.H0
FLOOR = {"PAIR": "type 1 on wall floor"}
PC = lambda spec, law: f"pair_coeff {spec} {law}\n"


def L(name, desc, body="run 3000\n", pre=None, pair=None, live="last run", data=None, **meta):
    pre = RB() if pre is None else pre
    pair = IN() if pair is None else pair
    DECKS[name] = ("# " + desc + "\n" + pre + pair + body, live, data or {}, meta)


def LG(name, desc, body="run 3000\n", pre=None, pair=None, live="last run", data=None, **meta):
    pre = LBASE() if pre is None else pre
    pair = LIN if pair is None else pair
    meta.setdefault("LIGGGHTS", "")
    DECKS[name] = ("# LIGGGHTS: " + desc + "\n" + pre + pair + body, live, data or {}, meta)


MOL = lambda: RB(mid="fix pm all property/atom mol ghost yes\n")
WALLB = lambda wl, coeff="pair_coeff * * " + HK + "\n": RB(coeff=coeff).replace("fix integ", wl + "fix integ")
FLOORW = "fix floor all wall/gran granular " + HK + " zplane 0 NULL\n"

# ================================================================ N: exclusions, newton, comm
L("N01_exclude_type_12", "neigh_modify exclude type 1 2 (the pair's types: no contact in LAMMPS)", pre=RB() + "neigh_modify exclude type 1 2\n")
L("N02_exclude_group_lv1_lv2", "neigh_modify exclude group lv1 lv2 after the groups (no contact)", pair=IN() + "neigh_modify exclude group lv1 lv2\n")
L("N03_exclude_molintra_same_mol", "fix property/atom mol; set both spheres mol 7; neigh_modify exclude molecule/intra all (no contact)",
  pre=MOL(), pair=IN() + "set atom 1*2 mol 7\nneigh_modify exclude molecule/intra all\n")
L("N04_exclude_molinter_two_mols", "property/atom mol; mols 1 and 2; exclude molecule/inter all (no contact)",
  pre=MOL(), pair=IN() + "set atom 1 mol 1\nset atom 2 mol 2\nneigh_modify exclude molecule/inter all\n")
L("N05_exclude_molintra_two_mols", "property/atom mol; mols 1 and 2; exclude molecule/intra all (control: they touch)",
  pre=MOL(), pair=IN() + "set atom 1 mol 1\nset atom 2 mol 2\nneigh_modify exclude molecule/intra all\n")
L("N06_exclude_type_11_only", "neigh_modify exclude type 1 1 (not the pair: control)", pre=RB() + "neigh_modify exclude type 1 1\n")
L("N07_exclude_molintra_mol0", "property/atom mol, no mol set (both 0); exclude molecule/intra all (same molecule 0: excluded?)",
  pre=MOL(), pair=IN() + "neigh_modify exclude molecule/intra all\n")
L("N08_exclude_then_set_type", "exclude type 1 2; then set atom 2 type 1 (the pair is 1 1, not excluded; pair_coeff 1 1 kn 5000)",
  pre=RB(coeff=PC("* *", HK) + PC("1 1", HK.replace("2000", "5000"))) + "neigh_modify exclude type 1 2\n", pair=IN() + "set atom 2 type 1\n", PAIR="types 1 1")
L("N09_newton_off", "newton off", pre=RB(head="newton off\n"))
L("N10_no_comm_vel", "comm_modify vel yes left out (LAMMPS: granular needs ghost velocities)", pre=RB().replace("comm_modify vel yes\n", ""))
L("N11_atom_modify_map_hash_sort0", "atom_modify map hash sort 0 0.0 (before the box)", pre=RB(head="atom_modify map hash sort 0 0.0\n"))
L("N12_exclude_molinter_mol0_vs_1", "property/atom mol; lv2 mol 3, lv1 stays 0; exclude molecule/inter all (different molecules: excluded?)",
  pre=MOL(), pair=IN() + "set atom 2 mol 3\nneigh_modify exclude molecule/inter all\n")
L("N13_exclude_type_by_label", "labelmap atom 1 sm 2 bg; neigh_modify exclude type sm bg (no contact)", pre=RB(mid="labelmap atom 1 sm 2 bg\n") + "neigh_modify exclude type sm bg\n")
L("N14_exclude_group_before_atoms", "group gl type 1 made before the atoms (a static group: stays empty); exclude group gl all (control: they touch)",
  pre=RB() + "group gl type 1\nneigh_modify exclude group gl all\n")
L("N15_exclude_type_then_none_before", "exclude type 1 2; neigh_modify exclude none (control)", pre=RB() + "neigh_modify exclude type 1 2\nneigh_modify exclude none\n")

# ================================================================ B: box and placement
PERIO = ("create_atoms 1 single 0.037900 0.02 0.05\ncreate_atoms 2 single 0.003000 0.02 0.05\n"
         "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
         "velocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\n")
L("B01_periodic_meet_through_x", "the pair meets through the periodic x boundary (lv1 at x 0.0379 going +x, lv2 at 0.003 going -x)", pair=PERIO, SEP="-0.0349")
L("B02_change_box_shrink_to_meet", "box 0..0.06; the pair 25 mm apart through x; change_box all x final 0 0.04 units box (no remap): 0.1 mm apart through x",
  pre=RB(box="region box block 0 0.06 0 0.04 0 0.1 units box\n"), pair=PERIO + "change_box all x final 0 0.04 units box\n", SEP="-0.0349")
L("B03_change_box_remap_bigger", "change_box all x final 0 0.05 remap units box (the pair scaled apart: 1.4 mm gap, meets later)", pair=IN() + "change_box all x final 0 0.05 remap units box\n")
L("B04_change_box_boundary_f", "change_box all boundary f p f (x fixed; the pair inside; control)", pair=IN() + "change_box all boundary f p f\n")
L("B05_displace_box_into_place", "lv2 made 10 mm further; displace_atoms lv2 move -0.01 0 0 units box",
  pair=IN().replace("create_atoms 2 single 0.023050", "create_atoms 2 single 0.033050"))
DECKS["B05_displace_box_into_place"] = (DECKS["B05_displace_box_into_place"][0].replace("run 3000\n", "displace_atoms lv2 move -0.01 0 0 units box\nrun 3000\n"),) + DECKS["B05_displace_box_into_place"][1:]
L("B06_displace_lattice_units", "lattice sc 0.02; lv1 made 10 mm back; displace_atoms lv1 move 0.5 0 0 (lattice units: 10 mm)",
  pair=IN().replace("create_atoms 1 single 0.017950", "create_atoms 1 single 0.007950") + "lattice sc 0.02\ndisplace_atoms lv1 move 0.5 0 0\n")
L("B07_displace_rotate_90", "displace_atoms all rotate about the pair's middle, axis z, 90 deg: the pair side by side in y, velocities still along x (no contact)",
  pair=IN() + "displace_atoms all rotate 0.0205 0.02 0.05 0 0 1 90 units box\n")
L("B08_delete_overlap_pair", "delete_atoms overlap 0.006 all all (the pair's centres 5.1 mm apart: one of them deleted, no contact)", pair=IN() + "delete_atoms overlap 0.006 all all\n")
L("B09_delete_region_lv2", "delete_atoms region around lv2 (lv1 alone, no contact)", pair=IN() + "region rdel sphere 0.02305 0.02 0.05 0.001 units box\ndelete_atoms region rdel\n")
L("B10_delete_overlap_small", "delete_atoms overlap 0.001 all all (nothing deleted: control)", pair=IN() + "delete_atoms overlap 0.001 all all\n")
PAIR3 = lambda far: (far + "create_atoms 1 single 0.017950 0.02 0.05\ncreate_atoms 2 single 0.023050 0.02 0.05\n"
         "set atom 2 diameter 0.004 density 2500\nset atom 3 diameter 0.006 density 2500\ngroup lv1 id 2\ngroup lv2 id 3\n"
         "velocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\n")
L("B11_delete_group_compress", "a third far sphere id 1 (type 2) deleted with compress yes: the pair renumbered 1 2",
  pair=PAIR3("create_atoms 2 single 0.01 0.01 0.09\nset atom 1 diameter 0.006 density 2500\n") + "group far id 1\ndelete_atoms group far compress yes\n")
L("B12_deform_x_along_pair", "fix deform 1 x final 0 0.03 remap x during the run (affine approach along the pair)", pair=IN() + "fix dfm all deform 1 x final 0 0.03 remap x\n")
L("B13_deform_y_across", "fix deform 1 y final 0 0.03 remap x (across the pair: no relative motion; control)", pair=IN() + "fix dfm all deform 1 y final 0 0.03 remap x\n")
L("B14_deform_x_remap_v", "fix deform 1 x erate -50 remap v (x periodic; velocities remapped only across the boundary)", pair=IN() + "fix dfm all deform 1 x erate -50 remap v\n")
L("B15_evaporate_lv2", "fix evaporate 50 1 region around lv2 (lv2 deleted before the meeting: no contact)",
  pair=IN() + "region rev sphere 0.02305 0.02 0.05 0.004 units box\nfix evap all evaporate 50 1 rev 4767\n")
L("B16_evaporate_far_region", "fix evaporate 50 1 of a far region with one sphere in it (control)",
  pair=PAIR3("create_atoms 1 single 0.01 0.01 0.09\nset atom 1 diameter 0.004 density 2500\n") + "region rev sphere 0.01 0.01 0.09 0.004 units box\nfix evap all evaporate 50 1 rev 4767\n")
L("B17_create_remap_outside", "lv2 created at x 0.06305 with remap yes (periodic x: lands at 0.02305)",
  pair=IN().replace("create_atoms 2 single 0.023050 0.02 0.05", "create_atoms 2 single 0.063050 0.02 0.05 remap yes"))
L("B18_set_x_into_place", "lv2 created far; set atom 2 x 0.02305 (positions by set)",
  pair=IN().replace("create_atoms 2 single 0.023050 0.02 0.05", "create_atoms 2 single 0.033050 0.02 0.05") + "set atom 2 x 0.02305\n")

# ================================================================ F: fixes on one sphere or both
INTEG = "fix integ all nve/sphere\n"
ONLY1 = lambda: RB().replace(INTEG, "")
L("F01_move_linear_lv2", "lv2 driven by fix move linear -0.2286 0 0 (infinite mass); nve/sphere on lv1 only",
  pre=ONLY1(), pair=IN() + "fix mv lv2 move linear -0.2285714286 0 0 units box\nfix integ lv1 nve/sphere\n")
L("F02_move_linear_null", "lv2 under fix move linear NULL NULL NULL (integrated as nve: free); nve/sphere on lv1",
  pre=ONLY1(), pair=IN() + "fix mv lv2 move linear NULL NULL NULL units box\nfix integ lv1 nve/sphere\n")
L("F03_move_wiggle_lv2", "lv2 under fix move wiggle 1e-4 0 0 period 0.001 (driven); nve/sphere on lv1",
  pre=ONLY1(), pair=IN() + "fix mv lv2 move wiggle 1e-4 0 0 0.001 units box\nfix integ lv1 nve/sphere\n")
L("F04_move_variable_const", "lv2 under fix move variable with a constant vx -0.2286 (driven)", pre=ONLY1(),
  pair=IN() + "variable vx equal -0.2285714286\nvariable dx equal -0.2285714286*elapsed*dt\nfix mv lv2 move variable v_dx NULL NULL v_vx NULL NULL units box\nfix integ lv1 nve/sphere\n")
L("F05_nve_noforce_lv2", "lv2 under fix nve/noforce (moves at its speed, feels no force); nve/sphere on lv1", pre=ONLY1(),
  pair=IN() + "fix nf lv2 nve/noforce\nfix integ lv1 nve/sphere\n")
L("F06_lineforce_perp_lv1", "fix lineforce 0 1 0 on lv1 (its x force removed: the contact force does not act on it)", pair=IN() + "fix lf lv1 lineforce 0 1 0\n")
L("F07_planeforce_x_lv2", "fix planeforce 1 0 0 on lv2 (the x component removed)", pair=IN() + "fix pf lv2 planeforce 1 0 0\n")
L("F08_aveforce_both_x", "fix aveforce 0 NULL NULL on group of both (the equal and opposite forces averaged: 0 on each)",
  pair=IN() + "group both id 1 2\nfix af both aveforce 0.0 NULL NULL\n")
L("F09_aveforce_lv2_alone", "fix aveforce NULL NULL NULL on lv2 alone (its own force: control)", pair=IN() + "fix af lv2 aveforce NULL NULL NULL\n")
L("F10_spring_tether_lv2", "fix spring tether K 200 on lv2 to its start x (a spring to space during the contact)",
  pair=IN() + "fix sp lv2 spring tether 200 0.02305 NULL NULL 0.0\n")
L("F11_temp_berendsen_strong", "fix temp/berendsen 0 0 1e-5 on all (velocities scaled towards zero)", pair=IN() + "fix tb all temp/berendsen 0.0 0.0 1e-5\n")
L("F12_temp_berendsen_weak", "fix temp/berendsen 0 0 1e6 on all (tiny scaling: control)", pair=IN() + "fix tb all temp/berendsen 0.0 0.0 1e6\n")
L("F13_nvt_sphere", "fix nvt/sphere temp 1e-9 1e-9 1e-4 replaces nve/sphere (a Nose-Hoover thermostat near 0 K)",
  pre=RB().replace(INTEG, "fix integ all nvt/sphere temp 1e-9 1e-9 1e-4\n"))
L("F14_recenter", "fix recenter INIT INIT INIT (shifts every atom each step: control)", pair=IN() + "fix rc all recenter INIT INIT INIT\n")
L("F15_omega_set_lv1", "set atom 1 omega 0 0 100 (lv1 spinning about z: head-on normal unchanged; control)", pair=IN() + "set atom 1 omega 0 0 100\n")
L("F16_setforce_region_lv2", "fix setforce 0 NULL NULL region around lv2's place (lv2 feels no x force while in it)",
  pair=IN() + "region rsf block 0.020 0.030 0 0.04 0 0.1 units box\nfix sf all setforce 0.0 NULL NULL region rsf\n")
L("F17_setforce_region_far", "fix setforce 0 0 0 region far off (control)", pair=IN() + "region rsf block 0 0.005 0 0.04 0 0.1 units box\nfix sf all setforce 0.0 0.0 0.0 region rsf\n")
L("F18_move_linear_000_lv2", "lv2 held still by fix move linear 0 0 0, lv1 at 1 m/s (a sphere as a wall)", pre=ONLY1(),
  pair=IN().replace("velocity lv1 set 0.7714285714", "velocity lv1 set 1.0").replace("velocity lv2 set -0.2285714286", "velocity lv2 set 0.0")
  + "fix mv lv2 move linear 0 0 0 units box\nfix integ lv1 nve/sphere\n")
L("F19_nve_limit_lv2", "lv2 under fix nve/limit 1e-7 (at most 0.1 m/s: its 0.2286 capped), nve/sphere on lv1", pre=ONLY1(),
  pair=IN() + "fix lim lv2 nve/limit 1e-7\nfix integ lv1 nve/sphere\n")
L("F20_oneway_lv2", "fix oneway 1 region everywhere -x on lv2 (its vx kept negative: may not bounce back)",
  pair=IN() + "region all_ block INF INF INF INF INF INF units box\nfix ow lv2 oneway 1 all_ -x\n")
L("F21_momentum_linear_every1", "fix momentum 1 linear 1 1 1 (the centre of mass stopped: relative motion unchanged; control)", pair=IN() + "fix mo all momentum 1 linear 1 1 1\n")
L("F22_viscous_sphere", "fix viscous/sphere 1e-3 (rotational drag: head-on control)", pair=IN() + "fix vs all viscous/sphere 1e-3\n")

# ================================================================ U: unit styles, dimension 2
UNIT = lambda u, dt="1e-6", run=3000: (RB().replace("units si\n", f"units {u}\n").replace("timestep 1e-6", f"timestep {dt}") + ("neighbor 0.001 bin\n" if u in ("real", "metal", "electron") else ""), f"run {run}\n")
for nm, u, dt, run in [("U01_units_lj", "lj", "1e-6", 3000), ("U03_units_metal", "metal", "1e-8", 13000),
                       ("U04_units_micro", "micro", "1e-6", 3000), ("U05_units_nano", "nano", "1e-6", 3000), ("U06_units_electron", "electron", "1e-6", 3000)]:
    pre, body = UNIT(u, dt, run)
    L(nm, f"units {u}, the si deck's numbers (timestep {dt}, run {run}; neighbor 0.001 bin where the units' default skin is in Angstrom or Bohr)", pre=pre, body=body)
pre, body = UNIT("real", "1e-6", 3000)
L("U07_units_real_hertzmat", "units real, hertz/material coeff_restitution e 0.5 (E 2.39e9: the si E over ftm2v)", pre=pre.replace("pair_coeff * * " + HK, "pair_coeff * * " + HZM.replace("1e6", "2.39e9")), body=body)
L("U16_units_real_kn_scaled", "units real, hooke kn 4.78e6 (the si kn over ftm2v: the same stiffness in motion), damping mass_velocity 3000", pre=pre.replace("hooke 2000", "hooke 4.78e6"), body=body)
pre, body = UNIT("metal", "1e-8", 13000)
L("U08_units_metal_floor", "units metal floor drop (hooke wall; gravity 9.81 in metal units)", pre=pre.replace("fix integ", FLOORW + "fix integ"), body=body,
  pair=FLOORP, **FLOOR)
D2 = lambda extra="", integ="fix integ all nve/sphere\n": ("units si\ndimension 2\natom_style sphere 1\nboundary p p p\ncomm_modify vel yes\n"
      "region box block 0 0.04 0 0.04 -0.001 0.001 units box\ncreate_box 2 box\npair_style granular\npair_coeff * * " + HK + "\n"
      "fix grav all gravity 9.81 vector 0 -1 0\n" + integ + "fix e2 all enforce2d\ntimestep 1e-6\n" + extra)
IN2 = lambda dens="density 2500": (f"create_atoms 1 single 0.017950 0.02 0.0\ncreate_atoms 2 single 0.023050 0.02 0.0\n"
       f"set atom 1 diameter 0.004 {dens}\nset atom 2 diameter 0.006 {dens}\ngroup lv1 id 1\ngroup lv2 id 2\n"
       "velocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\n")
L("U09_dim2_density", "dimension 2, enforce2d, set diameter density 2500 (mass?)", pre=D2(), pair=IN2())
L("U10_dim2_density_disc", "dimension 2, set density/disc 2500 (disc masses: pi r^2 rho; run 20000)", pre=D2(), pair=IN2("density/disc 2500"), body="run 20000\n")
L("U11_dim2_nve_sphere_disc", "dimension 2, nve/sphere disc, density/disc (run 20000)", pre=D2(integ="fix integ all nve/sphere disc\n"), pair=IN2("density/disc 2500"), body="run 20000\n")
L("U12_dim2_diameter_only", "dimension 2, set diameter only (create_atoms default density 1 in 2d: mass?; run 150000)", pre=D2(), pair=IN2("").replace(" \n", "\n"), body="run 150000\n")
L("U13_dim2_mass_set", "dimension 2, set diameter then set mass (lv2 3x lv1's)", pre=D2(),
  pair=IN2("").replace(" \n", "\n") + "set atom 1 mass 1e-4\nset atom 2 mass 3e-4\n")
L("U14_dim3_density_disc", "dimension 3 with set density/disc (LAMMPS: 2d only?)", pair=IN().replace("density 2500", "density/disc 2500"))
L("U15_dim2_hertzmat", "dimension 2, hertz/material coeff_restitution e 0.5, density/disc (run 20000)", pre=D2().replace("pair_coeff * * " + HK, "pair_coeff * * " + HZM), pair=IN2("density/disc 2500"), body="run 20000\n")

# ================================================================ R: run forms
L("R01_upto_after_reset_short", "reset_timestep 2990; run 3000 upto (10 steps: the pair never meets)", body="reset_timestep 2990\nrun 3000 upto\n")
L("R02_upto_after_run", "run 50; run 3000 upto (2950 more: control)", body="run 50\nrun 3000 upto\n")
L("R03_start_stop_three", "run 1000 start 0 stop 3000, three times", body="run 1000 start 0 stop 3000\nrun 1000 start 0 stop 3000\nrun 1000 start 0 stop 3000\n")
L("R04_pre_post_no", "run 50; run 2950 pre no post no", body="run 50\nrun 2950 pre no post no\n")
L("R05_timestep_finer_between", "run 50; timestep 5e-7; run 6000", body="run 50\ntimestep 5e-7\nrun 6000\n")
L("R06_timestep_coarse_between", "run 50; timestep 2e-5; run 200 (29 steps per contact)", body="run 50\ntimestep 2e-5\nrun 200\n")
L("R07_restart_clear_read", "write_restart r47.bin after the velocities; clear; read_restart; the fixes and timestep again; run",
  body="write_restart r47.bin\nclear\nread_restart r47.bin\ncomm_modify vel yes\nfix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\nrun 3000\n")
L("R08_restart_clear_read_kn5000", "R07 with pair_coeff * * kn 5000 after the read_restart (restart holds 2000)",
  body="write_restart r47.bin\nclear\nread_restart r47.bin\ncomm_modify vel yes\npair_coeff * * " + HK.replace("2000", "5000") + "\nfix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\nrun 3000\n")
L("R09_write_data_clear_read", "write_data d47.data nocoeff; clear; read_data with the base settings and pair_coeff kn 5000; run",
  body="write_data d47.data nocoeff\nclear\nunits si\natom_style sphere 1\nboundary p p f\ncomm_modify vel yes\nread_data d47.data\npair_style granular\npair_coeff * * "
  + HK.replace("2000", "5000") + "\nfix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\ngroup lv1 id 1\ngroup lv2 id 2\nrun 3000\n")
L("R10_print_file_then_var_changed", "variable kn equal 5000; print a pair_coeff with ${kn} to pc47.in; kn deleted and 8000; include pc47.in (5000 written)",
  body='variable kn equal 5000\nprint "pair_coeff * * hooke ${kn} 3000 damping mass_velocity tangential linear_nohistory 1 0.3" file pc47.in\n'
  "variable kn delete\nvariable kn equal 8000\ninclude pc47.in\nrun 3000\n")
L("R11_upto_first", "run 3000 upto at step 0 (control)", body="run 3000 upto\n")
L("R12_reset_then_run", "reset_timestep 5000; run 3000 (control)", body="reset_timestep 5000\nrun 3000\n")
L("R13_run_every_velocity", "run 3000 every 50 \"velocity lv2 set -0.2285714286 0 0 units box\" (lv2's speed reset every 50 steps through the contact)",
  body='run 3000 every 50 "velocity lv2 set -0.2285714286 0 0 units box"\n')
L("R14_timestep_before_atoms_units_after", "timestep 1e-6 before `units si` (units resets it to 1e-8); the pair at dt 1e-8 (300000 steps)",
  pre=RB().replace("timestep 1e-6\n", "").replace("units si\n", "timestep 1e-6\nunits si\n"), body="run 300000\n")
L("R15_write_restart_noclear", "write_restart then the same deck goes on (control)", body="write_restart r47.bin\nrun 3000\n")

# ================================================================ Y: bonds, pair hybrids
BOND = lambda: ("units si\natom_style hybrid sphere 1 bond\nboundary p p f\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.1 units box\n"
                "create_box 2 box bond/types 1 extra/bond/per/atom 2\npair_style granular\npair_coeff * * " + HK + "\n"
                "fix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\n")
THIRD = lambda x="0.007950", y="0.02", z="0.05": f"create_atoms 1 single {x} {y} {z}\nset atom 3 diameter 0.004 density 2500\n"
L("Y01_bond_lv1_to_third_harmonic", "hybrid sphere bond; bond harmonic K 500 r0 0.01 between lv1 and a sphere 10 mm behind it (pulls lv1 back in the contact)",
  pre=BOND() + "bond_style harmonic\nbond_coeff 1 500 0.01\n", pair=IN() + THIRD() + "create_bonds single/bond 1 1 3\n")
L("Y02_bond_far_pair", "hybrid sphere bond; a bond between two far spheres only (control)", pre=BOND() + "bond_style harmonic\nbond_coeff 1 500 0.01\n",
  pair=IN() + THIRD("0.01", "0.01", "0.09") + "create_atoms 1 single 0.02 0.01 0.09\nset atom 4 diameter 0.004 density 2500\ncreate_bonds single/bond 1 3 4\n")
L("Y03_bond_zero_lv1", "hybrid sphere bond; bond_style zero between lv1 and a far sphere (control)", pre=BOND() + "bond_style zero\nbond_coeff 1\n",
  pair=IN() + THIRD("0.01", "0.01", "0.09") + "create_bonds single/bond 1 1 3\n")
L("Y04_bond_between_pair_special_1", "a harmonic bond between lv1 and lv2 (r0 5.1 mm, K 500), default special_bonds lj 0 0 0: the bonded pair left out of the granular list, the bond acting",
  pre=BOND() + "bond_style harmonic\nbond_coeff 1 500 0.0051\n", pair=IN() + "create_bonds single/bond 1 1 2\n")
L("Y05_hybrid_none_12", "pair_style hybrid granular; pair_coeff * * granular; pair_coeff 1 2 none (no contact)",
  pre=RB(style="pair_style hybrid granular\n", coeff="pair_coeff * * granular " + HK + "\npair_coeff 1 2 none\n"))
L("Y06_overlay_zero_start", "pair_style hybrid/overlay zero 0.01 granular from the start (control)",
  pre=RB(style="pair_style hybrid/overlay zero 0.01 granular\n", coeff="pair_coeff * * zero\npair_coeff * * granular " + HK + "\n"))
L("Y07_hybrid_scaled_zero_granular", "pair_style hybrid/scaled 0.5 granular 0.5 granular: two halves of kn 4000 kt 3000 damping 3000 (kn 4000, damping 3000 in all)",
  pre=RB(style="pair_style hybrid/scaled 0.5 granular 0.5 granular\n", coeff="pair_coeff * * granular 1 " + HK.replace("2000", "4000") + "\npair_coeff * * granular 2 " + HK.replace("2000", "4000") + "\n"))
L("Y08_bond_lv1_third_fene_special_all", "hybrid sphere bond; bond harmonic between lv2 and a sphere ahead of it (x 0.0331), special_bonds lj 1 1 1",
  pre=BOND() + "bond_style harmonic\nbond_coeff 1 500 0.01\nspecial_bonds lj 1 1 1\n", pair=IN() + THIRD("0.03305") + "create_bonds single/bond 1 2 3\n")

# ================================================================ G: gravity forms on the floor drop
GF = lambda grav: WALLB(FLOORW).replace("fix grav all gravity 9.81 vector 0 0 -1\n", grav)
FP = lambda gn: FLOORP.replace(f"{-VZ:.10f}", f"{-math.sqrt(1 - 2 * gn * H0):.10f}")
GB = "run 900\n"
L("G01_spherical_down", "floor drop; gravity 9.81 spherical 0 180 (down)", pre=GF("fix grav all gravity 9.81 spherical 0.0 180.0\n"), pair=FLOORP, **FLOOR)
L("G02_chute_0", "floor drop; gravity 9.81 chute 0.0 (down)", pre=GF("fix grav all gravity 9.81 chute 0.0\n"), pair=FLOORP, **FLOOR)
L("G03_vector_not_unit", "floor drop; gravity 9.81 vector 0 0 -3 (normalised)", pre=GF("fix grav all gravity 9.81 vector 0 0 -3\n"), pair=FLOORP, **FLOOR)
L("G04_up_500", "floor drop at 1 m/s; gravity 500 vector 0 0 1 (upwards, strong; run 900: the first bounce)", pre=GF("fix grav all gravity 500 vector 0 0 1\n"), pair=FP(-500), body=GB, GN="-500", **FLOOR)
L("G05_down_500_spherical", "floor drop at 1 m/s; gravity 500 spherical 0 180 (strong, down; run 900)", pre=GF("fix grav all gravity 500 spherical 0.0 180.0\n"), pair=FP(500), body=GB, GN="500", **FLOOR)
L("G06_disable_500", "floor drop at 1 m/s; gravity 500 vector 0 0 -1 disable (no force; run 900)", pre=GF("fix grav all gravity 500 vector 0 0 -1 disable\n"), pair=FP(0), body=GB, GN="0", **FLOOR)
L("G07_two_fixes_250", "floor drop at 1 m/s; two gravity fixes of 250 each down (run 900)", pre=GF("fix grav all gravity 250 vector 0 0 -1\nfix grav2 all gravity 250 vector 0 0 -1\n"), pair=FP(500), body=GB, GN="500", **FLOOR)
L("G08_chute_90_500", "floor drop at 1 m/s; gravity 500 chute 90 (along +x: none into the floor; run 900)", pre=GF("fix grav all gravity 500 chute 90.0\n"), pair=FP(0), body=GB, GN="0", **FLOOR)
L("G09_down_500_vector", "floor drop at 1 m/s; gravity 500 vector 0 0 -1 (control for G05; run 900)", pre=GF("fix grav all gravity 500 vector 0 0 -1\n"), pair=FP(500), body=GB, GN="500", **FLOOR)
L("G10_addforce_down", "floor drop at 1 m/s; no gravity fix; addforce of 500 m/s^2 times the sphere's mass, down (run 900)",
  pre=GF(""), pair=FP(500) + "variable fz equal -500*mass(lv1)\nfix af lv1 addforce 0.0 0.0 v_fz\n", body=GB, GN="500", **FLOOR)

# ================================================================ E: shapes of two LAMMPS examples (SOURCES)
E2D = lambda extra="", integ="fix 1 all nve/sphere\n": ("units lj\natom_style sphere\ndimension 2\nlattice sq 0.5\nregion box block 0 60 0 60 -0.5 0.5\ncreate_box 2 box\n"
        "create_atoms 1 single 10.0 30.0 0.0 units box\ncreate_atoms 2 single 20.6 30.0 0.0 units box\n"
        "set type 2 mass 400\nset type 1 mass 1\nset type 2 diameter 20\nset type 1 diameter 1\n" + extra +
        "comm_modify vel yes\npair_style granular\npair_coeff * * hooke 1.0 0.5 tangential linear_history 1.0 0.5 0.1 damping mass_velocity\n"
        + integ + "fix 2 all enforce2d\ntimestep 0.005\ngroup lv1 id 1\ngroup lv2 id 2\nvelocity lv1 set 1.0 0 0 units box\n")
L("E01_multi_2d_lj_pair", "multi/in.granular's shape: 2d lj, diameters 1 and 20, masses 1 and 400, hooke 1.0 0.5 mass_velocity", pre=E2D(), pair="", body="run 2000\n", SEP="10.5")
L("E02_multi_triclinic_multi_neigh", "E01 with change_box triclinic, neighbor 1 multi, comm_modify mode multi vel yes",
  pre=E2D("change_box all triclinic\nneighbor 1 multi\nneigh_modify delay 0 collection/interval 2 1 20\ncomm_modify mode multi vel yes reduce/multi\n"), pair="", body="run 2000\n", SEP="10.5")
L("E03_multi_deform_xy", "E02 with fix deform 1 xy erate 1e-3 (shear across the pair's line)",
  pre=E2D("change_box all triclinic\n") + "fix 3 all deform 1 xy erate 1e-3\n", pair="", body="run 2000\n", SEP="10.5")
L("E04_multi_nph_sphere", "E02 with fix nph/sphere iso 0 1 10 drag 1 instead of nve/sphere (the example's integrator)",
  pre=E2D("change_box all triclinic\n", integ="fix 1 all nph/sphere iso 0.0 1.0 10.0 drag 1.0\n"), pair="", body="run 2000\n", SEP="10.5")
RIG = ("newton on\natom_style sphere\natom_modify map array sort 0 0\nunits si\nboundary p p f\nregion reg block 0 0.04 0 0.04 0 0.1 units box\ncreate_box 1 reg\n"
       "pair_style gran/hooke/history 4e5 NULL 1e2 NULL 0.5 0\npair_coeff * *\ntimestep 1e-6\ncomm_modify vel yes cutoff 0.01\n"
       "fix gravfix all gravity 9.8 vector 0 0 -1 disable\nfix zwall all wall/gran hooke/history 4000.0 NULL 100.0 NULL 0.5 0 zplane 0.0 NULL\nfix integ all nve/sphere\n")
L("E05_rigid_gravity_floor", "rigid/in.rigid.gravity's shape: gran/hooke/history pair, hooke/history zplane floor, gravity 9.8 `disable`; one sphere dropped",
  pre=RIG, pair=FLOORP, PAIR="type 1 on wall zwall")
L("E06_rigid_gravity_pair", "E05's lines, a head-on pair of type 1 (4e5 hooke/history)", pre=RIG,
  pair=IN(t2=1), PAIR="types 1 1")

# ================================================================ L: LIGGGHTS
LP = ("create_atoms 1 single 0.048 0 0.1 units box\ncreate_atoms 2 single -0.0469 0 0.1 units box\n"
      "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\ngroup lv1 id 1\ngroup lv2 id 2\n"
      "velocity lv1 set 0.7714285714 0 0\nvelocity lv2 set -0.2285714286 0 0\n")
LG("L01_exclude_type_12", "neigh_modify exclude type 1 2 (no contact)", pre=LBASE() + "neigh_modify exclude type 1 2\n")
LG("L02_freeze_lv2", "fix freeze on lv2 (a still 6 mm sphere; lv1 at 1 m/s)", pair=LIN.replace("velocity lv1 set 0.7714285714", "velocity lv1 set 1.0").replace("velocity lv2 set -0.2285714286", "velocity lv2 set 0.0") + "fix fz lv2 freeze\n")
LG("L03_delete_overlap", "delete_atoms overlap 0.006 all all (one of the pair deleted)", pair=LIN + "delete_atoms overlap 0.006 all all\n")
LG("L04_displace_into_place", "lv2 made 10 mm further; displace_atoms lv2 move -0.01 0 0 units box",
   pair=LIN.replace("create_atoms 2 single 0.002550", "create_atoms 2 single 0.012550") + "displace_atoms lv2 move -0.01 0 0 units box\n")
LG("L05_upto_after_reset_short", "reset_timestep 2990; run 3000 upto (10 steps, no meeting)", body="reset_timestep 2990\nrun 3000 upto\n")
LG("L06_dim2", "dimension 2, enforce2d, boundary p p p, box z thin (mass of a sphere in 2d?)",
   pre=LBASE(wall=False).replace("boundary p f f\n", "dimension 2\nboundary p p p\n").replace("-0.01 0.15 units box", "-0.001 0.001 units box").replace("vector 0.0 0.0 -1.0", "vector 0.0 -1.0 0.0")
   + "fix e2 all enforce2d\n", pair=LIN.replace(" 0 0.1 units box", " 0 0.0 units box"), body="run 30000\n")
LG("L07_periodic_meet_through_x", "the pair meets through the periodic x boundary", pair=LP, SEP="-0.0899")
LG("L08_move_linear_lv2", "lv2 driven by fix move linear -0.2286 0 0, nve/sphere on lv1", pre=LBASE().replace("fix integr all nve/sphere\n", ""),
   pair=LIN + "fix mv lv2 move linear -0.2285714286 0 0\nfix integr lv1 nve/sphere\n")
LG("L09_aveforce_both", "fix aveforce 0 NULL NULL on both (0 force on each along x)", pair=LIN + "group both id 1 2\nfix af both aveforce 0.0 NULL NULL\n")
LG("L10_timestep_coarse_between", "run 50; timestep 2e-5; run 200", body="run 50\ntimestep 2e-5\nrun 200\n")
LG("L11_restart_clear_read", "write_restart; clear; read_restart; materials, pair and fixes again; run",
   body="write_restart r47.bin\nclear\nnewton off\natom_modify map array\ncommunicate single vel yes\nread_restart r47.bin\nneighbor 0.002 bin\nneigh_modify delay 0\n"
   "fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6\nfix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3\n"
   "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5\n"
   "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.3 0.7 0.3 0.4 0.45 0.7 0.45 0.8\n"
   "pair_style gran model hertz tangential history\npair_coeff * *\ntimestep 1e-6\nfix gravi all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\nrun 3000\n")
LG("L12_no_comm_vel", "communicate single vel yes left out", pre=LBASE().replace("communicate single vel yes\n", ""))
LG("L13_newton_on", "newton on (LIGGGHTS granular)", pre=LBASE().replace("newton off\n", "newton on\n"))
LG("L14_lineforce_perp_lv1", "fix lineforce 0 1 0 on lv1", pair=LIN + "fix lf lv1 lineforce 0 1 0\n")
LG("L15_change_box_meet", "box x -0.05..0.05 then change_box x final -0.0475 0.05: the pair meets through x",
   pair=LP.replace("0.048 0 0.1", "0.0455 0 0.1") + "change_box all x final -0.0475 0.05 units box\n", SEP="-0.0899")
LG("L16_dim2_density_check", "dimension 2 as L06, with set mass (lv2 3x lv1's)",
   pre=LBASE(wall=False).replace("boundary p f f\n", "dimension 2\nboundary p p p\n").replace("-0.01 0.15 units box", "-0.001 0.001 units box").replace("vector 0.0 0.0 -1.0", "vector 0.0 -1.0 0.0")
   + "fix e2 all enforce2d\n", pair=LIN.replace(" 0 0.1 units box", " 0 0.0 units box") + "set atom 1 mass 1e-4\nset atom 2 mass 3e-4\n")
LG("L17_evaporate_lv2", "fix evaporate 50 1 of a region around lv2 (no contact)", pair=LIN + "region rev sphere 0.00255 0 0.1 0.004 units box\nfix evap all evaporate 50 1 rev 4767\n")
LG("L18_exclude_group", "neigh_modify exclude group lv1 lv2 (no contact)", pair=LIN + "neigh_modify exclude group lv1 lv2\n")


# ================================================================ set 2 (written after reading batch1: leads from Y08, F01-F05, G07)
BDATA = lambda bonds, b3="0.033050": ("LAMMPS data file: a pair and a third sphere, hybrid sphere bond\n\n3 atoms\n2 atom types\n1 bonds\n1 bond types\n\n"
         "0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # hybrid\n\n"
         f"1 1 0.017950 0.02 0.05 0.004 2500 0\n2 2 0.023050 0.02 0.05 0.006 2500 0\n3 1 {b3} 0.02 0.05 0.004 2500 0\n\n"
         "Velocities\n\n1 0.7714285714 0 0 0 0 0\n2 -0.2285714286 0 0 0 0 0\n3 0 0 0 0 0 0\n\nBonds\n\n" + bonds + "\n")
BRD = lambda bond, special="": ("units si\natom_style hybrid sphere 1 bond\nboundary p p f\ncomm_modify vel yes\nread_data d.data\npair_style granular\npair_coeff * * " + HK + "\n"
         + bond + special + "fix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\ngroup lv1 id 1\ngroup lv2 id 2\n")
L("Y09_data_bond_lv2_third_special1", "read_data Bonds: a harmonic bond (K 500, r0 10 mm) from lv2 to a sphere 10 mm ahead; special_bonds lj 1 1 1",
  pre=BRD("bond_style harmonic\nbond_coeff 1 500 0.01\n", "special_bonds lj 1 1 1\n"), pair="", data={"d.data": BDATA("1 1 2 3")})
L("Y10_data_bond_pair_harmonic", "read_data Bonds: a harmonic bond between lv1 and lv2 (r0 5.1 mm), default special_bonds (the pair left out of the granular list)",
  pre=BRD("bond_style harmonic\nbond_coeff 1 500 0.0051\n"), pair="", data={"d.data": BDATA("1 1 1 2")})
L("Y11_data_bond_pair_zero", "read_data Bonds: bond_style zero between lv1 and lv2, default special_bonds (no granular contact, no bond force: they pass)",
  pre=BRD("bond_style zero\nbond_coeff 1\n"), pair="", data={"d.data": BDATA("1 1 1 2")})
L("Y12_bond_create_pair_harmonic", "fix bond/create 1 1 2 0.005 1: a bond made between the pair as they come within 5 mm (at touching) (default special: the granular pair then left out), harmonic K 500 r0 5.1 mm",
  pre=BOND().replace("extra/bond/per/atom 2", "extra/bond/per/atom 2 extra/special/per/atom 2") + "bond_style harmonic\nbond_coeff 1 500 0.0051\n",
  pair=IN() + "fix bc all bond/create 1 1 2 0.005 1\n")
L("Y13_bond_create_pair_zero", "Y12 with bond_style zero (the bond made, no force: the pair passes)",
  pre=BOND().replace("extra/bond/per/atom 2", "extra/bond/per/atom 2 extra/special/per/atom 2") + "bond_style zero\nbond_coeff 1\n",
  pair=IN() + "fix bc all bond/create 1 1 2 0.005 1\n")
L("Y14_bond_zero_lv1_special1", "create_bonds bond_style zero from lv1 to a far sphere, special_bonds lj 1 1 1 (control)", pre=BOND() + "bond_style zero\nbond_coeff 1\nspecial_bonds lj 1 1 1\n",
  pair=IN() + THIRD("0.01", "0.01", "0.09") + "create_bonds single/bond 1 1 3\n")
L("Y15_bond_zero_pair_special1", "create_bonds bond_style zero between lv1 and lv2, special_bonds lj 1 1 1 (granular contact kept; control)", pre=BOND() + "bond_style zero\nbond_coeff 1\nspecial_bonds lj 1 1 1\n",
  pair=IN() + "create_bonds single/bond 1 1 2\n")
TG = "group t1 type 1\ngroup t2 type 2\n"
L("F23_type_move_linear", "groups by type: nve/sphere on t1, fix move linear -0.2286 0 0 on t2 (lv2 driven)", pre=ONLY1(), pair=IN() + TG + "fix integ t1 nve/sphere\nfix mv t2 move linear -0.2285714286 0 0 units box\n")
L("F24_type_nve_noforce", "groups by type: nve/sphere on t1, nve/noforce on t2", pre=ONLY1(), pair=IN() + TG + "fix integ t1 nve/sphere\nfix nf t2 nve/noforce\n")
L("F25_type_nve_limit_small", "groups by type: nve/sphere on t1, nve/limit 1e-7 on t2 (its speed capped at 0.1 m/s)", pre=ONLY1(), pair=IN() + TG + "fix integ t1 nve/sphere\nfix lim t2 nve/limit 1e-7\n")
L("F26_type_move_linear_null", "groups by type: nve/sphere on t1, fix move linear NULL NULL NULL on t2 (integrated as nve: free)", pre=ONLY1(), pair=IN() + TG + "fix integ t1 nve/sphere\nfix mv t2 move linear NULL NULL NULL units box\n")
L("F27_type_move_wiggle", "groups by type: nve/sphere on t1, fix move wiggle 1e-4 0 0 period 0.001 on t2", pre=ONLY1(), pair=IN() + TG + "fix integ t1 nve/sphere\nfix mv t2 move wiggle 1e-4 0 0 0.001 units box\n")
L("F28_type_move_rotate_own_centre", "groups by type: lv2 still, spun by fix move rotate about its own centre (period 0.01); lv1 at 1 m/s", pre=ONLY1(),
  pair=IN().replace("velocity lv1 set 0.7714285714", "velocity lv1 set 1.0").replace("velocity lv2 set -0.2285714286", "velocity lv2 set 0.0") + TG
  + "fix integ t1 nve/sphere\nfix mv t2 move rotate 0.02305 0.02 0.05 0 0 1 0.01 units box\n")
L("F29_nve_limit_all_small", "nve/limit 1e-7 as the only integrator (both speeds capped at 0.1 m/s; no rotation)", pre=RB().replace(INTEG, "fix integ all nve/limit 1e-7\n"))
L("N16_exclude_type_21", "neigh_modify exclude type 2 1 (reversed order: no contact)", pre=RB() + "neigh_modify exclude type 2 1\n")

# ================================================================ set 3 (hidden: written and engine-run before its audit; new fix styles, respa, bonds' reach)
L("F30_temp_csvr_strong", "fix temp/csvr 0 0 1e-5 (stochastic velocity rescaling towards 0 K)", pair=IN() + "fix tc all temp/csvr 0.0 0.0 1e-5 4767\n")
L("F31_temp_csld_strong", "fix temp/csld 0 0 1e-5 (velocities redrawn towards 0 K)", pair=IN() + "fix tc all temp/csld 0.0 0.0 1e-5 4767\n")
L("F32_heat_remove", "fix heat 1 -2e-6 (kinetic energy removed by velocity scaling)", pair=IN() + "fix ht all heat 1 -2e-6\n")
L("F33_ehex_remove", "fix ehex 1 -2e-6 (the same, ehex)", pair=IN() + "fix ht all ehex 1 -2e-6\n")
L("F34_damping_cundall", "fix damping/cundall 0.5 0.5 (Cundall's local damping of the forces)", pair=IN() + "fix dc all damping/cundall 0.5 0.5\n")
L("F35_propel_self_velocity", "fix propel/self velocity 1e-4 (a force along each atom's velocity)", pair=IN() + "fix ps all propel/self velocity 1e-4\n")
L("F36_brownian", "fix brownian at T 1e-20 as the integrator (overdamped motion)", pre=RB().replace(INTEG, "fix integ all brownian 1e-20 4767 gamma_t 1e-3\n"))
L("F37_wall_reflect_behind_lv2", "boundary f p f; fix wall/reflect xhi 0.0232 on lv2 (its centre turned back after the contact)",
  pre=RB().replace("boundary p p f", "boundary f p f"), pair=IN() + "fix wr lv2 wall/reflect xhi 0.0232 units box\n")
L("F38_wall_reflect_far", "boundary f p f; fix wall/reflect xlo 0.005 xhi 0.035 (far: control)", pre=RB().replace("boundary p p f", "boundary f p f"),
  pair=IN() + "fix wr all wall/reflect xlo 0.005 xhi 0.035 units box\n")
L("F39_press_berendsen_x", "fix press/berendsen x 0 0 1e-4 (the box rescaled along the pair each step, atoms with it)", pair=IN() + "fix pb all press/berendsen x 0.0 0.0 1e-4 dilate all\n")
L("F40_flow_gauss_x", "fix flow/gauss 1 0 0 on all (zero net x force on the group: the pair's forces cancel anyway; control)", pair=IN() + "fix fg all flow/gauss 1 0 0\n")
L("F41_drag_lv2", "fix drag on lv2 towards its start x (force 1e-4, delta 1e-3)", pair=IN() + "fix dr lv2 drag 0.02305 NULL NULL 1e-4 1e-3\n")
L("R16_respa_pair_inner", "run_style respa 2 2 pair 1 (the pair at the inner level: every half step)", body="run_style respa 2 2 pair 1\nrun 3000\n")
L("R17_respa_pair_outer", "run_style respa 2 2 pair 2 (the pair at the outer level: control)", body="run_style respa 2 2 pair 2\nrun 3000\n")
BOND3 = lambda: BOND().replace("create_box 2 box", "create_box 3 box").replace("pair_coeff * * ", "pair_coeff * * ")
L("Y16_create_bonds_many_lv2_third", "create_bonds many t2 t3 (lv2 bonded to a type 3 sphere 10 mm ahead), harmonic K 500 r0 10 mm, special_bonds lj 1 1 1",
  pre=BOND3() + "bond_style harmonic\nbond_coeff 1 500 0.01\nneighbor 0.008 bin\n",
  pair=IN() + "create_atoms 3 single 0.03305 0.02 0.05\nset atom 3 diameter 0.004 density 2500\ngroup t2 type 2\ngroup t3 type 3\ncreate_bonds many t2 t3 1 0.009 0.011\nspecial_bonds lj 1 1 1\n")
L("Y17_bond_pair_special1_harmonic", "a harmonic bond between lv1 and lv2 (K 500, r0 5.1 mm), special_bonds lj 1 1 1 (contact and bond both act)",
  pre=BOND() + "bond_style harmonic\nbond_coeff 1 500 0.0051\nspecial_bonds lj 1 1 1\n", pair=IN() + "create_bonds single/bond 1 1 2\n")
L("Y18_special_twice_last_1", "special_bonds lj 0 1 1 then special_bonds lj 1 1 1; bond_style zero between the pair (contact kept; control)",
  pre=BOND() + "bond_style zero\nbond_coeff 1\nspecial_bonds lj 0 1 1\nspecial_bonds lj 1 1 1\n", pair=IN() + "create_bonds single/bond 1 1 2\n")
L("Y19_data_bond_lv2_third_default_special", "read_data Bonds lv2 to a third sphere, harmonic, default special_bonds (the pair itself not bonded)",
  pre=BRD("bond_style harmonic\nbond_coeff 1 500 0.01\n"), pair="", data={"d.data": BDATA("1 1 2 3")})
L("Y20_bond_far_special1_harmonic", "special_bonds lj 1 1 1; a harmonic bond between two far spheres only (control)", pre=BOND() + "bond_style harmonic\nbond_coeff 1 500 0.01\nspecial_bonds lj 1 1 1\n",
  pair=IN() + THIRD("0.01", "0.01", "0.09") + "create_atoms 1 single 0.02 0.01 0.09\nset atom 4 diameter 0.004 density 2500\ncreate_bonds single/bond 1 3 4\n")
L("N17_neighbor_nsq", "neighbor 0.001 nsq (control)", pre=RB() + "neighbor 0.001 nsq\n")
L("G11_two_gravities_500_981", "floor drop at 1 m/s; gravity 9.81 down and a second gravity 500 down (509.81 in all; run 900)",
  pre=GF("fix grav all gravity 9.81 vector 0 0 -1\nfix grav2 all gravity 500 vector 0 0 -1\n"), pair=FP(509.81), body=GB, GN="509.81", **FLOOR)
LG("L20_nve_limit_small_lv2", "lv2 under nve/limit 1e-7 (speed capped at 0.1), nve/sphere on lv1", pre=LBASE().replace("fix integr all nve/sphere\n", ""),
   pair=LIN + "fix integr lv1 nve/sphere\nfix lim lv2 nve/limit absolute 1e-7\n")
LG("L21_move_linear_type2", "groups by type: nve/sphere on t1, fix move linear -0.2286 0 0 on t2", pre=LBASE().replace("fix integr all nve/sphere\n", ""),
   pair=LIN + "group t1 type 1\ngroup t2 type 2\nfix integr t1 nve/sphere\nfix mv t2 move linear -0.2285714286 0 0\n")
LG("L22_two_gravities_floor", "floor drop; gravity 9.81 and a second gravity 500 down (run 900)", pre=LBASE() + "fix grav2 all gravity 500 vector 0.0 0.0 -1.0\n",
   pair=LFLOOR.replace(f"{-VZ:.10f}", f"{-math.sqrt(1 - 2 * 509.81 * H0):.10f}"), body="run 900\n", PAIR="type 1 on wall wprim", GN="509.81")

# ================================================================ set 4 (after judging sets 1-3: the reach of SW-BOND-FORCE through special_bonds' 1-3 and 1-4 weights)
BONDS = lambda: BOND().replace("extra/bond/per/atom 2", "extra/bond/per/atom 2 extra/special/per/atom 4") + "bond_style zero\nbond_coeff 1\n"
FAR2 = THIRD("0.01", "0.01", "0.09") + "create_atoms 1 single 0.03 0.01 0.09\nset atom 4 diameter 0.004 density 2500\n"
L("Y21_chain13_special_101", "bond_style zero; lv1-3 and 3-lv2 bonds through a far sphere: the pair are 1-3 neighbours; special_bonds lj 1 0 1 (LAMMPS leaves them out of the list: they pass)",
  pre=BONDS(), pair=IN() + THIRD("0.01", "0.01", "0.09") + "create_bonds single/bond 1 1 3\ncreate_bonds single/bond 1 3 2\nspecial_bonds lj 1 0 1\n")
L("Y22_chain14_special_110", "bond_style zero; lv1-3-4-lv2 chain: 1-4 neighbours; special_bonds lj 1 1 0 (left out: they pass)",
  pre=BONDS(), pair=IN() + FAR2 + "create_bonds single/bond 1 1 3\ncreate_bonds single/bond 1 3 4\ncreate_bonds single/bond 1 4 2\nspecial_bonds lj 1 1 0\n")
L("Y23_chain13_special_111", "the 1-3 chain of Y21 under special_bonds lj 1 1 1 (control: they collide)",
  pre=BONDS(), pair=IN() + THIRD("0.01", "0.01", "0.09") + "create_bonds single/bond 1 1 3\ncreate_bonds single/bond 1 3 2\nspecial_bonds lj 1 1 1\n")
L("Y24_chain13_special_101_angle_yes", "Y21 with special_bonds lj 1 0 1 angle yes (no angles defined: the 1-3 weight not applied; they collide)",
  pre=BONDS(), pair=IN() + THIRD("0.01", "0.01", "0.09") + "create_bonds single/bond 1 1 3\ncreate_bonds single/bond 1 3 2\nspecial_bonds lj 1 0 1 angle yes\n")
L("Y25_chain13_special_lj_coul_101", "Y21 through special_bonds lj/coul 1.0 0.0 1.0 (the same weights: they pass)",
  pre=BONDS(), pair=IN() + THIRD("0.01", "0.01", "0.09") + "create_bonds single/bond 1 1 3\ncreate_bonds single/bond 1 3 2\nspecial_bonds lj/coul 1.0 0.0 1.0\n")
BDATA3 = ("LAMMPS data file: a pair and a far sphere bonded to both\n\n3 atoms\n2 atom types\n2 bonds\n1 bond types\n\n"
         "0 0.04 xlo xhi\n0 0.04 ylo yhi\n0 0.1 zlo zhi\n\nAtoms # hybrid\n\n"
         "1 1 0.017950 0.02 0.05 0.004 2500 0\n2 2 0.023050 0.02 0.05 0.006 2500 0\n3 1 0.01 0.01 0.09 0.004 2500 0\n\n"
         "Velocities\n\n1 0.7714285714 0 0 0 0 0\n2 -0.2285714286 0 0 0 0 0\n3 0 0 0 0 0 0\n\nBonds\n\n1 1 1 3\n2 1 3 2\n")
L("Y26_data_chain13_special_101", "read_data Bonds lv1-3, 3-lv2 (bond_style zero), special_bonds lj 1 0 1 (they pass)",
  pre=BRD("bond_style zero\nbond_coeff 1\n", "special_bonds lj 1 0 1\n"), pair="", data={"d.data": BDATA3})
L("Y27_chain13_special_1_05_1", "the 1-3 chain under special_bonds lj 1 0.5 1 (LAMMPS keeps them in the list; the granular pair ignores the weight? or scales)",
  pre=BONDS(), pair=IN() + THIRD("0.01", "0.01", "0.09") + "create_bonds single/bond 1 1 3\ncreate_bonds single/bond 1 3 2\nspecial_bonds lj 1 0.5 1\n")

# ================================================================ set 5 (hidden: 2d walls, dynamic groups, per-type mass, label ranges, a turning floor)
D2W = lambda dens, extra="": ("units si\ndimension 2\natom_style sphere 1\nboundary f p p\ncomm_modify vel yes\n"
      "region box block 0 0.04 0 0.04 -0.001 0.001 units box\ncreate_box 2 box\npair_style granular\npair_coeff * * " + HK + "\n"
      "fix grav all gravity 9.81 vector 0 -1 0\nfix wx all wall/gran granular " + HK + " xplane 0 NULL\nfix integ all nve/sphere\nfix e2 all enforce2d\ntimestep 1e-6\n" + extra +
      f"create_atoms 1 single 0.0021 0.02 0.0\nset atom 1 diameter 0.004 {dens}\ngroup lv1 id 1\nvelocity lv1 set -1.0 0 0 units box\n")
L("V01_dim2_xwall_density_disc", "2d, boundary f p p, a hooke xplane wall at x 0; one disc (density/disc 2500) at 1 m/s into it", pre=D2W("density/disc 2500"), pair="",
  PAIR="type 1 on wall wx", WALLX="")
L("V02_dim2_xwall_density", "V01 with set density 2500 (the sphere's mass in 2d)", pre=D2W("density 2500"), pair="", PAIR="type 1 on wall wx", WALLX="")
L("V03_dim2_xwall_hertz_mv_disc", "V01 under hertz/material 1e6 3000 0.3 damping mass_velocity (mass and size matter), density/disc", pre=D2W("density/disc 2500").replace(HK, "hertz/material 1e6 3000 0.3 tangential linear_nohistory 1 0.3 damping mass_velocity"),
  pair="", PAIR="type 1 on wall wx", WALLX="")
L("V04_dim2_pair_hertz_mv_disc", "2d pair under hertz/material 1e6 3000 0.3 damping mass_velocity, density/disc (run 20000)", pre=D2().replace("pair_coeff * * " + HK, "pair_coeff * * hertz/material 1e6 3000 0.3 tangential linear_nohistory 1 0.3 damping mass_velocity"),
  pair=IN2("density/disc 2500"), body="run 20000\n")
L("V05_dynamic_group_viscous", "group gd dynamic all region around the meeting point every 1; fix viscous 0.05 on gd (a drag while in it)",
  pair=IN() + "region rm block 0.016 0.026 0 0.04 0 0.1 units box\ngroup gd dynamic all region rm every 1\nfix vis gd viscous 0.05\n")
L("V06_dynamic_group_far_viscous", "V05 with the region far off (control)",
  pair=IN() + "region rm block 0 0.005 0 0.04 0 0.1 units box\ngroup gd dynamic all region rm every 1\nfix vis gd viscous 0.05\n")
L("V07_mass_per_type_sphere", "atom_style sphere; mass 2 1e-3 (per-type mass beside rmass)", pair=IN() + "mass 2 1e-3\n")
L("V08_label_range_pair_coeff", "labelmap atom 1 sm 2 bg; pair_coeff 1* bg hooke 5000 (a number range with a label)", pre=RB(mid="labelmap atom 1 sm 2 bg\n") + PC("1* bg", HK.replace("2000", "5000")))
L("V09_floor_region_rotating_about_z", "a hooke wall/gran/region plane floor turning about the vertical axis through it (its surface still); the drop", pre=RB().replace("fix integ",
  "variable th equal 2*PI*elapsed*dt/0.01\nregion flr plane 0.02 0.02 0 0 0 1 side in move NULL NULL NULL rotate v_th 0.02 0.02 0 0 0 1 units box\nfix floor all wall/gran/region granular " + HK + " region flr\nfix integ"),
  pair=FLOORP, **FLOOR)
L("V10_mass_type_hybrid_bond", "atom_style hybrid sphere bond; set type 2 mass 1e-3 (lv2 heavier than its density says)", pre=BOND(), pair=IN() + "set type 2 mass 1e-3\n")
L("V11_dim2_set_diameter_after_density_disc", "2d: density/disc 2500, then set atom 2 diameter 0.008 (mass kept? LAMMPS: set diameter keeps the density)", pre=D2(),
  pair=IN2("density/disc 2500").replace("create_atoms 2 single 0.023050", "create_atoms 2 single 0.024050") + "set atom 2 diameter 0.008\n", body="run 20000\n")

# ================================================================ set 6 (hidden: rigid bodies of spheres, shrink-wrapped and prism boxes, delete_bonds, a real angle under `angle yes`)
RIGB = lambda fx: (IN() + THIRD("0.02305", "0.02", "0.09") + "group body id 2 3\nfix integ lv1 nve/sphere\n" + fx)
L("K01_rigid_single_lv2_third", "fix rigid single on lv2 and a sphere 40 mm above it (one body); nve/sphere on lv1", pre=ONLY1(), pair=RIGB("fix rg body rigid single\n"))
L("K02_rigid_small_molecule", "fix property/atom mol; lv2 and the sphere above it molecule 1; fix rigid/small molecule on them; nve/sphere on lv1",
  pre=RB(head="atom_modify map array\n", mid="fix pm all property/atom mol ghost yes\n").replace(INTEG, ""), pair=RIGB("set group body mol 1\nfix rg body rigid/small molecule\n"))
L("K03_rigid_then_set_diameter", "K01, then set atom 2 diameter 0.008 after the rigid fix", pre=ONLY1(), pair=RIGB("fix rg body rigid single\nset atom 2 diameter 0.008\n").replace("create_atoms 2 single 0.023050", "create_atoms 2 single 0.024050"))
L("K04_boundary_mmm", "boundary m m m (the pair inside; control)", pre=RB().replace("boundary p p f", "boundary m m m"))
L("K05_boundary_ssf", "boundary s s f (shrink-wrapped around the pair; control)", pre=RB().replace("boundary p p f", "boundary s s f"))
L("K06_prism_box", "create_box on a prism region with zero tilts (a triclinic box; control)", pre=RB(box="region box prism 0 0.04 0 0.04 0 0.1 0 0 0 units box\n"))
L("K07_delete_bonds_pair", "a bond between the pair (bond_style zero, default special: left out), then delete_bonds all bond 1 remove special: the contact back",
  pre=BOND() + "bond_style zero\nbond_coeff 1\n", pair=IN() + "create_bonds single/bond 1 1 2\ndelete_bonds all bond 1 remove special\n")
ANG = lambda: ("units si\natom_style hybrid sphere 1 angle\nboundary p p f\ncomm_modify vel yes\nregion box block 0 0.04 0 0.04 0 0.1 units box\n"
               "create_box 2 box bond/types 1 angle/types 1 extra/bond/per/atom 2 extra/angle/per/atom 2 extra/special/per/atom 4\npair_style granular\npair_coeff * * " + HK + "\n"
               "fix grav all gravity 9.81 vector 0 0 -1\nfix integ all nve/sphere\ntimestep 1e-6\nbond_style zero\nbond_coeff 1\nangle_style zero\nangle_coeff 1\n")
L("K08_angle_special_101_angle_yes", "bonds lv1-3, 3-lv2 and an angle 1-3-2 (all zero styles); special_bonds lj 1 0 1 angle yes (the angle exists: the pair left out, they pass)",
  pre=ANG(), pair=IN() + THIRD("0.01", "0.01", "0.09") + "create_bonds single/bond 1 1 3\ncreate_bonds single/bond 1 3 2\ncreate_bonds single/angle 1 1 3 2\nspecial_bonds lj 1 0 1 angle yes\n")

def write(only=()):
    n = 0
    for name, (text, live, data, meta) in sorted(DECKS.items()):
        if only and not any(name.startswith(p) for p in only):
            continue
        d = os.path.join(D, name)
        os.makedirs(d, exist_ok=True)
        open(os.path.join(d, "in.deck"), "w").write(text)
        open(os.path.join(d, "DECK"), "w").write("in.deck\n")
        open(os.path.join(d, "G"), "w").write("1\n")
        open(os.path.join(d, "NP"), "w").write("1\n")
        open(os.path.join(d, "LIVE"), "w").write(("WALL " if "wall" in meta.get("PAIR", "") else "") + live + "\n")
        for k, v in meta.items():
            open(os.path.join(d, k), "w").write(v + "\n")
        for f, t in data.items():
            open(os.path.join(d, f), "wb" if isinstance(t, bytes) else "w").write(t)
        n += 1
    print(n, "decks")


if __name__ == "__main__":
    write(sys.argv[1:])

"""Field round 43: write decks/NAME/ (in.deck and the files it reads) for the referee (round 37's live37.py) and the
audit. An adversarial round against the deck audit of main's head at about 01:50 UTC (a new rule for changes between
runs). The pair meets at step 100 and a contact lasts about 580 steps, so `run 300; X; run 2000` makes X mid-contact
and `run 50; X; run 3000` before the meeting. Families:
- B: changes between runs not tried before: a new wall fix at a sphere of the pair mid-contact (wall/gran zplane,
  wall/gran/region plane), `region ID delete` and the region defined again elsewhere under a wall/gran/region in force,
  an equal-style variable redefined that a fix in force uses (addforce, move variable, gravity, adapt, a region's
  move), fix_modify, pair_modify (compute no, mix, shift), unfix of viscous/setforce/addforce mid-contact, viscous and
  nve/noforce and move added, identical redefinitions of the wall and the pair (controls), reset_atoms id (with a
  `set atom N` after it), hybrid/overlay added, `mass`; LIGGGHTS: property/global for one pair, mesh and primitive
  walls added at the pair, contactDistanceFactor, viscous, the pair style redefined, addforce by a variable;
- H: harmless changes between runs (print, thermo, dump, compute, unused variables/regions/groups, fix ave/time,
  balance, neighbor skin ...), LAMMPS pair and floor decks and LIGGGHTS, to count unneeded notes;
- O: `$(expr:%.3g)` formats into pair_coeff/set/if, pair_coeff type ranges on 4 types and type labels, set order,
  LIGGGHTS walls-only material types and asymmetric matrices, size ranges (pour) with hertz laws, region
  cylinder/sphere walls, pair_style hybrid granular + another style, coarse time steps.
Helpers are rounds 35-42's (make_decks42.py imported; its decks are not written). LAMMPS controls (round 37): kn 2000
0.413435, 5000 0.578975; the floor 0.361743; LIGGGHTS e 0.5 0.499928, the wall e 0.7 0.699141.
usage: python make_decks43.py [NAME-PREFIX ...]"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "field42"))
import make_decks42 as m42  # noqa: E402

m41, m7 = m42.m41, m42.m7
m7.DECKS.clear(); m7.LINKS.clear(); m7.HARD.clear()
m7.D = os.path.join(HERE, "decks")
L, LG, DECKS = m7.L, m7.LG, m7.DECKS
S, B, SW, BW, SG, BG = m41.S, m41.B, m41.SW, m41.BW, m41.SG, m41.BG
PCs, HKk, IN, LIN, HK = m41.PCs, m41.HKk, m41.IN, m41.LIN, m7.HK
BASE, WALLP, WALL, LBASE, LWALL = m41.BASE, m41.WALLP, m41.WALL, m41.LBASE, m41.LWALL
PC5 = PCs(5000) + "\n"
RB = BASE(wall=False)
WG = "granular " + HK
LWK = dict(PAIR="type 1 on wall wprim", LWALLZ="1")
SWG = lambda name, desc, X, pre=None, **kw: LG(name, "LIGGGHTS WALL: " + desc, "run 300\n" + X + "run 2000\n", pre=pre or LBASE(),
                                              pair=LWALL(1e-4), live="run 1 (and run 2)", **LWK, **kw)


def facet(pts):
    a, b, c = pts
    return (" facet normal 0 0 0\n  outer loop\n" + "".join(f"   vertex {p[0]} {p[1]} {p[2]}\n" for p in (a, b, c)) +
            "  endloop\n endfacet\n")


def stl_x(x, y0=-0.01, y1=0.01, z0=0.09, z1=0.11):
    """A square in the plane x = const (two facets)."""
    return ("solid wx\n" + facet([(x, y0, z0), (x, y1, z0), (x, y1, z1)]) + facet([(x, y0, z0), (x, y1, z1), (x, y0, z1)]) + "endsolid wx\n")


def stl_z(z, a=-0.05, b=0.05):
    return ("solid wz\n" + facet([(a, a, z), (b, a, z), (b, b, z)]) + facet([(a, a, z), (b, b, z), (a, b, z)]) + "endsolid wz\n")


# ================================================================ B: between runs (LAMMPS)
S("B01_wallgran_zplane_under_lv2_mid", "run 300; fix w2 all wall/gran zplane 0.0475 NULL (lv2's lowest point 0.047: 0.5 mm into the new wall)",
  "fix w2 all wall/gran " + WG + " zplane 0.0475 NULL\n")
S("B02_wallregion_plane_behind_lv2_mid", "run 300; region wx plane x=0.0259 normal -x; fix w2 all wall/gran/region (lv2's far side ~0.02598: 0.08 mm in)",
  "region wx plane 0.0259 0 0 -1 0 0 units box\nfix w2 all wall/gran/region " + WG + " region wx\n")
S("B03_wallregion_far_then_moved_to_lv2", "wall/gran/region on plane wx at x 0.035 (far) from the start; run 300; region wx delete; region wx plane x 0.0259 (at lv2)",
  "region wx delete\nregion wx plane 0.0259 0 0 -1 0 0 units box\n",
  pair=IN(0.1e-3) + "region wx plane 0.035 0 0 -1 0 0 units box\nfix w2 all wall/gran/region " + WG + " region wx\n")
S("B04_wallregion_far_redefined_same", "wall/gran/region on plane wx at x 0.035 (far); run 300; region wx delete; region wx the same again (control)",
  "region wx delete\nregion wx plane 0.035 0 0 -1 0 0 units box\n",
  pair=IN(0.1e-3) + "region wx plane 0.035 0 0 -1 0 0 units box\nfix w2 all wall/gran/region " + WG + " region wx\n")
B("B05_wallregion_far_then_moved_before", "wall/gran/region plane wx at 0.035; run 50; region wx delete; region wx plane x 0.0262 (lv2 meets it after the pair parts?)",
  "region wx delete\nregion wx plane 0.0259 0 0 -1 0 0 units box\n",
  pair=IN(0.1e-3) + "region wx plane 0.035 0 0 -1 0 0 units box\nfix w2 all wall/gran/region " + WG + " region wx\n")
RFL = BASE(wall=False) + "region fl plane 0 0 0 0 0 1 units box\nfix floor all wall/gran/region " + WG + " region fl\n"
SW("B06_floor_region_delete_moved_up", "floor = wall/gran/region plane fl at z 0; run 300; region fl delete; region fl plane z 0.0002 (the sphere pressed 0.2 mm more)",
   "region fl delete\nregion fl plane 0 0 0.0002 0 0 1 units box\n", pre=RFL)
SW("B07_floor_region_delete_same", "floor = wall/gran/region plane fl at z 0; run 300; region fl delete; the same region again (control)",
   "region fl delete\nregion fl plane 0 0 0 0 0 1 units box\n", pre=RFL)
SW("B08_floor_region_delete_block", "floor region plane fl; run 300; region fl delete; region fl block (a box whose floor is z 0: the same surface)",
   "region fl delete\nregion fl block -1 1 -1 1 0 1 units box\n", pre=RFL)
AF = lambda v: f"variable f equal {v}\nfix af lv2 addforce v_f 0.0 0.0\n"
S("B09_var_addforce_0_to_m05", "variable f equal 0; fix af lv2 addforce v_f 0 0 from the start; run 300; variable f equal -0.5",
  "variable f equal -0.5\n", pair=IN(0.1e-3) + AF("0.0"))
S("B10_var_addforce_m05_to_0", "variable f equal -0.5 from the start; run 300; variable f equal 0", "variable f equal 0.0\n", pair=IN(0.1e-3) + AF("-0.5"))
B("B11_var_addforce_0_to_m05_before", "variable f equal 0; addforce v_f; run 50; variable f equal -0.5 (the whole contact pushed)",
  "variable f equal -0.5\n", pair=IN(0.1e-3) + AF("0.0"))
S("B12_var_addforce_delete_redefine", "variable f equal 0; addforce v_f; run 300; variable f delete; variable f equal -0.5",
  "variable f delete\nvariable f equal -0.5\n", pair=IN(0.1e-3) + AF("0.0"))
S("B13_var_addforce_indirect_next", "variable a index 0.0 -0.5; variable f equal v_a; addforce v_f; run 300; next a (f = -0.5)",
  "next a\n", pair=IN(0.1e-3) + "variable a index 0.0 -0.5\nvariable f equal v_a\nfix af lv2 addforce v_f 0.0 0.0\n")
S("B14_var_addforce_same_redefined", "variable f equal 0; addforce v_f; run 300; variable f equal 0.0 again (control)",
  "variable f equal 0.0\n", pair=IN(0.1e-3) + AF("0.0"))
MV = ("unfix integ\nfix i1 lv1 nve/sphere\nvariable vx equal -0.2285714286\n"
      "fix mv lv2 move variable NULL NULL NULL v_vx NULL NULL\n")
S("B15_var_move_velocity_to_0", "lv2 moved by fix move variable (vx -0.2286, a wall of infinite mass); run 300; variable vx equal 0",
  "variable vx equal 0.0\n", pair=IN(0.1e-3) + MV)
S("B16_var_move_velocity_same", "lv2 moved by fix move variable; run 300; variable vx equal -0.2285714286 again (control)",
  "variable vx equal -0.2285714286\n", pair=IN(0.1e-3) + MV)
S("B17_var_gravity_lv2_0_to_1000", "variable g equal 0; fix g2 lv2 gravity v_g vector -1 0 0; run 300; variable g equal 1000",
  "variable g equal 1000.0\n", pair=IN(0.1e-3) + "variable g equal 0.0\nfix g2 lv2 gravity v_g vector -1 0 0\n")
S("B18_var_adapt_diameter", "variable d equal 0.006; fix ad lv2 adapt 1 atom diameter v_d; run 300; variable d equal 0.0062",
  "variable d equal 0.0062\n", pair=IN(0.1e-3) + "variable d equal 0.006\nfix ad lv2 adapt 1 atom diameter v_d\n")
S("B19_var_adapt_diameter_same", "variable d equal 0.006; fix adapt on lv2; run 300; variable d equal 0.006 again (control)",
  "variable d equal 0.006\n", pair=IN(0.1e-3) + "variable d equal 0.006\nfix ad lv2 adapt 1 atom diameter v_d\n")
RMV = (BASE(wall=False) + "variable dz equal 0.0\nregion fl plane 0 0 0 0 0 1 move NULL NULL v_dz units box\n"
       "fix floor all wall/gran/region " + WG + " region fl\n")
SW("B20_var_region_move_floor_up", "floor region fl with move NULL NULL v_dz, dz equal 0; run 300; variable dz equal 1e-4 (the floor jumps 0.1 mm)",
   "variable dz equal 1e-4\n", pre=RMV)
SW("B21_var_region_move_floor_same", "floor region fl with move v_dz, dz 0; run 300; variable dz equal 0.0 again (control)", "variable dz equal 0.0\n", pre=RMV)
SW("B22_fix_modify_floor", "run 300; fix_modify floor virial no (control)", "fix_modify floor virial no\n")
S("B23_fix_modify_addforce_energy", "fix af lv2 addforce 0 0 0 from the start; run 300; fix_modify af energy yes (control)", "fix_modify af energy yes\n",
  pair=IN(0.1e-3) + "fix af lv2 addforce 0.0 0.0 0.0\n")
S("B24_pair_modify_compute_no_mid", "run 300; pair_modify compute no (no pair force from step 300: the pair passes through)", "pair_modify compute no\n")
B("B25_pair_modify_compute_no_before", "run 50; pair_modify compute no (no contact force at all)", "pair_modify compute no\n")
S("B26_pair_modify_shift_mid", "run 300; pair_modify shift yes (control)", "pair_modify shift yes\n")
MIX = RB.replace("pair_coeff * * " + HK + "\n", "pair_coeff 1 1 " + HK + "\npair_coeff 2 2 " + HKk(8000) + "\n")
S("B27_pair_modify_mix_arith_mid", "pc 1 1 kn 2000, pc 2 2 kn 8000 (1 2 mixed); run 300; pair_modify mix arithmetic", "pair_modify mix arithmetic\n", pre=MIX)
L("B28_mix_control", "pc 1 1 kn 2000, pc 2 2 kn 8000 (1 2 mixed), one run (control of B27)", "run 3000\n", pre=MIX)
S("B29_pair_modify_compute_no_then_yes", "run 300; pair_modify compute no; run 100; pair_modify compute yes (overlapped when back)",
  "pair_modify compute no\nrun 100\npair_modify compute yes\n")
S("B30_unfix_viscous_mid", "fix vis lv2 viscous 0.05 from the start; run 300; unfix vis", "unfix vis\n", pair=IN(0.1e-3) + "fix vis lv2 viscous 0.05\n")
S("B31_unfix_setforce_mid", "fix sf lv2 setforce 0 0 0 from the start; run 300; unfix sf", "unfix sf\n", pair=IN(0.1e-3) + "fix sf lv2 setforce 0.0 0.0 0.0\n")
S("B32_unfix_addforce_mid", "fix af lv2 addforce -0.5 0 0 from the start; run 300; unfix af", "unfix af\n", pair=IN(0.1e-3) + "fix af lv2 addforce -0.5 0.0 0.0\n")
S("B33_viscous_lv1_added_mid", "run 300; fix vis lv1 viscous 0.02", "fix vis lv1 viscous 0.02\n")
S("B34_nve_noforce_lv2_mid", "run 300; unfix integ; fix i1 lv1 nve/sphere; fix i2 lv2 nve/noforce", "unfix integ\nfix i1 lv1 nve/sphere\nfix i2 lv2 nve/noforce\n")
B("B35_move_linear_lv2_before", "run 50; unfix integ; fix i1 lv1 nve/sphere; fix mv lv2 move linear -0.2285714286 0 0 (lv2 a wall of infinite mass)",
  "unfix integ\nfix i1 lv1 nve/sphere\nfix mv lv2 move linear -0.2285714286 0 0 units box\n")
SW("B36_floor_identical_mid", "run 300; fix floor redefined, the same (control)", "fix floor all wall/gran " + WG + " zplane 0 NULL\n")
S("B37_pair_coeff_identical_mid", "run 300; pair_coeff * * the same (control)", "pair_coeff * * " + HK + "\n")
S("B38_pair_style_identical_mid", "run 300; pair_style granular; pair_coeff * * the same (control)", "pair_style granular\npair_coeff * * " + HK + "\n")
S("B39_reset_atoms_id_mid", "run 300; reset_atoms id (ids 1 2 already: control)", "reset_atoms id\n")
RID = (RB + "create_atoms 1 single 0.005 0.005 0.09\ncreate_atoms 1 single 0.017950 0.02 0.05\ncreate_atoms 2 single 0.023050 0.02 0.05\n"
       "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.004 density 2500\nset atom 3 diameter 0.006 density 2500\n"
       "group lv1 id 2\ngroup lv2 id 3\nvelocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\n"
       "group far id 1\ndelete_atoms group far\n")
B("B40_reset_atoms_id_then_set_atom2", "a far atom (id 1) deleted; the pair ids 2 3; run 50; reset_atoms id (now 1 2); set atom 2 density 5000 (lv2 now)",
  "reset_atoms id\nset atom 2 density 5000\n", pre=RID, pair="")
B("B41_no_reset_set_atom2", "as B40 without reset_atoms: set atom 2 density 5000 (lv1) (control)", "set atom 2 density 5000\n", pre=RID, pair="")
B("B42_reset_atom_ids_alias_set_atom1", "as B40 with reset_atom_ids; set atom 1 density 5000 (lv1 now; atom 1 was deleted)",
  "reset_atom_ids\nset atom 1 density 5000\n", pre=RID, pair="")
B("B43_reset_then_group_id_viscous", "as B40: run 50; reset_atoms id; group gv id 2 (lv2 now); fix vis gv viscous 0.05",
  "reset_atoms id\ngroup gv id 2\nfix vis gv viscous 0.05\n", pre=RID, pair="")
S("B44_hybrid_overlay_zero_mid", "run 300; pair_style hybrid/overlay granular zero 0.01; coeffs (control)",
  "pair_style hybrid/overlay granular zero 0.01\npair_coeff * * granular " + HK + "\npair_coeff * * zero\n")
S("B45_hybrid_overlay_granular_twice_mid", "run 300; pair_style hybrid/overlay granular granular; both kn 2000 on * * (twice the force)",
  "pair_style hybrid/overlay granular granular\npair_coeff * * granular 1 " + HK + "\npair_coeff * * granular 2 " + HK + "\n")
S("B46_hybrid_overlay_lj_mid", "run 300; pair_style hybrid/overlay granular lj/cut 0.01; lj 1 2 eps 1e-3 sigma 0.005 (a push between the pair)",
  "pair_style hybrid/overlay granular lj/cut 0.01\npair_coeff * * granular " + HK + "\npair_coeff * * lj/cut 0.0 0.001\npair_coeff 1 2 lj/cut 1e-3 0.0049\n")
S("B47_mass_command_mid", "run 300; mass 2 1.0 (per-type mass in atom_style sphere)", "mass 2 1.0\n")
S("B48_var_gravity_delete_redefine_same", "variable g equal 0; fix g2 lv2 gravity v_g; run 300; variable g delete; variable g equal 0.0 (control)",
  "variable g delete\nvariable g equal 0.0\n", pair=IN(0.1e-3) + "variable g equal 0.0\nfix g2 lv2 gravity v_g vector -1 0 0\n")
S("B49_fix_modify_move", "lv2 moved by fix move variable; run 300; fix_modify mv virial no (control)", "fix_modify mv virial no\n", pair=IN(0.1e-3) + MV)
S("B50_wallgran_zplane_far_mid", "run 300; fix w2 all wall/gran zplane 0.04 NULL (below both spheres, 7 mm off: control)", "fix w2 all wall/gran " + WG + " zplane 0.04 NULL\n")
SW("B51_ceiling_far_mid", "run 300; fix ceil all wall/gran zplane NULL 0.05 (a ceiling far above: control)",
   "fix ceil all wall/gran " + WG + " zplane NULL 0.05\n")
SW("B52_floor_region_added_cylinder_mid", "run 300; a wall/gran/region on a horizontal cylinder whose lowest line is z 0.0002 (a second surface 0.2 mm in)",
   "region cy cylinder x 0.02 0.0202 0.02 INF INF side in units box\nfix w2 all wall/gran/region " + WG + " region cy\n")

# ================================================================ B: LIGGGHTS
LGE = lambda m: "fix m3 all property/global coefficientRestitution peratomtypepair 3 " + m + "\n"
SG("B53_lig_e_11_only_mid", "run 300; coefficientRestitution redefined with only 1 1 changed (0.9; 1 2 kept 0.5: control)", LGE("0.9 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8"))
SG("B54_lig_e_12_only_mid", "run 300; coefficientRestitution redefined with only 1 2 changed (0.8)", LGE("0.6 0.8 0.7 0.8 0.4 0.45 0.7 0.45 0.8"))
SG("B55_lig_e_identical_mid", "run 300; coefficientRestitution redefined the same (control)", LGE("0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8"))
SG("B56_lig_mesh_behind_lv2_mid", "run 300; a mesh wall in plane x 0.0054 (lv2's far side ~0.00549: 0.09 mm in)",
   "fix cad2 all mesh/surface file wx.stl type 3\nfix mw all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad2\n",
   data={"wx.stl": stl_x(0.0054)})
SG("B57_lig_primitive_under_lv2_mid", "run 300; fix w2 all wall/gran primitive zplane 0.0975 (lv2's lowest point 0.097: 0.5 mm in)",
   "fix w2 all wall/gran model hertz tangential history primitive type 3 zplane 0.0975\n")
SG("B58_lig_contact_distance_factor_mid", "run 300; neigh_modify contactDistanceFactor 1.5 (control)", "neigh_modify contactDistanceFactor 1.5\n")
SG("B59_lig_viscous_lv1_mid", "run 300; fix vis lv1 viscous 0.02", "fix vis lv1 viscous 0.02\n")
LG("B60_lig_unfix_viscous_mid", "LIGGGHTS: fix vis lv2 viscous 0.05 from the start; run 300; unfix vis", "run 300\nunfix vis\nrun 2000\n",
   pair=LIN(0.1e-3) + "fix vis lv2 viscous 0.05\n", live="run 1 (and run 2)")
SG("B61_lig_pair_style_identical_mid", "run 300; pair_style gran hertz again; pair_coeff * * (control)", "pair_style gran model hertz tangential history\npair_coeff * *\n")
SG("B62_lig_pair_style_hooke_mid", "run 300; pair_style gran model hooke (law changed mid-contact)", "pair_style gran model hooke tangential history\npair_coeff * *\n")
LG("B63_lig_var_addforce_0_to_m05", "LIGGGHTS: variable f equal 0; fix af lv2 addforce v_f 0 0; run 300; variable f equal -0.5",
   "run 300\nvariable f equal -0.5\nrun 2000\n", pair=LIN(0.1e-3) + AF("0.0"), live="run 1 (and run 2)")
SG("B64_lig_young_type1_only_mid", "run 300; youngsModulus 5e7 for type 1 only (1 2 mixed changes)",
   "fix m1 all property/global youngsModulus peratomtype 5e7 5e6 5e6\n")
SWG("B65_lig_mesh_floor_above_mid", "run 300; a mesh floor at z 0.0002 added (0.2 mm into the sphere in contact)",
    "fix cad2 all mesh/surface file wz.stl type 3\nfix mw all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad2\n",
    data={"wz.stl": stl_z(0.0002)})
SWG("B66_lig_floor_e_13_only_mid", "run 300; coefficientRestitution with only 1 3 changed (0.3): the floor's e mid-contact",
    LGE("0.6 0.5 0.3 0.5 0.4 0.45 0.3 0.45 0.8"))
SG("B67_lig_create_atoms_at_lv2_mid", "run 300; create_atoms 1 at x 0.00739 (0.1 mm into lv2's far side); set atom 3 d 0.004",
   "create_atoms 1 single 0.00739 0 0.1 units box\nset atom 3 diameter 0.004 density 2500\n")
LG("B68_lig_var_gravity_lv2", "LIGGGHTS: variable g equal 0; fix g2 lv2 gravity v_g vector -1 0 0; run 300; variable g equal 1000",
   "run 300\nvariable g equal 1000.0\nrun 2000\n", pair=LIN(0.1e-3) + "variable g equal 0.0\nfix g2 lv2 gravity v_g vector -1 0 0\n", live="run 1 (and run 2)")

# ================================================================ B: a second set (regions and variables a fix reads, indirectly)
S("B69_var_indirect_redefined", "variable a equal 0; variable f equal v_a; addforce v_f; run 300; variable a equal -0.5",
  "variable a equal -0.5\n", pair=IN(0.1e-3) + "variable a equal 0.0\nvariable f equal v_a\nfix af lv2 addforce v_f 0.0 0.0\n")
RE = "region R block 0.035 0.04 0 0.04 0 0.1 units box\n"
RL = "region R delete\nregion R block 0.0215 0.04 0 0.04 0 0.1 units box\n"
S("B70_setforce_region_moved_to_lv2", "fix sf all setforce 0 0 0 region R (R empty, far); run 300; region R delete; R at lv2's side", RL,
  pair=IN(0.1e-3) + RE + "fix sf all setforce 0.0 0.0 0.0 region R\n")
S("B71_addforce_region_moved_to_lv2", "fix af all addforce -0.5 0 0 region R (empty); run 300; R at lv2's side", RL,
  pair=IN(0.1e-3) + RE + "fix af all addforce -0.5 0.0 0.0 region R\n")
S("B72_dynamic_group_region_moved", "group gd dynamic all region R (empty); fix vis gd viscous 0.05; run 300; R at lv2's side", RL,
  pair=IN(0.1e-3) + RE + "group gd dynamic all region R\nfix vis gd viscous 0.05\n")
S("B73_wall_union_subregion_moved", "wall/gran/region on intersect of a (plane x < 0.035, far) and b (x < 0.036); run 300; region a delete; a at x 0.0259 (lv2)",
  "region a delete\nregion a plane 0.0259 0 0 -1 0 0 units box\n",
  pair=IN(0.1e-3) + "region a plane 0.035 0 0 -1 0 0 units box\nregion b plane 0.036 0 0 -1 0 0 units box\nregion u intersect 2 a b\n"
  "fix w2 all wall/gran/region " + WG + " region u\n")
S("B74_setforce_region_redefined_still_empty", "setforce region R (empty); run 300; R delete; R again elsewhere, still empty (control)",
  "region R delete\nregion R block 0.036 0.04 0 0.04 0 0.1 units box\n", pair=IN(0.1e-3) + RE + "fix sf all setforce 0.0 0.0 0.0 region R\n")
SG("B75_lig_hooke_with_charvel_mid", "run 300; characteristicVelocity 1; pair_style gran model hooke (law changed mid-contact)",
   "fix cv all property/global characteristicVelocity scalar 1.0\npair_style gran model hooke tangential history\npair_coeff * *\n")
L("B76_addforce_elapsed", "addforce v_f, f = -0.5*(elapsed>200): run 300; run 2000 (the force from step 200 in run 1, again from 500 in run 2)",
  "run 300\nrun 2000\n", pair=IN(0.1e-3) + "variable f equal -0.5*(elapsed>200)*(elapsed<260)\nfix af lv2 addforce v_f 0.0 0.0\n", live="run 1 (and run 2)")
L("B77_viscous_scale_zero", "fix vis all viscous 0.05 scale 1 0 scale 2 0 (no type damped: control)", "run 3000\n",
  pair=IN(0.1e-3) + "fix vis all viscous 0.05 scale 1 0.0 scale 2 0.0\n")
S("B78_region_move_var_setforce", "setforce region R, R block with move v_dx (dx 0: empty far); run 300; variable dx equal -0.0135 (R over lv2)",
  "variable dx equal -0.0135\n", pair=IN(0.1e-3) + "variable dx equal 0.0\nregion R block 0.035 0.04 0 0.04 0 0.1 move v_dx NULL NULL units box\n"
  "fix sf all setforce 0.0 0.0 0.0 region R\n")
SW("B79_floor_region_delete_moved_down", "floor region plane fl at z 0; run 300; region fl delete; plane at z -0.0002 (the sphere let go 0.2 mm)",
   "region fl delete\nregion fl plane 0 0 -0.0002 0 0 1 units box\n", pre=RFL)

S("B80_var_internal_addforce", "variable f internal 0; addforce v_f; run 300; variable f internal -0.5", "variable f internal -0.5\n",
  pair=IN(0.1e-3) + "variable f internal 0.0\nfix af lv2 addforce v_f 0.0 0.0\n")
S("B81_var_immediate_capture_next", "variable a index 0.0 -0.5; variable f equal ${a} (0.0 captured); addforce v_f; run 300; next a (f stays 0: control)",
  "next a\n", pair=IN(0.1e-3) + "variable a index 0.0 -0.5\nvariable f equal ${a}\nfix af lv2 addforce v_f 0.0 0.0\n")
S("B82_viscous_scale_redefined_acting", "fix vis all viscous 0.05 scale 1 0 scale 2 0 (none damped); run 300; fix vis all viscous 0.05 (all damped)",
  "fix vis all viscous 0.05\n", pair=IN(0.1e-3) + "fix vis all viscous 0.05 scale 1 0.0 scale 2 0.0\n")

S("B83_nve_sphere_lv2_added_mid", "run 300; fix i2 lv2 nve/sphere (lv2 integrated twice from step 300)", "fix i2 lv2 nve/sphere\n")
S("B84_nve_lv2_added_mid", "run 300; fix i2 lv2 nve (lv2 moved twice a step)", "fix i2 lv2 nve\n")
S("B85_pour_at_lv2_mid", "run 300; fix pour of one 4 mm sphere just beyond lv2's far side, thrown at -10 m/s into it (before step 650)",
  "region pr block 0.0282 0.0312 0.018 0.022 0.048 0.052 units box\nfix pour all pour 1 1 4767548 region pr diam one 0.004 dens 2500 2500 vol 1.0 100 vel -10.0 -10.0 0.0 0.0 0.0\n")
S("B86_minimize_mid", "run 300; min_modify dmax 1e-4; minimize 0 0 10 100 (the atoms moved mid-contact)", "min_modify dmax 1e-4\nminimize 0.0 0.0 10 100\n")
S("B87_gravity_lv2_x_added_mid", "run 300; fix g2 lv2 gravity 1000 vector -1 0 0 (round 42's F13 again)", "fix g2 lv2 gravity 1000 vector -1 0 0\n")
S("B88_dynamic_group_var_redefined", "variable sel atom x>0.035; group gd dynamic all var sel; fix vis gd viscous 0.05; run 300; variable sel atom x>0.0215 (lv2 in gd)",
  "variable sel atom x>0.0215\n", pair=IN(0.1e-3) + "variable sel atom x>0.035\ngroup gd dynamic all var sel\nfix vis gd viscous 0.05\n")
S("B89_compute_redefined_under_var", "compute cc lv1 reduce sum vy (0); variable f equal -6000*c_cc; addforce v_f; run 300; uncompute cc; compute cc lv1 reduce sum c_pm, lv1's mass (f -0.5)",
  "uncompute cc\ncompute cc lv1 reduce sum c_pm\n", pair=IN(0.1e-3) + "compute pm lv1 property/atom mass\ncompute cc lv1 reduce sum vy\nvariable f equal -6000*c_cc\nfix af lv2 addforce v_f 0.0 0.0\n")
S("B90_gravity_all_x_mid", "run 300; fix grav all gravity 1000 vector 1 0 0 (the same on both: no relative change: control)", "fix grav all gravity 1000 vector 1 0 0\n")
S("B91_pour_far_mid", "run 300; fix pour of one sphere far off (control)",
  "region pr block 0.003 0.013 0.003 0.013 0.085 0.095 units box\nfix pour all pour 1 1 4767548 region pr diam one 0.004 dens 2500 2500\n")
S("B92_unfix_gravity_lv2_mid", "fix g2 lv2 gravity 1000 vector -1 0 0 from the start; run 300; unfix g2", "unfix g2\n",
  pair=IN(0.1e-3) + "fix g2 lv2 gravity 1000 vector -1 0 0\n")

# ================================================================ B: a fourth set (the reach of B73 and B85), after the audit
S("B93_wall_union_subregion_moved", "wall/gran/region on union of a (plane x < 0.035) and b (a block far off); run 300; region a delete; a at x < 0.0259 (lv2)",
  "region a delete\nregion a plane 0.0259 0 0 -1 0 0 units box\n",
  pair=IN(0.1e-3) + "region a plane 0.035 0 0 -1 0 0 units box\nregion b block 0.001 0.002 0.001 0.002 0.001 0.002 units box\nregion u union 2 a b\n"
  "fix w2 all wall/gran/region " + WG + " region u\n")
S("B94_wall_subregion_move_var", "wall/gran/region on intersect u of a (x < 0.035, move v_dx, dx 0) and b; run 300; variable dx equal -0.0091 (a's plane to x 0.0259: lv2)",
  "variable dx equal -0.0091\n",
  pair=IN(0.1e-3) + "variable dx equal 0.0\nregion a plane 0.035 0 0 -1 0 0 move v_dx NULL NULL units box\nregion b plane 0.036 0 0 -1 0 0 units box\n"
  "region u intersect 2 a b\nfix w2 all wall/gran/region " + WG + " region u\n")
B("B95_pour_at_lv2_before", "run 50; fix pour of one 4 mm sphere beyond lv2's far side thrown at -10 m/s (a three-body meeting)",
  "region pr block 0.0282 0.0312 0.018 0.022 0.048 0.052 units box\nfix pour all pour 1 1 4767548 region pr diam one 0.004 dens 2500 2500 vol 1.0 100 vel -10.0 -10.0 0.0 0.0 0.0\n")

# ================================================================ H: harmless between runs
HX = [
    ("print", 'print "between runs"\n'),
    ("thermo_style", "thermo_style custom step atoms ke\n"),
    ("thermo", "thermo 100\n"),
    ("dump", "dump d1 all custom 500 d.txt id x y z\nrun 0\nundump d1\n"),
    ("compute", "compute kea all ke/atom\n"),
    ("variable_unused", "variable q equal 2*3\n"),
    ("region_unused", "region Rn block 0 0.001 0 0.001 0 0.001 units box\n"),
    ("group_unused", "group gn id 1\n"),
    ("ave_time", "fix at all ave/time 10 1 10 c_thermo_temp\n"),
    ("balance", "balance 1.0 shift x 10 1.0\n"),
    ("neighbor_skin", "neighbor 0.003 bin\n"),
    ("thermo_modify", "thermo_modify lost warn flush yes\n"),
    ("fix_print", 'fix fp all print 100 "tick" screen yes\n'),
    ("compute_pair_local", "compute pl all pair/local dist\n"),
    ("neigh_every", "neigh_modify every 1 delay 0 check yes\n"),
    ("echo", "echo both\n"),
    ("group_delete", "group gn id 1\ngroup gn delete\n"),
    ("variable_delete", "variable q equal 1\nvariable q delete\n"),
    ("timestep_same", "timestep 1e-6\n"),
    ("comm_same", "comm_modify vel yes\n"),
    ("ave_time_var", "variable xx equal xcm(lv1,x)\nfix at all ave/time 10 1 10 v_xx\n"),
    ("unused_region_delete", "region Rn block 0 0.001 0 0.001 0 0.001 units box\nregion Rn delete\n"),
]
HX2 = [
    ("dump_modify", "dump d1 all custom 500 d.txt id x y z\ndump_modify d1 sort id\nrun 0\nundump d1\n"),
    ("fix_store_state", "fix ss all store/state 0 x y z\n"),
    ("compute_reduce", "compute kea all ke/atom\ncompute kr all reduce sum c_kea\nthermo_style custom step c_kr\n"),
    ("variable_atom_unused", "variable va atom mass*vx\n"),
    ("run_0", "run 0\n"),
    ("label", "label here\n"),
    ("info", "info variables\n"),
    ("group_region_unused", "region Rn block 0 0.001 0 0.001 0 0.001 units box\ngroup gr region Rn\n"),
]
for i, (n, x) in enumerate(HX, 1):
    S(f"H{i:02d}_{n}_mid", f"run 300; {x.strip().splitlines()[0]} (harmless: control)", x)
HW = [("print", HX[0][1]), ("thermo_style", HX[1][1]), ("region_unused", HX[6][1]), ("neighbor_skin", HX[10][1]), ("group_unused", HX[7][1]),
      ("ave_time", HX[8][1])]
for j, (n, x) in enumerate(HW, len(HX) + 1):
    SW(f"H{j:02d}_wall_{n}_mid", f"run 300; {x.strip().splitlines()[0]} (harmless: control)", x)
HL = [("print", HX[0][1]), ("thermo_style", "thermo_style custom step atoms ke\n"), ("region_unused", "region Rn block 0 0.001 0 0.001 0 0.001 units box\n"),
      ("group_unused", HX[7][1]), ("compute", HX[4][1]), ("variable_unused", HX[5][1]), ("neighbor_skin", "neighbor 0.003 bin\n"),
      ("ave_time", "fix at all ave/time 10 1 10 c_thermo_temp\n")]
for j, (n, x) in enumerate(HL, len(HX) + len(HW) + 1):
    SG(f"H{j:02d}_lig_{n}_mid", f"run 300; {x.strip().splitlines()[0]} (harmless: control)", x)
SWG("H37_lig_wall_print_mid", "run 300; print (harmless: control)", HX[0][1])
SWG("H38_lig_wall_group_unused_mid", "run 300; group gn id 1 (harmless: control)", HX[7][1])
for j, (n, x) in enumerate(HX2, 39):
    S(f"H{j:02d}_{n}_mid", f"run 300; {x.strip().splitlines()[0]} (harmless: control)", x)
SW("H47_wall_variable_unused_mid", "run 300; variable q equal 2*3 (harmless: control)", HX[5][1])
SW("H48_wall_print_before", "run 300; print; thermo 50; compute ke/atom (three harmless commands: control)", HX[0][1] + "thermo 50\n" + HX[4][1])
SG("H49_lig_dump_mid", "run 300; dump d1 ... run 0; undump (harmless: control)", "dump d1 all custom 500 d.txt id x y z\nrun 0\nundump d1\n")
SG("H50_lig_thermo_modify_mid", "run 300; thermo_modify lost ignore (harmless: control)", "thermo_modify lost ignore\n")
S("H51_kspace_none_mid", "run 300; kspace_style none (harmless: control)", "kspace_style none\n")
S("H52_unfix_untouched_floor_mid", "a floor at z 0 the pair (z 0.05) never touches; run 300; unfix floor (harmless to the pair: control)", "unfix floor\n", pre=BASE())
SG("H53_lig_friction_redefined_mid", "run 300; coefficientFriction 0.3 everywhere (head-on: no tangential force: control)",
   "fix m7 all property/global coefficientFriction peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3\n")

# ================================================================ O: other classes
S("O01_fmt_1g_pc", "run 300 (no change) ... pair_coeff 1 2 kn $(2499:%.1g) from the start (= 2e+03: 2000)", "",
  pair=IN(0.1e-3) + "pair_coeff 1 2 hooke $(2499:%.1g) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
L("O02_fmt_1g_pc_5", "pair_coeff 1 2 kn $(5499:%.1g) (= 5e+03: 5000, not 5499)", "run 3000\n",
  pair=IN(0.1e-3) + "pair_coeff 1 2 hooke $(5499:%.1g) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
L("O03_fmt_0f_pc", "pair_coeff 1 2 kn $(4999.7:%.0f) (5000: control)", "run 3000\n",
  pair=IN(0.1e-3) + "pair_coeff 1 2 hooke $(4999.7:%.0f) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
L("O04_fmt_2g_damp", "pair_coeff 1 2 damping $(3499:%.1g) (3e+03: 3000 not 3499)", "run 3000\n",
  pair=IN(0.1e-3) + "pair_coeff 1 2 hooke 2000 $(3499:%.1g) damping mass_velocity tangential linear_nohistory 1 0.3\n")
L("O05_fmt_if_3g_true", "if \"$(0.1+0.2:%.3g) == 0.3\" then pc 5000 (true)", 'if "$(0.1+0.2:%.3g) == 0.3" then "' + PCs(5000) + '"\nrun 3000\n')
L("O06_fmt_if_20g_false", "if \"$(0.1+0.2:%.20g) == 0.3\" then pc 5000 (false: 0.30000000000000004441)", 'if "$(0.1+0.2:%.20g) == 0.3" then "' + PCs(5000) + '"\nrun 3000\n')
L("O07_fmt_if_default_true", "if \"$(0.1+0.2) == 0.3\" then pc 5000 (the default %.15g: 0.3, true)", 'if "$(0.1+0.2) == 0.3" then "' + PCs(5000) + '"\nrun 3000\n')
L("O08_fmt_var_string", "variable k string $(v_kk:%.1g) with kk 5499; pc 1 2 kn ${k} (5000)", "run 3000\n",
  pair=IN(0.1e-3) + "variable kk equal 5499\nvariable k string $(v_kk:%.1g)\npair_coeff 1 2 hooke ${k} 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
L("O09_fmt_set_density", "set atom 2 density $(4499:%.1g) (4000 not 4499)", "run 3000\n", pair=IN(0.1e-3) + "set atom 2 density $(4499:%.1g)\n")
L("O10_fmt_if_1g_eq", "if \"$(2499:%.1g) == 2000\" then pc 5000 (true)", 'if "$(2499:%.1g) == 2000" then "' + PCs(5000) + '"\nrun 3000\n')
L("O11_fmt_15g_third", "pair_coeff 1 2 kn $(6000/3:%.15g) (2000: control)", "run 3000\n",
  pair=IN(0.1e-3) + "pair_coeff 1 2 hooke $(6000/3:%.15g) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
L("O12_fmt_e_pc", "pair_coeff 1 2 kn $(5432.1:%.2e) (5.43e+03)", "run 3000\n",
  pair=IN(0.1e-3) + "pair_coeff 1 2 hooke $(5432.1:%.2e) 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
L("O13_fmt_if_else_branch", "if \"$(7/3:%.2f) > 2.333\" then pc 5000 else pc 3000 (2.33: else, 3000)",
  'if "$(7/3:%.2f) > 2.333" then "' + PCs(5000) + '" else "' + PCs(3000) + '"\nrun 3000\n')
# type ranges on 4 types: the live pair types 2 3
R4 = RB.replace("create_box 2 box", "create_box 4 box")
IN23 = IN(0.1e-3, t1=2, t2=3)
T4 = lambda name, desc, pc, **kw: L(name, "4 types, the pair 2 3: " + desc, "run 3000\n", pre=R4 + pc, pair=IN23, PAIR="types 2 3", **kw)
T4("O14_range_star_2", "pair_coeff * 2 kn 5000 (1 2, 2 2: not 2 3: 2000)", "pair_coeff * 2 " + HKk(5000) + "\n")
T4("O15_range_23_12", "pair_coeff 2*3 1*2 kn 5000 (only 2 2: 2000)", "pair_coeff 2*3 1*2 " + HKk(5000) + "\n")
T4("O16_range_2star_star", "pair_coeff 2* * kn 5000 (2 3 in it: 5000)", "pair_coeff 2* * " + HKk(5000) + "\n")
T4("O17_range_reversed_3_2", "pair_coeff 3 2 kn 5000 (reversed)", "pair_coeff 3 2 " + HKk(5000) + "\n")
T4("O18_range_24_34", "pair_coeff 2*4 3*4 kn 5000 (2 3 in it)", "pair_coeff 2*4 3*4 " + HKk(5000) + "\n")
T4("O19_range_star3_3star", "pair_coeff *3 3* kn 5000 (2 3 in it)", "pair_coeff *3 3* " + HKk(5000) + "\n")
T4("O20_range_3star_12", "pair_coeff 3* 1*2 kn 5000 (nothing set: the engine stops?)", "pair_coeff 3* 1*2 " + HKk(5000) + "\n")
T4("O21_range_12_star_then_33", "pair_coeff 1*2 * kn 5000 then 3*3 3* kn 3000 (2 3: 5000)", "pair_coeff 1*2 * " + HKk(5000) + "\npair_coeff 3*3 3* " + HKk(3000) + "\n")
T4("O22_range_3star_3star", "pair_coeff 3* 3* kn 5000 (3 3, 3 4, 4 4: not 2 3)", "pair_coeff 3* 3* " + HKk(5000) + "\n")
T4("O23_labels", "labelmap atom 1 ta 2 sm 3 bg 4 td; pair_coeff sm bg kn 5000", "labelmap atom 1 ta 2 sm 3 bg 4 td\npair_coeff sm bg " + HKk(5000) + "\n")
T4("O24_labels_reversed", "labelmap; pair_coeff bg sm kn 5000", "labelmap atom 1 ta 2 sm 3 bg 4 td\npair_coeff bg sm " + HKk(5000) + "\n")
T4("O25_labels_range_mixed", "labelmap; pair_coeff sm * kn 5000 (2 2, 2 3, 2 4)", "labelmap atom 1 ta 2 sm 3 bg 4 td\npair_coeff sm * " + HKk(5000) + "\n")
# set order
PSET = lambda lines: ("create_atoms 1 single 0.017950 0.02 0.05\ncreate_atoms 2 single 0.023050 0.02 0.05\n" + lines +
                      "group lv1 id 1\ngroup lv2 id 2\nvelocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\n")
L("O26_set_density_then_diameter", "set atom 2 density 2500, then set atom 2 diameter 0.006 (the mass of a 1 m sphere at 2500?)", "run 3000\n",
  pair=PSET("set atom 1 diameter 0.004 density 2500\nset atom 2 density 2500\nset atom 2 diameter 0.006\n"))
L("O27_set_one_line_density_first", "set atom 2 density 2500 diameter 0.006 (one line, density first)", "run 3000\n",
  pair=PSET("set atom 1 diameter 0.004 density 2500\nset atom 2 density 2500 diameter 0.006\n"))
L("O28_set_type_before_create", "set type 2 diameter 0.006 density 2500 before create_atoms 2; then set atom 2 diameter 0.006 only", "run 3000\n",
  pair=("create_atoms 1 single 0.017950 0.02 0.05\nset atom 1 diameter 0.004 density 2500\nset type 2 diameter 0.006 density 2500\n"
        "create_atoms 2 single 0.023050 0.02 0.05\nset atom 2 diameter 0.006\ngroup lv1 id 1\ngroup lv2 id 2\n"
        "velocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\n"))
L("O29_set_atom_range_past", "set atom 2*3 density 5000 after the pair (only atom 2 exists: 5000 for lv2)", "run 3000\n", pair=IN(0.1e-3) + "set atom 2*3 density 5000\n")
L("O30_set_mass_after_density", "set atom 2 mass 1e-4 after density 2500 (lighter than 2.83e-4)", "run 3000\n", pair=IN(0.1e-3) + "set atom 2 mass 1e-4\n")
L("O31_set_diameter_after_density_bigger", "set atom 2 diameter 0.008 after density (mass kept? lv2 placed 1 mm further)", "run 3000\n",
  pair=IN(0.1e-3).replace("create_atoms 2 single 0.023050", "create_atoms 2 single 0.024050") + "set atom 2 diameter 0.008\n")
L("O32_set_density_area_style", "set type 2 density 5000, then a third atom of type 2 made far off and set to 2500 (lv2 5000)", "run 3000\n",
  pair=IN(0.1e-3) + "set type 2 density 5000\ncreate_atoms 2 single 0.005 0.005 0.09\nset atom 3 diameter 0.004 density 2500\n")
# LIGGGHTS material types and matrices
L4 = LBASE(nt=4, e="0.6 0.5 0.7 0.65 0.5 0.4 0.45 0.7 0.7 0.45 0.8 0.7 0.65 0.7 0.7 0.8").replace("primitive type 4", "primitive type 4")
LG("O33_lig_wall_only_type4", "LIGGGHTS WALL: 4 material types, the floor type 4 only (e 1 4 0.65)", "run 3000\n", pre=L4, pair=LWALL(1e-4), **LWK)
LG("O34_lig_pair_type4_matrix", "LIGGGHTS: 4 material types (floor type 4), the pair 1 2 e 0.5", "run 3000\n", pre=L4)
LG("O35_lig_asym_pair_matrix", "LIGGGHTS: e matrix with 1 2 = 0.5 and 2 1 = 0.8 (not symmetric)", "run 3000\n",
   pre=LBASE(e="0.6 0.5 0.7 0.8 0.4 0.45 0.7 0.45 0.8"))
LG("O36_lig_asym_wall_matrix", "LIGGGHTS WALL: e matrix with 1 3 = 0.7 and 3 1 = 0.3", "run 3000\n", pre=LBASE(e="0.6 0.5 0.7 0.5 0.4 0.45 0.3 0.45 0.8"),
   pair=LWALL(1e-4), **LWK)
LG("O37_lig_fmt_e", "LIGGGHTS: coefficientRestitution 1 2 = $(0.54:%.1f) (0.5)", "run 3000\n",
   pre=LBASE(e="0.6 $(0.54:%.1f) 0.7 $(0.54:%.1f) 0.4 0.45 0.7 0.45 0.8"))
LG("O38_lig_wall_type3_unused_by_particles_e_fmt", "LIGGGHTS WALL: e 1 3 = $(0.66:%.1f) (0.7)", "run 3000\n",
   pre=LBASE(e="0.6 0.5 $(0.66:%.1f) 0.5 0.4 0.45 $(0.66:%.1f) 0.45 0.8"), pair=LWALL(1e-4), **LWK)
# size ranges with hertz laws (pour far above the pair)
HM = "hertz/material 1e7 0.5 0.3 damping tsuji tangential linear_nohistory 1 0.3"
HZ = "hertz 1e7 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
POUR = lambda d: "region pr block 0.001 0.039 0.001 0.039 0.085 0.098 units box\nfix pour all pour 4 1 4767548 region pr " + d + " dens 2500 2500\n"
L("O39_pour_range_hertz_material", "pair_coeff * * hertz/material E 1e7 e 0.5 tsuji; fix pour type 1 diam range 0.003 0.005 far above", "run 3000\n",
  pre=BASE(wall=False, coeff="pair_coeff * * " + HM + "\n"), pair=IN(0.1e-3) + POUR("diam range 0.003 0.005"))
L("O40_pour_range_hertz_massvel", "pair_coeff * * hertz 1e7 mass_velocity; fix pour type 1 diam range 0.003 0.005 far above", "run 3000\n",
  pre=BASE(wall=False, coeff="pair_coeff * * " + HZ + "\n"), pair=IN(0.1e-3) + POUR("diam range 0.003 0.005"))
L("O41_pour_poly_hertz_massvel", "hertz 1e7 mass_velocity; fix pour type 1 diam poly 2 0.003 0.5 0.005 0.5", "run 3000\n",
  pre=BASE(wall=False, coeff="pair_coeff * * " + HZ + "\n"), pair=IN(0.1e-3) + POUR("diam poly 2 0.003 0.5 0.005 0.5"))
L("O42_hertz_massvel_control", "hertz 1e7 mass_velocity, no pour (control)", "run 3000\n", pre=BASE(wall=False, coeff="pair_coeff * * " + HZ + "\n"))
# region walls
RW = lambda reg: BASE(wall=False) + reg + "fix floor all wall/gran/region " + WG + " region cy\n"
L("O43_region_cylinder_in_floor", "WALL: the floor a wall/gran/region cylinder along x (side in), lowest line z 0", "run 3000\n",
  pre=RW("region cy cylinder x 0.02 0.02 0.02 INF INF side in units box\n"), pair=WALLP(), **WALL)
L("O44_region_cylinder_out_floor", "WALL: a cylinder along x (side out) under the sphere, top line z 0", "run 3000\n",
  pre=RW("region cy cylinder x 0.02 -0.02 0.02 INF INF side out units box\n"), pair=WALLP(), **WALL)
L("O45_region_sphere_in_floor", "WALL: a sphere region (side in) of radius 0.02 centred 0.02 above the floor's point", "run 3000\n",
  pre=RW("region cy sphere 0.02 0.02 0.02 0.02 side in units box\n"), pair=WALLP(), **WALL)
L("O46_region_cone_floor", "WALL: a cone along z (side in) with its open top wide: the sphere meets the floor cap z 0?", "run 3000\n",
  pre=RW("region cy cone z 0.02 0.02 0.015 0.018 0 0.05 side in units box\n"), pair=WALLP(), **WALL)
# hybrid granular + another style
L("O47_hybrid_granular_lj_11", "pair_style hybrid granular lj/cut 0.01; granular on * *, lj/cut on 1 1 only (1 2 granular: control)", "run 3000\n",
  pre=BASE(wall=False, pstyle="pair_style hybrid granular lj/cut 0.01\n", coeff="pair_coeff * * granular " + HK + "\npair_coeff 1 1 lj/cut 1e-3 0.004\n"))
L("O48_hybrid_overlay_granular_lj_12", "hybrid/overlay granular lj/cut 0.01: lj on 1 2 eps 1e-3 sigma 0.0049", "run 3000\n",
  pre=BASE(wall=False, pstyle="pair_style hybrid/overlay granular lj/cut 0.01\n",
           coeff="pair_coeff * * granular " + HK + "\npair_coeff * * lj/cut 0.0 0.001\npair_coeff 1 2 lj/cut 1e-3 0.0049\n"))
L("O49_hybrid_overlay_granular_twice", "hybrid/overlay granular granular, kn 2000 each on * * (the forces add)", "run 3000\n",
  pre=BASE(wall=False, pstyle="pair_style hybrid/overlay granular granular\n",
           coeff="pair_coeff * * granular 1 " + HK + "\npair_coeff * * granular 2 " + HK + "\n"))
L("O50_hybrid_granular_zero_12", "pair_style hybrid granular zero 0.01: 1 2 zero (no force: they pass)", "run 3000\n",
  pre=BASE(wall=False, pstyle="pair_style hybrid granular zero 0.01\n", coeff="pair_coeff * * granular " + HK + "\npair_coeff 1 2 zero\n"))
L("O51_hybrid_granular_granular_12_k5", "hybrid granular granular: granular 1 on * *, granular 2 kn 5000 on 1 2 (5000)", "run 3000\n",
  pre=BASE(wall=False, pstyle="pair_style hybrid granular granular\n",
           coeff="pair_coeff * * granular 1 " + HK + "\npair_coeff 1 2 granular 2 " + HKk(5000) + "\n"))
L("O52_hybrid_overlay_granular_soft_zero", "hybrid/overlay granular soft 0.01 with soft A 0 on * * (control)", "run 3000\n",
  pre=BASE(wall=False, pstyle="pair_style hybrid/overlay granular soft 0.01\n", coeff="pair_coeff * * granular " + HK + "\npair_coeff * * soft 0.0\n"))
# coarse time steps of the deck's own
DT = lambda dt: RB.replace("timestep 1e-6", f"timestep {dt}")
L("O53_dt_5e5", "timestep 5e-5 (about 12 steps a contact)", "run 60\n", pre=DT("5e-5"))
L("O54_dt_1e4", "timestep 1e-4 (about 6 steps a contact)", "run 30\n", pre=DT("1e-4"))
L("O55_dt_2e4", "timestep 2e-4 (about 3 steps a contact)", "run 15\n", pre=DT("2e-4"))
L("O56_dt_1e4_wall", "WALL: timestep 1e-4", "run 30\n", pre=BASE().replace("timestep 1e-6", "timestep 1e-4"), pair=WALLP(), **WALL)
LG("O57_lig_dt_5e5", "LIGGGHTS: timestep 5e-5", "run 60\n", pre=LBASE().replace("timestep 1e-6", "timestep 5e-5"))
LG("O58_lig_dt_2e4", "LIGGGHTS: timestep 2e-4", "run 15\n", pre=LBASE().replace("timestep 1e-6", "timestep 2e-4"))
L("O59_dt_1e4_kn5000", "timestep 1e-4 with kn 5000 (about 4 steps)", "run 30\n", pre=DT("1e-4"), pair=IN(0.1e-3) + PC5)

# ================================================================ O: a second set
L("O60_var_format_style", "variable k0 equal 5499; variable k format k0 %.1g; pair_coeff 1 2 kn ${k} (5e+03)", "run 3000\n",
  pair=IN(0.1e-3) + "variable k0 equal 5499\nvariable k format k0 %.1g\npair_coeff 1 2 hooke ${k} 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
L("O61_equal_var_subst_if", "variable q equal 0.1+0.2; if \"${q} == 0.3\" then pc 5000 (${} of an equal-style variable: %.15g?)",
  'variable q equal 0.1+0.2\nif "${q} == 0.3" then "' + PCs(5000) + '"\nrun 3000\n')
L("O62_static_group_before_create", "group t2 type 2 before create_atoms 2 (static: empty); set group t2 density 5000 after (no atom)", "run 3000\n",
  pair=("create_atoms 1 single 0.017950 0.02 0.05\ngroup t2 type 2\ncreate_atoms 2 single 0.023050 0.02 0.05\n"
        "set atom 1 diameter 0.004 density 2500\nset atom 2 diameter 0.006 density 2500\nset group t2 density 5000\ngroup lv1 id 1\ngroup lv2 id 2\n"
        "velocity lv1 set 0.7714285714 0 0 units box\nvelocity lv2 set -0.2285714286 0 0 units box\n"))
L("O63_set_region_density", "set region R density 5000, R around lv2 only", "run 3000\n",
  pair=IN(0.1e-3) + "region R block 0.0215 0.04 0 0.04 0 0.1 units box\nset region R density 5000\n")
L("O64_set_density_then_smaller_diameter", "set type 2 density 5000 (6 mm), then set atom 2 diameter 0.003 (mass kept), lv2 placed 1.5 mm nearer", "run 3000\n",
  pair=IN(0.1e-3).replace("create_atoms 2 single 0.023050", "create_atoms 2 single 0.021550") + "set type 2 density 5000\nset atom 2 diameter 0.003\n")
L("O65_region_block_out_floor", "WALL: the floor a wall/gran/region block z < 0 with side out", "run 3000\n",
  pre=RW("region cy block INF INF INF INF -1 0 side out units box\n"), pair=WALLP(), **WALL)
L("O66_fmt_if_string_numeric", "if \"$(2499:%.1g) == 2e+03\" then pc 5000 (both numbers: true)", 'if "$(2499:%.1g) == 2e+03" then "' + PCs(5000) + '"\nrun 3000\n')
L("O67_fmt_round_var", "variable k equal round(5499/1000)*1000 (5000)", "run 3000\n",
  pair=IN(0.1e-3) + "variable k equal round(5499/1000)*1000\npair_coeff 1 2 hooke ${k} 3000 damping mass_velocity tangential linear_nohistory 1 0.3\n")
T4("O68_set_type_range_density", "set type 2*3 density 5000 (both live spheres 5000)", "", )
DECKS["O68_set_type_range_density"] = (DECKS["O68_set_type_range_density"][0].replace("run 3000\n", "set type 2*3 density 5000\nrun 3000\n"),) + DECKS["O68_set_type_range_density"][1:]
L4m = LBASE(nt=4, e="0.6 0.5 0.7 0.65 0.5 0.4 0.45 0.7 0.7 0.45 0.8 0.7 0.65 0.7 0.7 0.8", wall=False)
LG("O69_lig_mesh_type4_floor", "LIGGGHTS WALL: 4 types, a mesh floor of type 4 only (e 1 4 0.65)", "run 3000\n",
   pre=L4m + "fix cad all mesh/surface file wz.stl type 4\nfix wprim all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n",
   pair=LWALL(1e-4), data={"wz.stl": stl_z(0.0)}, **LWK)

NP2 = []
if __name__ == "__main__":
    names = sys.argv[1:]
    m7.big = lambda *a, **k: None
    m7.lmp_gen = lambda *a, **k: None
    m7.write(names)
    for n in m7.DECKS:
        if not names or any(n.startswith(p) for p in names):
            open(os.path.join(m7.D, n, "NP"), "w").write("1 2\n" if any(n.startswith(p) for p in NP2) else "1\n")

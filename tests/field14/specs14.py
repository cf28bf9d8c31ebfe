"""Field round 14: each deck's spec.json for round 13's referee (tests/field13/referee13.py, which runs round
10's head-on referee unchanged), from the sizes and masses the engine itself holds at the end of the deck
(engine_state.txt beside each deck, written by tests/field12/engine_state.py or tests/field13/liggghts_state.py)
and the deck's own contact lines. usage: python specs14.py [DECKID ...]"""
import json, os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit.specs import FLOOR, LL, P13 as P, W13 as W, m  # noqa: E402,F401  (rounds 13-14's)

D = os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks")
HK = "hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
JKR = "jkr 1e7 3000 0.3 0.5 damping mass_velocity tangential linear_nohistory 1 0.3"
DMT = "dmt 1e7 3000 0.3 0.5 damping mass_velocity tangential linear_nohistory 1 0.3"
HM = "hertz/material 1e7 1.4e7 0.3 damping viscoelastic tangential linear_nohistory 1 0.3"


m2, m3 = m(0.002, 2500), m(0.003, 2500)
m25_2000 = m(0.0025, 2000)
S = {
 "p01_star_after_jkr_overrides": {"engine": "lammps", "lines": LL + [f"pair_coeff 1 2 {JKR}",
    "pair_coeff * * hooke 4000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"], "checks": [
    P(1, 2, 0.002, m2, 0.003, m3), P(1, 1, 0.002, m2)]},
 "p02_range_jkr_then_specific": {"engine": "lammps", "ntypes": 3, "lines": LL + [f"pair_coeff 1 * {JKR}",
    "pair_coeff 1 1 hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"], "checks": [
    P(1, 1, 0.002, m2), P(2, 3, 0.003, m3, 0.0025, m25_2000)]},
 "p03_labels_reversed_dmt": {"engine": "lammps", "pre": ["labelmap atom 1 glass 2 steel"], "lines": ["pair_style granular",
    f"pair_coeff glass glass {HK}", "pair_coeff steel steel hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3",
    f"pair_coeff steel glass {DMT}"], "checks": [P(2, 2, 0.003, m3), P(1, 1, 0.002, m2)]},
 "p12b_mixed_all_cohesion0": {"engine": "lammps", "lines": ["pair_style granular",
    "pair_coeff 1 1 jkr 1e7 3000 0.3 0 damping mass_velocity tangential linear_nohistory 1 0.3",
    "pair_coeff 2 2 jkr 2e7 3000 0.3 0 damping mass_velocity tangential linear_nohistory 1 0.3"], "checks": [
    P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[0, 2, 4]), P(2, 2, 0.003, m3, speed_idx=[0, 2])]},
 "p04_hybrid_instances_jkr_22": {"engine": "lammps", "lines": ["pair_style hybrid granular granular",
    f"pair_coeff * * granular 1 {HK}", f"pair_coeff 2 2 granular 2 {JKR}"], "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
 "p05_cutoff_keyword_near_contact": {"engine": "lammps", "lines": LL + [f"pair_coeff 1 1 {HK} cutoff 0.0039",
    f"pair_coeff 2 2 {HK} cutoff 0.001"], "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
 "p06_range_rule_empty_second": {"engine": "lammps", "ntypes": 3, "lines": LL + [f"pair_coeff 2*3 1*2 {JKR}",
    "pair_coeff * 1 hooke 3000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"], "checks": [
    P(1, 1, 0.002, m2), P(1, 2, 0.002, m2, 0.003, m3), P(2, 3, 0.003, m3, 0.0025, m25_2000)]},
 "p07_jkr_then_later_mapped_same_pair": {"engine": "lammps", "lines": LL + [
    "pair_coeff 1 2 hooke 6000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"], "checks": [
    P(1, 2, 0.002, m2, 0.003, m3, stage=2)]},
 "p08_dmt_22_limit_damping_others": {"engine": "lammps", "lines": ["pair_style granular", f"pair_coeff * * {HM} limit_damping",
    f"pair_coeff 2 2 {DMT}"], "checks": [P(1, 2, 0.002, m2, 0.003, m3),
    W(1, 0.002, m2, wall=f"fix floor all wall/gran granular {HM} limit_damping zplane 0 NULL")]},
 "q02_hybrid_sphere_bond_read_data": {"engine": "lammps", "lines": LL, "checks": [
    P(1, 2, 0.002, m2, 0.003, 0.00011309734), W(2, 0.003, 0.00011309734)]},
 "q03_set_mass_then_diameter": {"engine": "lammps", "lines": LL, "checks": [P(1, 1, 0.0025, 1e-4), W(1, 0.0025, 1e-4)]},
 "r01_adapt_diameter_mass_no": {"engine": "lammps", "lines": LL, "checks": [
    P(1, 2, 0.003, m2, stage=2), W(1, 0.003, m2, stage=2)]},
 "r02_adapt_diameter_scale_yes": {"engine": "lammps", "lines": LL, "checks": [
    P(1, 2, 0.003, m3, stage=2), W(1, 0.003, m3, stage=2)]},
 "r02b_adapt_scale_constant": {"engine": "lammps", "lines": LL, "checks": [
    P(1, 2, 0.003, m3, stage=2), W(1, 0.003, m3, stage=2)]},
 "r18_adapt_ramp_growth": {"engine": "lammps", "lines": LL, "checks": [
    P(1, 2, 0.003, m3, stage=2), P(2, 2, 0.003, m3, stage=2), W(1, 0.003, m3, stage=2)]},
 "r20_adapt_elapsed_growth": {"engine": "lammps", "lines": LL, "checks": [
    P(1, 2, 0.003, m3, stage=2), W(1, 0.003, m3, stage=2)]},
 "p09_hybrid_granular_and_granhooke_jkr11": {"engine": "lammps", "lines": ["pair_style hybrid granular gran/hooke/history 2000 NULL 3000 NULL 0.3 1",
    "pair_coeff * * gran/hooke/history", f"pair_coeff 1 1 granular {JKR}"], "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
 "p10_labels_star_with_label_jkr": {"engine": "lammps", "ntypes": 3, "pre": ["labelmap atom 1 a 2 b 3 c"], "lines": LL + [f"pair_coeff * c {JKR}"],
    "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
 "p11_data_pairij_jkr_row": {"engine": "lammps", "lines": ["pair_style granular", f"pair_coeff 1 1 {HK}", f"pair_coeff 1 2 {JKR}", f"pair_coeff 2 2 {HK}",
    "pair_coeff 1 1 hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"], "checks": [P(1, 1, 0.002, m2), P(2, 2, 0.003, m3)]},
 "q04_hybrid_sphere_bond_mass_cmd": {"engine": "lammps", "atom_style": "hybrid sphere bond", "pre": ["mass * 1.0"], "lines": LL, "checks": [
    P(1, 2, 0.002, m2, 0.003, m3)]},
 "w08_wall_on_region_group": {"engine": "lammps", "lines": LL, "checks": [
    W(2, 0.003, m3, wall=f"fix wr all wall/gran granular {HK} zplane 0 NULL", wall_id="wr", speed_idx=[0, 2, 4], label="wr row vs wr + wl (engine truth)",
      spec_override={"post": ["fix wl all wall/gran granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL"]}),
    W(1, 0.002, m2, wall=f"fix wr all wall/gran granular {HK} zplane 0 NULL", wall_id="wr")]},
 "r17_vdisplace_swiggle_between_runs": {"engine": "lammps", "lines": ["pair_style granular",
    "pair_coeff * * hooke 3500 3000 damping mass_velocity tangential linear_nohistory 1 0.3"], "checks": [
    P(1, 1, 0.002, 0.00020106193, stage=2), P(1, 2, 0.002, 0.00020106193, 0.003, m3, stage=2)]},
 "x07_run0_only_in_loop": {"engine": "lammps", "lines": ["pair_style granular",
    "pair_coeff * * hooke 4000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"], "checks": [
    P(1, 2, 0.002, m2, 0.003, m3, stage=3)]},
 "r06_adapt_fep_diameter": {"engine": "lammps", "lines": LL, "checks": [
    P(1, 2, 0.002, m2, 0.003, m3), P(2, 2, 0.003, m3), W(2, 0.003, m3)]},
 "r03_adapt_group_type2_only": {"engine": "lammps", "lines": LL, "checks": [
    P(1, 2, 0.002, m2, 0.003, m3, stage=2), W(2, 0.003, m3, stage=2)]},
 "r09_bound_zmax_sets_density": {"engine": "lammps", "lines": LL, "checks": [
    P(1, 1, 0.002, 4.3558771e-05, stage=2), W(1, 0.002, 4.3558771e-05, stage=2)]},
 "r11_temp_read_if": {"engine": "lammps", "lines": LL, "checks": [P(1, 2, 0.002, 3.3510322e-05, 0.003, m3, stage=2)]},
 "r12_compute_ke_read_if": {"engine": "lammps", "lines": LL, "checks": [P(1, 1, 0.002, 3.3510322e-05, stage=2)]},
 "r13_dt_reset_then_coeff_from_dt": {"engine": "lammps", "lines": ["pair_style granular",
    "pair_coeff * * hooke 200 3000 damping mass_velocity tangential linear_nohistory 1 0.3"], "checks": [
    P(1, 1, 0.002, m2, stage=2)]},
 "r14_vcm_read_if": {"engine": "lammps", "lines": LL, "checks": [W(1, 0.002, 3.3510322e-05, stage=2)]},
 "r15_deform_vol_if": {"engine": "lammps", "lines": LL, "checks": [P(1, 2, 0.002, 3.3510322e-05, 0.003, m3, stage=2)]},
 "t01_hertzmat_two_sizes_coarse_dt": {"engine": "lammps", "lines": ["pair_style granular", f"pair_coeff * * {HM}"], "checks": [
    P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[0, 2], at_dt=True),
    W(2, 0.003, m3, wall=f"fix floor all wall/gran granular {HM} zplane 0 NULL", speed_idx=[0], at_dt=True)]},
 "t02_tsuji_unequal_masses_coarse_dt": {"engine": "lammps", "lines": ["pair_style granular",
    "pair_coeff * * hooke 2000 0.5 damping tsuji tangential linear_nohistory 1 0.3 limit_damping"], "checks": [
    P(2, 2, 0.003, m(0.003, 8000), at_dt=True),
    W(2, 0.003, m(0.003, 8000), wall="fix floor all wall/gran granular hooke 2000 0.5 damping tsuji tangential linear_nohistory 1 0.3 limit_damping zplane 0 NULL", at_dt=True)]},
 "t03_coeffrest_hertz_limit_coarse": {"engine": "lammps", "lines": ["pair_style granular",
    "pair_coeff * * hertz/material 1e7 0.5 0.3 damping coeff_restitution tangential linear_nohistory 1 0.3 limit_damping"], "checks": [
    W(2, 0.003, m3, wall="fix floor all wall/gran granular hertz/material 1e7 0.5 0.3 damping coeff_restitution tangential linear_nohistory 1 0.3 limit_damping zplane 0 NULL", speed_idx=[0, 2], at_dt=True)]},
 "w01_zplane_lo_hi_one_fix_narrow": {"engine": "lammps", "lines": LL, "checks": [
    W(1, 0.002, m2, wall=f"fix w all wall/gran granular {HK} zplane 0 0.0041", wall_id="w", speed_idx=[0, 2, 3, 4])]},
 "w02_yplane_hele_shaw_two_fixes": {"engine": "lammps", "lines": LL, "checks": [
    W(1, 0.002, m2, wall=f"fix wy1 all wall/gran granular {HK} yplane -0.0021 NULL", wall_id="wy1", axis="y", z0=-0.0001, zw=-0.0021,
      speed_idx=[2, 3, 4], label="wy1 with wy2 (engine: both fixes)",
      spec_override={"post": ["fix wy2 all wall/gran granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 yplane NULL 0.0021"]})]},
 "w03_region_sphere_side_out_hertz": {"engine": "lammps", "lines": ["pair_style granular", f"pair_coeff * * {HM}"],
    "pre": ["region ball sphere 0 0 0 0.01 side out units box"], "checks": [
    W(1, 0.002, m2, wall=f"fix wb all wall/gran/region granular {HM} region ball", wall_id="wb", z0=0.012, zw=0.01, speed_idx=[0, 2, 4])]},
 "w03b_region_sphere_side_out_coarse_dt": {"engine": "lammps", "lines": ["pair_style granular", f"pair_coeff * * {HM}"],
    "pre": ["region ball sphere 0 0 0 0.01 side out units box"], "checks": [
    W(1, 0.002, m2, wall=f"fix wb all wall/gran/region granular {HM} region ball", wall_id="wb", z0=0.012, zw=0.01, speed_idx=[0, 2], at_dt=True)]},
 "w04b_zcylinder_coarse_dt": {"engine": "lammps", "lines": ["pair_style granular", f"pair_coeff * * {HM}"], "checks": [
    W(1, 0.002, m2, wall=f"fix cyl all wall/gran granular {HM} zcylinder 0.0075", wall_id="cyl", axis="x", z0=0.0055, zw=0.0075, sign=-1,
      speed_idx=[0, 2], at_dt=True)]},
 "w15_oscillating_plane_region_hooke": {"engine": "lammps", "lines": LL,
    "pre": ["variable zw equal 0.0005*sin(2*PI*time/0.01)", "region pl plane 0 0 0 0 0 1 side in move NULL NULL v_zw units box"], "checks": [
    W(1, 0.002, m2, wall="fix rw all wall/gran/region granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 region pl",
      wall_id="rw", speed_idx=[0, 2, 4], label="rw, the sphere meeting the plane at t = 0 (the plane rising at 0.31 m/s)")]},
 "w16_block_open_bottom_on_floor": {"engine": "lammps", "lines": LL,
    "pre": ["region cup block -0.015 0.015 -0.015 0.015 0 0.04 open 5 units box"], "checks": [
    W(1, 0.002, m2, wall="fix floor all wall/gran granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 zplane 0 NULL",
      speed_idx=[0, 2, 4], label="floor row vs floor + the open-bottomed block wall (engine truth)",
      spec_override={"post": [f"fix wc all wall/gran/region granular {HK} region cup"]})]},
 "w17_rocking_plane_region_hooke": {"engine": "lammps", "lines": LL,
    "pre": ["variable th equal 0.05*sin(2*PI*time/0.01)", "region pl plane 0 0 0 0 0 1 side in rotate v_th 0 0 0 0 1 0 units box"], "checks": [
    W(1, 0.002, m2, wall="fix rw all wall/gran/region granular hooke 5000 3000 damping mass_velocity tangential linear_nohistory 1 0.3 region pl",
      wall_id="rw", x=0.01, speed_idx=[0, 2, 4], label="rw at x = 0.01, met at t = 0 (the plane turning at 31 rad/s)")]},
 "w04_zcylinder_and_floor_edge": {"engine": "lammps", "lines": ["pair_style granular", f"pair_coeff * * {HM}"], "checks": [
    W(1, 0.002, m2, wall=f"fix floor all wall/gran granular {HM} zplane 0 NULL", x=0.0079, label="floor alone, near the cylinder's edge"),
    W(1, 0.002, m2, wall=f"fix floor all wall/gran granular {HM} zplane 0 NULL", x=0.0079, label="floor row vs floor+cylinder at the edge (engine truth)",
      spec_override={"post": [f"fix cyl all wall/gran granular {HM} zcylinder 0.01"]})]},
}


def main(names):
    for n in names or S:
        if n not in S:
            continue
        json.dump(S[n], open(os.path.join(D, n, "spec.json"), "w"), indent=1)
    print("specs:", len([n for n in (names or S) if n in S]))


# ---------------------------------------------------------------- LIGGGHTS
MAT3 = ["fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6",
        "fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3",
        "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5"]
E3 = "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8"
HERTZ = ["pair_style gran model hertz tangential history", "pair_coeff * *"]
WALL3 = "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0"
STIFF3 = ["fix m4 all property/global kn peratomtypepair 3 2000 2500 3000 2500 4000 3500 3000 3500 5000",
          "fix m5 all property/global gamman peratomtypepair 3 3000 2000 1000 2000 2500 1500 1000 1500 2000",
          "fix m6 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000",
          "fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50"]
L1, L2, L2b = (0.002, 8.37758e-05), (0.003, 0.000169646), (0.003, 0.000113097)


def LP(t1, t2, a, b, **kw):
    return P(t1, t2, a[0], a[1], b[0], b[1], **kw)


def LW(t1, a, wall=WALL3, wall_id="wprim", **kw):
    return W(t1, a[0], a[1], wall=wall, wall_id=wall_id, **kw)


S.update({
 "L01_e_one_everywhere": {"engine": "liggghts", "ntypes": 3, "lines": MAT3 + [
    "fix m3 all property/global coefficientRestitution peratomtypepair 3 1 1 1 1 1 1 1 1 1"] + HERTZ, "checks": [
    LP(1, 2, L1, L2), LW(1, L1)]},
 "L03_variable_count_alias": {"engine": "liggghts", "ntypes": 3, "lines": MAT3 + [
    "fix m3 all property/global coefficientRestitution atomtypepair 3 0.6 0.55 0.7 0.55 0.4 0.45 0.7 0.45 0.8"] + HERTZ, "checks": [
    LP(1, 2, L1, L2), LW(1, L1)]},
 "L04_sjkr_one_pair_22": {"engine": "liggghts", "ntypes": 3, "lines": MAT3 + [E3,
    "fix m9 all property/global cohesionEnergyDensity peratomtypepair 3 0 0 0 0 300000 0 0 0 0",
    "pair_style gran model hertz tangential history cohesion sjkr", "pair_coeff * *"], "checks": [
    LP(1, 2, L1, L2), LW(1, L1, wall="fix wprim all wall/gran model hertz tangential history cohesion sjkr primitive type 3 zplane 0.0")]},
 "L05_sjkr_wall_pair_only": {"engine": "liggghts", "ntypes": 3, "lines": MAT3 + [E3,
    "fix m9 all property/global cohesionEnergyDensity peratomtypepair 3 0 0 300000 0 0 0 300000 0 0",
    "pair_style gran model hertz tangential history cohesion sjkr", "pair_coeff * *"], "checks": [
    LP(1, 1, L1, L1), LP(1, 2, L1, L2)]},
 "L06_hookestiff_two_templates_two_types": {"engine": "liggghts", "ntypes": 3, "lines": MAT3 + STIFF3 + [
    "pair_style gran model hooke/stiffness tangential history", "pair_coeff * *"], "checks": [
    LP(1, 2, L1, L2b), LP(1, 1, L1, L1), LW(1, L1, wall="fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0")]},
 "L07_rolling_epsd2_tangential_damping_off": {"engine": "liggghts", "ntypes": 3, "lines": MAT3 + [E3,
    "fix m10 all property/global coefficientRollingFriction peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1",
    "pair_style gran model hertz tangential history rolling_friction epsd2 tangential_damping off", "pair_coeff * *"], "checks": [
    LP(1, 2, L1, L2), LW(1, L1, wall="fix wprim all wall/gran model hertz tangential history rolling_friction epsd2 primitive type 3 zplane 0.0")]},
 "L08_hertzstiff_coarse_dt": {"engine": "liggghts", "ntypes": 3, "lines": MAT3 + [
    "fix m4 all property/global kn peratomtypepair 3 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5",
    "fix m5 all property/global gamman peratomtypepair 3 3e5 3e5 3e5 3e5 3e5 3e5 3e5 3e5 3e5"] + STIFF3[2:] + [
    "pair_style gran model hertz/stiffness tangential history", "pair_coeff * *"], "checks": [
    LP(1, 2, L1, L2, speed_idx=[0, 3], at_dt=True),
    LW(1, L1, wall="fix wprim all wall/gran model hertz/stiffness tangential history primitive type 3 zplane 0.0", speed_idx=[2], at_dt=True)]},
 "L09_mesh_scale_rotate_move": {"engine": "liggghts", "ntypes": 3, "files": ["plane_mm.stl"], "lines": MAT3 + [E3] + HERTZ, "checks": [
    LW(1, L1, wall="fix cad all mesh/surface file plane_mm.stl type 3 scale 0.001 rotate axis 0 0 1 angle 30 move 0 0 0.001\n"
       "fix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad", wall_id="wmesh", z0=0.003, zw=0.001)]},
 "L10_mesh_plane_and_primitive_1e-4": {"engine": "liggghts", "ntypes": 3, "files": ["plane0.stl"], "lines": MAT3 + [E3] + HERTZ, "checks": [
    LW(1, L1, wall="fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0001", z0=0.0021, zw=0.0001,
       speed_idx=[0, 2, 4], label="wprim row vs mesh+primitive (engine truth)",
       spec_override={"post": ["fix cad all mesh/surface file plane0.stl type 3",
                               "fix wmesh all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad"]})]},
 "L11_two_primitive_planes_1e-4": {"engine": "liggghts", "ntypes": 3, "lines": MAT3 + [E3] + HERTZ, "checks": [
    LW(1, L1, wall="fix wprim2 all wall/gran model hertz tangential history primitive type 3 zplane 0.0001", wall_id="wprim2", z0=0.0021, zw=0.0001,
       speed_idx=[0, 2, 4], label="wprim2 row vs both planes (engine truth)", spec_override={"post": [WALL3]})]},
 "L12_soft_particles_low_E": {"engine": "liggghts", "ntypes": 3, "pre": ["soft_particles yes"], "lines": [
    MAT3[0].replace("5e6 5e6 5e6", "1e5 1e5 1e5")] + MAT3[1:] + [E3] + HERTZ, "checks": [LP(1, 2, L1, L2, speed_idx=[0, 2]), LW(1, L1, speed_idx=[0, 1])]},
 "L13_hertz_limitforce_pair_only": {"engine": "liggghts", "ntypes": 3, "lines": MAT3 + [E3.replace("0.6 0.5 0.7", "0.2 0.5 0.7"),
    "pair_style gran model hertz tangential history limitForce on", "pair_coeff * *"], "checks": [LP(1, 1, L1, L1), LW(1, L1)]},
})


L3 = (0.003, 0.000282743)
STIFFL = MAT3 + STIFF3 + ["pair_style gran model hooke/stiffness tangential history", "pair_coeff * *"]
WSTIFF = "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0"
S.update({
 "L14_adapt_growth_hookestiff": {"engine": "liggghts", "ntypes": 3, "lines": STIFFL, "checks": [
    LP(1, 2, L3, L3, stage=2), LW(1, L3, wall=WSTIFF, stage=2)]},
 "L16_adapt_ramp_hookestiff": {"engine": "liggghts", "ntypes": 3, "lines": STIFFL, "checks": [
    LP(1, 2, L3, L3, stage=2), LW(1, L3, wall=WSTIFF, stage=2)]},
})

DUMMY1 = ["create_atoms 1 single 0.1 0.1 0.1 units box", "set atom 2 diameter 0.004 density 2500"]  # LIGGGHTS wants type 1 present
S.update({
 "L17_wall_on_region_group_same_plane": {"engine": "liggghts", "ntypes": 3, "lines": MAT3 + [E3] + HERTZ, "checks": [
    LW(2, L2, label="wprim type 2 alone (control)", spec_override={"post": DUMMY1}),
    LW(2, L2, label="wprim row type 2 vs wprim + wl (engine truth)", speed_idx=[0, 2, 4],
       spec_override={"post": DUMMY1 + ["fix wl all wall/gran model hertz tangential history primitive type 3 zplane 0.0"]})]},
})

S.update({
 "L19_read_data_granular_columns": {"engine": "liggghts", "ntypes": 3, "lines": STIFFL, "checks": [
    LP(1, 2, (0.0025, 7.85398e-05), (0.0015, 0.00011027)), LW(1, (0.0025, 7.85398e-05), wall=WSTIFF)]},
})

# ---------------------------------------------------------------- real decks
S.update({
 "R01_gravelle_pouring_granular": {"engine": "lammps", "units": "lj", "lines": ["pair_style granular",
    "pair_coeff * * hooke 15000 500 tangential linear_nohistory 1.0 0.4 damping mass_velocity"], "checks": [
    P(1, 2, 0.5, 0.52359878, tc=0.01, speed_idx=[0, 2, 4]),
    W(1, 0.5, 0.52359878, wall="fix mywall1 all wall/gran/region hooke/history 15000 NULL 500 NULL 0.5 0 region wbox", wall_id="mywall1",
      z0=-24.5, zw=-25, tc=0.01, speed_idx=[0, 2, 4], spec_override={"pre": ["region wbox block -25 25 -25 25 -25 25"]})]},
 "R02_caesar_random_diameter_drop": {"engine": "liggghts", "ntypes": 1, "pre": ["hard_particles yes"], "files": ["ground_standin.stl"], "lines": [
    "fix m1 all property/global youngsModulus peratomtype 2.1e11", "fix m2 all property/global poissonsRatio peratomtype 0.30",
    "fix m3 all property/global coefficientRestitution atomtypepair 1 0.4", "fix m4 all property/global coefficientFriction atomtypepair 1 0.3",
    "pair_style gran model hertz tangential history", "pair_coeff * *"], "checks": [
    P(1, 1, 0.0025, 0.000513781, 0.015, 0.110977, label="types 1 1 (r 2.5 mm on r 15 mm)"),
    W(1, 0.015, 0.110977, wall="fix z_wall_lo all wall/gran model hertz tangential history primitive type 1 zplane 0.0", wall_id="z_wall_lo")]},
 "R03_caesar_simple_drop_ground": {"engine": "liggghts", "ntypes": 1, "files": ["ground_standin.stl"], "lines": [
    "fix m1 all property/global youngsModulus peratomtype 5e7", "fix m2 all property/global poissonsRatio peratomtype 0.25",
    "fix m3 all property/global coefficientRestitution atomtypepair 1 0.5", "fix m4 all property/global coefficientFriction atomtypepair 1 0.4",
    "pair_style gran model hertz tangential history", "pair_coeff * *"], "checks": [
    P(1, 1, 0.25, 163.625),
    W(1, 0.25, 163.625, wall="fix ground all mesh/surface file ground_standin.stl type 1\nfix walls all wall/gran model hertz tangential history mesh n_meshes 1 meshes ground",
      wall_id="walls", x=5.0, y=5.0)]},
})

if __name__ == "__main__":
    main(sys.argv[1:])

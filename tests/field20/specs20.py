"""Field round 20: each refereed deck's spec.json for this round's copy of round 13's referee (referee20.py, which runs
round 10's head-on referee unchanged: two bodies touching at t = 0, contact time / 1000 ... / 8000, Richardson to
dt -> 0). Sizes and masses are the engine's own (engine_stages20.py for LAMMPS, liggghts_state20.py for LIGGGHTS, run on
the deck; ENGINE_STATE.txt beside the deck). The contact lines are the deck's own, so the engine decides what they mean
(type ranges, labels, repeated keywords). usage: python specs20.py [NAME ...]"""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from fieldkit.specs import GL, HK, HM, K, LE3, LMAT, LST, P, TL, W, hk, m, m2, m3, write  # noqa: E402,F401

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
LE = lambda e: [f"fix m3 all property/global coefficientRestitution peratomtypepair 3 " + " ".join([str(e)] * 9)]
CV = ["fix m9 all property/global characteristicVelocity scalar 2.0"]
LIG = lambda **kw: dict({"engine": "liggghts", "ntypes": 3}, **kw)

S = {
    "p02_range_23_12_sets_22_only": {"ntypes": 3, "lines": GL(f"* * {HK}", f"2*3 1*2 {hk(9000)}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3), P(2, 2, 0.003, m3, 0.003, m3), P(1, 3, 0.002, m2, 0.0025, m(0.0025, 2500))]},
    "p05_range_star3_2star": {"ntypes": 3, "lines": GL(f"* * {HK}", f"*2 2* {hk(5000)}"),
        "checks": [P(1, 3, 0.002, m2, 0.0025, m(0.0025, 2500)), P(3, 3, 0.0025, m(0.0025, 2500), 0.0025, m(0.0025, 2500))]},
    "p03_labels_reversed": {"pre": ["labelmap atom 1 glass 2 steel"], "lines": GL(f"* * {HK}", f"steel glass {hk(6000)}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
    "p07_mixed_pair_from_two_types": {"lines": GL(f"1 1 {HK}", f"2 2 hooke 8000 1000 {K}"), "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
    "s01_density_before_diameter": {"lines": GL(f"* * {HK}"), "checks": [P(1, 2, 0.002, 1309.0, 0.002, 1309.0, tc=3e-3)]},
    "s08_data_file_sizes": {"lines": GL(f"* * {HK}"), "checks": [P(1, 1, 0.002, m2, 0.001, m(0.001, 7800))]},
    "x01_format_0f_half_even": {"lines": GL(f"* * hooke 2500 3002 {K}"), "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
    "x03_format_1f_binary_half": {"lines": GL(f"* * hertz/material 1.2e+07 1.4e7 0.3 damping viscoelastic {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[0, 1])]},
    "m06_tsuji_e1": {"lines": GL(f"* * hertz/material 1e7 1.0 0.3 damping tsuji {TL}"), "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
    "m21_fix_move_type2_groups_after": {"lines": GL(f"* * {HK}"), "integr_lines": ["fix nve a1 nve/sphere", "fix mv a2 move linear 0 0 0"],
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, still2=True)]},
    "h05_suffix_omp_command": {"lines": ["pair_style gran/hooke 2000 NULL 300 NULL 0.5 0", "pair_coeff * *"], "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
    "w07_wall_limit_damping_only": {"lines": GL(f"* * hooke 2000 0.5 damping velocity {TL}"),
        "checks": [W(1, 0.002, m2, f"fix floor all wall/gran granular hooke 2000 0.5 damping velocity {TL} limit_damping zplane 0 NULL")]},
    "t09_units_lj_default_dt": {"units": "lj", "lines": GL(f"* * hooke 2000 50 {K}"), "checks": [P(1, 2, 0.5, m(0.5, 1), 0.5, m(0.5, 1))]},
    "R01_gravelle_pouring_loop": {"units": "lj", "lines": GL("* * hooke 15000 500 tangential linear_nohistory 1.0 0.4 damping mass_velocity"),
        "checks": [P(1, 2, 0.5, m(0.5, 1), 0.5, m(0.5, 1), speed_idx=[1])]},
    "L56_set_density_then_diameter": LIG(lines=LMAT + LST, checks=[P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 1500))]),
    "L57_diameter_only_default_density": LIG(lines=LMAT + LST, checks=[P(1, 2, 0.002, 3.35103e-08, 0.003, m(0.003, 1500))]),
    "L51_limitforce_pair_only": LIG(lines=LMAT + LE3 + CV + ["pair_style gran model hooke tangential history limitForce on", "pair_coeff * *"],
        checks=[W(1, 0.002, m(0.002, 2500), "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0", wall_id="wprim"),
                P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 1500))]),
    "L42_hooke_e_one_cv": LIG(lines=LMAT + LE(1.0) + ["fix m9 all property/global characteristicVelocity scalar 1.0",
        "pair_style gran model hooke tangential history", "pair_coeff * *"], checks=[P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 1500))]),
    "L43_hertz_e_0051": LIG(lines=LMAT + LE(0.051) + ["pair_style gran model hertz tangential history", "pair_coeff * *"],
        checks=[P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 1500))]),
    "L24_hertz_set_density_after_run": LIG(lines=LMAT + LST, checks=[P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 7800), stage=2)]),  # 2 2 alone: LIGGGHTS needs type 1 present
    "x36_damping_keyword_twice": {"lines": GL(f"* * hooke 2000 0.5 damping mass_velocity {TL} damping velocity"), "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},  # the deck's type 2 is 6 mm
    "p21_limit_damping_cleared_by_later_star": {"lines": GL(f"* * hooke 2000 0.5 damping velocity {TL} limit_damping", f"1 1 hooke 2000 0.5 damping velocity {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3), P(1, 1, 0.002, m2, 0.002, m2)]},
    "w15_region_sphere_hertz_inside": {"lines": GL(f"* * {HM}"), "checks": [W(1, 0.002, m2, f"fix sw all wall/gran/region granular {HM} region sp", wall_id="sw",
        z0=-0.01 + 0.002, zw=-0.01, spec_override={"pre": ["region sp sphere 0 0 0.04 0.05 units box"]})]},
    "w18_region_sphere_hertz_outside": {"lines": GL(f"* * {HM}"), "checks": [W(1, 0.002, m2, f"fix ow all wall/gran/region granular {HM} region ob", wall_id="ow",
        spec_override={"pre": ["region ob sphere 0 0 -0.01 0.01 side out units box"]})]},
    "w19_zcylinder_wall_gran_hertz": {"lines": GL(f"* * {HM}"), "checks": [W(1, 0.002, m2, f"fix cyl all wall/gran granular {HM} zcylinder 0.019", wall_id="cyl",
        axis="x", z0=0.017, zw=0.019, sign=-1)]},
    "m07_coeffrest_e_tiny": {"lines": GL(f"* * hertz/material 1e7 0.001 0.3 damping coeff_restitution {TL}"), "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
    "L36_hooke_characteristic_velocity": LIG(lines=LMAT + LE3 + CV + ["pair_style gran model hooke tangential history", "pair_coeff * *"],
        checks=[P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 1500))]),
    "L27_stiffness_e_hertz_stiffness": LIG(lines=LMAT + [l.replace("hooke/stiffness", "hertz/stiffness") for l in LST],
        checks=[P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 1500))]),
    "L13_limitforce_restyle": LIG(lines=LMAT + LE3 + ["pair_style gran model hertz tangential history limitForce on", "pair_coeff * *"],
        checks=[W(1, 0.002, m(0.002, 2500), "fix wprim all wall/gran model hertz tangential history primitive type 3 zplane 0.0", wall_id="wprim", stage=1),
                P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 1500), stage=1)]),
    "L54_radius_per_type_set_region": LIG(lines=LMAT + LST, checks=[P(1, 1, 0.002, m(0.002, 2500), 0.003, m(0.003, 2500))]),
    "L86_liggghts_quit_minimal": LIG(ntypes=1, lines=["fix m1 all property/global youngsModulus peratomtype 5e6", "fix m2 all property/global poissonsRatio peratomtype 0.3",
        "fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5", "fix m7 all property/global coefficientFriction peratomtypepair 1 0.5",
        "pair_style gran model hertz tangential history", "pair_coeff * *"], checks=[P(1, 1, 0.002, m(0.002, 2500), 0.002, m(0.002, 2500), stage=1)]),
    "e16_run_every_unfix_floor_then_floor2": {"lines": GL(f"* * {HK}"), "checks": [W(1, 0.002, m2, f"fix floor2 all wall/gran granular {hk(9000)} zplane 0 NULL", wall_id="floor2", stage=2)]},
    "e27_run_every_quit": {"lines": GL(f"* * {HK}"), "checks": [P(1, 2, 0.002, m2, 0.002, m2, stage=1)]},
    "z30_partition_yes_1_pair_coeff": {"lines": GL(f"* * {HK}") + [f"partition yes 1 pair_coeff * * {hk(9000)}"], "checks": [P(1, 2, 0.002, m2, 0.002, m2)]},
    "L98_liggghts_partition_yes_1_property": LIG(lines=LMAT + LE3 + ["partition yes 1 fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3",
        "pair_style gran model hertz tangential history", "pair_coeff * *"], checks=[P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 1500))]),
    "L61_read_data_liggghts_cv": LIG(lines=LMAT + LST, checks=[P(1, 2, 0.001, m(0.001, 7800), 0.003, m(0.003, 1500), match="largest")]),
}


if __name__ == "__main__":
    write(S, D, sys.argv[1:])

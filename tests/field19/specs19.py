"""Field round 19: each refereed deck's spec.json for round 13's referee (tests/field13/referee13.py, which runs round
10's head-on referee unchanged: two bodies touching at t = 0, contact time / 1000 ... / 8000, Richardson to dt -> 0).
Sizes and masses are the engine's own (tests/field16/engine_stages.py for LAMMPS, tests/field13/liggghts_state.py for
LIGGGHTS, run on the deck). usage: python specs19.py [NAME ...]"""
import json, math, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
m = lambda r, rho: rho * 4 / 3 * math.pi * r ** 3
TL = "tangential linear_nohistory 1 0.3"
K = f"damping mass_velocity {TL}"
HK = f"hooke 2000 3000 {K}"
HM = f"hertz/material 1e7 1.4e7 0.3 damping viscoelastic {TL}"
m2, m3 = m(0.002, 2500), m(0.003, 2500)


def P(t1, t2, r1, m1, r2, m2_, **kw):
    return dict({"t1": t1, "t2": t2, "r1": r1, "m1": m1, "r2": r2, "m2": m2_, "speed_idx": [0]}, **kw)


def W(t1, r1, m1, wall, wall_id="floor", **kw):
    return dict({"t1": t1, "wall_id": wall_id, "wall": wall, "r1": r1, "m1": m1, "z0": r1, "zw": 0, "speed_idx": [0]}, **kw)


GL = lambda *l: ["pair_style granular"] + [f"pair_coeff {x}" for x in l]
LMAT = ["fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6",
        "fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3",
        "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5"]
LST = ["fix m4 all property/global kn peratomtypepair 3 2000 2500 3000 2500 4000 3500 3000 3500 5000",
       "fix m5 all property/global gamman peratomtypepair 3 300 200 100 200 250 150 100 150 200",
       "fix m6 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000",
       "fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50",
       "pair_style gran model hooke/stiffness tangential history", "pair_coeff * *"]
LE3 = ["fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8"]
LWST = "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0"

S = {
    "a02_granular_to_gran_history_and_wall": {"lines": ["pair_style gran/hooke/history 3000 NULL 400 NULL 0.5 0", "pair_coeff * *"],
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, stage=2),
                   W(2, 0.003, m3, "fix floor2 all wall/gran hooke/history 3000 NULL 400 NULL 0.5 0 zplane 0 NULL", wall_id="floor2", stage=2)]},
    "a04_type3_created_after_run": {"ntypes": 3, "lines": GL(f"* * {HK}", f"3 3 hooke 9000 3000 {K}"),
        "checks": [P(1, 3, 0.002, m2, 0.0025, m(0.0025, 7800), stage=2), P(3, 3, 0.0025, m(0.0025, 7800), 0.0025, m(0.0025, 7800), stage=2)]},
    "a08_pair_modify_mix_arithmetic": {"lines": GL(f"1 1 hertz/material 1e7 1.4e7 0.3 damping viscoelastic {TL}",
                                                    f"2 2 hertz/material 8e7 0.35e7 0.45 damping viscoelastic {TL}") + ["pair_modify mix arithmetic"],
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[0, 1])]},
    "a09_clear_and_new_box": {"lines": GL(f"* * {HM}"),
        "checks": [P(1, 1, 0.0015, m(0.0015, 2500), 0.0015, m(0.0015, 2500), stage=2)]},
    "a11_wall_moved_by_unfix_refix_model": {"lines": GL(f"* * {HK}"),
        "checks": [W(1, 0.002, m2, f"fix floor all wall/gran granular hertz 1e6 0.05 damping velocity {TL} zplane 0 NULL", stage=2, speed_idx=[0, 1]),
                   W(2, 0.003, m3, f"fix floor all wall/gran granular jkr 1e7 1.4e7 0.3 0.0 damping viscoelastic {TL} zplane 0 NULL", stage=3, speed_idx=[1])]},
    "a12_density_changed_between_runs": {"lines": GL(f"* * {HK}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m(0.003, 7800), stage=2), P(2, 2, 0.003, m(0.003, 7800), 0.003, m(0.003, 7800), stage=2)]},
    "a14_minimize_stage": {"lines": GL(f"* * hooke 6000 3000 {K}"), "checks": [P(1, 2, 0.002, m2, 0.002, m2)]},
    "d01_read_data_sizes_densities_hertzmat": {"lines": GL(f"* * {HM}"),
        "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 7800), match="smallest", speed_idx=[0, 1]),
                   P(1, 2, 0.001, m(0.001, 2500), 0.0025, m(0.0025, 1500), match="largest"),
                   P(2, 2, 0.0025, m(0.0025, 7800), 0.003, m(0.003, 7800), match="smallest", speed_idx=[1]),
                   W(2, 0.003, m(0.003, 7800), f"fix floor all wall/gran granular {HM} zplane 0 NULL", match="smallest")]},
    "d03_read_data_type_offset": {"ntypes": 3, "lines": GL(f"* * {HM}"),
        "checks": [P(1, 1, 0.0015, m(0.0015, 2500), 0.0025, m(0.0025, 2500))]},
    "d04_read_data_type_labels": {"lines": ["labelmap atom 1 steel 2 glass"] + GL(f"glass glass {HK}", f"steel steel hooke 9000 3000 {K}", f"glass steel hooke 4000 3000 {K}"),
        "checks": [P(1, 2, 0.002, m(0.002, 7800), 0.002, m(0.002, 2500))]},
    "d07_read_data_2d_discs": {"dimension": 2, "lines": GL(f"* * {HM}"),
        "checks": [P(1, 1, 0.003, m(0.003, 2500), 0.004, m(0.004, 2500), match="smallest", speed_idx=[0, 1])]},  # LAMMPS holds 4/3 pi r^3 rho from read_data in 2d (engine_stages)
    "d10_pour_diam_poly_hertzmat_ends": {"lines": GL(f"* * {HM}"),
        "checks": [P(2, 2, 0.003, m(0.003, 3000), 0.003, m(0.003, 3000), match="smallest"),
                   P(2, 2, 0.001, m(0.001, 2000), 0.001, m(0.001, 2000), match="largest", speed_idx=[1])]},
    "e13_wall_model_differs_from_pair": {"lines": GL(f"* * {HM}"),
        "checks": [W(1, 0.002, m2, f"fix floor all wall/gran granular hertz/material 1e9 1.4e7 0.2 damping viscoelastic {TL} zplane 0 NULL", speed_idx=[0, 1])]},
    "e08_zcylinder_shear_z": {"lines": GL(f"* * {HM}"),
        "checks": [W(1, 0.002, m2, f"fix cyl all wall/gran granular {HM} zcylinder 0.03 shear z 0.5", wall_id="cyl", axis="x", z0=0.028, zw=0.03, sign=-1)]},
    "f01_adapt_diameter_reset_no": {"lines": GL(f"* * {HK}"), "checks": [P(1, 2, 0.003, m3, 0.003, m3, stage=2)]},
    "f06_adapt_diameter_type2_scale": {"lines": GL(f"* * {HK}"),
        "checks": [P(1, 2, 0.002, m2, 0.004, m(0.004, 2500), stage=2), W(2, 0.004, m(0.004, 2500), f"fix floor all wall/gran granular {HK} zplane 0 NULL", stage=2)]},
    "m01_hooke_coeffrest_no_limit": {"lines": GL(f"* * hooke 2000 0.5 damping coeff_restitution {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[1])]},
    "m02_hertzmat_mass_velocity": {"lines": GL(f"* * hertz/material 1e7 30 0.3 damping mass_velocity {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[0, 1])]},
    "m05_hooke_velocity_mixed_three_types": {"ntypes": 3, "lines": GL(f"1 1 hooke 2000 0.05 damping velocity {TL}", f"2 2 hooke 8000 0.2 damping velocity {TL}", f"3 3 hooke 4000 0.1 damping velocity {TL}"),
        "checks": [P(1, 3, 0.002, m2, 0.0025, m(0.0025, 7800), speed_idx=[2]), P(2, 3, 0.003, m3, 0.0025, m(0.0025, 7800), speed_idx=[2])]},
    "m07_tsuji_e_small": {"lines": GL(f"* * hertz/material 1e7 0.05 0.3 damping tsuji {TL} limit_damping"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
    "m09_gran_hooke_dampflag_limit": {"lines": ["pair_style gran/hooke 2000 NULL 300 NULL 0.5 1 limit_damping", "pair_coeff * *"],
        "checks": [P(1, 2, 0.002, m2, 0.003, m3),
                   W(2, 0.003, m3, "fix floor all wall/gran hooke 2000 NULL 300 NULL 0.5 1 limit_damping zplane 0 NULL")]},
    "m10_granular_units_lj_hertzmat": {"units": "lj", "lines": GL(f"* * hertz/material 1e4 1e3 0.3 damping viscoelastic {TL}"),
        "checks": [P(1, 2, 0.5, m(0.5, 1), 0.75, m(0.75, 1), speed_idx=[0, 1])]},
    "m11_units_cgs_granular_tsuji": {"units": "cgs", "lines": GL(f"* * hertz/material 1e8 0.6 0.3 damping tsuji {TL} limit_damping"),
        "checks": [P(1, 2, 0.2, m(0.2, 2.5), 0.3, m(0.3, 2.5), speed_idx=[1])]},
    "m13_units_real_granular_hooke_velocity": {"units": "real", "lines": GL(f"* * hooke 20 0.5 damping velocity {TL}"),
        "checks": [P(1, 2, 2.0, m(2.0, 2), 3.0, m(3.0, 2))]},
    "v02_coeff_from_step_after_run": {"lines": GL(f"* * hooke 3000 3000 {K}"), "checks": [P(1, 2, 0.002, m2, 0.002, m2, stage=2)]},
    "v05_coeff_from_time_after_two_runs_dt": {"lines": GL(f"* * hooke 5000 3000 {K}"), "checks": [P(1, 2, 0.002, m2, 0.002, m2, stage=2)]},
    "v08_format_expression_in_coeff": {"lines": GL(f"* * hertz/material 1.23e+07 1.4e7 0.31 damping viscoelastic {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[0, 1])]},
    "v14_ternary_and_logic": {"lines": GL(f"* * hertz/material 5e7 1.4e7 0.3 damping viscoelastic {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
    "L08_hooke_stiffness_insert_radius_range": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + LST,
        "checks": [P(1, 1, 0.004, m(0.004, 2500), 0.004, m(0.004, 2500), match="smallest"),
                   W(1, 0.002, m(0.002, 2500), LWST, wall_id="wprim", match="largest")]},
    "L09_read_data_sizes_hookestiffness": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + LST,
        "checks": [P(1, 2, 0.001, m(0.001, 1000), 0.0015, m(0.0015, 7800), match="largest")]},  # 2 2 alone: LIGGGHTS needs type 1 present in the referee's box
    "L10_hertz_units_cgs": {"engine": "liggghts", "ntypes": 3, "units": "cgs",
        "lines": ["fix m1 all property/global youngsModulus peratomtype 5e7 5e7 5e7", "fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3",
                  LMAT[2]] + LE3 + ["pair_style gran model hertz tangential history", "pair_coeff * *"],
        "checks": [P(1, 2, 0.2, m(0.2, 2.5), 0.3, m(0.3, 1.5))]},
    "L17_set_type_after_insert_run": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + LST,
        "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.0015, m(0.0015, 7800), stage=2)]},  # 2 2 alone: LIGGGHTS needs type 1 present
    "L20_hertz_per_pair_e_asymmetric_order": {"engine": "liggghts", "ntypes": 2,
        "lines": ["fix m1 all property/global youngsModulus peratomtype 5e6 2e7", "fix m2 all property/global poissonsRatio peratomtype 0.3 0.25",
                  "fix m3 all property/global coefficientRestitution peratomtypepair 2 0.9 0.3 0.3 0.5", "fix m7 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5",
                  "pair_style gran model hertz tangential history", "pair_coeff * *"],
        "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 1500))]},
    "b02_static_group_before_atoms_integrator": {"lines": GL(f"* * {HK}"), "integr_lines": ["fix nve a1 nve/sphere"],
        "checks": [P(2, 1, 0.003, m3, 0.002, m2, still2=True)]},
    "b05_limit_damping_mixed": {"lines": GL(f"1 1 {HM} limit_damping", f"2 2 {HM}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[0, 1])]},
    "L25_property_redefined_same_id": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + ["fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3",
        "pair_style gran model hertz tangential history", "pair_coeff * *"], "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 1500), stage=2)]},
    "L28_pair_model_changed_walls_kept": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + LE3 + ["fix m9 all property/global characteristicVelocity scalar 2.0",
        "pair_style gran model hooke tangential history", "pair_coeff * *"], "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 1500), stage=2)]},
    "R04_dirt_repose_lift_cylinder": {"lines": GL("1 1 hertz/material 1.000000e+07 0.4 0.25 tangential mindlin NULL 1.0 0.3 damping coeff_restitution rolling sds 1.000000e+02 1.000000e-06 0.1 twisting none"),
        "ntypes": 1, "checks": [P(1, 1, 0.002, m2, 0.002, m2, speed_idx=[1])]},
    "R05_dirt_slot_hopper": {"lines": GL("1 1 hertz/material 5.000000e+07 0.5 0.3 tangential mindlin NULL 1.0 0.5 damping tsuji"),
        "ntypes": 1, "checks": [P(1, 1, 0.002, m2, 0.002, m2)]},
    "c05_lammps_coeffrest_e_low": {"lines": GL(f"1 1 hertz/material 1e7 0.05 0.3 damping coeff_restitution {TL}", f"2 2 hooke 2000 0.05 damping coeff_restitution {TL}",
                                                f"1 2 hertz/material 1e7 0.95 0.3 damping coeff_restitution {TL}"),
        "checks": [P(1, 1, 0.002, m2, 0.002, m2, speed_idx=[1]), P(1, 2, 0.002, m2, 0.003, m3)]},
    "c11_pour_diam_range_dens_range_hertzmat": {"lines": GL(f"* * {HM}"),
        "checks": [P(1, 1, 0.003, m(0.003, 7800), 0.003, m(0.003, 7800), match="smallest"), P(1, 1, 0.001, m(0.001, 1500), 0.001, m(0.001, 1500), match="largest", speed_idx=[1])]},
    "c07_dmt_cohesion_mixed_to_zero": {"lines": GL(f"1 1 dmt 1e7 1.4e7 0.3 0.0 damping viscoelastic {TL}", f"2 2 dmt 1e7 1.4e7 0.3 0.05 damping viscoelastic {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[0, 1])]},
    "c19_star_then_22_no_mix": {"lines": GL(f"* * {HM}", f"2 2 hertz/material 8e7 0.35e7 0.45 damping viscoelastic {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
    "c02_2d_density_disc": {"dimension": 2, "lines": GL(f"* * {HM}"),
        "checks": [P(1, 2, 0.002, m2, 0.002, math.pi * 0.002 ** 2 * 2500, speed_idx=[1])]},
    "c31_pour_poly_zero_probability": {"lines": GL(f"* * {HM}"),
        "checks": [P(2, 2, 0.003, m3, 0.003, m3, match="smallest", speed_idx=[0, 1])]},
    "L37_distribution_weight_zero": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + LST,
        "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.0015, m(0.0015, 1500), match="smallest")]},
}


def main(names):
    for n in names or S:
        s = dict({"engine": "lammps"}, **S[n])
        json.dump(s, open(os.path.join(D, n, "spec.json"), "w"), indent=1)
    print(len(names or S), "specs")


main(sys.argv[1:])

"""Field round 18: each refereed deck's spec.json for round 13's referee (tests/field13/referee13.py, which runs round
10's head-on referee unchanged: two bodies touching at t = 0, contact time / 1000 ... / 8000, Richardson to dt -> 0).
Sizes and masses are the engine's own (tests/field16/engine_stages.py on the deck: radius and rmass per type after
its runs). usage: python specs18.py [NAME ...]"""
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
LE3 = ["fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8"]
LSTIFF = ["fix m4 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000",
          "fix m5 all property/global gamman peratomtypepair 3 300 300 300 300 300 300 300 300 300",
          "fix m6 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000",
          "fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50",
          "pair_style gran model hooke/stiffness tangential history", "pair_coeff * *"]
lm1, lm2 = m(0.002, 2500), m(0.003, 1500)

S = {
    "p01_mix_hertzmaterial_viscoelastic_E": {"lines": GL(f"1 1 hertz/material 1e7 1.4e7 0.3 damping viscoelastic {TL}",
                                                          f"2 2 hertz/material 8e7 0.35e7 0.45 damping viscoelastic {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[0, 1])]},
    "p02_mix_tsuji_e": {"lines": GL(f"1 1 hertz/material 1e7 0.3 0.3 damping tsuji {TL}", f"2 2 hertz/material 5e7 0.9 0.2 damping tsuji {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
    "p03_dmt_zero_cohesion": {"lines": GL(f"* * dmt 1e7 1.4e7 0.3 0.0 damping viscoelastic {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[0, 1]),
                   W(1, 0.002, m2, f"fix floor all wall/gran granular dmt 1e7 1.4e7 0.3 0.0 damping viscoelastic {TL} zplane 0 NULL", speed_idx=[1])]},
    "p06_hooke_viscoelastic": {"lines": GL(f"* * hooke 2000 300 damping viscoelastic {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[1])]},
    "p07_hertz_velocity": {"lines": GL(f"* * hertz 1e6 0.05 damping velocity {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[0, 1]),
                   W(2, 0.003, m3, f"fix floor all wall/gran granular hertz 1e6 0.05 damping velocity {TL} zplane 0 NULL", speed_idx=[1])]},
    "p08_hooke_tsuji_limit": {"lines": GL(f"* * hooke 2000 0.6 damping tsuji {TL} limit_damping"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
    "p09_hertz_coeffrest_limit": {"lines": GL(f"* * hertz 1e6 0.5 damping coeff_restitution {TL} limit_damping"),
        "checks": [P(1, 1, 0.002, m2, 0.002, m2),
                   W(1, 0.002, m2, f"fix floor all wall/gran granular hertz 1e6 0.5 damping coeff_restitution {TL} limit_damping zplane 0 NULL", speed_idx=[1])]},
    "p10_hertz_mass_velocity": {"lines": GL(f"* * hertz 1e6 30 {K}"),
        "checks": [P(2, 2, 0.003, m3, 0.003, m3, speed_idx=[0, 1])]},
    "p14_hybrid_granular_by_type": {"lines": ["pair_style hybrid granular gran/hooke 4000 NULL 50 NULL 0.5 0",
                                              f"pair_coeff 1 1 granular {HK}", f"pair_coeff 2 2 granular {HK}", "pair_coeff 1 2 gran/hooke"],
        "checks": [P(1, 2, 0.002, m2, 0.002, m2, speed_idx=[2])]},
    "p15_gran_hertz_history_limit": {"lines": ["pair_style gran/hertz/history 1e6 NULL 2000 NULL 0.5 0 limit_damping", "pair_coeff * *"],
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[1]),
                   W(2, 0.003, m3, "fix floor all wall/gran hertz/history 1e6 NULL 2000 NULL 0.5 0 zplane 0 NULL", speed_idx=[1])]},
    "p18_hertzmaterial_nu_half": {"lines": GL(f"* * hertz/material 1e7 1.4e7 0.5 damping viscoelastic {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[1])]},
    "p21_hooke_velocity_unlike_mass": {"lines": GL(f"1 1 hooke 2000 0.05 damping velocity {TL}", f"2 2 hooke 8000 0.2 damping velocity {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m(0.003, 7800), speed_idx=[2])]},
    "p22_mix_hertzmaterial_coeffrest_limit": {"lines": GL(f"1 1 hertz/material 1e7 0.4 0.3 damping coeff_restitution {TL} limit_damping",
                                                           f"2 2 hertz/material 9e7 0.9 0.25 damping coeff_restitution {TL} limit_damping"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3)]},
    "s01_pour_density_range": {"lines": GL(f"* * {HK}"),
        "checks": [P(1, 1, 0.002, m(0.002, 3500), 0.002, m(0.002, 3500), speed_idx=[2], match="smallest"),
                   P(1, 1, 0.002, m(0.002, 1500), 0.002, m(0.002, 1500), speed_idx=[2], match="largest")]},
    "s03_deposit_default_size": {"units": "lj", "lines": GL(f"* * hooke 2e4 30 {K}"),
        "checks": [P(1, 2, 1.0, 12.566370614359172, 0.5, 0.5235987755982988)]},
    "s06_set_mass_after_diameter": {"lines": GL(f"* * {HK}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, 0.001, speed_idx=[2]), P(2, 2, 0.003, 0.001, 0.003, 0.001, speed_idx=[2]),
                   W(2, 0.003, 0.001, f"fix floor all wall/gran granular {HK} zplane 0 NULL", speed_idx=[2])]},
    "s11_create_mol_template": {"lines": GL(f"* * {HK}"),
        "checks": [P(1, 2, 0.002, 8e-5, 0.003, 4e-4, speed_idx=[2])]},
    "u01_units_micro": {"units": "micro", "lines": GL(f"* * hooke 2000 2.8 {K}"),
        "checks": [P(1, 2, 2.0, m(2.0, 2.5), 3.0, m(3.0, 2.5))]},
    "u02_units_nano_hertzmaterial": {"units": "nano", "lines": GL(f"* * hertz/material 1e4 0.05 0.3 damping viscoelastic {TL}"),
        "checks": [P(1, 2, 20.0, m(20.0, 2.5), 30.0, m(30.0, 2.5), speed_idx=[0, 1])]},
    "u03_units_metal_granular": {"units": "metal", "lines": GL(f"* * hooke 20 0.003 {K}"),
        "checks": [P(1, 2, 2.0, m(2.0, 2), 3.0, m(3.0, 2))]},
    "u04_units_real_hertzmaterial": {"units": "real", "lines": GL(f"* * hertz/material 1e5 500 0.3 damping viscoelastic {TL}"),
        "checks": [P(1, 2, 2.0, m(2.0, 2), 3.0, m(3.0, 2), speed_idx=[0, 1])]},
    "u08_2d_hertzmaterial_disc": {"dimension": 2, "lines": GL(f"* * {HM}"),
        "checks": [P(1, 2, 0.002, math.pi * 0.002 ** 2 * 5, 0.003, math.pi * 0.003 ** 2 * 5, speed_idx=[0, 1])]},
    "u10_cgs_gran_hertz_history": {"units": "cgs", "lines": ["pair_style gran/hertz/history 2e8 NULL 5000 NULL 0.5 0", "pair_coeff * *"],
        "checks": [P(1, 2, 0.2, m(0.2, 2.5), 0.3, m(0.3, 2.5), speed_idx=[0, 1])]},
    "w02_region_sphere_inside": {"lines": GL(f"* * {HM}"), "pre": ["region ball sphere 0 0 0 0.02 side in units box"],
        "checks": [W(1, 0.002, m2, f"fix bw all wall/gran/region granular {HM} region ball", wall_id="bw", axis="x", z0=0.018, zw=0.02, sign=-1, speed_idx=[0, 1])]},
    "w03_region_sphere_outside": {"lines": GL(f"* * {HM}"), "pre": ["region ball sphere 0 0 0 0.005 side out units box"],
        "checks": [W(1, 0.002, m2, f"fix bw all wall/gran/region granular {HM} region ball", wall_id="bw", axis="x", z0=0.007, zw=0.005, sign=1, speed_idx=[0, 1])]},
    "w04_region_cylinder_pillar": {"lines": GL(f"* * {HM}"), "pre": ["region pil cylinder z 0 0 0.003 -0.05 0.05 side out units box"],
        "checks": [W(1, 0.002, m2, f"fix pw all wall/gran/region granular {HM} region pil", wall_id="pw", axis="x", z0=0.005, zw=0.003, sign=1,
                     speed_idx=[0, 1], match="curved")]},
    "w09_wall_tsuji_limit_temperature": {"lines": GL(f"* * hertz/material 1e7 0.6 0.3 damping tsuji {TL}"),
        "checks": [W(1, 0.002, m2, f"fix floor all wall/gran granular hertz/material 1e7 0.6 0.3 damping tsuji {TL} limit_damping zplane 0 NULL")]},
    "w13_zcylinder_hooke_outside_no": {"lines": GL(f"* * hertz 1e6 30 {K}"),
        "checks": [W(2, 0.003, m3, f"fix cyl all wall/gran granular hertz 1e6 30 {K} zcylinder 0.015", wall_id="cyl", axis="x", z0=0.012, zw=0.015, sign=-1, speed_idx=[0, 1])]},
    "k03_setforce_partner_moving": {"lines": GL(f"* * {HK}"), "integr_lines": ["fix nve all nve/sphere", "fix sf a2 setforce 0 0 0"],
        "checks": [P(1, 2, 0.002, m2, 0.002, m2, speed_idx=[2], still2=True)]},
    "k11_freeze_partner_integrated_moving": {"lines": GL(f"* * {HK}"), "integr_lines": ["fix nve all nve/sphere", "fix fr a2 freeze"],
        "checks": [P(1, 2, 0.002, m2, 0.002, m2, speed_idx=[2], still2=True)]},
    "G01_hertz_unlike_young_poisson": {"engine": "liggghts", "ntypes": 3, "lines": [
        "fix m1 all property/global youngsModulus peratomtype 5e6 5e7 1e8", "fix m2 all property/global poissonsRatio peratomtype 0.3 0.45 0.25",
        LMAT[2]] + LE3 + ["pair_style gran model hertz tangential history", "pair_coeff * *"],
        "checks": [P(1, 2, 0.002, lm1, 0.003, lm2)]},
    "G03_hookestiffness_absolute_damping": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + [
        "fix m4 all property/global kn peratomtypepair 3 2000 2500 3000 2500 4000 3500 3000 3500 5000",
        "fix m5 all property/global gamman_abs peratomtypepair 3 0.3 0.2 0.1 0.2 0.25 0.15 0.1 0.15 0.2",
        "fix m6 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000",
        "fix m8 all property/global gammat_abs peratomtypepair 3 0.05 0.05 0.05 0.05 0.05 0.05 0.05 0.05 0.05",
        "pair_style gran model hooke/stiffness tangential history absolute_damping on", "pair_coeff * *"],
        "checks": [P(1, 2, 0.002, lm1, 0.003, lm2),
                   W(1, 0.002, lm1, "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0 absolute_damping on", wall_id="wprim")]},
    "G04_hertzstiffness": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + [
        "fix m4 all property/global kn peratomtypepair 3 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5",
        "fix m5 all property/global gamman peratomtypepair 3 300 300 300 300 300 300 300 300 300",
        "fix m6 all property/global kt peratomtypepair 3 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5",
        "fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50",
        "pair_style gran model hertz/stiffness tangential history", "pair_coeff * *"],
        "checks": [P(1, 2, 0.002, lm1, 0.003, lm2, speed_idx=[1])]},
    "G11_insert_rate_region_three_templates": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + LSTIFF,
        "checks": [P(1, 1, 0.003, m3, 0.003, m3, match="smallest"), P(1, 1, 0.0015, m(0.0015, 2500), 0.0015, m(0.0015, 2500), match="largest")]},
    "G22_hookestiffness_two_densities_same_type": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + LSTIFF,
        "checks": [P(1, 1, 0.002, m(0.002, 8000), 0.002, m(0.002, 8000), match="smallest"),
                   P(1, 1, 0.002, m(0.002, 1000), 0.002, m(0.002, 1000), match="largest")]},
    "G29_hooke_limitforce_stage": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + LE3 + [
        "fix m5 all property/global characteristicVelocity scalar 2.0", "pair_style gran model hooke tangential history limitForce on", "pair_coeff * *"],
        "checks": [P(1, 2, 0.002, lm1, 0.003, lm2),
                   W(1, 0.002, lm1, "fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0 limitForce on", wall_id="wprim")]},
    "b07_explicit_unlike_models": {"lines": GL(f"1 1 {HK}", f"2 2 {HM}", f"1 2 hertz 1e6 30 {K}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[1]), P(2, 2, 0.003, m3, 0.003, m3, speed_idx=[1])]},
    "b17_hybrid_two_granular_instances": {"lines": ["pair_style hybrid granular granular", f"pair_coeff 1 1 granular 1 {HK}",
                                                    f"pair_coeff 1 2 granular 1 {HK}", f"pair_coeff 2 2 granular 2 hooke 8000 1000 {K}"],
        "checks": [P(2, 2, 0.002, m2, 0.002, m2, speed_idx=[2])]},
    "G36_zcylinder_hertzstiffness": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + [
        "fix m4 all property/global kn peratomtypepair 3 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5",
        "fix m5 all property/global gamman peratomtypepair 3 30000 30000 30000 30000 30000 30000 30000 30000 30000",
        "fix m6 all property/global kt peratomtypepair 3 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5",
        "fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50",
        "pair_style gran model hertz/stiffness tangential history", "pair_coeff * *"],
        "checks": [W(1, 0.002, lm1, "fix wcyl all wall/gran model hertz/stiffness tangential history primitive type 3 zcylinder 0.03 0. 0.",
                     wall_id="wcyl", axis="x", z0=0.028, zw=0.03, sign=-1, speed_idx=[0, 1])]},
    "G37_hertzstiffness_damped": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + [
        "fix m4 all property/global kn peratomtypepair 3 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5 2e5",
        "fix m5 all property/global gamman peratomtypepair 3 30000 20000 10000 20000 25000 15000 10000 15000 20000",
        "fix m6 all property/global kt peratomtypepair 3 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5",
        "fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50",
        "pair_style gran model hertz/stiffness tangential history", "pair_coeff * *"],
        "checks": [P(1, 2, 0.002, lm1, 0.003, lm2, speed_idx=[0, 1])]},
    "G40_2d_liggghts_set_density": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + LSTIFF,
        "checks": [P(1, 2, 0.002, math.pi * 0.002 ** 2 * 2500, 0.003, math.pi * 0.003 ** 2 * 1500)]},
    "G32_set_density_then_diameter": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + LSTIFF,
        "checks": [P(1, 1, 0.003, 0.000904779, 0.003, 0.000904779, label="types 2 2 (as 1 1: every entry alike)")]},

    "k05_timestep_change_between_runs": {"lines": GL(f"* * {HM}"),
        "checks": [P(1, 1, 0.002, m2, 0.002, m2, speed_idx=[1]), P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[1])]},

    "b22_set_after_pour_run": {"lines": GL(f"* * {HM}"),
        "checks": [P(2, 2, 0.003, 8.37758e-05, 0.003, 8.37758e-05, speed_idx=[0, 1], stage=2),
                   P(1, 2, 0.002, 8.37758e-05, 0.003, 8.37758e-05, speed_idx=[0], stage=2)]},

    "b27_synchronized_verlet_coarse": {"lines": GL("* * hooke 2000 3000 damping mass_velocity tangential linear_history 1000 1.0 0.3 synchronized_verlet"),
        "checks": [P(1, 2, 0.002, m2, 0.002, m2, speed_idx=[2])]},
    "b28_plain_verlet_coarse": {"lines": GL("* * hooke 2000 3000 damping mass_velocity tangential linear_history 1000 1.0 0.3"),
        "checks": [P(1, 2, 0.002, m2, 0.002, m2, speed_idx=[2])]},
    "b30_synchronized_verlet_hertz_fine": {"lines": GL("* * hertz/material 1e7 1.4e7 0.3 damping viscoelastic tangential linear_history 1000 1.0 0.3 synchronized_verlet"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[0, 1])]},

    "u11_real_gran_hertz_history": {"units": "real", "lines": ["pair_style gran/hertz/history 1e6 NULL 20 NULL 0.5 0", "pair_coeff * *"],
        "checks": [P(1, 2, 2.0, m(2.0, 2), 3.0, m(3.0, 2), speed_idx=[0, 1]),
                   W(2, 3.0, m(3.0, 2), "fix floor all wall/gran hertz/history 1e6 NULL 20 NULL 0.5 0 zplane 0 NULL", speed_idx=[1])]},
    "u12_metal_gran_hooke_history": {"units": "metal", "lines": ["pair_style gran/hooke/history 20 NULL 0.003 NULL 0.5 0", "pair_coeff * *"],
        "checks": [P(1, 2, 2.0, m(2.0, 2), 3.0, m(3.0, 2))]},
    "x01_extreme_speeds_hertz": {"lines": GL(f"* * {HM}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[0, 2]), W(1, 0.002, m2, f"fix floor all wall/gran granular {HM} zplane 0 NULL", speed_idx=[0, 1])]},
    "x02_near_critical_hooke": {"lines": GL(f"* * hooke 2000 13000 {K}"),
        "checks": [P(1, 1, 0.002, m2, 0.002, m2, speed_idx=[2])]},

    "b39_long_finite_loop_then_change": {"lines": GL(f"* * hooke 9000 3000 {K}"),
        "checks": [P(1, 2, 0.002, m2, 0.002, m2, speed_idx=[2], stage=2)]},
    "b40_long_loop_echo_then_change": {"lines": GL(f"* * hooke 9000 3000 {K}"),
        "checks": [P(1, 2, 0.002, m2, 0.002, m2, speed_idx=[2], label="types 1 2 in the production run (pair_coeff after the loop)")]},
    "p28_jkr_zero_cohesion_viscoelastic": {"lines": GL(f"* * jkr 1e7 1.4e7 0.3 0.0 damping viscoelastic {TL}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, m3, speed_idx=[0, 1])]},

    "k18_respa_granular": {"lines": GL(f"* * {HK}"), "post": ["run_style respa 2 2 pair 2"],
        "checks": [P(1, 2, 0.002, m2, 0.002, m2, speed_idx=[2])]},

    "b42_old_hertz_history_zcylinder": {"lines": ["pair_style gran/hertz/history 1e6 NULL 2000 NULL 0.5 0", "pair_coeff * *"],
        "checks": [W(1, 0.002, m2, "fix cyl all wall/gran hertz/history 1e6 NULL 2000000 NULL 0.5 0 zcylinder 0.015", wall_id="cyl", axis="x", z0=0.013, zw=0.015, sign=-1, speed_idx=[0, 1]),
                   W(2, 0.003, m3, "fix cyl all wall/gran hertz/history 1e6 NULL 2000000 NULL 0.5 0 zcylinder 0.015", wall_id="cyl", axis="x", z0=0.012, zw=0.015, sign=-1, speed_idx=[1])]},

    "p16_restyle_keeps_coeffs": {"lines": ["pair_style granular", f"pair_coeff * * {HK}", "pair_style granular", f"pair_coeff 1 1 hooke 9000 3000 {K}"],
        "checks": [P(1, 2, 0.002, m2, 0.002, m2, speed_idx=[2], stage=2), P(1, 1, 0.002, m2, 0.002, m2, speed_idx=[2], stage=2)]},
    "G14_e_one_pair": {"engine": "liggghts", "ntypes": 3, "lines": LMAT + [
        "fix m3 all property/global coefficientRestitution peratomtypepair 3 1.0 0.5 0.7 0.5 0.2 0.45 0.7 0.45 0.8",
        "pair_style gran model hertz tangential history", "pair_coeff * *"],
        "checks": [P(1, 1, 0.002, lm1, 0.002, lm1, speed_idx=[1]), P(1, 2, 0.002, lm1, 0.003, lm2, speed_idx=[1])]},

    "b16_pour_mol_type_offset": {"lines": GL(f"* * {HK}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, 0.0009, speed_idx=[2]), P(2, 2, 0.003, 0.0009, 0.003, 0.0009, speed_idx=[2])]},
    "b24_delete_after_pour_run": {"lines": GL(f"* * {HK}"),
        "checks": [P(1, 1, 0.002, 0.000167552, 0.002, 0.000167552, speed_idx=[2], stage=2)]},

    "b53_deposit_mol_offset_type_present": {"lines": GL(f"* * {HM}"),
        "checks": [P(1, 2, 0.002, m2, 0.003, 0.0009, speed_idx=[0, 1], label="types 1 2 with a deposited 6 mm type-2 sphere (audit row: its 4 mm one)"),
                   P(2, 2, 0.003, 0.0009, 0.003, 0.0009, speed_idx=[0, 1], label="types 2 2, two deposited 6 mm spheres"),
                   P(2, 2, 0.002, m2, 0.003, 0.0009, speed_idx=[0], label="types 2 2, a 4 mm and a deposited 6 mm sphere"),
                   W(2, 0.003, 0.0009, f"fix floor all wall/gran granular {HM} zplane 0 NULL", speed_idx=[0, 1], label="wall floor type 2, a deposited 6 mm sphere")]},

}


if __name__ == "__main__":
    names = sys.argv[1:] or list(S)
    for name in names:
        spec = dict({"engine": "lammps"}, **S[name])
        json.dump(spec, open(os.path.join(D, name, "spec.json"), "w"), indent=1)
    print(len(names), "specs")

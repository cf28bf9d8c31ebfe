"""Field round 14: each deck's spec.json for round 13's referee (tests/field13/referee13.py, which runs round
10's head-on referee unchanged), from the sizes and masses the engine itself holds at the end of the deck
(engine_state.txt beside each deck, written by tests/field12/engine_state.py or tests/field13/liggghts_state.py)
and the deck's own contact lines. usage: python specs14.py [DECKID ...]"""
import json, math, os, sys

D = os.path.join(os.path.dirname(os.path.abspath(__file__)), "decks")
HK = "hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
JKR = "jkr 1e7 3000 0.3 0.5 damping mass_velocity tangential linear_nohistory 1 0.3"
DMT = "dmt 1e7 3000 0.3 0.5 damping mass_velocity tangential linear_nohistory 1 0.3"
HM = "hertz/material 1e7 1.4e7 0.3 damping viscoelastic tangential linear_nohistory 1 0.3"
LL = ["pair_style granular", f"pair_coeff * * {HK}"]
FLOOR = f"fix floor all wall/gran granular {HK} zplane 0 NULL"


def m(r, rho):
    return rho * 4.0 / 3.0 * math.pi * r ** 3


def P(t1, t2, r1, m1, r2=None, m2=None, **kw):
    c = {"t1": t1, "t2": t2, "r1": r1, "m1": m1, "r2": r2 or r1, "m2": m2 or m1, "speed_idx": [2]}
    c.update(kw)
    return c


def W(t1, r1, m1, wall=FLOOR, wall_id="floor", **kw):
    c = {"t1": t1, "wall_id": wall_id, "wall": wall, "r1": r1, "m1": m1, "z0": r1, "zw": 0, "speed_idx": [2]}
    c.update(kw)
    return c


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


if __name__ == "__main__":
    main(sys.argv[1:])

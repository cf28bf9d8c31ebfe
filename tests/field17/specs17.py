"""Field round 17: each deck's spec.json for round 13's referee (tests/field13/referee13.py, which runs round 10's
head-on referee unchanged). Sizes and masses are those the deck gives with create_atoms + set (no run changes them
in these decks; the engine's own state is checked by engine.sh's run of the deck). usage: python specs17.py"""
import json, math, os

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
m = lambda r, rho: rho * 4 / 3 * math.pi * r ** 3
K = "damping mass_velocity tangential linear_nohistory 1 0.3"
HK = f"hooke 2000 3000 {K}"
HM = "hertz/material 1e7 1.4e7 0.3 damping viscoelastic tangential linear_nohistory 1 0.3"
R03 = "hertz/material 7e7 0.926 0.245 tangential mindlin NULL 1.0 0.16 rolling sds 1e5 1.0 0.1 damping tsuji twisting none"


def P(t1, t2, r1, m1, r2, m2, **kw):
    return dict({"t1": t1, "t2": t2, "r1": r1, "m1": m1, "r2": r2, "m2": m2, "speed_idx": [0, 2]}, **kw)


def W(t1, r1, m1, wall, wall_id="floor", **kw):
    return dict({"t1": t1, "wall_id": wall_id, "wall": wall, "r1": r1, "m1": m1, "z0": r1, "zw": 0, "speed_idx": [0, 2]}, **kw)


S = {
    "m01_mix_hertzmaterial_E": {"lines": ["pair_style granular",
        "pair_coeff 1 1 hertz/material 1e7 0.5 0.3 damping coeff_restitution tangential linear_nohistory 1 0.3",
        "pair_coeff 2 2 hertz/material 4e7 0.8 0.2 damping coeff_restitution tangential linear_nohistory 1 0.3"],
        "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 2500))]},
    "m02_mix_hooke_viscoelastic": {"lines": ["pair_style granular", f"pair_coeff 1 1 {HK}", f"pair_coeff 2 2 hooke 8000 1000 {K}"],
        "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 2500))]},
    "m05_limit_damping_one_pair": {"lines": ["pair_style granular", f"pair_coeff 1 1 hooke 2000 30000 {K} limit_damping",
        f"pair_coeff 2 2 hooke 2000 30000 {K}"],
        "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 2500)), P(1, 1, 0.002, m(0.002, 2500), 0.002, m(0.002, 2500))]},
    "m06_labelmap_pair_coeff": {"pre": ["labelmap atom 1 big 2 small"], "lines": ["pair_style granular", f"pair_coeff * * {HK}",
        f"pair_coeff big small hooke 5000 3000 {K}"],
        "checks": [P(1, 2, 0.003, m(0.003, 2500), 0.002, m(0.002, 2500))]},
    "w11_fix_move_partner": {"lines": ["pair_style granular", f"pair_coeff * * {HK}"],
        "integr_lines": ["fix nve a1 nve/sphere", "fix mv a2 move linear 0 0 0"],
        "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.002, m(0.002, 2500), still2=True)]},
    "w17_wallgran_limit_damping_wall_only": {"lines": ["pair_style granular", f"pair_coeff * * hooke 2000 30000 {K}"],
        "checks": [W(1, 0.002, m(0.002, 2500), f"fix floor all wall/gran granular hooke 2000 30000 {K} limit_damping zplane 0 NULL")]},
    "m10_units_cgs": {"units": "cgs", "lines": ["pair_style granular", f"pair_coeff * * hooke 2e6 3000 {K}"],
        "checks": [P(1, 2, 0.2, m(0.2, 2.5), 0.2, m(0.2, 2.5))]},
    "G16_hookestiffness_distribution": {"engine": "liggghts", "ntypes": 3, "lines": [
        "fix m1 all property/global kn peratomtypepair 3 2000 2000 2000 2000 2000 2000 2000 2000 2000",
        "fix m2 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000",
        "fix m3 all property/global gamman peratomtypepair 3 300 300 300 300 300 300 300 300 300",
        "fix m4 all property/global gammat peratomtypepair 3 100 100 100 100 100 100 100 100 100",
        "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5",
        "pair_style gran model hooke/stiffness tangential history", "pair_coeff * *"],
        "checks": [P(1, 1, 0.003, m(0.003, 2500), 0.003, m(0.003, 2500), match="smallest"),
                   P(1, 1, 0.002, m(0.002, 2500), 0.002, m(0.002, 2500), match="largest"),
                   W(1, 0.003, m(0.003, 2500), "fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0",
                     wall_id="wprim", match="smallest")]},
    "w23_fix_move_linear_null": {"lines": ["pair_style granular", f"pair_coeff * * {HK}"],
        "integr_lines": ["fix nve a1 nve/sphere", "fix mv a2 move linear NULL NULL NULL"],
        "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.002, m(0.002, 2500))]},
    "R03_dirt_column_collapse": {"ntypes": 1, "lines": ["pair_style granular", "pair_coeff 1 1 " + R03],
        "checks": [P(1, 1, 0.0015, m(0.0015, 2500), 0.0015, m(0.0015, 2500), speed_idx=[1], stage=2),
                   W(1, 0.0015, m(0.0015, 2500), "fix floor all wall/gran granular " + R03 + " zplane 0.0 NULL", speed_idx=[1], stage=2)]},
    "G20_cohesion_one_pair": {"engine": "liggghts", "ntypes": 3, "lines": [
        "fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6",
        "fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3",
        "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5",
        "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8",
        "fix m9 all property/global cohesionEnergyDensity peratomtypepair 3 5e4 0 0 0 0 0 0 0 0",
        "pair_style gran model hertz tangential history cohesion sjkr", "pair_coeff * *"],
        "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 1500), speed_idx=[1])]},
    "m13_data_type_labels": {"pre": ["labelmap atom 1 glass 2 steel"], "lines": ["pair_style granular", f"pair_coeff * * {HK}",
        f"pair_coeff glass steel hooke 6000 3000 {K}"],
        "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 7800)), P(2, 2, 0.003, m(0.003, 7800), 0.003, m(0.003, 7800))]},
    "w28_wallgran_zcylinder_hertz": {"lines": ["pair_style granular", f"pair_coeff * * {HM}"],
        "checks": [W(1, 0.002, m(0.002, 2500), f"fix cyl all wall/gran granular {HM} zcylinder 0.015", wall_id="cyl",
                     axis="x", z0=0.013, zw=0.015, sign=-1, speed_idx=[0, 2]),
                   W(2, 0.003, m(0.003, 2500), f"fix cyl all wall/gran granular {HM} zcylinder 0.015", wall_id="cyl",
                     axis="x", z0=0.012, zw=0.015, sign=-1, speed_idx=[0, 2])]},
    "d01_2d_set_density": {"dimension": 2, "lines": ["pair_style granular", f"pair_coeff * * {HK}"],
        "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 2500))]},
    "d03_2d_read_data": {"dimension": 2, "lines": ["pair_style granular", f"pair_coeff * * {HK}"],
        "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.003, m(0.003, 2500))]},
    "a21_units_lj_default_skin": {"units": "lj", "lines": ["pair_style granular", f"pair_coeff * * hooke 2e5 30 {K}"],
        "checks": [P(1, 2, 0.5, m(0.5, 1), 0.5, m(0.5, 1), speed_idx=[0])]},
    "a34_nve_noforce_type2": {"lines": ["pair_style granular", f"pair_coeff * * {HK}"],
        "integr_lines": ["fix nve a1 nve/sphere", "fix nf a2 nve/noforce"],
        "checks": [P(1, 2, 0.002, m(0.002, 2500), 0.002, m(0.002, 2500), still2=True)]},
}


if __name__ == "__main__":
    for name, spec in S.items():
        spec = dict({"engine": "lammps"}, **spec)
        if name == "m01_mix_hertzmaterial_E":
            spec["checks"][0]["speed_idx"] = [0, 1]
        json.dump(spec, open(os.path.join(D, name, "spec.json"), "w"), indent=1)
    print(len(S), "specs")

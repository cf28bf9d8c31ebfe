"""Field round 16: each deck's spec.json for round 13's referee (tests/field13/referee13.py, which runs round 10's
head-on referee unchanged), on round 15's helpers (tests/field15/specs15.py) pointed at this round's decks. Sizes and
masses are the engine's own after the stage's run (engine_stages.json from engine_stages.py; in.unrolled for decks
with loops), never the audit's. usage: python specs16.py [DECKID ...]"""
import importlib.util, json, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
_s = importlib.util.spec_from_file_location("s15", os.path.join(HERE, "..", "field15", "specs15.py"))
S15 = importlib.util.module_from_spec(_s)
_s.loader.exec_module(S15)
S15.D = D                       # E(), LS() read this round's decks
P, W, HK, LL, FLOOR, E, PE, WE, LP, LW = S15.P, S15.W, S15.HK, S15.LL, S15.FLOOR, S15.E, S15.PE, S15.WE, S15.LP, S15.LW
HM = "hertz/material 1e7 1.4e7 0.3 damping viscoelastic tangential linear_nohistory 1 0.3"
LH = ["pair_style granular", f"pair_coeff * * {HM}"]
FLOORH = f"fix floor all wall/gran granular {HM} zplane 0 NULL"
K = "damping mass_velocity tangential linear_nohistory 1 0.3"
M2, M3 = 2500 * 4 / 3 * 3.141592653589793 * 0.002 ** 3, 2500 * 4 / 3 * 3.141592653589793 * 0.003 ** 3


def build():
    S = {}
    lam = lambda n, checks, **kw: S.__setitem__(n, dict({"engine": "lammps", "lines": LL, "checks": checks}, **kw))
    # the law's rows of the neighbour decks at speeds the audit gives (the engine's own eps there under the deck's
    # lists is neighbor_check16.py's): sizes as made by the deck (create_atoms + set, no run changes them)
    lam("n01_every10_checkyes_below", [P(1, 2, 0.002, M2, 0.002, M2, speed_idx=[0, 2, 4], at_dt=True)])
    lam("n02_every10_checkno_near", [P(1, 2, 0.002, M2, 0.002, M2, speed_idx=[1])])
    lam("n11_hertzmaterial_stale", [P(1, 2, 0.002, M2, 0.002, M2, speed_idx=[0, 1])], lines=LH)
    lam("n10_granhookehistory_stale", [P(1, 2, 0.002, M2, 0.002, M2, speed_idx=[1])],
        lines=["pair_style gran/hooke/history 2000 NULL 30 NULL 0.5 1", "pair_coeff * *"])
    lam("s01_fixset_mass_unfix", [PE("s01_fixset_mass_unfix", 2, 1, 1), PE("s01_fixset_mass_unfix", 2, 1, 2),
                                  WE("s01_fixset_mass_unfix", 2, 1)])
    d = "s02b_fixset_type_atomvar"
    lam(d, [W(2, 0.002, M2, match="largest"), W(2, 0.003, M3, match="smallest")])
    d = "s03c_fixset_diameter_grows_hertz"
    lam(d, [PE(d, 1, 1, 2, astage=1), PE(d, 2, 1, 2, astage=2), WE(d, 2, 1, astage=2, wall=FLOORH)], lines=LH)
    d = "s07_set_mass_loop"
    lam(d, [PE(d, k, 2, 2, astage=k) for k in (1, 2, 3)] + [WE(d, 3, 2, astage=3)])
    d = "s09_atom_swap_odd_count_loop"
    lam(d, [PE(d, 1, 1, 1, astage=1), PE(d, 2, 1, 1, astage=2), WE(d, 4, 1, astage=3)])
    d = "s10_set_type_in_loop_by_variable"
    lam(d, [PE(d, 1, 1, 2, astage=1), PE(d, 2, 2, 2, astage=2)], lines=LH)
    d = "s11_fixset_density_never_unfixed"
    lam(d, [PE(d, 2, 2, 2), WE(d, 2, 2)])
    d = "v01b_avechunk_if_stiffness"
    lam(d, [PE(d, 2, 1, 2, astage=2)], lines=["pair_style granular", f"pair_coeff * * hooke 8000 3000 {K}"])
    d = "v02_aveatom_set_diameter"
    lam(d, [PE(d, 2, 1, 2, astage=2), WE(d, 2, 1, astage=2, wall=FLOORH)], lines=LH)
    d = "s06_set_diameter_loop"
    lam(d, [PE(d, k, 1, 2, astage=k) for k in (1, 3)], lines=LH)
    d = "w04_two_walls_disjoint_groups"
    S[d] = {"engine": "lammps", "lines": LL, "checks": [W(2, 0.003, M3, wall=f"fix floor2 all wall/gran granular {HM} zplane 0 NULL", wall_id="floor2"),
                                                         W(1, 0.002, M2, wall=FLOOR, wall_id="floor")]}
    d = "w08_wallgran_xplane_both_sides"
    S[d] = {"engine": "lammps", "lines": LL, "checks": [W(1, 0.002, M2, wall=f"fix xw all wall/gran granular {HM} xplane 0 NULL", wall_id="xw", axis="x")]}
    d = "b01_rigid_small_mol_plus_free"
    lam(d, [P(2, 2, 0.003, M3), W(2, 0.003, M3)])
    d = "R01_granudrum_liggghts_basics"
    mat = ["hard_particles yes", "soft_particles yes",
           "fix m1 all property/global youngsModulus peratomtype 5e6 5e6", "fix m2 all property/global poissonsRatio peratomtype 0.3 0.3",
           "fix m3 all property/global coefficientFriction peratomtypepair 2 0.6 0.6 0.6 0",
           "fix m4 all property/global coefficientRollingFriction peratomtypepair 2 0.5 0.5 0.5 0",
           "fix m5 all property/global coefficientRestitution peratomtypepair 2 0.3 0.3 0.3 0.1",
           "fix m6 all property/global cohesionEnergyDensity peratomtypepair 2 0 0 0 0",
           "pair_style gran model hertz tangential history cohesion sjkr rolling_friction cdt", "pair_coeff * *"]
    rho = 1580
    mm = lambda r: rho * 4 / 3 * 3.141592653589793 * r ** 3
    S[d] = {"engine": "liggghts", "ntypes": 2, "lines": mat, "checks": [
        P(1, 1, 0.000525, mm(0.000525), 0.000525, mm(0.000525), speed_idx=[0, 2, 4]),
        P(1, 1, 0.000525, mm(0.000525), 0.00075, mm(0.00075), speed_idx=[2])]}
    import importlib.util as _u
    _m = _u.spec_from_file_location("ml14", os.path.join(HERE, "..", "field14", "make_ldecks.py"))
    ML = _u.module_from_spec(_m); _m.loader.exec_module(ML)
    mat3 = ML.MAT3.strip().splitlines()
    lig = lambda n, checks, lines: S.__setitem__(n, {"engine": "liggghts", "ntypes": 3, "lines": lines, "checks": checks})
    e3 = lambda e11: [f"fix m3 all property/global coefficientRestitution peratomtypepair 3 {e11} 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8"]
    hz = ["pair_style gran model hertz tangential history", "pair_coeff * *"]
    lig("L11_loop_e_from_index", [LP("L11_loop_e_from_index", 1, 1, stage=1)], mat3 + e3(0.3) + hz)
    lig("L12_restart_in_loop", [LP("L12_restart_in_loop", 1, 1, stage=2)], mat3 + e3(0.5) + hz)
    st = ML.STIFF3.strip().splitlines()
    st[0] = "fix m4 all property/global kn peratomtypepair 3 2000 2500 3000 2500 4000 3500 3000 3500 5000"
    lig("L17_hooke_stiffness_peratomtype_loop", [LP("L17_hooke_stiffness_peratomtype_loop", 1, 1, stage=2),
        LW("L17_hooke_stiffness_peratomtype_loop", 1, wall="fix wprim all wall/gran model hooke/stiffness tangential history primitive type 3 zplane 0.0", stage=2)],
        mat3 + st + ["pair_style gran model hooke/stiffness tangential history", "pair_coeff * *"])
    lig("L14_peratomtype_from_variables", [LP("L14_peratomtype_from_variables", 1, 2)],
        ["fix m1 all property/global youngsModulus peratomtype 5e6 1e7 5e6", "fix m2 all property/global poissonsRatio peratomtype 0.25 0.25 0.25",
         "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5",
         "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.55 0.7 0.55 0.4 0.45 0.7 0.45 0.8",
         "pair_style gran model hooke tangential history", "pair_coeff * *", "fix m11 all property/global characteristicVelocity scalar 1.0"])
    lam("x06_shell_putenv_getenv", [P(1, 2, 0.002, M2, 0.003, M3)], lines=["pair_style granular", f"pair_coeff * * hooke 4000 3000 {K}"])
    lam("v03_avecorrelate_if", [P(1, 2, 0.002, M2, 0.003, M3, stage=2)], lines=["pair_style granular", f"pair_coeff * * hooke 2000 6000 {K}"])
    lam("v04_fix_vector_if", [P(1, 2, 0.002, M2, 0.003, M3, stage=2)], lines=["pair_style granular", f"pair_coeff * * hooke 5000 3000 {K}"])
    lam("v05_avetime_running_loop", [P(1, 2, 0.002, M2, 0.003, M3, stage=2)], lines=["pair_style granular", f"pair_coeff * * hooke 2000 1500 {K}"])
    lam("x05_write_restart_parent_then_read", [P(1, 2, 0.002, M2, 0.003, M3, stage=2)], lines=["pair_style granular", f"pair_coeff * * hooke 3000 3000 {K}"])
    lam("n21_every5_checkyes_default_skin", [P(1, 2, 0.002, M2, 0.002, M2, speed_idx=[2], at_dt=True)])
    lam("n24_granhertzhistory_every10_checkyes", [P(1, 2, 0.002, M2, 0.002, M2, speed_idx=[1])],
        lines=["pair_style gran/hertz/history 2e7 NULL 3000 NULL 0.5 1", "pair_coeff * *"])
    lam("n23_hertzmaterial_every10_checkyes", [P(1, 2, 0.002, M2, 0.002, M2, speed_idx=[1])], lines=LH)
    d = "R02b_repose_no_twisting_none"
    HMc = "hertz/material 1e7 0.5 0.3 tangential mindlin NULL 1.0 0.5 damping coeff_restitution rolling sds 1e3 10 0.1"
    r, m = E(d, 1, 1)
    S[d] = {"engine": "lammps", "ntypes": 1, "lines": ["pair_style granular", f"pair_coeff 1 1 {HMc}"],
            "pre": ["region cyl cylinder z 0 0 0.025 -0.05 0.05 units box"],
            "checks": [P(1, 1, r, m, stage=1), W(1, r, m, wall=f"fix floor all wall/gran granular {HMc} zplane 0.0 NULL", wall_id="floor", stage=2),
                       W(1, r, m, wall=f"fix cylwall all wall/gran/region granular {HMc} region cyl", wall_id="cylwall", axis="x",
                         z0=0.025 - r, zw=0.025, sign=-1, touch=r, face="curved", stage=1)]}
    return S


if __name__ == "__main__":
    S = build()
    for n in (sys.argv[1:] or S):
        json.dump(S[n], open(os.path.join(D, n, "spec.json"), "w"), indent=1)
        print("spec", n)

"""Field round 15: each deck's spec.json for round 13's referee (tests/field13/referee13.py, which runs round
10's head-on referee unchanged). Sizes and masses are the engine's own after the stage's run
(engine_stages.json from engine_stages.py, LAMMPS; liggghts_state.txt from tests/field13/liggghts_state.py),
read here by `E(deck, stage, type)`, never from the audit. usage: python specs15.py [DECKID ...]"""
import importlib.util, json, os, sys

HERE = os.path.dirname(os.path.abspath(__file__))
D = os.path.join(HERE, "decks")
_s = importlib.util.spec_from_file_location("s14", os.path.join(HERE, "..", "field14", "specs14.py"))
S14 = importlib.util.module_from_spec(_s)
_s.loader.exec_module(S14)
P, W, HK, LL, FLOOR = S14.P, S14.W, S14.HK, S14.LL, S14.FLOOR
MAT3, E3, HERTZ, WALL3, STIFF3 = S14.MAT3, S14.E3, S14.HERTZ, S14.WALL3, S14.STIFF3


def E(deck, stage, t):
    """(r, m) LAMMPS holds for type t after the stage's run (stage 1-based, -1 the last); one size only."""
    st = json.load(open(os.path.join(D, deck, "engine_stages.json")))
    v = st[stage - 1 if stage > 0 else stage]["state"][str(t)]
    assert len(v) == 1, (deck, stage, t, v)
    return tuple(v[0])


def LS(deck, t):
    """(r, m) LIGGGHTS holds for type t at the deck's end (liggghts_state.txt); one size only."""
    for ln in open(os.path.join(D, deck, "liggghts_state.txt")):
        if ln.startswith(f"type {t}:"):
            parts = ln.split(":")[1].split(",")
            assert len(parts) == 1, (deck, t, ln)
            w = parts[0].split()
            return float(w[1]), float(w[3])
    raise KeyError((deck, t))


def PE(deck, stage, t1, t2, astage=None, **kw):
    a, b = E(deck, stage, t1), E(deck, stage, t2)
    if astage:
        kw["stage"] = astage
    return P(t1, t2, a[0], a[1], b[0], b[1], **kw)


def WE(deck, stage, t, astage=None, **kw):
    a = E(deck, stage, t)
    if astage:
        kw["stage"] = astage
    return W(t, a[0], a[1], **kw)


def LP(deck, t1, t2, **kw):
    a, b = LS(deck, t1), LS(deck, t2)
    return P(t1, t2, a[0], a[1], b[0], b[1], **kw)


def LW(deck, t, wall=WALL3, wall_id="wprim", **kw):
    a = LS(deck, t)
    return W(t, a[0], a[1], wall=wall, wall_id=wall_id, **kw)


def build():
    S = {}
    lam = lambda n, checks, **kw: S.__setitem__(n, dict({"engine": "lammps", "lines": LL, "checks": checks}, **kw))
    lam("a01_adapt_N7_ramp_count_unfix", [PE("a01_adapt_N7_ramp_count_unfix", 2, 1, 2, 2), WE("a01_adapt_N7_ramp_count_unfix", 2, 1, 2)])
    lam("a04_adapt_mass_no_constant_count", [PE("a04_adapt_mass_no_constant_count", 2, 1, 2, 2), WE("a04_adapt_mass_no_constant_count", 2, 1, 2)])
    lam("a05_adapt_run_start_stop", [PE("a05_adapt_run_start_stop", 2, 1, 2, 2), WE("a05_adapt_run_start_stop", 2, 2, 2)])
    lam("a07_adapt_scale_yes_pre_no", [PE("a07_adapt_scale_yes_pre_no", 3, 1, 2, 2), WE("a07_adapt_scale_yes_pre_no", 3, 1, 2)])
    lam("a09_adapt_time_var_group_type2_count_loop", [PE("a09_adapt_time_var_group_type2_count_loop", -1, 1, 2, 4),
                                                      PE("a09_adapt_time_var_group_type2_count_loop", -1, 2, 2, 4),
                                                      WE("a09_adapt_time_var_group_type2_count_loop", -1, 2, 4)])
    lam("a10_deform_then_lz_diameter", [PE("a10_deform_then_lz_diameter", 2, 1, 1, 2), WE("a10_deform_then_lz_diameter", 2, 1, 2)])
    lam("a11_var_after_run_k_from_step_pour", [PE("a11_var_after_run_k_from_step_pour", 2, 1, 2, 2)],
        lines=["pair_style granular", "pair_coeff * * hooke 3000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"])
    lam("a13_pour_loop_pe", [PE("a13_pour_loop_pe", -1, 1, 2, 2), WE("a13_pour_loop_pe", -1, 1, 2)])
    lam("a16_create_random_after_run", [PE("a16_create_random_after_run", 2, 1, 2, 2), WE("a16_create_random_after_run", 2, 2, 2)])
    lam("a19_deposit_no_set", [PE("a19_deposit_no_set", 1, 2, 2, tc=0.1), WE("a19_deposit_no_set", 1, 2, tc=0.1)])
    lam("a12_pour_loop_count_then_set", [PE("a12_pour_loop_count_then_set", -1, 1, 2, 2), WE("a12_pour_loop_count_then_set", -1, 1, 2)])
    lam("a25_type2_poured_in_second_run", [PE("a25_type2_poured_in_second_run", 2, 1, 2, 2), WE("a25_type2_poured_in_second_run", 2, 2, 2)])
    lam("m01_adapt_fep_diameter_growth", [PE("m01_adapt_fep_diameter_growth", 2, 1, 2, 2), WE("m01_adapt_fep_diameter_growth", 2, 2, 2)])
    lam("m02_adapt_fep_diameter_kept", [PE("m02_adapt_fep_diameter_kept", 1, 2, 2)])
    lam("u04_read_data_diameter_density", [PE("u04_read_data_diameter_density", 1, 1, 2), WE("u04_read_data_diameter_density", 1, 2)])
    lam("u08_fix_property_atom_mol_set_by_var", [PE("u08_fix_property_atom_mol_set_by_var", 1, 1, 2), WE("u08_fix_property_atom_mol_set_by_var", 1, 2)])
    lam("u06_hybrid_overlay_lj_11", [PE("u06_hybrid_overlay_lj_11", 1, 1, 2)],
        lines=["pair_style hybrid/overlay granular lj/cut 0.01", f"pair_coeff * * granular {HK}", "pair_coeff 1 1 lj/cut 1e-6 0.004",
               "pair_coeff 1 2 lj/cut 0 0.004", "pair_coeff 2 2 lj/cut 0 0.004"])
    lam("b14_rigid_small_group_type2_mol_ids_from_type", [PE("b14_rigid_small_group_type2_mol_ids_from_type", 1, 1, 1)])
    lam("x04_deck_is_symlink", [P(2, 2, 0.003, 1500 * 4 / 3 * 3.141592653589793 * 0.003 ** 3)])
    HK1e3 = "hooke 2e6 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
    lam("u01_units_cgs", [PE("u01_units_cgs", 1, 1, 2), WE("u01_units_cgs", 1, 2, wall=f"fix floor all wall/gran granular {HK1e3} zplane 0 NULL")],
        units="cgs", lines=["pair_style granular", f"pair_coeff * * {HK1e3}"])
    HMm = "hertz/material 1e4 0.5 0.3 damping coeff_restitution tangential linear_nohistory 1 0.3"
    lam("u02_units_micro", [PE("u02_units_micro", 1, 1, 2), WE("u02_units_micro", 1, 1, wall=f"fix floor all wall/gran granular {HMm} zplane 0 NULL")],
        units="micro", lines=["pair_style granular", f"pair_coeff * * {HMm}"])
    HKn = "hooke 1e-3 1e-6 damping mass_velocity tangential linear_nohistory 1 0.3"
    lam("u03_units_nano_hooke", [PE("u03_units_nano_hooke", 1, 1, 2), WE("u03_units_nano_hooke", 1, 1, wall=f"fix floor all wall/gran granular {HKn} zplane 0 NULL")],
        units="nano", lines=["pair_style granular", f"pair_coeff * * {HKn}"])
    K4 = "hooke 4000 3000 damping mass_velocity tangential linear_nohistory 1 0.3"
    lam("w10_block_open_side_faces_floor", [WE("w10_block_open_side_faces_floor", 1, 1, wall=f"fix cont all wall/gran/region granular {HK} region bx",
                                               wall_id="cont", z0=0.002, zw=0.0)],
        pre=["region bx block -0.05 0.05 -0.05 0.05 0 0.09 open 6 units box"])
    lam("w11_block_open_bottom_plane_region_floor", [
        WE("w11_block_open_bottom_plane_region_floor", 1, 1, wall=f"fix floor all wall/gran/region granular {HK} region pl", wall_id="floor",
           label="floor row vs floor + open-bottomed block (engine truth)", spec_override={"post": [f"fix cont all wall/gran/region granular {K4} region bx"]})],
        pre=["region pl plane 0 0 0 0 0 1 side in", "region bx block -0.05 0.05 -0.05 0.05 0 0.09 open 5 units box"])
    lam("w06_block_variable_face_constant", [WE("w06_block_variable_face_constant", 1, 1, wall=f"fix floor all wall/gran/region granular {HK} region bx",
                                                label="floor (no audit row: named as moving) engine", wall_id="floor")],
        pre=["variable zl equal 0", "region bx block -1 1 -1 1 -0.05 v_zl side out units box"])
    lam("w09_plane_region_rotate_const_angle", [WE("w09_plane_region_rotate_const_angle", 1, 1, wall=f"fix floor all wall/gran/region granular {HK} region pl",
                                                   label="floor (no audit row: named as moving) engine", wall_id="floor")],
        pre=["variable th equal 0", "region pl plane 0 0 0 0 0 1 side in rotate v_th 0 0 0 0 1 0"])

    HM = "hertz/material 1e7 1.4e7 0.3 damping viscoelastic tangential linear_nohistory 1 0.3"
    lam("n03b_fix_set_diameter_hertz", [PE("n03b_fix_set_diameter_hertz", 2, 1, 1), PE("n03b_fix_set_diameter_hertz", 2, 1, 2),
                                        WE("n03b_fix_set_diameter_hertz", 2, 1, wall=f"fix floor all wall/gran granular {HM} zplane 0 NULL")],
        lines=["pair_style granular", f"pair_coeff * * {HM}"])
    lam("n04_fix_set_density_then_unfix", [PE("n04_fix_set_density_then_unfix", 2, 1, 2), PE("n04_fix_set_density_then_unfix", 2, 2, 2),
                                           WE("n04_fix_set_density_then_unfix", 2, 2)])
    lam("n04b_fix_set_density_count_read", [PE("n04b_fix_set_density_count_read", 2, 2, 2), WE("n04b_fix_set_density_count_read", 2, 2)])
    lam("d01_2d_density_disc", [PE("d01_2d_density_disc", 1, 1, 2, tc=0.01)], dimension=2)
    K = "damping mass_velocity tangential linear_nohistory 1 0.3"
    lam("c01_run_upto_step_read", [PE("c01_run_upto_step_read", 3, 1, 2, 2)], lines=["pair_style granular", f"pair_coeff * * hooke 2500 3000 {K}"])
    lam("c02_time_after_dt_change", [PE("c02_time_after_dt_change", 3, 1, 2, 2)], lines=["pair_style granular", f"pair_coeff * * hooke 4000 3000 {K}"])
    lam("c03_reset_timestep_time_kw", [PE("c03_reset_timestep_time_kw", 2, 1, 2)], lines=["pair_style granular", f"pair_coeff * * hooke 2000 3000 {K}"])
    lam("w18_region_cylinder_hertz", [WE("w18_region_cylinder_hertz", 1, 1, wall=f"fix cw all wall/gran/region granular {HM} region cy", wall_id="cw",
                                         axis="x", z0=0.0055, zw=0.0075, sign=-1, match="inside", z=0.05)],
        lines=["pair_style granular", f"pair_coeff * * {HM}"], pre=["region cy cylinder z 0 0 0.0075 -1 1 side in units box"])
    TS = "hooke 2000 0.5 damping tsuji tangential linear_nohistory 1 0.3"
    lam("p02_hooke_damping_tsuji", [PE("p02_hooke_damping_tsuji", 1, 1, 2), WE("p02_hooke_damping_tsuji", 1, 2, wall=f"fix floor all wall/gran granular {TS} zplane 0 NULL")],
        lines=["pair_style granular", f"pair_coeff * * {TS}"])
    HV = "hertz 1e6 50 damping viscoelastic tangential linear_nohistory 1 0.3"
    lam("p03_hertz_damping_viscoelastic", [PE("p03_hertz_damping_viscoelastic", 1, 1, 2)], lines=["pair_style granular", f"pair_coeff * * {HV}"])
    lam("w16_region_plane_tilted_only_floor", [WE("w16_region_plane_tilted_only_floor", 1, 1, wall=f"fix floor all wall/gran/region granular {HK} region pl",
                                                  label="tilted plane met along -z, the plane's normal tilted 30 deg (LAMMPS: the contact along the normal)")],
        pre=["region pl plane 0 0 0 0 0 1 side in units box"])
    lig = lambda n, lines, checks, **kw: S.__setitem__(n, dict({"engine": "liggghts", "ntypes": 3, "lines": lines, "checks": checks}, **kw))
    DUMP = {"post": ["create_atoms 1 single 0.1 0.1 0.1 units box", "set atom 3 diameter 0.004 density 2500"]}
    DUMW = {"post": ["create_atoms 1 single 0.1 0.1 0.1 units box", "set atom 2 diameter 0.004 density 2500"]}
    E3B = "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.3 0.35 0.4 0.35 0.45 0.5 0.4 0.5 0.55"
    CV = "fix m11 all property/global characteristicVelocity scalar 1.0"
    lig("L01_restart_clear_new_e", MAT3 + [E3B] + HERTZ, [LP("L01_restart_clear_new_e", 1, 2, stage=2), LW("L01_restart_clear_new_e", 1, stage=2)])
    lig("L02_restart_pair_style_changed", MAT3 + [E3, CV, "pair_style gran model hooke tangential history", "pair_coeff * *"],
        [LP("L02_restart_pair_style_changed", 1, 2, stage=2),
         LW("L02_restart_pair_style_changed", 2, wall="fix wprim all wall/gran model hooke tangential history primitive type 3 zplane 0.0", stage=2, spec_override=DUMW)])
    DUMP = {"post": ["create_atoms 1 single 0.1 0.1 0.1 units box", "set atom 3 diameter 0.004 density 2500"]}
    DUMW = {"post": ["create_atoms 1 single 0.1 0.1 0.1 units box", "set atom 2 diameter 0.004 density 2500"]}
    lig("L03_restart_resized_after_read", MAT3 + [E3] + HERTZ, [LP("L03_restart_resized_after_read", 2, 2, stage=2, spec_override=DUMP)])
    lig("L08_hooke_tangential_damping_off", MAT3 + [E3, CV, "pair_style gran model hooke tangential history tangential_damping off", "pair_coeff * *"],
        [LP("L08_hooke_tangential_damping_off", 1, 2)])
    GABS = ["fix m12 all property/global gamman_abs peratomtypepair 3 0.3 0.2 0.1 0.2 0.25 0.15 0.1 0.15 0.2",
            "fix m13 all property/global gammat_abs peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1"]
    lig("L09_hooke_limitforce_absolute_damping", MAT3 + STIFF3 + GABS + ["pair_style gran model hooke/stiffness tangential history limitForce on absolute_damping on",
                                                                     "pair_coeff * *"],
        [LP("L09_hooke_limitforce_absolute_damping", 1, 1), LP("L09_hooke_limitforce_absolute_damping", 2, 2, spec_override=DUMP)])
    lig("L07_hertzstiff_rolling_cdt", MAT3 + STIFF3 + ["fix m10 all property/global coefficientRollingFriction peratomtypepair 3 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1",
                                                     "pair_style gran model hertz/stiffness tangential history rolling_friction cdt", "pair_coeff * *"],
        [LP("L07_hertzstiff_rolling_cdt", 1, 2)])
    lig("L06_cohesion_sjkr2", MAT3 + [E3, "fix m9 all property/global cohesionEnergyDensity peratomtypepair 3 300000 0 0 0 0 0 0 0 0",
                                      "pair_style gran model hertz tangential history cohesion sjkr2", "pair_coeff * *"],
        [LP("L06_cohesion_sjkr2", 1, 2)])
    lig("L14_hertz_e_from_variable_after_step", MAT3 + [E3.replace("3 0.6 0.5", "3 0.5 0.5")] + HERTZ,
        [LP("L14_hertz_e_from_variable_after_step", 1, 1, stage=2)])
    lig("L12_adapt_growth_count_read", MAT3 + STIFF3 + ["pair_style gran model hooke/stiffness tangential history", "pair_coeff * *"],
        [LP("L12_adapt_growth_count_read", 1, 2, stage=2)])
    return S


if __name__ == "__main__":
    S = build()
    names = sys.argv[1:] or list(S)
    for n in names:
        json.dump(S[n], open(os.path.join(D, n, "spec.json"), "w"), indent=1)
    print("specs:", len(names))

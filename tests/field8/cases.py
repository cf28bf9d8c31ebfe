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
    for r in (0.0005062582509797333, 0.0006099561759045066):
        m = R.sphere_mass(r, 1580)
        ref = R.extrapolate(lambda **kw: R.liggghts_pair(mat, 1, r, m, 1, r, m, 0.5, **kw), 1e-7)
        report("r05", f"1-1 r={r:.6g} g=0.5", eps_of(find(st["pairs"], [1, 1]), 0.5), ref)
    # the mesh face: a flat two-triangle mesh of type 2 with the deck's wall line (a stand-in for
    # cylinder.stl's faces: the face is flat, LIGGGHTS takes the sphere's radius against a wall)
    stl = ("solid f\nfacet normal 0 0 1\nouter loop\nvertex -1 -1 0\nvertex 1 -1 0\nvertex 1 1 0\n"
           "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex -1 -1 0\nvertex 1 1 0\n"
           "vertex -1 1 0\nendloop\nendfacet\nendsolid f\n")
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


CASES = {k: v for k, v in dict(globals()).items() if k[:1] in "ra" and k[1:3].isdigit()}

if __name__ == "__main__":
    for name in sys.argv[1:]:
        CASES[name]()

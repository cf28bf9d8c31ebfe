"""What the spec tables of field rounds 18-21 share: the contact strings, sizes and masses they name, the check
builders (a pair `P`, a wall `W`) and the writer of each deck's spec.json for the spec referee
(tests/fieldkit/spec_referee.py). Each round's specsNN.py keeps its own table S (the record of what it checked).
"""
import json, math, os

m = lambda r, rho: rho * 4 / 3 * math.pi * r ** 3  # noqa: E731 (the tables call it as a short name)
TL = "tangential linear_nohistory 1 0.3"
K = f"damping mass_velocity {TL}"
HK = f"hooke 2000 3000 {K}"
HM = f"hertz/material 1e7 1.4e7 0.3 damping viscoelastic {TL}"
m2, m3 = m(0.002, 2500), m(0.003, 2500)
LMAT = ["fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6",
        "fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3",
        "fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5"]
LE3 = ["fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8"]

# rounds 19-21's LIGGGHTS hooke/stiffness lines
LST = ["fix m4 all property/global kn peratomtypepair 3 2000 2500 3000 2500 4000 3500 3000 3500 5000",
       "fix m5 all property/global gamman peratomtypepair 3 300 200 100 200 250 150 100 150 200",
       "fix m6 all property/global kt peratomtypepair 3 1000 1000 1000 1000 1000 1000 1000 1000 1000",
       "fix m8 all property/global gammat peratomtypepair 3 50 50 50 50 50 50 50 50 50",
       "pair_style gran model hooke/stiffness tangential history", "pair_coeff * *"]
# rounds 13-14's granular hooke and floor, and their check builders (the middle speed; r2, m2 default to r1, m1)
LL = ["pair_style granular", f"pair_coeff * * {HK}"]
FLOOR = f"fix floor all wall/gran granular {HK} zplane 0 NULL"


def P13(t1, t2, r1, m1, r2=None, m2=None, **kw):
    """Rounds 13-14's pair check: the third speed; the second sphere the first's unless given."""
    c = {"t1": t1, "t2": t2, "r1": r1, "m1": m1, "r2": r2 or r1, "m2": m2 or m1, "speed_idx": [2]}
    c.update(kw)
    return c


def W13(t1, r1, m1, wall=FLOOR, wall_id="floor", **kw):
    """Rounds 13-14's wall check: the third speed, the granular hooke floor unless a wall is given."""
    c = {"t1": t1, "wall_id": wall_id, "wall": wall, "r1": r1, "m1": m1, "z0": r1, "zw": 0, "speed_idx": [2]}
    c.update(kw)
    return c


def P(t1, t2, r1, m1, r2, m2_, **kw):
    """A pair check: types, radii and masses (the engine's), the first speed unless `speed_idx` says others.

    Examples
    --------
    >>> P(1, 2, 0.002, 1.0, 0.003, 2.0, stage=2)["stage"]
    2
    """
    return dict({"t1": t1, "t2": t2, "r1": r1, "m1": m1, "r2": r2, "m2": m2_, "speed_idx": [0]}, **kw)


def W(t1, r1, m1, wall, wall_id="floor", **kw):
    """A wall check: the sphere's type, radius and mass, the wall's fix line and ID (a zplane-0 floor by default)."""
    return dict({"t1": t1, "wall_id": wall_id, "wall": wall, "r1": r1, "m1": m1, "z0": r1, "zw": 0, "speed_idx": [0]}, **kw)


def GL(*lines):
    """A granular pair style with the pair_coeff lines given.

    Examples
    --------
    >>> GL("* * hooke 1 2")
    ['pair_style granular', 'pair_coeff * * hooke 1 2']
    """
    return ["pair_style granular"] + [f"pair_coeff {x}" for x in lines]


def hk(k, gam=3000):
    """The hooke model at stiffness `k` and damping `gam`, mass_velocity damping, linear_nohistory tangential."""
    return f"hooke {k} {gam} {K}"


def write(S, D, names):
    """Write the spec.json of each deck named (all of `S` when `names` is empty) into its folder under `D`."""
    for n in names or S:
        s = dict({"engine": "lammps"}, **S[n])
        json.dump(s, open(os.path.join(D, n, "spec.json"), "w"), indent=1)
    print(len(names or S), "specs")

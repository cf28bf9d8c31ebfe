"""Probe (field round 46, lists 2): a command X between runs mid-contact (or from the start) in one of several base
decks; the engine's eps (1 process, and 2 under mpirun where NP=2) vs the audit's words. A cases file's first line
may be `#base NAME` (lmp, lmp2d, lig, lig2d; default lmp), then `#measure EXPR` (the engine's relative velocity,
minus, in place of vx[1]-vx[2]; the first LIVEVR line printed counts, so a case may print its own earlier), `#row
PREFIX` (the audit's row in place of "types 1 2") and `#stage last` (the last stage's row); a cases line is
BETWEEN || START || HEAD || FIRSTRUN (" ;; " joins commands in one field; an empty field is "||  ||"). Each case's
folder, and the engine's, hold extra.data, one.mol (the first lists round's) and plane.stl (LIGGGHTS' mesh). The pair: types 1 and 2, radii 2 and 3 mm, head-on along x at a relative
speed of 1 m/s, meeting at x = 0.02 (the middle of the LAMMPS box: the border of `processors 2 1 1`) at step ~100.
lmp/lmp2d: hooke kn 2000 damping 3000 mass_velocity (LAMMPS 0.4134 at dt 1e-6, a contact ~586 steps);
lig/lig2d: hertz, typed e 0.5. The eps is the relative x velocity after the runs over the 1 m/s before.
usage: PROBE_OUT=DIR [NP=2] python probe2.py CASES"""
import os, re, shutil, subprocess, sys, tempfile

LMP = """units si
{dim}atom_style sphere 1
atom_modify map array
boundary {bnd}
comm_modify vel yes
{head}
region box block 0 0.04 0 0.04 {zlo} {zhi} units box
create_box 2 box
pair_style granular
pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3
fix grav all gravity 9.81 vector {gvec}
fix integ all nve/sphere{disc}
{e2d}timestep 1e-6
create_atoms 1 single 0.017950 0.02 {z}
create_atoms 2 single 0.023050 0.02 {z}
set atom 1 diameter 0.004 {dens1}
set atom 2 diameter 0.006 {dens2}
group lv1 id 1
group lv2 id 2
group far empty
velocity lv1 set 0.7714285714 0 0 units box
velocity lv2 set -0.2285714286 0 0 units box
{start}
run {first}
{between}
run 2000
variable vr equal vx[1]-vx[2]
print "LIVEVR ${{vr}}"
"""
LMP3 = dict(dim="", bnd="p p f", zlo="0", zhi="0.1", gvec="0 0 -1", disc="", e2d="", z="0.05", dens1="density 2500", dens2="density 2500")
LMP2 = dict(dim="dimension 2\n", bnd="p p p", zlo="-0.005", zhi="0.005", gvec="0 -1 0", disc=" disc",
            e2d="fix e2d all enforce2d\n", z="0",
            # the 3d spheres' masses: area density 2500 (4/3) r
            dens1="density/disc 6.666666667", dens2="density/disc 10")
LIG = """atom_style granular
atom_modify map array
boundary {bnd}
newton off
communicate single vel yes
units si
{dim}{head}
region reg block -0.05 0.05 -0.05 0.05 {zlo} {zhi} units box
create_box 2 reg
neighbor 0.002 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3
fix m7 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.6 0.5 0.5 0.4
{pair}
pair_coeff * *
timestep 1e-6
fix gravi all gravity 9.81 vector {gvec}
fix integr all nve/sphere
{e2d}create_atoms 1 single -0.002550 0 {z} units box
create_atoms 2 single 0.002550 0 {z} units box
set atom 1 diameter 0.004 density 2500
set atom 2 diameter 0.006 density 2500
group lv1 id 1
group lv2 id 2
velocity lv1 set 0.7714285714 0 0
velocity lv2 set -0.2285714286 0 0
{start}
run {first}
{between}
run 2000
variable vr equal vx[1]-vx[2]
print "LIVEVR ${{vr}}"
"""
LIG3 = dict(bnd="p f f", dim="", zlo="-0.01", zhi="0.15", gvec="0.0 0.0 -1.0", e2d="", z="0.1")
LIG2 = dict(bnd="p f p", dim="dimension 2\n", zlo="-0.005", zhi="0.005", gvec="0.0 -1.0 0.0",
            e2d="fix e2d all enforce2d\n", z="0")
BASES = {"lmp": (LMP, LMP3), "lmp2d": (LMP, LMP2), "lig": (LIG, LIG3), "lig2d": (LIG, LIG2)}

EXTRA = """x

1 atoms
2 atom types

0 0.04 xlo xhi
0 0.04 ylo yhi
0 0.1 zlo zhi

Atoms # sphere

1 1 0.004 2500 0.0206 0.02 0.0545 0 0 0
"""


#: a one-atom molecule (the first lists round's cases read it)
MOL = """x

1 atoms

Coords

1 0 0 0

Types

1 1
"""
#: a square of two facets at z = 0 (LIGGGHTS' fix mesh/surface file plane.stl; move it with its move keyword)
PLANE = """solid plane
facet normal 0 0 1
 outer loop
  vertex -0.04 -0.04 0
  vertex 0.04 -0.04 0
  vertex 0.04 0.04 0
 endloop
endfacet
facet normal 0 0 1
 outer loop
  vertex -0.04 -0.04 0
  vertex 0.04 0.04 0
  vertex -0.04 0.04 0
 endloop
endfacet
endsolid plane
"""


def engine(deck, np=1, lig=False):
    """The engine's measured eps: the deck run in a folder of its own (files it writes stay there)."""
    open(os.path.join(d0 := tempfile.mkdtemp(prefix="l46b."), "plane.stl"), "w").write(PLANE)
    open(os.path.join(d0, "extra.data"), "w").write(EXTRA)
    open(os.path.join(d0, "one.mol"), "w").write(MOL)
    if np == 1:     # the one-process reference: a processors grid for 2 is LAMMPS' stop on 1, so it goes
        deck = "\n".join(l for l in deck.split("\n") if not l.startswith("processors"))
    d = d0
    open(os.path.join(d, "in.deck"), "w").write(deck)
    if lig:
        cmd = ["liggghts", "-in", "in.deck", "-log", "none"]
    else:
        cmd = ["lmp", "-in", "in.deck", "-log", "none", "-nocite"]
    if np > 1:
        # LAMMPS' lmp is the venv's (MPICH, its mpirun); the liggghts binary is linked to Open MPI
        cmd = (["mpirun.openmpi", "--oversubscribe", "--allow-run-as-root"] if lig else ["mpirun"]) + ["-np", str(np)] + cmd
    try:
        p = subprocess.run(cmd, cwd=d, capture_output=True, text=True, errors="replace", timeout=300)
    except subprocess.TimeoutExpired:
        return "timeout"
    finally:
        shutil.rmtree(d)
    for l in p.stdout.splitlines():
        if l.startswith("LIVEVR "):
            return -float(l.split()[1])
    err = [l for l in (p.stdout + p.stderr).splitlines() if "ERROR" in l]
    return f"stops rc{p.returncode}: {(err or ['(no line)'])[0][:90]}"


ROW = ["types 1 2"]
LAST = [False]


def audit(path):
    p = subprocess.run(["restitution", "deck", path, "--g", "1"], capture_output=True, text=True)
    out = p.stdout.splitlines()
    # the row at g 1 (the probe's impact speed) of the first types 1 2 block (stage 1 where there are stages)
    eps = [k for k, l in enumerate(out) if l.startswith(ROW[0])]
    k = eps[-1] if LAST[0] and eps else eps[0] if eps else None
    rows = [l for l in out[k + 1:k + 7] if l.split()[:2] == ["g", "1"]] if eps else []
    line = rows[0] if rows else ""
    value = "sticks" if "sticks" in line else line.split("eps")[1].split()[0] if "eps" in line else "-"
    return p.returncode, value, p.stderr, p.stdout


def fmt(e):
    return e if isinstance(e, str) else f"{e:.6f}"


if __name__ == "__main__":
    lines = open(sys.argv[1]).read().splitlines()
    base = lines[0].split()[1] if lines and lines[0].startswith("#base") else "lmp"
    # optional header lines: `#measure EXPR` (the relative velocity, minus, that the engine prints in place of
    # vx[1]-vx[2]), `#row PREFIX` (the audit's row read in place of "types 1 2")
    text, fill = BASES[base]
    heads = {l.split()[0]: l.split(None, 1)[1] for l in lines if l.startswith(("#measure ", "#row ", "#stage "))}
    # `#stage last`: the last stage's row (where the pair meets after the change), not the first's
    LAST[0] = heads.get("#stage") == "last"
    if "#measure" in heads:
        text = text.replace("vx[1]-vx[2]", heads["#measure"])
    ROW[0] = heads.get("#row", "types 1 2")
    lig = base.startswith("lig")
    np = int(os.environ.get("NP", "1"))
    cases = [l for l in lines if l.strip() and not l.startswith("#")]
    only = os.environ.get("ONLY")
    for n, case in enumerate(cases):
        if only and n not in [int(x) for x in only.split(",")]:
            continue
        parts = dict(zip(["between", "start", "head", "first"], (case.split(" || ") + ["", "", "", ""])[:4]))
        parts = {k: v.strip().replace(" ;; ", "\n") for k, v in parts.items()}
        parts["first"] = parts["first"] or "300"
        if lig:
            heads = parts["head"].split("\n")
            pair = [h for h in heads if h.startswith("pair_style")]
            parts["pair"] = pair[0] if pair else "pair_style gran model hertz tangential history"
            parts["head"] = "\n".join(h for h in heads if not h.startswith("pair_style"))
        deck = text.format(**parts, **fill)
        d = os.path.join(os.environ.get("PROBE_OUT") or tempfile.gettempdir(),
                         f"{os.path.basename(sys.argv[1])[:-4]}-{n:02d}")
        os.makedirs(d, exist_ok=True)
        open(f"{d}/in.deck", "w").write(deck)
        open(f"{d}/extra.data", "w").write(EXTRA)
        open(f"{d}/plane.stl", "w").write(PLANE)
        open(f"{d}/one.mol", "w").write(MOL)
        e1 = engine(deck, 1, lig)
        e2 = engine(deck, 2, lig) if np > 1 else None
        rc, eps, err, out = audit(f"{d}/in.deck")
        words = [l for l in err.splitlines() if not re.match(
            r"restitution deck: (types [0-9 ]+|type [0-9]+ on wall \S+)( \(stage [^)]*\))?: at the deck's time step", l)
            and not re.match(r"restitution deck: print \(line", l)]
        e2s = f" | np2 {fmt(e2)}" if e2 is not None else ""
        print(f"{n:02d} | {case[:70]:70s} | engine {fmt(e1)}{e2s} | audit rc{rc} {eps} | notes={len(words)}",
              flush=True)
        open(f"{d}/audit.err", "w").write(err)
        open(f"{d}/audit.out", "w").write(out)
        for w in words:
            print("      " + w[:260], flush=True)

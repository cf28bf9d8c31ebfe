"""Field round 27: the eps LAMMPS itself gives a sphere on any wall of a deck: the deck run to its end in a scratch copy,
its atoms deleted, its gravity fix (ID given, or - for none) removed, one sphere of the type asked for made at X Y Z
(where it just touches the wall, the caller computes it) moving at speed G along -N (N the wall's normal into the
domain, unit), run at dt DT (default 1e-8) until its centre is back past X Y Z along N (step > 10); eps = v.N / G.
No import from the project. usage: python wgprobe27.py DECKDIR T D RHO GRAVID X Y Z NX NY NZ [G] [DT]"""
import os, shutil, subprocess, sys, tempfile
d, t, dia, rho, grav, x, y, z, nx, ny, nz = sys.argv[1:12]
g = float(sys.argv[12]) if len(sys.argv) > 12 else 1.0
dt = sys.argv[13] if len(sys.argv) > 13 else "1e-8"
deck = open(os.path.join(d, "DECK")).read().strip()
top = tempfile.mkdtemp(prefix="field27-wgprobe."); tmp = os.path.join(top, "a", "b", "c")
shutil.copytree(d, tmp)
tail = "\n" + ("" if grav == "-" else f"unfix {grav}\n") + os.environ.get("PROBE_PRE", "").replace(";", "\n") + f"""
delete_atoms group all
create_atoms {t} single {x} {y} {z} units box
group f26a type {t}
set group f26a diameter {dia} density {rho}
""" + os.environ.get("PROBE_MID", "").replace(";", "\n") + f"""
velocity all set {-g * float(nx)} {-g * float(ny)} {-g * float(nz)} units box
variable f26p equal (xcm(f26a,x)-({x}))*({nx})+(xcm(f26a,y)-({y}))*({ny})+(xcm(f26a,z)-({z}))*({nz})
variable f26s equal (v_f26p>0)&&(step>10)
fix f26h all halt 1 v_f26s == 1 error continue
timestep {dt}
thermo 0
run {os.environ.get("PROBE_STEPS", "3000000")}
print "PROBE26 wall eps $((vcm(f26a,x)*({nx})+vcm(f26a,y)*({ny})+vcm(f26a,z)*({nz}))/{g}:%.6f) steps $(step)"
"""
target = os.environ.get("PROBE_FILE", deck)
txt = open(os.path.join(tmp, target), newline="", encoding="latin-1").read()
open(os.path.join(tmp, target), "w", newline="", encoding="latin-1").write(txt + tail)
p = subprocess.run(["lmp", "-in", deck, "-log", "none"], cwd=tmp, capture_output=True, text=True)
print(os.path.basename(d.rstrip("/")), "wall", t, *[l for l in p.stdout.splitlines() if l.startswith("PROBE26") or "ERROR" in l][:3])
shutil.rmtree(top)

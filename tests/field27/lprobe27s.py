"""Field round 27: the eps LIGGGHTS itself gives a head-on pair with the contact settings a deck leaves it holding: the
deck run to its end in a scratch copy (byte for byte), its atoms deleted, two spheres made touching far above the walls
at relative speed G along x, run at dt 1e-7 s in chunks of 10 steps until they part (at most 20000), eps = (vx2 - vx1)/G.
Needs `atom_modify map array` in the deck. No import from the project. usage: python lprobe27.py DECKDIR T1 T2 D1 RHO1 D2 RHO2 [G] [Z]"""
import os, shutil, subprocess, sys, tempfile
d, t1, t2, d1, r1, d2, r2 = sys.argv[1:8]
g = float(sys.argv[8]) if len(sys.argv) > 8 else 1.0
z = sys.argv[9] if len(sys.argv) > 9 else "0.1"
deck = open(os.path.join(d, "DECK")).read().strip()
top = tempfile.mkdtemp(prefix="field27-lprobe."); tmp = os.path.join(top, "a", "b", "c")
shutil.copytree(d, tmp)
m1 = float(r1) * float(d1) ** 3; m2 = float(r2) * float(d2) ** 3
v1, v2 = g * m2 / (m1 + m2), -g * m1 / (m1 + m2)
tail = f"""
delete_atoms group all
create_atoms {t1} single {-float(d1) / 2} 0 {z} units box
create_atoms {t2} single {float(d2) / 2} 0 {z} units box
group f24a1 id 1
group f24a2 id 2
set group f24a1 diameter {d1} density {r1}
set group f24a2 diameter {d2} density {r2}
velocity f24a1 set {v1} 0 0
velocity f24a2 set {v2} 0 0
timestep 1e-7
thermo 0
variable f26d equal x[2]-x[1]-{(float(d1) + float(d2)) / 2}
variable f26n loop 2000
label f26l
run 10
if "${{f26d}} > 0" then "jump SELF f26out"
next f26n
jump SELF f26l
label f26out
variable f24e equal (vx[2]-vx[1])/{g}
print "LPROBE26 eps ${{f24e}}"
"""
target = os.environ.get("PROBE_FILE", deck)  # where the deck ends: a file it jumps to
txt = open(os.path.join(tmp, target), newline="", encoding="latin-1").read()
open(os.path.join(tmp, target), "w", newline="", encoding="latin-1").write(txt + tail)
p = subprocess.run(["liggghts", "-in", deck, "-log", "none"], cwd=tmp, capture_output=True, text=True, errors="replace")
print(os.path.basename(d.rstrip("/")), t1, t2, *[l for l in p.stdout.splitlines() if l.startswith("LPROBE26") or "ERROR" in l][:3])
shutil.rmtree(top)

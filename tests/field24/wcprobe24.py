"""Field round 24: the eps LAMMPS itself gives a sphere on a curved wall (wall/gran zcylinder, wall/gran/region on a
cylinder or sphere) with the contact settings the deck leaves it holding: the deck run to its end in a scratch copy, its
atoms deleted, its gravity fix removed, one sphere of the type asked for made touching the wall at (X, Y, Z), moving
along x at speed G with sign S (+1 outward into a concave wall, -1 onto a convex one), run at dt 1e-8 s until it leaves;
eps = -vx_after / vx_before. No import from the project. usage: python wcprobe24.py DECKDIR T D RHO GRAVID X Y Z S [G]"""
import os, shutil, subprocess, sys, tempfile
d, t, dia, rho, grav, x, y, z, s = sys.argv[1:10]
g = float(sys.argv[10]) if len(sys.argv) > 10 else 1.0
deck = open(os.path.join(d, "DECK")).read().strip()
top = tempfile.mkdtemp(prefix="field24-wcprobe."); tmp = os.path.join(top, "a", "b", "c")
shutil.copytree(d, tmp)
v = float(s) * g
tail = f"""
unfix {grav}
delete_atoms group all
create_atoms {t} single {x} {y} {z} units box
group f24a type {t}
set group f24a diameter {dia} density {rho}
velocity all set {v} 0 0 units box
variable f24s equal ({float(s)}*(xcm(f24a,x)-{x})<0)&&(step>10)
fix f24h all halt 1 v_f24s == 1 error continue
timestep 1e-8
thermo 0
run 3000000
print "PROBE24 wall eps $(-vcm(f24a,x)/{v}:%.6f) steps $(step)"
"""
open(os.path.join(tmp, deck), "a").write(tail)
p = subprocess.run(["lmp", "-in", deck, "-log", "none"], cwd=tmp, capture_output=True, text=True)
print(os.path.basename(d.rstrip("/")), "wall", t, *[l for l in p.stdout.splitlines() if l.startswith("PROBE24") or "ERROR" in l])
shutil.rmtree(top)

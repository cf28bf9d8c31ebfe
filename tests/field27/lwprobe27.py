"""Field round 27: the eps LIGGGHTS itself gives a sphere on a deck's zplane-0 wall: the deck run to its end in a
scratch copy, its atoms deleted, its gravity fix (ID given) removed, one sphere of the type asked for made touching
z = 0 from above moving at -G, run at dt 1e-7 s for 20000 steps (it leaves long before), eps = vz / G.
Needs `atom_modify map array`. No import from the project. usage: python lwprobe27.py DECKDIR T D RHO GRAVID [G]"""
import os, shutil, subprocess, sys, tempfile
d, t, dia, rho, grav = sys.argv[1:6]
g = float(sys.argv[6]) if len(sys.argv) > 6 else 1.0
deck = open(os.path.join(d, "DECK")).read().strip()
top = tempfile.mkdtemp(prefix="field27-lwprobe."); tmp = os.path.join(top, "a", "b", "c")
shutil.copytree(d, tmp)
r = float(dia) / 2
tail = f"""
unfix {grav}
delete_atoms group all
create_atoms {t} single 0 0 {r} units box
group f26a id 1
set group f26a diameter {dia} density {rho}
velocity f26a set 0 0 {-g}
timestep 1e-7
thermo 0
run 20000
variable f26e equal vz[1]/{g}
print "LPROBE26 wall eps ${{f26e}}"
"""
txt = open(os.path.join(tmp, deck), newline="", encoding="latin-1").read()
open(os.path.join(tmp, deck), "w", newline="", encoding="latin-1").write(txt + tail)
p = subprocess.run(["liggghts", "-in", deck, "-log", "none"], cwd=tmp, capture_output=True, text=True, errors="replace")
print(os.path.basename(d.rstrip("/")), "wall", t, *[l for l in p.stdout.splitlines() if l.startswith("LPROBE26") or "ERROR" in l][:3])
shutil.rmtree(top)

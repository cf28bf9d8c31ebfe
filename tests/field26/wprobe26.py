"""Field round 26: the eps LAMMPS itself gives a sphere on a deck's zplane-0 floor with the contact settings the deck
leaves it holding: the deck is run to its end in a scratch copy, its atoms deleted, its gravity fix (ID given) removed,
one sphere of the type asked for made touching z = 0 from above at -g, run at dt = 1e-8 s until it leaves (z > r).
No import from the project. usage: python wprobe21.py DECKDIR T D RHO GRAVID [G]"""
import os, shutil, subprocess, sys, tempfile
d, t, dia, rho, grav = sys.argv[1:6]
g = float(sys.argv[6]) if len(sys.argv) > 6 else 1.0
deck = open(os.path.join(d, "DECK")).read().strip()
top = tempfile.mkdtemp(prefix="field26-wprobe."); tmp = os.path.join(top, "a", "b", "c")
shutil.copytree(d, tmp)
r = float(dia) / 2
tail = f"""
unfix {grav}
delete_atoms group all
create_atoms {t} single 0.02 0.02 {r} units box
group f24a type {t}
set group f24a diameter {dia} density {rho}
velocity all set 0 0 {-g}
variable f24s equal (xcm(f24a,z)>{r})&&(step>10)
fix f24h all halt 1 v_f24s == 1 error continue
timestep 1e-8
thermo 0
run 3000000
print "PROBE26 wall eps $(vcm(f24a,z)/{g}:%.6f) steps $(step)"
"""
open(os.path.join(tmp, deck), "a").write(tail)
p = subprocess.run(["lmp", "-in", deck, "-log", "none"], cwd=tmp, capture_output=True, text=True)
print(os.path.basename(d.rstrip("/")), "wall", t, *[l for l in p.stdout.splitlines() if l.startswith("PROBE26") or "ERROR" in l])
shutil.rmtree(top)

"""Field round 27: the eps LAMMPS gives a pair that APPROACHES from a gap at the deck's own time step and neighbour
settings (probe26 starts the spheres touching, which hides neighbour lists built late): the deck run to its end in a
scratch copy, its atoms deleted, two spheres of the types asked for made GAP apart (centre line along x, far above the
walls), approaching at relative speed G; run STEPS steps at the deck's dt; eps = relative speed after / G, with the gap
then (positive: they parted). No import from the project. usage: python aprobe27.py DECKDIR T1 T2 D1 RHO1 D2 RHO2 [G] [GAP] [STEPS] [Z]"""
import os, shutil, subprocess, sys, tempfile
d, t1, t2, d1, r1, d2, r2 = sys.argv[1:8]
g = float(sys.argv[8]) if len(sys.argv) > 8 else 1.0
gap = float(sys.argv[9]) if len(sys.argv) > 9 else 0.002
steps = sys.argv[10] if len(sys.argv) > 10 else "2000"
z = sys.argv[11] if len(sys.argv) > 11 else "0.05"
deck = open(os.path.join(d, "DECK")).read().strip()
top = tempfile.mkdtemp(prefix="field27-aprobe."); tmp = os.path.join(top, "a", "b", "c")
shutil.copytree(d, tmp)
x1 = 0.02 - float(d1) / 2 - gap / 2; x2 = 0.02 + float(d2) / 2 + gap / 2
tail = "\n" + os.environ.get("PROBE_PRE", "").replace(";", "\n") + f"""
delete_atoms group all
create_atoms {t1} single {x1} 0.02 {z} units box
create_atoms {t2} single {x2} 0.02 {z} units box
variable f26n equal count(all)
group f26a1 id $(v_f26n-1)
group f26a2 id $(v_f26n)
set group f26a1 diameter {d1} density {r1}
set group f26a2 diameter {d2} density {r2}
variable f26m1 equal mass(f26a1)
variable f26m2 equal mass(f26a2)
velocity all set 0 0 0 units box
velocity f26a1 set $({g}*v_f26m2/(v_f26m1+v_f26m2)) 0 0 units box
velocity f26a2 set $(-{g}*v_f26m1/(v_f26m1+v_f26m2)) 0 0 units box
thermo 0
run {steps}
print "APROBE26 eps $((vcm(f26a2,x)-vcm(f26a1,x))/{g}:%.6f) gap $(xcm(f26a2,x)-xcm(f26a1,x)-{(float(d1) + float(d2)) / 2}:%.6f)"
"""
txt = open(os.path.join(tmp, deck), newline="", encoding="latin-1").read()
open(os.path.join(tmp, deck), "w", newline="", encoding="latin-1").write(txt + tail)
p = subprocess.run(["lmp", "-in", deck, "-log", "none"], cwd=tmp, capture_output=True, text=True)
print(os.path.basename(d.rstrip("/")), t1, t2, *[l for l in p.stdout.splitlines() if l.startswith("APROBE26") or "ERROR" in l][:3])
shutil.rmtree(top)

"""Field round 28: the eps LAMMPS itself gives a head-on pair with the contact settings a deck leaves it holding: the deck
is run to its end in a scratch copy (nested so ../ stays inside), then its atoms are deleted, two spheres of the types
asked for are made far above any wall, touching, at relative speed g along x, and run at dt = 1e-8 s until they part (at most PROBE_STEPS, default 3e6 = 0.03 s: 20 times the longest contact here; a pair still together then has stuck)
(gravity moves both alike; fixes of the deck stay). No import from the project: the engine decides. Resolution: at
dt = 1e-8 s a 4 mm hooke contact (~5e-4 s) lasts ~5e4 steps, so the step error in eps is below 1e-4.
PROBE_MID (env): commands put after the two spheres are made (e.g. group t2 type 2, so a deck's fix on group t2 acts on them).
PROBE_FILE (env): the file the probe is appended to (default the deck; a file the deck jumps to and ends in).
PROBE_PRE (env): commands, ;-separated, put before the probe (e.g. unfix p for a fix pour that forbids a timestep change).
usage: python probe28.py DECKDIR T1 T2 D1 RHO1 D2 RHO2 [G] [Z] [XC] [DT]"""
import os, shutil, subprocess, sys, tempfile
d, t1, t2, d1, r1, d2, r2 = sys.argv[1:8]
g = float(sys.argv[8]) if len(sys.argv) > 8 else 1.0
z = sys.argv[9] if len(sys.argv) > 9 else "0.05"
xc = float(sys.argv[10]) if len(sys.argv) > 10 else 0.02
dt = sys.argv[11] if len(sys.argv) > 11 else "1e-8"
deck = open(os.path.join(d, "DECK")).read().strip()
top = tempfile.mkdtemp(prefix="field28-probe."); tmp = os.path.join(top, "a", "b", "c")
shutil.copytree(d, tmp)
x1, x2 = -float(d1) / 2, float(d2) / 2
tail = "\n" + os.environ.get("PROBE_PRE", "").replace(";", "\n") + f"""
delete_atoms group all
create_atoms {t1} single {xc + x1} {xc} {z} units box
create_atoms {t2} single {xc + x2} {xc} {z} units box
variable f24n equal count(all)
variable f24i1 equal $(v_f24n-1)
variable f24i2 equal $(v_f24n)
group f24a1 id ${{f24i1}}
group f24a2 id ${{f24i2}}
set group f24a1 diameter {d1} density {r1}
set group f24a2 diameter {d2} density {r2}
""" + os.environ.get("PROBE_MID", "").replace(";", "\n") + f"""
variable f24m1 equal mass(f24a1)
variable f24m2 equal mass(f24a2)
velocity all set 0 0 0 units box
velocity f24a1 set $({g}*v_f24m2/(v_f24m1+v_f24m2)) 0 0 units box
velocity f24a2 set $(-{g}*v_f24m1/(v_f24m1+v_f24m2)) 0 0 units box
variable f24d equal xcm(f24a2,x)-xcm(f24a1,x)-({float(d1) / 2 + float(d2) / 2})
variable f24s equal (v_f24d>0)&&(step>10)
fix f24h all halt 1 v_f24s == 1 error continue
timestep {dt}
thermo 0
run {os.environ.get("PROBE_STEPS", "3000000")}
print "PROBE26 eps $((vcm(f24a2,x)-vcm(f24a1,x))/{g}:%.6f) steps $(step) m $(v_f24m1) $(v_f24m2)"
"""
target = os.environ.get("PROBE_FILE", deck)  # where the deck ends: a file it jumps to
txt = open(os.path.join(tmp, target), newline="", encoding="latin-1").read()  # byte for byte: lone CRs, NULs, Latin-1 as the engine reads them
open(os.path.join(tmp, target), "w", newline="", encoding="latin-1").write(txt + tail)
if os.path.exists(os.path.join(d, "LIGGGHTS")):
    sys.exit("LAMMPS only")
p = subprocess.run(["lmp", "-in", deck, "-log", "none"], cwd=tmp, capture_output=True, text=True)
out = [l for l in p.stdout.splitlines() if l.startswith("PROBE26") or "ERROR" in l]
print(os.path.basename(d.rstrip("/")), t1, t2, *out)
shutil.rmtree(top)

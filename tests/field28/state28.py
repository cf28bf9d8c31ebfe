"""Field round 28: the atoms LAMMPS holds at a deck's end (id type radius mass density), the deck run to its end in a
scratch copy with a write_dump appended; the first atom of each type is printed. No import from the project. usage: python state28.py DECKDIR"""
import os, shutil, subprocess, sys, tempfile
d = sys.argv[1]
deck = open(os.path.join(d, "DECK")).read().strip()
top = tempfile.mkdtemp(prefix="field28-state."); tmp = os.path.join(top, "a", "b", "c")
shutil.copytree(d, tmp)
tail = "\nwrite_dump all custom f24state.txt id type radius mass z modify sort id\n"
open(os.path.join(tmp, os.environ.get("PROBE_FILE", deck)), "a").write(os.environ.get("PROBE_PRE", "").replace(";", "\n") + tail)  # PROBE_FILE: the file the deck ends in
p = subprocess.run(["lmp", "-in", deck, "-log", "none"], cwd=tmp, capture_output=True, text=True)
import math
rows = []
if os.path.exists(os.path.join(tmp, "f24state.txt")):
    for l in open(os.path.join(tmp, "f24state.txt")).read().split("ITEM: ATOMS")[1].splitlines()[1:]:
        i, ty, r, m, z = l.split(); rows.append(f"STATE24 id {i} type {ty} radius {r} mass {m} rho {float(m)/(4/3*math.pi*float(r)**3):.6g} z {z}")
seen = {}
for r in rows:
    seen.setdefault(r.split()[4], r)
print(os.path.basename(d.rstrip("/")), f"{len(rows)} atoms", *seen.values(), *[l for l in p.stdout.splitlines() if "ERROR" in l][:2], sep="\n  ")
shutil.rmtree(top)

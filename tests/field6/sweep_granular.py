"""Sweep LAMMPS pair granular normal x damping x limit_damping: audit vs own harness (unlike spheres)."""
import json, os, subprocess, sys, itertools, tempfile
sys.path.insert(0, os.path.dirname(__file__))
from harness import measure, lammps_once

HERE = os.path.dirname(os.path.abspath(__file__))
#: a folder of its own for the deck (the audit copies the deck's whole folder)
SCRATCH = tempfile.mkdtemp(prefix="field6-sweep-")
EXE = os.path.join(HERE, "..", "..", ".venv", "bin", "restitution")
normals = {"hooke": "hooke 2000 {d}", "hertz": "hertz 5e7 {d}", "hertz/material": "hertz/material 5e7 {d} 0.3"}
damps = {"velocity": {"hooke": 0.2, "hertz": 0.05, "hertz/material": 0.05},
         "mass_velocity": {"hooke": 1500, "hertz": 1500, "hertz/material": 1500},
         "viscoelastic": {"hooke": 2e6, "hertz": 2e6, "hertz/material": 2e6},
         "tsuji": {"hooke": 0.5, "hertz": 0.5, "hertz/material": 0.5},
         "coeff_restitution": {"hooke": 0.5, "hertz": 0.5, "hertz/material": 0.5}}
DECK = """units si
atom_style sphere
atom_modify map array
comm_modify vel yes
boundary f f f
region box block -0.05 0.05 -0.05 0.05 -0.05 0.05
create_box 2 box
create_atoms 1 single 0 0 0
create_atoms 2 single 0.01 0 0
set type 1 diameter 0.004 density 2500
set type 2 diameter 0.006 density 7800
pair_style granular
pair_coeff * * {law}
fix integrate all nve/sphere
timestep 1e-7
run 10
"""
g = float(sys.argv[1]) if len(sys.argv) > 1 else 1.0
only = sys.argv[2:] 
rows = []
for (nn, nf), dn, lim in itertools.product(normals.items(), damps, ("", " limit_damping")):
    tag = f"{nn}+{dn}{lim}"
    if only and not any(o in tag for o in only):
        continue
    law = nf.format(d=damps[dn][nn]) + f" damping {dn} tangential linear_nohistory 0 0" + lim
    path = os.path.join(SCRATCH, "in.sweep")
    open(path, "w").write(DECK.format(law=law))
    out = subprocess.run([EXE, "deck", path, "--g", str(g), "--json"], capture_output=True, text=True)
    if out.returncode != 0:
        print(tag, "AUDIT FAIL", out.returncode, out.stderr.strip()[-300:]); continue
    js = json.loads(out.stdout)
    pair = [p for p in js["pairs"] if p["types"] == [1, 2]][0]
    ours = pair["eps"][pair["speeds"].index(g)] if g in pair["speeds"] else pair["eps"][len(pair["speeds"]) // 2]
    try:
        r = measure(lammps_once, 1e-7, pair_lines=["pair_style granular", "pair_coeff * * " + law], t1=1, t2=2,
                    r1=0.002, r2=0.003, rho1=2500, rho2=7800, g=g)
        eng, wob = r["eps0"], abs(r["eps0"] - r["rich"])
    except Exception as e:
        eng, wob = float("nan"), str(e)[:80]
    flag = "" if ours is None else ("  <-- DIFF" if abs(ours - eng) > 1e-5 + 3 * (wob if isinstance(wob, float) else 0) else "")
    print(f"{tag:40s} ours {ours} engine {eng:.9f} wob {wob}{flag}", flush=True)

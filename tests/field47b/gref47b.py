"""Field round 47b: the floor decks whose gravity is not 9.81 down (G04-G10, U08), referee'd by hand: the deck run as
written with its lv1's vz and height printed to 9 digits after its last line; the speed it left the floor with is
sqrt(vz^2 + 2 GN h) (GN from the folder's GN file: the gravity's component into the floor, m/s^2), its impact speed 1 m/s.
usage: python gref47b.py DECKDIR ... (prints NAME GREF eps ... vz ... h ...)"""
import math, os, shutil, subprocess, sys, tempfile
for d in sys.argv[1:]:
    t = tempfile.mkdtemp(prefix="f47b-g.")
    shutil.copytree(d, t + "/d")
    open(t + "/d/in.deck", "a").write('\nprint "GR $(vcm(lv1,z):%.9f) $(xcm(lv1,z)-0.002:%.9f) $(step)"\n')
    p = subprocess.run(["lmp", "-in", "in.deck", "-log", "none"], cwd=t + "/d", capture_output=True, text=True)
    l = [x for x in p.stdout.splitlines() if x.startswith("GR ") or "ERROR" in x]
    gn = float(open(d + "/GN").read()) if os.path.exists(d + "/GN") else 9.81
    if l and l[0].startswith("GR "):
        vz, h, st = l[0].split()[1:]
        v2 = float(vz) ** 2 + 2 * gn * float(h)
        print(os.path.basename(d), "GREF eps", f"{math.sqrt(v2):.6f}" if v2 >= 0 else "nan", "vz", vz, "h", h, "GN", gn, "step", st)
    else:
        print(os.path.basename(d), l[:1])
    shutil.rmtree(t)

"""Field round 28: the eps LAMMPS (or LIGGGHTS) gives the deck's own live pair, the deck run AS WRITTEN: the deck makes two
spheres (groups lv1 on the left, lv2 on the right, along x, far above any wall) approaching at relative speed 1 m/s from a
gap timed so that they meet in the run named in the deck's LIVE file; after the deck's last line this script only prints
(vx(lv2) - vx(lv1)) / 1 and the gap then (positive: they parted). No import from the project: the engine decides.
Resolution: the decks use dt 1e-6 s, 360-900 steps per contact; controls (ctrl28.log) give the step error.
usage: python live28.py DECKDIR ..."""
import os, shutil, subprocess, sys, tempfile
for d in sys.argv[1:]:
    deck = open(os.path.join(d, "DECK")).read().strip()
    top = tempfile.mkdtemp(prefix="field28-live."); tmp = os.path.join(top, "a", "b", "c")
    shutil.copytree(d, tmp)
    lig = os.path.exists(os.path.join(d, "LIGGGHTS"))
    sep = float(open(os.path.join(d, "SEP")).read()) if os.path.exists(os.path.join(d, "SEP")) else 0.005
    wall = "WALL" in open(os.path.join(d, "LIVE")).read()
    if wall:  # the speed the sphere left the floor with, from its speed and height at the end (energy under gravity 9.81)
        tail = '\nprint "LIVE28 eps $(sqrt(vcm(lv1,z)^2+2*9.81*(xcm(lv1,z)-0.002)):%.6f) vz $(vcm(lv1,z):%.6f) h $(xcm(lv1,z)-0.002:%.6f) n $(count(all)) step $(step)"\n'
    elif lig:
        tail = f'\nvariable l28e equal vx[2]-vx[1]\nvariable l28g equal x[2]-x[1]-{sep}\nprint "LIVE28 eps ${{l28e}} gap ${{l28g}} n $(atoms)"\n'
    else:
        tail = f'\nprint "LIVE28 eps $(vcm(lv2,x)-vcm(lv1,x):%.6f) gap $(xcm(lv2,x)-xcm(lv1,x)-{sep}:%.6f) n $(count(all)) step $(step)"\n'
    target = os.environ.get("LIVE_FILE", deck)
    txt = open(os.path.join(tmp, target), newline="", encoding="latin-1").read()
    open(os.path.join(tmp, target), "w", newline="", encoding="latin-1").write(txt + tail)
    cmd = ["liggghts", "-in", deck, "-log", "none"] if lig else ["lmp", "-in", deck, "-log", "none"]
    p = subprocess.run(cmd, cwd=tmp, capture_output=True, text=True, errors="replace", timeout=900)
    out = [l for l in p.stdout.splitlines() if l.startswith("LIVE28") or "ERROR" in l][:3]
    print(os.path.basename(d.rstrip("/")), *out, flush=True)
    shutil.rmtree(top)

"""Field round 28: the deck's own pair in a public restitution variant (PUBLIVE: groups a b, axis), the deck run AS
WRITTEN in LAMMPS: prints (v_axis(b) - v_axis(a)) / (their approach speed at the start, 2 m/s in in.restitution).
No import from the project. usage: python publive28.py DECKDIR ..."""
import os, shutil, subprocess, sys, tempfile
for d in sys.argv[1:]:
    deck = open(os.path.join(d, "DECK")).read().strip()
    a, b, ax = open(os.path.join(d, "PUBLIVE")).read().split()
    top = tempfile.mkdtemp(prefix="field28-pub."); tmp = os.path.join(top, "a", "b", "c")
    shutil.copytree(d, tmp)
    with open(os.path.join(tmp, deck), "a") as f:
        f.write(f'\nprint "PUBLIVE eps $((vcm({b},{ax})-vcm({a},{ax}))/2:%.6f) types $(count({a})) step $(step)"\n')
    p = subprocess.run(["lmp", "-in", deck, "-log", "none"], cwd=tmp, capture_output=True, text=True, errors="replace", timeout=1800)
    out = [l for l in p.stdout.splitlines() if l.startswith("PUBLIVE") or "ERROR" in l][:3]
    print(os.path.basename(d.rstrip("/")), *out, flush=True)
    shutil.rmtree(top)

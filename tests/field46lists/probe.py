"""Probe (LAMMPS): a command X between runs mid-contact (or from the start, or in a run's every); LAMMPS' eps vs the
audit's words. A cases line is BETWEEN || START || HEAD || FIRSTRUN (" ;; " joins commands in one field; an empty
field is "||  ||"). The pair: types 1 and 2, radii 2 and 3 mm, head-on at a relative speed of 1 m/s, hooke kn 2000
damping 3000 mass_velocity: eps 0.4149 by the law, 0.4134 as LAMMPS measures it at dt 1e-6; they meet at step ~100
and a contact lasts ~586 steps. Prints LAMMPS' eps (relative velocity after the runs / 1 m/s), the audit's exit
status and eps for types 1 2 (the first such row, stage 1 where there are stages), and its notes.
usage: PROBE_OUT=DIR python probe.py CASES"""
import os, re, subprocess, sys, json, tempfile
BASE = """units si
atom_style sphere 1
atom_modify map array
boundary p p f
comm_modify vel yes
{head}
region box block 0 0.04 0 0.04 0 0.1 units box
create_box 2 box
pair_style granular
pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3
fix grav all gravity 9.81 vector 0 0 -1
fix integ all nve/sphere
timestep 1e-6
create_atoms 1 single 0.017950 0.02 0.05
create_atoms 2 single 0.023050 0.02 0.05
set atom 1 diameter 0.004 density 2500
set atom 2 diameter 0.006 density 2500
group lv1 id 1
group lv2 id 2
group far empty
velocity lv1 set 0.7714285714 0 0 units box
velocity lv2 set -0.2285714286 0 0 units box
{start}
run {first}
{between}
run 2000
variable vr equal vx[1]-vx[2]
print "LIVEVR ${{vr}}"
"""
def engine(deck):
    """LAMMPS' measured eps: the deck run by the lmp binary in a process and a folder of its own (a crash stays
    there; the files a deck writes and reads, by relative names, are that folder's)."""
    import shutil, tempfile
    d = tempfile.mkdtemp(prefix="l46lmp.")
    open(os.path.join(d, "in.deck"), "w").write(deck)
    helpers(d)
    try:
        p = subprocess.run(["lmp", "-in", "in.deck", "-log", "none", "-nocite"], cwd=d, capture_output=True, text=True,
                           timeout=300)
    except subprocess.TimeoutExpired:
        return "timeout"
    finally:
        shutil.rmtree(d)
    for l in p.stdout.splitlines():
        if l.startswith("LIVEVR "):
            return -float(l.split()[1])
    err = [l for l in (p.stdout + p.stderr).splitlines() if "ERROR" in l]
    return f"stops rc{p.returncode}: {(err or ['(no line)'])[0][:80]}"

EXTRA = """x

1 atoms
2 atom types

0 0.04 xlo xhi
0 0.04 ylo yhi
0 0.1 zlo zhi

Atoms # sphere

1 1 0.004 2500 0.0206 0.02 0.0545 0 0 0
"""
MOL = """x

1 atoms

Coords

1 0 0 0

Types

1 1
"""


def helpers(d):
    """The files some cases read: a data file of one more sphere (above the pair) and a one-atom molecule."""
    open(os.path.join(d, "extra.data"), "w").write(EXTRA)
    open(os.path.join(d, "one.mol"), "w").write(MOL)


def audit(path):
    p = subprocess.run(["restitution", "deck", path, "--g", "1"], capture_output=True, text=True)
    out = p.stdout.splitlines()
    eps = [k for k, l in enumerate(out) if l.startswith("types 1 2")]
    line = out[eps[0] + 1] if eps else ""
    return p.returncode, line.split("eps")[1].split()[0] if "eps" in line else "-", p.stderr

if __name__ == "__main__":
    cases = [l.rstrip("\n") for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
    for n, case in enumerate(cases):
        parts = dict(zip(["between", "start", "head", "first"], (case.split(" || ") + ["", "", "", ""])[:4]))
        parts = {k: v.strip().replace(" ;; ", "\n") for k, v in parts.items()}
        parts["first"] = parts["first"] or "300"
        deck = BASE.format(**parts)
        d = os.path.join(os.environ.get("PROBE_OUT") or tempfile.gettempdir(), f"{os.path.basename(sys.argv[1])[:-4]}-{n:02d}"); os.makedirs(d, exist_ok=True)
        open(f"{d}/in.deck", "w").write(deck)
        helpers(d)
        e = engine(deck)
        rc, eps, err = audit(f"{d}/in.deck")
        words = [l for l in err.splitlines() if not re.match(r"restitution deck: (types [0-9 ]+|type [0-9]+ on wall \S+)( \(stage [^)]*\))?: at the deck's time step", l) and not re.match(r"restitution deck: print \(line", l)]
        print(f"{n:02d} | {case[:60]:60s} | engine {e if isinstance(e,str) else f'{e:.6f}'} | audit rc{rc} {eps} | notes={len(words)}", flush=True)
        open(f"{d}/audit.err", "w").write(err)
        for w in words: print("      " + w[:230], flush=True)

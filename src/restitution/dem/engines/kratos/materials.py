"""What eps does a Kratos MaterialsDEM.json really give? Each material relation of spheres, and each
relation of a sphere material with a wall (FEM) material, audited as a head-on collision.

A relation names its discontinuum law (DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME) and its typed
COEFFICIENT_OF_RESTITUTION; the materials give YOUNG_MODULUS, POISSON_RATIO and, for spheres,
PARTICLE_DENSITY (restitution.dem.engines.kratos.contact maps both onto the model). Which materials
are walls: those the material_assignation_table gives to a RigidFacePart, spheres those it gives to
a SpheresPart, DEMInletPart or ClusterPart (without a table: a material with PARTICLE_DENSITY is a
sphere). The spheres' radii come from the model part beside the file (<problem_name>DEM.mdpa, its
RADIUS nodal data over the nodes of the part each material is assigned to), else from ``radius``
per material id; ProjectParametersDEM.json beside it gives the time step (MaxTimeStep), the
integration scheme and the element type. Under both mapped laws eps depends on the typed e alone:
the radius and the speed enter D1, D2, the contact time and whether the overlap reaches the
centres, not eps.

Refused in one line: a law not mapped (JKR, DMT, the stress-dependent and conical-damage laws, the
2D variants, any other), bonded (continuum) particles, a 2D analysis, a GlobalDamping other than 0,
a VirtualMassCoefficient other than 1, a relation naming a material not in the list, a sphere
without density or radius, a JSON file that is not a MaterialsDEM.json (another engine's, or
Kratos' ProjectParametersDEM.json).
"""

from __future__ import annotations

import json

from ....core.collision import StickError
from ....core.errors import InputFileError, ParameterError
from ...pair import Pair
from .contact import KRATOS_E_RANGE, KRATOS_LAWS, kratos_contact
from .design import kratos_design

__all__ = ["is_materials_file", "audit_materials", "MaterialsError"]

#: The model parts whose entities are spheres and walls in a DEM analysis (DEM_analysis_stage)
_SPHERE_PARTS = ("SpheresPart", "DEMInletPart", "ClusterPart")
_WALL_PARTS = ("RigidFacePart",)


class MaterialsError(InputFileError):
    """One line naming what in a Kratos materials file cannot be mapped or is missing.

    Parameters
    ----------
    where : str
        The field or place named.
    text
        What the file holds there.
    why : str
        What is wrong or allowed.

    Examples
    --------
    >>> str(MaterialsError("file", "JSON", "not a Kratos MaterialsDEM.json"))
    "file = 'JSON': not a Kratos MaterialsDEM.json"
    """


def _json(text: str):
    try:
        return json.loads(text)
    except ValueError:
        return None


def is_materials_file(text: str) -> bool:
    """Whether ``text`` is a JSON document (the dispatch of ``restitution deck``: a deck is never one);
    what it holds is :func:`audit_materials`' to check.

    Parameters
    ----------
    text : str
        The file's text.

    Returns
    -------
    bool

    Examples
    --------
    >>> is_materials_file('{"materials": []}'), is_materials_file("units si")
    (True, False)
    """
    return text.lstrip().startswith("{") and isinstance(_json(text), dict)


def _materials(doc: dict) -> dict:
    """{material_id: {"name", "variables"}}, refused where the file is not a MaterialsDEM.json."""
    if not isinstance(doc.get("materials"), list) or not isinstance(doc.get("material_relations"), list):
        if "solver_settings" in doc or "problem_name" in doc:
            raise MaterialsError("file", "ProjectParametersDEM.json", "this is Kratos' project parameters file: give "
                                 "the materials file it names (solver_settings.material_import_settings)")
        raise MaterialsError("file", "JSON", "not a Kratos MaterialsDEM.json (no \"materials\" and "
                                             "\"material_relations\" lists): no other engine's JSON file is read")
    out = {}
    for k, m in enumerate(doc["materials"]):
        if not isinstance(m, dict) or not isinstance(m.get("material_id"), int):
            raise MaterialsError(f"materials[{k}]", m, "needs an integer material_id")
        out[m["material_id"]] = {"name": m.get("material_name", str(m["material_id"])),
                                 "variables": m.get("Variables", {})}
    return out


def _kinds(doc: dict, materials: dict) -> dict:
    """{material_id: the set of what it is assigned to, of "sphere" and "wall"} (empty: no part)."""
    table = doc.get("material_assignation_table")
    by_name = {m["name"]: i for i, m in materials.items()}
    if not table:
        return {i: {"sphere" if "PARTICLE_DENSITY" in m["variables"] else "wall"} for i, m in materials.items()}
    kinds = {i: set() for i in materials}
    for entry in table:
        part, material = entry[0], entry[1]
        i = material if isinstance(material, int) else by_name.get(material)
        if i not in materials:
            raise MaterialsError("material_assignation_table", material, "names no material of the list")
        root = str(part).split(".")[0]
        if root in _WALL_PARTS:
            kinds[i].add("wall")
        elif root in _SPHERE_PARTS:
            kinds[i].add("sphere")
    return kinds


def mdpa_radii(text: str) -> dict:
    """{sub model part path ("" for the whole part): [the RADIUS of each of its nodes]} of an .mdpa."""
    radius, members, stack = {}, {"": set()}, []
    block = None
    for raw in text.splitlines():
        line = raw.split("//")[0].strip()
        if not line:
            continue
        words = line.split()
        if words[0] == "Begin":
            if words[1] == "SubModelPart":
                stack.append(words[2])
                members[".".join(stack)] = set()
            block = " ".join(words[1:3]) if words[1] != "SubModelPart" else None
            continue
        if words[0] == "End":
            if words[1] == "SubModelPart":
                stack.pop()
            block = None
            continue
        if block == "NodalData RADIUS" and len(words) >= 3:
            radius[int(words[0])] = float(words[2])
        elif block == "SubModelPartNodes" and stack:
            members[".".join(stack)].add(int(words[0]))
        elif block == "Nodes":
            members[""].add(int(words[0]))
    return {path: [radius[n] for n in nodes if n in radius] for path, nodes in members.items()}


def _radius(i: int, name: str, doc: dict, radius: dict, mdpa: dict | None) -> tuple[float, str]:
    """The radius of sphere material i and where it came from."""
    if i in radius:
        return radius[i], "--radius"
    if mdpa is not None:
        for part, material in doc.get("material_assignation_table") or []:
            if material in (name, i) and part.split(".")[0] == "SpheresPart":
                values = mdpa.get(".".join(part.split(".")[1:]), [])
                if values:
                    return min(values), f"model part {part} (smallest of {len(values)})"
    raise MaterialsError("radius", name, f"the spheres of material {i} have no radius the model part gives: "
                                         f"give --radius {i}=R")


def _relation_law(k: int, rel: dict) -> tuple[str, float]:
    v = rel.get("Variables", {})
    law = v.get("DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME")
    if law not in KRATOS_LAWS:
        raise MaterialsError(f"material_relations[{k}]", law, "not mapped: only DEM_D_Hertz_viscous_Coulomb and "
                             "DEM_D_Linear_viscous_Coulomb are (JKR, DMT, bonded and other laws are not)")
    e = v.get("COEFFICIENT_OF_RESTITUTION")
    if not isinstance(e, (int, float)) or not 0.0 < e <= 1.0:
        raise MaterialsError(f"material_relations[{k}]", e, "COEFFICIENT_OF_RESTITUTION must be a number in (0, 1]")
    if e > KRATOS_E_RANGE[1]:
        raise MaterialsError(f"material_relations[{k}]", e, f"COEFFICIENT_OF_RESTITUTION above {KRATOS_E_RANGE[1]}: "
                                                            "Kratos sets no damping at all (eps = 1)")
    return law, float(e)


def _modulus(i: int, m: dict) -> tuple[float, float]:
    v = m["variables"]
    if "YOUNG_MODULUS" not in v or "POISSON_RATIO" not in v:
        raise MaterialsError("materials", m["name"], f"material {i} needs YOUNG_MODULUS and POISSON_RATIO")
    return float(v["YOUNG_MODULUS"]), float(v["POISSON_RATIO"])


def _beside(read_file, name: str) -> str | None:
    if read_file is None:
        return None
    try:
        return read_file(name)
    except OSError:
        return None


def _parameters(text: str | None) -> dict:
    """Time step, scheme and element type of a ProjectParametersDEM.json (None where not given)."""
    doc = _json(text) if text else None
    if not isinstance(doc, dict):
        return {"dt": None, "scheme": None, "element": None}
    element = doc.get("ElementType")
    if isinstance(element, str) and "Cont" in element:
        raise MaterialsError("ElementType", element, "bonded (continuum) particles: their contacts follow the "
                                                     "continuum law, not mapped")
    if doc.get("Dimension", 3) != 3 or (isinstance(element, str) and "Cylinder" in element):
        raise MaterialsError("Dimension", doc.get("Dimension"), "a 2D analysis (cylinders): its contacts are not "
                                                                "the spheres' mapped here")
    if doc.get("GlobalDamping", 0.0) != 0.0:
        raise MaterialsError("GlobalDamping", doc["GlobalDamping"], "a damping force outside the contact law acts "
                             "on every particle: eps is not the contact's; audited with 0 only")
    if doc.get("VirtualMassCoefficient", 1.0) != 1.0:
        raise MaterialsError("VirtualMassCoefficient", doc["VirtualMassCoefficient"], "scales the masses the "
                             "contact sees: audited with 1 only")
    return {"dt": doc.get("MaxTimeStep"), "scheme": doc.get("TranslationalIntegrationScheme", "Symplectic_Euler"),
            "element": element}


def audit_materials(text: str, speeds, radius: dict | None = None, read_file=None) -> dict:
    """The eps a Kratos MaterialsDEM.json really gives, for every relation of spheres and of a
    sphere with a wall.

    Parameters
    ----------
    text : str
        The MaterialsDEM.json.
    speeds : sequence of float
        Impact speeds.
    radius : dict, optional
        {material_id: radius} of sphere materials (over the model part's).
    read_file : callable, optional
        name -> text of a file beside it (OSError where there is none): ProjectParametersDEM.json,
        and the spheres' model part <problem_name>DEM.mdpa it names.

    Returns
    -------
    dict
        {"code": "Kratos", "time_step", "scheme", "relations", "walls", "not_audited"}: a row per
        relation, as ``restitution deck`` prints a deck's ("materials", "ids", "model", "typed_e",
        "end", "speeds", "eps", "passes_through", "exact_line", "steps_per_contact", the contact's
        alpha, gamma, D1, D2, "radius_from"); ``not_audited``: relations between two walls or with a
        material assigned to no part, with the reason.

    Raises
    ------
    MaterialsError
        One line naming what cannot be mapped or is missing.

    Examples
    --------
    >>> doc = {"materials": [{"material_name": "glass", "material_id": 1, "Variables": {
    ...     "PARTICLE_DENSITY": 2500.0, "YOUNG_MODULUS": 5e7, "POISSON_RATIO": 0.3}}],
    ...     "material_relations": [{"material_names_list": ["glass", "glass"], "material_ids_list": [1, 1],
    ...     "Variables": {"COEFFICIENT_OF_RESTITUTION": 0.5,
    ...                   "DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME": "DEM_D_Linear_viscous_Coulomb"}}]}
    >>> row = audit_materials(json.dumps(doc), [1.0], radius={1: 1e-3})["relations"][0]
    >>> round(row["eps"][0], 6), row["end"]
    (0.499995, 'force')
    """
    speeds = [float(g) for g in speeds]
    if not speeds:
        raise ParameterError("g", speeds, "give at least one impact speed")
    doc = _json(text)
    if not isinstance(doc, dict):
        raise MaterialsError("file", "JSON", "not a JSON object: not a Kratos MaterialsDEM.json")
    materials = _materials(doc)
    kinds = _kinds(doc, materials)
    parameters = _beside(read_file, "ProjectParametersDEM.json")
    params = _parameters(parameters)
    problem = (_json(parameters) or {}).get("problem_name") if parameters else None
    mdpa = _beside(read_file, f"{problem}DEM.mdpa") if isinstance(problem, str) else None
    model_part = mdpa_radii(mdpa) if mdpa else None
    radius = radius or {}
    relations, walls, not_audited = [], [], []
    for k, rel in enumerate(doc["material_relations"]):
        ids = rel.get("material_ids_list")
        if not (isinstance(ids, list) and len(ids) == 2 and all(i in materials for i in ids)):
            raise MaterialsError(f"material_relations[{k}]", ids, "material_ids_list must name two materials of "
                                                                  "the list")
        uses = [(a, b) for a, b in ((0, 1), (1, 0)) if "sphere" in kinds[ids[a]] and "wall" in kinds[ids[b]]]
        uses = ([None] if "sphere" in kinds[ids[0]] and "sphere" in kinds[ids[1]] else []) + \
            list(dict.fromkeys(uses if ids[0] != ids[1] else uses[:1]))
        if not uses:
            not_audited.append({"relation": k, "materials": [materials[i]["name"] for i in ids],
                                "why": "no sphere of one material meets a sphere or a wall of the other"})
            continue
        law, e = _relation_law(k, rel)
        for use in uses:
            order = list(ids) if use is None else [ids[use[0]], ids[use[1]]]
            row = _row(k, order, use is not None, law, e, materials, doc, radius, model_part, params, speeds)
            (relations if use is None else walls).append(row)
    return {"code": "Kratos", "time_step": params["dt"], "scheme": params["scheme"], "relations": relations,
            "walls": walls, "not_audited": not_audited, "model_part": f"{problem}DEM.mdpa" if mdpa else None}


def _row(k, ids, wall, law, e, materials, doc, radius, model_part, params, speeds) -> dict:
    """The audit of relation k used by spheres of ids[0] against a sphere (or a wall) of ids[1]."""
    size = []
    for i in ids[:1] if wall else ids:
        v = materials[i]["variables"]
        if "PARTICLE_DENSITY" not in v:
            raise MaterialsError("materials", materials[i]["name"], f"sphere material {i} has no PARTICLE_DENSITY")
        size.append((*_radius(i, materials[i]["name"], doc, radius, model_part), float(v["PARTICLE_DENSITY"])))
    (E1, nu1), (E2, nu2) = _modulus(ids[0], materials[ids[0]]), _modulus(ids[1], materials[ids[1]])
    pair = Pair.wall(size[0][0], size[0][2]) if wall else Pair.spheres(size[0][0], size[1][0], size[0][2], size[1][2])
    stiffness = {"law": KRATOS_LAWS[law], "E": E1, "nu": nu1, "E2": E2, "nu2": nu2, "wall": wall}
    contact = kratos_contact(pair, e=e, **stiffness)
    limit = pair.R1 if wall else pair.R1 + pair.R2
    through = [contact.reaches(g, limit) for g in speeds]
    row = {"relation": k, "materials": [materials[i]["name"] for i in ids], "ids": ids, "model": f"Kratos {law}",
           "typed_e": e, "end": contact.end, "radius_from": [s[1] for s in size], "speeds": speeds,
           "passes_through": through, "eps": [None if t else _eps(contact, g) for g, t in zip(speeds, through)],
           "overlap_limit": limit,
           "steps_per_contact": None if not params["dt"] else [None if t else contact.contact_time(g) / params["dt"]
                                                               for g, t in zip(speeds, through)],
           **{key: v for key, v in contact.as_dict().items() if key != "end"}}
    row["exact_line"] = _exact_line(pair, e, stiffness, speeds, through)
    return row


def _eps(contact, g: float) -> float:
    try:
        return contact.eps(g)
    except StickError:       # not under the force rule; kept for a law mapped later
        return 0.0


def _exact_line(pair: Pair, e: float, stiffness: dict, speeds: list, through: list) -> str | None:
    """The relation's COEFFICIENT_OF_RESTITUTION entry that gives eps = e (the typed one), or None
    where the middle speed passes through or no e in Kratos' range gives it."""
    if through[len(speeds) // 2]:
        return None
    try:
        design = kratos_design(pair, eps=e, g=speeds[len(speeds) // 2], **stiffness)
    except ParameterError:
        return None
    # ten digits: Hertz's eps moves by about 1e-10, the linear law's bisection lands on the same zeta
    return f'"COEFFICIENT_OF_RESTITUTION": {design["COEFFICIENT_OF_RESTITUTION"]:.10g} (gives eps {design["eps"]:.8f})'

"""What a scene writes for Kratos: its candidate laws, each material pair's
COEFFICIENT_OF_RESTITUTION from a fitted model, and the scene's MaterialsDEM.json (materials, one
relation per material pair that meets, the assignation of sphere materials to SpheresPart and of
walls to RigidFacePart sub model parts)."""

from __future__ import annotations

import json
from fractions import Fraction

from ...model_choice import ContactModel, Fit
from .contact import KRATOS_LAWS, kratos_contact, kratos_typed_e

# Scene and SceneContact appear in annotations only, unimported (see the LIGGGHTS scene module).

__all__ = ["kratos_models", "scene_setting", "contact_lines", "input_lines", "LAW_OPTION"]

#: Both laws' damping is set from a typed e, so eps is constant in the speed
_MODELS = {"DEM_D_Hertz_viscous_Coulomb": (Fraction(3, 2), Fraction(1, 4)),
           "DEM_D_Linear_viscous_Coulomb": (Fraction(1), Fraction(0))}
#: The scene option that names the law
LAW_OPTION = {"description": "Kratos discontinuum law, or choose (the first that meets the tolerance)",
              "enum": ["choose", *_MODELS], "default": "choose"}


def kratos_models(law: str) -> list[ContactModel]:
    """The candidate laws (one, or both where ``law`` is "choose"), each with a constant e."""
    names = list(_MODELS) if law == "choose" else [law]
    return [ContactModel(name, KRATOS_LAWS[name], "COEFFICIENT_OF_RESTITUTION", *_MODELS[name]) for name in names]


def _stiffness(scene: Scene, c: SceneContact) -> dict:
    m1, m2 = c.materials
    p, q = scene.materials[m1], scene.materials[m2]
    return {"E": float(p["E"]), "nu": float(p["nu"]), "E2": float(q["E"]), "nu2": float(q["nu"]),
            "wall": c.b is None}


def scene_setting(scene: Scene, c: SceneContact, fit: Fit) -> dict:
    """The contact's setting for the fitted model: the COEFFICIENT_OF_RESTITUTION whose damping is
    the fit's (linear: the nearest Kratos' bisection can give), as the materials file prints it."""
    law = fit.model.normal
    stiffness = _stiffness(scene, c)
    damped = fit.damped(kratos_contact(c.pair, law=law, e=0.5, **stiffness))
    e = kratos_typed_e(damped)
    return {"law": law, "e": float(f"{e:.12g}"), **stiffness}


def _ids(scene: Scene) -> dict:
    """Kratos material ids: the scene's materials in file order, from 1."""
    return {m: k for k, m in enumerate(scene.materials, 1)}


def contact_lines(scene: Scene, c: SceneContact, setting: dict) -> list[str]:
    """The relation's entries that set this contact."""
    i, j = (_ids(scene)[m] for m in c.materials)
    law = {ours: theirs for theirs, ours in KRATOS_LAWS.items()}[setting["law"]]
    return [f'material_ids_list [{i}, {j}]: "DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME": "{law}", '
            f'"COEFFICIENT_OF_RESTITUTION": {setting["e"]:.12g}']


def input_lines(scene: Scene, rows: list) -> list[str]:
    """The scene's MaterialsDEM.json, one relation per material pair answered (frictionless: the
    scene is about head-on contacts; set your own friction)."""
    ids = _ids(scene)
    used = {t.material for t in scene.types}
    materials = [{"material_name": m, "material_id": ids[m],
                  "Variables": {**({"PARTICLE_DENSITY": float(v["density"])} if m in used else {}),
                                "YOUNG_MODULUS": float(v["E"]), "POISSON_RATIO": float(v["nu"])}}
                 for m, v in scene.materials.items() if m in used or m in scene.walls]
    relations = {}
    for row in rows:
        if row["chosen"] is None:
            continue
        a, b = row["materials"]
        law = {ours: theirs for theirs, ours in KRATOS_LAWS.items()}[row["setting"]["law"]]
        relations.setdefault(frozenset((a, b)), {
            "material_names_list": [a, b], "material_ids_list": [ids[a], ids[b]],
            "Variables": {"DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME": law,
                          "COEFFICIENT_OF_RESTITUTION": row["setting"]["e"], "STATIC_FRICTION": 0.0,
                          "DYNAMIC_FRICTION": 0.0, "FRICTION_DECAY": 500.0, "ROLLING_FRICTION": 0.0,
                          "ROLLING_FRICTION_WITH_WALLS": 0.0}})
    table = [[f"SpheresPart.{m}", m] for m in dict.fromkeys(t.material for t in scene.types)] + \
        [[f"RigidFacePart.{w}", w] for w in scene.walls]
    doc = {"materials": materials, "material_relations": list(relations.values()), "material_assignation_table": table}
    return json.dumps(doc, indent=4).splitlines()

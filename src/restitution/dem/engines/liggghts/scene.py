"""What a scene writes for LIGGGHTS ``model hertz``: its candidate model, each contact's
coefficientRestitution from a fitted model (fix property/global per atom type, walls with atom
types of their own), and the scene's input lines."""

from __future__ import annotations

from fractions import Fraction

from ....core.errors import ParameterError
from ...model_choice import ContactModel, Fit
from .contact import LIGGGHTS_E, LIGGGHTS_MODULUS, liggghts_accepts_e, liggghts_contact, liggghts_e

# Scene (restitution.dem.scene.file) and SceneContact (restitution.dem.scene.contacts) appear in
# annotations only, unimported: scene.file checks a scene against this registry, so importing them
# here would tie the two into a loop.

__all__ = ["liggghts_models", "wall_types", "scene_setting", "contact_lines", "input_lines"]


def liggghts_models(model: str) -> list[ContactModel]:
    """LIGGGHTS 3.8 model hertz sets its damping from a coefficientRestitution: one constant-e model."""
    return [ContactModel("hertz (coefficientRestitution)", model, "coefficientRestitution", Fraction(3, 2),
                         Fraction(1, 4))]


def wall_types(scene: Scene) -> dict:
    """LIGGGHTS gives a wall a material through an atom type of its own: numbered after the particles'."""
    return {w: len(scene.types) + 1 + k for k, w in enumerate(scene.walls)}


def _materials(scene: Scene, c: SceneContact) -> dict:
    m1, m2 = c.materials
    p, q = scene.materials[m1], scene.materials[m2]
    same = m1 == m2
    return {"E": float(p["E"]), "nu": float(p["nu"]), "E2": None if same else float(q["E"]),
            "nu2": None if same else float(q["nu"])}


def scene_setting(scene: Scene, c: SceneContact, fit: Fit) -> dict:
    """The model's setting for this contact: D2 from the fitted C, as the coefficientRestitution
    rounded as the input line prints it."""
    mats = _materials(scene, c)
    limit = scene.options["limitForce"]
    base = liggghts_contact(c.pair, e=0.5, limit_force=limit, model=fit.model.normal, **mats)
    e = float(f"{liggghts_e(fit.damped(base)):.12g}")
    if not liggghts_accepts_e(e):
        # LIGGGHTS stops on such a matrix before the first step (found running these lines)
        raise ParameterError("coefficientRestitution", e, f"LIGGGHTS requires {LIGGGHTS_E[0]} < e <= "
                                                          f"{LIGGGHTS_E[1]}")
    return {"model": fit.model.normal, **mats, "e": e, "limit_force": limit}


def contact_lines(scene: Scene, c: SceneContact, setting: dict) -> list[str]:
    """The contact's entry of the coefficientRestitution matrix."""
    j = c.b.number if c.b is not None else wall_types(scene)[c.wall]
    return [f"coefficientRestitution {c.a.number} {j} {setting['e']:.12g}"]


def input_lines(scene: Scene, rows: list) -> list[str]:
    """fix property/global lines for every atom type (walls' after the particles'), the
    coefficientRestitution matrix from the contacts (entries between two walls never act: 0.5)."""
    walls = wall_types(scene)
    mats = [t.material for t in scene.types] + list(walls)
    n = len(mats)
    e = [[0.5] * n for _ in range(n)]
    for row in rows:
        if row["chosen"] is None:
            continue
        i, j = row["types"]
        e[i - 1][j - 1] = e[j - 1][i - 1] = row["setting"]["e"]
    answered = {(min(r["types"]), max(r["types"])) for r in rows if r["chosen"] is not None}
    left = [f"{i}-{j}" for i in range(1, n + 1) for j in range(i, n + 1) if (i, j) not in answered]
    prop = lambda key: " ".join(f"{float(scene.materials[m][key]):.12g}" for m in mats)   # noqa: E731
    note = [f"# coefficientRestitution left at 0.5 (walls only, or no model within the tolerance): {', '.join(left)}"]
    # LIGGGHTS refuses youngsModulus outside [5e6, 1e9] in SI units unless told (found running these lines)
    moduli = [float(scene.materials[m]["E"]) for m in mats]
    told = (["soft_particles yes"] if min(moduli) < LIGGGHTS_MODULUS["si"][0] else []) + \
        (["hard_particles yes"] if max(moduli) > LIGGGHTS_MODULUS["si"][1] else [])
    return (note if left else []) + told + [f"fix m1 all property/global youngsModulus peratomtype {prop('E')}",
            f"fix m2 all property/global poissonsRatio peratomtype {prop('nu')}",
            f"fix m3 all property/global coefficientRestitution peratomtypepair {n} "
            + " ".join(f"{x:.12g}" for r in e for x in r),
            "# the tangential model reads a friction matrix: zero here (the scene is about head-on contacts); "
            "set your own",
            f"fix m4 all property/global coefficientFriction peratomtypepair {n} " + " ".join(["0"] * n * n),
            f"pair_style gran model {scene.options['model']} tangential no_history limitForce "
            + ("on" if scene.options["limitForce"] else "off"),
            "pair_coeff * *"]

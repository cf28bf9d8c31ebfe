"""What a scene writes for LAMMPS ``pair_style granular``: its candidate models, each contact's
setting from a fitted model (a pair_coeff per type pair, a fix wall/gran per type and wall), and the
scene's input lines."""

from __future__ import annotations

import math
from fractions import Fraction

from ...model_choice import ContactModel, Fit
from .contact import base_eta_n0, lammps_contact, lammps_eta_n0, lammps_pair_coeff

# Scene (restitution.dem.scene.file) and SceneContact (restitution.dem.scene.contacts) appear in
# annotations only, unimported: scene.file checks a scene against this registry, so importing them
# here would tie the two into a loop.

__all__ = ["lammps_models", "scene_setting", "contact_lines", "input_lines"]


def lammps_models(normal: str, damping: str) -> list[ContactModel]:
    """The candidate models for LAMMPS pair_style granular with this normal model; ``damping`` =
    "choose" for all, cheapest first, else that one. A linear spring (hooke) gives a constant eps
    with every damping (gamma = 0, alpha = 1): one model, the classical linear spring-dashpot. With a
    Hertz normal model: coeff_restitution (gamma = (alpha-1)/2, constant e), then viscoelastic (gamma
    = 1/2, Kuwabara-Kono) and velocity (gamma = 0), both speed-dependent; mass_velocity has velocity's
    exponents and reaches the same eps(v) for each pair, so "choose" does not try it again.
    tsuji is the same law as coeff_restitution with another e; "choose" writes coeff_restitution,
    whose e is the eps of the overlap rule, whose range of damping is wider (B(e) up to sqrt(5)
    against tsuji's A(0) = 1.27), and which LAMMPS' development source applies as 22 Jul 2025
    does, where tsuji's damping changed by sqrt(2) (contact.TSUJI_VERSION_NOTE)."""
    h = Fraction(3, 2)
    if normal == "hooke":
        every = [ContactModel("linear spring-dashpot", "hooke", "velocity", Fraction(1), Fraction(0))]
        fixed = {d: ContactModel(f"hooke + {d}", "hooke", d, Fraction(1), Fraction(0))
                 for d in ("tsuji", "coeff_restitution", "viscoelastic", "velocity", "mass_velocity")}
        fixed["viscoelastic"] = ContactModel("hooke + viscoelastic", "hooke", "viscoelastic", Fraction(1),
                                             Fraction(1, 2))
    else:
        every = [ContactModel("hertz + coeff_restitution", normal, "coeff_restitution", h, Fraction(1, 4)),
                 ContactModel("hertz + viscoelastic", normal, "viscoelastic", h, Fraction(1, 2)),
                 ContactModel("hertz + velocity", normal, "velocity", h, Fraction(0))]
        fixed = {m.damping: m for m in every}
        fixed["mass_velocity"] = ContactModel("hertz + mass_velocity", normal, "mass_velocity", h, Fraction(0))
        fixed["tsuji"] = ContactModel("hertz + tsuji", normal, "tsuji", h, Fraction(1, 4))
    return every if damping == "choose" else [fixed[damping]]


def _stiffness(scene: Scene, m1: str, m2: str) -> dict:
    """The normal model's arguments for a contact of materials m1 and m2, as one pair_coeff I J
    line states them: k_n the geometric mean (LAMMPS' own mixing of k_n); for hertz/material the
    E that gives the pair's E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) with the mean nu, since the
    engine reads E and nu of one line as E* = E / (2 (1 - nu^2))."""
    normal = scene.options["normal"]
    p, q = scene.materials[m1], scene.materials[m2]
    if normal != "hertz/material":
        return {"normal": normal, "k_n": p["k_n"] if m1 == m2 else math.sqrt(p["k_n"] * q["k_n"])}
    if m1 == m2:
        return {"normal": normal, "E": float(p["E"]), "nu": float(p["nu"])}
    e_star = 1.0 / ((1.0 - p["nu"] ** 2) / p["E"] + (1.0 - q["nu"] ** 2) / q["E"])
    nu = 0.5 * (p["nu"] + q["nu"])
    return {"normal": normal, "E": 2.0 * (1.0 - nu ** 2) * e_star, "nu": nu}


def scene_setting(scene: Scene, c: SceneContact, fit: Fit) -> dict:
    """The model's setting for this contact: D2 from the fitted C, as LAMMPS' eta_n0 (or the e of
    tsuji or coeff_restitution) rounded as the input line prints it."""
    model = fit.model
    stiff = _stiffness(scene, *c.materials)
    base = lammps_contact(c.pair, damping=model.damping, eta_n0=base_eta_n0(model.damping),
                          limit_damping=scene.options["limit_damping"], **stiff)
    eta = lammps_eta_n0(c.pair, model.damping, fit.damped(base))
    return {**stiff, "damping": model.damping, "eta_n0": float(f"{eta:.12g}"),
            "limit_damping": scene.options["limit_damping"]}


def contact_lines(c: SceneContact, setting: dict) -> list[str]:
    """A type pair's pair_coeff line, or a type's group and fix wall/gran lines on a wall."""
    line = lammps_pair_coeff(**setting)
    if c.b is not None:
        return [line.replace("pair_coeff * *", f"pair_coeff {c.a.number} {c.b.number}", 1)]
    model = line.removeprefix("pair_coeff * * ")
    tag = f"{c.wall}_{c.a.number}"
    return [f"group type{c.a.number} type {c.a.number}",
            f"fix wall_{tag} type{c.a.number} wall/gran granular {model} zplane 0.0 NULL"]


def input_lines(rows: list) -> list[str]:
    """The scene's lines: pair_style granular, the pairs' lines, then the walls'."""
    lines = ["pair_style granular"] + [ln for row in rows if not row["b"].startswith("wall:")
                                       for ln in row["input_lines"]]
    walls = [ln for row in rows if row["b"].startswith("wall:") for ln in row["input_lines"]]
    if walls:
        # LAMMPS groups are static and fix wall/gran refuses dynamic ones: a group defined
        # before the atoms exist holds none, and its wall lets them through (measured)
        lines += ["# the groups hold the atoms present when they are defined: put these lines after "
                  "create_atoms/read_data,", "# or give a fix pour of type N the group typeN"]
    return lines + walls

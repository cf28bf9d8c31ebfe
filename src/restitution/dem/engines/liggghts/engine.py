"""LIGGGHTS 3.8 ``pair_style gran`` as one Engine (restitution.dem.engine)."""

from __future__ import annotations

from ....core.errors import ParameterError
from ...engine import Engine
from . import scene
from .contact import LIGGGHTS_NU, liggghts_contact, liggghts_e
from .design import TYPED_E, liggghts_design

__all__ = ["LIGGGHTS", "LIGGGHTS_VERSION"]

#: The release the typed-e rows are confirmed in (tests/library/test_dem_typed_e.py)
LIGGGHTS_VERSION = "LIGGGHTS 3.8.0"


class LiggghtsEngine(Engine):
    """LIGGGHTS ``model hertz`` / ``hooke``: settings are liggghts_contact's keywords."""

    name = "liggghts"
    label = "LIGGGHTS"
    sample_setting = ({"model": "hertz", "E": 1e7, "nu": 0.3, "e": 0.6}, {"model": "hertz", "E": 1e7, "nu": 0.3})
    typed_e, version = TYPED_E, LIGGGHTS_VERSION
    typed_e_steps = 8000
    install_hint = "as root, apt-get install liggghts (make test does it)"
    runner_module = "restitution.dem.engines.liggghts.run"
    deck_module = "restitution.dem.engines.liggghts.deck"
    scene_option_schema = {
        "model": {"description": "LIGGGHTS pair_style gran model", "enum": ["hertz"], "default": "hertz"},
        "limitForce": {"description": "LIGGGHTS limitForce (on - contact ends where the normal force vanishes)",
                       "type": "boolean", "default": False},
    }

    def contact(self, pair, **setting):
        return liggghts_contact(pair, **setting)

    def setting(self, pair, contact, **given) -> dict:
        return {**given, "e": liggghts_e(contact)}

    def design(self, pair, **target) -> dict:
        return liggghts_design(pair, **target)

    def typed_e_case(self, row, e, pair, material) -> tuple:
        from .run import liggghts_pair_style
        model = {"model": "hertz"} if "hertz" in row else {"model": "hooke", "characteristic_velocity": 0.5}
        setting = {"e": e, "limit_force": row.endswith("limitForce on"), **material, **model}
        return liggghts_contact(pair, **setting), liggghts_pair_style(**setting)

    def end_rule(self, options: dict) -> str:
        return "force" if options["limitForce"] else "overlap"

    def material_keys(self, options: dict) -> tuple:
        return ("E", "nu"), f"LIGGGHTS model {options['model']}"

    def check_material(self, name: str, material: dict) -> None:
        if material["nu"] < LIGGGHTS_NU[0]:
            # the schema's range is the physical one; LIGGGHTS stops below its own (checked with it)
            raise ParameterError(f"materials.{name}.nu", material["nu"],
                                 f"LIGGGHTS requires {LIGGGHTS_NU[0]:g} <= nu <= {LIGGGHTS_NU[1]:g}")

    def models(self, options: dict) -> list:
        return scene.liggghts_models(options["model"])

    def scene_setting(self, scene_, contact, fit) -> dict:
        return scene.scene_setting(scene_, contact, fit)

    def wall_types(self, scene_) -> dict:
        return scene.wall_types(scene_)

    def contact_lines(self, scene_, contact, setting: dict) -> list:
        return scene.contact_lines(scene_, contact, setting)

    def input_lines(self, scene_, rows: list) -> list:
        return scene.input_lines(scene_, rows)


LIGGGHTS = LiggghtsEngine()

"""Kratos DEMApplication as one Engine (restitution.dem.engine): contact laws, designer, runner,
material-file audit and scenes (``code: kratos``)."""

from __future__ import annotations

from ...engine import Engine
from . import scene
from .contact import kratos_contact, kratos_e
from .design import TYPED_E, kratos_design

__all__ = ["KRATOS", "KRATOS_VERSION"]

#: The release the typed-e rows are confirmed in (tests/library/test_dem_typed_e.py)
KRATOS_VERSION = "Kratos DEMApplication 10.4.4"


class KratosEngine(Engine):
    """Kratos' DEM_D_Hertz_viscous_Coulomb and DEM_D_Linear_viscous_Coulomb: a setting is
    kratos_contact's keywords (law, e, E, nu, E2, nu2, wall)."""

    name = "kratos"
    label = "Kratos"
    sample_setting = ({"law": "hertz", "e": 0.6, "E": 1e7, "nu": 0.3}, {"law": "hertz", "E": 1e7, "nu": 0.3})
    typed_e, version = TYPED_E, KRATOS_VERSION
    typed_e_steps = 500
    install_hint = "pip install -e '.[kratos]' (make test does it)"
    runner_module = "restitution.dem.engines.kratos.run"
    materials_module = "restitution.dem.engines.kratos.materials"
    scene_option_schema = {"law": scene.LAW_OPTION}
    scene_input_file = "MaterialsDEM.json"

    def contact(self, pair, **setting):
        return kratos_contact(pair, **setting)

    def setting(self, pair, contact, **given) -> dict:
        """The typed e (COEFFICIENT_OF_RESTITUTION) that gives ``contact``'s damping, with ``given``
        (law and materials) for the rest."""
        return {**given, "e": kratos_e(contact)["COEFFICIENT_OF_RESTITUTION"]}

    def design(self, pair, **target) -> dict:
        return kratos_design(pair, **target)

    def typed_e_case(self, row, e, pair, material) -> tuple:
        law = row.split()[1]
        return kratos_contact(pair, law=law, e=e, **material), {"law": law, "e": e, **material}

    def end_rule(self, options: dict) -> str:
        return "force"           # both laws clip a negative total normal force

    def material_keys(self, options: dict) -> tuple:
        return ("E", "nu"), "Kratos' viscous Coulomb laws"

    def models(self, options: dict) -> list:
        return scene.kratos_models(options["law"])

    def scene_setting(self, scene_, contact, fit) -> dict:
        return scene.scene_setting(scene_, contact, fit)

    def contact_lines(self, scene_, contact, setting: dict) -> list:
        return scene.contact_lines(scene_, contact, setting)

    def input_lines(self, scene_, rows: list) -> list:
        return scene.input_lines(scene_, rows)


KRATOS = KratosEngine()

"""Yade as one Engine (restitution.dem.engine); scenes do not name it."""

from __future__ import annotations

from ....core.errors import one_of
from ...engine import Engine
from .contact import yade_mindlin_contact, yade_mindlin_en, yade_viscel_contact, yade_viscel_setting
from .design import TYPED_E, yade_design

__all__ = ["YADE", "YADE_VERSION"]

#: The release the typed-e rows are confirmed in (tests/library/test_dem_typed_e.py)
YADE_VERSION = "Yade 2023.02a"


class YadeEngine(Engine):
    """Yade's ViscElMat (law "viscel") and Hertz-Mindlin (law "mindlin"): a setting is ``law`` and
    the keywords of yade_viscel_contact or yade_mindlin_contact."""

    name = "yade"
    label = "Yade"
    sample_setting = ({"law": "viscel", "tc": 1e-4, "en": 0.6}, {"law": "viscel"})
    typed_e, version = TYPED_E, YADE_VERSION
    typed_e_steps = 2000
    install_hint = "as root, apt-get install yade (make test does it)"
    runner_module = "restitution.dem.engines.yade.run"

    def contact(self, pair, *, law: str, **setting):
        law = one_of("law", law, ("viscel", "mindlin"))
        return (yade_viscel_contact if law == "viscel" else yade_mindlin_contact)(pair, **setting)

    def setting(self, pair, contact, *, law: str, given: str = "tc") -> dict:
        """ViscElMat's {"tc", "en"} or {"kn", "cn"} (``given``), or Hertz-Mindlin's {"betan", "en"}."""
        law = one_of("law", law, ("viscel", "mindlin"))
        return yade_viscel_setting(pair, contact, given=given) if law == "viscel" else yade_mindlin_en(contact)

    def design(self, pair, **target) -> dict:
        return yade_design(pair, **target)

    def typed_e_case(self, row, e, pair, material) -> tuple:
        from .run import mindlin_material, viscel_material
        if "ViscElMat" in row:
            return yade_viscel_contact(pair, tc=1e-4, en=e), viscel_material(pair, tc=1e-4, en=e)
        return yade_mindlin_contact(pair, en=e, **material), mindlin_material(pair, en=e, **material)


YADE = YadeEngine()

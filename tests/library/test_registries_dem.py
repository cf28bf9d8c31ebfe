"""Adding a DEM engine is one module and one registry entry (issue 44): a stub engine, one
module-like object put into restitution.dem.engines.ENGINES, is what a scene file may name, what
answers the scene (its models, settings and input lines), what the typed-e table lists and what the
``restitution scene`` command says beside its answer. Without the entry the same scene is refused:
nothing reaches the engine except through the registry."""

from __future__ import annotations

import io
import json
import math
import types
from contextlib import redirect_stderr
from fractions import Fraction
from pathlib import Path

import pytest
import yaml

from restitution.cli import main
from restitution.core.errors import ParameterError
from restitution.dem.contact import Contact
from restitution.dem.engine import Engine
from restitution.dem.engines import ENGINES, scene_engines
from restitution.dem.model_choice import ContactModel
from restitution.dem.pair import Pair
from restitution.dem.scene import answer_scene
from restitution.dem.scene.file import SCHEMA_PATH, scene_from_dict, scene_schema
from restitution.dem.engines.typed_e_table import typed_e_table

STUB_NOTE = "the stub engine's note"


def _stub_module() -> types.ModuleType:
    """The whole engine, as its own module would hold it: a linear spring-dashpot whose setting is a
    stiffness k and a dashpot c (per unit mass: D1 = k / m, D2 = c / m)."""

    class StubEngine(Engine):
        name = "stub"
        label = "Stub"
        typed_e = {"Stub linear, typed e as D2": lambda e: Contact("1", "0", 1.0, 1.0 - e, "force")}
        version = "Stub 1.0"
        # an option no shipped engine has: the scene schema takes it from here
        scene_option_schema = {"stub_limit": {"description": "the stub's contact ends where its force vanishes",
                                              "type": "boolean", "default": True}}

        def contact(self, pair, *, k, c, limit):
            return Contact("1", "0", k / pair.m, c / pair.m, "force" if limit else "overlap")

        def setting(self, pair, contact, **given):
            return {**given, "c": contact.D2 * pair.m}

        def end_rule(self, options):
            return "force" if options["stub_limit"] else "overlap"

        def material_keys(self, options):
            return ("k_n",), "the stub engine"

        def models(self, options):
            return [ContactModel("stub spring-dashpot", "linear", "dashpot", Fraction(1), Fraction(0))]

        def scene_setting(self, scene, contact, fit):
            k = float(scene.materials[contact.materials[0]]["k_n"])
            limit = scene.options["stub_limit"]
            base = self.contact(contact.pair, k=k, c=1.0, limit=limit)
            return self.setting(contact.pair, fit.damped(base), k=k, limit=limit)

        def contact_lines(self, scene, contact, setting):
            other = contact.b.number if contact.b is not None else contact.wall
            return [f"stub_coeff {contact.a.number} {other} {setting['k']:.6g} {setting['c']:.12g}"]

        def input_lines(self, scene, rows):
            return ["stub_style linear"] + [ln for row in rows for ln in row["input_lines"]]

        def notes(self, settings):
            return [STUB_NOTE] if settings else []

    module = types.ModuleType("stub_engine")
    module.ENGINE = StubEngine()
    return module


def _scene() -> dict:
    return {"name": "stub-scene", "code": "stub", "options": {"stub_limit": False}, "tolerance": 0.01,
            "speeds": [0.1, 1.0], "check_points": 20, "report_points": 3,
            "materials": {"steel": {"k_n": 1.0e5, "density": 7800.0}},
            "species": [{"name": "s", "material": "steel", "radius": 1.0e-3}],
            "targets": [{"pair": ["steel", "steel"], "e": 0.8}]}


@pytest.fixture
def stub(monkeypatch):
    module = _stub_module()
    monkeypatch.setitem(ENGINES, module.ENGINE.name, module.ENGINE)
    return module.ENGINE


def test_without_its_registry_entry_a_scene_cannot_name_the_engine():
    with pytest.raises(ParameterError, match="code"):
        scene_from_dict(_scene())


def test_the_scene_is_answered_by_the_registered_engine(stub):
    res = answer_scene(scene_from_dict(_scene()))
    (row,) = res["contacts"]
    assert res["code"] == "stub" and row["chosen"] == "stub spring-dashpot"
    assert row["end"] == "overlap"       # the engine's end rule, from the scene's options
    assert res["input_lines"][0] == "stub_style linear" and res["input_lines"][1].startswith("stub_coeff 1 1 100000 ")
    # the printed dashpot gives the target back through the engine's own contact law
    assert max(abs(e - 0.8) for e in row["eps"]) < 1e-8
    c = float(res["input_lines"][1].split()[-1])
    pair = Pair.spheres(1.0e-3, 1.0e-3, 7800.0)
    assert math.isclose(stub.contact(pair, k=1e5, c=c, limit=False).eps(1.0), 0.8, rel_tol=1e-8)


def test_the_scene_command_prints_the_engines_lines_and_notes(stub, tmp_path):
    path = tmp_path / "stub.yaml"
    path.write_text(yaml.safe_dump(_scene()))
    out, err = io.StringIO(), io.StringIO()
    with redirect_stderr(err):
        status = main(["scene", str(path), "--json"], out=out)
    assert status == 0, err.getvalue()
    assert json.loads(out.getvalue())["input_lines"][0] == "stub_style linear"
    assert f"restitution scene: note: {STUB_NOTE}" in err.getvalue()


def test_the_typed_e_table_lists_the_registered_engines_rows(stub):
    (row,) = typed_e_table([0.5])
    assert row["Stub linear, typed e as D2"] == Contact("1", "0", 1.0, 0.5, "force").eps(1.0)
    assert list(row)[-1] == "Stub linear, typed e as D2"      # after the shipped engines' rows


def test_the_scene_schema_takes_the_engines_and_their_options_from_the_registry(stub):
    """No engine or option is listed by hand in scene.schema.yaml: the stub's own option is checked
    by the schema like a shipped one's, and refused in one line naming it."""
    schema = scene_schema()
    assert schema["properties"]["code"]["enum"] == scene_engines() == ["lammps", "liggghts", "kratos", "stub"]
    options = schema["properties"]["options"]["properties"]
    assert options["stub_limit"]["type"] == "boolean" and options["limitForce"]["type"] == "boolean"
    assert "stub - stub_limit" in schema["properties"]["options"]["description"]
    raw = yaml.safe_load(Path(SCHEMA_PATH).read_text())
    assert "enum" not in raw["properties"]["code"] and "properties" not in raw["properties"]["options"]
    with pytest.raises(ParameterError, match=r"options\.stub_limit"):
        scene_from_dict({**_scene(), "options": {"stub_limit": "yes"}})
    with pytest.raises(ParameterError, match=r"options\.limitForce.*not an option of code stub"):
        scene_from_dict({**_scene(), "options": {"limitForce": True}})


def test_two_engines_may_not_give_one_option_two_schemas(stub, monkeypatch):
    monkeypatch.setattr(stub, "scene_option_schema", {"stub_limit": {"type": "boolean"},
                                                      "limitForce": {"type": "integer"}}, raising=False)
    with pytest.raises(ValueError, match="limitForce"):
        scene_schema()


def test_an_engine_without_a_runner_says_so_and_one_with_a_runner_gives_its_module():
    assert ENGINES["mercurydpm"].runner is None       # not run here: no runner at all
    lammps = ENGINES["lammps"]
    from restitution.dem.engines.lammps import run
    assert lammps.runner in (None, run) and (lammps.runner is run) == run.available()


def test_the_deck_reader_takes_its_dialects_from_the_engines_deck_hooks():
    from restitution.dem.deck.reader import DIALECTS
    from restitution.dem.engines.lammps import deck as lammps_deck
    from restitution.dem.engines.liggghts import deck as liggghts_deck
    assert ENGINES["lammps"].deck is lammps_deck and ENGINES["liggghts"].deck is liggghts_deck
    assert DIALECTS == {"LAMMPS": lammps_deck, "LIGGGHTS": liggghts_deck}
    assert ENGINES["mercurydpm"].deck is None

"""A scene with ``code: kratos``: the registry's fourth scene engine. Its answer is a MaterialsDEM.json
(one relation per material pair, walls as RigidFacePart materials); that file, audited back by
``restitution deck`` (restitution.dem.engines.kratos.materials), gives every target within the
scene's tolerance; and two of its contacts, run in Kratos itself at the scene's time step, too."""

import json

import pytest

from restitution.dem.engines.kratos.materials import audit_materials
from restitution.dem.engines.kratos.run import KRATOS_INSTALL, available, kratos_eps_runs
from restitution.dem.pair import Pair
from restitution.dem.scene import answer_scene
from restitution.dem.scene.file import scene_from_dict

from test_scene import _liggghts_scene


def _scene(law="choose") -> dict:
    """The LIGGGHTS scene's materials, sizes, wall and targets, for Kratos."""
    return {**_liggghts_scene(False), "name": "kratos", "code": "kratos", "options": {"law": law}}


TARGET = {frozenset(("glass",)): 0.9, frozenset(("glass", "steel")): 0.85, frozenset(("steel",)): 0.8}


@pytest.mark.parametrize("law", ["choose", "DEM_D_Linear_viscous_Coulomb"])
def test_the_scenes_materials_file_gives_its_targets_back(law):
    res = answer_scene(scene_from_dict(_scene(law)))
    assert res["met"] and len(res["contacts"]) == 6 + 3 and res["code"] == "kratos"
    assert {c["chosen"] for c in res["contacts"]} == ({"DEM_D_Hertz_viscous_Coulomb"} if law == "choose" else {law})
    doc = json.loads("\n".join(res["input_lines"]))
    assert len(doc["material_relations"]) == 3       # glass-glass, glass-steel, steel-steel (walls: steel)
    audit = audit_materials(json.dumps(doc), [0.1, 1.0, 2.0], radius={1: 1e-3, 2: 1.5e-3})
    assert len(audit["relations"]) == 3 and len(audit["walls"]) == 2
    for row in audit["relations"] + audit["walls"]:
        want = TARGET[frozenset(row["materials"])]
        assert all(abs(e - want) <= 0.01 for e in row["eps"]), (row["materials"], row["eps"])
        # the constant-e laws reach the target far closer than the tolerance (linear: Kratos' grid)
        assert abs(row["eps"][0] - want) <= (1e-9 if law == "choose" else 1e-4)
    for c in res["contacts"]:
        assert c["setting"]["e"] == doc["material_relations"][[frozenset(r["material_names_list"]) for r in
                                                              doc["material_relations"]].index(
            frozenset(c["materials"]))]["Variables"]["COEFFICIENT_OF_RESTITUTION"]


def test_the_scene_out_directory_holds_the_materials_file(tmp_path):
    from deck_cli import run  # noqa: F401  (the CLI in process, as the deck tests run it)
    import contextlib
    import io

    from restitution.cli import main
    import yaml
    path = tmp_path / "scene.yaml"
    path.write_text(yaml.safe_dump(_scene()))
    with contextlib.redirect_stderr(io.StringIO()):
        status = main(["scene", str(path), "--out", str(tmp_path / "o")], out=io.StringIO())
    assert status == 0
    assert sorted(p.name for p in (tmp_path / "o").iterdir()) == ["MaterialsDEM.json", "scene.json", "table.txt"]
    assert json.loads((tmp_path / "o" / "MaterialsDEM.json").read_text())["material_relations"]


@pytest.mark.dem
@pytest.mark.slow
@pytest.mark.skipif(not available(), reason=f"Kratos not installed: {KRATOS_INSTALL}")
def test_kratos_gives_the_predicted_eps_at_the_scenes_time_step():
    res = answer_scene(scene_from_dict(_scene()))
    types = {t["number"]: t for t in res["types"]}
    cases, expected = [], []
    for c in res["contacts"]:
        if c["b"].startswith("wall:") or c["types"][0] != c["types"][1] - 1:
            continue            # two type pairs: unlike sizes, one of them unlike materials
        a, b = types[c["types"][0]], types[c["types"][1]]
        pair = Pair.spheres(a["radius"], b["radius"], a["density"], b["density"])
        s = c["setting"]
        setting = {"law": s["law"], "e": s["e"], "E": s["E"], "nu": s["nu"], "E2": s["E2"], "nu2": s["nu2"]}
        g, t_c = c["speeds"][-1], c["contact_time"][-1]
        eps = kratos_eps_runs(pair, [(setting, g, c["dt"], 3.0 * t_c)])[0]
        expected.append((c["a"], c["b"], eps, c["eps"][-1]))
    assert len(expected) == 2
    for a, b, eps, predicted in expected:
        assert abs(eps - predicted) <= res["tolerance"], (a, b, eps, predicted)

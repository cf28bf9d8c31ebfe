"""`restitution deck` on a Kratos MaterialsDEM.json (restitution.dem.engines.kratos.materials): eps per
relation of spheres and of a sphere with a wall, radii from the model part or --radius, the time step
from ProjectParametersDEM.json, the line to type for eps = e, and the one-line refusals. The files
are written here in the form of Kratos' own test examples (DEM3D_contact_tests_files and the like)."""

import json

import pytest

from deck_cli import run
from restitution.dem.engines.kratos.contact import kratos_contact
from restitution.dem.engines.kratos.materials import MaterialsError, audit_materials, mdpa_radii
from restitution.dem.pair import Pair

HERTZ = "DEM_D_Hertz_viscous_Coulomb"
LINEAR = "DEM_D_Linear_viscous_Coulomb"


def _materials(law=HERTZ, e_pair=0.2, e_wall=0.6, table=True):
    doc = {"materials": [
        {"material_name": "glass", "material_id": 1,
         "Variables": {"PARTICLE_DENSITY": 2500.0, "YOUNG_MODULUS": 5e7, "POISSON_RATIO": 0.3}},
        {"material_name": "steel", "material_id": 2,
         "Variables": {"PARTICLE_DENSITY": 7800.0, "YOUNG_MODULUS": 2e8, "POISSON_RATIO": 0.25}},
        {"material_name": "plate", "material_id": 3, "Variables": {"YOUNG_MODULUS": 1e9, "POISSON_RATIO": 0.2}}],
        "material_relations": [
            {"material_names_list": ["glass", "steel"], "material_ids_list": [1, 2],
             "Variables": {"COEFFICIENT_OF_RESTITUTION": e_pair, "DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME": law,
                           "STATIC_FRICTION": 0.5}},
            {"material_names_list": ["plate", "glass"], "material_ids_list": [3, 1],
             "Variables": {"COEFFICIENT_OF_RESTITUTION": e_wall, "DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME": law}}]}
    if table:
        doc["material_assignation_table"] = [["SpheresPart.Parts_glass", "glass"], ["SpheresPart.Parts_steel", "steel"],
                                             ["RigidFacePart.Walls", "plate"]]
    return doc


MDPA = """Begin Nodes
 1 0 0 0
 2 1 0 0
 3 2 0 0
End Nodes
Begin NodalData RADIUS // comment
 1 0 0.001
 2 0 0.0012
 3 0 0.0015
End NodalData
Begin SubModelPart Parts_glass
  Begin SubModelPartNodes
   1
   2
  End SubModelPartNodes
End SubModelPart
Begin SubModelPart Parts_steel
  Begin SubModelPartNodes
   3
  End SubModelPartNodes
End SubModelPart
"""


def _write(tmp_path, doc, parameters=None, mdpa=None):
    (tmp_path / "MaterialsDEM.json").write_text(json.dumps(doc, indent=2))
    if parameters is not None:
        (tmp_path / "ProjectParametersDEM.json").write_text(json.dumps(parameters))
    if mdpa is not None:
        (tmp_path / "caseDEM.mdpa").write_text(mdpa)
    return tmp_path / "MaterialsDEM.json"


def test_each_relation_is_the_contact_kratos_maps_it_to(tmp_path):
    path = _write(tmp_path, _materials(), {"problem_name": "case", "MaxTimeStep": 1e-7,
                                           "ElementType": "SphericPartDEMElement3D"}, MDPA)
    status, out, err = run(path, "--g", 1.0, "--json")
    assert status == 0 and err == "", err
    res = json.loads(out)
    assert res["time_step"] == 1e-7 and len(res["relations"]) == 1 and len(res["walls"]) == 1
    pair_row, wall_row = res["relations"][0], res["walls"][0]
    # radii from the model part: the smallest of each material's part
    pair = Pair.spheres(0.001, 0.0015, 2500.0, 7800.0)
    contact = kratos_contact(pair, law="hertz", e=0.2, E=5e7, nu=0.3, E2=2e8, nu2=0.25)
    assert pair_row["D1"] == pytest.approx(contact.D1, rel=1e-14) and pair_row["D2"] == pytest.approx(contact.D2)
    assert pair_row["eps"][2] == pytest.approx(contact.eps(1.0), rel=1e-12) and pair_row["end"] == "force"
    assert pair_row["steps_per_contact"][2] == pytest.approx(contact.contact_time(1.0) / 1e-7)
    # the wall relation, written wall first, audited as the glass sphere on the plate (its own E, nu)
    assert wall_row["materials"] == ["glass", "plate"]
    wall = kratos_contact(Pair.wall(0.001, 2500.0), law="hertz", e=0.6, E=5e7, nu=0.3, E2=1e9, nu2=0.2, wall=True)
    assert wall_row["D1"] == pytest.approx(wall.D1, rel=1e-14) and wall_row["eps"][0] == pytest.approx(wall.eps(0.1))


def test_the_line_to_type_gives_eps_e(tmp_path):
    for law, tol in ((HERTZ, 1e-9), (LINEAR, 1e-4)):
        path = _write(tmp_path, _materials(law=law, e_pair=0.3), mdpa=None)
        status, out, _ = run(path, "--g", 1.0, "--radius", "1=0.001", "2=0.0015")
        assert status == 0
        line = [ln for ln in out.splitlines() if "for eps = e" in ln][0]
        typed = float(line.split('"COEFFICIENT_OF_RESTITUTION": ')[1].split()[0])
        pair = Pair.spheres(0.001, 0.0015, 2500.0, 7800.0)
        short = "hertz" if law == HERTZ else "linear"
        eps = kratos_contact(pair, law=short, e=typed, E=5e7, nu=0.3, E2=2e8, nu2=0.25).eps(1.0)
        assert abs(eps - 0.3) <= tol, (law, typed, eps)       # linear: the bisection's grid, about 1e-4


def test_a_material_of_spheres_and_walls_gives_both_rows():
    doc = _materials()
    doc["material_assignation_table"].append(["RigidFacePart.More", "glass"])
    doc["material_relations"].append({"material_names_list": ["glass", "glass"], "material_ids_list": [1, 1],
                                      "Variables": {"COEFFICIENT_OF_RESTITUTION": 0.5,
                                                    "DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME": LINEAR}})
    res = audit_materials(json.dumps(doc), [1.0], radius={1: 1e-3, 2: 1e-3})
    assert [r["materials"] for r in res["relations"]] == [["glass", "steel"], ["glass", "glass"]]
    # glass is now a wall too: steel spheres meet it through the glass - steel relation
    assert [r["materials"] for r in res["walls"]] == [["steel", "glass"], ["glass", "plate"], ["glass", "glass"]]


def test_without_a_table_a_material_with_density_is_a_sphere():
    res = audit_materials(json.dumps(_materials(table=False)), [1.0], radius={1: 1e-3, 2: 1e-3})
    assert len(res["relations"]) == 1 and [r["materials"] for r in res["walls"]] == [["glass", "plate"]]


def test_mdpa_radii_by_sub_model_part():
    radii = mdpa_radii(MDPA)
    assert sorted(radii[""]) == [0.001, 0.0012, 0.0015]
    assert sorted(radii["Parts_glass"]) == [0.001, 0.0012] and radii["Parts_steel"] == [0.0015]


@pytest.mark.parametrize("change, word", [
    (lambda d: d["material_relations"][0]["Variables"].update(DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME="DEM_D_JKR_"
                                                                                                   "Cohesive_Law"),
     "not mapped"),
    (lambda d: d["material_relations"][0]["Variables"].update(DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME="DEM_D_DMT_"
                                                                                                   "Cohesive_Law"),
     "not mapped"),
    (lambda d: d["material_relations"][0]["Variables"].update(COEFFICIENT_OF_RESTITUTION=1.0), "no damping"),
    (lambda d: d["material_relations"][0].update(material_ids_list=[1, 7]), "two materials"),
    (lambda d: d.pop("material_relations"), "not a Kratos MaterialsDEM.json"),
])
def test_what_is_refused_in_one_line(tmp_path, change, word):
    doc = _materials()
    change(doc)
    path = _write(tmp_path, doc)
    status, out, err = run(path, "--g", 1.0, "--radius", "1=0.001", "2=0.001")
    assert status == 2 and out == "" and err.count("\n") == 1 and word in err, err


@pytest.mark.parametrize("parameters, word", [
    ({"ElementType": "SphericContPartDEMElement3D"}, "bonded"),
    ({"GlobalDamping": 0.1}, "GlobalDamping"),
    ({"VirtualMassCoefficient": 0.5}, "VirtualMassCoefficient"),
    ({"Dimension": 2, "ElementType": "CylinderPartDEMElement2D"}, "2D"),
])
def test_project_parameters_that_change_the_contact_are_refused(tmp_path, parameters, word):
    path = _write(tmp_path, _materials(), parameters)
    status, out, err = run(path, "--g", 1.0, "--radius", "1=0.001", "2=0.001")
    assert status == 2 and out == "" and err.count("\n") == 1 and word in err, err


def test_a_sphere_without_radius_names_the_option(tmp_path):
    path = _write(tmp_path, _materials())
    status, out, err = run(path, "--g", 1.0)
    assert status == 2 and "--radius 1=R" in err and err.count("\n") == 1, err


def test_the_project_parameters_file_itself_is_refused_naming_the_materials_file(tmp_path):
    path = tmp_path / "ProjectParametersDEM.json"
    path.write_text(json.dumps({"problem_name": "x", "solver_settings": {}}))
    status, out, err = run(path, "--g", 1.0)
    assert status == 2 and "materials file" in err and err.count("\n") == 1, err


def test_a_deck_is_still_a_deck(tmp_path):
    deck = tmp_path / "in.deck"
    deck.write_text("atom_style sphere\ncomm_modify vel yes\nregion box block -2 2 -2 2 -2 2\ncreate_box 1 box\n"
                    "create_atoms 1 single 0 0 0\npair_style granular\npair_coeff * * hooke 1000 50 tangential linear_nohistory 0 0\n"
                    "set type 1 diameter 1 density 1\n")
    status, out, _ = run(deck, "--g", 1.0)
    assert status == 0 and "LAMMPS hooke" in out


def test_audit_refuses_without_speeds():
    with pytest.raises(Exception) as info:
        audit_materials(json.dumps(_materials()), [])
    assert not isinstance(info.value, MaterialsError) and "speed" in str(info.value)

"""`restitution deck` on the engines' own shipped examples (Debian packages liggghts-doc and
lammps-examples; skipped with the reason where missing), and on the files a deck names (include,
read_data) written here for what the examples do not exercise."""

import math
import re

import pytest

from dashpot import damped_overlap, dashpot_eps
from deck_cli import LAMMPS_EXAMPLES, LIGGGHTS_EXAMPLES, audit, needs_lammps_examples, needs_liggghts_examples, run
from restitution.dem.engines.lammps.contact import lammps_contact
from restitution.dem.engines.liggghts.contact import liggghts_contact
from restitution.dem.pair import Pair



@needs_liggghts_examples
def test_liggghts_contact_model_tutorial():
    """contactModels/in.newModels: hertz, e = 0.95, limitForce off: eps is e at every speed."""
    res, err = audit(LIGGGHTS_EXAMPLES / "contactModels" / "in.newModels", "--g", 1.0)
    (pair,) = res["pairs"]
    assert pair["types"] == [1, 1] and pair["typed_e"] == 0.95 and pair["end"] == "overlap"
    assert len(pair["speeds"]) == 5 and max(pair["speeds"]) / min(pair["speeds"]) == pytest.approx(100)
    assert all(abs(e - 0.95) < 1e-9 for e in pair["eps"])
    assert pair["exact_line"].endswith("coefficientRestitution peratomtypepair 1 0.95")
    # its two plane walls and its cylinder (of type 1, hertz) give e as well: the cylinder is a
    # plane to LIGGGHTS' contact, which takes the sphere's own radius against every wall
    assert [(w["wall"], w["types"], w["wall_type"]) for w in res["walls"]] == [("zwalls1", [1], 1),
                                                                                ("zwalls2", [1], 1),
                                                                                ("cylwalls", [1], 1)]
    assert "audited as a flat wall" in res["walls"][2]["model"]
    assert all(abs(e - 0.95) < 1e-9 for w in res["walls"] for e in w["eps"])
    assert [row["text"].split()[1] for row in res["unknown_lines"] if "wall" in row["why"]] == []
    # the same numbers from the dictionary, with the template's radius and density
    contact = liggghts_contact(Pair.spheres(0.0025, 0.0025, 2500.0), E=5e6, nu=0.45, e=0.95)
    assert pair["D1"] == pytest.approx(contact.D1, rel=1e-12) and pair["D2"] == pytest.approx(contact.D2, rel=1e-12)


@needs_liggghts_examples
def test_liggghts_hooke_tutorial_and_a_cohesion_model():
    res, _ = audit(LIGGGHTS_EXAMPLES / "hysteresis" / "in.noHysteresis", "--g", 0.5, 2.0, 50.0)
    (pair,) = res["pairs"]
    assert pair["alpha"] == "1" and pair["speeds"] == [0.5, 2.0, 50.0]
    assert all(abs(e - pair["typed_e"]) < 1e-9 for e in pair["eps"][:2])
    # at 50 m/s the linear spring's overlap (5.7 mm undamped) passes R1 + R2 = 3 mm: no eps
    assert pair["passes_through"] == [False, False, True] and pair["eps"][2] is None
    # in.cohesion: its one pair's sjkr cohesion is not mapped, and named; its walls carry no cohesion
    # model and give e (LIGGGHTS, a sphere dropped on the deck's zplane at dt 1e-7: 0.90000142);
    # before, the whole deck was refused
    res, err = audit(LIGGGHTS_EXAMPLES / "cohesion" / "in.cohesion", "--g", 1.0)
    assert res["pairs"] == [] and "types 1 1: cohesion sjkr with cohesionEnergyDensity 300000" in err, err
    assert [w["wall"] for w in res["walls"]] == ["zwalls1", "zwalls2", "cylwalls"]
    assert all(abs(e - 0.9) < 1e-9 for w in res["walls"] for e in w["eps"])


@needs_lammps_examples
def test_lammps_granular_examples():
    """in.pour.drum: LAMMPS 22 Jul 2025 itself stops on its JKR pair with tsuji damping (one line,
    LAMMPS' words). multi/in.granular: the masses LAMMPS holds (set mass, then a diameter, which
    keeps the mass), no --density needed; hooke + mass_velocity is the linear dashpot, eps in
    closed form."""
    drum = LAMMPS_EXAMPLES / "granular" / "in.pour.drum"
    status, _, err = run(drum, "--g", 1.0)
    assert status == 2 and err.count("\n") == 1 and "LAMMPS stops here: Cannot use tsuji model with a cohesive" in err
    res, err = audit(LAMMPS_EXAMPLES / "multi" / "in.granular", "--g", 1.0)
    # 2d changes no granular force and no mass LAMMPS holds (test_dem_deck_engine.py): said nowhere
    assert "dimension 2" not in err, err
    assert [p["types"] for p in res["pairs"]] == [[1, 1], [1, 2], [2, 2]]
    masses = {1: 1.0, 2: 400.0}
    for p in res["pairs"]:       # hooke + mass_velocity: the linear dashpot, eps in closed form
        i, j = p["types"]
        # (a density is read from LAMMPS' mass and radius to 12 digits)
        assert p["D1"] == pytest.approx(1.0 * (1 / masses[i] + 1 / masses[j]), rel=1e-10)
        zeta = p["D2"] / (2.0 * math.sqrt(p["D1"]))
        closed = math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta ** 2)) if zeta < 1 else 0.0
        assert p["typed_e"] is None and p["exact_line"] is None
        # the example runs in reduced units with diameters 1 and 20: from g ~ 3 type 1's overlap
        # would pass the sum of the radii
        assert p["passes_through"] == [damped_overlap(p, g) >= p["overlap_limit"] for g in p["speeds"]]
        assert all(abs(e - closed) < 1e-9 for e, t in zip(p["eps"], p["passes_through"]) if not t)
        assert all(p["sticks"]) == (zeta >= 1)
    assert any(any(p["passes_through"]) for p in res["pairs"])


@needs_lammps_examples
def test_lammps_read_data_example():
    """multi/in.powerlaw: LAMMPS 22 Jul 2025 itself stops on its data file (a 2d box whose z range
    does not straddle 0): refused in one line, LAMMPS' words (the hand reader audited it)."""
    status, out, err = run(LAMMPS_EXAMPLES / "multi" / "in.powerlaw", "--g", 1.0)
    assert status == 2 and out == "" and err.count("\n") == 1
    assert "line 6 (read_data data.powerlaw): LAMMPS stops here: Read_data zlo/zhi for 2d" in err


@needs_liggghts_examples
@pytest.mark.slow
def test_liggghts_read_data_example():
    """hydrogel_multicontact/in.hydrogel_default: read_data data/input.data (every atom of type 1, of
    505 diameters; none of type 2, the walls' type), E per type, nu = 0.5 (an incompressible gel).
    Its sizes are LIGGGHTS' own, sampled; its walls-only type is no refusal (it was both, before)."""
    deck = LIGGGHTS_EXAMPLES / "hydrogel_multicontact" / "in.hydrogel_default"
    res, err = audit(deck, "--g", 1.0)
    assert [p["types"] for p in res["pairs"]] == [[1, 1]] and res["pairs"][0]["sizes"] == "any"
    assert all(abs(e - 0.95) < 1e-9 for p in res["pairs"] + res["walls"] for e in p["eps"])
    notes = " ".join(res["notes"])
    # sampled: evenly in radius, with the two ends' neighbours (field round 8)
    assert re.search(r"type 1 holds 505 sizes: audited at 1\d of them", notes) and "type 2 has no particle" in notes
    # the smallest diameter in the data file, 0.01816704, is the smallest radius audited
    assert min(r for p in res["pairs"] for r, _ in p["at"]) == pytest.approx(0.00908352, rel=1e-12)
    # its gravity beside the floor depends on size where the law's eps does not: given at the
    # smallest and the largest sphere (diameter 0.0245606), the ends of its range
    floor = next(w for w in res["walls"] if w["wall"] == "wall_bottom")
    assert [b["at"] for b in floor["beside"] if b["style"] == "gravity"] == [[[0.00908352, 11.5]],
                                                                             [[0.0122803, 11.5]]]
    res, err = audit(deck, "--g", 1.0, "--radius", "1=0.01")
    assert [p["types"] for p in res["pairs"]] == [[1, 1]] and "sizes" not in res["pairs"][0]
    res, _ = audit(deck, "--g", 1.0, "--radius", "1=0.01", "2=0.01", "--density", "2=11.5")
    pairs = {tuple(p["types"]): p for p in res["pairs"]}
    assert set(pairs) == {(1, 1), (1, 2), (2, 2)}
    contact = liggghts_contact(Pair.spheres(0.01, 0.01, 11.5), E=23.3e3, nu=0.5, E2=5e7, nu2=0.5, e=0.95)
    assert pairs[(1, 2)]["D1"] == pytest.approx(contact.D1, rel=1e-12)     # the data file's density 11.5
    assert all(abs(e - 0.95) < 1e-9 for p in pairs.values() for e in p["eps"])


@needs_liggghts_examples
@pytest.mark.slow
def test_liggghts_include_example():
    """ParScale's in.liggghts_init takes its materials and sizes from variables in the file it
    includes (in.DEM); in.liggghts_run then reads a binary restart, which is refused in one line."""
    here = LIGGGHTS_EXAMPLES / "ParScale" / "fluidizedBedTempParScale"
    res, _ = audit(here / "in.liggghts_init", "--g", 1.0, "--radius", "2=1e-3", "3=1e-3", "--density", "2=2500",
                   "3=2500")
    p = res["pairs"][0]
    assert p["types"] == [1, 1] and p["typed_e"] == 0.97 and all(abs(e - 0.97) < 1e-9 for e in p["eps"])
    # E = 1.e7, nu = 0.45, diameter 2e-3 and density 2500, all from in.DEM's variables
    contact = liggghts_contact(Pair.spheres(1e-3, 1e-3, 2500.0), E=1e7, nu=0.45, e=0.97)
    assert p["D1"] == pytest.approx(contact.D1, rel=1e-12) and p["D2"] == pytest.approx(contact.D2, rel=1e-12)
    status, out, err = run(here / "in.liggghts_run", "--g", 1.0)
    assert status == 2 and out == "" and err.count("\n") == 1 and "line 27" in err and "read_restart" in err


SPHERES_DATA = """\
written by hand: two types

 4 atoms
 2 atom types

 -1 1 xlo xhi
 -1 1 ylo yhi
 -1 1 zlo zhi

Atoms # sphere

1 1 0.002 2500 0 0 0
2 1 0.002 2500 0.5 0 0
3 2 0.003 7800 0 0.5 0
4 2 0.003 7800 0.5 0.5 0

Velocities

1 0 0 0 0 0 0
2 0 0 0 0 0 0
3 0 0 0 0 0 0
4 0 0 0 0 0 0
"""


@pytest.mark.slow
def test_include_and_read_data_written_decks(tmp_path):
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "materials.in").write_text("variable E equal 5*10^7\nvariable e index 0.5 0.6\n")
    (tmp_path / "spheres.data").write_text(SPHERES_DATA)
    deck = tmp_path / "in.main"
    deck.write_text("atom_style sphere\ncomm_modify vel yes\ninclude sub/materials.in\nread_data spheres.data\n"
                    "timestep 1e-7\npair_style granular\n"
                    "pair_coeff * * hertz/material ${E} ${e} 0.3 damping tsuji tangential linear_nohistory 0 0\n")
    res, err = audit(deck, "--g", 1.0)
    assert err == ""
    pairs = {tuple(p["types"]): p for p in res["pairs"]}
    contact = lammps_contact(Pair.spheres(0.001, 0.0015, 2500.0, 7800.0), normal="hertz/material", E=5e7, nu=0.3,
                             damping="tsuji", eta_n0=0.5, limit_damping=False)
    assert pairs[(1, 2)]["typed_e"] == 0.5 and pairs[(1, 2)]["D1"] == pytest.approx(contact.D1, rel=1e-12)
    assert pairs[(1, 2)]["eps"][2] == pytest.approx(contact.eps(1.0), rel=1e-12)
    # the data file's own pair coefficients, mixed by LAMMPS' rule where no line covers a pair
    (tmp_path / "spheres.data").write_text(SPHERES_DATA + "\nPair Coeffs # granular\n\n"
                                           "1 hooke 1e3 0.5 damping mass_velocity tangential linear_nohistory 0 0\n"
                                           "2 hooke 4e3 0.5 damping mass_velocity tangential linear_nohistory 0 0\n")
    deck.write_text("atom_style sphere\npair_style granular\nread_data spheres.data\n")
    res, err = audit(deck, "--g", 1.0)
    p12 = {tuple(p["types"]): p for p in res["pairs"]}[(1, 2)]
    assert "mixed from spheres.data line 26 and spheres.data line 27" in p12["model"]
    m_eff = 1.0 / (1.0 / (2500.0 * 4.0 / 3.0 * math.pi * 1e-9) + 1.0 / (7800.0 * 4.0 / 3.0 * math.pi * 1.5e-3 ** 3))
    assert p12["D1"] == pytest.approx(2e3 / m_eff, rel=1e-12)        # hooke: k mixed as a geometric mean
    assert all(abs(e - dashpot_eps(p12)) < 1e-9 for e in p12["eps"])


@pytest.mark.parametrize("files, word", [
    ({"in.main": "include missing.in\n"}, "Cannot open input script missing.in"),
    ({"in.main": "atom_style sphere\nread_data spheres.data add append\n", "spheres.data": SPHERES_DATA},
     "Cannot use read_data add before simulation box is defined"),
    ({"in.main": "atom_style full\nread_data spheres.data\n",
      "spheres.data": SPHERES_DATA.replace("Atoms # sphere", "Atoms")}, "LAMMPS stops here"),
])
def test_files_a_deck_names_refused_in_one_line(tmp_path, files, word):
    """A file LAMMPS cannot open, reads as another atom style or adds to a box not yet made stops
    it: its words, on the deck's line. (A deck that includes itself runs until
    the budget: test_dem_deck_engine.py; a type with no atom in the data file is a type without
    particles: test_dem_deck_engine.py.)"""
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    (tmp_path / "in.main").write_text(files["in.main"] + "pair_style granular\npair_coeff * * hooke 1e3 0.5 "
                                      "damping velocity tangential linear_nohistory 0 0\n")
    status, out, err = run(tmp_path / "in.main", "--g", 1.0)
    assert status == 2 and out == "" and err.count("\n") == 1 and word in err, err

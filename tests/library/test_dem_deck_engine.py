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
from deck_cli import outside_file, outside_file_outcome
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.engines.lammps.contact import lammps_contact
from restitution.dem.pair import Pair

pytestmark = pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS' Python module not installed "
                                "(pip install -e '.[dem]')")

T = "tangential linear_nohistory 0 0"
#: A box in SI units with LAMMPS' ghost velocities, which its granular pairs need
BOX = """units si
atom_style sphere
comm_modify vel yes
region box block -1 1 -1 1 -1 1
"""
HEAD = BOX + """create_box 3 box
create_atoms 1 single 0 0 0
create_atoms 2 single 0.5 0 0
create_atoms 3 single -0.5 0 0
set type 1*3 diameter 0.02 density 2500
fix integrate all nve/sphere
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
    text = BOX + f"""create_box 2 box
create_atoms 1 single 0 0 0
set type 1*2 diameter 0.02 density 2500
create_atoms 2 single 0.5 0 0
pair_style granular
pair_coeff * * hertz 1e5 0.5 {T}
fix integrate all nve/sphere
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


def test_a_size_flag_that_replaces_what_the_particles_hold_says_so(tmp_path):
    # the flags are for walls-only types; replacing a held size without a word gave another eps silently
    status, out, err = deck(tmp_path, HEAD + f"pair_coeff * * hooke 1000 1 {T}\nrun 1\n", "--radius", "1=0.05",
                            "--density", "3=2500")
    assert status == 0 and "type 1: --radius 0.05 replaces the 0.01 its particles hold" in err, err
    assert "--density" not in err          # the same value as held: nothing replaced


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
    # write_data runs, into the scratch copy (a later read_data reads it back): not beside the deck
    for word in ("shell", "print", "dump"):
        assert f"restitution deck: {word} (line" in err


@pytest.mark.parametrize("line", ["region2vmd {out} region box", "dynamical_matrix all eskm 1e-6 file {out}",
                                  "third_order all eskm 1e-6 file {out}"])
def test_a_command_that_writes_its_own_file_is_not_run(tmp_path, line):
    """Field test r10: region2vmd and dynamical_matrix write a file of their own. Run in the pass, a
    write above the deck's folder failed in the confinement and the deck was refused with "LAMMPS
    stops here", which LAMMPS run by hand never says (it writes the file and goes on)."""
    out = tmp_path.parent / f"{tmp_path.name}_written.out"
    text = HEAD + f"pair_coeff * * hooke 1000 1 {T}\n" + line.format(out=out) + "\nrun 1\n"
    status, _, err = deck(tmp_path, text)
    assert status == 0 and not out.exists(), err
    assert f"restitution deck: {line.split()[0]} (line" in err


def test_a_deck_in_latin1_is_made_safe_and_audited(tmp_path):
    """Field test r7: a deck whose comment holds a Latin-1 byte (saved by another editor) was passed
    over when the copy was made safe, as if it were not a script: its pair_style went unseen ("the
    deck has no pair_style") and its shell lines would have been left in place. LAMMPS runs it."""
    target = tmp_path / "TOUCHED"
    text = ("# r\xe9glages du contact\n" + HEAD + f"pair_coeff * * hooke 1000 1 {T}  # \xe9crit\n"
            f"shell touch {target}\nrun 1\n").encode("latin-1")
    path = tmp_path / "in.deck"
    path.write_bytes(text)
    status, out, err = run_cli(["deck", str(path), "--g", "1.0", "--json"])
    assert status == 0, err
    assert not target.exists() and "restitution deck: shell (line" in err
    got = {tuple(p["types"]): p for p in json.loads(out)["pairs"]}
    assert got[(1, 1)]["eps"][2] == pytest.approx(eps_hooke(1000, 1.0), rel=1e-10)
    assert path.read_bytes() == text


@pytest.mark.parametrize("style, coeff", [("granular", f"hooke 1000 0 {T}"),
                                          ("granular", f"hertz/material 1e8 0.0 0.3 damping viscoelastic {T}"),
                                          ("gran/hooke 1000 NULL 0.0 NULL 0.5 0", "")],
                         ids=["hooke velocity 0", "viscoelastic 0", "gran/hooke gamma_n 0"])
def test_an_undamped_contact_is_elastic_not_refused(tmp_path, style, coeff):
    """Field test r7: an elastic reference run (normal damping 0) was refused ('eta_n0 = 0.0: must
    be a finite number > 0'), with one such pair the whole deck. LAMMPS runs it; nothing damps."""
    text = HEAD.replace("pair_style granular", f"pair_style {style}") + f"pair_coeff * * {coeff}\nrun 1\n"
    p = pairs(tmp_path, text)
    assert p[(1, 2)]["eps"][2] == 1.0
    pair = Pair.spheres(0.01, 0.01, 2500.0)
    t_c = 3.2 * math.sqrt(pair.m / 1000.0) if "hooke" in (style + coeff) else 1e-4
    if "hooke" in (style + coeff):
        line = f"pair_coeff * * {coeff}" if coeff else "pair_coeff * *"
        # LAMMPS' velocity Verlet: 1 + 6.7e-6 at t_c/400, falling as dt^2 towards the audit's 1
        coarse, fine = (lammps_run.lammps_eps(pair, line, 1.0, t_c / n, 1.5 * t_c, style=style) for n in (400, 1600))
        assert abs(fine - 1.0) <= 1e-6 and abs(fine - 1.0) <= abs(coarse - 1.0) / 8, (coarse, fine)


DATA_ONE_TYPE = """one sphere

1 atoms
1 atom types
-1 1 xlo xhi
-1 1 ylo yhi
-1 1 zlo zhi

Atoms # sphere

1 1 0.02 2500 0 0 0
"""


def test_read_data_with_room_for_more_types_is_audited(tmp_path):
    """Field test r7: ``read_data FILE extra/atom/types 1`` (room for a type created later) was
    refused as if it shifted types; LAMMPS keeps the file's types and makes room for type 2."""
    text = BOX.replace("region box block -1 1 -1 1 -1 1\n", "") + f"""read_data data.one extra/atom/types 1
create_atoms 2 single 0.5 0 0
set type 2 diameter 0.01 density 3000
fix integrate all nve/sphere
pair_style granular
pair_coeff * * hooke 1000 1 {T}
run 1
"""
    p = pairs(tmp_path, text, files={"data.one": DATA_ONE_TYPE})
    assert p[(1, 2)]["eps"][2] == pytest.approx(eps_hooke(1000, 1.0, r2=0.005, rho2=3000.0), rel=1e-10)
    assert p[(2, 2)]["eps"][2] == pytest.approx(eps_hooke(1000, 1.0, 0.005, 0.005, 3000.0, 3000.0), rel=1e-10)


def test_an_output_fix_is_not_executed_and_is_named(tmp_path):
    """Field test: fix print, fix ave/time and fix balance with an output file were made no-ops (a
    fix of the same ID that does nothing) but, unlike the commands made no-ops, never named on
    stderr, which the documentation promises for both."""
    text = HEAD + f"""pair_coeff * * hooke 1000 1 {T}
compute ke all ke
fix p all print 1 "x" file printed.txt
fix a all ave/time 1 1 1 c_ke file averaged.txt
fix b all balance 1 1.1 shift x 5 1.1 out balanced.txt
unfix b
fix ph all phonon 1 1 0 map.in {tmp_path / "phonon_out"}
run 1
"""
    before = set(tmp_path.iterdir())
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    assert set(tmp_path.iterdir()) == before | {tmp_path / "in.deck"}
    # field test r7: fix phonon (its log to a path of the deck's choosing) ran in the engine's pass
    # fix ave/time runs without its file (its values may be read after a run: field round 14, r10)
    for word, line in (("fix print", 14), ("the file keyword of fix ave/time", 15), ("the out keyword of fix balance", 16),
                       ("fix phonon", 18)):
        assert f"restitution deck: {word} (line {line} and any like it): not executed" in err, err


@pytest.mark.parametrize("fix", ['fix a all ave/time 1 1 1 c_ke file "a.txt', 'fix b all balance 1 1.1 shift x 5 1.1 out "b.txt'],
                         ids=["ave/time", "balance"])
def test_an_output_fix_whose_file_name_is_not_closed_stops_as_the_engine_does(tmp_path, fix):
    """An unclosed quote in an output fix's file name stops LAMMPS ("Unmatched double quote"); the
    copy split the line at whitespace and dropped the file keyword with the broken name, so it ran a
    line the engine never runs and printed the law. The line is now left as written: one line,
    LAMMPS' message, the line as the deck wrote it."""
    status, out, err = deck(tmp_path, HEAD + f"pair_coeff * * hooke 1000 1 {T}\ncompute ke all ke\n{fix}\nrun 1\n")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert "Unmatched double quote" in err and f"({fix}):" in err and "#restitution" not in err, err


@pytest.mark.parametrize("before", [True, False], ids=["before the pair style", "after it"])
def test_fix_balance_runs_so_its_order_check_is_lammps(tmp_path, before):
    """Field round 35, X01 (and LAMMPS' own examples/granular/in.pour.drum): fix balance defined
    before a pair style with a contact history stops LAMMPS at the run ("Pair styles using neighbor
    history must be defined before fix bal balance"); the copy made the fix a no-op and printed the
    law. It now runs in the copy (without its out file), and LAMMPS says it; after the pair style
    the deck is audited."""
    balance = "fix bal all balance 1000 1.1 shift x 10 1.1 out balanced.txt\n"
    style = HEAD.split("pair_style")[0], "pair_style" + HEAD.split("pair_style", 1)[1]
    text = (style[0] + (balance if before else "") + style[1] + "pair_coeff * * hooke 1000 1 tangential linear_history 10 0 0.3\n"
            + ("" if before else balance) + "run 1\n")
    status, out, err = deck(tmp_path, text)
    if before:
        assert status == 2 and "must be defined before fix bal balance" in err, err
    else:
        assert status == 0, err
    assert not (tmp_path / "balanced.txt").exists()


def test_a_size_given_for_a_type_the_deck_has_not_is_named(tmp_path):
    """Field test: --radius 4=0.1 on a deck of three atom types was taken without a word, though it
    sizes nothing (a slip for type 3, say)."""
    status, out, err = deck(tmp_path, HEAD + f"pair_coeff * * hooke 1000 1 {T}\nrun 1\n", "--radius", "4=0.1",
                            "--density", "5=3000")
    assert status == 0, err
    assert "restitution deck: type 4: --radius 0.1 names no atom type of the deck (it has 3): not used" in err, err
    assert "restitution deck: type 5: --density 3000 names no atom type of the deck (it has 3): not used" in err, err


@pytest.mark.parametrize("lines", [
    'variable c string shell\nif "1 > 0" then "${{c}} touch {target}"',
    'variable c string shell\nif "1 > 0" then "print x" else "${{c}} touch {target}"',
    'variable c string "shell touch {target}"\nif "1 > 0" then ${{c}}',
    'if "1 > 0" then "if \'1 > 0\' then \'shell touch {target}\'"',
], ids=["quoted", "else", "unquoted", "nested"])
def test_a_command_an_if_runs_is_made_safe_whatever_its_text(tmp_path, lines):
    """A branch's command whose name a variable gives was once taken for a condition and run:
    the shell touched the file (found by trying it, not by a test)."""
    target = tmp_path / "TOUCHED"
    text = HEAD + f"pair_coeff * * hooke 1000 1 {T}\n" + lines.format(target=target) + "\nrun 1\n"
    status, out, err = deck(tmp_path, text)
    assert not target.exists()
    assert "Traceback" not in err


@pytest.mark.parametrize("absolute", [True, False], ids=["absolute", "climbing"])
def test_a_file_included_from_outside_the_deck_folder_is_not_run(tmp_path, absolute):
    """An include of a file outside the deck's folder ran that file as written, and its shell
    touched the file (found by trying it, not by a test). Named above the folder as written, or by
    an absolute path (field round 8: refused), it is copied into the scratch, made safe and run."""
    folder, target, name = outside_file(tmp_path, absolute)
    status, out, err = deck(folder, HEAD + f"pair_coeff * * hooke 1000 1 {T}\ninclude {name}\nrun 1\n")
    assert not target.exists()
    shown = name if absolute else "../outside/evil.in"
    assert status == 0 and f"shell ({shown} line 1 and any like it): not executed" in err, err


@pytest.mark.parametrize("absolute", [True, False], ids=["absolute", "climbing"])
def test_a_file_outside_the_deck_folder_named_by_a_variable_is_not_run(tmp_path, absolute):
    """The engine resolves ``include ${f}`` as it runs, after the copy was made safe: a file
    outside the deck's folder ran as written, and its shell touched the file (issue 52's hole)."""
    folder, target, name = outside_file(tmp_path, absolute)
    before = sorted(tmp_path.rglob("*"))
    status, out, err = deck(folder, HEAD + f"pair_coeff * * hooke 1000 1 {T}\nvariable f string {name}\n"
                            "include ${f}\nrun 1\n")
    assert not target.exists() and sorted(tmp_path.rglob("*")) == sorted(before + [folder / "in.deck"])
    outside_file_outcome((status, out, err), absolute, folder, 14)


@pytest.mark.parametrize("how", ["name", "folder"])
def test_a_file_inside_the_deck_folder_named_by_a_variable_is_run(tmp_path, how):
    """By its name, or by the deck's folder's own absolute path: the engine reads the safe copy."""
    target = tmp_path / "TOUCHED"
    name = "part.in" if how == "name" else str(tmp_path / "part.in")
    part = f"shell touch {target}\npair_coeff * * hooke 2000 1 {T}\n"
    p = pairs(tmp_path, HEAD + f"variable f string {name}\ninclude ${{f}}\nrun 1\n", files={"part.in": part})
    assert not target.exists()
    assert p[(1, 1)]["eps"][2] == pytest.approx(eps_hooke(2000, 1.0), rel=1e-10)


@pytest.mark.parametrize("name, setting", [
    ("part.in", ""), ('"part.in"', ""), ("'part.in'", ""), ('"sub dir/part.in"', ""),
    ('"${f}"', "variable f string part.in\n"), ('"p${a}.in"', "variable a string art\n"),
    ('"p$(2*0).in"', "")],
    ids=["plain", "double", "single", "space", "variable", "part variable", "formula"])
def test_an_include_name_in_quotes_is_read_as_the_engine_reads_it(tmp_path, name, setting):
    """Session 23: ``include "part.in"`` (LAMMPS takes the name without its quotes) was followed under
    the name with its quotes, so the contact in part.in was never read and the deck was refused with
    "no pair_style granular". Field round 29 (I14, I18, V02, I45): a quoted name with a space, or with
    a variable or formula LAMMPS substitutes as it opens the file (its echo keeps them): the included
    contact was not read, and the deck's earlier one printed (0.414916 where LAMMPS ran 0.578975)."""
    (tmp_path / "sub dir").mkdir()
    part = f"pair_coeff * * hooke 2000 1 {T}\n"
    (tmp_path / "sub dir" / "part.in").write_text(part)
    p = pairs(tmp_path, BOX + "create_box 3 box\ncreate_atoms 1 single 0 0 0\nset type 1 diameter 0.02 density 2500\n"
              f"fix integrate all nve/sphere\npair_style granular\npair_coeff * * hooke 9000 1 {T}\n"
              f"{setting}include {name}\nrun 1\n", files={"part.in": part, "p0.in": part})
    assert p[(1, 1)]["eps"][2] == pytest.approx(eps_hooke(2000, 1.0), rel=1e-10)


def test_echoed_commands_are_the_lines_they_came_from_never_another_file_or_the_audits_own(tmp_path):
    """Field test: the audit's marker runs "timer timeout off" and "run 0 post no"; matched by text
    they were another file's line 1 (not understood) and more runs of the deck's own line 15. Each
    echoed command is known by its line's tag; the file a variable names, by its own lines only."""
    files = {"part.in": f'pair_coeff * * hooke 2000 1 {T}\nif "1 > 0" then "timestep 2e-6"\n',
             "other.in": "timer timeout off\nrun 0 post no\npair_coeff * * hooke 9000 1 " + T + "\n"}
    status, out, err = deck(tmp_path, HEAD + "variable f string part.in\ninclude ${f}\nfix 1 all nve/sphere\n"
                                             "run 0 post no\nrun 10\n", files=files)
    assert status == 0 and "other.in" not in err and "not understood" not in err, err
    res = json.loads(out)
    # (the deck's own run 0 makes no step, so it is no run of a stage: field round 19, C1)
    assert [(r["line"], r["text"]) for r in res["stages"][0]["runs"]] == [(16, "run 10")]
    row = {tuple(p["types"]): p for p in res["pairs"]}[(1, 1)]
    assert row["dt"] == 2e-6 and row["eps"][2] == pytest.approx(eps_hooke(2000, 1.0), rel=1e-10)


def test_commands_that_cannot_change_a_contact_are_accepted_without_a_word(tmp_path):
    """dimension 2: LAMMPS keeps a sphere's mass and its granular forces (a head-on pair r 0.005 and
    0.01, hertz/material viscoelastic, g 0.1, dt 2e-7: eps 0.86088418 in 2d and 3d alike); a
    fix_modify of what a fix reports. A fix_modify of anything else is still named."""
    text = HEAD.replace("units si", "units si\ndimension 2").replace("region box block -1 1 -1 1 -1 1",
                                                                     "region box block -1 1 -1 1 -0.1 0.1")
    text = text.replace("comm_modify vel yes", "comm_modify vel yes\nboundary f f p")
    text += f"pair_coeff * * hooke 1000 1 {T}\nfix 1 all nve/sphere\nfix 2 all enforce2d\n"
    text += "fix w all gravity 9.81 vector 0 -1 0\n"
    status, out, err = deck(tmp_path, text + "fix_modify w energy yes virial no\nrun 1\n")
    assert status == 0 and "not understood" not in err, err
    p = {tuple(r["types"]): r for r in json.loads(out)["pairs"]}
    assert p[(1, 1)]["eps"][2] == pytest.approx(eps_hooke(1000, 1.0), rel=1e-10)
    status, out, err = deck(tmp_path, text + "fix_modify w respa 1\nrun 1\n")
    assert status == 0 and "line 18 not understood: fix_modify w respa 1" in err, err


def test_without_user_namespaces_a_file_named_by_a_variable_is_not_run(tmp_path, monkeypatch):
    """Where the engine cannot be confined to the scratch directory, such an include is refused."""
    import restitution.dem.deck as deck_module
    import restitution.dem.dialect.child as child
    monkeypatch.setattr(deck_module, "confining", lambda: False)
    monkeypatch.setattr(child, "confining", lambda: False)
    target = tmp_path / "TOUCHED"
    (tmp_path / "part.in").write_text(f"shell touch {target}\npair_coeff * * hooke 2000 1 {T}\n")
    from restitution.dem.deck import DeckError, engine_read
    path = _write(tmp_path, HEAD + "variable f string part.in\ninclude ${f}\nrun 1\n")
    with pytest.raises(DeckError, match="named by a variable"):
        engine_read(path)
    assert not target.exists()


def test_a_pair_table_written_by_the_deck_is_not_written(tmp_path):
    target = tmp_path / "table.out"
    status, out, err = deck(tmp_path, HEAD + f"pair_coeff * * hooke 1000 1 {T}\n"
                           f"pair_write 1 1 10 r 0.001 0.02 {target} K\nrun 1\n")
    assert not target.exists()
    assert "Traceback" not in err


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
    res = audit_deck(text, [1.0], path=path, budget=20.0, run_budget=5.0)
    # the loop reads ke, which the runs change: LAMMPS makes them, within their own budget, and the
    # loop (the spheres never stop) does not end there either
    assert time.monotonic() - start < 40.0 + 5.0
    assert any("had not ended the deck" in note and "same contact settings" in note for note in res["notes"])
    assert any("ran out of the audit's --run-budget 5 s" in note for note in res["notes"]), res["notes"]
    assert res["pairs"][0]["eps"][0] == pytest.approx(eps_hooke(1000, 1.0), rel=1e-10)


def test_a_deck_that_jumps_to_another_file_is_read_where_it_ends(tmp_path):
    # the end's atoms were written by an include appended to the deck's own file, which a jump to
    # another file never reaches: its particles were then reported as absent, exit status 0
    rest = f"pair_coeff * * hooke 1000 1 {T}\n"
    p = pairs(tmp_path, HEAD + "jump rest.in\n", files={"rest.in": rest})
    assert p[(1, 1)]["eps"][2] == pytest.approx(eps_hooke(1000, 1.0), rel=1e-10)


def test_particles_never_shown_by_the_engine_are_not_reported_absent(tmp_path):
    # no run and no end reached (a loop without a run, stopped by the budget): the atoms LAMMPS
    # holds are unknown, and "type 1 has no particle" with no pair would be a guess
    text = HEAD + f"pair_coeff * * hooke 1000 1 {T}\nlabel l\njump SELF l\n"
    from restitution.dem.deck import audit_deck
    from restitution.dem.dialect.state import DeckError
    # either part of the budget may run out first: a loop without a run echoes megabytes a second,
    # and a loaded machine reaches the echo cap before the 5 s
    with pytest.raises(DeckError, match=r"had not reached a run or the deck's end within the audit's budget "
                                         r"\((5 s of wall time|16 MB of echo)"):
        audit_deck(text, [1.0], path=_write(tmp_path, text), budget=5.0)


def test_a_loop_without_a_run_is_refused_at_the_echo_cap_in_little_memory(tmp_path, monkeypatch):
    # a 3-line loop with no run echoes megabytes a second: the audit once read 2 GB of it after
    # the engine's 60 s; now the engine is stopped where its echo reaches the cap, which the
    # refusal names, and the echo is never read whole
    from restitution.dem.dialect import child
    monkeypatch.setattr(child, "MAX_ECHO", 2 ** 16)
    monkeypatch.setattr(child, "ECHO_PER_SECOND", 0)      # the cap itself, whatever the budget
    text = HEAD + f"pair_coeff * * hooke 1000 1 {T}\nlabel l\nvariable i equal 1\njump SELF l\nrun 10\n"
    from restitution.dem.deck import audit_deck
    from restitution.dem.dialect.state import DeckError
    import time
    start = time.monotonic()
    with pytest.raises(DeckError, match=r"within the audit's budget \(0.0625 MB of echo"):
        audit_deck(text, [1.0], path=_write(tmp_path, text), budget=60.0)
    assert time.monotonic() - start < 30.0


def _engine_pass(tmp_path, text: str):
    """(EngineRun, commands) of the audit's LAMMPS pass through the deck."""
    from restitution.dem.deck import _engine_pass as engine_pass
    from restitution.dem.deck.scratch import scratch_copy
    from restitution.dem.engines.lammps import deck_run
    (tmp_path / "deck").mkdir()
    path = _write(tmp_path / "deck", text)
    root = tmp_path / "scratch"
    root.mkdir()
    scratch = scratch_copy(path, root, deck_run.marker(root))
    return engine_pass(deck_run, scratch, 60.0, path.parent)


def test_a_loop_of_runs_that_change_nothing_is_set_up_once(tmp_path):
    # a real pour deck repeats 10 000 times: define pours with a new seed, run; LAMMPS set up each
    # run (milliseconds each: 60 times its own pass). A run met again where nothing in between
    # changes what it checks or sees is not set up again, and its atoms are those of the last one
    text = HEAD + f"""pair_coeff * * hooke 1000 1 {T}
region top block -0.5 0.5 -0.5 0.5 0.5 0.9
fix g all gravity 1.0 vector 0 0 -1
variable n loop 300
label l
variable seed equal $n+1000
fix drop all pour 1 2 ${{seed}} region top diam one 0.04 dens 2500 2500
run 10
next n
jump SELF l
"""
    done, commands = _engine_pass(tmp_path, text)
    runs = [c for c in commands if c.stage is not None]
    assert len(runs) == 300
    assert done.echo.count("Setting up Verlet run") == 1
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    # every run sees the atoms LAMMPS holds (the pour inserts nothing while runs are skipped): one stage
    stages = json.loads(out)["stages"]
    assert len(stages) == 1 and len(stages[0]["runs"]) == 300
    p = {tuple(r["types"]): r for r in stages[0]["pairs"]}
    assert p[(1, 1)]["eps"][2] == pytest.approx(eps_hooke(1000, 1.0), rel=1e-10)
    # type 2's one created sphere (radius 0.01) meets the poured ones (0.02) only: its largest eps
    assert p[(2, 2)]["at"] == [[0.01, 2500.0], [0.02, 2500.0]]
    assert p[(2, 2)]["eps"][2] == pytest.approx(eps_hooke(1000, 1.0, 0.01, 0.02), rel=1e-10)


@pytest.mark.parametrize("change, stages", [
    ("pair_coeff * * hooke ${k}000 1 " + T, 3), ("set type 1*3 diameter 0.0${k}", 3),
    # a pour of other sizes into a type that holds atoms: its spheres join them and stay (the
    # second pass pours the size of type 2's one sphere, which then meets another of its size: a
    # stage of its own)
    ("fix drop all pour 1 2 ${k}123 region top diam one 0.0${k} dens 2500 2500", 3)])
def test_a_loop_that_changes_the_contact_sees_each_change(tmp_path, change, stages):
    # a marker met again skips LAMMPS' set-up and its dump only where nothing changed in between:
    # here each pass of the loop changes the contact, the sizes or a pour, each run checked
    text = HEAD + f"""pair_coeff * * hooke 1000 1 {T}
region top block -0.5 0.5 -0.5 0.5 0.5 0.9
fix g all gravity 1.0 vector 0 0 -1
variable k loop 3
label l
{change}
run 10
next k
jump SELF l
"""
    _, commands = _engine_pass(tmp_path, text)
    assert sum(c.stage is not None and c.snapshot is not False for c in commands) == 3
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    assert len(json.loads(out)["stages"]) == stages


def test_a_variable_a_fix_reads_is_checked_at_each_run(tmp_path):
    # LAMMPS checks a fix's variable when it sets a run up: deleted in a loop, the second run stops
    text = HEAD + f"""pair_coeff * * hooke 1000 1 {T}
variable f equal 0
fix push all addforce v_f 0 0
variable n loop 3
label l
run 10
variable f delete
next n
jump SELF l
"""
    err = refused(tmp_path, text)
    assert "LAMMPS stops here" in err and "addforce" in err


@pytest.mark.parametrize("ending", ["quit\n", 'if "1 > 0" then quit\n', 'if "1 > 0" then "quit"\n'])
def test_a_quit_is_where_the_deck_ends(tmp_path, ending):
    # LAMMPS ends the process at a quit: the atoms it holds there are written before it (the
    # deck was refused, its particles never shown); the lines after it never run
    text = HEAD + f"pair_coeff * * hooke 1000 1 {T}\n" + ending + f"pair_coeff * * hooke 4000 1 {T}\n"
    p = pairs(tmp_path, text)
    assert p[(1, 1)]["eps"][2] == pytest.approx(eps_hooke(1000, 1.0), rel=1e-10)


def test_a_type_without_particles_is_not_asked_for_a_radius(tmp_path):
    # type 3 never created (in LAMMPS an unused type; in LIGGGHTS, often the walls'): its pairs
    # cannot happen and are not listed, no radius is asked for it, and the others are answered
    text = HEAD.replace("create_atoms 3 single -0.5 0 0\n", "") + f"pair_coeff * * hooke 1000 1 {T}\nrun 1\n"
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    rows = json.loads(out)["pairs"]
    assert [p["types"] for p in rows] == [[1, 1], [1, 2], [2, 2]]
    assert all(p["eps"][2] == pytest.approx(eps_hooke(1000, 1.0), rel=1e-10) for p in rows)
    assert "type 3 has no particle" in err and "--radius" not in err


def test_a_drag_beside_the_contact_is_named(tmp_path):
    text = HEAD + f"pair_coeff * * hooke 1000 1 {T}\nfix drag all viscous 0.01\nrun 1\n"
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    assert "fix viscous (drag): a drag force" in err and "changes the eps the engine measures: " in err


def test_a_time_step_the_same_at_every_speed_is_said_once(tmp_path):
    """A linear spring and dashpot: the contact time and eps do not depend on g, and the sentence
    was repeated once per speed."""
    text = HEAD + f"pair_coeff * * hooke 1000 0.5 damping velocity {T}\ntimestep 1e-3\nrun 1\n"
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    p = next(p for p in json.loads(out)["pairs"] if p["types"] == [1, 1])
    assert len({f"{n:.6g}" for n in p["steps_per_contact"]}) == 1 and len(p["speeds"]) > 1
    line = next(ln for ln in err.splitlines() if ln.startswith("restitution deck: types 1 1:"))
    assert line.count("steps") == 1 and "at every speed given" in line, err


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
    from restitution.dem.engines.lammps import deck_run
    monkeypatch.setattr(deck_run.importlib.util, "find_spec", lambda name: None)
    err = refused(tmp_path, HEAD + f"pair_coeff * * hooke 1000 1 {T}\nrun 1\n")
    assert "pip install 'restitution[dem]'" in err


# ------------------------------------------------------------------ item 4: several sizes, hybrid styles
from restitution.dem.contact import Contact  # noqa: E402


def _in_lammps(row: dict, pair: Pair, lines: str, style: str = "granular", types=(1, 1), ntypes=1,
               g: float = 1.0) -> float:
    """The row's law run head-on in LAMMPS at g, extrapolated to dt = 0 from 4000 steps per contact."""
    t_c = Contact(row["alpha"], row["gamma"], row["D1"], row["D2"], row["end"]).contact_time(g)
    return lammps_run.lammps_eps_extrapolated(pair, lines, g, t_c, types=types, ntypes=ntypes, style=style)[0]


SIZES = BOX + f"""create_box 1 box
create_atoms 1 single 0 0 0
create_atoms 1 single 0.5 0 0
create_atoms 1 single 0 0.5 0
create_atoms 1 single 0.5 0.5 0
set type 1 diameter 0.02 density 2500
set atom 2 diameter 0.04 density 2500
set atom 4 diameter 0.04 density 2500
pair_style granular
pair_coeff * * hooke 1000 50 {T}
fix integrate all nve/sphere
run 1
"""


@pytest.mark.dem
def test_a_type_of_two_sizes_gives_the_eps_range_with_the_sizes_at_its_ends(tmp_path):
    # hooke with viscoelastic damping: eps depends on size; the smallest eps at the two large
    # spheres, the largest at the two small ones (each checked in LAMMPS, extrapolated to dt = 0)
    status, out, err = deck(tmp_path, SIZES)
    assert status == 0, err
    rows = json.loads(out)["pairs"]
    assert [(r["types"], r["sizes"], r["at"]) for r in rows] == [
        ([1, 1], "smallest eps", [[0.02, 2500.0], [0.02, 2500.0]]),
        ([1, 1], "largest eps", [[0.01, 2500.0], [0.01, 2500.0]])]
    for r, radius in zip(rows, (0.02, 0.01)):
        assert r["eps"][2] == pytest.approx(eps_hooke(1000, 50, radius, radius), rel=1e-10)
        assert r["exact_line"] is None
        got = _in_lammps(r, Pair.spheres(radius, radius, 2500.0, 2500.0), f"pair_coeff * * hooke 1000 50 {T}")
        assert abs(got / r["eps"][2] - 1) < 1e-6, (radius, got, r["eps"][2])
    assert rows[0]["eps"][2] < rows[1]["eps"][2] - 1e-3
    status, text, _ = run_cli(["deck", str(tmp_path / "in.deck"), "--g", "1.0"])
    assert "types 1 1 (smallest eps over the sizes present, at radius 0.02 density 2500 and radius 0.02" in text


@pytest.mark.dem
def test_a_law_whose_eps_does_not_depend_on_size_gives_one_value(tmp_path):
    # tsuji with hertz: eps depends on e alone; one row, the sizes' eps within 1e-9 (LAMMPS, the
    # mixed pair of a small and a large sphere)
    line = f"pair_coeff * * hertz/material 1e7 0.5 0.3 damping tsuji {T}"
    status, out, err = deck(tmp_path, SIZES.replace(f"pair_coeff * * hooke 1000 50 {T}", line))
    assert status == 0, err
    (row,) = json.loads(out)["pairs"]
    assert row["sizes"] == "any" and row["exact_line"]
    got = _in_lammps(row, Pair.spheres(0.01, 0.02, 2500.0, 2500.0), line)
    assert abs(got / row["eps"][2] - 1) < 1e-6, (got, row["eps"][2])
    # one sentence, not a list of spheres that "gives the same"
    status, text, _ = run_cli(["deck", str(tmp_path / "in.deck"), "--g", "1.0"])
    assert ("types 1 1 (spheres of several sizes: this law's eps does not depend on size, so this row holds for "
            "every size): LAMMPS hertz/material") in text, text


POUR_RANGE = f"""units si
atom_style sphere
comm_modify vel yes
region box block -0.1 0.1 -0.1 0.1 0 0.2
create_box 1 box
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
region feed block -0.05 0.05 -0.05 0.05 0.1 0.15
fix grav all gravity 9.81 vector 0 0 -1
fix ins all pour 100 1 4242 region feed diam range 0.01 0.02 dens 2500 2500
"""


@pytest.mark.dem
def test_a_pour_of_a_diameter_range_gives_the_eps_range(tmp_path):
    # the linear dashpot of gran/hooke/history: eps falls as the mass grows; its ends at the
    # range's ends (the hand reader asked for a radius), each checked in LAMMPS
    status, out, err = deck(tmp_path, POUR_RANGE)
    assert status == 0, err
    rows = json.loads(out)["pairs"]
    assert [(r["sizes"], r["at"]) for r in rows] == [("smallest eps", [[0.01, 2500.0], [0.01, 2500.0]]),
                                                     ("largest eps", [[0.005, 2500.0], [0.005, 2500.0]])]
    style = "gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0"
    for r, radius in zip(rows, (0.01, 0.005)):
        got = _in_lammps(r, Pair.spheres(radius, radius, 2500.0, 2500.0), "pair_coeff * *", style=style)
        assert abs(got / r["eps"][2] - 1) < 1e-6, (radius, got, r["eps"][2])


HYBRID = HEAD + """pair_style {hybrid} gran/hooke 2000.0 NULL 50.0 NULL 0.5 0 lj/cut 0.05
pair_coeff * * gran/hooke
pair_coeff {other} lj/cut 1e-9 0.01
run 1
"""


@pytest.mark.dem
@pytest.mark.parametrize("hybrid, other, named", [
    ("hybrid", "3 3", "pair_coeff gives them sub-style lj/cut, not gran/hooke: no granular contact"),
    ("hybrid/overlay", "1 2", "sub-style lj/cut adds its force to gran/hooke's (hybrid/overlay)")])
def test_hybrid_pair_styles_audit_the_granular_sub_style_where_it_alone_acts(tmp_path, hybrid, other, named):
    text = HYBRID.format(hybrid=hybrid, other=other)
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    res = json.loads(out)
    gone = tuple(int(t) for t in other.split())
    assert [tuple(p["types"]) for p in res["pairs"]] == [t for t in [(1, 1), (1, 2), (1, 3), (2, 2), (2, 3), (3, 3)]
                                                         if t != gone]
    assert [named in row["why"] and row["why"].endswith("not audited") for row in res["unknown_lines"]] == [True]
    # the granular sub-style's pair in LAMMPS, under the deck's own hybrid style
    p = res["pairs"][0]
    style = f"{hybrid} gran/hooke 2000.0 NULL 50.0 NULL 0.5 0 lj/cut 0.05"
    got = _in_lammps(p, Pair.spheres(0.01, 0.01, 2500.0, 2500.0),
                     f"pair_coeff * * gran/hooke\npair_coeff {other} lj/cut 1e-9 0.01", style=style, ntypes=3)
    assert abs(got / p["eps"][2] - 1) < 1e-6, (got, p["eps"][2])


@pytest.mark.dem
@pytest.mark.parametrize("other, audited", [("zero", True), ("soft 0.0", True), ("lj/cut 0 0.01", True),
                                            ("soft 1e-9", False), ("lj/cut 1e-9 0.01", False)])
def test_an_overlaid_sub_style_that_carries_no_force_leaves_the_pair_audited(tmp_path, other, audited):
    # pair_style hybrid/overlay: a sub-style whose coefficients give it no force (zero; soft or
    # lj/cut with a prefactor 0) adds nothing to the granular contact; any other is named, and so is
    # a fix adapt that changes the idle sub-style's prefactor as the run goes
    name = other.split()[0]
    style = f"hybrid/overlay gran/hooke 2000.0 NULL 50.0 NULL 0.5 0 {name} 0.05"
    text = HEAD + f"pair_style {style}\npair_coeff * * gran/hooke\npair_coeff 1 2 {other}\nrun 1\n"
    status, out, err = deck(tmp_path, text)
    assert status == 0, err
    res = json.loads(out)
    assert ((1, 2) in [tuple(p["types"]) for p in res["pairs"]]) == audited, err
    if audited:
        # LAMMPS under the deck's own hybrid/overlay lines gives the granular sub-style's eps
        (p,) = [p for p in res["pairs"] if p["types"] == [1, 2]]
        got = _in_lammps(p, Pair.spheres(0.01, 0.01, 2500.0, 2500.0),
                         f"pair_coeff * * gran/hooke\npair_coeff 1 2 {other}", style=style, types=(1, 2), ntypes=3)
        assert abs(got / p["eps"][2] - 1) < 1e-6, (got, p["eps"][2])
    if audited and name == "soft":
        adapted = text.replace("run 1", "variable a equal ramp(0,1)\nfix ad all adapt 1 pair soft a 1 2 v_a\nrun 1")
        status, out, err = deck(tmp_path, adapted)
        assert status == 0, err
        assert (1, 2) not in [tuple(p["types"]) for p in json.loads(out)["pairs"]]
        assert "adapt" in err


def test_an_engine_killed_without_an_error_says_so_not_its_last_cut_line(tmp_path, monkeypatch):
    """LAMMPS ended by a signal mid-echo (its screen cut mid-word, no ERROR): the refusal names how
    it ended, not the echo's last fragment (it had said "LAMMPS stops here: va")."""
    from restitution.dem.engines.lammps import deck_run
    real = deck_run.run_child

    def killed(*args, **kwargs):
        done = real(*args, **kwargs)
        done.echo, done.atoms, done.at_end = done.echo[:done.echo.index("pair_coeff") + 2], "", ""
        done.status, done.error = -9, ""
        return done
    monkeypatch.setattr(deck_run, "run_child", killed)
    err = refused(tmp_path, HEAD + f"pair_coeff * * hooke 1000 1 {T}\nrun 1\n")
    assert "LAMMPS stops here: it ended without an error message (killed by signal 9)" in err, err


@pytest.mark.parametrize("bare", ["jump", "include"])
def test_a_bare_jump_or_include_is_lammps_own_refusal(tmp_path, bare):
    """make fuzz (seed 53): a mutation left `jump` without its file; LAMMPS stops on it, and the
    audit's check of where the file lies read a name that is not there (a traceback)."""
    status, out, err = deck(tmp_path, HEAD + f"pair_coeff * * hooke 1000 1 {T}\n{bare}\nrun 1\n")
    assert status == 2 and out == "" and err.count("\n") == 1 and "Traceback" not in err, err
    assert f"({bare}): LAMMPS stops here" in err, err


@pytest.mark.parametrize("lines, refused", [
    ("region low block -1 1 -1 1 -1 0\nset region low diameter 0.03", True),
    ("region low block -1 1 -1 1 -1 0\ngroup fallen region low\nset group fallen density 3000", True),
    ("variable d atom 0.02+0.01*(z<0)\nset type 1 diameter v_d", True),
    ("region low block -1 1 -1 1 -1 0\ndelete_atoms region low", True),
    ("region low block -1 1 -1 1 -1 0\nset region low vx 0.0", False),
    ("group one type 1\nset group one diameter 0.03", False),
], ids=["set region", "group region", "atom variable", "delete region", "sizeless", "group by type"])
def test_a_set_by_where_the_atoms_are_after_a_run_is_refused(tmp_path, lines, refused):
    """Field test r11 (D1): after spheres fell, ``set region low diameter 0.02`` resized those the
    run left in the region; the audit's pass, its runs skipped, resized those at the start (0.96186
    printed where LAMMPS gives 0.94036, exit 0). Such a set (a region, a group picked by region
    after a run, an atom-style variable, delete_atoms by region) after a run is refused in one
    line where the runs are not made (--run-budget 0; made, the engine's state is audited:
    test_dem_deck_made_runs.py); before any run, or on sizeless keywords, or by type, it is the
    engine's own."""
    text = HEAD + f"pair_coeff * * hooke 1000 1 {T}\nrun 10\n{lines}\nrun 10\n"
    status, out, err = deck(tmp_path, text, "--run-budget", 0)
    if refused:
        assert status == 2 and out == "" and err.count("\n") == 1 and "where the run left them" in err, err
    else:
        assert status == 0, err
    status, out, err = deck(tmp_path, text)
    assert status == 0 and ("for real" in err) == refused, err
    before = HEAD + f"pair_coeff * * hooke 1000 1 {T}\n{lines}\nrun 10\n"
    status, _, err = deck(tmp_path, before)
    assert status == 0 or "where the run left them" not in err, err


def test_read_data_with_a_fixs_own_section_is_audited(tmp_path):
    """Field test r11 (a38): ``read_data FILE fix ID NULL Section`` (a fix property/atom reads its own
    section of the file) was refused as if it shifted types; LAMMPS runs it, and the section holds
    per-atom values of the fix's, no size."""
    text = BOX.replace("region box block -1 1 -1 1 -1 1\n", "") + f"""fix prop all property/atom d_charge2
read_data data.one fix prop NULL Charge2
fix integrate all nve/sphere
pair_style granular
pair_coeff * * hooke 1000 1 {T}
run 1
"""
    data = DATA_ONE_TYPE + "\nCharge2\n\n1 0.5\n"
    p = pairs(tmp_path, text, files={"data.one": data})
    assert p[(1, 1)]["eps"][2] == pytest.approx(eps_hooke(1000, 1.0, 0.01, 0.01, 2500.0, 2500.0), rel=1e-10)


@pytest.mark.parametrize("fix, words", [
    ("fix ev all evaporate 1000 1 box 12345", "fix evaporate deletes atoms as the runs go; it adds no force"),
    # remap v: the atoms stay where they are (remap x, the default, moves them with the box: field round 40)
    ("fix df all deform 1 x final 0 2 remap v", "fix deform changes the box as the runs go; it adds no force"),
])
def test_a_fix_that_pushes_no_atom_is_not_said_to_add_forces(tmp_path, fix, words):
    """Field round 15 (n06-n08, a10): evaporate, deform, atom/swap and set were each said to "add
    forces" their eps did not include; none pushes an atom."""
    status, out, err = deck(tmp_path, HEAD + f"pair_coeff * * hooke 1000 1 {T}\n{fix}\nrun 1\n")
    assert status == 0, err
    assert words in err and "may add forces" not in err, err


@pytest.mark.parametrize("where, stops", [("before", False), ("after", True)])
def test_processors_after_the_box_stops_as_the_engine_does(tmp_path, where, stops):
    """processors is never run in the pass (the audit's engine has one process); after the box
    LAMMPS and LIGGGHTS stop on it ("Processors command after simulation box is defined", both
    measured), where the audit printed the rows with exit 0 (field round 46, lists)."""
    body = HEAD + f"pair_coeff * * hooke 1000 1 {T}\n"
    text = "processors * * *\n" + body + "run 1\n" if where == "before" else body + "processors * * *\nrun 1\n"
    status, out, err = deck(tmp_path, text)
    assert (status, "LAMMPS stops here: Processors command after simulation box is defined" in err) == \
        ((2, True) if stops else (0, False)), err


@pytest.mark.parametrize("command", ["fix st all store/state 0 x", "reset_atoms id", "min_modify dmax 0.1",
                                     "unfix integrate\nfix integrate all nve/sphere/omp"])
def test_commands_that_push_nothing_are_not_said_to(tmp_path, command):
    """Field round 46, lists: each was said "not understood" (the fixes "may add forces"); LAMMPS
    measured the eps of the deck without them (0.413436 where the deck's own is 0.413436)."""
    status, out, err = deck(tmp_path, HEAD + f"pair_coeff * * hooke 1000 1 {T}\n{command}\nrun 1\n")
    assert status == 0 and "not understood" not in err, err

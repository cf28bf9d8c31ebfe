"""``pair_style hybrid`` of two granular sub-styles, an older gran/* style and granular, each pair
mapped to one of them by its pair_coeff line (field test: refused as "maps one granular sub-style",
though LAMMPS runs it). Each pair is audited with its own sub-style and checked in LAMMPS under the
deck's own hybrid lines, head-on, dt -> 0. A pair no line names mixes only from two like pairs of one
sub-style (else LAMMPS stops); a pair both sub-styles cover (hybrid/overlay) stays refused."""

import json
import subprocess
import sys

import pytest

from deck_cli import needs_lammps, run
from restitution.dem.contact import Contact
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.engines.lammps.run import richardson
from restitution.dem.pair import Pair

SIZES = {1: (0.005, 2500.0), 2: (0.01, 1000.0)}
STYLE = "gran/hooke 2e4 NULL 300 NULL 0.5 0 granular"
LINES = """pair_coeff 1 1 gran/hooke
pair_coeff 1 2 granular hooke 1e4 0.3 tangential linear_nohistory 1 0.3 damping mass_velocity
pair_coeff 2 2 granular hertz 1e6 0.2 tangential linear_nohistory 1 0.3 damping tsuji
"""


def _deck(tmp_path, hybrid: str, lines: str, styles: str = STYLE):
    (tmp_path / "in.deck").write_text(f"""units si
atom_style sphere
comm_modify vel yes
region box block 0 1 0 1 0 1
create_box 2 box
create_atoms 1 single 0.3 0.5 0.5
create_atoms 2 single 0.6 0.5 0.5
set type 1 diameter 0.01 density 2500
set type 2 diameter 0.02 density 1000
pair_style {hybrid} {styles}
{lines}fix 1 all nve/sphere
timestep 1e-6
run 10
""")
    return run(tmp_path / "in.deck", "--g", "0.5", "--json")


@needs_lammps
@pytest.mark.dem
def test_each_pair_takes_the_granular_sub_style_its_pair_coeff_names(tmp_path):
    """Before: refused. gran/hooke on 1 1, granular hooke on 1 2 and hertz/tsuji on 2 2."""
    status, out, err = _deck(tmp_path, "hybrid", LINES)
    assert status == 0, err
    rows = json.loads(out)["pairs"]
    assert [(r["types"], r["model"]) for r in rows] == [
        ([1, 1], "LAMMPS gran/hooke"), ([1, 2], "LAMMPS hooke, damping mass_velocity"),
        ([2, 2], "LAMMPS hertz, damping tsuji")]
    for r in rows:
        (i, j), g = r["types"], r["speeds"][2]
        t_c = Contact(r["alpha"], r["gamma"], r["D1"], r["D2"], r["end"]).contact_time(g)
        pair = Pair.spheres(SIZES[i][0], SIZES[j][0], SIZES[i][1], SIZES[j][1])
        engine = lammps_run.lammps_eps_extrapolated(pair, LINES, g, t_c, types=(i, j), ntypes=2, steps=16000,
                                                    style=f"hybrid {STYLE}")[0]
        print(r["types"], r["eps"][2], engine)
        assert abs(engine / r["eps"][2] - 1) < 1e-6


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("hybrid, lines, named", [
    ("hybrid/overlay", LINES.replace("1 1 gran/hooke", "* * gran/hooke"),
     "sub-styles gran/hooke and granular both act on this pair"),
    ("hybrid", LINES.replace("pair_coeff 1 2 granular hooke", "#"), "LAMMPS stops")])
def test_a_pair_of_both_or_neither_sub_style_is_refused(tmp_path, hybrid, lines, named):
    status, out, err = _deck(tmp_path, hybrid, lines)
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and named in err, err


#: two instances of granular, numbered in their pair_coeff lines as LAMMPS requires
TWO = "granular granular"
TWO_LINES = """pair_coeff 1 1 granular 1 hertz/material 1e8 0.5 0.3 damping coeff_restitution tangential linear_nohistory 0 0
pair_coeff 1 2 granular 2 hooke 1e4 0.3 tangential linear_nohistory 1 0.3 damping mass_velocity
pair_coeff 2 2 granular 2 hertz 1e6 0.2 tangential linear_nohistory 1 0.3 damping tsuji
"""


def _engine_in_child(g: float, t_c: float, types: tuple, steps: int = 16000) -> float:
    """LAMMPS' eps under the hybrid lines, dt -> 0 as lammps_eps_extrapolated takes it, each run in
    a child process: LAMMPS aborts the process that closes an instance of two granular sub-styles
    (its teardown deletes one fix twice), after the run."""
    def one(dt: float) -> float:
        # the instance is not closed (its close aborts): the child ends without a teardown
        code = ("import os\nfrom restitution.dem.engines.lammps import run\nfrom restitution.dem.pair import Pair\n"
                "run._load().lammps.close = lambda self: None\n"
                f"pair = Pair.spheres({SIZES[types[0]][0]!r}, {SIZES[types[1]][0]!r}, {SIZES[types[0]][1]!r}, "
                f"{SIZES[types[1]][1]!r})\n"
                f"eps = run.lammps_eps(pair, {TWO_LINES!r}, {g!r}, {dt!r}, {1.5 * t_c!r}, {types!r}, 2, "
                f"'hybrid {TWO}')\n"
                "print(repr(eps), flush=True)\nos._exit(0)\n")
        done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, done.stderr[-2000:]
        return float(done.stdout.split()[-1])
    return richardson(*(one(t_c / steps / k) for k in (1, 2, 4)), 1)


def _two(tmp_path, hybrid: str, lines: str):
    return _deck(tmp_path, hybrid, lines, TWO)


@needs_lammps
@pytest.mark.dem
def test_each_pair_takes_the_granular_instance_its_pair_coeff_names(tmp_path):
    """Field round 8: hybrid granular granular was refused, LAMMPS' abort at its own teardown (it
    deletes a fix twice, after the deck has run) read as the deck stopping at its run. Each pair takes
    its instance's law, checked in LAMMPS under the deck's hybrid lines, head-on, dt -> 0; the exact
    line names the instance."""
    status, out, err = _two(tmp_path, "hybrid", TWO_LINES)
    assert status == 0, err
    rows = json.loads(out)["pairs"]
    assert [(r["types"], r["model"]) for r in rows] == [
        ([1, 1], "LAMMPS hertz/material, damping coeff_restitution"), ([1, 2], "LAMMPS hooke, damping mass_velocity"),
        ([2, 2], "LAMMPS hertz, damping tsuji")]
    assert rows[0]["exact_line"].startswith("pair_coeff 1 1 granular 1 hertz/material")
    for r in rows:
        (i, j), g = r["types"], r["speeds"][2]
        t_c = Contact(r["alpha"], r["gamma"], r["D1"], r["D2"], r["end"]).contact_time(g)
        engine = _engine_in_child(g, t_c, (i, j))
        print(r["types"], r["eps"][2], engine)
        assert abs(engine / r["eps"][2] - 1) < 1e-6


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("hybrid, lines, named", [
    ("hybrid/overlay", TWO_LINES.replace("1 1 granular 1", "* * granular 1"),
     "sub-styles granular 1 and granular 2 both act on this pair"),
    ("hybrid", TWO_LINES.replace("pair_coeff 1 2 granular 2 hooke", "#"), "LAMMPS stops")])
def test_a_pair_of_two_instances_or_of_none_is_refused(tmp_path, hybrid, lines, named):
    status, out, err = _two(tmp_path, hybrid, lines)
    assert status == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and named in err, err

"""``pair_style hybrid`` of two granular sub-styles, an older gran/* style and granular, each pair
mapped to one of them by its pair_coeff line (field test: refused as "maps one granular sub-style",
though LAMMPS runs it). Each pair is audited with its own sub-style and checked in LAMMPS under the
deck's own hybrid lines, head-on, dt -> 0. A pair no line names mixes only from two like pairs of one
sub-style (else LAMMPS stops); a pair both sub-styles cover (hybrid/overlay) stays refused."""

import json

import pytest

from deck_cli import needs_lammps, run
from restitution.dem.contact import Contact
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.pair import Pair

SIZES = {1: (0.005, 2500.0), 2: (0.01, 1000.0)}
STYLE = "gran/hooke 2e4 NULL 300 NULL 0.5 0 granular"
LINES = """pair_coeff 1 1 gran/hooke
pair_coeff 1 2 granular hooke 1e4 0.3 tangential linear_nohistory 1 0.3 damping mass_velocity
pair_coeff 2 2 granular hertz 1e6 0.2 tangential linear_nohistory 1 0.3 damping tsuji
"""


def _deck(tmp_path, hybrid: str, lines: str):
    (tmp_path / "in.deck").write_text(f"""units si
atom_style sphere
comm_modify vel yes
region box block 0 1 0 1 0 1
create_box 2 box
create_atoms 1 single 0.3 0.5 0.5
create_atoms 2 single 0.6 0.5 0.5
set type 1 diameter 0.01 density 2500
set type 2 diameter 0.02 density 1000
pair_style {hybrid} {STYLE}
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

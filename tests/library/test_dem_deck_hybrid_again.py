"""``pair_style hybrid`` issued again, and a non-granular sub-style's pair_coeff over type ranges.

Measured in LAMMPS 22 Jul 2025: every ``pair_style`` command that is, or replaces, a hybrid style
drops every coefficient (hybrid then the same hybrid, hybrid then granular, granular then hybrid:
the next run stops on "All pair coeffs are not set"), where ``pair_style granular`` issued again
keeps them. The reader kept them (its style compared by the granular sub-styles' names alone), so a
pair LAMMPS mixes from the new like pairs was audited with the old line's coefficients. And a
pair_coeff of another sub-style over type ranges sets the pairs of LAMMPS' own loop (i over the
first range, j from max(jlo, i) over the second), not every product of the two ranges."""

import json

import pytest

from deck_cli import needs_lammps, run
from restitution.dem.contact import Contact
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.pair import Pair

R, RHO = 0.005, 2500.0
TAIL = "damping mass_velocity tangential linear_nohistory 1 0.3"
HYBRID = "hybrid granular lj/cut 0.05"


def _deck(tmp_path, ntypes: int, lines: str, first: str = HYBRID):
    (tmp_path / "in.deck").write_text(f"""units si
atom_style sphere
comm_modify vel yes
region box block 0 1 0 1 0 1
create_box {ntypes} box
""" + "".join(f"create_atoms {t} single {0.1 + 0.2 * t} 0.5 0.5\n" for t in range(1, ntypes + 1)) + f"""
set type * diameter {2 * R} density {RHO}
pair_style {first}
{lines}fix 1 all nve/sphere
timestep 1e-6
run 10
""")
    return run(tmp_path / "in.deck", "--g", "0.5", "--json")


AGAIN = f"""pair_coeff * * granular hooke 1e4 100 {TAIL}
pair_style {HYBRID}
pair_coeff 1 1 granular hooke 2e4 500 {TAIL}
pair_coeff 2 2 granular hooke 3e4 1000 {TAIL}
pair_coeff * 3 lj/cut 0 0.01
"""
#: granular after a hybrid style: the same, of two types
TO_GRANULAR = f"""pair_coeff * * granular hooke 1e4 100 {TAIL}
pair_style granular
pair_coeff 1 1 hooke 2e4 500 {TAIL}
pair_coeff 2 2 hooke 3e4 1000 {TAIL}
"""


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("ntypes, lines", [(3, AGAIN), (2, TO_GRANULAR)])
def test_a_style_after_a_hybrid_one_drops_the_earlier_coefficients(tmp_path, ntypes, lines):
    """Before: 1 2 audited with the first line's k 1e4, damping 100; LAMMPS mixes it from 1 1 and 2 2."""
    status, out, err = _deck(tmp_path, ntypes, lines)
    assert status == 0, err
    rows = {tuple(r["types"]): r for r in json.loads(out)["pairs"]}
    assert "mixed from line" in rows[(1, 2)]["model"], rows[(1, 2)]["model"]
    pair = Pair.spheres(R, R, RHO, RHO)
    for (i, j), r in rows.items():
        g = r["speeds"][2]
        t_c = Contact(r["alpha"], r["gamma"], r["D1"], r["D2"], r["end"]).contact_time(g)
        # the deck's own lines, the style issued twice, in LAMMPS
        engine = lammps_run.lammps_eps_extrapolated(pair, lines, g, t_c, types=(i, j), ntypes=ntypes, steps=4000,
                                                    style=HYBRID)
        print((i, j), r["eps"][2], engine)
        assert abs(engine[0] / r["eps"][2] - 1) < 1e-6
        assert all(abs(e / r["eps"][2] - 1) < 1e-3 for e in engine[1:])     # each time step itself


@needs_lammps
@pytest.mark.dem
def test_a_hybrid_style_after_granular_leaves_no_coefficient(tmp_path):
    """granular, then hybrid: LAMMPS stops at the run (no coefficient left); refused in its words."""
    lines = f"pair_coeff * * hooke 1e4 100 {TAIL}\npair_style {HYBRID}\npair_coeff * 3 lj/cut 0 0.01\n"
    status, out, err = _deck(tmp_path, 3, lines, first="granular")
    assert status == 2 and out == "", out
    assert len(err.strip().splitlines()) == 1 and "All pair coeffs are not set" in err, err


@needs_lammps
@pytest.mark.dem
def test_another_sub_style_over_type_ranges_takes_lammps_own_loop(tmp_path):
    """pair_coeff 2 1*3 lj/cut sets (2, 2) and (2, 3) in LAMMPS, not (1, 2): before, 1 2 was named as
    lj/cut's and not audited."""
    lines = f"pair_coeff * * granular hooke 1e4 100 {TAIL}\npair_coeff 2 1*3 lj/cut 0 0.01\n"
    status, out, err = _deck(tmp_path, 3, lines)
    assert status == 0, err
    got = json.loads(out)
    assert sorted(tuple(r["types"]) for r in got["pairs"]) == [(1, 1), (1, 2), (1, 3), (3, 3)]
    named = sorted(u["why"].split(":")[0] for u in got["unknown_lines"] if "lj/cut" in u["why"])
    assert named == ["types 2 2", "types 2 3"], got["unknown_lines"]
    pair = Pair.spheres(R, R, RHO, RHO)
    r = next(r for r in got["pairs"] if r["types"] == [1, 2])
    g = r["speeds"][2]
    t_c = Contact(r["alpha"], r["gamma"], r["D1"], r["D2"], r["end"]).contact_time(g)
    engine = lammps_run.lammps_eps_extrapolated(pair, lines, g, t_c, types=(1, 2), ntypes=3, style=HYBRID)
    assert abs(engine[0] / r["eps"][2] - 1) < 1e-6

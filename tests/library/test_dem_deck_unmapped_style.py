"""A pair style the reader does not map is refused where a run uses it, not where it is typed
(field test: a deck that set up a Lennard-Jones pair style, then replaced it by gran/hooke before
its only run, was refused at the lj/cut line though LAMMPS ran the granular law alone)."""

import json

import pytest

from deck_cli import needs_lammps, run
from restitution.dem.contact import Contact
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.pair import Pair

GRAN = "gran/hooke 3e4 2e4 200 100 0.0 1"
HEAD = """units si
atom_style sphere
comm_modify vel yes
region box block 0 1 0 1 0 1
create_box 1 box
create_atoms 1 single 0.5 0.5 0.5
set type 1 diameter 0.01 density 2500
fix 1 all nve/sphere
timestep 1e-6
"""


@needs_lammps
@pytest.mark.dem
def test_a_style_replaced_before_any_run_is_not_refused(tmp_path):
    (tmp_path / "in.deck").write_text(HEAD + f"pair_style lj/cut 1.0\npair_coeff * * 1 1\npair_style {GRAN}\n"
                                             "pair_coeff * *\nrun 10\n")
    status, out, err = run(tmp_path / "in.deck", "--g", "1.0", "--json")
    assert status == 0, err
    (row,) = json.loads(out)["pairs"]
    t_c = Contact(row["alpha"], row["gamma"], row["D1"], row["D2"], row["end"]).contact_time(1.0)
    engine = lammps_run.lammps_eps_extrapolated(Pair.spheres(0.005, 0.005, 2500.0), "pair_coeff * *", 1.0, t_c,
                                                style=GRAN)[0]
    print(row["eps"][2], engine)
    assert abs(engine / row["eps"][2] - 1) < 1e-6


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("tail", ["run 10\n", "", f"pair_style {GRAN}\npair_coeff * *\nrun 10\npair_style lj/cut 1.0\n"
                                                  "pair_coeff * * 1 1\nrun 10\n"])
def test_a_style_a_run_uses_is_refused_at_its_line(tmp_path, tail):
    (tmp_path / "in.deck").write_text(HEAD + "pair_style lj/cut 1.0\npair_coeff * * 1 1\n" + tail)
    status, out, err = run(tmp_path / "in.deck", "--g", "1.0")
    assert status == 2 and out == ""
    line = 10 if tail.count("lj/cut") == 0 else 15
    assert err.startswith(f"restitution: line {line} (pair_style lj/cut 1.0): pair_style lj/cut is not mapped"), err
    assert len(err.splitlines()) == 1

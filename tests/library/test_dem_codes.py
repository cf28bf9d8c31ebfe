"""Each engine's contact law and designer (restitution.dem.engines): the DEM codes' parameters <->
(alpha, gamma, D1, D2, end)."""

import io
import json
import math

import pytest

from restitution.cli import main
from restitution.core.errors import ParameterError
from restitution.dem import Contact
from restitution.dem.engines.lammps.contact import lammps_contact, lammps_eta_n0, lammps_pair_coeff, tsuji_a
from restitution.dem.engines.lammps.design import lammps_audit, lammps_design, tsuji_audit
from restitution.dem.engines.liggghts.contact import liggghts_contact
from restitution.dem.engines.mercurydpm.contact import mercury_linear_contact
from restitution.dem.pair import Pair

PAIR = Pair.spheres(1e-3, 2e-3, 2500.0, 7800.0)


def test_pair_effective_mass_and_radius():
    m1, m2 = 2500.0 * 4 / 3 * math.pi * 1e-9, 7800.0 * 4 / 3 * math.pi * 8e-9
    assert PAIR.m == pytest.approx(m1 * m2 / (m1 + m2), rel=1e-14)
    assert PAIR.R == pytest.approx(2e-3 / 3, rel=1e-14)


@pytest.mark.parametrize("normal, damping, alpha, gamma, d1, d2", [
    ({"normal": "hooke", "k_n": 7.0}, "velocity", "1", "0", lambda: 7.0 / PAIR.m, lambda: 3.0 / PAIR.m),
    ({"normal": "hooke", "k_n": 7.0}, "mass_velocity", "1", "0", lambda: 7.0 / PAIR.m, lambda: 3.0),
    ({"normal": "hertz", "k_n": 7.0}, "viscoelastic", "3/2", "1/2", lambda: 7.0 * math.sqrt(PAIR.R) / PAIR.m,
     lambda: 3.0 * math.sqrt(PAIR.R)),
    ({"normal": "hertz/material", "E": 7.0, "nu": 0.25}, "velocity", "3/2", "0",
     lambda: 4 / 3 * 7.0 / (2 * (1 - 0.25 ** 2)) * math.sqrt(PAIR.R) / PAIR.m, lambda: 3.0 / PAIR.m),
])
def test_lammps_rows_of_the_dictionary(normal, damping, alpha, gamma, d1, d2):
    for limit, end in ((True, "force"), (False, "overlap")):
        c = lammps_contact(PAIR, damping=damping, eta_n0=3.0, limit_damping=limit, **normal)
        assert (str(c.alpha), str(c.gamma), c.end) == (alpha, gamma, end)
        assert c.D1 == pytest.approx(d1(), rel=1e-14) and c.D2 == pytest.approx(d2(), rel=1e-14)


@pytest.mark.parametrize("normal", ["hooke", "hertz"])
@pytest.mark.parametrize("damping", ["velocity", "mass_velocity", "viscoelastic", "tsuji", "coeff_restitution"])
def test_eta_n0_inverts_the_damping_column(damping, normal):
    eta = 0.4 if damping in ("tsuji", "coeff_restitution") else 123.0
    c = lammps_contact(PAIR, normal=normal, k_n=1e6, damping=damping, eta_n0=eta, limit_damping=True)
    assert lammps_eta_n0(PAIR, damping, c) == pytest.approx(eta, rel=1e-12)


@pytest.mark.parametrize("normal, k", [("hooke", {"k_n": 2e4}), ("hertz/material", {"E": 5e7, "nu": 0.3})])
@pytest.mark.parametrize("e", [0.05, 0.5, 0.99])
def test_coeff_restitution_gives_its_e_only_without_limit_damping(normal, k, e):
    """LAMMPS' coeff_restitution damping (hooke: 2, Hertz: sqrt(5) times -ln e / sqrt(pi^2 +
    ln^2 e)): eps = e at every speed under the overlap rule; with limit_damping higher, the same
    for both models (0.55028 for e = 0.5, as LIGGGHTS' limitForce: the same law)."""
    c = lammps_contact(PAIR, normal=normal, damping="coeff_restitution", eta_n0=e, limit_damping=False, **k)
    clipped = lammps_contact(PAIR, normal=normal, damping="coeff_restitution", eta_n0=e, limit_damping=True, **k)
    for g in (0.01, 1.0, 30.0):
        assert c.eps(g) == pytest.approx(e, rel=1e-10)
        assert clipped.eps(g) > e + (1e-3 if e < 0.9 else 1e-6)
    if e == 0.5:
        assert clipped.eps(1.0) == pytest.approx(0.550283, abs=1e-6)


def test_pair_coeff_line():
    line = lammps_pair_coeff(normal="hertz/material", E=5e7, nu=0.3, damping="tsuji", eta_n0=0.8,
                             limit_damping=True)
    assert line == ("pair_coeff * * hertz/material 50000000 0.8 0.3 damping tsuji "
                    "tangential linear_nohistory 0 0 limit_damping")
    assert not lammps_pair_coeff(normal="hooke", k_n=1e3, damping="velocity", eta_n0=1.0,
                                 limit_damping=False).endswith("limit_damping")


def test_tsuji_e_is_not_the_eps_lammps_produces():
    rows = {r["e"]: r for r in tsuji_audit([0.5, 0.8])}
    # the values LAMMPS itself gives with limit_damping (tests/library/test_dem_lammps.py checks the engine)
    assert rows[0.8]["eps_limit_damping"] == pytest.approx(0.858, abs=1e-3)
    assert rows[0.5]["eps_limit_damping"] == pytest.approx(0.646, abs=1e-3)
    for r in rows.values():
        assert r["eps_default"] < r["eps_limit_damping"] and abs(r["eps_default"] - r["e"]) > 1e-3
    # independent of speed and particles: Omega = 1 / A(e)^2
    c = lammps_contact(PAIR, normal="hertz/material", E=5e7, nu=0.3, damping="tsuji", eta_n0=0.8,
                       limit_damping=True)
    assert c.omega(0.01) == pytest.approx(1 / tsuji_a(0.8) ** 2, rel=1e-12) == pytest.approx(c.omega(30.0))


@pytest.mark.parametrize("e", [0.1, 0.5, 0.9])
def test_liggghts_hertz_gives_its_e_only_without_limit_force(e):
    default = liggghts_contact(PAIR, E=1e8, nu=0.3, e=e)
    assert default.end == "overlap" and default.eps(1.0) == pytest.approx(e, rel=1e-10)
    assert default.eps(0.01) == pytest.approx(e, rel=1e-10)
    limited = liggghts_contact(PAIR, E=1e8, nu=0.3, e=e, limit_force=True)
    assert limited.eps(1.0) > e * (1 + 1e-5)


def test_mercury_linear_species_gives_its_e_and_collision_time():
    c = mercury_linear_contact(PAIR, t_c=2e-4, e=0.7)
    assert c.eps(3.0) == pytest.approx(0.7, rel=1e-10) and c.contact_time(3.0) == pytest.approx(2e-4, rel=1e-10)


@pytest.mark.parametrize("damping", ["velocity", "mass_velocity", "viscoelastic", "tsuji", "coeff_restitution"])
@pytest.mark.parametrize("limit", [False, True])
def test_design_then_audit_round_trip(damping, limit):
    kw = {"normal": "hertz/material", "E": 5e7, "nu": 0.3, "damping": damping, "limit_damping": limit}
    d = lammps_design(PAIR, eps=0.6, g=1.0, **kw)
    a = lammps_audit(PAIR, [1.0], eta_n0=d["eta_n0"], **kw)
    assert a["rows"][0]["eps"] == pytest.approx(0.6, rel=1e-9) and a["pair_coeff"] == d["pair_coeff"]


def test_cli_lammps_design_and_audit():
    base = ["lammps", "--normal", "hertz/material", "--E", "5e7", "--nu", "0.3", "--damping", "viscoelastic",
            "--radius", "1e-3", "--density", "2500", "--json"]
    out = io.StringIO()
    assert main(base + ["--eps", "0.6", "--g", "1"], out=out) == 0
    design = json.loads(out.getvalue())
    assert design["pair_coeff"].startswith("pair_coeff * * hertz/material") and design["end"] == "overlap"
    out = io.StringIO()
    assert main(base + ["--eta-n0", str(design["eta_n0"]), "--g", "0.1", "1", "10"], out=out) == 0
    rows = json.loads(out.getvalue())["rows"]
    assert rows[1]["eps"] == pytest.approx(0.6, rel=1e-9) and rows[0]["eps"] > rows[1]["eps"] > rows[2]["eps"]


@pytest.mark.parametrize("extra", [["--damping", "bogus", "--eps", "0.5", "--g", "1"],
                                   ["--damping", "viscoelastic", "--g", "1"],
                                   ["--damping", "tsuji", "--eta-n0", "1.2", "--g", "1"],
                                   ["--damping", "viscoelastic", "--eps", "1.2", "--g", "1"]])
def test_cli_lammps_bad_input_is_one_line(extra, capsys):
    argv = ["lammps", "--normal", "hertz", "--k-n", "1e6", "--radius", "1e-3", "--density", "2500", *extra]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "Traceback" not in err


def test_contact_validates_its_fields():
    with pytest.raises(ParameterError, match="end"):
        Contact("3/2", "1", 1.0, 1.0, "sometimes")
    with pytest.raises(ParameterError, match="D2"):
        Contact("3/2", "1", 1.0, -1.0)

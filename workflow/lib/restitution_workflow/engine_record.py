"""What a DEM engine was given and what it printed, kept for every run the pipeline makes, so that
a reader can run the same deck in the same engine and compare (the arXiv bundle carries them).

The library's runners (restitution.dem.engines.*.run) drive the engine and keep only the numbers
they need; recording happens around them, without changing what they send: LAMMPS' Python module is
stood in for by one that passes every command on and keeps it, and screens the run to a file
instead of to nowhere. After the runner's last command the state it read (every atom's position and
velocity) is printed by LAMMPS itself, so the output shows the numbers the library used. The engines
run as a child process (LIGGGHTS, Yade, Kratos) are recorded at the process: the runner module's
``subprocess.run`` is stood in for by one that keeps the command, the files of the run directory it
names (the input deck or script) and what the process printed, the runner reading the same output.

Outputs must be the same bytes for the same inputs: the only lines of LAMMPS' screen that change
from run to run are its timings, which are masked.
"""

from __future__ import annotations

import contextlib
import re
import shlex
import subprocess
import sys
import tempfile
import types
from pathlib import Path

__all__ = ["LammpsRecorder", "ProcessRecorder", "lammps_version", "mask_timings"]

#: The screen lines that carry a wall or CPU time, a date or a port of this machine (LAMMPS', LIGGGHTS'
#: and Yade's), and what they become.
_TIMINGS = [
    (re.compile(r"(CPU = )[-+0-9.eE]+( seconds)"), r"\1(time)\2"),
    (re.compile(r"^(Loop time of )\S+", re.MULTILINE), r"\1(time)"),
    (re.compile(r"^(Total wall time: )\S+", re.MULTILINE), r"\1(time)"),
    (re.compile(r"^(Setting up run at ).*$", re.MULTILINE), r"\1(date)"),
    (re.compile(r"(, finish time ).*$", re.MULTILINE), r"\1(date)"),
    (re.compile(r"^([A-Z][a-z]+ +time \(%\) = ).*$", re.MULTILINE), r"\1(time)"),
    (re.compile(r"(XMLRPC info provider on http://localhost:)\d+"), r"\1(port)"),
]
_THERMO_HEAD = re.compile(r"^\s*Step\s.*\bCPU\b")


def _mask_cpu_column(text: str) -> str:
    """The CPU column of LIGGGHTS' thermo lines (under a header naming it) replaced by ``(time)``."""
    out, column = [], None
    for line in text.split("\n"):
        words = line.split()
        if _THERMO_HEAD.match(line):
            column = words.index("CPU")
        elif column is not None and len(words) > column and words[0].isdigit():
            words[column] = "(time)"
            line = " ".join(words)
        else:
            column = None
        out.append(line)
    return "\n".join(out)


def mask_timings(text: str) -> str:
    """``text`` with every timing, date and port of an engine's screen replaced by a word saying which.

    Examples
    --------
    >>> mask_timings("Loop time of 1.6e-05 on 1 procs\\n  create_atoms CPU = 0.000 seconds\\nTotal wall time: 0:00:00")
    'Loop time of (time) on 1 procs\\n  create_atoms CPU = (time) seconds\\nTotal wall time: (time)'
    >>> print(mask_timings("    Step    Atoms            CPU \\n       0        2              0 \\n   12000        2    0.011288415 "))
        Step    Atoms            CPU 
    0 2 (time)
    12000 2 (time)
    """
    for pattern, replacement in _TIMINGS:
        text = pattern.sub(replacement, text)
    return _mask_cpu_column(text)


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


def _is_file(path: Path) -> bool:
    """Whether ``path`` is a file; an argument too long to be a name (Kratos' cases, as JSON) is not."""
    try:
        return path.is_file()
    except OSError:
        return False


class ProcessRecorder:
    """Keeps the command, input files and printed output of every engine process a runner module
    starts with ``subprocess.run`` while :meth:`active`.

    ``runs`` holds one {"command", "files", "output"} per process, in order: ``command`` the command
    line as a shell would take it in the run directory (files there named by their own name, the
    program by its name, not its path), ``files`` {name: text} of the files of the run directory
    the command names, ``output`` its standard output with timings masked (:func:`mask_timings`).

    Parameters
    ----------
    module : module
        The runner module (it imports ``subprocess`` and calls ``subprocess.run``).

    Examples
    --------
    >>> import sys, types
    >>> runner = types.ModuleType("runner"); runner.subprocess = subprocess
    >>> rec = ProcessRecorder(runner)
    >>> with rec.active():
    ...     proc = runner.subprocess.run([sys.executable, "-c", "print(6 * 7)"], capture_output=True, text=True)
    >>> proc.stdout, rec.runs[0]["output"], rec.runs[0]["command"].split(" ", 1)[1]
    ('42\\n', '42\\n', "-c 'print(6 * 7)'")
    """

    def __init__(self, module):
        self._module = module
        self.runs: list[dict] = []

    def _run(self, args, *posargs, cwd=None, **kwargs):
        here = Path(cwd) if cwd is not None else Path.cwd()
        files, words = {}, []
        for i, arg in enumerate(map(str, args)):
            path = Path(arg) if Path(arg).is_absolute() else here / arg
            if i > 0 and _is_file(path) and path.parent.resolve() == here.resolve():
                files[path.name] = path.read_text()
                words.append(path.name)
            else:
                # the program by its name: where it is installed is this machine's, not the run's
                words.append(Path(arg).name if i == 0 else arg)
        proc = subprocess.run(args, *posargs, cwd=cwd, **kwargs)
        out = proc.stdout if isinstance(proc.stdout, str) else (proc.stdout or b"").decode(errors="replace")
        self.runs.append({"command": shlex.join(words), "files": files, "output": mask_timings(out)})
        return proc

    @contextlib.contextmanager
    def active(self):
        shim = types.SimpleNamespace(**{k: getattr(subprocess, k) for k in ("DEVNULL", "PIPE", "STDOUT",
                                                                         "CalledProcessError", "TimeoutExpired")})
        shim.run = self._run
        self._module.subprocess = shim
        try:
            yield self
        finally:
            self._module.subprocess = subprocess


def lammps_version(outputs) -> str:
    """The version LAMMPS names in the first line of its screen, ``LAMMPS (22 Jul 2025 - Update 4)``,
    as it prints it; the same in every one of ``outputs`` (screen texts), else ValueError."""
    found = set()
    for text in outputs:
        m = re.match(r"LAMMPS \((.+)\)\s*$", text.splitlines()[0] if text else "")
        if not m:
            raise ValueError("a LAMMPS screen without its version line")
        found.add(m.group(1))
    if len(found) != 1:
        raise ValueError(f"LAMMPS screens of different versions: {sorted(found)}")
    return found.pop()


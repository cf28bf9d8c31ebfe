"""What every subcommand of the ``restitution`` command shares: a parser whose errors are one line,
the usage error, the common options, JSON output, a progress
report for long computations, the argv fixes made before argparse reads it, and the guard that turns
a lost standard output into one line."""

from __future__ import annotations

import argparse
import json
import re
import sys

__all__ = ["EXIT_USAGE", "EXIT_OUTPUT", "OutputLost", "GuardedOutput", "OneLineParser", "UsageError",
           "positive_int", "add_end", "add_exponents", "write_json", "Progress", "duration",
           "attach_negative_values", "refuse_repeated_options"]

EXIT_USAGE = 2
#: The answer could not be written: standard output closed, full, or a pipe its reader closed
EXIT_OUTPUT = 1


class OneLineParser(argparse.ArgumentParser):
    """argparse prints the whole usage block on error; we print one line."""

    def error(self, message):  # noqa: D401 - argparse hook
        raise UsageError(f"{self.prog}: {message}")

    def print_help(self, file=None):
        # argparse ignores a failed write of the help: a lost standard output would pass unseen
        stream = GuardedOutput(file or sys.stdout)
        stream.write(self.format_help())
        stream.flush()


class UsageError(Exception):
    pass


class OutputLost(Exception):
    """Writing the answer failed; the message is the one line the user sees."""


class GuardedOutput:
    """The answer's stream, whose write errors become :class:`OutputLost`: only a failure of this
    stream is reported as a lost output, never an OSError from elsewhere (a deck's engine, a file)."""

    def __init__(self, stream):
        self.stream = stream

    def write(self, text):
        return self._guard(self.stream.write, text)

    def flush(self):
        return self._guard(self.stream.flush)

    @staticmethod
    def _guard(call, *args):
        try:
            return call(*args)
        except BrokenPipeError:
            raise OutputLost("restitution: standard output closed by its reader (broken pipe): "
                             "the answer is incomplete") from None
        except (OSError, ValueError) as exc:   # ValueError: the stream was closed in this process
            why = getattr(exc, "strerror", None) or str(exc)
            raise OutputLost(f"restitution: standard output cannot be written ({why}): "
                             "the answer is incomplete") from None


def positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not an integer: {text!r}") from None
    if value < 0:
        raise argparse.ArgumentTypeError(f"must be >= 0, got {value}")
    return value


def add_end(p: argparse.ArgumentParser) -> None:
    p.add_argument("--end", default="force",
                   help="end-of-contact rule: force (contact ends where the total force vanishes; LAMMPS "
                        "limit_damping, default) or overlap (when the overlap returns to 0; LAMMPS' default)")


def add_exponents(p: argparse.ArgumentParser) -> None:
    p.add_argument("--alpha", required=True, help="elastic exponent, a rational > 0 such as 3/2")
    p.add_argument("--gamma", required=True, help="dissipative exponent, a rational >= 0 such as 1")


def write_json(data, out) -> None:
    json.dump(data, out, separators=(", ", ": "))
    out.write("\n")


class Progress:
    """A long computation's price on stderr while it runs: past a few seconds it says how far it is
    and about how long it takes in all, then again every half minute. ``power``: how the cost of the
    first k of n steps grows (k^power), so the estimate is elapsed * (n/k)^power."""

    FIRST, EVERY = 3.0, 30.0

    def __init__(self, label: str, steps: str, power: float = 1.0, note: str = "", stream=None):
        import time
        self.clock = time.monotonic
        self.start = self.clock()
        self.next = self.start + self.FIRST
        self.label, self.steps, self.power, self.note, self.stream = label, steps, power, note, stream

    def __call__(self, done: int, total: int) -> None:
        now = self.clock()
        if now < self.next or done >= total:
            return
        self.next = now + self.EVERY
        elapsed = now - self.start
        whole = elapsed * (total / done) ** self.power
        print(f"restitution {self.label}: {done} of {total} {self.steps} after {elapsed:.0f} s; about "
              f"{duration(whole)} in all{self.note}", file=self.stream or sys.stderr, flush=True)


def duration(seconds: float) -> str:
    if seconds < 90:
        return f"{seconds:.0f} s"
    if seconds < 5400:
        return f"{seconds / 60:.0f} min"
    return f"{seconds / 3600:.1f} h"


NEGATIVE_VALUE = re.compile(r"^-(\d|\.\d|inf|nan)", re.IGNORECASE)


def attach_negative_values(argv: list[str]) -> list[str]:
    """`--gamma -1/2` -> `--gamma=-1/2`: argparse would read -1/2 or -inf as an option and say only
    "expected one argument"; attached, the value reaches the physics, which names the allowed range."""
    out: list[str] = []
    i = 0
    while i < len(argv):
        tok = argv[i]
        if (tok.startswith("--") and "=" not in tok and i + 1 < len(argv)
                and NEGATIVE_VALUE.match(argv[i + 1])):
            out.append(f"{tok}={argv[i + 1]}")
            i += 2
            continue
        out.append(tok)
        i += 1
    return out


def refuse_repeated_options(argv) -> None:
    """argparse keeps the last of `--omega 1 --omega 2` silently; a value given twice is a mistake."""
    seen = set()
    for token in argv:
        if token.startswith("--"):
            name = token.split("=", 1)[0]
            if name in seen:
                raise UsageError(f"restitution: {name} given twice: give it once (several values "
                                  "go after one option: --omega 0.1 0.5)")
            seen.add(name)



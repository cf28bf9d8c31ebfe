"""Command line: `restitution series`, `collide`, `eps`, `calibrate`, `lammps`, `deck` and `scene`.

User mistakes end in one line on stderr and exit status 2, never a traceback. The subcommands of
the model live in :mod:`restitution.cli.physics`, those for DEM modellers in
:mod:`restitution.cli.dem`, what they share in :mod:`restitution.cli.common`.
"""

from __future__ import annotations

import argparse
import sys

from ..core.errors import ParameterError
from .common import (EXIT_OUTPUT, EXIT_USAGE, GuardedOutput, OneLineParser, OutputLost, Progress, UsageError,
                     attach_negative_values, refuse_repeated_options)
from .dem import LARGE_SCENE, add_dem_subcommands, run_deck, run_lammps, run_scene, scene_table
from .physics import add_eps_subcommand, add_physics_subcommands, run_calibrate, run_collide, run_eps, run_series

__all__ = ["main", "build_parser", "COMMANDS", "EXIT_USAGE", "EXIT_OUTPUT", "LARGE_SCENE", "Progress", "add_eps_subcommand",
           "run_eps", "scene_table"]

#: Each subcommand's runner (args, out) -> exit status or None
COMMANDS = {"series": run_series, "collide": run_collide, "eps": run_eps, "calibrate": run_calibrate,
            "lammps": run_lammps, "deck": run_deck, "scene": run_scene}


class _ShowVersion(argparse.Action):
    """``--version``: prints the installed version and exits, reading it only when asked."""

    def __init__(self, option_strings, dest, help=None):
        super().__init__(option_strings, dest, nargs=0, default=argparse.SUPPRESS, help=help)

    def __call__(self, parser, namespace, values, option_string=None):
        from importlib.metadata import version
        print(f"{parser.prog} {version('restitution')}")
        parser.exit()


def build_parser() -> argparse.ArgumentParser:
    """The ``restitution`` command's parser, every subcommand included (the CLI reference page is
    generated from it).

    Returns
    -------
    argparse.ArgumentParser
        A parser whose errors are one line (exit status 2).

    Examples
    --------
    >>> from restitution.cli import build_parser
    >>> args = build_parser().parse_args(["collide", "--alpha", "3/2", "--gamma", "1", "--omega", "0.47"])
    >>> args.command, args.omega
    ('collide', 0.47)
    """
    parser = OneLineParser(prog="restitution",
                            description="Coefficient of restitution of viscoelastic collisions.")
    parser.add_argument("--version", action=_ShowVersion, help="print the version and exit")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=OneLineParser)

    add_physics_subcommands(sub)
    add_dem_subcommands(sub)
    return parser


def main(argv=None, out=None) -> int:
    """Run the ``restitution`` command.

    Parameters
    ----------
    argv : list of str, optional
        The arguments (default: ``sys.argv[1:]``).
    out : file-like, optional
        Where the answer is written (default: standard output); notes go to standard error.

    Returns
    -------
    int
        The exit status: 0 on success, 1 where a subcommand reports a failed check (``scene``) or
        where the answer cannot be written (standard output closed, full, or a pipe its reader
        closed), 2 for a mistake in the arguments; each failure is one line on standard error,
        no traceback.

    Raises
    ------
    SystemExit
        Only from ``--help`` and ``--version``, as argparse does.

    Examples
    --------
    >>> from restitution.cli import main
    >>> main(["collide", "--alpha", "1", "--gamma", "0", "--omega", "1"])   # doctest: +ELLIPSIS
     alpha  1
     gamma  0
     omega  1
       eps  0.298436059...
    ...
    0
    >>> main(["collide", "--alpha", "1", "--gamma", "0", "--omega", "-1"])   # the message goes to stderr
    2
    """
    out = sys.stdout if out is None else out
    if out is None:   # `>&-`: Python has no sys.stdout at all; say so before any work
        print("restitution: standard output is closed: there is nowhere to write the answer", file=sys.stderr)
        return EXIT_OUTPUT
    guarded = GuardedOutput(out)
    argv = sys.argv[1:] if argv is None else list(argv)
    try:
        refuse_repeated_options(argv)
        args = build_parser().parse_args(attach_negative_values(argv))
        status = COMMANDS[args.command](args, guarded)
        guarded.flush()   # here, not at exit, where a full disk would pass unseen or as a traceback
    except UsageError as exc:
        print(str(exc), file=sys.stderr)
        return EXIT_USAGE
    except ParameterError as exc:
        print(f"restitution: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except OutputLost as exc:
        print(str(exc), file=sys.stderr)
        _silence_exit_flush(out)
        return EXIT_OUTPUT
    return status or 0


def _silence_exit_flush(out) -> None:
    """What is left in sys.stdout's buffer would be flushed again at exit, failing again with a
    message and status 120; pointing its descriptor at /dev/null is what Python's documentation
    on SIGPIPE recommends."""
    import os

    if out is sys.stdout:
        try:
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, out.fileno())
            os.close(devnull)
        except (OSError, ValueError, AttributeError):   # not a real file: nothing flushes at exit
            pass

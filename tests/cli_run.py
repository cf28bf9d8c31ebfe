"""The command line run in process as a user's shell would see it (shared by the tests of bad
input in tests/library and tests/pipeline)."""

from __future__ import annotations

import io
import sys
import warnings

from restitution import cli


def run_cli(argv):
    """main() in process, with warnings printed to stderr as in a real process."""
    out, err = io.StringIO(), io.StringIO()
    real_err = sys.stderr
    sys.stderr = err
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("default")
            warnings.showwarning = lambda m, c, f, n, file=None, line=None: err.write(
                warnings.formatwarning(m, c, f, n, line))
            try:
                code = cli.main(argv, out=out)
            except SystemExit as exc:  # pragma: no cover - argparse exits are bugs here
                code = exc.code
            except Exception as exc:  # noqa: BLE001 - a traceback is what we test against
                import traceback

                err.write("Traceback (most recent call last):\n" + "".join(traceback.format_exception(exc)))
                code = 1
    finally:
        sys.stderr = real_err
    return code, out.getvalue(), err.getvalue()

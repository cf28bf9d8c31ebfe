"""Write outputs so that a half-written file never exists under its final name.

    with atomic_path("results/x/table.csv") as tmp:   # tmp: results/x/.table.csv.<random>.tmp.csv
        frame.to_csv(tmp)                             # anything that writes a file at a path
    # renamed to results/x/table.csv here, only if the block finished without an exception

The temporary file lives in the same directory (rename is atomic only within one file system),
is hidden (leading dot: rebuild.py and `make check` ignore dot files) and is removed when the
block fails. A job killed in the middle (SIGKILL, power loss) leaves at most a stray
``.<name>.*.tmp`` beside the outputs, never a truncated output; Snakemake's own incomplete-job
markers then make the restart rerun the job (the Makefile passes --rerun-incomplete).

An unwritable or full results/ is turned into one line naming the path and the cause
(:class:`OutputError`), not a traceback from deep inside pandas or matplotlib.
"""

from __future__ import annotations

import contextlib
import errno
import os
import tempfile
from pathlib import Path

__all__ = ["OutputError", "atomic_path", "write_text_atomic", "write_bytes_atomic"]

_UMASK = os.umask(0)
os.umask(_UMASK)


class OutputError(OSError):
    """An output could not be written (read-only or full file system, a file where a directory
    should be, ...). The message is one line: the path and what to do."""

    def __str__(self) -> str:
        return str(self.strerror)


_ADVICE = {
    errno.ENOSPC: "the file system is full: free some space and rerun",
    errno.EDQUOT: "disk quota exceeded: free some space and rerun",
    errno.EROFS: "the file system is read-only: make results/ writable (or a symlink to a writable place)",
    errno.EACCES: "permission denied: make results/ writable by this user",
    errno.EPERM: "operation not permitted: make results/ writable by this user",
    errno.ENOTDIR: "a file is in the way where a directory is needed: remove it",
    errno.EEXIST: "a file is in the way where a directory is needed: remove it",
    errno.EISDIR: "a directory is in the way where a file is needed: remove it",
}


def describe(err: OSError, path) -> str:
    why = _ADVICE.get(err.errno, err.strerror or str(err))
    return f"cannot write {path}: {why} ({errno.errorcode.get(err.errno, err.errno)})"


@contextlib.contextmanager
def atomic_path(path):
    """Yield a temporary path beside ``path``; rename it to ``path`` when the block succeeds."""
    final = Path(path)
    try:
        final.parent.mkdir(parents=True, exist_ok=True)
        # the format is often chosen from the extension (savefig, to_csv): keep it at the end
        fd, tmp = tempfile.mkstemp(prefix=f".{final.name}.", suffix=".tmp" + final.suffix, dir=final.parent)
        os.close(fd)
    except OSError as err:
        raise OutputError(err.errno, describe(err, final)) from None
    tmp_path = Path(tmp)
    try:
        yield tmp_path
        with open(tmp_path, "rb+") as fh:
            os.fsync(fh.fileno())
        os.chmod(tmp_path, 0o666 & ~_UMASK)   # mkstemp makes 0600; outputs get the usual mode
        os.replace(tmp_path, final)
    except OSError as err:
        with contextlib.suppress(OSError):
            tmp_path.unlink()
        raise OutputError(err.errno, describe(err, final)) from None
    except BaseException:
        with contextlib.suppress(OSError):
            tmp_path.unlink()
        raise


def write_text_atomic(path, text: str) -> None:
    if not text.endswith("\n"):
        text += "\n"
    with atomic_path(path) as tmp:
        tmp.write_text(text)


def write_bytes_atomic(path, data: bytes) -> None:
    with atomic_path(path) as tmp:
        tmp.write_bytes(data)

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
import hashlib
import json
import os
import shutil
import sys
import tempfile
from pathlib import Path

__all__ = ["OutputError", "atomic_path", "write_text_atomic", "write_bytes_atomic", "install", "verify_written"]

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
    errno.EFBIG: "a file size limit (ulimit -f) stops the writes: raise it",
}


def advice(err: OSError) -> str:
    """What to do about `err`, with its errno name."""
    why = _ADVICE.get(err.errno, err.strerror or str(err))
    return f"{why} ({errno.errorcode.get(err.errno, err.errno)})"


def describe(err: OSError, path) -> str:
    return f"cannot write {path}: {advice(err)}"


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
        _record(final)
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


def install(src, dest) -> None:
    """Copy a finished file into place (shell rules: a figure copy, the PDF from latexmk)."""
    with atomic_path(dest) as tmp:
        shutil.copyfile(src, tmp)


# ------------------------------------------------------------------------------- what was written
# Every output the pipeline writes is recorded with its sha256 in build/written.jsonl (beside
# results/), so that a file changed or truncated afterwards -- even with its time stamp put back,
# which Snakemake cannot see -- is found and rebuilt instead of being used (workflow/tools/guard.py,
# `make verify`). One appended line per write: appends this small are atomic, so parallel jobs
# need no lock, and the last line for a path is the one that counts.
WRITTEN = Path("build") / "written.jsonl"


def _sha256(path: Path) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def _tree_of(path: Path) -> tuple[Path, str] | None:
    """(project tree, path relative to it) for a file under a results/ directory, else None."""
    path = path.resolve()
    for parent in path.parents:
        if parent.name == "results":
            return parent.parent, str(path.relative_to(parent.parent))
    return None


def _record(final: Path) -> None:
    where = _tree_of(final)
    if where is None:
        return
    tree, rel = where
    log = tree / WRITTEN
    log.parent.mkdir(parents=True, exist_ok=True)
    line = json.dumps({"path": rel, "sha256": _sha256(final)}, sort_keys=True) + "\n"
    fd = os.open(log, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o666 & ~_UMASK)
    try:
        os.write(fd, line.encode())
    finally:
        os.close(fd)


def written(tree) -> dict[str, str]:
    """path -> sha256 of what the pipeline last wrote there (unreadable lines are skipped: a line
    cut by a full disk must not hide the others)."""
    out: dict[str, str] = {}
    try:
        lines = (Path(tree) / WRITTEN).read_text(errors="replace").splitlines()
    except FileNotFoundError:
        return out
    for line in lines:
        try:
            entry = json.loads(line)
            out[str(entry["path"])] = str(entry["sha256"])
        except (ValueError, KeyError, TypeError):
            continue
    return out


def verify_written(tree) -> tuple[list[str], list[str]]:
    """(changed, missing): outputs whose bytes are not what the pipeline wrote, and recorded
    outputs that are gone."""
    tree = Path(tree)
    changed, missing = [], []
    for rel, digest in sorted(written(tree).items()):
        path = tree / rel
        if not path.is_file():
            missing.append(rel)
        elif _sha256(path) != digest:
            changed.append(rel)
    return changed, missing


def compact_written(tree) -> None:
    """Keep one record per existing path (run under the pipeline's lock: no job is appending)."""
    tree = Path(tree)
    lines = [json.dumps({"path": p, "sha256": d}, sort_keys=True) + "\n"
             for p, d in written(tree).items() if (tree / p).is_file()]
    if (tree / WRITTEN).exists():
        tmp = tree / WRITTEN.with_suffix(".tmp")
        tmp.write_text("".join(lines))
        os.replace(tmp, tree / WRITTEN)


def report(tree) -> int:
    """`make verify`: one line per output that is not what the pipeline wrote; exit 1 if any."""
    changed, missing = verify_written(tree)
    for rel in changed:
        print(f"verify: {rel}: changed since the pipeline wrote it (make paper moves it aside and rebuilds it)")
    for rel in missing:
        print(f"verify: {rel}: missing (make paper rebuilds it)")
    n = len(written(tree))
    print(f"verify: {n - len(changed) - len(missing)} of {n} recorded outputs are as the pipeline wrote them")
    return 1 if changed or missing else 0


def _main(argv: list[str]) -> int:
    """`install SRC DEST` and `write DEST` (text on stdin) for shell rules; `verify [TREE]`."""
    try:
        if len(argv) == 3 and argv[0] == "install":
            install(argv[1], argv[2])
        elif len(argv) == 2 and argv[0] == "write":
            write_bytes_atomic(argv[1], sys.stdin.buffer.read())
        elif len(argv) in (1, 2) and argv[0] == "verify":
            return report(argv[1] if len(argv) == 2 else ".")
        else:
            print("usage: atomic.py install SRC DEST | write DEST < text | verify [TREE]", file=sys.stderr)
            return 2
    except OutputError as err:
        print(err, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(_main(sys.argv[1:]))

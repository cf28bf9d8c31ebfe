"""On-disk cache for built objects (master curves): plain JSON, written atomically.

Location: ``$RESTITUTION_CACHE`` if set, else ``~/.cache/restitution``. A file is written to a
temporary name in the same directory and renamed into place, so a reader never sees half a file and
a killed build leaves at most a stray ``*.tmp`` behind (ignored, and cleaned up by the next write of
the same key). Each file carries the sha256 of its content: a file that cannot be read, does not
match its digest (changed after it was written) or does not validate is not used, but rebuilt.
A cache directory that cannot be written is not an error: the object is built, used and a note is
printed on stderr.

An entry that passed its checks on load (spot checks against the integrator, which would start
numba: most of a second) is, where the caller says its checks depend on nothing but the entry's
name, content and the library (``remember``), marked so (``<entry>.checked``: a digest of its name, its content and
the library's source) and not checked again by later processes; an entry changed since, even sealed
again, or a library changed since, has another digest and is checked again.
"""

from __future__ import annotations

import hashlib
import io
import json
import os
import sys
import tempfile
import time
from contextlib import contextmanager
from pathlib import Path
from typing import Callable

__all__ = ["cache_dir", "cache_path", "nearest_existing", "load_json", "load_or_discard", "discard_damaged", "entry_lock",
           "save_json_atomic", "get_or_build"]

ENV_VAR = "RESTITUTION_CACHE"
#: A build that takes (or is expected to take) longer than this says so on stderr.
ANNOUNCE_SECONDS = 1.0


def cache_dir() -> Path:
    """The cache directory (not created here)."""
    env = os.environ.get(ENV_VAR)
    if env:
        return Path(env).expanduser()
    return Path.home() / ".cache" / "restitution"


def _safe(text: str) -> str:
    return "".join(c if c.isalnum() or c in "-_." else "_" for c in text)


def cache_path(key: str, directory: Path | None = None) -> Path:
    """Path of the JSON file for ``key`` (characters outside [A-Za-z0-9-_.] become '_')."""
    return (directory or cache_dir()) / f"{_safe(key)}.json"


def _digest(data: dict) -> str:
    """sha256 of the canonical JSON of ``data`` (what was written, whatever the file's layout)."""
    text = json.dumps(data, sort_keys=True, separators=(",", ":"), allow_nan=False)
    return hashlib.sha256(text.encode()).hexdigest()


def load_json(path: Path, stream=None) -> dict | None:
    """The stored dict, or None when the file is missing, unreadable, or not what was written: the
    content must match the sha256 sealed with it, so an edited value (even valid JSON) is refused
    and rebuilt instead of being used with the bound of the original. A damaged file is named on
    ``stream`` (default stderr); a missing one is not."""
    sealed = _load_sealed(path, stream)
    return None if sealed is None else sealed[0]


def _load_sealed(path: Path, stream=None) -> tuple[dict, str] | None:
    """:func:`load_json`'s dict with the sha256 it was verified against."""
    try:
        with open(path, encoding="utf-8") as fh:
            stored = json.load(fh)
    except FileNotFoundError:
        return None
    except NotADirectoryError:   # the cache's place is a file (load_or_discard says so once)
        return None
    except (OSError, ValueError):
        stored = None
    try:
        if isinstance(stored, dict) and isinstance(stored.get("content"), dict) \
                and stored.get("sha256") == _digest(stored["content"]):
            return stored["content"], stored["sha256"]
    except ValueError:   # NaN or infinity in the content: never written by us
        pass
    print(f"restitution: the cache file {path} is damaged or was changed after it was written; "
          "it is not used", file=sys.stderr if stream is None else stream, flush=True)
    return None


def save_json_atomic(path: Path, data: dict) -> None:
    """Write ``data`` as JSON to ``path``, sealed with its sha256, through a temporary file and an
    atomic rename."""
    path = Path(path)
    sealed = {"sha256": _digest(data), "content": data}
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=path.name + ".", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            json.dump(sealed, fh, separators=(",", ":"), allow_nan=False)
            fh.write("\n")
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def discard_damaged(path: Path, stream=None, why: str = "is damaged or was changed after it was written") -> None:
    """Remove a cache file that cannot be used, with one note: it would otherwise be read, refused
    and reported on every later call, and never replaced by a request that does not build."""
    stream = sys.stderr if stream is None else stream
    try:
        os.unlink(path)
        fate = "removed; it is rebuilt when a request needs it"
    except (FileNotFoundError, NotADirectoryError):
        return
    except OSError as exc:
        fate = f"not used (could not remove it: {exc.strerror})"
    print(f"restitution: the cache file {path} {why}: {fate}", file=stream, flush=True)


_NOTED_NOT_A_DIRECTORY: set = set()


def nearest_existing(path) -> Path:
    """``path`` itself if it exists, else its nearest existing ancestor: what decides whether a
    folder that is not made yet can be made there (a file in the way cannot be a folder).

    Parameters
    ----------
    path : str or Path
        A path that may not exist yet.

    Returns
    -------
    Path
        The first of ``path`` and its parents that exists (the root at the latest).

    Examples
    --------
    >>> import tempfile
    >>> base = Path(tempfile.mkdtemp())
    >>> nearest_existing(base / "a" / "b") == base
    True
    """
    here = Path(path)
    while not here.exists() and here != here.parent:
        here = here.parent
    return here


def _not_a_directory(directory: Path, stream=None) -> bool:
    """True where the cache's place, or a folder above it, is a file (RESTITUTION_CACHE set to a
    file, say): then nothing can be cached there, and one note per process says so, instead of
    a "damaged" note for every entry asked for."""
    if Path(directory).is_dir():
        return False
    here = nearest_existing(directory)
    if here.is_dir():
        return False                    # not made yet: the first build makes it
    if here not in _NOTED_NOT_A_DIRECTORY:
        _NOTED_NOT_A_DIRECTORY.add(here)
        print(f"restitution: note: the cache location {here} is a file, not a directory: nothing is read "
              f"from or written to the cache (set {ENV_VAR} to a directory)",
              file=sys.stderr if stream is None else stream, flush=True)
    return True


_SOURCE_DIGEST: list = []


def _source_digest() -> str:
    """sha256 of the library's own source (what the checks run), once per process (a few ms)."""
    if not _SOURCE_DIGEST:
        h = hashlib.sha256()
        root = Path(__file__).resolve().parents[1]
        for f in sorted(root.rglob("*.py")):
            h.update(f.relative_to(root).as_posix().encode() + b"\0" + f.read_bytes())
        _SOURCE_DIGEST.append(h.hexdigest())
    return _SOURCE_DIGEST[0]


def _checked_mark(path: Path, sha256: str) -> str:
    return hashlib.sha256(f"{path.name}\n{_source_digest()}\n{sha256}".encode()).hexdigest()


def _mark_path(path: Path) -> Path:
    return path.with_name(path.name + ".checked")


def load_or_discard(path: Path, stream=None, valid: Callable[[dict], bool] = lambda d: True,
                    why_invalid: str = "does not pass its checks", remember: bool = False) -> dict | None:
    """The stored dict if it is sealed and ``valid`` (or marked as having passed ``valid`` in this
    very form, see the module docstring); a file that is not is removed with one note
    (:func:`discard_damaged`), so the next call finds nothing and says nothing."""
    if _not_a_directory(Path(path).parent, stream):
        return None
    quiet = io.StringIO()
    sealed = _load_sealed(path, quiet)
    if sealed is None:
        if quiet.getvalue():
            discard_damaged(path, stream)
        return None
    data, sha256 = sealed
    mark = _checked_mark(path, sha256) if remember else None
    try:
        if mark is not None and _mark_path(path).read_text(encoding="ascii") == mark:
            return data
    except (OSError, ValueError):
        pass
    if not valid(data):
        discard_damaged(path, stream, why_invalid)
        return None
    if mark is not None:
        try:   # best effort: without the mark the next process only checks again
            _mark_path(path).write_text(mark, encoding="ascii")
        except OSError:
            pass
    return data


@contextmanager
def entry_lock(path: Path, label: str, stream):
    """One builder per cache entry across processes: the lock file beside the entry is held while
    building; a second caller says once that it waits, then reads what the first one wrote. Where
    no lock file can be made (a read-only cache), each caller builds for itself, as before."""
    try:
        from filelock import FileLock, Timeout
    except ImportError:  # pragma: no cover - filelock is a dependency; without it: no lock
        yield
        return
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        lock = FileLock(str(path) + ".lock")
        try:
            lock.acquire(timeout=0)
        except Timeout:
            print(f"restitution: another process is building {label} ({path}); waiting for it",
                  file=stream, flush=True)
            lock.acquire()
    except OSError:
        yield
        return
    try:
        yield
    finally:
        lock.release()


def get_or_build(key: str, build: Callable[[], dict], *, valid: Callable[[dict], bool] = lambda d: True,
                 what: str = "", directory: Path | None = None, stream=None, announce: bool = True,
                 estimate: float | None = None, remember: bool = False) -> dict:
    """The cached dict for ``key`` if present and ``valid``; otherwise ``build()`` it and store it.

    Progress ("building ..." / "built in") goes to ``stream`` (default stderr); with ``announce``
    False only "built in", and only if it took longer than ANNOUNCE_SECONDS; ``estimate``: the
    expected seconds, said when it starts. Concurrent callers of
    the same key build it once (:func:`entry_lock`); a damaged or invalid entry is removed with one
    note and rebuilt.
    """
    stream = sys.stderr if stream is None else stream
    path = cache_path(key, directory)
    label = what or key
    data = load_or_discard(path, stream, valid, remember=remember)
    if data is not None:
        return data
    with entry_lock(path, label, stream):
        # the first builder may have finished while we waited for the lock
        data = load_or_discard(path, stream, valid, remember=remember)
        if data is not None:
            return data
        cacheable = not _not_a_directory(path.parent, stream)
        if announce:
            about = "" if estimate is None else f"about {estimate:.0f} s, "
            where = f"cached in {path}" if cacheable else "not cached"
            print(f"restitution: building {label} ({about}{where}) ...", file=stream, flush=True)
        t0 = time.perf_counter()
        data = build()
        try:
            if cacheable:
                save_json_atomic(path, data)
        except OSError as exc:
            print(f"restitution: note: could not write the cache ({exc}); using the result without "
                  "caching it", file=stream, flush=True)
        seconds = time.perf_counter() - t0
        if announce or seconds > ANNOUNCE_SECONDS:
            print(f"restitution: built {label} in {seconds:.1f} s", file=stream, flush=True)
    return data

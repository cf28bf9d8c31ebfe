"""numba's ``njit`` when numba is installed, else a no-op decorator: the compiled kernels
(:mod:`restitution.fast.integrator`, :mod:`restitution.fast.panels`) are also valid plain Python,
only much slower. ``HAVE_NUMBA`` says which.

A kernel compiled with ``cache=True`` is re-compiled when its own file changes, not when a file it
calls into does; so each kernel module calls only compiled functions of its own file.

numba's on-disk cache of compiled kernels (``*.nbi`` index and ``*.nbc`` data files, in the
package's ``__pycache__`` or under ``NUMBA_CACHE_DIR``) is disposable, but numba itself stops with
an unpickling error on a truncated or otherwise damaged file. :func:`_survive_damaged_cache` makes
such a file count as absent: the kernel is recompiled (one note on stderr per process) and the
damaged file is removed where that is allowed, so the next process finds a good one.
"""

import sys

try:  # numba is an optional accelerator: everything below is also valid plain Python.
    from numba import njit as _numba_njit

    HAVE_NUMBA = True

    def njit(*args, **kwargs):
        """numba's njit; where no cache directory can be written (a read-only package and no
        writable user cache), numba refuses ``cache=True`` at import: compile without caching."""
        if args and callable(args[0]) and len(args) == 1 and not kwargs:
            return _numba_njit(args[0])

        def decorate(func):
            try:
                return _numba_njit(*args, **kwargs)(func)
            except RuntimeError as exc:
                if not kwargs.get("cache") or "cannot cache" not in str(exc):
                    raise
                if not _NOTED:
                    print("restitution: note: no writable place for compiled kernels (read-only package "
                          "and no writable NUMBA_CACHE_DIR or user cache); compiling them in memory for this "
                          "process", file=sys.stderr, flush=True)
                    _NOTED.add("<no locator>")
                return _numba_njit(*args, **dict(kwargs, cache=False))(func)
        return decorate
except ImportError:  # pragma: no cover - exercised only without numba
    HAVE_NUMBA = False

    def njit(*args, **kwargs):
        if args and callable(args[0]):
            return args[0]
        return lambda f: f

_NOTED: set = set()


def _note_damaged(path: str, exc: BaseException) -> None:
    import os
    try:
        os.unlink(path)
        fate = "removed it"
    except OSError:
        fate = "could not remove it"
    if not _NOTED:   # one line per process, however many kernels share the damaged directory
        print(f"restitution: note: a compiled-kernel cache file ({os.path.basename(path)}: "
              f"{type(exc).__name__}) is damaged; recompiling (and {fate})", file=sys.stderr, flush=True)
    _NOTED.add(path)


def _survive_damaged_cache() -> None:
    """Wrap numba's index/data readers so that a file that cannot be unpickled reads as missing."""
    try:
        from numba.core.caching import IndexDataCacheFile
    except ImportError:  # pragma: no cover - another numba layout: its own behaviour applies
        return
    if getattr(IndexDataCacheFile, "_restitution_guarded", False):
        return
    load_index, load_data = IndexDataCacheFile._load_index, IndexDataCacheFile._load_data

    def _load_index(self):
        try:
            return load_index(self)
        except FileNotFoundError:
            return {}
        except Exception as exc:  # noqa: BLE001 - any unreadable index is as good as none
            _note_damaged(self._index_path, exc)
            return {}

    def _load_data(self, name):
        try:
            return load_data(self, name)
        except OSError:
            raise   # numba's load() already treats a vanished data file as a miss
        except Exception as exc:  # noqa: BLE001 - any unreadable data file is as good as none
            _note_damaged(self._data_path(name), exc)
            # numba's load() turns OSError into "not cached": the kernel is compiled afresh
            raise OSError(f"damaged numba cache file {name}") from exc

    IndexDataCacheFile._load_index = _load_index
    IndexDataCacheFile._load_data = _load_data
    IndexDataCacheFile._restitution_guarded = True


if HAVE_NUMBA:
    _survive_damaged_cache()

__all__ = ["HAVE_NUMBA", "njit"]

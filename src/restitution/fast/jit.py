"""numba's ``njit`` when numba is installed (numba imported and the kernel made on its first call),
else a no-op decorator: the compiled kernels
(:mod:`restitution.fast.collision_kernels`, :mod:`restitution.fast.panels`) are also valid plain Python,
only much slower. ``HAVE_NUMBA`` says which.

A kernel compiled with ``cache=True`` is re-compiled when its own file changes, not when a file it
calls into does; so each kernel module calls only compiled functions of its own file.

numba's on-disk cache of compiled kernels (``*.nbi`` index and ``*.nbc`` data files, in the
package's ``__pycache__`` or under ``NUMBA_CACHE_DIR``) is disposable, but numba itself stops with
an unpickling error on a truncated or otherwise damaged file. :func:`_survive_damaged_cache` makes
such a file count as absent: the kernel is recompiled (one note on stderr per process) and the
damaged file is removed where that is allowed, so the next process finds a good one.

:func:`call_kernel` runs kernels as the plain Python they are while numba is not imported
yet and the work is small: importing and starting numba costs about 0.4 s with its compiled kernels
on disk, a one-point eps call's integration 10-50 ms in plain Python (same floating-point
operations, same results: 40 points of both end rules compared bit for bit in the tests). A process
that asks many small requests (a loop over speeds, a calibration's root search) stops doing so once
its plain-Python kernels have taken about what numba's start costs (0.4 s with the kernels
compiled on disk, 6-8 s to compile them): past that, starting it would have been cheaper (432
one-point calls of a DEM study took 5.5 s plain).

numba's start leaves some hundred thousand objects that live until the process ends. Python's
garbage collector walks them at every full collection and once more at exit: a third of what a
process that starts numba from its compiled kernels on disk pays (0.79 s against 0.58 s of CPU for
one compiled call, whole processes). :func:`_starting` keeps the collector off while numba starts
and freezes the heap at exit (``gc.freeze``, registered then), where the operating system frees it
anyway; the collector's state is the caller's again afterwards.
"""

import contextlib
import gc
import importlib.util
import sys
import threading
import time

# numba is an optional accelerator: everything below is also valid plain Python. Whether it is there
# is asked without importing it: its import and start cost most of a second, which a request that
# runs no kernel (a closed form, the series) should not pay.
HAVE_NUMBA = importlib.util.find_spec("numba") is not None


def _compile(func, args, kwargs):
    """numba's njit of ``func``; where no cache directory can be written (a read-only package and
    no writable user cache), numba refuses ``cache=True``: compile without caching."""
    from numba import njit as numba_njit

    _skip_blas_probe()
    _survive_damaged_cache()
    if args and callable(args[0]):
        return numba_njit(func)
    try:
        return numba_njit(*args, **kwargs)(func)
    except RuntimeError as exc:
        if not kwargs.get("cache") or "cannot cache" not in str(exc):
            raise
        if not _NOTED:
            print("restitution: note: no writable place for compiled kernels (read-only package "
                  "and no writable NUMBA_CACHE_DIR or user cache); compiling them in memory for this "
                  "process", file=sys.stderr, flush=True)
            _NOTED.add("<no locator>")
        return numba_njit(*args, **dict(kwargs, cache=False))(func)


class _Kernel:
    """A kernel whose numba dispatcher is made on its first call (or first attribute read). Then
    every kernel of the same module is made too and put in the module's namespace in place of its
    stand-in: compiled code reads the kernels it calls from there, and numba types only its own
    dispatchers."""

    def __init__(self, func, args, kwargs):
        self.py_func, self._args, self._kwargs = func, args, kwargs
        self._dispatcher = None
        self.__name__, self.__qualname__, self.__doc__ = func.__name__, func.__qualname__, func.__doc__
        self.__module__ = func.__module__

    def _real(self):
        if self._dispatcher is None:
            with _starting():
                self._make_all()
        return self._dispatcher

    def _make_all(self):
        space = self.py_func.__globals__
        for name, obj in list(space.items()):
            if isinstance(obj, _Kernel) and obj.py_func.__globals__ is space and obj._dispatcher is None:
                obj._dispatcher = _compile(obj.py_func, obj._args, obj._kwargs)
                space[name] = obj._dispatcher
        if self._dispatcher is None:   # not bound to a module-level name
            self._dispatcher = _compile(self.py_func, self._args, self._kwargs)

    def __call__(self, *args):
        if getattr(_MODE, "plain", False):
            return self.py_func(*args)
        # the first call through the stand-in loads the compiled code from disk: numba's start too
        with _starting():
            return self._real()(*args)

    def __getattr__(self, name):
        return getattr(self._real(), name)


if HAVE_NUMBA:
    def njit(*args, **kwargs):
        """numba's njit, made when the kernel is first used (see :class:`_Kernel`)."""
        if args and callable(args[0]) and len(args) == 1 and not kwargs:
            return _Kernel(args[0], args, {})
        return lambda func: _Kernel(func, args, kwargs)
else:  # pragma: no cover - exercised only without numba
    def njit(*args, **kwargs):
        if args and callable(args[0]):
            return args[0]
        return lambda f: f

_NOTED: set = set()
_MODE = threading.local()
_FROZEN_AT_EXIT: list = []


@contextlib.contextmanager
def _starting():
    """numba's start (its import, a kernel's dispatcher, its first call) with the garbage collector
    off: nothing it makes is garbage, and a collection would only walk it. At the first, the heap is
    set to be frozen at exit, so that the interpreter's last collection does not walk it either."""
    was = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was:
            gc.enable()
        if not _FROZEN_AT_EXIT:
            import atexit
            atexit.register(gc.freeze)
            _FROZEN_AT_EXIT.append(True)


#: Seconds of plain-Python kernel time after which a process starts numba: its start with the
#: kernel's compiled code on disk (measured 0.40-0.46 s of CPU with the 45-point call that made it,
#: scipy.linalg not imported: :func:`_skip_blas_probe`), or compiling it (6-8 s) where there is none.
#: Either way at most twice the cost of the choice made in hindsight. The kernels' time is the
#: calling thread's CPU time, not the wall clock: on a loaded machine the wall clock stretches the
#: plain kernels' time, and numba was started earlier than the work asked for.
PLAIN_BUDGET = 0.4
COMPILE_BUDGET = 6.0
_SPENT = {"plain": 0.0}


def _compiled_on_disk(kernel) -> bool:
    """Whether numba's cache seems to hold ``kernel``: an index file by its name in the package's
    __pycache__ or under NUMBA_CACHE_DIR. A guess that only sets a budget (numba keys the index by
    the source's content, which an edited kernel no longer matches)."""
    import os
    from pathlib import Path

    func = getattr(kernel, "py_func", kernel)
    source = Path(func.__code__.co_filename)
    pattern = f"{source.stem}.{func.__qualname__}-*.nbi"
    where = os.environ.get("NUMBA_CACHE_DIR")
    try:
        return any(Path(where).rglob(pattern) if where else (source.parent / "__pycache__").glob(pattern))
    except OSError:
        return False


def _within_budget(kernel) -> bool:
    spent = _SPENT["plain"]
    if spent < PLAIN_BUDGET:
        return True
    if "warm" not in _SPENT:
        _SPENT["warm"] = _compiled_on_disk(kernel)
    return not _SPENT["warm"] and spent < COMPILE_BUDGET


def compiled(kernel):
    """The compiled dispatcher of ``kernel`` (made now if it is not yet), or the plain function
    without numba: what threads call, so that none of them compiles."""
    return kernel._real() if isinstance(kernel, _Kernel) else kernel


def worker_threads() -> int:
    """Processors this process may run on."""
    import os
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:   # pragma: no cover - not Linux
        return os.cpu_count() or 1


def call_kernel(n: int, limit: int, kernel, *args):
    """``kernel(*args)``, as plain Python when numba is not imported yet, ``n`` (the caller's
    measure of work, e.g. points) is at most ``limit`` and the process's plain-Python kernels have
    not yet taken what starting numba would (PLAIN_BUDGET, or COMPILE_BUDGET where nothing is
    compiled on disk); otherwise compiled as always. Where plain
    Python raises on what compiled code carries on with (an overflow to inf, a division by zero
    that numba also raises on, any ArithmeticError), the compiled kernel runs instead."""
    if (HAVE_NUMBA and n <= limit and "numba" not in sys.modules and not getattr(_MODE, "plain", False)
            and _within_budget(kernel)):
        import numpy as np

        _MODE.plain = True
        start = time.thread_time()
        try:
            with np.errstate(all="ignore"):   # compiled code warns about nothing
                return kernel(*args)
        except ArithmeticError:
            pass
        finally:
            _MODE.plain = False
            _SPENT["plain"] += time.thread_time() - start
    return kernel(*args)


def _skip_blas_probe() -> None:
    """Import numba's ``numba.np.arraymath`` without its probe for a BLAS, which imports
    ``scipy.linalg`` (a quarter of a second of CPU, a third of numba's start with the kernels on
    disk) only to choose the inner product of ``np.correlate`` and ``np.convolve``, which no kernel
    here uses: with the probe answering "none", those two fall back to numba's own loop. Every other
    use of BLAS in numba asks ``ensure_blas`` when it compiles, which is given back unchanged.
    Nothing happens where the module is already imported or scipy.linalg is (then the probe is free)."""
    if "numba.np.arraymath" in sys.modules or "scipy.linalg" in sys.modules:
        return
    try:
        from numba.np import linalg
    except ImportError:   # pragma: no cover - another numba layout: its own probe runs
        return
    probe = getattr(linalg, "ensure_blas", None)
    if probe is None:     # pragma: no cover - another numba layout
        return

    def absent():
        raise ImportError("BLAS not probed (restitution.fast.jit)")

    linalg.ensure_blas = absent
    try:
        from numba.np import arraymath
    finally:
        linalg.ensure_blas = probe
    if getattr(arraymath, "ensure_blas", None) is absent:
        arraymath.ensure_blas = probe


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


__all__ = ["HAVE_NUMBA", "njit", "call_kernel"]

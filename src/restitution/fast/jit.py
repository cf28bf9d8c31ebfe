"""numba's ``njit`` when numba is installed, else a no-op decorator: the compiled kernels
(:mod:`restitution.fast.integrator`, :mod:`restitution.fast.panels`) are also valid plain Python,
only much slower. ``HAVE_NUMBA`` says which.

A kernel compiled with ``cache=True`` is re-compiled when its own file changes, not when a file it
calls into does; so each kernel module calls only compiled functions of its own file.
"""

try:  # numba is an optional accelerator: everything below is also valid plain Python.
    from numba import njit

    HAVE_NUMBA = True
except ImportError:  # pragma: no cover - exercised only without numba
    HAVE_NUMBA = False

    def njit(*args, **kwargs):
        if args and callable(args[0]):
            return args[0]
        return lambda f: f


__all__ = ["HAVE_NUMBA", "njit"]

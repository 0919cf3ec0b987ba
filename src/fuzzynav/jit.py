"""The one way kernels are compiled (numba), with the on-disk cache."""

from __future__ import annotations

import numba


def jit(function):
    """``numba.njit`` with the on-disk cache and NumPy's floating-point error model (x / 0 is
    inf or nan, as in the rest of the package). The cache lives in ``__pycache__`` beside this
    package, or — when that is not writable (a read-only install) — in numba's user-wide cache
    directory (``NUMBA_CACHE_DIR`` overrides both); with no writable place at all, the kernels
    are compiled in memory at every start."""
    try:
        return numba.njit(cache=True, error_model="numpy")(function)
    except RuntimeError:  # "cannot cache function ...: no locator available"
        return numba.njit(error_model="numpy")(function)

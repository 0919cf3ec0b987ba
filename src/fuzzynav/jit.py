"""The one way kernels are compiled (numba), with the on-disk cache."""

from __future__ import annotations

import numba


def jit(function=None, *, fastmath: tuple = ()):
    """``numba.njit`` with the on-disk cache and NumPy's floating-point error model (x / 0 is
    inf or nan, as in the rest of the package). The cache lives in ``__pycache__`` beside this
    package, or — when that is not writable (a read-only install) — in numba's user-wide cache
    directory (``NUMBA_CACHE_DIR`` overrides both); with no writable place at all, the kernels
    are compiled in memory at every start.

    ``@jit(fastmath=("contract",))`` lets the compiler fuse a * b + c into one instruction (one
    rounding instead of two, where the processor has FMA): for polynomial kernels
    (:mod:`fuzzynav.fuzzy.engine.vmath`), whose last bits may then differ between processors
    (never between two runs on one)."""
    if function is None:
        return lambda f: jit(f, fastmath=fastmath)
    options = {"error_model": "numpy", "fastmath": set(fastmath) if fastmath else False}
    try:
        return numba.njit(cache=True, **options)(function)
    except RuntimeError:  # "cannot cache function ...: no locator available"
        return numba.njit(**options)(function)

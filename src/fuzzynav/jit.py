"""The one way kernels are compiled (numba), with the on-disk cache."""

from __future__ import annotations

import numba


def jit(function=None, *, fused_multiply_add: bool = False):
    """``numba.njit`` with the on-disk cache and NumPy's floating-point error model (x / 0 is
    inf or nan, as in the rest of the package). The cache lives in ``__pycache__`` beside this
    package, or — when that is not writable (a read-only install) — in numba's user-wide cache
    directory (``NUMBA_CACHE_DIR`` overrides both); with no writable place at all, the kernels
    are compiled in memory at every start.

    ``@jit(fused_multiply_add=True)`` lets the compiler fuse a * b + c into one instruction
    (one rounding instead of two, where the processor has FMA): for polynomial kernels whose
    last-ulp bits may differ between machines (:mod:`fuzzynav.fuzzy.engine.vmath`)."""
    if function is None:
        return lambda f: jit(f, fused_multiply_add=fused_multiply_add)
    options = {"error_model": "numpy", "fastmath": {"contract"} if fused_multiply_add else False}
    try:
        return numba.njit(cache=True, **options)(function)
    except RuntimeError:  # "cannot cache function ...: no locator available"
        return numba.njit(**options)(function)

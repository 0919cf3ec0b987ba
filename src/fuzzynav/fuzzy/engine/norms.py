"""The T-norms and S-norms of fuzzylite 8 (thesis §II.3), compiled: of two values and of two columns.

:func:`tnorm` / :func:`snorm` compute ``TNORMS[kind]`` / ``SNORMS[kind]`` of
:mod:`fuzzynav.fuzzy.operators` on two values, NaN-propagating as NumPy's ``maximum`` /
``minimum``; :func:`tnorm_into` / :func:`snorm_into` on two columns, one loop per norm so that
each loop vectorises. Used by the rule, aggregation and defuzzification kernels of
:mod:`.staged_kernels` and :mod:`.fused_kernel`.
"""

from __future__ import annotations

from fuzzynav.fuzzy.operators import SNORMS, TNORMS
from fuzzynav.jit import jit

MINIMUM, PRODUCT = TNORMS.index("Minimum"), TNORMS.index("AlgebraicProduct")
MAXIMUM, ALGEBRAIC_SUM = SNORMS.index("Maximum"), SNORMS.index("AlgebraicSum")


@jit
def nan_max(a, b):
    """max(a, b), NaN winning as in NumPy's ``maximum``."""
    return a if (a >= b or a != a) else b


@jit
def nan_min(a, b):
    """min(a, b), NaN winning as in NumPy's ``minimum``."""
    return a if (a <= b or a != a) else b


@jit
def tnorm(kind, a, b):
    """T-norm ``TNORMS[kind]`` of a and b."""
    if kind == 0:
        return a * b
    if kind == 1:
        return nan_max(0.0, a + b - 1.0)
    if kind == 2:
        return nan_min(a, b) if nan_max(a, b) == 1.0 else 0.0
    if kind == 3:
        return (a * b) / (2.0 - (a + b - a * b))
    if kind == 4:
        return (a * b) / (a + b - a * b) if a + b != 0.0 else 0.0
    if kind == 5:
        return nan_min(a, b)
    return nan_min(a, b) if a + b > 1.0 else 0.0


@jit
def snorm(kind, a, b):
    """S-norm ``SNORMS[kind]`` of a and b."""
    if kind == 0:
        return a + b - a * b
    if kind == 1:
        return nan_min(1.0, a + b)
    if kind == 2:
        return nan_max(a, b) if nan_min(a, b) == 0.0 else 1.0
    if kind == 3:
        return (a + b) / (1.0 + a * b)
    if kind == 4:
        return (a + b - 2.0 * a * b) / (1.0 - a * b) if a * b != 1.0 else 1.0
    if kind == 5:
        return nan_max(a, b)
    if kind == 6:
        return nan_max(a, b) if a + b < 1.0 else 1.0
    if kind == 7:
        return (a + b) / nan_max(1.0, a + b)
    return a + b


@jit
def tnorm_into(kind, a, b, out):
    """out ← T(a, b) elementwise (``out`` may be ``a``), one loop per T-norm: with the norm a
    constant, the loops vectorise."""
    if kind == 0:
        for i in range(out.shape[0]):
            out[i] = tnorm(0, a[i], b[i])
    elif kind == 1:
        for i in range(out.shape[0]):
            out[i] = tnorm(1, a[i], b[i])
    elif kind == 2:
        for i in range(out.shape[0]):
            out[i] = tnorm(2, a[i], b[i])
    elif kind == 3:
        for i in range(out.shape[0]):
            out[i] = tnorm(3, a[i], b[i])
    elif kind == 4:
        for i in range(out.shape[0]):
            out[i] = tnorm(4, a[i], b[i])
    elif kind == 5:
        for i in range(out.shape[0]):
            out[i] = tnorm(5, a[i], b[i])
    elif kind == 6:
        for i in range(out.shape[0]):
            out[i] = tnorm(6, a[i], b[i])


@jit
def conjoin_into(kind, a, b, c, d, more, out):
    """out ← T(T(T(a, b), c), d) (``more`` = 3) or T(T(a, b), c) (``more`` = 2) in one loop, for the
    product and the minimum: the bits of two or three :func:`tnorm_into`, with half or a third of
    their memory traffic. Returns whether it did (False, nothing written, for another T-norm)."""
    if kind == PRODUCT:
        for i in range(out.shape[0]):
            v = tnorm(PRODUCT, tnorm(PRODUCT, a[i], b[i]), c[i])
            out[i] = tnorm(PRODUCT, v, d[i]) if more == 3 else v
    elif kind == MINIMUM:
        for i in range(out.shape[0]):
            v = tnorm(MINIMUM, tnorm(MINIMUM, a[i], b[i]), c[i])
            out[i] = tnorm(MINIMUM, v, d[i]) if more == 3 else v
    else:
        return False
    return True


@jit
def snorm_into(kind, a, b, out):
    """out ← S(a, b) elementwise (``out`` may be ``a``), one loop per S-norm (see :func:`tnorm_into`)."""
    if kind == 0:
        for i in range(out.shape[0]):
            out[i] = snorm(0, a[i], b[i])
    elif kind == 1:
        for i in range(out.shape[0]):
            out[i] = snorm(1, a[i], b[i])
    elif kind == 2:
        for i in range(out.shape[0]):
            out[i] = snorm(2, a[i], b[i])
    elif kind == 3:
        for i in range(out.shape[0]):
            out[i] = snorm(3, a[i], b[i])
    elif kind == 4:
        for i in range(out.shape[0]):
            out[i] = snorm(4, a[i], b[i])
    elif kind == 5:
        for i in range(out.shape[0]):
            out[i] = snorm(5, a[i], b[i])
    elif kind == 6:
        for i in range(out.shape[0]):
            out[i] = snorm(6, a[i], b[i])
    elif kind == 7:
        for i in range(out.shape[0]):
            out[i] = snorm(7, a[i], b[i])
    elif kind == 8:
        for i in range(out.shape[0]):
            out[i] = snorm(8, a[i], b[i])

"""One-pass implication and aggregation of a Mamdani term over its samples, compiled.

:func:`fuzzynav.fuzzy.engine.staged_kernels.integral` otherwise implies a term (T-norm of the activation
degree and the term's samples, into a scratch array) and aggregates it (S-norm into the sampled
set) in two passes of the general norms; for the usual pairs of norms, where no NaN can occur
(activation degrees in [0, 1], samples within the term's support), these loops do both in one pass
with the same operations, so the same bits. Each is its own function, given whole arrays
(faster than the same loop on views made in the caller's row loop, or in one function of
several loops).
"""

from __future__ import annotations

from fuzzynav.fuzzy.engine.norms import PRODUCT
from fuzzynav.jit import jit


@jit
def stored(v):
    """v + 0: a maximum as stored back in place (the same value but −0, made +0). ``m[k] =
    max(m[k], v)`` as such lets LLVM store only where v is the larger, which it vectorises as masked
    stores (VMASKMOVPD: several times slower than plain stores on AMD processors); the addition,
    which it may not fold, keeps every store."""
    return v + 0.0


@jit
def max_min(mu, shapes, t, first, end, w):
    """mu ← max(mu, min(w, term t)) on the samples [first, end) (Minimum implication, Maximum
    aggregation)."""
    m, shape = mu[first:end], shapes[t, first:end]
    for k in range(m.shape[0]):
        m[k] = stored(max(m[k], min(w, shape[k])))


@jit
def max_product(mu, shapes, t, first, end, w):
    """mu ← max(mu, w × term t) on the samples [first, end) (AlgebraicProduct implication, Maximum
    aggregation)."""
    m, shape = mu[first:end], shapes[t, first:end]
    for k in range(m.shape[0]):
        m[k] = stored(max(m[k], w * shape[k]))


@jit
def sum_min(mu, shapes, t, first, end, w):
    """mu ← mu + i − mu i, i = min(w, term t), on the samples [first, end) (Minimum implication,
    AlgebraicSum aggregation)."""
    m, shape = mu[first:end], shapes[t, first:end]
    for k in range(m.shape[0]):
        i = min(w, shape[k])
        m[k] = m[k] + i - m[k] * i


@jit
def implication(w, sample, product):
    """min(w, sample), or w × sample for the AlgebraicProduct implication."""
    return w * sample if product else min(w, sample)


@jit
def max_four(mu, shapes, units, j, unit, w, first, end):
    """mu ← max(…max(max(mu, i₀), i₁)…, i₃) on the samples [first, end), i_q the implied term of
    unit u = ``units[j + q]`` (of ``unit``, a :class:`~.records.Units`: its term ``unit.term[u]``,
    degree ``w[u]``, the product or the minimum by ``unit.implication[u]``): four :func:`max_min` /
    :func:`max_product` passes in one, the same maxima in the same order (so the same bits), a
    quarter of the reads and writes of ``mu``."""
    unit_term, unit_implication = unit.term, unit.implication
    m = mu[first:end]
    u0, u1, u2, u3 = units[j], units[j + 1], units[j + 2], units[j + 3]
    s0, s1 = shapes[unit_term[u0], first:end], shapes[unit_term[u1], first:end]
    s2, s3 = shapes[unit_term[u2], first:end], shapes[unit_term[u3], first:end]
    p0, p1 = unit_implication[u0] == PRODUCT, unit_implication[u1] == PRODUCT
    p2, p3 = unit_implication[u2] == PRODUCT, unit_implication[u3] == PRODUCT
    w0, w1, w2, w3 = w[u0], w[u1], w[u2], w[u3]
    for k in range(m.shape[0]):
        v = max(m[k], implication(w0, s0[k], p0))
        v = max(v, implication(w1, s1[k], p1))
        v = max(v, implication(w2, s2[k], p2))
        m[k] = stored(max(v, implication(w3, s3[k], p3)))

"""One-pass implication and aggregation of a Mamdani term over its samples, compiled.

:func:`fuzzynav.fuzzy.engine.compiled.integral` otherwise implies a term (T-norm of the activation
degree and the term's samples, into a scratch array) and aggregates it (S-norm into the sampled
set) in two passes of the general norms; for the usual pairs of norms, where no NaN can occur
(activation degrees in [0, 1], samples within the term's support), these loops do both in one pass
with the same operations, so the same bits. Each is its own function, given whole arrays
(faster than the same loop on views made in the caller's row loop, or in one function of
several loops).
"""

from __future__ import annotations

from fuzzynav.jit import jit


@jit
def max_min(mu, shapes, t, first, end, w):
    """mu ← max(mu, min(w, term t)) on the samples [first, end) (Minimum implication, Maximum
    aggregation)."""
    m, shape = mu[first:end], shapes[t, first:end]
    for k in range(m.shape[0]):
        m[k] = max(m[k], min(w, shape[k]))


@jit
def max_product(mu, shapes, t, first, end, w):
    """mu ← max(mu, w × term t) on the samples [first, end) (AlgebraicProduct implication, Maximum
    aggregation)."""
    m, shape = mu[first:end], shapes[t, first:end]
    for k in range(m.shape[0]):
        m[k] = max(m[k], w * shape[k])


@jit
def sum_min(mu, shapes, t, first, end, w):
    """mu ← mu + i − mu i, i = min(w, term t), on the samples [first, end) (Minimum implication,
    AlgebraicSum aggregation)."""
    m, shape = mu[first:end], shapes[t, first:end]
    for k in range(m.shape[0]):
        i = min(w, shape[k])
        m[k] = m[k] + i - m[k] * i

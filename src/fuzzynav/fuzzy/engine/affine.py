"""A Takagi–Sugeno output where every activation triggers: Σ g z / Σ g over constant and linear terms.

:func:`every_row_affine` is :func:`~fuzzynav.fuzzy.engine.compiled.weighted_affine` for the
General activation: by chunks of rows that stay in cache, each term group's degree (its
activation's, or several folded with the output's S-norm), its value z = c₀ + c₁ x₁ + … + cₘ xₘ
and the sums num += g z, den += g, group after group; then num / den (times den for a weighted
sum). With one to four inputs (most of MATLAB's ANFIS systems), four groups go through one loop,
their values computed in it: each row's sums are read and written once for the four instead of
once for each, and z is never stored — the same operations in the same order (so the same bits),
a fraction of the memory traffic. Other groups go one loop each.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.fuzzy.engine.norms import snorm_into
from fuzzynav.jit import jit

CHUNK = 1024  # rows a chunked kernel (rule degrees, constant / linear outputs) takes at a time
TILE = 4  # groups a loop of :func:`_four_groups` takes, of at most TILE inputs


@jit
def _add_weighted(d, z, num, den):
    """num += d z, den += d (its own function, so that the loop vectorises: inline it did not)."""
    for k in range(d.shape[0]):
        num[k] += d[k] * z[k]
        den[k] += d[k]


@jit
def _add_weighted_linear(d, z, c, x, num, den):
    """num += d (z + c x), den += d: :func:`_add_weighted` with the value's last term added in the same loop."""
    for k in range(d.shape[0]):
        num[k] += d[k] * (z[k] + c * x[k])
        den[k] += d[k]


@jit
def _linear_start(z, constant, c, x):
    """z = constant + c x: a linear value's first two terms in one loop."""
    for k in range(z.shape[0]):
        z[k] = constant + c * x[k]


@jit
def _group_rows(rows, groups, n_groups):
    """Per group: its first activation's row of degrees and its number of activations."""
    first, count = np.zeros(n_groups, dtype=np.int64), np.zeros(n_groups, dtype=np.int64)
    for a in range(rows.shape[0]):
        g = groups[a]
        if count[g] == 0:
            first[g] = rows[a]
        count[g] += 1
    return first, count


@jit
def _group_degree(degrees, rows, groups, aggregation, g, first, count, lo, hi, folded):
    """Group g's degree on rows [lo, hi): its one activation's row of ``degrees`` (no copy), or its
    activations folded in order with the S-norm ``aggregation`` into ``folded``."""
    if count == 1:
        return degrees[first, lo:hi]
    seen = 0
    for a in range(rows.shape[0]):
        if groups[a] == g:
            if seen > 0:  # the second activation folds the first into ``folded``
                snorm_into(aggregation, degrees[first, lo:hi] if seen == 1 else folded, degrees[rows[a], lo:hi], folded)
            seen += 1
    return folded


@jit
def _terms(coefficients, constants, g):
    """Group g's constant and first four coefficients (its last repeated where it has fewer)."""
    row, last = coefficients[g], coefficients.shape[1] - 1
    return constants[g], row[0], row[min(1, last)], row[min(2, last)], row[min(3, last)]


@jit
def _value(c, m, u, v, t, r):
    """z = ((c₀ + c₁ u) + c₂ v) + … over the first m of the inputs u, v, t, r."""
    z = c[0] + c[1] * u
    if m > 1:
        z = z + c[2] * v
    if m > 2:
        z = z + c[3] * t
    if m > 3:
        z = z + c[4] * r
    return z


@jit
def _four_groups(d0, d1, d2, d3, coefficients, constants, g, x0, x1, x2, x3, num, den):
    """num += g z, den += g for the groups g … g + 3 (degrees d0 … d3) in order, each z
    (:func:`_value`) of the m = 1 to 4 inputs computed in the loop."""
    m = coefficients.shape[1]  # the coefficients as scalars before the loop (the arrays might alias num, den)
    a, b, c, e = (_terms(coefficients, constants, g), _terms(coefficients, constants, g + 1),
                  _terms(coefficients, constants, g + 2), _terms(coefficients, constants, g + 3))
    for k in range(num.shape[0]):
        u, v, t, r = x0[k], x1[k], x2[k], x3[k]
        s, w = num[k], den[k]
        s = s + d0[k] * _value(a, m, u, v, t, r)
        w = w + d0[k]
        s = s + d1[k] * _value(b, m, u, v, t, r)
        w = w + d1[k]
        s = s + d2[k] * _value(c, m, u, v, t, r)
        w = w + d2[k]
        s = s + d3[k] * _value(e, m, u, v, t, r)
        num[k], den[k] = s, w + d3[k]


@jit
def every_row_affine(degrees, rows, groups, aggregation, coefficients, constants, inputs, weighted_sum, out):
    """``out``: Σ g z / Σ g (× Σ g for a weighted sum; NaN without groups) on every row, activation
    a of degree ``degrees[rows[a]]`` in group ``groups[a]``, group g's value z the constant
    ``constants[g]`` plus ``coefficients[g]`` · the ``inputs`` (n_inputs, N) (module docstring)."""
    n_groups, n, m = coefficients.shape[0], out.shape[0], coefficients.shape[1]
    tiled = n_groups - n_groups % TILE if 1 <= m <= TILE else 0  # groups that go four by four
    first, count = _group_rows(rows, groups, n_groups)
    folded = np.empty((TILE, CHUNK))
    z, num, den = np.empty(CHUNK), np.empty(CHUNK), np.empty(CHUNK)
    for lo in range(0, n, CHUNK):
        hi = min(n, lo + CHUNK)
        size = hi - lo
        num[:size] = 0.0
        den[:size] = 0.0
        for g in range(0, tiled, TILE):
            d0 = _group_degree(degrees, rows, groups, aggregation, g, first[g], count[g], lo, hi,
                               folded[0, :size])
            d1 = _group_degree(degrees, rows, groups, aggregation, g + 1, first[g + 1], count[g + 1], lo, hi,
                               folded[1, :size])
            d2 = _group_degree(degrees, rows, groups, aggregation, g + 2, first[g + 2], count[g + 2], lo, hi,
                               folded[2, :size])
            d3 = _group_degree(degrees, rows, groups, aggregation, g + 3, first[g + 3], count[g + 3], lo, hi,
                               folded[3, :size])
            _four_groups(d0, d1, d2, d3, coefficients, constants, g, inputs[0, lo:hi], inputs[min(1, m - 1), lo:hi],
                         inputs[min(2, m - 1), lo:hi], inputs[min(3, m - 1), lo:hi], num[:size], den[:size])
        for g in range(tiled, n_groups):
            d = _group_degree(degrees, rows, groups, aggregation, g, first[g], count[g], lo, hi, folded[0, :size])
            zg = z[:size]  # z = ((c₀ + c₁ x₁) + c₂ x₂) + …, its last term added with the sums
            if m <= 1:
                zg[:] = constants[g]
            else:
                _linear_start(zg, constants[g], coefficients[g, 0], inputs[0, lo:hi])
            for i in range(1, m - 1):
                c, x = coefficients[g, i], inputs[i, lo:hi]
                for k in range(size):
                    zg[k] += c * x[k]
            if m == 0:
                _add_weighted(d, zg, num[:size], den[:size])
            else:
                _add_weighted_linear(d, zg, coefficients[g, m - 1], inputs[m - 1, lo:hi], num[:size], den[:size])
        for k in range(size):
            y = num[k] / den[k]
            out[lo + k] = (y * den[k] if weighted_sum else y) if n_groups > 0 else np.nan

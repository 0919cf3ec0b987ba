"""A Takagi–Sugeno output where every activation triggers: Σ g z / Σ g over constant and linear terms.

:func:`every_row_affine` is :func:`~fuzzynav.fuzzy.engine.staged_kernels.weighted_affine` for the
General activation: by chunks of rows that stay in cache, each term group's degree (its
activation's, or several folded with the output's S-norm), its value z = c₀ + c₁ x₁ + … + cₘ xₘ
and the sums num += g z, den += g, group after group; then num / den (times den for a weighted
sum). With one to four inputs (most of MATLAB's ANFIS systems), four groups go through one loop,
their values computed in it: each row's sums are read and written once for the four instead of
once for each, and z is never stored — the same operations in the same order (so the same bits),
a fraction of the memory traffic. Other groups go one loop each. A group whose one activation is
a rule p and q left to its output (:mod:`.pack`, MATLAB's ANFIS grids) multiplies p q in that
loop: the rule's degree is never stored either.
"""

from __future__ import annotations

import numpy as np
from numba import literally

from fuzzynav.fuzzy.engine.norms import PRODUCT, snorm_into, tnorm_into
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
def _group_rows(rows, partners, groups, n_groups):
    """Per group: its first activation's row of degrees and partner, and its number of activations."""
    first, partner, count = (np.zeros(n_groups, dtype=np.int64), np.zeros(n_groups, dtype=np.int64),
                             np.zeros(n_groups, dtype=np.int64))
    for a in range(rows.shape[0]):
        g = groups[a]
        if count[g] == 0:
            first[g], partner[g] = rows[a], partners[a]
        count[g] += 1
    return first, partner, count


@jit
def _group_degree(degrees, grouping, g, heads, lo, hi, folded, ones):
    """Group g's degree on rows [lo, hi) as two factors (no copy): its one activation's row of
    ``degrees`` and the row ``partner`` where it has one (a deferred rule), else ``ones`` (× 1
    changes no bit); or its activations folded in order with the S-norm ``aggregation`` into
    ``folded``, and ``ones`` (``grouping`` a :class:`~.records.Groups`, ``heads`` the arrays of
    :func:`_group_rows`)."""
    rows, groups, aggregation = grouping.rows, grouping.groups, grouping.aggregation
    first, partner, count = heads[0][g], heads[1][g], heads[2][g]
    if count == 1:
        return degrees[first, lo:hi], degrees[partner, lo:hi] if partner >= 0 else ones
    seen = 0
    for a in range(rows.shape[0]):
        if groups[a] == g:
            if seen > 0:  # the second activation folds the first into ``folded``
                snorm_into(aggregation, degrees[first, lo:hi] if seen == 1 else folded, degrees[rows[a], lo:hi], folded)
            seen += 1
    return folded, ones


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
def _degree(d, f, paired, k):
    """d[k] f[k], or d[k] where not ``paired`` (the loop is compiled once for each: no reading f)."""
    return d[k] * f[k] if paired else d[k]


@jit
def _four_groups(paired, tile, coefficients, constants, g, x, num, den):
    """num += d z, den += d for the groups g … g + 3 in order, of degrees d = d0 f0 … d3 f3
    (``tile`` = (d0, f0, …, d3, f3), :func:`_group_degree`'s factors; d0 … d3 alone unless
    ``paired``) and values z (:func:`_value`) of the m = 1 to 4 inputs ``x``, both computed in the loop."""
    literally(paired)  # compiled once for each value: the loop not paired reads no f
    d0, f0, d1, f1, d2, f2, d3, f3 = tile
    x0, x1, x2, x3 = x
    m = coefficients.shape[1]  # the coefficients as scalars before the loop (the arrays might alias num, den)
    a, b, c, e = (_terms(coefficients, constants, g), _terms(coefficients, constants, g + 1),
                  _terms(coefficients, constants, g + 2), _terms(coefficients, constants, g + 3))
    for k in range(num.shape[0]):
        u, v, t, r = x0[k], x1[k], x2[k], x3[k]
        s, w = num[k], den[k]
        g0, g1, g2, g3 = _degree(d0, f0, paired, k), _degree(d1, f1, paired, k), _degree(d2, f2, paired, k), \
            _degree(d3, f3, paired, k)
        s = s + g0 * _value(a, m, u, v, t, r)
        w = w + g0
        s = s + g1 * _value(b, m, u, v, t, r)
        w = w + g1
        s = s + g2 * _value(c, m, u, v, t, r)
        w = w + g2
        s = s + g3 * _value(e, m, u, v, t, r)
        num[k], den[k] = s, w + g3


@jit
def every_row_affine(degrees, grouping, partners, terms, inputs, weighted_sum, out):
    """``out``: Σ g z / Σ g (× Σ g for a weighted sum; NaN without groups) on every row, activation
    a of degree ``degrees[rows[a]]`` (times ``degrees[partners[a]]`` where that is not −1: a
    deferred rule, alone in its group) in group ``groups[a]`` (``grouping``, a
    :class:`~.records.Groups`, its triggers not read), group g's value z the constant
    ``constants[g]`` plus ``coefficients[g]`` · the ``inputs`` (n_inputs, N) (``terms``, a
    :class:`~.records.Affine`; module docstring)."""
    coefficients, constants = terms.coefficients, terms.constants
    n_groups, n, m = coefficients.shape[0], out.shape[0], coefficients.shape[1]
    tiled = n_groups - n_groups % TILE if 1 <= m <= TILE else 0  # groups that go four by four
    heads = _group_rows(grouping.rows, partners, grouping.groups, n_groups)
    _, partner, count = heads
    folded, ones = np.empty((TILE, CHUNK)), np.ones(CHUNK)
    z, num, den = np.empty(CHUNK), np.empty(CHUNK), np.empty(CHUNK)
    for lo in range(0, n, CHUNK):
        hi = min(n, lo + CHUNK)
        size = hi - lo
        num[:size] = 0.0
        den[:size] = 0.0
        for g in range(0, tiled, TILE):
            d0, f0 = _group_degree(degrees, grouping, g, heads, lo, hi, folded[0, :size], ones[:size])
            d1, f1 = _group_degree(degrees, grouping, g + 1, heads, lo, hi, folded[1, :size], ones[:size])
            d2, f2 = _group_degree(degrees, grouping, g + 2, heads, lo, hi, folded[2, :size], ones[:size])
            d3, f3 = _group_degree(degrees, grouping, g + 3, heads, lo, hi, folded[3, :size], ones[:size])
            tile = (d0, f0, d1, f1, d2, f2, d3, f3)
            x = (inputs[0, lo:hi], inputs[min(1, m - 1), lo:hi], inputs[min(2, m - 1), lo:hi],
                 inputs[min(3, m - 1), lo:hi])
            if max(partner[g], partner[g + 1], partner[g + 2], partner[g + 3]) >= 0:
                _four_groups(True, tile, coefficients, constants, g, x, num[:size], den[:size])
            else:
                _four_groups(False, tile, coefficients, constants, g, x, num[:size], den[:size])
        for g in range(tiled, n_groups):
            d, f = _group_degree(degrees, grouping, g, heads, lo, hi, folded[0, :size], ones[:size])
            if partner[g] >= 0 and count[g] == 1:
                tnorm_into(PRODUCT, d, f, folded[1, :size])  # the deferred rule's degree, as the rule pass writes it
                d = folded[1, :size]
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

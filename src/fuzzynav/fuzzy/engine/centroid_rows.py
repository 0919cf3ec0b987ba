"""The centroid of a Mamdani output of Maximum aggregation, computed across rows, compiled.

:func:`fuzzynav.fuzzy.engine.staged_kernels.integral` otherwise works row by row: each row's units
imply and max-combine their terms over the samples, then the centroid's eight lane sums
(:func:`~.sampled_defuzzify.centroid_sums`). Where every unit implies by the minimum or the product a term
whose samples all lie in [0, 1], the same numbers can be computed for a block of rows at once,
sample after sample, each step a loop over the rows: the units' degrees (the maximum of their
activations'), μ of the sample (every unit whose term's support holds it, max-combined in unit
order), then its lane sum (sample k in lane k mod 8). The same operations in the same order on
every value, and zeros only where the row-by-row pass skips (a unit of degree 0, a sample outside
the supports: max(μ, 0) = μ, s + 0 = s), so the same bits; but the loops are as long as the block
rather than a term's support, and nothing is paid per row. A row whose degrees are not all in
[0, 1] (NaN among them) is left to the row-by-row pass, which samples every term everywhere there.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.fuzzy.engine.implication import implication, stored
from fuzzynav.fuzzy.engine.norms import MINIMUM, PRODUCT
from fuzzynav.fuzzy.engine.records import Lanes
from fuzzynav.jit import jit

BLOCK = 128  # rows at a time: the units' degrees and the sixteen lane sums stay in the L1 cache
WORK_PER_ROW = 400  # values a row beyond which the row-by-row pass is faster (see applies)


@jit
def applies(unit_term, unit_implication, support, size):
    """Whether :func:`max_centroid` takes an output of these units and ``size`` samples: every one
    implies by the minimum or the product a term whose samples lie in [0, 1] (its support known),
    and their supports are short enough that its loops, one per unit and one more for each sample
    a support holds, cost less than the row-by-row pass's own cost per row (at most
    ``WORK_PER_ROW`` values a row: sparse outputs, such as a partition of triangles; measured in
    the README)."""
    work, held = 0, np.zeros(size, dtype=np.bool_)
    for u in range(unit_term.shape[0]):
        imp, (first, end) = unit_implication[u], (support[unit_term[u], 0], support[unit_term[u], 1])
        if first < 0 or not (imp == MINIMUM or imp == PRODUCT):
            return False
        work += end - first
        held[first:end] = True
    return work + held.sum() <= WORK_PER_ROW


@jit
def _unit_degrees(degrees, rows, units, r0, m, w):
    """``w[u, :m]``: the largest degree of unit u's activations on rows r0 … r0 + m − 1 (NaN wins)."""
    w[:, :m] = -np.inf
    for a in range(rows.shape[0]):
        d, wu = degrees[rows[a], r0:r0 + m], w[units[a], :m]
        for r in range(m):
            v = d[r]
            wu[r] = stored(v if v > wu[r] or v != v else wu[r])  # every row stored: no masked store


@jit
def _bounded(w, r, n_units):
    """Whether every unit's degree on row r lies in [0, 1] (no NaN)."""
    for u in range(n_units):
        if not 0.0 <= w[u, r] <= 1.0:
            return False
    return True


@jit
def _max_implied(mu, w, u, s, product, opened, m):
    """mu[r] ← max(mu[r], min(w[u, r], s)) (or w[u, r] × s) for the first m rows, s one sample of
    unit u's term; mu is 0 where not ``opened`` (max(0, ·), as the row-by-row pass from its zeros).
    Indexed in place: a view a sample would cost more than its loop."""
    for r in range(m):
        mu[r] = stored(max(mu[r] if opened else 0.0, implication(w[u, r], s, product)))


@jit
def _add_to_lane(mu, at, lane, totals, moments, m):
    """totals[lane] += μ, moments[lane] += μ x over the first m rows: one sample's share of its lane's sums."""
    for r in range(m):
        totals[lane, r] += mu[r]
        moments[lane, r] += mu[r] * at


@jit
def _one_unit_to_lane(w, u, s, product, at, lane, sums, m):
    """A sample only unit u's term's support holds: its μ, max(0, min(w[u, r], s)) (or the
    product), straight into its lane's ``sums`` (a :class:`~.records.Lanes`) — :func:`_max_implied`
    then :func:`_add_to_lane` in one loop."""
    totals, moments = sums.totals, sums.moments
    for r in range(m):
        mu = stored(max(0.0, implication(w[u, r], s, product)))
        totals[lane, r] += mu
        moments[lane, r] += mu * at


@jit
def _lanes_total(lanes, r):
    """((l0 + l1) + (l2 + l3)) + ((l4 + l5) + (l6 + l7)) of row r's eight lane sums."""
    return ((lanes[0, r] + lanes[1, r]) + (lanes[2, r] + lanes[3, r])) + \
        ((lanes[4, r] + lanes[5, r]) + (lanes[6, r] + lanes[7, r]))


@jit
def max_centroid(degrees, rows, unit, sampled, out, unbounded):
    """``out[n]``: the centroid of row n of an output :func:`applies` takes (the arguments of
    :func:`~.staged_kernels.integral`), block of rows by block of rows (module docstring); returns the
    number of rows whose degrees are not all in [0, 1], their indices in ``unbounded`` (their
    ``out`` left to the row-by-row pass)."""
    units, unit_term, unit_implication = unit.of, unit.term, unit.implication
    shapes, support, x = sampled.shapes, sampled.support, sampled.x
    n_units, n = unit_term.shape[0], degrees.shape[1]
    first, end = x.shape[0], 0
    for u in range(n_units):
        first, end = min(first, support[unit_term[u], 0]), max(end, support[unit_term[u], 1])
    w, mu = np.empty((n_units, BLOCK)), np.empty(BLOCK)
    totals, moments = np.empty((8, BLOCK)), np.empty((8, BLOCK))
    sums = Lanes(totals, moments)
    count = 0
    for r0 in range(0, n, BLOCK):
        m = min(BLOCK, n - r0)
        _unit_degrees(degrees, rows, units, r0, m, w)
        totals[:, :m] = 0.0
        moments[:, :m] = 0.0
        for k in range(first, end):
            held, only = 0, 0  # how many terms' supports hold sample k (none: it is 0, nothing to add)
            for u in range(n_units):
                if support[unit_term[u], 0] <= k < support[unit_term[u], 1]:
                    held, only = held + 1, u
            if held == 1:
                _one_unit_to_lane(w, only, shapes[unit_term[only], k], unit_implication[only] == PRODUCT, x[k], k % 8,
                                  sums, m)
                continue
            opened = False
            for u in range(n_units):
                t = unit_term[u]
                if support[t, 0] <= k < support[t, 1]:
                    _max_implied(mu, w, u, shapes[t, k], unit_implication[u] == PRODUCT, opened, m)
                    opened = True
            if opened:
                _add_to_lane(mu, x[k], k % 8, totals, moments, m)
        for r in range(m):
            out[r0 + r] = _lanes_total(moments, r) / _lanes_total(totals, r)
            if not _bounded(w, r, n_units):
                unbounded[count] = r0 + r
                count += 1
    return count

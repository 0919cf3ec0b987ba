"""The reductions of a sampled Mamdani output (fuzzylite 8's integral defuzzifiers), compiled.

:func:`reduce_sampled` turns the aggregated set, sampled at the defuzzifier's points, into the
crisp value: centroid Σ μ x / Σ μ, bisector (the samples where the running area is closest to half
of it, averaged; sampled MATLAB's way, the first sample where it reaches half, as MATLAB's
``defuzzBisector``), mean / smallest / largest of the samples of maximum membership (sampled
MATLAB's way, smallest / largest in magnitude, the first on ties, as its ``defuzzSmallestOfMax``);
NaN for an empty set. Used row by row by :func:`fuzzynav.fuzzy.engine.staged_kernels.integral`.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.fuzzy.engine.centroid_lanes import lane_sums
from fuzzynav.jit import jit

REDUCTIONS = ("Centroid", "Bisector", "MeanOfMaximum", "SmallestOfMaximum", "LargestOfMaximum")
# the reductions MATLAB computes otherwise, on its samples (grid linspace): module docstring
MATLAB_BISECTOR, MATLAB_SMALLEST, MATLAB_LARGEST = len(REDUCTIONS), len(REDUCTIONS) + 1, len(REDUCTIONS) + 2
MATLAB_REDUCTIONS = {"Bisector": MATLAB_BISECTOR, "SmallestOfMaximum": MATLAB_SMALLEST,
                     "LargestOfMaximum": MATLAB_LARGEST}


def reduction_of(defuzzifier) -> int:
    """The ``kind`` :func:`reduce_sampled` takes for an integral ``defuzzifier``: its index in
    :data:`REDUCTIONS`, or MATLAB's reduction of it for one sampled MATLAB's way."""
    if defuzzifier.grid == "linspace" and defuzzifier.kind in MATLAB_REDUCTIONS:
        return MATLAB_REDUCTIONS[defuzzifier.kind]
    return REDUCTIONS.index(defuzzifier.kind)


@jit
def centroid_sums(mu, x, lo, hi):
    """(Σ μ, Σ μ x) over the samples [lo, hi) of ``mu``, which is 0 elsewhere (and padded with zeros,
    as ``x``, to a multiple of 8 samples): eight running sums, sample k in sum k mod 8 (eight
    independent additions per step instead of a chain of dependent ones), added pairwise, as
    vector instructions (:func:`~.centroid_lanes.lane_sums`). Anchored on the sample index, so any
    [lo, hi) holding the non-zero samples gives the same bits."""
    return lane_sums(mu, x, lo - lo % 8, hi + (-hi) % 8)


@jit
def _top(mu, lo, hi):
    """The largest of ``mu[lo:hi]`` (no NaN there; 0 if empty): eight running maxima."""
    first, end = lo - lo % 8, hi + (-hi) % 8
    t0 = t1 = t2 = t3 = t4 = t5 = t6 = t7 = 0.0
    for k in range(first, end, 8):
        t0, t1, t2, t3 = max(t0, mu[k]), max(t1, mu[k + 1]), max(t2, mu[k + 2]), max(t3, mu[k + 3])
        t4, t5, t6, t7 = max(t4, mu[k + 4]), max(t5, mu[k + 5]), max(t6, mu[k + 6]), max(t7, mu[k + 7])
    return max(max(max(t0, t1), max(t2, t3)), max(max(t4, t5), max(t6, t7)))


@jit
def padded(size):
    """The length of the sample arrays :func:`reduce_sampled` reads: ``size`` rounded up to 8."""
    return size + (-size) % 8


@jit
def reduce_sampled(kind, mu, x, area, lo, hi, size):
    """``REDUCTIONS[kind]`` of the sampled set ``mu`` at ``x`` (NaN when it is empty), which is 0
    outside samples [lo, hi); ``area`` (as long as ``mu``) is scratch; ``mu`` and ``x`` are padded
    with zeros beyond them to a multiple of 8 (see :func:`padded`), ``size`` samples before."""
    if kind == 0:
        total, moment = centroid_sums(mu, x, lo, hi)
        return moment / total
    if kind == 1:  # the samples where the running area is closest to half of it, averaged
        total = 0.0
        for k in range(size):
            if mu[k] == mu[k]:
                total += mu[k]
            area[k] = total
        best = np.inf
        for k in range(size):
            gap = abs(area[k] / total - 0.5)
            if gap != gap:
                return np.nan
            best = min(best, gap)
        count, where = 0, 0.0
        for k in range(size):
            if abs(area[k] / total - 0.5) == best:
                count += 1
                where += x[k]
        return where / count if count > 0 else np.nan
    if kind == MATLAB_BISECTOR:  # the first sample where the running area reaches half of it
        total = 0.0
        for k in range(size):
            total += mu[k]
        if not total > 0.0:
            return np.nan
        running = 0.0
        for k in range(size):
            running += mu[k]
            if running >= total / 2:
                return x[k]
        return x[size - 1]
    nan = False
    for k in range(lo, hi):
        nan |= mu[k] != mu[k]
    if nan:
        return np.nan
    top = _top(mu, lo, hi)
    if not top > 0.0:
        return np.nan
    if kind == MATLAB_SMALLEST or kind == MATLAB_LARGEST:  # by magnitude, the first sample on ties
        best = -1
        for k in range(lo, hi):
            if mu[k] == top and (best < 0 or (abs(x[k]) < abs(x[best]) if kind == MATLAB_SMALLEST
                                              else abs(x[k]) > abs(x[best]))):
                best = k
        return x[best]
    if kind == 2:  # the samples of maximum membership (area: 1 there, else 0), averaged
        first, end = lo - lo % 8, hi + (-hi) % 8
        for k in range(first, end):
            area[k] = 1.0 if mu[k] == top else 0.0
        count, where = centroid_sums(area, x, lo, hi)
        return where / count
    step = 1 if kind == 3 else -1
    k = lo if kind == 3 else hi - 1
    while mu[k] != top:
        k += step
    return x[k]

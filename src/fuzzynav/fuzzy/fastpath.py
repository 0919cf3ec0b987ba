"""Fast TS0 kernel for piecewise-linear input partitions (thesis §IV.3, eqs IV.4–IV.5).

When every input term is a continuous piecewise-linear function (triangles, trapezoids,
shoulders — the thesis' strong partitions), each membership is an exact linear interpolation
between the breakpoints of its variable. One bisection per input finds the interval; only the
terms that are non-zero on it fire (two for a strong triangular partition), so a two-input grid
evaluates 2 × 2 = 4 of its 35 rules instead of all. The rule base is folded into a dense table
over the term grid: ``num[o][cell] = Σ_r weight_r b_ro`` and ``den[o][cell] = Σ_r weight_r`` over
the rules r whose premises select ``cell`` (an input a rule leaves out selects all its terms).

The same kernel serves the batch path (NumPy, ``evaluate``) and a plain-Python scalar path
(``evaluate_one``, a few microseconds). Results equal the generic kernels of
:mod:`fuzzynav.fuzzy.inference` to rounding (tested).
"""

from __future__ import annotations

import math
from bisect import bisect_right

import numpy as np

from fuzzynav.fuzzy.membership import Trapezoidal

MAX_TABLE_CELLS = 1 << 20
MAX_LOOKUP_CELLS = 1 << 16
_CHECK_FRACTIONS = np.array([0.25, 0.5, 0.75])


class _InputPartition:
    """Breakpoints of one input and, per interval, the active terms with their end memberships."""

    def __init__(self, variable, stride: int):
        lo, hi = variable.universe
        inner = {b for mf in variable.terms.values() for b in mf.breakpoints() if lo < b < hi}
        self.bp = np.array(sorted(inner | {lo, hi}))
        self.lo, self.hi = lo, hi
        mu = variable.fuzzify(self.bp, clamp=False)  # (n_bp, n_terms)
        left, right = mu[:-1], mu[1:]
        active = [np.flatnonzero((left[k] > 0) | (right[k] > 0)) for k in range(len(self.bp) - 1)]
        slots = max(1, max(len(a) for a in active))
        n_int = len(active)
        self.term = np.zeros((slots, n_int), dtype=np.intp)
        self.ml = np.zeros((slots, n_int))
        self.dm = np.zeros((slots, n_int))
        for k, idx in enumerate(active):
            self.term[: len(idx), k] = idx * stride
            self.ml[: len(idx), k] = left[k, idx]
            self.dm[: len(idx), k] = right[k, idx] - left[k, idx]
        self.inv_width = 1.0 / np.diff(self.bp)
        self._build_lookup()
        # plain-Python copies for the scalar path
        self.bp_list = self.bp.tolist()
        self.n_int = n_int
        self.inv_width_list = self.inv_width.tolist()
        self.intervals = [
            [(int(self.term[s, k]), float(self.ml[s, k]), float(self.dm[s, k])) for s in range(len(active[k]))]
            for k in range(n_int)
        ]

    def _build_lookup(self) -> None:
        """Uniform lookup grid finer than the smallest interval: interval = lut[cell] ± 1.

        Replaces a binary search per element (``np.searchsorted``) by a multiply, a gather and
        two comparisons; falls back to the search when the grid would be too large.
        """
        gap = float(np.diff(self.bp).min())
        cells = int(math.ceil((self.hi - self.lo) / (0.5 * gap))) + 1
        self.inner = self.bp[1:-1].copy()
        self.lut = None
        if cells <= MAX_LOOKUP_CELLS:
            self.inv_h = cells / (self.hi - self.lo)
            edges = self.lo + np.arange(cells + 1) / self.inv_h
            self.lut = np.searchsorted(self.inner, edges, side="right")
            self.left_edge = self.bp[:-1].copy()
            self.right_edge = np.append(self.inner, math.inf)

    def locate(self, x: np.ndarray) -> np.ndarray:
        """Interval index k (0 … n_int − 1) with bp[k] <= x < bp[k+1] for clamped ``x``."""
        if self.lut is None:
            return np.searchsorted(self.inner, x, side="right")
        k = np.take(self.lut, ((x - self.lo) * self.inv_h).astype(np.intp))
        k += x >= np.take(self.right_edge, k)
        k -= x < np.take(self.left_edge, k)
        return k

    @staticmethod
    def exact_for(variable) -> bool:
        """True if linear interpolation between breakpoints reproduces every term exactly."""
        if not all(isinstance(mf, Trapezoidal) for mf in variable.terms.values()):
            return False
        lo, hi = variable.universe
        inner = {b for mf in variable.terms.values() for b in mf.breakpoints() if lo < b < hi}
        bp = np.array(sorted(inner | {lo, hi}))
        mu = variable.fuzzify(bp, clamp=False)
        widths = np.diff(bp)
        x = (bp[:-1, None] + widths[:, None] * _CHECK_FRACTIONS).ravel()
        expected = (mu[:-1, None, :] + (mu[1:] - mu[:-1])[:, None, :] * _CHECK_FRACTIONS[None, :, None])
        # one-sided limits at every breakpoint catch jumps (vertical edges inside the universe)
        near = np.concatenate([np.nextafter(bp[1:], -np.inf), np.nextafter(bp[:-1], np.inf)])
        near_expected = np.concatenate([mu[1:], mu[:-1]])
        return bool(
            np.allclose(variable.fuzzify(x, clamp=False), expected.reshape(-1, mu.shape[1]), rtol=0, atol=1e-12)
            and np.allclose(variable.fuzzify(near, clamp=False), near_expected, rtol=0, atol=1e-9)
        )


class StrongPartitionKernel:
    """Compiled TS0 evaluator; build it with :meth:`build` (``None`` when it does not apply)."""

    def __init__(self, inputs, premises, conclusions, weights, values, tnorm, defuzzifier):
        sizes = [len(v.terms) for v in inputs]
        strides = [int(np.prod(sizes[i + 1 :], dtype=np.int64)) for i in range(len(sizes))]
        self.parts = [_InputPartition(v, s) for v, s in zip(inputs, strides)]
        self.product = tnorm == "product"
        self.average = defuzzifier == "weighted_average"
        n_cells, n_out = int(np.prod(sizes, dtype=np.int64)), conclusions.shape[1]
        num = np.zeros((n_out, n_cells))
        den = np.zeros((n_out, n_cells))
        grid = [np.arange(n) for n in sizes]
        for r in range(premises.shape[0]):
            axes = [grid[i] if premises[r, i] < 0 else premises[r, i : i + 1] for i in range(len(sizes))]
            cells = np.ravel_multi_index(np.meshgrid(*axes, indexing="ij"), sizes).ravel()
            for o in range(n_out):
                if conclusions[r, o] >= 0:
                    np.add.at(num[o], cells, weights[r] * values[r, o])
                    np.add.at(den[o], cells, weights[r])
        self.num, self.den = num, den
        self.num_list = [row.tolist() for row in num]
        self.den_list = [row.tolist() for row in den]

    @classmethod
    def build(cls, system) -> StrongPartitionKernel | None:
        """The kernel for a TS0 ``system`` whose inputs are all piecewise-linear, else ``None``."""
        if system.method != "ts0" or system.defuzzifier not in ("weighted_sum", "weighted_average"):
            return None
        n_cells = math.prod(len(v.terms) for v in system.inputs)
        if n_cells > MAX_TABLE_CELLS or not all(_InputPartition.exact_for(v) for v in system.inputs):
            return None
        c = system.compiled
        return cls(system.inputs, c.premises, c.conclusions, c.weights, c.values, system.tnorm, system.defuzzifier)

    def evaluate(self, X: np.ndarray) -> np.ndarray:
        """Batch: inputs (N, n_in), clamped here column by column -> outputs (N, n_out).

        Written as 1-D ``np.take`` gathers and element-wise operations on contiguous columns,
        the fastest NumPy idiom for this (2-D fancy indexing and small-axis reductions are
        several times slower).
        """
        n = X.shape[0]
        columns = np.ascontiguousarray(X.T)
        combos = [(None, None)]  # (cell offset, firing strength) per combination of active slots
        for p, x in zip(self.parts, columns):
            np.maximum(x, p.lo, out=x)
            np.minimum(x, p.hi, out=x)
            k = p.locate(x)
            t = (x - np.take(p.bp, k)) * np.take(p.inv_width, k)
            slots = [(np.take(p.term[s], k), np.take(p.ml[s], k) + t * np.take(p.dm[s], k))
                     for s in range(p.term.shape[0])]
            combos = [(c2 if c1 is None else c1 + c2,
                       f2 if f1 is None else (f1 * f2 if self.product else np.minimum(f1, f2)))
                      for c1, f1 in combos for c2, f2 in slots]
        out = np.empty((n, self.num.shape[0]))
        for o in range(self.num.shape[0]):
            num = np.zeros(n)
            den = np.zeros(n) if self.average else None
            for cell, f in combos:
                num += f * np.take(self.num[o], cell)
                if den is not None:
                    den += f * np.take(self.den[o], cell)
            if den is not None:
                with np.errstate(invalid="ignore", divide="ignore"):
                    num = np.where(den > 0, num / np.where(den > 0, den, 1.0), np.nan)
            out[:, o] = num
        return out

    def evaluate_one(self, x) -> tuple[float, ...]:
        """Scalar: one clamped input vector (sequence of floats) -> outputs, in plain Python."""
        combos = [(0, 1.0)]
        for p, v in zip(self.parts, x):
            k = bisect_right(p.bp_list, v) - 1
            if k >= p.n_int:
                k = p.n_int - 1
            elif k < 0:
                k = 0
            t = (v - p.bp_list[k]) * p.inv_width_list[k]
            act = p.intervals[k]
            if self.product:
                combos = [(c1 + c2, f1 * (ml + t * dm)) for c1, f1 in combos for c2, ml, dm in act]
            else:
                combos = [(c1 + c2, min(f1, ml + t * dm)) for c1, f1 in combos for c2, ml, dm in act]
        if not self.average:
            return tuple([sum([f * num[c] for c, f in combos]) for num in self.num_list])
        out = []
        for num, den in zip(self.num_list, self.den_list):
            d = sum([f * den[c] for c, f in combos])
            out.append(sum([f * num[c] for c, f in combos]) / d if d > 0 else math.nan)
        return tuple(out)

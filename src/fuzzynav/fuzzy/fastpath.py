"""Fast TS0 kernel for piecewise-linear input partitions (thesis §IV.3, eqs IV.4–IV.5).

When every input term is a continuous piecewise-linear function (triangles, trapezoids,
shoulders — the thesis' strong partitions), each membership is an exact linear interpolation
between the breakpoints of its variable. One bisection per input finds the interval; only the
terms that are non-zero on it fire (two for a strong triangular partition), so a two-input grid
evaluates 2 × 2 = 4 of its 35 rules instead of all. The rule base is folded into a dense table
over the term grid: ``num[o][cell] = Σ_r weight_r b_ro`` and ``den[o][cell] = Σ_r weight_r`` over
the rules r whose premises select ``cell`` (an input a rule leaves out selects all its terms,
which is exact only for the product T-norm over a strong partition of that input; otherwise the
generic kernel runs). With the product T-norm the output is multilinear inside each cell of the
breakpoint grid, and the kernel evaluates that polynomial directly.

The same kernel serves the batch path (NumPy, ``evaluate``) and a plain-Python scalar path
(``evaluate_one``, a few microseconds). Results equal the generic kernels of
:mod:`fuzzynav.fuzzy.inference` to rounding (tested).
"""

from __future__ import annotations

import math
from bisect import bisect_right
from operator import mul

import numpy as np

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.membership import Trapezoidal
from fuzzynav.fuzzy.partition import check_strong_partition

MAX_TABLE_CELLS = 1 << 20
MAX_LOOKUP_CELLS = 1 << 16
MAX_MULTILINEAR_INPUTS = 6
_CHECK_FRACTIONS = np.array([0.25, 0.5, 0.75])


class _InputPartition:
    """Breakpoints of one input and, per interval, the active terms with their end memberships."""

    def __init__(self, variable, stride: int):
        lo, hi = variable.universe
        inner = {b for mf in variable.terms.values() for b in mf.breakpoints() if lo < b < hi}
        self.bp = np.array(sorted(inner | {lo, hi}))
        self.lo, self.hi = lo, hi
        self.name = variable.name
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
        with np.errstate(divide="ignore", over="ignore"):
            inv_width = 1.0 / np.diff(self.bp)
        # a cell too narrow for 1/width (sub-normal) is flat: x in it takes its left values
        self.inv_width = np.where(np.isfinite(inv_width), inv_width, 0.0)
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
        with np.errstate(over="ignore", divide="ignore"):
            ratio = np.float64(self.hi - self.lo) / (0.5 * gap)  # inf for sub-normal gaps: no grid
        self.inner = self.bp[1:-1].copy()
        self.lut = None
        if ratio < MAX_LOOKUP_CELLS:
            cells = int(math.ceil(ratio)) + 1
            self.inv_h = cells / (self.hi - self.lo)
            edges = self.lo + np.arange(cells + 1) / self.inv_h
            self.lut = np.searchsorted(self.inner, edges, side="right")
            self.left_edge = self.bp[:-1].copy()
            self.right_edge = np.append(self.inner, math.inf)

    def locate(self, x: np.ndarray) -> np.ndarray:
        """Interval index k (0 … n_int − 1) with bp[k] <= x < bp[k+1] for clamped ``x``."""
        if self.lut is None:
            return np.searchsorted(self.inner, x, side="right")
        k = self.lut.take(((x - self.lo) * self.inv_h).astype(np.intp))
        k += x >= self.right_edge.take(k)
        k -= x < self.left_edge.take(k)
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
        self.multilinear = self.product and len(self.parts) <= MAX_MULTILINEAR_INPUTS
        if self.multilinear:
            self._build_multilinear()

    def _build_multilinear(self) -> None:
        """Per interval cell, the coefficients c_S of y = Σ_S c_S Π_{i∈S} t_i (S ⊆ inputs).

        With the product T-norm every firing strength is a product of memberships that are affine
        in each t_i inside a cell, so numerator and denominator of the TS0 output are multilinear
        there, fixed by their values at the cell corners (the breakpoint grid). The coefficients
        are those corner values' finite differences, one axis at a time.
        """
        shape = [len(p.bp) for p in self.parts]
        nodes = np.stack(np.meshgrid(*[p.bp for p in self.parts], indexing="ij"), axis=-1).reshape(-1, len(shape))
        num, den = self._accumulate(np.ascontiguousarray(nodes.T))
        self.istride = [int(np.prod([p.n_int for p in self.parts[i + 1 :]], dtype=np.int64))
                        for i in range(len(self.parts))]

        def coefficients(values: np.ndarray) -> np.ndarray:
            coefs = {0: values.reshape(shape)}
            for axis in range(len(shape)):
                split = {}
                for subset, arr in coefs.items():
                    split[subset] = np.delete(arr, -1, axis=axis)
                    split[subset | (1 << axis)] = np.diff(arr, axis=axis)
                coefs = split
            return np.stack([coefs[subset].ravel() for subset in range(1 << len(shape))])  # (2^n, n_cells)

        self.coef_num = [coefficients(row) for row in num]
        self.coef_den = [coefficients(row) for row in den] if self.average else None
        self.coef_num_rows = [list(map(tuple, c.T.tolist())) for c in self.coef_num]
        self.coef_den_rows = [list(map(tuple, c.T.tolist())) for c in self.coef_den] if self.average else None

    @classmethod
    def build(cls, system) -> StrongPartitionKernel | None:
        """The kernel for a TS0 ``system`` whose inputs are all piecewise-linear, else ``None``."""
        if system.method != "ts0" or system.defuzzifier not in ("weighted_sum", "weighted_average"):
            return None
        n_cells = math.prod(len(v.terms) for v in system.inputs)
        if n_cells > MAX_TABLE_CELLS or not all(_InputPartition.exact_for(v) for v in system.inputs):
            return None
        c = system.compiled
        # a rule that ignores input i is spread over all of i's terms in the table: exact only if
        # Σ_j μ_ij = 1 (strong partition) and the T-norm is the product
        skipped = [v for i, v in enumerate(system.inputs) if (c.premises[:, i] < 0).any()]
        if skipped and (system.tnorm != "product" or not all(check_strong_partition(v).strong for v in skipped)):
            return None
        return cls(system.inputs, c.premises, c.conclusions, c.weights, c.values, system.tnorm, system.defuzzifier)

    def _locate(self, p: _InputPartition, x: np.ndarray):
        """Clamp ``x`` in place; its interval index k and position t in [0, 1] inside it."""
        np.maximum(x, p.lo, out=x)
        np.minimum(x, p.hi, out=x)
        k = p.locate(x)
        return k, (x - p.bp.take(k)) * p.inv_width.take(k)

    def _accumulate(self, columns: np.ndarray):
        """Σ_cells f·num and Σ_cells f·den over the active term combinations, (n_out, N) each.

        Written as 1-D ``take`` gathers and element-wise operations on contiguous columns,
        the fastest NumPy idiom here (2-D fancy indexing and small-axis reductions are slower).
        """
        n = columns.shape[1]
        combos = [(None, None)]  # (cell offset, firing strength) per combination of active slots
        for p, x in zip(self.parts, columns):
            k, t = self._locate(p, x)
            slots = [(p.term[s].take(k), p.ml[s].take(k) + t * p.dm[s].take(k))
                     for s in range(p.term.shape[0])]
            combos = [(c2 if c1 is None else c1 + c2,
                       f2 if f1 is None else (f1 * f2 if self.product else np.minimum(f1, f2)))
                      for c1, f1 in combos for c2, f2 in slots]
        num = np.zeros((self.num.shape[0], n))
        den = np.zeros((self.num.shape[0], n))
        for o in range(self.num.shape[0]):
            for cell, f in combos:
                num[o] += f * self.num[o].take(cell)
                den[o] += f * self.den[o].take(cell)
        return num, den

    def _multilinear_batch(self, columns: np.ndarray):
        cell, prods = None, [None]
        for p, x, stride in zip(self.parts, columns, self.istride):
            k, t = self._locate(p, x)
            cell = k * stride if cell is None else cell + k * stride
            prods = prods + [t if q is None else q * t for q in prods]

        def value(coef: np.ndarray) -> np.ndarray:
            y = coef[0].take(cell)
            for subset in range(1, len(prods)):
                y += coef[subset].take(cell) * prods[subset]
            return y

        num = [value(c) for c in self.coef_num]
        den = [value(c) for c in self.coef_den] if self.average else None
        return num, den

    def evaluate(self, X: np.ndarray) -> np.ndarray:
        """Batch: inputs (N, n_in), clamped here column by column -> outputs (N, n_out)."""
        columns = np.array(X.T, dtype=float, order="C")
        num, den = self._multilinear_batch(columns) if self.multilinear else self._accumulate(columns)
        out = np.empty((X.shape[0], len(num)))
        for o in range(len(num)):
            if self.average:
                with np.errstate(invalid="ignore", divide="ignore"):
                    out[:, o] = np.where(den[o] > 0, num[o] / np.where(den[o] > 0, den[o], 1.0), np.nan)
            else:
                out[:, o] = num[o]
        return out

    @staticmethod
    def _locate_one(p: _InputPartition, v) -> tuple[int, float]:
        v = float(v)
        if not p.lo <= v <= p.hi:
            if v != v:
                raise InputError("NaN input", field=p.name)
            v = p.lo if v < p.lo else p.hi
        k = bisect_right(p.bp_list, v, 1, p.n_int) - 1
        return k, (v - p.bp_list[k]) * p.inv_width_list[k]

    def _multilinear_one(self, x) -> tuple[float, ...]:
        cell, prods = 0, [1.0]
        for p, v, stride in zip(self.parts, x, self.istride):
            k, t = self._locate_one(p, v)
            cell += k * stride
            prods += [q * t for q in prods]
        nums = [sum(map(mul, prods, rows[cell])) for rows in self.coef_num_rows]
        if not self.average:
            return tuple(nums)
        dens = [sum(map(mul, prods, rows[cell])) for rows in self.coef_den_rows]
        return tuple(n / d if d > 0 else math.nan for n, d in zip(nums, dens))

    def evaluate_one(self, x) -> tuple[float, ...]:
        """Scalar: one input vector (sequence of numbers) -> outputs, in plain Python.

        Clamps each value to its universe; a NaN raises :class:`InputError` naming the input.
        """
        if self.multilinear:
            return self._multilinear_one(x)
        combos = [(0, 1.0)]
        for p, v in zip(self.parts, x):
            k, t = self._locate_one(p, v)
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

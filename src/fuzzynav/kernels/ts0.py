"""Strong-partition TS0 systems of one to three inputs, compiled (thesis §IV.3, eqs IV.4–IV.5).

:func:`pack` stores the multilinear form that :class:`fuzzynav.fuzzy.fastpath.StrongPartitionKernel`
derives from a rule table — per input its breakpoints, per breakpoint cell the coefficients c_S
of y = Σ_S c_S Π_{i∈S} t_i (t_i the position of input i inside its interval) — for several
systems in one flat array; :func:`evaluate` reads system ``k`` of it. Any rule table over
piecewise-linear input terms with the product T-norm (weighted sum or weighted average) runs
this way, so an edited or learned table is as fast as the thesis' own. The products and sums
follow the library's scalar path term for term, so the results are the same numbers.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.errors import InputError
from fuzzynav.jit import jit

MAX_INPUTS, MAX_OUTPUTS = 3, 2


def pack(systems, names=None) -> np.ndarray:
    """One flat array holding ``systems`` (a sequence of :class:`~fuzzynav.fuzzy.FuzzySystem`);
    ``names`` (one per system) name them in the :class:`InputError` of one that cannot be packed
    (not TS0 with the product T-norm over piecewise-linear terms, or more than 3 inputs / 2
    outputs)."""
    blocks, names = [], list(names or [f"system {k}" for k in range(len(systems))])
    for system, name in zip(systems, names):
        kernel = getattr(system, "_kernel", None)
        if kernel is None or not kernel.multilinear:
            loose = next((v.name for v in getattr(system, "inputs", ()) if getattr(v, "lock_range", True) is False), None)
            why = (f": this one is a fuzzylite engine, its input {loose} not clipped to its range (lock-range: true "
                   "in .fll, % fuzzynav: LockRange=1 in .fis)") if kernel is None and loose else ""
            raise InputError("needs a TS0 system with the product T-norm over piecewise-linear input terms "
                             f"(triangles, trapezoids, shoulders){why}", field=name)
        n_in, n_out = len(kernel.parts), len(kernel.coef_num)
        if n_in > MAX_INPUTS or n_out > MAX_OUTPUTS:
            raise InputError(f"has {n_in} inputs and {n_out} outputs; at most {MAX_INPUTS} and {MAX_OUTPUTS} here",
                             field=name)
        block = [n_in, n_out, float(kernel.average), kernel.coef_num[0].shape[1]]
        for part, stride in zip(kernel.parts, kernel.istride):
            block += [part.lo, part.hi, part.n_int, stride, *part.bp.tolist(), *part.inv_width.tolist()]
        for coef in kernel.coef_num + (kernel.coef_den or []):
            block += coef.T.ravel().tolist()  # [cell][subset]
        blocks.append(block)
    offsets = 1 + len(blocks) + np.cumsum([0] + [len(b) for b in blocks[:-1]])
    return np.array([len(blocks), *offsets.tolist(), *(v for b in blocks for v in b)], dtype=float)


@jit
def locate(tables, at, v):
    """(interval k, position t in [0, 1] inside it, offset of the next input) of input value v
    clamped to the universe of the input described at ``at``."""
    lo, hi, n_int = tables[at], tables[at + 1], int(tables[at + 2])
    if not lo <= v <= hi:
        if v != v:
            raise ValueError("NaN input to a fuzzy system")
        v = lo if v < lo else hi
    bp = at + 4
    k = 0
    while k + 1 < n_int and tables[bp + k + 1] <= v:
        k += 1
    t = (v - tables[bp + k]) * tables[bp + n_int + 1 + k]
    return k, t, bp + 2 * n_int + 1


@jit
def evaluate(tables, system, x0, x1, x2):
    """Outputs (y0, y1) of system ``system`` of ``tables`` for inputs (x0, x1, x2) — those beyond
    its input count are ignored, y1 is 0 for a one-output system."""
    at = int(tables[1 + system])
    n_in, n_out, average, n_cells = int(tables[at]), int(tables[at + 1]), tables[at + 2] != 0.0, int(tables[at + 3])
    at += 4
    t0 = t1 = t2 = 0.0
    cell = 0
    for i in range(n_in):
        stride = int(tables[at + 3])
        k, t, at = locate(tables, at, x0 if i == 0 else (x1 if i == 1 else x2))
        cell += k * stride
        if i == 0:
            t0 = t
        elif i == 1:
            t1 = t
        else:
            t2 = t
    size = 1 << n_in
    y0 = _cell_sum(tables, at + cell * size, size, t0, t1, t2)
    y1 = _cell_sum(tables, at + (n_cells + cell) * size, size, t0, t1, t2) if n_out > 1 else 0.0
    if average:
        d0 = _cell_sum(tables, at + (n_out * n_cells + cell) * size, size, t0, t1, t2)
        y0 = y0 / d0 if d0 > 0 else math.nan
        if n_out > 1:
            d1 = _cell_sum(tables, at + ((n_out + 1) * n_cells + cell) * size, size, t0, t1, t2)
            y1 = y1 / d1 if d1 > 0 else math.nan
    return y0, y1


@jit
def _cell_sum(tables, row, size, t0, t1, t2):
    """Σ_S c_S Π_{i∈S} t_i over the ``size`` coefficients at ``row`` (products built input by
    input, summed in subset order)."""
    acc = 0.0
    for s in range(size):
        p = 1.0
        if s & 1:
            p = p * t0
        if s & 2:
            p = p * t1
        if s & 4:
            p = p * t2
        acc += p * tables[row + s]
    return acc

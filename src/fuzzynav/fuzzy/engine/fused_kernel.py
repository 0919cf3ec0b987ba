"""One compiled kernel from an engine's input batch to its outputs.

:func:`run` takes the arrays of :mod:`.pack` (built once per engine, handed over as three
buffers: :func:`~.pack.flatten`) and the degrees of the few propositions fuzzified in NumPy,
and does in one call what :class:`~fuzzynav.fuzzy.engine.Engine` otherwise does in Python
around several kernels: the input values (clipped where
``lock-range``); every proposition's degree (:func:`~.fuzzify_terms.term_column`, then its hedges);
each block's rules (:func:`~.staged_kernels.rule_degrees`: postfix antecedents with the block's norms,
times the weights; a block reading an output term runs rule by rule, that degree accumulated
from the conclusions before, as fuzzylite does; a rule p and q alone in its output's term group
is left to that output, which multiplies p q where it reads it: ``pack.rule_skipped``); each
conclusion's degree (hedges carried from one conclusion to the next); then each output — Mamdani
by :func:`~.staged_kernels.integral`, weighted by :func:`~.sugeno_outputs.every_row_affine` — and its
``lock-previous`` / ``default`` / ``lock-range``
(:func:`~.staged_kernels.finish`). The same operations in the same order as that path, so the same
bits (the NumPy path stays for what :func:`~.pack.pack` refuses; the tests compare the two on the
test engines and on pyfuzzylite's examples).
"""

from __future__ import annotations

import numpy as np

from fuzzynav.fuzzy.engine import staged_kernels
from fuzzynav.fuzzy.engine.fuzzify_terms import hedge_column, term_column
from fuzzynav.fuzzy.engine.norms import snorm_into
from fuzzynav.fuzzy.engine.pack import ANY, INTEGRAL, NAN_OUTPUT, NUMPY, TERM, WEIGHTED, ZERO, Flat, Packed
from fuzzynav.fuzzy.engine.sugeno_outputs import every_row_affine
from fuzzynav.jit import jit

ROWS, CACHE_BYTES = 2048, 2 ** 19  # a block of :func:`run`: at least ROWS rows, as many as fit in 512 KiB
LO, LITERAL, WEIGHT, CONCLUSION_ROW, OUTPUT, OUTPUT_LIMITS = (
    Packed._fields.index(name) for name in ("lo", "literal", "rule_weight", "conclusion_row", "output", "output_limits"))


def evaluate(flat: Flat, table: np.ndarray, X: np.ndarray) -> np.ndarray:
    """Outputs (N, K) for the inputs X (N, n_inputs) of the engine packed as ``flat``
    (:func:`~.pack.flatten`); ``table`` (L, N) holds the degrees of the propositions
    :func:`~.pack.pack` leaves to NumPy (its other rows are not read; (0, 0) when there are none)."""
    raw = run(np.ascontiguousarray(X, dtype=float), table, *flat)
    return np.ascontiguousarray(raw.T)  # one output: (1, N) seen as (N, 1), no copy


@jit
def _field(buffer, layout, k):
    """Field k of a :class:`~.pack.Flat` as a 1-D array of its buffer."""
    return buffer[layout[k, 1]:layout[k, 1] + layout[k, 2]]


@jit
def _field2(buffer, layout, k):
    """Field k of a :class:`~.pack.Flat` as a 2-D array of its buffer."""
    rows, columns = layout[k, 2], layout[k, 3]
    return buffer[layout[k, 1]:layout[k, 1] + rows * columns].reshape((rows, columns))


@jit
def _unpack(ints, floats, bools, layout):
    """The fields of a :class:`~.pack.Flat` engine in :class:`~.pack.Packed`'s order, as views of
    its buffers (ints, floats, bools)."""
    i, f, b, a = ints, floats, bools, layout
    return (_field(b, a, 0), _field(f, a, 1), _field(f, a, 2), _field2(i, a, 3), _field(i, a, 4), _field(i, a, 5),
            _field(f, a, 6), _field(f, a, 7), _field2(i, a, 8), _field(i, a, 9), _field(i, a, 10), _field(i, a, 11),
            _field2(i, a, 12), _field(b, a, 13), _field(i, a, 14), _field(i, a, 15), _field(f, a, 16),
            _field(b, a, 17), _field(i, a, 18), _field(i, a, 19), _field(i, a, 20), _field2(i, a, 21),
            _field2(f, a, 22), _field(i, a, 23), _field(i, a, 24), _field(i, a, 25), _field(b, a, 26),
            _field(i, a, 27), _field(i, a, 28), _field(i, a, 29), _field(i, a, 30), _field(i, a, 31),
            _field(f, a, 32), _field(i, a, 33), _field(f, a, 34), _field(i, a, 35), _field2(i, a, 36),
            _field2(f, a, 37), _field(f, a, 38))


@jit
def _hedges(d, hedges, first, end):
    for h in range(first, end):
        hedge_column(hedges[h], d)


@jit
def _accumulate(value, conclusions, conclusion_row, before, aggregation, d):
    """``d`` = the S-norm ``aggregation`` of the degrees (rows ``conclusion_row`` of ``value``) of
    ``conclusions`` (one output term, in order) numbered below ``before``; 0 where there is none."""
    opened = False
    for c in conclusions:
        if c >= before:
            break
        if opened:
            snorm_into(aggregation, d, value[conclusion_row[c]], d)
        else:
            d[:] = value[conclusion_row[c]]
            opened = True
    if not opened:
        d[:] = 0.0


@jit
def _fuzzify(X, lock, lo, hi, literal, term_code, term_start, term_height, params, hedges, inputs, table):
    """``inputs`` (n_inputs, N): X's columns clipped where locked; ``table`` rows of the
    propositions evaluated here."""
    for i in range(lo.shape[0]):
        for n in range(X.shape[0]):
            v = X[n, i]
            inputs[i, n] = min(max(v, lo[i]), hi[i]) if lock[i] and v == v else v
    for lit in range(literal.shape[0]):
        how, i, t, first, end = literal[lit, 0], literal[lit, 1], literal[lit, 2], literal[lit, 3], literal[lit, 4]
        row = table[lit]
        if how == TERM:
            term_column(term_code[t], params, term_start[t], term_start[t + 1], term_height[t], inputs[i], row)
        elif how == ZERO:
            row[:] = 0.0
            continue
        elif how == ANY:
            row[:] = np.nan
        else:
            continue  # NumPy's (hedges applied) or chained (filled rule by rule)
        _hedges(row, hedges, first, end)


@jit
def _conclude(r, value, hedges, rule_conclusions, conclusion_hedges, conclusion_row):
    """The degrees of rule r's hedged conclusions (the others read the rule's row of ``value``):
    the degree before, hedged, carried from one conclusion to the next."""
    row = r
    for c in range(rule_conclusions[r], rule_conclusions[r + 1]):
        if conclusion_row[c] != row:
            value[conclusion_row[c]] = value[row]
            row = conclusion_row[c]
            _hedges(value[row], hedges, conclusion_hedges[c], conclusion_hedges[c + 1])


@jit
def run(X, table, ints, floats, bools, layout):
    """The outputs (K, N) for the inputs X of the engine packed as (ints, floats, bools, layout)
    (:func:`~.pack.flatten`; module docstring): :func:`_rows` by blocks of rows whose arrays
    stay in cache (whole batches for small engines, as each block costs its allocations), then
    each output's ``lock-previous`` / ``default`` / ``lock-range`` over the whole batch
    (``lock-previous`` carries a value from one row to the next; none of them, nothing to do)."""
    lo, literal, rule_weight = _field(floats, layout, LO), _field2(ints, layout, LITERAL), _field(floats, layout, WEIGHT)
    conclusion_row, output = _field(ints, layout, CONCLUSION_ROW), _field2(ints, layout, OUTPUT)
    output_limits = _field2(floats, layout, OUTPUT_LIMITS)
    n, n_literals = X.shape[0], literal.shape[0]
    n_values = max(rule_weight.shape[0], conclusion_row.max() + 1 if conclusion_row.shape[0] else 0)
    raw = np.empty((output.shape[0], n))
    per_row = n_literals + n_values + lo.shape[0] + output.shape[0]  # arrays of one value a row
    rows = max(ROWS, CACHE_BYTES // (8 * per_row))
    for r0 in range(0, n, rows):
        r1 = min(n, r0 + rows)
        work = np.empty((n_literals + n_values, r1 - r0))  # the propositions' degrees, then the rules' values
        for lit in range(n_literals):
            if literal[lit, 0] == NUMPY:
                work[lit] = table[lit, r0:r1]
        _rows(X[r0:r1], work, ints, floats, bools, layout, raw, r0)
    for k in range(output.shape[0]):
        lock_previous, default, lock_range = output[k, 4] != 0, output_limits[k, 0], output[k, 5] != 0
        if output[k, 0] != NAN_OUTPUT and (lock_previous or default == default or lock_range):
            staged_kernels.finish(raw[k], lock_previous, default, lock_range, output_limits[k, 1], output_limits[k, 2])
    return raw


@jit
def _rows(X, work, ints, floats, bools, layout, raw, at):
    """``raw[k, at:at + len(X)]``: output k before its ``lock-previous`` / ``default`` /
    ``lock-range``, on the rows X; ``work`` holds the propositions' degrees there (NumPy's rows filled), then room for
    the rules' values (the activations' rows index both: an aliased or deferred rule's is its
    proposition's, a deferred one's partner its second)."""
    (lock, lo, hi, literal, term_code, term_start, term_height, params, chained, chained_start, chained_conclusions,
     hedges, block, block_chained, program, rule_start, rule_weight, rule_skipped, rule_conclusions, conclusion_hedges,
     conclusion_row, output, output_limits, act_start, act_conclusion, act_unit, act_opens, act_partner, unit_start,
     unit_term, unit_implication, shape_start, shapes, points_start, points, support_start, support, coefficients,
     constants) = _unpack(ints, floats, bools, layout)
    n = X.shape[0]
    table, value = work[:literal.shape[0]], work[literal.shape[0]:]
    inputs = np.empty((lo.shape[0], n))
    _fuzzify(X, lock, lo, hi, literal, term_code, term_start, term_height, params, hedges, inputs, table)
    for b in range(block.shape[0]):
        first, end, conjunction, disjunction = block[b, 0], block[b, 1], block[b, 2], block[b, 3]
        step = 1 if block_chained[b] else end - first  # rule by rule when a premise reads an output
        for r0 in range(first, end, step):
            r1 = r0 + step
            for j in range(chained.shape[0] if block_chained[b] else 0):
                lit = chained[j, 0]
                _accumulate(value, chained_conclusions[chained_start[j]:chained_start[j + 1]], conclusion_row,
                            rule_conclusions[r0], chained[j, 1], table[lit])
                _hedges(table[lit], hedges, literal[lit, 3], literal[lit, 4])
            a = r0
            while a < r1:  # the runs of rules computed here (not aliased nor deferred to their output)
                if rule_skipped[a]:
                    a += 1
                    continue
                e = a + 1
                while e < r1 and not rule_skipped[e]:
                    e += 1
                staged_kernels.rule_degrees(table, program, rule_start[a:e + 1], rule_weight[a:e], conjunction, disjunction,
                                      value[a:e])
                a = e
            for r in range(r0, r1):
                _conclude(r, value, hedges, rule_conclusions, conclusion_hedges, conclusion_row)
    for k in range(output.shape[0]):
        y = raw[k, at:at + n]
        kind, acts, units = output[k, 0], act_conclusion[act_start[k]:act_start[k + 1]], act_unit[act_start[k]:act_start[k + 1]]
        first, end = unit_start[k], unit_start[k + 1]
        if kind == INTEGRAL:
            n_terms, size = support_start[k + 1] - support_start[k], points_start[k + 1] - points_start[k]
            sampled = shapes[shape_start[k]:shape_start[k + 1]].reshape((n_terms, size))
            staged_kernels.integral(work, acts, units, unit_term[first:end], unit_implication[first:end], sampled,
                              support[support_start[k]:support_start[k + 1]], points[points_start[k]:points_start[k + 1]],
                              output[k, 1], output[k, 2], y)
        elif kind == WEIGHTED:
            every_row_affine(work, acts, act_partner[act_start[k]:act_start[k + 1]], units, output[k, 1],
                             coefficients[first:end], constants[first:end], inputs, output[k, 3] != 0, y)
        else:
            y[:] = np.nan

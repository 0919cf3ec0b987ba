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
from fuzzynav.fuzzy.engine.records import Affine, Groups, Sampled, Units
from fuzzynav.fuzzy.engine.sugeno_outputs import every_row_affine
from fuzzynav.jit import jit

NOT_MASKED = np.zeros((0, 0), dtype=np.bool_)  # the triggers of a weighted output: every row (never read)
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
    """The :class:`~.pack.Packed` record of a :class:`~.pack.Flat` engine, its fields views of the
    buffers (ints, floats, bools), field k at row k of ``layout``."""
    i, f, b, a = ints, floats, bools, layout
    return Packed(lock=_field(b, a, 0), lo=_field(f, a, 1), hi=_field(f, a, 2), literal=_field2(i, a, 3),
                  term_code=_field(i, a, 4), term_start=_field(i, a, 5), term_height=_field(f, a, 6),
                  params=_field(f, a, 7), chained=_field2(i, a, 8), chained_start=_field(i, a, 9),
                  chained_conclusions=_field(i, a, 10), hedges=_field(i, a, 11), block=_field2(i, a, 12),
                  block_chained=_field(b, a, 13), program=_field(i, a, 14), rule_start=_field(i, a, 15),
                  rule_weight=_field(f, a, 16), rule_skipped=_field(b, a, 17), rule_conclusions=_field(i, a, 18),
                  conclusion_hedges=_field(i, a, 19), conclusion_row=_field(i, a, 20), output=_field2(i, a, 21),
                  output_limits=_field2(f, a, 22), act_start=_field(i, a, 23), act_conclusion=_field(i, a, 24),
                  act_unit=_field(i, a, 25), act_opens=_field(b, a, 26), act_partner=_field(i, a, 27),
                  unit_start=_field(i, a, 28), unit_term=_field(i, a, 29), unit_implication=_field(i, a, 30),
                  shape_start=_field(i, a, 31), shapes=_field(f, a, 32), points_start=_field(i, a, 33),
                  points=_field(f, a, 34), support_start=_field(i, a, 35), support=_field2(i, a, 36),
                  coefficients=_field2(f, a, 37), constants=_field(f, a, 38))


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
def _fuzzify(X, p, inputs, table):
    """``inputs`` (n_inputs, N): X's columns clipped where locked; ``table`` rows of the
    propositions evaluated here (``p``: the engine's :class:`~.pack.Packed` record)."""
    lock, lo, hi, literal, hedges = p.lock, p.lo, p.hi, p.literal, p.hedges
    term_code, term_start, term_height, params = p.term_code, p.term_start, p.term_height, p.params
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
    p = _unpack(ints, floats, bools, layout)
    n = X.shape[0]
    table, value = work[:p.literal.shape[0]], work[p.literal.shape[0]:]
    inputs = np.empty((p.lo.shape[0], n))
    _fuzzify(X, p, inputs, table)
    for b in range(p.block.shape[0]):
        first, end, conjunction, disjunction = p.block[b, 0], p.block[b, 1], p.block[b, 2], p.block[b, 3]
        step = 1 if p.block_chained[b] else end - first  # rule by rule when a premise reads an output
        for r0 in range(first, end, step):
            r1 = r0 + step
            for j in range(p.chained.shape[0] if p.block_chained[b] else 0):
                lit = p.chained[j, 0]
                _accumulate(value, p.chained_conclusions[p.chained_start[j]:p.chained_start[j + 1]], p.conclusion_row,
                            p.rule_conclusions[r0], p.chained[j, 1], table[lit])
                _hedges(table[lit], p.hedges, p.literal[lit, 3], p.literal[lit, 4])
            a = r0
            while a < r1:  # the runs of rules computed here (not aliased nor deferred to their output)
                if p.rule_skipped[a]:
                    a += 1
                    continue
                e = a + 1
                while e < r1 and not p.rule_skipped[e]:
                    e += 1
                staged_kernels.rule_degrees(table, p.program, p.rule_start[a:e + 1], p.rule_weight[a:e], conjunction,
                                            disjunction, value[a:e])
                a = e
            for r in range(r0, r1):
                _conclude(r, value, p.hedges, p.rule_conclusions, p.conclusion_hedges, p.conclusion_row)
    for k in range(p.output.shape[0]):
        y = raw[k, at:at + n]
        acts_at, acts_end = p.act_start[k], p.act_start[k + 1]
        kind, acts, units = p.output[k, 0], p.act_conclusion[acts_at:acts_end], p.act_unit[acts_at:acts_end]
        first, end = p.unit_start[k], p.unit_start[k + 1]
        if kind == INTEGRAL:
            n_terms, size = p.support_start[k + 1] - p.support_start[k], p.points_start[k + 1] - p.points_start[k]
            shapes = p.shapes[p.shape_start[k]:p.shape_start[k + 1]].reshape((n_terms, size))
            staged_kernels.integral(work, acts,
                                    Units(units, p.unit_term[first:end], p.unit_implication[first:end], p.output[k, 1]),
                                    Sampled(shapes, p.support[p.support_start[k]:p.support_start[k + 1]],
                                            p.points[p.points_start[k]:p.points_start[k + 1]], p.output[k, 2]), y)
        elif kind == WEIGHTED:
            grouping = Groups(acts, units, p.act_opens[acts_at:acts_end], NOT_MASKED, False, p.output[k, 1])
            every_row_affine(work, grouping, p.act_partner[acts_at:acts_end],
                             Affine(p.coefficients[first:end], p.constants[first:end]), inputs, p.output[k, 3] != 0, y)
        else:
            y[:] = np.nan

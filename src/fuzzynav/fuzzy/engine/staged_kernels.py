"""The compiled part of :class:`~fuzzynav.fuzzy.engine.Engine`: rules, aggregation, defuzzification.

Plain loops over the rows of a batch, compiled with numba (:func:`fuzzynav.jit.jit`;
``NUMBA_DISABLE_JIT=1`` runs them as Python). The engine fuzzifies in NumPy (one vectorised
evaluation per input term and hedge) and hands these kernels flat arrays:

- :func:`rule_degrees` — each rule's antecedent as a postfix program over the fuzzified
  propositions (``AND`` / ``OR`` join the two values on top of the stack with the block's
  T-norm / S-norm), times the rule's weight;
- :func:`integral` — a Mamdani output: every activation implies its term (sampled once at the
  defuzzifier's points) with the block's T-norm, the output's S-norm aggregates them, and the
  sampled set is reduced (centroid, bisector, mean / smallest / largest of maximum: :mod:`.sampled_defuzzify`)
  — row by row, units of Maximum aggregation four in one pass where their supports overlap, or,
  for a centroid over short supports, across rows (:mod:`.centroid_rows`), the same bits;
- :func:`group` and :func:`weighted_average` — a weighted output: activations of one term
  combined with the output's S-norm, then Σ g z / Σ g (times Σ g for ``WeightedSum``), with
  :func:`affine` values z of constant and linear terms (:func:`weighted_affine`: all three by
  chunks of rows);
- :func:`finish` — ``lock-previous``, ``default`` and ``lock-range`` of an output.

The norms are :mod:`.norms` (fuzzylite 8's, thesis §II.3). A Mamdani row whose activation degrees all lie in [0, 1] skips what cannot change
the result: activations of degree 0 and samples outside a term's support (T(w, 0) = 0 and
S(a, 0) = a for every norm here on [0, 1]); other rows sample every term everywhere.
"""

from __future__ import annotations

import numpy as np
from numba import literally

from fuzzynav.fuzzy.engine.centroid_rows import applies, max_centroid
from fuzzynav.fuzzy.engine.implication import max_four, max_min, max_product, sum_min
from fuzzynav.fuzzy.engine.norms import ALGEBRAIC_SUM, MAXIMUM, MINIMUM, PRODUCT, conjoin_into, snorm_into, tnorm_into
from fuzzynav.fuzzy.engine.records import Groups
from fuzzynav.fuzzy.engine.sampled_defuzzify import centroid_sums, padded, reduce_sampled
from fuzzynav.fuzzy.engine.sugeno_outputs import CHUNK, every_row_affine
from fuzzynav.jit import jit

AND, OR = -1, -2  # program codes; codes >= 0 push a proposition's degree


@jit
def _left_deep(program, first, end):
    """Whether ``program[first:end]`` is p (q OP)*: each operator joins the value so far and a proposition."""
    if (end - first) % 2 == 0 or program[first] < 0:
        return False
    for i in range(first + 1, end, 2):
        if program[i] < 0 or program[i + 1] >= 0:
            return False
    return True


@jit
def _conjunctions(program, i, end):
    """How many of the next three propositions of a left-deep ``program[i:end]`` join by AND in a row."""
    more = 0
    while more < 3 and i + 2 * more < end and program[i + 2 * more + 1] == AND:
        more += 1
    return more


@jit
def rule_degrees(table, program, starts, weights, conjunction, disjunction, out):
    """``out[r]`` = ``weights[r]`` × the antecedent of rule r on every row; rule r's program is
    ``program[starts[r]:starts[r + 1]]`` over the propositions' degrees ``table`` (L, N). Rows go
    by chunks that stay in cache. A left-deep program (p q OP r OP …, every conjunction of
    propositions) is folded in ``out[r]`` (its first proposition, each operator in place —
    up to three conjunctions in a row in one loop: :func:`~.norms.conjoin_into` — then the
    weight); others run on a stack. Either way the same operations in the same order."""
    n, depth = table.shape[1], 1
    for r in range(starts.shape[0] - 1):
        depth = max(depth, starts[r + 1] - starts[r])  # a rule's stack holds at most its program's length
    stack = np.empty((depth, CHUNK))
    for lo in range(0, n, CHUNK):
        size = min(n, lo + CHUNK) - lo
        for r in range(starts.shape[0] - 1):
            s, e, weight, degree = starts[r], starts[r + 1], weights[r], out[r, lo:lo + size]
            if _left_deep(program, s, e):
                value = table[program[s], lo:lo + size]  # the first operator writes degree: no copy
                i = s + 1
                while i < e:
                    more = _conjunctions(program, i, e)
                    if more >= 2 and conjoin_into(conjunction, value, table[program[i], lo:lo + size],
                                                  table[program[i + 2], lo:lo + size],
                                                  table[program[i + 2 * more - 2], lo:lo + size], more, degree):
                        i += 2 * more
                    elif program[i + 1] == AND:
                        tnorm_into(conjunction, value, table[program[i], lo:lo + size], degree)
                        i += 2
                    else:
                        snorm_into(disjunction, value, table[program[i], lo:lo + size], degree)
                        i += 2
                    value = degree
                if e == s + 1:
                    degree[:] = value
                if weight != 1.0:  # x × 1 = x: skipping it changes no bit
                    for k in range(size):
                        degree[k] = weight * degree[k]
                continue
            top = 0
            for i in range(s, e):
                code = program[i]
                if code >= 0:
                    stack[top, :size] = table[code, lo:lo + size]
                    top += 1
                    continue
                top -= 1
                if code == AND:
                    tnorm_into(conjunction, stack[top - 1, :size], stack[top, :size], stack[top - 1, :size])
                else:
                    snorm_into(disjunction, stack[top - 1, :size], stack[top, :size], stack[top - 1, :size])
            first = stack[0, :size]
            for k in range(size):
                degree[k] = weight * first[k]


@jit
def _max_units(mu, shapes, support, units, count, unit, w):
    """mu ← the maximum of mu and the implied term (min or product, :mod:`.implication`) of each of
    the first ``count`` of ``units``, in order, over its support: four in one pass
    (:func:`~.implication.max_four`, over the span of their supports, where a term is 0 outside its
    own) where their supports overlap (:func:`_spans_overlap`), else one by one (``unit``: the
    output's :class:`~.records.Units`)."""
    unit_term, unit_implication = unit.term, unit.implication
    j = 0
    while j < count:
        if j + 4 <= count:
            first, end, overlap = _spans_overlap(support, unit_term, units, j)
            if overlap:
                max_four(mu, shapes, units, j, unit, w, first, end)
                j += 4
                continue
        u = units[j]
        t = unit_term[u]
        if unit_implication[u] == MINIMUM:
            max_min(mu, shapes, t, support[t, 0], support[t, 1], w[u])
        else:
            max_product(mu, shapes, t, support[t, 0], support[t, 1], w[u])
        j += 1


@jit
def _spans_overlap(support, unit_term, units, j):
    """(first, end, whether) of the span of the supports of the four units ``units[j:j + 4]``:
    whether it is at most half their total length (MATLAB's Bells: everywhere), where
    :func:`~.implication.max_four` pays."""
    first, end, total = support[unit_term[units[j]], 0], 0, 0
    for i in range(j, j + 4):
        t = unit_term[units[i]]
        first, end, total = min(first, support[t, 0]), max(end, support[t, 1]), total + support[t, 1] - support[t, 0]
    return first, end, 2 * (end - first) <= total


@jit
def integral(degrees, rows, unit, sampled, out):
    """:func:`_integral`. The centroid of Maximum aggregation, where it applies, is computed across
    rows (:func:`~.centroid_rows.max_centroid`: the same bits), :func:`_integral` taking only its
    rows of degrees outside [0, 1]; otherwise units of Maximum aggregation go four at a time
    (:func:`_max_units`) when the first four's supports overlap (:func:`_spans_overlap`)."""
    n, unit_term, support = degrees.shape[1], unit.term, sampled.support
    if sampled.reduction == 0 and unit.aggregation == MAXIMUM and applies(unit_term, unit.implication, support,
                                                                          sampled.x.shape[0]):
        unbounded = np.empty(n, dtype=np.int64)
        for i in range(max_centroid(degrees, rows, unit, sampled, out, unbounded)):
            _integral(False, degrees, rows, unit, sampled, out, unbounded[i], unbounded[i] + 1)
    elif unit.aggregation == MAXIMUM and unit_term.shape[0] >= 4 and _spans_overlap(support, unit_term, np.arange(4),
                                                                                    0)[2]:
        _integral(True, degrees, rows, unit, sampled, out, 0, n)
    else:
        _integral(False, degrees, rows, unit, sampled, out, 0, n)


@jit
def _integral(four, degrees, rows, unit, sampled, out, start, stop):
    """A Mamdani output for every row n in [start, stop): activation a has degree ``degrees[rows[a], n]`` and
    belongs to unit ``units[a]`` (``unit``, a :class:`~.records.Units`: its own, or — Maximum
    aggregation — the one of every activation of the same term and implication, whose degrees
    max-combine first: T is monotone); unit u implies term ``unit_term[u]`` sampled as ``shapes``
    (T, R) at ``x`` (``sampled``, a :class:`~.records.Sampled`) with the T-norm
    ``unit_implication[u]``. ``support[t]`` = (first, end) of term t's non-zero samples, (-1, R)
    when a sample lies outside [0, 1]. ``four`` (compiled once for each value): the units of
    Maximum aggregation and Minimum or product implication are left to :func:`_max_units`."""
    literally(four)
    units, unit_term, unit_implication, aggregation = unit.of, unit.term, unit.implication, unit.aggregation
    shapes, support, x, reduction = sampled.shapes, sampled.support, sampled.x, sampled.reduction
    n_units, size = unit_term.shape[0], x.shape[0]
    w, maxed = np.empty(n_units), np.empty(n_units, dtype=np.int64)  # maxed: the units left to max_four
    mu, scratch, area = np.zeros(padded(size)), np.empty(size), np.empty(padded(size))
    at = np.zeros(padded(size))  # the points, padded for reduce_sampled
    at[:size] = x
    for n in range(start, stop):
        for u in range(n_units):
            w[u] = -np.inf
        for a in range(rows.shape[0]):
            v = degrees[rows[a], n]
            u = units[a]
            if v > w[u] or v != v:
                w[u] = v
        bounded = True
        for u in range(n_units):
            bounded = bounded and 0.0 <= w[u] <= 1.0
        lo, hi, n_maxed = size, 0, 0  # the samples any unit touched (mu is 0 elsewhere)
        for u in range(n_units):
            t, wu, imp = unit_term[u], w[u], unit_implication[u]
            plain = bounded and support[t, 0] >= 0  # no NaN: the support alone, skipped where w = 0
            if plain and wu == 0.0:
                continue
            first, end = (support[t, 0], support[t, 1]) if plain else (0, size)
            lo, hi = min(lo, first), max(hi, end)
            if four and plain and aggregation == MAXIMUM and (imp == MINIMUM or imp == PRODUCT):
                maxed[n_maxed] = u  # after the others: the maximum is exact, so any order gives the same bits
                n_maxed += 1
            elif plain and aggregation == MAXIMUM and imp == MINIMUM:  # one pass (:mod:`.implication`)
                max_min(mu, shapes, t, first, end, wu)
            elif plain and aggregation == MAXIMUM and imp == PRODUCT:
                max_product(mu, shapes, t, first, end, wu)
            elif plain and aggregation == ALGEBRAIC_SUM and imp == MINIMUM:
                sum_min(mu, shapes, t, first, end, wu)
            else:
                implied = scratch[first:end]
                implied[:] = wu
                tnorm_into(imp, implied, shapes[t, first:end], implied)
                snorm_into(aggregation, mu[first:end], implied, mu[first:end])
        if four:
            _max_units(mu, shapes, support, maxed, n_maxed, unit, w)
        if reduction == 0:  # Centroid: its sums called here, as reduce_sampled's call costs more than they do
            total, moment = centroid_sums(mu, at, lo, max(lo, hi))
            out[n] = moment / total
        else:
            out[n] = reduce_sampled(reduction, mu, at, area, lo, max(lo, hi), size)
        mu[lo:hi] = 0.0


@jit
def group(degrees, grouping, degree, present):
    """Per term group g of ``grouping`` (a :class:`~.records.Groups`) and row n: ``degree[g, n]``
    the S-norm ``aggregation`` folded over its activations' degrees in order (``opens[a]``: a is
    the group's first; 0 where not triggered), ``present[g, n]`` whether any triggered (``masked``
    False: every activation triggers)."""
    rows, groups, opens, triggered = grouping.rows, grouping.groups, grouping.opens, grouping.triggered
    masked, aggregation = grouping.masked, grouping.aggregation
    zeroed = np.empty(degrees.shape[1])
    for a in range(rows.shape[0]):
        g, v = groups[a], degrees[rows[a]]
        if masked:
            for n in range(v.shape[0]):
                zeroed[n] = v[n] if triggered[a, n] else 0.0
            v = zeroed
        if opens[a]:
            degree[g] = v
            if masked:
                present[g] = triggered[a]
            else:
                present[g] = True
            continue
        snorm_into(aggregation, degree[g], v, degree[g])
        if masked:
            for n in range(v.shape[0]):
                present[g, n] = present[g, n] or triggered[a, n]


@jit
def weighted_average(degree, present, z, weighted_sum, out):
    """Σ_g g z_g / Σ_g g over the groups present in each row (times Σ g for a weighted sum);
    NaN where none is."""
    n = out.shape[0]
    num, den, seen = np.zeros(n), np.zeros(n), np.zeros(n, dtype=np.bool_)
    for g in range(degree.shape[0]):
        for k in range(n):
            if present[g, k]:
                seen[k] = True
                num[k] += degree[g, k] * z[g, k]
                den[k] += degree[g, k]
    for k in range(n):
        y = num[k] / den[k]
        if weighted_sum:
            y = y * den[k]
        out[k] = y if seen[k] else np.nan


@jit
def affine(coefficients, constants, inputs, z):
    """``z[g, n]`` = ``constants[g]`` + Σ_i ``coefficients[g, i]`` × ``inputs[i, n]``: constant and
    linear terms' values on every row."""
    for g in range(z.shape[0]):
        z[g] = constants[g]
        for i in range(coefficients.shape[1]):
            c, x = coefficients[g, i], inputs[i]
            for n in range(z.shape[1]):
                z[g, n] += c * x[n]


@jit
def weighted_affine(degrees, grouping, terms, inputs, weighted_sum, out):
    """:func:`group`, :func:`affine` and :func:`weighted_average` by chunks of rows that stay in
    cache: a weighted output whose terms (``terms``, a :class:`~.records.Affine`) are all constant
    or linear, its groups ``grouping`` (a :class:`~.records.Groups`)."""
    coefficients, constants = terms.coefficients, terms.constants
    if not grouping.masked:
        every_row_affine(degrees, grouping, np.full(grouping.rows.shape[0], -1), terms, inputs, weighted_sum, out)
        return
    n_groups, n = coefficients.shape[0], out.shape[0]
    degree, present = np.empty((n_groups, CHUNK)), np.empty((n_groups, CHUNK), dtype=np.bool_)
    z = np.empty((n_groups, CHUNK))
    for lo in range(0, n, CHUNK):
        hi = min(n, lo + CHUNK)
        size = hi - lo
        chunk = Groups(grouping.rows, grouping.groups, grouping.opens, grouping.triggered[:, lo:hi], True,
                       grouping.aggregation)
        group(degrees[:, lo:hi], chunk, degree[:, :size], present[:, :size])
        affine(coefficients, constants, inputs[:, lo:hi], z[:, :size])
        weighted_average(degree[:, :size], present[:, :size], z[:, :size], weighted_sum, out[lo:hi])


@jit
def finish(y, lock_previous, default, lock_range, minimum, maximum):
    """In place: NaN becomes the previous row's value (``lock_previous``), then ``default`` (if
    not NaN); then clipped to [minimum, maximum] if ``lock_range``."""
    previous = np.nan
    for n in range(y.shape[0]):
        v = y[n]
        if lock_previous:
            if v != v:
                v = previous
            else:
                previous = v
        if v != v:
            v = default
        if lock_range and v == v:
            v = min(max(v, minimum), maximum)
        y[n] = v

"""The compiled part of :class:`~fuzzynav.fuzzy.engine.Engine`: rules, aggregation, defuzzification.

Plain loops over the rows of a batch, compiled with numba (:func:`fuzzynav.kernels.compile.jit`;
``NUMBA_DISABLE_JIT=1`` runs them as Python). The engine fuzzifies in NumPy (one vectorised
evaluation per input term and hedge) and hands these kernels flat arrays:

- :func:`rule_degrees` — each rule's antecedent as a postfix program over the fuzzified
  propositions (``AND`` / ``OR`` join the two values on top of the stack with the block's
  T-norm / S-norm), times the rule's weight;
- :func:`integral` — a Mamdani output: every activation implies its term (sampled once at the
  defuzzifier's points) with the block's T-norm, the output's S-norm aggregates them, and the
  sampled set is reduced (centroid, bisector, mean / smallest / largest of maximum);
- :func:`group` and :func:`weighted_average` — a weighted output: activations of one term
  combined with the output's S-norm, then Σ g z / Σ g (times Σ g for ``WeightedSum``);
- :func:`finish` — ``lock-previous``, ``default`` and ``lock-range`` of an output.

The norms are fuzzylite 8's (thesis §II.3), NaN-propagating as NumPy's ``maximum`` /
``minimum``. A Mamdani row whose activation degrees all lie in [0, 1] skips what cannot change
the result: activations of degree 0 and samples outside a term's support (T(w, 0) = 0 and
S(a, 0) = a for every norm here on [0, 1]); other rows sample every term everywhere.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.fuzzy.operators import SNORMS, TNORMS
from fuzzynav.kernels.compile import jit

REDUCTIONS = ("Centroid", "Bisector", "MeanOfMaximum", "SmallestOfMaximum", "LargestOfMaximum")
AND, OR = -1, -2  # program codes; codes >= 0 push a proposition's degree
MAXIMUM, MINIMUM, PRODUCT = SNORMS.index("Maximum"), TNORMS.index("Minimum"), TNORMS.index("AlgebraicProduct")


@jit
def _max(a, b):
    return a if (a >= b or a != a) else b


@jit
def _min(a, b):
    return a if (a <= b or a != a) else b


@jit
def tnorm(kind, a, b):
    """T-norm ``TNORMS[kind]`` of a and b."""
    if kind == 0:
        return a * b
    if kind == 1:
        return _max(0.0, a + b - 1.0)
    if kind == 2:
        return _min(a, b) if _max(a, b) == 1.0 else 0.0
    if kind == 3:
        return (a * b) / (2.0 - (a + b - a * b))
    if kind == 4:
        return (a * b) / (a + b - a * b) if a + b != 0.0 else 0.0
    if kind == 5:
        return _min(a, b)
    return _min(a, b) if a + b > 1.0 else 0.0


@jit
def snorm(kind, a, b):
    """S-norm ``SNORMS[kind]`` of a and b."""
    if kind == 0:
        return a + b - a * b
    if kind == 1:
        return _min(1.0, a + b)
    if kind == 2:
        return _max(a, b) if _min(a, b) == 0.0 else 1.0
    if kind == 3:
        return (a + b) / (1.0 + a * b)
    if kind == 4:
        return (a + b - 2.0 * a * b) / (1.0 - a * b) if a * b != 1.0 else 1.0
    if kind == 5:
        return _max(a, b)
    if kind == 6:
        return _max(a, b) if a + b < 1.0 else 1.0
    if kind == 7:
        return (a + b) / _max(1.0, a + b)
    return a + b


@jit
def rule_degrees(table, program, starts, weights, conjunction, disjunction, out):
    """``out[r, n]`` = ``weights[r]`` × the antecedent of rule r on row n; rule r's program is
    ``program[starts[r]:starts[r + 1]]`` over the propositions' degrees ``table`` (L, N)."""
    stack = np.empty(max(1, program.shape[0]))
    for n in range(table.shape[1]):
        for r in range(starts.shape[0] - 1):
            top = 0
            for i in range(starts[r], starts[r + 1]):
                code = program[i]
                if code >= 0:
                    stack[top] = table[code, n]
                    top += 1
                    continue
                top -= 1
                if code == AND:
                    stack[top - 1] = tnorm(conjunction, stack[top - 1], stack[top])
                else:
                    stack[top - 1] = snorm(disjunction, stack[top - 1], stack[top])
            out[r, n] = weights[r] * stack[0]


@jit
def _reduce(kind, mu, x, area):
    """``REDUCTIONS[kind]`` of the sampled set ``mu`` at ``x`` (NaN when it is empty)."""
    size = mu.shape[0]
    if kind == 0:
        total, moment = 0.0, 0.0
        for k in range(size):
            total += mu[k]
            moment += mu[k] * x[k]
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
    top = -np.inf
    for k in range(size):
        if mu[k] != mu[k]:
            return np.nan
        top = max(top, mu[k])
    if not top > 0.0:
        return np.nan
    count, where, first, last = 0, 0.0, -1, -1
    for k in range(size):
        if mu[k] == top:
            count += 1
            where += x[k]
            last = k
            if first < 0:
                first = k
    if kind == 2:
        return where / count
    return x[first] if kind == 3 else x[last]


@jit
def integral(degrees, rows, units, unit_term, unit_implication, shapes, support, x, aggregation, reduction, out):
    """A Mamdani output for every row n: activation a has degree ``degrees[rows[a], n]`` and
    belongs to unit ``units[a]`` (its own, or — Maximum aggregation — the one of every
    activation of the same term and implication, whose degrees max-combine first: T is
    monotone); unit u implies term ``unit_term[u]`` sampled as ``shapes`` (T, R) at ``x`` with the
    T-norm ``unit_implication[u]``. ``support[t]`` = (first, end) of term t's non-zero samples,
    (-1, R) when a sample lies outside [0, 1]."""
    n_units, size = unit_term.shape[0], x.shape[0]
    w = np.empty(n_units)
    mu = np.empty(size)
    area = np.empty(size)
    for n in range(degrees.shape[1]):
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
        mu[:] = 0.0
        for u in range(n_units):
            t, wu = unit_term[u], w[u]
            first, end = 0, size
            if bounded and support[t, 0] >= 0:
                if wu == 0.0:
                    continue
                first, end = support[t, 0], support[t, 1]
            imp = unit_implication[u]
            if bounded and support[t, 0] >= 0 and aggregation == MAXIMUM and imp == MINIMUM:
                for k in range(first, end):  # no NaN here: plain max / min, vectorised
                    mu[k] = max(mu[k], min(wu, shapes[t, k]))
            elif bounded and support[t, 0] >= 0 and aggregation == MAXIMUM and imp == PRODUCT:
                for k in range(first, end):
                    mu[k] = max(mu[k], wu * shapes[t, k])
            else:
                for k in range(first, end):
                    mu[k] = snorm(aggregation, mu[k], tnorm(imp, wu, shapes[t, k]))
        out[n] = _reduce(reduction, mu, x, area)


@jit
def group(degrees, rows, groups, opens, triggered, masked, aggregation, degree, present):
    """Per term group g and row n: ``degree[g, n]`` the S-norm ``aggregation`` folded over its
    activations' degrees in order (``opens[a]``: a is the group's first; 0 where not triggered),
    ``present[g, n]`` whether any triggered (``masked`` False: every activation triggers)."""
    for n in range(degrees.shape[1]):
        for a in range(rows.shape[0]):
            g = groups[a]
            on = (not masked) or triggered[a, n]
            v = degrees[rows[a], n] if on else 0.0
            if opens[a]:
                degree[g, n], present[g, n] = v, on
            else:
                degree[g, n], present[g, n] = snorm(aggregation, degree[g, n], v), present[g, n] or on


@jit
def weighted_average(degree, present, z, weighted_sum, out):
    """Σ_g g z_g / Σ_g g over the groups present in each row (times Σ g for a weighted sum);
    NaN where none is."""
    for n in range(degree.shape[1]):
        num, den, seen = 0.0, 0.0, False
        for g in range(degree.shape[0]):
            if present[g, n]:
                seen = True
                num += degree[g, n] * z[g, n]
                den += degree[g, n]
        y = num / den
        if weighted_sum:
            y = y * den
        out[n] = y if seen else np.nan


@jit
def affine(coefficients, constants, inputs, z):
    """``z[g, n]`` = ``constants[g]`` + Σ_i ``coefficients[g, i]`` × ``inputs[i, n]``: constant and
    linear terms' values on every row."""
    for g in range(z.shape[0]):
        for n in range(z.shape[1]):
            value = constants[g]
            for i in range(coefficients.shape[1]):
                value += coefficients[g, i] * inputs[i, n]
            z[g, n] = value


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

"""An :class:`~fuzzynav.fuzzy.engine.Engine` packed into flat arrays once, for the fused kernel.

:func:`pack` returns the propositions to fuzzify in NumPy before the kernel (terms built on
``exp`` or ``pow``, ``Function`` and ``Linear`` premises: see :mod:`.fuzzify_terms`) and a
:class:`Packed` record of arrays that :func:`fuzzynav.fuzzy.engine.fused_kernel.run` reads (handed
over as a :class:`Flat`), or — for what the kernel does not cover — the reason the engine keeps
its NumPy path: an activation method other than General, or a
weighted output whose conclusions are not all constant or linear (Tsukamoto's inverses, functions
of the degree). Index ranges are ``X_start[k]:X_start[k + 1]``.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from fuzzynav.fuzzy.engine import defuzzify, staged_kernels
from fuzzynav.fuzzy.engine.fuzzify_terms import HEDGE_CODES, pack_term
from fuzzynav.fuzzy.engine.model import Proposition
from fuzzynav.fuzzy.engine.norms import PRODUCT
from fuzzynav.fuzzy.engine.sampled_defuzzify import reduction_of
from fuzzynav.fuzzy.membership import Linear, Singleton
from fuzzynav.fuzzy.operators import SNORMS, TNORMS
from fuzzynav.fuzzy.terms import Constant

NUMPY, TERM, ZERO, ANY, CHAINED = 0, 1, 2, 3, 4  # how a proposition's degree is found (`literal` column 0)
NAN_OUTPUT, INTEGRAL, WEIGHTED, EMPTY = 0, 1, 2, 3  # how an output is computed (EMPTY: weighted, never concluded)


class Packed(NamedTuple):
    """The arrays the fused kernel reads, in the order :func:`fuzzynav.fuzzy.engine.fused_kernel._unpack`
    returns them from a :class:`Flat`."""

    lock: np.ndarray  # inputs: clipped to [lo, hi] where locked
    lo: np.ndarray
    hi: np.ndarray
    literal: np.ndarray  # (L, 5): how (NUMPY…CHAINED), input, term, first and end of its hedges
    term_code: np.ndarray  # terms evaluated in the kernel: code, parameters, height
    term_start: np.ndarray
    term_height: np.ndarray
    params: np.ndarray
    chained: np.ndarray  # (J, 2) per chained proposition: its literal, the output's S-norm, and
    chained_start: np.ndarray  # the conclusions on its term, in order
    chained_conclusions: np.ndarray
    hedges: np.ndarray
    block: np.ndarray  # (B, 4): first rule, end, conjunction, disjunction
    block_chained: np.ndarray  # a block with a chained premise runs rule by rule
    program: np.ndarray  # per rule: postfix antecedent (staged_kernels.AND / OR, or a proposition)
    rule_start: np.ndarray
    rule_weight: np.ndarray
    rule_skipped: np.ndarray  # a rule the rule pass does not compute: its degree its one proposition's row
    # (aliased) or the product of two, computed where its output reads it (deferred)
    rule_conclusions: np.ndarray  # start of the rule's conclusions
    conclusion_hedges: np.ndarray  # (C + 1): start of each conclusion's hedges
    conclusion_row: np.ndarray  # (C,): its row of the rules' values: its rule's (r < R), or its own once hedged
    output: np.ndarray  # (K, 6): kind, aggregation, reduction, weighted sum, lock-previous, lock-range
    output_limits: np.ndarray  # (K, 3): default, minimum, maximum
    act_start: np.ndarray  # per output: its activations (row of degrees, unit or group, opens a group;
    # rows index the propositions' degrees, then the rules' values)
    act_conclusion: np.ndarray
    act_unit: np.ndarray
    act_opens: np.ndarray
    act_partner: np.ndarray  # a deferred rule's second proposition (its first is the activation's row), else −1
    unit_start: np.ndarray  # per output: integral units (term, implication) or weighted groups
    unit_term: np.ndarray
    unit_implication: np.ndarray
    shape_start: np.ndarray  # per integral output: its terms sampled (T × R, flat), points, supports
    shapes: np.ndarray
    points_start: np.ndarray
    points: np.ndarray
    support_start: np.ndarray
    support: np.ndarray
    coefficients: np.ndarray  # per unit: linear coefficients (U, n_inputs) and constants (U,) of weighted groups
    constants: np.ndarray


class Flat(NamedTuple):
    """A :class:`Packed` in three buffers, so that a call hands the kernel four arrays instead of
    38 (each array costs the call its unboxing: microseconds, tens right after other work):
    field k is ``(ints, floats, bools)[layout[k, 0]][layout[k, 1]:…]`` of shape ``layout[k, 2]``
    (by ``layout[k, 3]`` when 2-D, else −1)."""

    ints: np.ndarray
    floats: np.ndarray
    bools: np.ndarray
    layout: np.ndarray


def flatten(packed: Packed) -> Flat:
    """The :class:`Flat` form of ``packed`` (its fields in order)."""
    parts: tuple[list, list, list] = ([], [], [])
    kinds, layout, offsets = (np.int64, np.float64, np.bool_), [], [0, 0, 0]
    for array in packed:
        kind = kinds.index(array.dtype.type)
        layout.append((kind, offsets[kind], array.shape[0], array.shape[1] if array.ndim == 2 else -1))
        parts[kind].append(array.ravel())
        offsets[kind] += array.size
    ints, floats, bools = (np.concatenate([np.empty(0, dtype=t), *p]) for t, p in zip(kinds, parts))
    return Flat(ints, floats, bools, _ints(layout).reshape(-1, 4))


def _ints(values) -> np.ndarray:
    return np.array(values, dtype=np.int64)


def pack(engine) -> tuple[list, Packed] | str:
    """(propositions in table order, :class:`Packed`), or why the kernel cannot evaluate ``engine``."""
    if any(b.enabled and b.rules and b.activation != "General" for b in engine.blocks):
        return "an activation method other than General"
    inputs = {v.name: i for i, v in enumerate(engine.inputs)}
    outputs = {v.name: v for v in engine.outputs}
    literals: dict[Proposition, int] = {}
    program, rule_start, weights, rule_conclusions, blocks, conclusions = [], [0], [], [0], [], []
    for block in (b for b in engine.blocks if b.enabled and b.rules):
        first = len(weights)
        for rule in block.rules:
            _emit(rule.antecedent, literals, program)
            rule_start.append(len(program))
            weights.append(rule.weight)
            conclusions += [(block, c) for c in rule.conclusions]
            rule_conclusions.append(len(conclusions))
        blocks.append((first, len(weights), TNORMS.index(block.conjunction) if block.conjunction else -1,
                       SNORMS.index(block.disjunction) if block.disjunction else -1))
    rows, hedges, terms, chained, chained_start, chained_conclusions = [], [], {}, [], [0], []
    for lit, p in enumerate(literals):
        var = outputs.get(p.variable) or engine.inputs[inputs[p.variable]]
        how, term = NUMPY, -1
        if not var.enabled:
            how = ZERO
        elif p.term is None:
            how = ANY
        elif p.variable in outputs:
            how = CHAINED
            chained.append((lit, SNORMS.index(var.aggregation or "UnboundedSum")))
            chained_conclusions += [c for c, (_, conclusion) in enumerate(conclusions)
                                    if (conclusion.variable, conclusion.term) == (p.variable, p.term)]
            chained_start.append(len(chained_conclusions))
        elif (packed := pack_term(var.terms[p.term])) is not None:
            how, term = TERM, terms.setdefault((p.variable, p.term), (len(terms), packed))[0]
        rows.append((how, inputs.get(p.variable, -1), term, len(hedges), len(hedges) + len(p.hedges)))
        hedges += [HEDGE_CODES[h] for h in reversed(p.hedges)]
    conclusion_hedges, conclusion_row, hedged = [len(hedges)], [], len(weights)
    for r in range(len(weights)):
        row = r  # a rule's degree, until a hedge makes a conclusion's own (carried to the next ones)
        for _, c in conclusions[rule_conclusions[r]:rule_conclusions[r + 1]]:
            hedges += [HEDGE_CODES[h] for h in reversed(c.hedges)]
            conclusion_hedges.append(len(hedges))
            if c.hedges:
                row, hedged = hedged, hedged + 1
            conclusion_row.append(row)
    aliased = [_aliased(program, rule_start, weights, rule_conclusions, conclusions, rows, chained, r)
               for r in range(len(weights))]
    degree_row = [program[rule_start[r]] if aliased[r] else len(literals) + conclusion_row[c]
                  for r in range(len(weights)) for c in range(rule_conclusions[r], rule_conclusions[r + 1])]
    products = {rule_conclusions[r]: (program[rule_start[r]], program[rule_start[r] + 1]) for first, end, conjunction, _
                in blocks for r in range(first, end) if conjunction == PRODUCT
                and _product_of_two(program, rule_start, weights, rule_conclusions, conclusions, chained, r)}
    packed_outputs = _pack_outputs(engine, conclusions, degree_row, products)
    if isinstance(packed_outputs, str):
        return packed_outputs
    *packed_outputs, deferred = packed_outputs
    skipped = [aliased[r] or rule_conclusions[r] in deferred for r in range(len(weights))]
    term_list = [packed for _, packed in terms.values()]
    block_chained = [any(rows[program[i]][0] == CHAINED for i in range(rule_start[first], rule_start[end])
                         if program[i] >= 0) for first, end, *_ in blocks]
    return list(literals), Packed(
        np.array([v.lock_range for v in engine.inputs], dtype=np.bool_),
        np.array([v.minimum for v in engine.inputs], dtype=float), np.array([v.maximum for v in engine.inputs], dtype=float),
        _ints(rows).reshape(-1, 5), _ints([t[0] for t in term_list]),
        _ints(np.cumsum([0] + [len(t[1]) for t in term_list])), np.array([t[2] for t in term_list], dtype=float),
        np.array([p for t in term_list for p in t[1]], dtype=float),
        _ints(chained).reshape(-1, 2), _ints(chained_start), _ints(chained_conclusions), _ints(hedges),
        _ints(blocks).reshape(-1, 4), np.array(block_chained, dtype=np.bool_), _ints(program), _ints(rule_start),
        np.array(weights, dtype=float), np.array(skipped, dtype=np.bool_), _ints(rule_conclusions),
        _ints(conclusion_hedges), _ints(conclusion_row),
        *packed_outputs)


def _aliased(program, rule_start, weights, rule_conclusions, conclusions, rows, chained, r) -> bool:
    """Whether rule r's degree is its one proposition's degree, read in place: a single
    proposition of weight 1 (× 1 changes no bit), no hedged conclusion, and no chained
    proposition in the engine (whose degrees are accumulated from the rules' rows)."""
    first, end = rule_start[r], rule_start[r + 1]
    hedged = any(c.hedges for _, c in conclusions[rule_conclusions[r]:rule_conclusions[r + 1]])
    return end - first == 1 and weights[r] == 1.0 and not hedged and not chained and rows[program[first]][0] != CHAINED


def _product_of_two(program, rule_start, weights, rule_conclusions, conclusions, chained, r) -> bool:
    """Whether rule r (of a block whose conjunction is the product) is p and q of weight 1 with one
    conclusion, not hedged, and no chained proposition in the engine: its degree p q can then be
    computed where its output reads it (:func:`_pack_outputs` defers it when its term group has no
    other activation), the same bits (× 1 changes none)."""
    first, end = rule_start[r], rule_start[r + 1]
    mine = conclusions[rule_conclusions[r]:rule_conclusions[r + 1]]
    return (end - first == 3 and program[end - 1] == staged_kernels.AND and weights[r] == 1.0 and len(mine) == 1
            and not mine[0][1].hedges and not chained)


def _emit(node, literals: dict, program: list) -> None:
    if isinstance(node, Proposition):
        program.append(literals.setdefault(node, len(literals)))
    else:
        _emit(node.left, literals, program)
        _emit(node.right, literals, program)
        program.append(staged_kernels.AND if node.name == "and" else staged_kernels.OR)


def _pack_outputs(engine, conclusions: list, degree_row: list, products: dict) -> tuple | str:
    """The output part of :class:`Packed` (from ``output`` on) then the conclusions deferred, or why
    not; conclusion c's degrees are row ``degree_row[c]`` of the propositions' then the rules'
    values, or — ``products[c]`` = (p, q), :func:`_product_of_two` — the product of propositions p
    and q, computed by a weighted output where c is its term group's only activation."""
    rows, limits, act_start, act_conclusion, act_unit, act_opens = [], [], [0], [], [], []
    act_partner, deferred = [], []
    unit_start, unit_term, unit_implication = [0], [], []
    shape_start, shapes, points_start, points, support_start, support = [0], [], [0], [], [0], []
    coefficients, constants = [], []
    n_in = len(engine.inputs)
    for var in engine.outputs:
        acts = [(c, block.implication, conclusion.term) for c, (block, conclusion) in enumerate(conclusions)
                if conclusion.variable == var.name]
        d = var.defuzzifier
        kind = NAN_OUTPUT if not var.enabled or d is None else INTEGRAL if d.integral else WEIGHTED if acts else EMPTY
        units, n_units, sampled = [], 0, None
        if kind == INTEGRAL:  # units as defuzzify.integral makes them
            keys = [(label, implication) for _, implication, label in acts]
            index = {key: u for u, key in enumerate(dict.fromkeys(keys))} if var.aggregation == "Maximum" else None
            units = [index[key] for key in keys] if index else list(range(len(keys)))
            unique = list(index) if index else keys
            labels = list(var.terms)
            unit_term += [labels.index(label) for label, _ in unique]
            unit_implication += [TNORMS.index(implication) for _, implication in unique]
            n_units, sampled = len(unique), defuzzify.sampled(var)
            coefficients.append(np.zeros((n_units, n_in)))  # unused: groups of weighted outputs share unit offsets
            constants.append(np.zeros(n_units))
        elif kind == WEIGHTED:  # groups as defuzzify.weighted makes them
            groups = {label: g for g, label in enumerate(dict.fromkeys(label for *_, label in acts))}
            mfs = [var.terms[label] for label in groups]
            if d.type == "Tsukamoto" or not all(isinstance(mf, (Constant, Singleton, Linear)) for mf in mfs):
                return f"output {var.name}: a weighted conclusion that is not constant or linear"
            units, n_units = [groups[label] for *_, label in acts], len(groups)
            coef, const = defuzzify._affine_terms(mfs, n_in)
            coefficients.append(coef)
            constants.append(const)
        else:
            acts = []
        act_opens += [a == units.index(u) for a, u in enumerate(units)]
        alone = [kind == WEIGHTED and c in products and units.count(u) == 1 for (c, *_), u in zip(acts, units)]
        act_conclusion += [products[c][0] if a else degree_row[c] for (c, *_), a in zip(acts, alone)]
        act_partner += [products[c][1] if a else -1 for (c, *_), a in zip(acts, alone)]
        deferred += [c for (c, *_), a in zip(acts, alone) if a]
        act_unit += units
        act_start.append(len(act_conclusion))
        unit_start.append(unit_start[-1] + n_units)
        if sampled is not None:
            shapes.append(sampled[0].ravel())
            support.append(sampled[1])
            points.append(sampled[2])
        shape_start.append(sum(a.size for a in shapes))
        support_start.append(sum(len(a) for a in support))
        points_start.append(sum(a.size for a in points))
        rows.append((kind, SNORMS.index(var.aggregation or "UnboundedSum"),
                     reduction_of(d) if kind == INTEGRAL else 0,
                     d is not None and d.kind == "WeightedSum", var.lock_previous, var.lock_range))
        limits.append((var.default, var.minimum, var.maximum))
    return (_ints(rows).reshape(-1, 6), np.array(limits, dtype=float), _ints(act_start), _ints(act_conclusion),
            _ints(act_unit), np.array(act_opens, dtype=np.bool_), _ints(act_partner), _ints(unit_start),
            _ints(unit_term), _ints(unit_implication), _ints(shape_start), np.concatenate([np.empty(0), *shapes]),
            _ints(points_start), np.concatenate([np.empty(0), *points]), _ints(support_start),
            np.concatenate([np.empty((0, 2), dtype=np.int64), *support]).astype(np.int64),
            np.concatenate([np.empty((0, n_in)), *coefficients]), np.concatenate([np.empty(0), *constants]), deferred)

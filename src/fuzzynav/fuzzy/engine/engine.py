"""A fuzzy engine with fuzzylite's full semantics, evaluated on a batch of inputs at once.

``Engine(inputs, outputs, blocks)`` evaluates ``(N, n_inputs) -> (N, n_outputs)`` as fuzzylite 8
processes an engine (J. Rada-Vilela, fuzzylite.com): every enabled rule block in order activates
its rules (degree = weight × antecedent, with the block's conjunction / disjunction and the
hedges), the activation method selects the rules that trigger, each triggered rule adds its
conclusions to the outputs' fuzzy sets, and every output is then defuzzified in order, with its
own aggregation, defuzzifier, ``lock_previous``, ``default`` and ``lock_range``.

A premise on an output variable reads the degree its term has accumulated so far (a chained
system). ``Function`` terms read the current value of every variable (outputs not yet
defuzzified read NaN, the state of a fresh engine). Each call is independent: ``lock_previous``
carries a value from one *row* of the batch to the next, as fuzzylite's vectorised engine does,
starting from NaN. NaN inputs propagate (fuzzylite's behaviour); everything is NumPy over the
batch, one membership evaluation per (input, term).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.engine import defuzzify
from fuzzynav.fuzzy.engine.model import InputVariable, Operator, OutputVariable, Proposition, RuleBlock
from fuzzynav.fuzzy.formula import Function
from fuzzynav.fuzzy.membership import Linear
from fuzzynav.fuzzy.terms import Scaled
from fuzzynav.fuzzy.operators import ACTIVATIONS, HEDGES, SNORMS, TNORMS, activate
from fuzzynav.fuzzy.variable import VariableNames


class Engine(VariableNames):
    """A fuzzylite-style engine: ``evaluate(X)`` maps (N, n_inputs) to (N, n_outputs)."""

    method = "engine"

    def __init__(self, inputs: Sequence[InputVariable], outputs: Sequence[OutputVariable],
                 blocks: Sequence[RuleBlock], *, name: str = "", description: str = ""):
        self.inputs = list(inputs)
        self.outputs = list(outputs)
        self.blocks = list(blocks)
        self.name = name
        self.description = description
        self._check()
        self._flat = [_flatten(block, {v.name for v in self.inputs}) for block in self.blocks]
        self._level_sets: dict = {}  # sorted level sets of max-min centroids, built on first use

    # ------------------------------------------------------------------ construction
    @property
    def rules(self) -> list:
        """Every rule of every block, in order."""
        return [rule for block in self.blocks for rule in block.rules]

    def _check(self) -> None:
        self.check_unique_names()
        if not self.outputs:
            raise InputError("an engine needs at least one output", field="variables")
        for var in self.inputs + self.outputs:
            if not var.minimum <= var.maximum:
                raise InputError(f"range [{var.minimum}, {var.maximum}] is empty", field=f"{var.name}.range")
        for var in self.outputs:
            for label, mf in var.terms.items():
                base = mf.term if isinstance(mf, Scaled) else mf
                if var.defuzzifier is not None and var.defuzzifier.type == "Tsukamoto" and not hasattr(base, "inverse"):
                    raise InputError(f"a {type(base).__name__} term has no inverse for Tsukamoto's method (monotone "
                                     "terms: Ramp, Sigmoid, SShape, ZShape, Concave, Arc)", field=f"{var.name}.{label}")
                if isinstance(mf, Linear) and len(mf.coefficients) != len(self.inputs):
                    raise InputError(f"a linear term takes {len(self.inputs)} coefficients (one per input) and a "
                                     f"constant, got {len(mf.params())} numbers", field=f"{var.name}.{label}")
            if var.aggregation is not None and var.aggregation not in SNORMS:
                raise InputError(f"unknown aggregation {var.aggregation!r} (one of {', '.join(SNORMS)})",
                                 field=f"{var.name}.aggregation")
            if var.enabled and var.defuzzifier is None and any(c.variable == var.name for r in self.rules
                                                               for c in r.conclusions):
                raise InputError("an output that rules conclude on needs a defuzzifier", field=f"{var.name}.defuzzifier")
            if var.defuzzifier is not None and var.defuzzifier.integral:
                if var.defuzzifier.resolution < 1:
                    raise InputError("resolution must be >= 1", field=f"{var.name}.defuzzifier")
                for label, mf in var.terms.items():
                    if isinstance(mf, Function) and mf.variables:
                        raise InputError("a Function term of an integral output may use only x",
                                         field=f"{var.name}.{label}")
        for b, block in enumerate(self.blocks):
            where = f"RuleBlock {block.name or b + 1}"
            for key, table in (("conjunction", TNORMS), ("implication", TNORMS), ("disjunction", SNORMS)):
                value = getattr(block, key)
                if value is not None and value not in table:
                    raise InputError(f"unknown {key} {value!r} (one of {', '.join(table)})", field=f"{where}.{key}")
            if block.activation not in ACTIVATIONS:
                raise InputError(f"unknown activation {block.activation!r} (one of {', '.join(ACTIVATIONS)})",
                                 field=f"{where}.activation")
            for rule in block.rules:
                self._check_rule(rule, block, where)

    def _check_rule(self, rule, block: RuleBlock, where: str) -> None:
        def operators(node):
            return set() if isinstance(node, Proposition) else {node.name} | operators(node.left) | operators(node.right)
        used = operators(rule.antecedent)
        for op, key in (("and", "conjunction"), ("or", "disjunction")):
            if op in used and getattr(block, key) is None:
                raise InputError(f"rule uses '{op}' but the block has no {key}", field=f"{where}: {rule.text()}")
        outputs = {v.name: v for v in self.outputs}
        if block.implication is None and any(
                outputs[c.variable].defuzzifier is not None and outputs[c.variable].defuzzifier.integral
                for c in rule.conclusions):
            raise InputError("a rule concluding on an integral-defuzzified output needs an implication",
                             field=f"{where}: {rule.text()}")

    # ------------------------------------------------------------------ evaluation
    def _values(self, X) -> tuple[np.ndarray, dict]:
        """Input values as rows (n_inputs, N), clipped where locked, and every variable's value by name."""
        X = np.asarray(X, dtype=float)
        if X.ndim != 2 or X.shape[1] != len(self.inputs):
            raise InputError(f"expected an array of shape (N, {len(self.inputs)}) "
                             f"({', '.join(self.input_names)}), got {X.shape}", field="inputs")
        columns = np.array(X.T, order="C")  # (n_inputs, N): one contiguous row per input
        values = {}
        for i, var in enumerate(self.inputs):
            if var.lock_range:
                np.clip(columns[i], var.minimum, var.maximum, out=columns[i])
            values[var.name] = columns[i]
        for var in self.outputs:
            values[var.name] = np.full(X.shape[0], np.nan)
        return columns, values

    def evaluate(self, X) -> np.ndarray:
        """Outputs for a batch of inputs: X (N, n_in) -> (N, n_out), columns in ``output_names``."""
        X = np.asarray(X, dtype=float)
        columns, values = self._values(X)
        n = X.shape[0]
        state = _State(self, values, n)
        for block, flat in zip(self.blocks, self._flat):
            if block.enabled:
                state.run(block, flat)
        out = np.full((n, len(self.outputs)), np.nan)
        for k, var in enumerate(self.outputs):
            if not var.enabled or var.defuzzifier is None:
                continue
            acts = state.fuzzy[var.name]
            if var.defuzzifier.integral:
                y = defuzzify.integral(var, acts, n, self._level_sets)
            else:
                y = defuzzify.weighted(var, state.groups(var), columns, values)
            y = _finish(var, y)
            values[var.name] = y
            out[:, k] = y
        return out

    def evaluate_one(self, *x: float) -> tuple[float, ...]:
        """Outputs for one input vector (a thin wrapper of :meth:`evaluate`)."""
        if len(x) != len(self.inputs):
            raise InputError(f"expected {len(self.inputs)} values ({', '.join(self.input_names)}), got {len(x)}",
                             field="inputs")
        return tuple(self.evaluate(np.array([x], dtype=float))[0].tolist())

    def __repr__(self) -> str:
        return (f"Engine({self.name or 'unnamed'}: inputs={self.input_names}, outputs={self.output_names}, "
                f"{len(self.blocks)} block(s), {len(self.rules)} rules)")


def _flatten(block: RuleBlock, inputs: set):
    """(literals, index (n_rules, k), operator, weights) when every rule of ``block`` joins
    propositions on inputs by a single operator (the same one in every rule), else ``None``."""
    def leaves(node, op):
        if isinstance(node, Proposition):
            return [node], op
        if op is not None and node.name != op:
            return None, None
        left, op = leaves(node.left, node.name)
        right, op2 = leaves(node.right, node.name) if left is not None else (None, None)
        return (left + right, node.name) if right is not None else (None, None)
    literals, premises, block_op = {}, [], None
    for rule in block.rules:
        props, op = leaves(rule.antecedent, block_op)
        if props is None or any(p.variable not in inputs for p in props):
            return None
        block_op = op or block_op
        premises.append([literals.setdefault(p, len(literals)) for p in props])
    if not premises:
        return None
    width = max(len(p) for p in premises)
    index = np.array([p + [len(literals)] * (width - len(p)) for p in premises], dtype=np.intp)
    return list(literals), index, block_op, np.array([rule.weight for rule in block.rules])


def _finish(var: OutputVariable, y: np.ndarray) -> np.ndarray:
    """lock-previous (NaN -> the previous row's value), default (NaN -> default), lock-range (clip)."""
    if var.lock_previous:
        index = np.where(np.isnan(y), -1, np.arange(y.shape[0]))
        np.maximum.accumulate(index, out=index)
        y = np.where(index >= 0, y[np.maximum(index, 0)], np.nan)
    if not np.isnan(var.default):
        y = np.where(np.isnan(y), var.default, y)
    if var.lock_range:
        y = np.clip(y, var.minimum, var.maximum)
    return y


class _State:
    """The fuzzy outputs while rule blocks run: per output, (term, degree, triggered, implication)."""

    def __init__(self, engine: Engine, values: dict, n: int):
        self.vars = {v.name: v for v in engine.inputs + engine.outputs}
        self.outputs = {v.name for v in engine.outputs}
        self.values = values
        self.n = n
        self.memo: dict = {}
        self.fuzzy: dict[str, list] = {v.name: [] for v in engine.outputs}

    def run(self, block: RuleBlock, flat) -> None:
        if block.activation == "General" and flat is not None:  # every rule at once: (n_rules, N)
            for rule, degree in zip(block.rules, self.flat_degrees(block, *flat)):
                self.trigger(rule, degree, None, block)
            return
        if block.activation == "General":  # rule by rule: a chained premise sees the rules before it
            for rule in block.rules:
                self.trigger(rule, rule.weight * self.degree(rule.antecedent, block), None, block)
            return
        degrees = np.column_stack([rule.weight * self.degree(rule.antecedent, block) for rule in block.rules]) \
            if block.rules else np.zeros((self.n, 0))
        degrees, triggered = activate(block.activation, block.activation_params, degrees)
        for r, rule in enumerate(block.rules):
            self.trigger(rule, degrees[:, r], triggered[:, r], block)

    def flat_degrees(self, block: RuleBlock, literals, index, op, weights) -> np.ndarray:
        """Degrees of rules that each join their premises by one operator ``op``, all at once."""
        rows = [self.degree(p, block) for p in literals]
        rows.append(np.ones(self.n) if op != "or" else np.zeros(self.n))  # the neutral element pads short rules
        table = np.stack(rows)
        degrees = table[index[:, 0]]
        if index.shape[1] > 1:
            norm = TNORMS[block.conjunction] if op == "and" else SNORMS[block.disjunction]
            for k in range(1, index.shape[1]):
                degrees = norm(degrees, table[index[:, k]])
        return degrees * weights[:, None] if (weights != 1.0).any() else degrees

    def trigger(self, rule, degree, triggered, block: RuleBlock) -> None:
        for conclusion in rule.conclusions:
            for hedge in reversed(conclusion.hedges):  # fuzzylite carries the hedged degree to the next conclusion
                degree = HEDGES[hedge](degree)
            if self.vars[conclusion.variable].enabled:
                self.fuzzy[conclusion.variable].append((conclusion.term, degree, triggered, block.implication))

    def degree(self, node, block: RuleBlock) -> np.ndarray:
        if isinstance(node, Operator):
            left, right = self.degree(node.left, block), self.degree(node.right, block)
            return (TNORMS[block.conjunction] if node.name == "and" else SNORMS[block.disjunction])(left, right)
        var = self.vars[node.variable]
        if not var.enabled:
            return np.zeros(self.n)
        if node.term is None:  # ... is [hedges] any
            result = np.full(self.n, np.nan)
        elif node.variable in self.outputs:
            result = self.grouped(var, node.term)[0]
        else:
            key = (node.variable, node.term)
            if key not in self.memo:
                mf = var.terms[node.term]
                x = self.values[node.variable]
                self.memo[key] = mf(x, self.values) if isinstance(mf, Function) else np.broadcast_to(mf(x), x.shape)
            result = self.memo[key]
        for hedge in reversed(node.hedges):
            result = HEDGES[hedge](result)
        return np.broadcast_to(result, (self.n,))

    def grouped(self, var: OutputVariable, label: str) -> tuple[np.ndarray, np.ndarray | None]:
        """Degree a term has accumulated (output's S-norm, or sum) and where it was triggered at all
        (``None``: everywhere)."""
        return self.groups(var, label).get(label, (np.zeros(self.n), np.zeros(self.n, dtype=bool)))

    def groups(self, var: OutputVariable, only: str | None = None) -> dict:
        """``{term: (degree, present)}`` over the activations of ``var`` (of term ``only`` if given)."""
        snorm = SNORMS[var.aggregation or "UnboundedSum"]
        out: dict = {}
        for term, d, triggered, _ in self.fuzzy[var.name]:
            if only is not None and term != only:
                continue
            if triggered is not None:
                d = np.where(triggered, d, 0.0)
            if term not in out:
                out[term] = (d, triggered)
                continue
            degree, present = out[term]
            both = None if present is None or triggered is None else present | triggered
            out[term] = (snorm(degree, d), both)
        return out

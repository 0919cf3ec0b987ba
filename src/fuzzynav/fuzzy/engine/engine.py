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
starting from NaN. NaN inputs propagate (fuzzylite's behaviour).

An engine with General activation and constant, linear or integral-defuzzified outputs (every
Mamdani and Takagi–Sugeno example fuzzylite ships) is packed into arrays on first use and
evaluated by one compiled call (:mod:`fuzzynav.fuzzy.engine.fused_kernel`), only its ``exp``/``pow``
terms fuzzified in NumPy first. Others (:attr:`Engine.fallback` says why) take the NumPy path:
terms and hedges in NumPy over the batch, once per proposition; rules, aggregation and
defuzzification compiled over the rows (:mod:`fuzzynav.fuzzy.engine.staged_kernels`). Both give the
same bits (tested on every fuzzylite example).
"""

from __future__ import annotations

import functools
from collections.abc import Sequence

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.engine import defuzzify
from fuzzynav.fuzzy.engine.checks import check_values
from fuzzynav.fuzzy.engine.model import InputVariable, OutputVariable, Proposition, RuleBlock
from fuzzynav.fuzzy.formula import Function
from fuzzynav.fuzzy.membership import Linear
from fuzzynav.fuzzy.operators import ACTIVATIONS, HEDGES, SNORMS, TNORMS, activate
from fuzzynav.fuzzy.terms import Scaled
from fuzzynav.fuzzy.variable import VariableNames


class Engine(VariableNames):
    """A fuzzylite-style engine: ``evaluate(X)`` maps (N, n_inputs) to (N, n_outputs)."""

    method = "engine"

    def __init__(self, inputs: Sequence[InputVariable], outputs: Sequence[OutputVariable],
                 blocks: Sequence[RuleBlock], *, name: str = "", description: str = ""):
        self.inputs = list(inputs)
        self.outputs = list(outputs)
        self.blocks = list(blocks)
        self.name = validation.text(name, field="name", one_line=True)  # printed by fis show, plotted
        self.description = description
        self._check()
        self._programs = [_program(block, {v.name for v in self.outputs}) for block in self.blocks]
        self._sampled: dict = {}  # integral outputs' terms sampled at their defuzzifier's points, on first use
        self._packed = None  # the engine as the fused kernel's arrays (or why not), on first use

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
        for var in self.inputs:  # (as FuzzySystem says it) Linear reads the input vector, not a degree of x
            for label, mf in var.terms.items():
                if isinstance(mf.term if isinstance(mf, Scaled) else mf, Linear):
                    raise InputError("a linear term concludes a ts1 rule; it cannot describe an input",
                                     field=f"{var.name}.{label}")
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
                validation.integer(var.defuzzifier.resolution, field=f"{var.name}.defuzzifier resolution", lo=1,
                                   hi=validation.MAX_RESOLUTION)
                for label, mf in var.terms.items():
                    if isinstance(mf, Function) and mf.variables:
                        raise InputError("a Function term of an integral output may use only x",
                                         field=f"{var.name}.{label}")
        if not self.rules:
            raise InputError("a fuzzy system needs at least one rule", field="rules")
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
        check_values(self.inputs, self.outputs, self.blocks)

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
        X = self.input_matrix(X)
        columns = np.array(X.T, order="C")  # (n_inputs, N): one contiguous row per input
        values = {}
        for i, var in enumerate(self.inputs):
            if var.lock_range:
                np.clip(columns[i], var.minimum, var.maximum, out=columns[i])
            values[var.name] = columns[i]
        for var in self.outputs:
            values[var.name] = np.full(X.shape[0], np.nan)
        return columns, values

    @property
    def fallback(self) -> str | None:
        """Why :meth:`evaluate` keeps the NumPy path; None when one compiled kernel evaluates the
        engine (:mod:`fuzzynav.fuzzy.engine.fused_kernel`)."""
        if self._packed is None:  # packed once: a call then costs no imports nor searches
            from fuzzynav.fuzzy.engine import fused_kernel
            from fuzzynav.fuzzy.engine.pack import NUMPY, flatten, pack

            packed = pack(self)
            self._packed = packed if isinstance(packed, str) else \
                (*packed, np.flatnonzero(packed[1].literal[:, 0] == NUMPY).tolist(),
                 functools.partial(fused_kernel.evaluate, flatten(packed[1])))
        return self._packed if isinstance(self._packed, str) else None

    def evaluate(self, X) -> np.ndarray:
        """Outputs for a batch of inputs: X (N, n_in) -> (N, n_out), columns in ``output_names``."""
        X = self.input_matrix(X)
        n = X.shape[0]
        if self.fallback is None:
            literals, _, in_numpy, evaluate_fused = self._packed  # in_numpy: propositions NumPy fuzzifies
            table = np.empty((len(literals), n) if in_numpy else (0, 0))  # read by the kernel only if in_numpy
            if in_numpy:
                state = _State(self, self._values(X)[1], n)
                for row in in_numpy:
                    table[row] = state.degree(literals[row])
            return evaluate_fused(table, X)
        from fuzzynav.fuzzy.engine import staged_kernels

        columns, values = self._values(X)
        state = _State(self, values, n)
        for block, program in zip(self.blocks, self._programs):
            if block.enabled and block.rules:
                state.run(block, program)
        out = np.full((n, len(self.outputs)), np.nan)
        for k, var in enumerate(self.outputs):
            if not var.enabled or var.defuzzifier is None:
                continue
            acts = state.activations(var)
            if var.defuzzifier.integral:
                if var.name not in self._sampled:
                    self._sampled[var.name] = defuzzify.sampled(var)
                y = defuzzify.integral(var, acts, self._sampled[var.name], n)
            else:
                y = defuzzify.weighted(var, acts, columns, values)
            staged_kernels.finish(y, var.lock_previous, var.default, var.lock_range, var.minimum, var.maximum)
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


def _program(block: RuleBlock, outputs: set) -> tuple:
    """(propositions, program, starts, weights, chained): every rule's antecedent in postfix over
    the block's distinct propositions (see :func:`~fuzzynav.fuzzy.engine.staged_kernels.rule_degrees`);
    ``chained`` when a premise reads an output."""
    from_codes = {"and": -1, "or": -2}  # staged_kernels.AND, staged_kernels.OR
    literals: dict = {}
    program, starts = [], [0]

    def emit(node):
        if isinstance(node, Proposition):
            program.append(literals.setdefault(node, len(literals)))
        else:
            emit(node.left)
            emit(node.right)
            program.append(from_codes[node.name])
    for rule in block.rules:
        emit(rule.antecedent)
        starts.append(len(program))
    chained = any(p.variable in outputs for p in literals)
    return (list(literals), np.array(program, dtype=np.int64), np.array(starts, dtype=np.int64),
            np.array([rule.weight for rule in block.rules], dtype=float), chained)


class _State:
    """The fuzzy outputs while rule blocks run: per output, its activations in order, each
    (term, degrees, row, triggered, implication) — the activation degree is ``degrees[row]``
    (several activations share one array of rule degrees), ``triggered`` None where every row
    triggers."""

    def __init__(self, engine: Engine, values: dict, n: int):
        self.vars = {v.name: v for v in engine.inputs + engine.outputs}
        self.outputs = {v.name for v in engine.outputs}
        self.values = values
        self.n = n
        self.memo: dict = {}
        self.fuzzy: dict[str, list] = {v.name: [] for v in engine.outputs}

    def run(self, block: RuleBlock, program) -> None:
        literals, codes, starts, weights, chained = program
        if block.activation == "General" and chained:  # rule by rule: a chained premise sees the rules before it
            for r, rule in enumerate(block.rules):
                self.trigger(rule, self.rule_degrees(block, literals, codes, starts[r:r + 2], weights[r:r + 1]), 0,
                             None, block)
            return
        degrees = self.rule_degrees(block, literals, codes, starts, weights)  # (n_rules, N)
        if block.activation == "General":
            for r, rule in enumerate(block.rules):
                self.trigger(rule, degrees, r, None, block)
            return
        degrees, triggered = activate(block.activation, block.activation_params, degrees.T)
        degrees, triggered = np.ascontiguousarray(degrees.T), np.ascontiguousarray(triggered.T)
        for r, rule in enumerate(block.rules):
            self.trigger(rule, degrees, r, triggered[r], block)

    def rule_degrees(self, block: RuleBlock, literals, codes, starts, weights) -> np.ndarray:
        """Weighted antecedent degrees (n_rules, N) of the rules whose programs ``starts`` delimits."""
        from fuzzynav.fuzzy.engine import staged_kernels

        table = np.stack([self.degree(p) for p in literals]) if literals else np.empty((0, self.n))
        out = np.empty((len(starts) - 1, self.n))
        conjunction = TNORMS.index(block.conjunction) if block.conjunction else -1
        disjunction = SNORMS.index(block.disjunction) if block.disjunction else -1
        staged_kernels.rule_degrees(table, codes, starts, weights, conjunction, disjunction, out)
        return out

    def trigger(self, rule, degrees: np.ndarray, row: int, triggered, block: RuleBlock) -> None:
        for conclusion in rule.conclusions:
            if conclusion.hedges:  # fuzzylite carries the hedged degree to the next conclusion
                degree = degrees[row]
                for hedge in reversed(conclusion.hedges):
                    degree = HEDGES[hedge](degree)
                degrees, row = np.asarray(degree, dtype=float)[None, :], 0
            if self.vars[conclusion.variable].enabled:
                self.fuzzy[conclusion.variable].append((conclusion.term, degrees, row, triggered, block.implication))

    def degree(self, node: Proposition) -> np.ndarray:
        """Degree of a proposition (hedges applied) for every row."""
        var = self.vars[node.variable]
        if not var.enabled:
            return np.zeros(self.n)
        if node.term is None:  # ... is [hedges] any
            result = np.full(self.n, np.nan)
        elif node.variable in self.outputs:
            result = self.accumulated(var, node.term)
        else:
            key = (node.variable, node.term)
            if key not in self.memo:
                mf = var.terms[node.term]
                x = self.values[node.variable]
                self.memo[key] = mf(x, self.values) if isinstance(mf, Function) else mf(x)
            result = self.memo[key]
        for hedge in reversed(node.hedges):
            result = HEDGES[hedge](result)
        return result if np.shape(result) == (self.n,) else np.broadcast_to(result, (self.n,))

    def accumulated(self, var: OutputVariable, label: str) -> np.ndarray:
        """Degree the term ``label`` of ``var`` has accumulated so far (0 where never triggered)."""
        acts = self.activations(var, label)
        return defuzzify.group(var, acts)[1][0] if acts.labels else np.zeros(self.n)

    def activations(self, var: OutputVariable, only: str | None = None) -> defuzzify.Activations:
        """The activations of ``var`` (of its term ``only`` if given) as flat arrays."""
        acts = [a for a in self.fuzzy[var.name] if only is None or a[0] == only]
        if len({id(a[1]) for a in acts}) == 1:
            degrees, rows = acts[0][1], [a[2] for a in acts]
        else:
            degrees = np.stack([a[1][a[2]] for a in acts]) if acts else np.empty((0, self.n))
            rows = list(range(len(acts)))
        triggered = None
        if any(a[3] is not None for a in acts):
            triggered = np.stack([np.ones(self.n, dtype=bool) if a[3] is None else a[3] for a in acts])
        return defuzzify.Activations(degrees, np.array(rows, dtype=np.int64), [a[0] for a in acts],
                                     [a[4] for a in acts], triggered)

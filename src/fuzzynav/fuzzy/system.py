"""The fuzzy inference system: an engine object holding variables and rules (thesis §II.3–II.4).

``FuzzySystem(inputs, outputs, rules, method=...)`` is checked and compiled once; treat it as
immutable (build a new one to change a rule). Methods (§II.4.3):

- ``"ts0"`` — Takagi–Sugeno order 0: output terms are :class:`Singleton` values b_i,
  y = Σ w_i b_i (``weighted_sum``, eq IV.4) or Σ w_i b_i / Σ w_i (``weighted_average``, II.40);
- ``"ts1"`` — order 1: output terms are :class:`Linear` (affine in the inputs) or singletons;
- ``"tsukamoto"`` — monotone output terms (:class:`Ramp`, :class:`Sigmoid`), z_i = B_i⁻¹(w_i),
  y = Σ w_i z_i / Σ w_i (§II.4.3.3);
- ``"mamdani"`` — output sets clipped (``implication="min"``) or scaled (``"product"``),
  aggregated by ``"max"`` or ``"sum"``, centroid defuzzification on ``resolution`` samples.

Firing strengths use the ``tnorm`` ``"product"`` (eq IV.5, the thesis' choice) or ``"min"``.
Every input is clamped to its universe before fuzzification (see :mod:`fuzzynav.fuzzy.variable`).
TS0 systems whose inputs are piecewise-linear run on :mod:`fuzzynav.fuzzy.fastpath`.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.fuzzy import inference
from fuzzynav.fuzzy.fastpath import StrongPartitionKernel
from fuzzynav.fuzzy.membership import Linear, Ramp, Sigmoid, Singleton
from fuzzynav.fuzzy.rules import Rule, parse_rule
from fuzzynav.fuzzy.variable import Variable, VariableNames

METHODS = ("ts0", "ts1", "tsukamoto", "mamdani")
_DEFAULT_DEFUZZIFIER = {"ts0": "weighted_average", "ts1": "weighted_average",
                        "tsukamoto": "weighted_average", "mamdani": "centroid"}


@dataclass(frozen=True)
class Compiled:
    """Rule base as index arrays: term index per (rule, input) and per (rule, output), −1 = none."""

    premises: np.ndarray  # (n_rules, n_in) int
    conclusions: np.ndarray  # (n_rules, n_out) int
    weights: np.ndarray  # (n_rules,)
    values: np.ndarray  # (n_rules, n_out) singleton values (TS0), 0 where not applicable


def _choice(name: str, value: str, allowed: Sequence[str]) -> str:
    if value not in allowed:
        raise InputError(f"must be one of {', '.join(allowed)}, got {value!r}", field=name)
    return value


class FuzzySystem(VariableNames):
    """A fuzzy inference system: ``evaluate(X)`` maps (N, n_inputs) to (N, n_outputs)."""

    def __init__(
        self,
        inputs: Sequence[Variable],
        outputs: Sequence[Variable],
        rules: Sequence[Rule | str],
        *,
        method: str = "ts0",
        tnorm: str = "product",
        defuzzifier: str | None = None,
        implication: str = "min",
        aggregation: str = "max",
        resolution: int = 200,
        name: str = "",
        description: str = "",
    ):
        self.inputs = list(inputs)
        self.outputs = list(outputs)
        self.rules = [parse_rule(r) if isinstance(r, str) else r for r in rules]
        self.method = _choice("method", method, METHODS)
        self.tnorm = _choice("tnorm", tnorm, inference.TNORMS)
        self.defuzzifier = _choice("defuzzifier", _DEFAULT_DEFUZZIFIER[method] if defuzzifier is None else defuzzifier,
                                   ("centroid",) if method == "mamdani" else ("weighted_sum", "weighted_average"))
        self.implication = _choice("implication", implication, inference.IMPLICATIONS)
        self.aggregation = _choice("aggregation", aggregation, inference.AGGREGATIONS)
        self.resolution = validation.integer(resolution, field="resolution", lo=2, hi=validation.MAX_RESOLUTION)
        self.name = validation.text(name, field="name", one_line=True)  # printed by fis show, plotted
        self.description = description
        self._check_variables()
        self.compiled = self._compile()
        self._kernel = StrongPartitionKernel.build(self)

    # ------------------------------------------------------------------ construction
    @property
    def fast(self) -> bool:
        """True when evaluation runs on the piecewise-linear kernel of :mod:`fastpath`."""
        return self._kernel is not None

    def _check_variables(self) -> None:
        if not self.inputs or not self.outputs:
            raise InputError("a fuzzy system needs at least one input and one output", field="variables")
        self.check_unique_names()
        if not self.rules:
            raise InputError("a fuzzy system needs at least one rule", field="rules")
        concluded = {variable for rule in self.rules for variable, _ in rule.conclusions}
        for var in self.outputs:
            if var.name not in concluded:
                raise InputError("no rule concludes on this output (it would always answer 0)",
                                 field=f"outputs.{var.name}")
        for var in self.inputs:
            for label, mf in var.terms.items():
                if isinstance(mf, Linear):
                    raise InputError("a linear term concludes a ts1 rule; it cannot describe an input",
                                     field=f"inputs.{var.name}.{label}")
        allowed = {"ts0": (Singleton,), "ts1": (Singleton, Linear), "tsukamoto": (Ramp, Sigmoid)}
        for var in self.outputs:
            for label, mf in var.terms.items():
                field = f"outputs.{var.name}.{label}"
                ok = isinstance(mf, allowed[self.method]) if self.method in allowed else not isinstance(
                    mf, (Linear, Singleton))
                if not ok:
                    raise InputError(f"a {type(mf).__name__} term cannot conclude a {self.method} rule", field=field)
                if isinstance(mf, Linear) and len(mf.coefficients) != len(self.inputs):
                    raise InputError(f"linear term needs {len(self.inputs)} coefficients, has {len(mf.coefficients)}",
                                     field=field)
                if isinstance(mf, Singleton) and not var.universe[0] <= mf.value <= var.universe[1]:
                    raise InputError(f"singleton {mf.value!r} outside the universe {var.universe}", field=field)

    def _compile(self) -> Compiled:
        ins = {v.name: (i, v) for i, v in enumerate(self.inputs)}
        outs = {v.name: (i, v) for i, v in enumerate(self.outputs)}
        n = len(self.rules)
        premises = np.full((n, len(self.inputs)), -1, dtype=np.intp)
        conclusions = np.full((n, len(self.outputs)), -1, dtype=np.intp)
        values = np.zeros((n, len(self.outputs)))
        for r, rule in enumerate(self.rules):
            field = f"rules[{r}] ({rule.text()})"
            for table, known, pairs, side in ((premises, ins, rule.premises, "input"),
                                              (conclusions, outs, rule.conclusions, "output")):
                for var_name, label in pairs:
                    if var_name not in known:
                        raise InputError(f"unknown {side} variable {var_name!r} (known: {', '.join(known)})",
                                         field=field)
                    i, var = known[var_name]
                    if label not in var.terms:
                        raise InputError(f"unknown term {label!r} of {var_name!r} (known: {', '.join(var.labels)})",
                                         field=field)
                    if table[r, i] >= 0:
                        raise InputError(f"variable {var_name!r} appears twice", field=field)
                    table[r, i] = var.index(label)
            for o, var in enumerate(self.outputs):
                term = list(var.terms.values())[conclusions[r, o]] if conclusions[r, o] >= 0 else None
                if isinstance(term, Singleton):
                    values[r, o] = term.value
        weights = np.array([rule.weight for rule in self.rules])
        return Compiled(premises, conclusions, weights, values)

    # ------------------------------------------------------------------ evaluation
    def _checked(self, X) -> np.ndarray:
        """``X`` as a float array (N, n_in), NaN-free (InputError otherwise), not yet clamped."""
        X = self.input_matrix(X)
        with np.errstate(over="ignore", invalid="ignore"):  # ±1e308 inputs overflow the sum to inf, quietly
            screened = np.isnan(X.sum())  # cheap screen; inf - inf also lands here
        if screened:
            bad = np.isnan(X).any(axis=0)
            if bad.any():
                raise InputError("NaN input", field=", ".join(np.array(self.input_names)[bad]))
        return X

    def _batch(self, X) -> np.ndarray:
        """Checked inputs clamped to their universes, (N, n_in)."""
        X = self._checked(X)
        out = np.empty_like(X)
        for i, v in enumerate(self.inputs):
            np.minimum(np.maximum(X[:, i], v.universe[0]), v.universe[1], out=out[:, i])
        return out

    def _memberships(self, X: np.ndarray) -> list[np.ndarray]:
        return [v.fuzzify(X[:, i], clamp=False) for i, v in enumerate(self.inputs)]

    def _strengths(self, X: np.ndarray) -> np.ndarray:
        c = self.compiled
        return inference.firing(self._memberships(X), c.premises, c.weights, self.tnorm)

    def firing_strengths(self, X, normalise: bool = True) -> np.ndarray:
        """Firing strength of every rule for a batch: (N, n_rules), rule order of ``rules``.

        w_r = weight_r · T(μ(x_i)) (eq IV.5); ``normalise`` divides by Σ_r w_r (ANFIS layer 3,
        fuzzy Q-learning's α_i(x)); a row where no rule fires stays 0.
        """
        w = self._strengths(self._batch(X))
        return inference.normalised(w) if normalise else w

    def _rule_values(self, X: np.ndarray, w: np.ndarray, o: int) -> np.ndarray:
        """Crisp conclusion z_r of every rule on output ``o``: (n_rules,) or (N, n_rules)."""
        c = self.compiled
        if self.method == "ts0":
            return c.values[:, o]
        terms = list(self.outputs[o].terms.values())
        if self.method == "tsukamoto":
            return inference.tsukamoto_values(w, terms, c.conclusions[:, o])
        z = np.zeros((X.shape[0], len(self.rules)))
        for r, t in enumerate(c.conclusions[:, o]):
            if t >= 0:
                term = terms[t]
                z[:, r] = term(X) if isinstance(term, Linear) else term.value
        return z

    def _generic(self, X: np.ndarray) -> np.ndarray:
        c = self.compiled
        w = self._strengths(X)
        out = np.empty((X.shape[0], len(self.outputs)))
        for o, var in enumerate(self.outputs):
            concl = c.conclusions[:, o]
            if self.method == "mamdani":
                samples = inference.centroid_grid(var.universe, self.resolution)
                term_mu = np.array([mf(samples) for mf in var.terms.values()])
                out[:, o] = inference.mamdani(w, samples, term_mu, concl, self.implication, self.aggregation)
            else:
                out[:, o] = inference.combine(w, self._rule_values(X, w, o), concl >= 0, self.defuzzifier)
        return out

    def evaluate(self, X) -> np.ndarray:
        """Outputs for a batch of inputs: X (N, n_in) -> (N, n_out), columns in ``output_names``.

        Inputs are clamped to their universes; a NaN input raises :class:`InputError`. An output
        on which no rule fires is NaN (weighted average, centroid) or 0 (weighted sum).
        """
        if self._kernel is not None:
            return self._kernel.evaluate(self._checked(X))
        return self._generic(self._batch(X))

    def evaluate_one(self, *x: float) -> tuple[float, ...]:
        """Outputs for one input vector, ``evaluate_one(drg, theta) -> (alpha, v)``.

        Plain Python on the fast kernel (a few µs); otherwise a thin wrapper of :meth:`evaluate`.
        """
        if len(x) != len(self.inputs):
            raise InputError(f"expected {len(self.inputs)} values ({', '.join(self.input_names)}), got {len(x)}",
                             field="inputs")
        if self._kernel is None:
            return tuple(self.evaluate(np.array([x], dtype=float))[0].tolist())
        return self._kernel.evaluate_one(x)

    def contributions(self, X) -> np.ndarray:
        """Per-rule share of every output, (N, n_rules, n_out), summing over rules to ``evaluate(X)``.

        Rule r contributes w_r z_r (weighted sum) or w_r z_r / Σ w (weighted average): this is
        what explains a decision ("rule 12 pushed α by +0.2 rad"). Defined for the additive
        methods (TS0, TS1, Tsukamoto); Mamdani's centroid does not decompose over rules.
        """
        if self.method == "mamdani":
            raise ValueError("contributions are defined for the additive methods (ts0, ts1, tsukamoto)")
        X = self._batch(X)
        c = self.compiled
        w = self._strengths(X)
        out = np.empty((X.shape[0], len(self.rules), len(self.outputs)))
        for o in range(len(self.outputs)):
            concl = c.conclusions[:, o] >= 0
            share = w * concl
            if self.defuzzifier == "weighted_average":
                share = inference.normalised(share)
            z = self._rule_values(X, w, o)
            out[:, :, o] = share * z
        return out

    # ------------------------------------------------------------------ display
    def __repr__(self) -> str:
        return (f"FuzzySystem({self.name or 'unnamed'}: {self.method}, inputs={self.input_names}, "
                f"outputs={self.output_names}, {len(self.rules)} rules)")

    def __eq__(self, other) -> bool:
        keys = ("inputs", "outputs", "rules", "method", "tnorm", "defuzzifier", "implication", "aggregation",
                "resolution", "name", "description")
        return isinstance(other, FuzzySystem) and all(getattr(self, k) == getattr(other, k) for k in keys)

    __hash__ = None  # mutable-looking container: equality by value, not hashable

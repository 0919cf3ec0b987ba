"""The one extractor of learned rule bases: a premise's rules with one chosen conclusion each, as a TS0 system (§VI.4).

Every learned fuzzy controller of the package is a zero-order Takagi–Sugeno rule base whose rules
keep the premises they were learned on and conclude, for each output, the candidate the learner
chose (:meth:`fuzzynav.learn.fql.FuzzyQLearner.greedy_indices`). :func:`rule_table` builds it from
the chosen candidate indices; :func:`fuzzynav.learn.fql.extract_system` reads them from learners.
An output's conclusions are named in one of three ways:

- a name: a variable of singletons ``c0, c1, …``, one per distinct candidate value, in increasing
  order, is built;
- a :class:`~fuzzynav.fuzzy.Variable` whose singletons include every chosen value (e.g. the
  thesis' steering variable, for readable labels): each rule concludes the first singleton of its
  chosen value;
- :class:`Interpretations`: each rule's choice among several interpretations of its own label
  (the optimised wall follower, §VI.5.3.2): a variable of the chosen ones only.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from fuzzynav.errors import InputError
from fuzzynav.fuzzy import FuzzySystem, Rule, Singleton, Variable


@dataclass(frozen=True)
class Interpretations:
    """Output ``name`` on ``universe`` whose rule r, choosing candidate j, concludes a singleton
    labelled ``label(r, j)`` (one term per distinct label, in rule order)."""

    name: str
    universe: tuple
    label: Callable[[int, int], str]


def _named(output, values: np.ndarray, chosen: np.ndarray) -> tuple[Variable, list[str]]:
    """The variable of one output and the label each rule concludes (module docstring)."""
    column = values[np.arange(len(chosen)), chosen]
    if isinstance(output, Interpretations):
        terms, labels = {}, []
        for r, j in enumerate(chosen):
            labels.append(output.label(r, int(j)))
            terms[labels[-1]] = Singleton(float(values[r, j]))
        return Variable(output.name, output.universe, terms), labels
    if isinstance(output, Variable):
        singles = {label: mf.value for label, mf in output.terms.items() if isinstance(mf, Singleton)}
        labels = []
        for value in column:
            match = [label for label, v in singles.items() if np.isclose(v, value, rtol=0, atol=1e-9)]
            if not match:
                raise InputError(f"no singleton of value {value!r}", field=f"outputs.{output.name}")
            labels.append(match[0])
        return output, labels
    distinct = np.unique(values)
    lo, hi = float(distinct[0]), float(distinct[-1])
    variable = Variable(str(output), (lo, hi) if hi > lo else (lo - 1.0, hi + 1.0),
                        {f"c{k}": Singleton(float(v)) for k, v in enumerate(distinct)})
    return variable, [f"c{int(np.argmin(np.abs(distinct - value)))}" for value in column]


def rule_table(premise, outputs, *, rules: int | None = None, defuzzifier: str = "weighted_sum", name: str,
               description: str) -> FuzzySystem:
    """The TS0 system of ``premise``'s rules (a :class:`~fuzzynav.fuzzy.FuzzySystem`, or a learning
    premise holding one as ``system``; its inputs, premises, weights and T-norm are kept), the
    first ``rules`` of them (default all), each concluding its chosen candidate of every output.

    ``outputs``: ``(naming, values (R, K), chosen (R,))`` per output — how its conclusions are
    named (module docstring), the K candidate values of every rule, the index each rule chose.
    """
    system = getattr(premise, "system", premise)
    if not hasattr(system, "inputs") or not hasattr(system, "rules"):
        raise InputError("the premise is not a fuzzy system (no inputs / rules)", field="premise")
    kept = system.rules[:rules]
    variables, labels = [], []
    for naming, values, chosen in outputs:
        variable, concluded = _named(naming, np.asarray(values, dtype=float)[:len(kept)],
                                     np.asarray(chosen, dtype=int)[:len(kept)])
        variables.append(variable)
        labels.append(concluded)
    table = [Rule(rule.premises, tuple((v.name, labels[o][i]) for o, v in enumerate(variables)), rule.weight)
             for i, rule in enumerate(kept)]
    return FuzzySystem(system.inputs, variables, table, method="ts0", tnorm=system.tnorm, defuzzifier=defuzzifier,
                       name=name, description=description)

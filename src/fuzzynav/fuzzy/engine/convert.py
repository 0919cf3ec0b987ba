"""Between :class:`~fuzzynav.fuzzy.system.FuzzySystem` (the thesis' systems, with a fast kernel)
and :class:`~fuzzynav.fuzzy.engine.Engine` (fuzzylite's full semantics).

Every FuzzySystem is an engine: its inputs lock their range (it clamps them), one rule block,
activation General, conjunction AlgebraicProduct / Minimum, TS outputs ``Weighted… TakagiSugeno``
(singletons become ``Constant``), Tsukamoto ``Weighted… Tsukamoto``, Mamdani ``Centroid`` with its
implication and aggregation. The way back (:func:`engine_to_system`) is taken only when it keeps
the meaning (up to the first difference below); otherwise the engine stays an engine.

Two documented differences remain where a FuzzySystem and fuzzylite disagree by design: where
no rule fires, a FuzzySystem's weighted sum is 0 (eq IV.4) and fuzzylite's NaN; and a
FuzzySystem's Tsukamoto inverts rule by rule (the textbook method, §II.4.3.3) where fuzzylite
first sums the rules sharing a term — so a Tsukamoto engine becomes a FuzzySystem only when no
two rules share a conclusion term; and a rule that does not fire adds 0 to a FuzzySystem's
Tsukamoto output, where fuzzylite multiplies 0 by the inverse (∞ for a sigmoid: NaN).
"""

from __future__ import annotations

import math

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.engine import model
from fuzzynav.fuzzy.engine.engine import Engine
from fuzzynav.fuzzy.membership import KINDS, Linear, Singleton
from fuzzynav.fuzzy.rules import Rule
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.terms import Constant
from fuzzynav.fuzzy.variable import Variable

TNORM_NAMES = {"product": "AlgebraicProduct", "min": "Minimum"}
AGGREGATION_NAMES = {"max": "Maximum", "sum": "UnboundedSum"}
DEFUZZIFIER_NAMES = {"weighted_sum": "WeightedSum", "weighted_average": "WeightedAverage", "centroid": "Centroid"}
_SYSTEM_TERMS = tuple(KINDS.values())


def _by_value(table: dict, value: str) -> str | None:
    return next((k for k, v in table.items() if v == value), None)


def system_to_engine(system: FuzzySystem) -> Engine:
    """The engine computing what ``system`` computes (see module docstring)."""
    inputs = [model.InputVariable(v.name, *v.universe, dict(v.terms), lock_range=True) for v in system.inputs]
    if system.method == "mamdani":
        defuzzifier = model.Defuzzifier("Centroid", system.resolution)
        aggregation, implication = AGGREGATION_NAMES[system.aggregation], TNORM_NAMES[system.implication]
    else:
        kind = "Tsukamoto" if system.method == "tsukamoto" else "TakagiSugeno"
        defuzzifier = model.Defuzzifier(DEFUZZIFIER_NAMES[system.defuzzifier], type=kind)
        aggregation, implication = None, None
    outputs = [model.OutputVariable(v.name, *v.universe, {k: Constant(mf.value) if isinstance(mf, Singleton) else mf
                                                     for k, mf in v.terms.items()},
                              aggregation=aggregation, defuzzifier=defuzzifier) for v in system.outputs]
    rules = []
    for rule in system.rules:
        props = [model.Proposition(v, (), t) for v, t in rule.premises]
        antecedent = props[0] if props else model.Proposition(system.inputs[0].name, ("any",), None)
        for prop in props[1:]:
            antecedent = model.Operator("and", antecedent, prop)
        conclusions = tuple(model.Proposition(v, (), t) for v, t in rule.conclusions)
        rules.append(model.EngineRule(antecedent, conclusions, rule.weight))
    block = model.RuleBlock(rules, conjunction=TNORM_NAMES[system.tnorm], implication=implication, name="rules")
    return Engine(inputs, outputs, [block], name=system.name, description=system.description)


def _premises(node) -> list[model.Proposition] | None:
    """The propositions of a pure conjunction without hedges, else None."""
    if isinstance(node, model.Proposition):
        return [node] if not node.hedges else None
    if node.name != "and":
        return None
    left, right = _premises(node.left), _premises(node.right)
    return None if left is None or right is None else left + right


def engine_to_system(engine: Engine) -> FuzzySystem | None:
    """``engine`` as a FuzzySystem when that keeps its meaning exactly, else ``None``."""
    try:
        return _system_of(engine)
    except (InputError, ValueError):
        return None


def system_refusal(engine: Engine) -> InputError | None:
    """Why an engine shaped as a FuzzySystem is not one: the FuzzySystem's error on one of its
    values (e.g. an input range of no width, which fuzzylite evaluates); ``None`` when the engine
    is one, or is shaped otherwise (:func:`engine_to_system`)."""
    try:
        _system_of(engine)
    except InputError as error:
        return error
    except ValueError as error:  # a term's own check (a singleton of -inf)
        return InputError(str(error))
    return None


def _system_of(engine: Engine) -> FuzzySystem | None:
    """:func:`engine_to_system`, raising the FuzzySystem's InputError where a value is refused."""
    if len(engine.blocks) != 1:
        return None
    block = engine.blocks[0]
    outs = engine.outputs
    if (not block.enabled or block.activation != "General" or not engine.inputs
            or any(not v.lock_range or not v.enabled or not v.terms for v in engine.inputs)
            or any(v.lock_range or v.lock_previous or not math.isnan(v.default) or not v.enabled
                   or v.defuzzifier != outs[0].defuzzifier or v.aggregation != outs[0].aggregation for v in outs)):
        return None
    d = outs[0].defuzzifier
    terms = [mf for v in engine.inputs + outs for mf in v.terms.values()]
    if d is None or not all(type(mf) in _SYSTEM_TERMS or type(mf) is Constant for mf in terms):
        return None
    options = {}
    if d.kind == "Centroid":
        implication, aggregation = _by_value(TNORM_NAMES, block.implication), _by_value(AGGREGATION_NAMES,
                                                                                         outs[0].aggregation)
        if implication is None or aggregation is None:
            return None
        options.update(method="mamdani", resolution=d.resolution, implication=implication, aggregation=aggregation)
    elif d.kind in ("WeightedSum", "WeightedAverage") and d.type in ("TakagiSugeno", "Automatic"):
        out_terms = [mf for v in outs for mf in v.terms.values()]
        if not all(isinstance(mf, (Constant, Linear)) for mf in out_terms):
            return None
        options.update(method="ts0" if all(isinstance(mf, Constant) for mf in out_terms) else "ts1",
                       defuzzifier=_by_value(DEFUZZIFIER_NAMES, d.kind))
    elif d.kind in ("WeightedSum", "WeightedAverage") and d.type == "Tsukamoto":
        conclusions = [(c.variable, c.term) for rule in engine.rules for c in rule.conclusions]
        if len(set(conclusions)) != len(conclusions):  # fuzzylite sums rules sharing a term before inverting
            return None
        options.update(method="tsukamoto", defuzzifier=_by_value(DEFUZZIFIER_NAMES, d.kind))
    else:
        return None
    rules = []
    for rule in engine.rules:
        premises = _premises(rule.antecedent)
        if premises is None or any(c.hedges for c in rule.conclusions) or (
                len(premises) > 1 and block.conjunction not in TNORM_NAMES.values()):
            return None
        rules.append(Rule(tuple((p.variable, p.term) for p in premises),
                          tuple((c.variable, c.term) for c in rule.conclusions), rule.weight))
    options["tnorm"] = _by_value(TNORM_NAMES, block.conjunction) or "product"

    def variable(v):
        mfs = {k: Singleton(mf.value) if isinstance(mf, Constant) else mf for k, mf in v.terms.items()}
        return Variable(v.name, v.universe, mfs)
    return FuzzySystem([variable(v) for v in engine.inputs], [variable(v) for v in outs], rules,
                       name=engine.name, description=engine.description, **options)

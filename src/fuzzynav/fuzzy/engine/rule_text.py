"""Rule text of the fuzzylite language: ``if A is very X or (B is Y and C is not Z) then O is W with 0.5``.

``and`` binds tighter than ``or``; parentheses group; hedges (not, very, somewhat, extremely,
seldom, any) come between ``is`` and the term; ``any`` ends a proposition without a term.
Keywords are case-insensitive (``IF … THEN`` as in fuzzynav's own rules); names are not. A
premise may name an output variable of an earlier rule (a chained system). Errors raise
:class:`ValueError` with the offending word; the importers turn them into ``InputError``s naming
file and line.
"""

from __future__ import annotations

from fuzzynav.fuzzy.engine.model import EngineRule, Operator, Proposition
from fuzzynav.fuzzy.formula import decimal
from fuzzynav.fuzzy.operators import HEDGES
from fuzzynav.validation import MAX_DEPTH


def _words(text: str) -> list[str]:
    return text.replace("(", " ( ").replace(")", " ) ").split()


def _proposition(words: list[str], i: int, variables: dict) -> tuple[Proposition, int]:
    if i >= len(words):
        raise ValueError("expected a variable at the end of the rule")
    name = words[i]
    if name not in variables:
        raise ValueError(f"unknown variable {name!r} (known: {', '.join(variables)})")
    if i + 1 >= len(words) or words[i + 1].lower() != "is":
        raise ValueError(f"expected 'is' after {name!r}")
    i += 2
    hedges = []
    while i < len(words) and words[i].lower() in HEDGES and words[i] not in variables[name]:
        hedges.append(words[i].lower())
        i += 1
        if hedges[-1] == "any":
            return Proposition(name, tuple(hedges), None), i
    if i >= len(words) or words[i] not in variables[name]:
        got = words[i] if i < len(words) else "the end of the rule"
        raise ValueError(f"expected a term of {name!r} ({', '.join(variables[name]) or 'it has none'}), got {got!r}")
    return Proposition(name, tuple(hedges), words[i]), i + 1


def _expression(words, i, variables, level=0):
    """Precedence climbing: level 0 = or, 1 = and, 2 = atom."""
    if level == 2:
        if i < len(words) and words[i] == "(":
            node, i = _expression(words, i + 1, variables)
            if i >= len(words) or words[i] != ")":
                raise ValueError("missing ')'")
            return node, i + 1
        return _proposition(words, i, variables)
    op = ("or", "and")[level]
    left, i = _expression(words, i, variables, level + 1)
    while i < len(words) and words[i].lower() == op:
        right, i = _expression(words, i + 1, variables, level + 1)
        left = Operator(op, left, right)
    return left, i


def _nesting(words: list[str]) -> int:
    """The deepest bracket nesting of ``words``."""
    depth = deepest = 0
    for word in words:
        depth += (word == "(") - (word == ")")
        deepest = max(deepest, depth)
    return deepest


def _operator_depth(node) -> int:
    """Depth of a premise tree, found without recursion."""
    deepest, stack = 0, [(node, 1)]
    while stack:
        node, depth = stack.pop()
        deepest = max(deepest, depth)
        if isinstance(node, Operator):
            stack.extend(((node.left, depth + 1), (node.right, depth + 1)))
    return deepest


def parse_engine_rule(text: str, inputs: dict[str, list[str]], outputs: dict[str, list[str]]) -> EngineRule:
    """Parse one rule; ``inputs`` / ``outputs`` map variable names to their term labels. A premise
    nests at most :data:`~fuzzynav.validation.MAX_DEPTH` levels (brackets, or a chain of and / or)."""
    words = _words(text)
    if _nesting(words) > MAX_DEPTH:
        raise ValueError(f"brackets nested deeper than {MAX_DEPTH} levels")
    lowered = [w.lower() for w in words]
    if not words or lowered[0] != "if" or "then" not in lowered:
        raise ValueError("a rule reads 'if ... then ...'")
    then = lowered.index("then")
    weight = 1.0
    tail = words[then + 1:]
    if len(tail) >= 2 and tail[-2].lower() == "with":
        try:
            weight = decimal(tail[-1])  # ('0_1' was read as 1)
        except ValueError:
            raise ValueError(f"rule weight {tail[-1]!r} is not a number") from None
        tail = tail[:-2]
    antecedent, end = _expression(words[1:then], 0, {**inputs, **outputs})
    if _operator_depth(antecedent) > MAX_DEPTH:
        raise ValueError(f"a premise nested deeper than {MAX_DEPTH} levels (a chain of more than {MAX_DEPTH} "
                         "and / or)")
    if end != then - 1:
        raise ValueError(f"unexpected {words[1 + end]!r} in the premise")
    conclusions, i = [], 0
    while i < len(tail):
        prop, i = _proposition(tail, i, outputs)
        if prop.term is None:
            raise ValueError("a conclusion needs a term")
        conclusions.append(prop)
        if i < len(tail):
            if tail[i].lower() != "and":
                raise ValueError(f"expected 'and' between conclusions, got {tail[i]!r}")
            i += 1
            if i == len(tail):
                raise ValueError("dangling 'and' in the conclusion")
    if not conclusions:
        raise ValueError("a rule needs a conclusion")
    return EngineRule(antecedent, tuple(conclusions), weight)

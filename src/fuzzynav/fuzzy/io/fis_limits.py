"""What a MATLAB ``.fis`` file cannot hold, refused before one is written (:func:`fuzzynav.fuzzy.io.fis.to_fis`).

A ``.fis`` file has one rule block that fires every rule on every variable, and one defuzzifier
and aggregation for all its outputs. A fuzzylite engine that needs more — several blocks, a
disabled block or variable (``enabled: false``), an activation that fires only some rules
(fuzzylite's Highest, Lowest, Threshold, …), per-output settings — would answer otherwise once
written without it, so it is refused, naming what it uses. So is a negated conclusion of a
Mamdani output (``then v is not hi``, code ``-2``), which the two read otherwise: MATLAB implies with
1 − μ of the term (``fisFinalOutputMf`` of its ``fis.c``), fuzzylite with the term at 1 − the rule's
degree (its hedges act on the degree); the reader refuses it under MATLAB's semantics too. So is a
name the reader would read otherwise: a variable's or a term's of other characters than letters,
digits and ``_``, a system's holding ``%`` or ``#`` (a comment begins there).
"""

from __future__ import annotations

import re

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.fis_terms import number

NEGATED_CONCLUSION = ("MATLAB reads a negated conclusion of a Mamdani output as 1 − μ of the term, fuzzylite as "
                      "the term at 1 − the rule's degree, and the two answer otherwise")


def negated_conclusion(rule, outputs) -> str | None:
    """The first conclusion of ``rule`` that is negated on an output of ``outputs`` defuzzified by
    integration (Mamdani), where MATLAB and fuzzylite disagree (module docstring); else None."""
    integral = {v.name for v in outputs if v.defuzzifier is not None and v.defuzzifier.integral}
    return next((c.text() for c in rule.conclusions if c.hedges[:1] == ("not",) and c.variable in integral), None)


def refuse_what_fis_lacks(engine) -> None:
    """Raise :class:`InputError` (its field the variable, ``rules``, ``activation`` or ``outputs``)
    when ``engine`` (a :class:`~fuzzynav.fuzzy.engine.Engine`) uses what a ``.fis`` file cannot hold."""
    if len(engine.blocks) != 1:
        raise InputError(".fis holds one rule block", field="rules")
    block, outs = engine.blocks[0], engine.outputs
    if not block.enabled:
        raise InputError("the rule block is disabled (enabled: false), which a .fis file cannot hold: write it as "
                         "fll", field="rules")
    if block.activation != "General":
        activation = " ".join([block.activation, *(number(p) if isinstance(p, float) else str(p)
                                                    for p in block.activation_params)])
        raise InputError(f"the rule block's activation is {activation}; a .fis file applies every rule that fires "
                         "(activation General): write it as fll", field="activation")
    off = [v.name for v in engine.inputs + outs if not v.enabled]
    if off:
        raise InputError(f"{', '.join(off)} {'is' if len(off) == 1 else 'are'} disabled (enabled: false), which a "
                         ".fis file cannot hold: write it as fll", field=off[0])
    if any(v.defuzzifier != outs[0].defuzzifier or v.aggregation != outs[0].aggregation for v in outs):
        raise InputError(".fis gives every output the same defuzzifier and aggregation", field="outputs")
    negated = next((text for text in (negated_conclusion(rule, outs) for rule in block.rules) if text), None)
    if negated:
        raise InputError(f"{NEGATED_CONCLUSION} ({negated!r}): write it as fll", field="rules")
    lost = [(f"name {engine.name!r}", "name")] if re.search(r"[%#]", engine.name) else []  # a comment from there
    for v in engine.inputs + outs:  # the reader keeps a name's letters, digits and _ only
        lost += [(f"variable name {v.name!r}", v.name)] if re.search(r"\W", v.name) else []
        lost += [(f"term name {label!r}", f"{v.name}.{label}") for label in v.terms if re.search(r"\W", label)]
    if lost:
        raise InputError(f"the {lost[0][0]} would read back otherwise from a .fis file (its reader keeps a name's "
                         "letters, digits and _, and % or # begins a comment): write it as fll", field=lost[0][1])

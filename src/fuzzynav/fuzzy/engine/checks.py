"""The values of an engine that every file format must give sensibly, checked once for all formats.

An engine read from ``.fll``, ``.fis``, JSON or YAML (or built in Python) must have, else an
:class:`~fuzzynav.errors.InputError` naming the variable, term or rule block:

- finite ranges, ``minimum <= maximum``, and an output defuzzified over its range (centroid,
  bisector, maxima) of positive width (a ``Range=[4 4]`` output has no point to sample);
- rule weights finite in [0, 1] (fuzzylite's and MATLAB's range: a weight of −2 would turn a
  rule's conclusion round);
- term heights finite in [0, 1], a ``Discrete`` term's points finite with x non-decreasing, at
  most ``MAX_UNIVERSE_WIDTH`` apart (as a range: NumPy's interpolation overflows beyond);
- activation parameters as fuzzylite reads them: ``First``/``Last``/``Highest``/``Lowest`` a
  count of at least 1, a threshold finite in [0, 1], a ``Threshold`` comparator one of
  ``< <= == != >= >``;
- no ``Function`` term of an output reading that output itself (its value is what is being
  computed), nor any term's reading a name that is not a variable of the system, nor a constant
  one that is infinite (``1/0``): both failed at the first evaluation, without the file's name.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.formula import Function
from fuzzynav.fuzzy.operators import COMPARATORS
from fuzzynav.fuzzy.terms import Discrete, Scaled
from fuzzynav.validation import MAX_UNIVERSE_WIDTH


def check_values(inputs, outputs, blocks) -> None:
    """Refuse the values of the module docstring (InputError naming the field)."""
    names = {var.name for var in [*inputs, *outputs]}
    for var in [*inputs, *outputs]:
        if not (math.isfinite(var.minimum) and math.isfinite(var.maximum)
                and var.maximum - var.minimum <= MAX_UNIVERSE_WIDTH):  # (samples across it stay finite)
            raise InputError(f"range [{var.minimum}, {var.maximum}] must be finite, at most "
                             f"{MAX_UNIVERSE_WIDTH:g} wide", field=f"{var.name}.range")
        for label, term in var.terms.items():
            _check_term(term, f"{var.name}.{label}")
            formula = term.term if isinstance(term, Scaled) else term
            if isinstance(formula, Function):
                _check_function(formula, names, f"{var.name}.{label}")
    for var in outputs:
        integral = var.defuzzifier is not None and var.defuzzifier.integral
        if integral and not var.minimum < var.maximum:
            raise InputError(f"range [{var.minimum}, {var.maximum}] has no width: an output defuzzified over its "
                             "range needs minimum < maximum", field=f"{var.name}.range")
        for label, term in var.terms.items():
            if isinstance(term, Function) and var.name in term.variables:
                raise InputError(f"a Function term of {var.name} reads {var.name} itself", field=f"{var.name}.{label}")
    for b, block in enumerate(blocks):
        where = f"RuleBlock {block.name or b + 1}"
        _check_activation(block.activation, tuple(block.activation_params), where)
        for rule in block.rules:
            if not (isinstance(rule.weight, (int, float)) and 0.0 <= rule.weight <= 1.0):
                raise InputError(f"rule weight must be a number in [0, 1], got {rule.weight!r}",
                                 field=f"{where}: {rule.text()}")


def _check_function(formula: Function, names: set, field: str) -> None:
    """Every name ``formula`` reads is one of the system's variables (``names``); a constant one
    (it reads nothing) is finite."""
    unknown = formula.variables - names
    if unknown:
        raise InputError(f"Function {formula.formula!r} reads {', '.join(sorted(unknown))}, not a variable of this "
                         f"system ({', '.join(sorted(names))}; x is the term's own input)", field=field)
    if not formula.reads:  # a constant: infinite now or never
        try:
            formula(0.0)
        except InputError as error:
            raise InputError(f"Function {formula.formula!r} {error.problem}", field=field) from None


def _check_term(term, field: str) -> None:
    if isinstance(term, Scaled):
        if not 0.0 <= term.height <= 1.0:
            raise InputError(f"height must be a number in [0, 1], got {term.height!r}", field=field)
        term = term.term
    if isinstance(term, Discrete):
        if not (np.isfinite(term.x).all() and np.isfinite(term.y).all()):
            raise InputError("discrete points must be finite", field=field)
        if term.x.size and float(term.x.max()) - float(term.x.min()) > MAX_UNIVERSE_WIDTH:  # (interpolation overflows)
            raise InputError(f"discrete points must lie at most {MAX_UNIVERSE_WIDTH:g} apart, got x from "
                             f"{term.x.min():g} to {term.x.max():g}", field=field)
        if (np.diff(term.x) < 0).any():
            raise InputError(f"discrete points must be given by increasing x, got x = {term.x.tolist()}", field=field)


def _check_activation(kind: str, params: tuple, where: str) -> None:
    field = f"{where}.activation"
    if kind in ("First", "Last", "Highest", "Lowest") and params:
        if not (isinstance(params[0], (int, np.integer)) and params[0] >= 1):
            raise InputError(f"{kind} takes a number of rules >= 1, got {params[0]!r}", field=field)
    threshold = params[1] if kind in ("First", "Last", "Threshold") and len(params) > 1 else None
    if threshold is not None and not (isinstance(threshold, (int, float)) and 0.0 <= threshold <= 1.0):
        raise InputError(f"{kind} threshold must be a number in [0, 1], got {threshold!r}", field=field)
    if kind == "Threshold" and params and params[0] not in COMPARATORS:
        raise InputError(f"Threshold comparator must be one of {' '.join(COMPARATORS)}, got {params[0]!r}", field=field)

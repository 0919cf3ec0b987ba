"""A fuzzy system as a plain document (dict of lists / strings / numbers) — the JSON and YAML schema.

```yaml
format: fuzzynav-fis
version: 1
name: goal-seeking
description: ...
method: ts0               # ts0 | ts1 | tsukamoto | mamdani
tnorm: product            # product | min
defuzzifier: weighted_sum # weighted_sum | weighted_average (TS, Tsukamoto) | centroid (Mamdani)
implication: min          # Mamdani only: min | product
aggregation: max          # Mamdani only: max | sum
resolution: 200           # Mamdani centroid samples
inputs:
  - name: drg
    universe: [0.0, 28.284271247461902]
    terms:
      Z: {kind: triangle, params: [-inf, 0.1, 3.5]}
outputs: [...]
rules:                    # either text rules ...
  - IF drg IS Z AND theta IS NG THEN alpha IS PM AND v IS Z
# ... or a grid printed as in the thesis (row/column labels default to the term order):
# rules: {grid: {rows: theta, columns: drg, outputs: [alpha, v], cells: ["PM/Z PG/F ...", ...]}}
```

Numbers are written exactly (shortest round-trip repr); infinite parameters as the strings
``"inf"`` / ``"-inf"`` so that the JSON is standard. Every problem raises
:class:`~fuzzynav.errors.InputError` naming the source file and the field.
"""

from __future__ import annotations

import math

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.membership import make
from fuzzynav.fuzzy.rules import parse_rule, rules_from_grid
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.variable import Variable
from fuzzynav.storage import matches, supported_version

FORMAT = "fuzzynav-fis"
VERSION = 1
_OPTIONS = ("method", "tnorm", "defuzzifier", "implication", "aggregation", "resolution")


def _number_out(value: float):
    return value if math.isfinite(value) else ("inf" if value > 0 else "-inf")


def _number_in(value, source, field) -> float:
    if isinstance(value, bool):
        raise InputError(f"expected a number, got {value!r}", source=source, field=field)
    if isinstance(value, float):
        return value
    if isinstance(value, int):  # a 400-digit integer is refused, not an OverflowError
        return validation.number(value, source, field)
    if isinstance(value, str) and value.strip().lower() in ("inf", "+inf", "-inf", ".inf", "-.inf"):
        return -math.inf if value.strip().startswith("-") else math.inf
    raise InputError(f"expected a number, got {value!r}", source=source, field=field)


def to_document(system: FuzzySystem) -> dict:
    """The document of ``system`` (see module docstring); rules as text lines."""
    def variable(v: Variable) -> dict:
        return {
            "name": v.name,
            "universe": [v.universe[0], v.universe[1]],
            "terms": {label: {"kind": mf.kind, "params": [_number_out(p) for p in mf.params()]}
                      for label, mf in v.terms.items()},
        }
    doc = {"format": FORMAT, "version": VERSION, "name": system.name, "description": system.description}
    doc.update({key: getattr(system, key) for key in _OPTIONS})
    doc["inputs"] = [variable(v) for v in system.inputs]
    doc["outputs"] = [variable(v) for v in system.outputs]
    doc["rules"] = [rule.text() for rule in system.rules]
    return doc


TOP_KEYS = ("format", "version", "name", "description", *_OPTIONS, "inputs", "outputs", "rules")
_VARIABLE_KEYS = ("name", "universe", "terms")
_TERM_KEYS = ("kind", "params")
_GRID_KEYS = ("rows", "columns", "outputs", "cells", "row_labels", "column_labels", "columns_first")


def _check_keys(mapping, known, source, field, strict: bool = True) -> None:
    """Reject the keys of ``mapping`` outside ``known``, suggesting the closest one.

    ``strict=False`` (the top level of a model file, which has a ``kind``) rejects only near misses
    of a known key (``tnrom``, ``methd``): its other top-level keys belong to the model (its training
    record, its speed…), which its loader checks; a plain system file is strict (``defuzz`` was
    ignored, the default defuzzifier run).
    """
    if isinstance(mapping, dict):  # (a mapping's type is checked where it is read)
        validation.known_keys(mapping, known, source, field or None, near_misses_only=not strict)


def _require(mapping, key, kind, source, field):
    if not isinstance(mapping, dict) or key not in mapping:
        raise InputError(f"missing field {key!r}", source=source, field=field)
    value = mapping[key]
    if not isinstance(value, kind):
        raise InputError(f"{key!r} must be a {kind.__name__ if isinstance(kind, type) else 'list'}, "
                         f"got {type(value).__name__}", source=source, field=f"{field}.{key}" if field else key)
    return value


def _variable(doc, source, field) -> Variable:
    _check_keys(doc, _VARIABLE_KEYS, source, field)
    name = _require(doc, "name", str, source, field)
    universe = _require(doc, "universe", list, source, field)
    if len(universe) != 2:
        raise InputError("universe must be [lo, hi]", source=source, field=f"{field}.universe")
    lo, hi = (_number_in(u, source, f"{field}.universe") for u in universe)
    terms = {}
    for label, term in _require(doc, "terms", dict, source, field).items():
        where = f"{field}.terms.{label}"
        _check_keys(term, _TERM_KEYS, source, where)
        kind = _require(term, "kind", str, source, where)
        params = [_number_in(p, source, f"{where}.params") for p in _require(term, "params", list, source, where)]
        try:
            terms[str(label)] = make(kind, params)
        except (TypeError, ValueError) as error:
            raise InputError(str(error), source=source, field=where) from None
    try:
        return Variable(name, (lo, hi), terms)
    except InputError as error:
        raise InputError(error.problem, source=source, field=f"{field} ({error.field})") from None


def _rules(doc, inputs, source) -> list:
    rules = doc.get("rules")
    if isinstance(rules, list):
        out = []
        for i, text in enumerate(rules):
            if not isinstance(text, str):
                raise InputError(f"a rule is a text line, got {text!r}", source=source, field=f"rules[{i}]")
            try:
                out.append(parse_rule(text))
            except InputError as error:
                raise InputError(error.problem, source=source, field=f"rules[{i}]") from None
        return out
    if isinstance(rules, dict) and isinstance(rules.get("grid"), dict):
        grid = rules["grid"]
        _check_keys(rules, ("grid",), source, "rules")
        _check_keys(grid, _GRID_KEYS, source, "rules.grid")
        by_name = {v.name: v for v in inputs}
        names = {}
        for key in ("rows", "columns"):
            name = _require(grid, key, str, source, "rules.grid")
            if name not in by_name:
                raise InputError(f"unknown input variable {name!r}", source=source, field=f"rules.grid.{key}")
            names[key] = name
        outputs = _require(grid, "outputs", list, source, "rules.grid")
        cells = _require(grid, "cells", list, source, "rules.grid")
        row_labels = grid.get("row_labels", by_name[names["rows"]].labels)
        column_labels = grid.get("column_labels", by_name[names["columns"]].labels)
        for key, value in (("outputs", outputs), ("row_labels", row_labels), ("column_labels", column_labels),
                           ("cells", cells)):
            _grid_strings(value, key == "cells", source, f"rules.grid.{key}")
        try:
            return rules_from_grid(names["rows"], names["columns"], row_labels, column_labels, cells, outputs,
                                   columns_first=bool(grid.get("columns_first", True)), source=source)
        except InputError as error:
            raise InputError(error.problem, source=source, field=f"rules.grid: {error.field}") from None
    raise InputError("rules must be a list of text rules or {grid: {...}}", source=source, field="rules")


def _grid_strings(value, rows: bool, source, field) -> None:
    """A grid list of labels (strings); with ``rows``, each item a string or a list of strings."""
    validation.sequence(value, source, field)
    for i, item in enumerate(value):
        if rows and isinstance(item, list):
            for j, cell in enumerate(item):
                validation.text(cell, source, f"{field}[{i}][{j}]")
        else:
            validation.text(item, source, f"{field}[{i}]")


def from_document(doc, source: str | None = None) -> FuzzySystem:
    """Build the system a document describes; errors name ``source`` and the field."""
    if not isinstance(doc, dict):
        raise InputError("a fuzzy system file holds a mapping", source=source)
    if not matches(doc.get("format", FORMAT), FORMAT):
        raise InputError(f"format must be {FORMAT!r}, got {doc.get('format')!r}", source=source, field="format")
    supported_version(doc, VERSION, source)
    _check_keys(doc, TOP_KEYS, source, "", strict="kind" not in doc)  # a model's own keys: its loader's
    if "inputs" not in doc and doc.get("kind") == "fuzzynav-checkpoint":  # learn.checkpoint.KIND
        raise InputError("a training checkpoint, not a fuzzy system (`fuzzynav train ... --resume` reads it)",
                         source=source, field="kind")
    if "inputs" not in doc and isinstance(doc.get("kind"), str):  # the command that runs it, whichever read it
        raise InputError(f"a {doc['kind']!r} model file, not a fuzzy system (`fuzzynav run --model` runs it)",
                         source=source, field="kind")
    inputs = [_variable(v, source, f"inputs[{i}]") for i, v in enumerate(_require(doc, "inputs", list, source, ""))]
    outputs = [_variable(v, source, f"outputs[{i}]") for i, v in enumerate(_require(doc, "outputs", list, source, ""))]
    options = {key: doc[key] for key in _OPTIONS if doc.get(key) is not None}
    try:
        return FuzzySystem(inputs, outputs, _rules(doc, inputs, source), name=str(doc.get("name") or ""),
                           description=str(doc.get("description") or ""), **options)
    except InputError as error:
        if error.source:
            raise
        raise InputError(error.problem, source=source, field=error.field) from None

"""MATLAB Fuzzy Logic Toolbox ``.fis`` files: import and export.

Sections ``[System]``, ``[InputN]``, ``[OutputN]``, ``[Rules]``. Membership functions: trimf,
trapmf, gaussmf, gauss2mf, gbellmf, sigmf, dsigmf, psigmf, zmf, smf, pimf, constant, linear, and
the names fuzzylite adds for its other terms (rampmf, concavemf, cosinemf, spikemf, rectmf,
binarymf, discretemf, function; an extra last parameter is a height). Methods: and/or/imp/agg
``min max prod probor sum`` (and fuzzylite's other norm names), defuzzification ``centroid
bisector mom lom som wtaver wtsum``. A rule line ``1 0 -2, 3 (0.5) : 1`` gives one term index per
input then per output (0: the variable is left out; negative: NOT; a decimal part is a hedge as
fuzzylite writes it: .01 seldom, .05 somewhat, .2 very, .3 extremely, .4 very very, .99 any), the
weight in parentheses and the connective (1 AND, 2 OR).

**Semantics** (``semantics="matlab"``, the default) — where MATLAB's ``evalfis`` differs from
fuzzylite's reading of the same file (``semantics="fuzzylite"``, what fuzzylite's FisImporter
builds, used to compare with fuzzylite):

- a Mamdani output is sampled at 101 points from end to end of its range (fuzzylite: the midpoints
  of ``resolution`` cells, 1000 unless the file says), its bisector the first sample reaching half
  the area, som / lom the smallest / largest in magnitude (fuzzylite: closest to half; in value);
- an output on which no rule fires takes the middle of its range, fuzzylite gives NaN (its
  ``Default`` when the file states one, ``nan`` included);
- a Sugeno output averages rule by rule, so a Sugeno ``AggMethod`` (ignored by MATLAB) is ignored;
  fuzzylite first aggregates the rules sharing an output term with it;
- a negated conclusion of a Mamdani output (``-2``) implies with 1 − μ of the term, fuzzylite's with
  the term at 1 − the rule's degree: refused, as MATLAB's is not computed here (:mod:`.fis_limits`).

Neither clips inputs to their range (MATLAB warns and evaluates the value as it is), unless the
variable says ``LockRange=1``. Beside MATLAB's keys the writer puts fuzzylite's ``LockRange``,
``LockPrevious`` and ``Default`` of an output where they are set, and — where fuzzylite's reader
would refuse a key (an input's ``LockRange``, a ``Default`` of NaN) — writes it in a comment,
``% fuzzynav: LockRange=1``, which MATLAB and fuzzylite skip and this reader takes as the key; so
are the samples of an integral defuzzifier other than MATLAB's (``% fuzzynav: Resolution=1000``,
``% fuzzynav: Grid=midpoints`` in ``[System]``). So a system written as ``.fis`` reads back
answering as before everywhere (outside the ranges too), and the file stays one the other two
read. Errors raise :class:`InputError` naming the file, the line and the field.
"""

from __future__ import annotations

import math
import re

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.engine import Engine, model
from fuzzynav.fuzzy.engine.convert import engine_to_system
from fuzzynav.fuzzy.fis_terms import number, term_from_fis, term_to_fis
from fuzzynav.fuzzy.formula import Function, decimal
from fuzzynav.fuzzy.io.fis_limits import NEGATED_CONCLUSION, negated_conclusion, refuse_what_fis_lacks
from fuzzynav.fuzzy.system import FuzzySystem

MATLAB_POINTS = 101  # evalfis' default number of output samples
ANNOTATION = re.compile(r"\s*%\s*fuzzynav:\s*(\S.*)")  # "% fuzzynav: Key=value": a key in a comment
_TNORMS = {"min": "Minimum", "prod": "AlgebraicProduct", "bounded_difference": "BoundedDifference",
           "drastic_product": "DrasticProduct", "einstein_product": "EinsteinProduct",
           "hamacher_product": "HamacherProduct", "nilpotent_minimum": "NilpotentMinimum"}
_SNORMS = {"max": "Maximum", "probor": "AlgebraicSum", "bounded_sum": "BoundedSum", "drastic_sum": "DrasticSum",
           "einstein_sum": "EinsteinSum", "hamacher_sum": "HamacherSum", "nilpotent_maximum": "NilpotentMaximum",
           "normalized_sum": "NormalizedSum", "sum": "UnboundedSum"}
_TYPES = ("mamdani", "sugeno", "tsukamoto")
_SUGENO_DEFUZZ = ("wtaver", "wtsum")  # MATLAB: a Sugeno system's output is a weighted average or sum
_COUNTS = ("NumInputs", "NumOutputs", "NumRules")
_DEFUZZ = {"centroid": "Centroid", "bisector": "Bisector", "mom": "MeanOfMaximum", "lom": "LargestOfMaximum",
           "som": "SmallestOfMaximum", "wtaver": "WeightedAverage", "wtsum": "WeightedSum"}
_HEDGE_CODES = {0.01: ("seldom",), 0.05: ("somewhat",), 0.2: ("very",), 0.3: ("extremely",), 0.4: ("very", "very"),
                0.99: ("any",)}


def _inverse(table: dict, value, what: str) -> str:
    for k, v in table.items():
        if v == value:
            return k
    raise InputError(f"{what} {value!r} has no .fis name", field=what)


class _Lines:
    """Sections of a .fis file: ``{"name": "[Input1]", "line": n, "items": [(key, value, line)]}``."""

    def __init__(self, text: str, source):
        self.source = source
        self.sections: list[dict] = []
        for line_number, raw in enumerate(text.splitlines(), start=1):  # names are printed: no ESC, NUL...
            validation.text(raw.replace("\t", " "), source, f"line {line_number}", max_length=len(raw), one_line=True)
            noted = ANNOTATION.fullmatch(raw)  # a key of this package's, in a comment other readers skip
            line = noted.group(1).strip() if noted else raw.split("%", 1)[0].split("#", 1)[0].strip()
            if not line:
                continue
            if line.startswith("["):
                self.sections.append({"name": line, "line": line_number, "items": []})
            elif not self.sections:
                raise self.error("text before the first [Section]", line_number)
            elif self.sections[-1]["name"] == "[Rules]":
                self.sections[-1]["items"].append(("rule", line, line_number))
            else:
                key, sep, value = line.partition("=")
                if not sep:
                    raise self.error(f"expected 'Key=value', got {line!r}", line_number)
                self.sections[-1]["items"].append((key.strip(), value.strip(), line_number))

    def error(self, message: str, line, field: str | None = None) -> InputError:
        where = f"line {line}" if line else None
        return InputError(message, source=self.source, field=f"{where} ({field})" if field and where else where or field)


def _text(value: str) -> str:
    return value.strip().strip("'\"")


def _range(value: str, lines: _Lines, line) -> tuple[float, float]:
    """``[lo hi]``; each end a number or a constant expression MATLAB accepts (``-pi/4``)."""
    parts = value.strip().strip("[]").replace(",", " ").split()
    try:
        lo, hi = (float(Function(p)(0.0)) for p in parts)
    except ValueError:
        raise lines.error(f"Range must be [lo hi], got {value!r}", line, "Range") from None
    return lo, hi


def _in_order(name: str, kind: str, before: list[str], lines: _Lines, line) -> None:
    """Refuse ``name`` (``MF2``, ``Input1``) numbered below the one before it: MATLAB and fuzzylite
    take sections and terms by their place in the file, and rules refer to them by that place, so
    a file numbered otherwise (``MF2`` written before ``MF1``) would be read against its own numbers.
    A number repeated (MATLAB's ``slcp1.fis`` reads MF1, MF2, MF2) is read by its place, as they do."""
    number, last = name[len(kind):], before[-1][len(kind):] if before else ""
    if number.isdigit() and last.isdigit() and int(number) < int(last):
        raise lines.error(f"{name} comes after {before[-1]}: rules refer to {kind} by place in the file, so "
                          f"number them in file order", line, name if kind == "MF" else None)


def _variable(section: dict, lines: _Lines, output: bool, matlab: bool):
    """The variable and its term labels in file order (rules refer to terms by position).

    MATLAB tells terms apart by position, so a repeated name gets a suffix (``_2``, ``_3``, …);
    fuzzylite resolves the name, so its reading keeps the last term of that name."""
    cls = model.OutputVariable if output else model.InputVariable
    var = cls("", -math.inf, math.inf)
    order: list[str] = []
    previous: list[str] = []  # the MF keys read so far
    declared = None  # (NumMFs as written, its line)
    for key, value, line in section["items"]:
        if key == "Name":
            var.name = re.sub(r"\W", "", _text(value)) or "_"
        elif key == "Range":
            var.minimum, var.maximum = _range(value, lines, line)
        elif key.startswith("MF"):
            _in_order(key, "MF", previous, lines, line)
            previous.append(key)
            label, mf = term_from_fis(value, lines.source, line)
            if matlab and label in var.terms:
                label = next(f"{label}_{k}" for k in range(2, len(var.terms) + 3) if f"{label}_{k}" not in var.terms)
            var.terms[label] = mf
            order.append(label)
        elif key in ("Enabled", "Default", "LockPrevious", "LockRange") and (output or key in ("Enabled", "LockRange")):
            try:
                number = decimal(value)
            except ValueError:
                raise lines.error(f"{key} must be a number, got {value!r}", line, key) from None
            if key == "Default":
                var.default = number
            else:
                attribute = {"Enabled": "enabled", "LockPrevious": "lock_previous", "LockRange": "lock_range"}[key]
                setattr(var, attribute, number == 1.0)
        elif key == "NumMFs":
            declared = (value.strip(), line)
        else:
            raise lines.error(f"unknown key {key!r} in {section['name']}", line, key)
    if not var.name:
        raise lines.error(f"{section['name']} has no Name", section["line"], "Name")
    if declared is not None and declared[0] != str(len(order)):  # as the [System] counts (_check_counts)
        raise lines.error(f"says {declared[0]}, {section['name']} holds {len(order)} MFs", declared[1], "NumMFs")
    return var, order


def _proposition(code: float, var, order: list, lines: _Lines, line) -> model.Proposition | None:
    if code == 0:
        return None
    index = int(math.floor(abs(code))) - 1
    fraction = round(abs(code) - math.floor(abs(code)), 2)
    hedges = ("not",) if code < 0 else ()
    if fraction:
        if fraction not in _HEDGE_CODES:
            raise lines.error(f"no hedge for the code {code!r}", line, var.name)
        hedges += _HEDGE_CODES[fraction]
    if hedges[-1:] == ("any",):
        return model.Proposition(var.name, hedges, None)
    if not 0 <= index < len(order):
        raise lines.error(f"term {index + 1} of {var.name} does not exist (it has {len(order)})", line, var.name)
    return model.Proposition(var.name, hedges, order[index])


def _rule(text: str, inputs, outputs, lines: _Lines, line) -> tuple[model.EngineRule, int]:
    match = re.fullmatch(r"([-\d.\s]+),([-\d.\s]+)\(\s*([-\d.eE+]+)\s*\)\s*:\s*(\d)", text, re.ASCII)
    if not match:
        raise lines.error(f"a rule reads 'i1 i2 ..., o1 ... (weight) : 1|2', got {text!r}", line)
    try:
        ins, outs = ([decimal(v) for v in group.split()] for group in match.group(1, 2))
        weight = decimal(match.group(3))
    except ValueError as error:
        raise lines.error(f"rule codes and weight are numbers: {error}", line) from None
    if len(ins) != len(inputs) or len(outs) != len(outputs):
        raise lines.error(f"expected {len(inputs)} input and {len(outputs)} output codes, got {len(ins)} and "
                          f"{len(outs)}", line)
    premises = [p for p in (_proposition(c, *v, lines, line) for c, v in zip(ins, inputs)) if p]
    conclusions = tuple(p for p in (_proposition(c, *v, lines, line) for c, v in zip(outs, outputs)) if p)
    connective = int(match.group(4))
    if connective not in (1, 2):
        raise lines.error(f"the connective is 1 (AND) or 2 (OR), got {connective}", line)
    if not premises or not conclusions:
        raise lines.error("a rule needs at least one premise and one conclusion (a .fis rule cannot read an output)",
                          line)
    antecedent = premises[0]
    for p in premises[1:]:
        antecedent = model.Operator("and" if connective == 1 else "or", antecedent, p)
    return model.EngineRule(antecedent, conclusions, weight), connective


def _system_options(section: dict, lines: _Lines) -> dict:
    options = {}
    for key, value, line in section["items"]:
        value = _text(value)
        table = {"AndMethod": _TNORMS, "ImpMethod": _TNORMS, "OrMethod": _SNORMS, "AggMethod": _SNORMS,
                 "DefuzzMethod": _DEFUZZ}.get(key)
        if table is not None:
            if value and value not in table:
                raise lines.error(f"unknown {key} {value!r} (known: {', '.join(table)})", line, key)
            options[key] = table.get(value)
        elif key == "Type":
            if value.lower() not in _TYPES:
                raise lines.error(f"must be one of {', '.join(_TYPES)}, got {value!r}", line, key)
            options[key], options["Type line"] = value, line
        elif key == "Name":
            options[key] = value
        elif key == "Resolution":  # written in a comment (module docstring): the samples of an integral output
            if not (value.isascii() and value.isdigit() and 1 <= int(value) <= validation.MAX_RESOLUTION):
                raise lines.error(f"must be a whole number of samples in [1, {validation.MAX_RESOLUTION}], got {value!r}", line,
                                  key)
            options[key] = int(value)
        elif key == "Grid":
            if value not in model.GRIDS:
                raise lines.error(f"must be one of {', '.join(model.GRIDS)}, got {value!r}", line, key)
            options[key] = value
        elif key in _COUNTS:
            options[key] = (value, line)
        elif key != "Version":
            raise lines.error(f"unknown key {key!r} in [System]", line, key)
    defuzz = next((v for k, v, _ in section["items"] if k == "DefuzzMethod"), None)
    allowed = _SUGENO_DEFUZZ if options.get("Type", "mamdani").lower() == "sugeno" else None
    if defuzz is not None and allowed is not None and _text(defuzz) not in allowed:
        raise lines.error(f"a sugeno system takes {' or '.join(allowed)}, got {_text(defuzz)!r}",
                          options.get("Type line"), "DefuzzMethod")
    return options


def _check_counts(options: dict, counts: dict, lines: _Lines) -> None:
    """The [System] header's NumInputs, NumOutputs and NumRules, where given, match the sections."""
    for key, found in counts.items():
        if key in options:
            value, line = options[key]
            if value != str(found):
                raise lines.error(f"says {value}, the file holds {found}", line, key)


def from_fis_engine(text: str, source: str | None = None, semantics: str = "matlab") -> Engine:
    """Parse a ``.fis`` file into an :class:`Engine` (``semantics``: see module docstring)."""
    if semantics not in ("matlab", "fuzzylite"):
        raise InputError(f"semantics is 'matlab' or 'fuzzylite', got {semantics!r}", field="semantics")
    lines = _Lines(text, source)
    system = [s for s in lines.sections if s["name"] == "[System]"]
    if len(system) != 1:
        raise lines.error("a .fis file has one [System] section", None)
    options = _system_options(system[0], lines)
    matlab = semantics == "matlab"
    for kind in ("Input", "Output"):
        seen: list[str] = []
        for section in (s for s in lines.sections if s["name"].startswith(f"[{kind}")):
            _in_order(section["name"].strip("[]"), kind, seen, lines, section["line"])
            seen.append(section["name"].strip("[]"))
    in_vars = [_variable(s, lines, False, matlab) for s in lines.sections if s["name"].startswith("[Input")]
    out_vars = [_variable(s, lines, True, matlab) for s in lines.sections if s["name"].startswith("[Output")]
    inputs, outputs = [v for v, _ in in_vars], [v for v, _ in out_vars]
    stated = [any(key == "Default" for key, _, _ in s["items"]) for s in lines.sections if s["name"].startswith("[Output")]
    unknown = [s for s in lines.sections if not re.fullmatch(r"\[(System|Input\d+|Output\d+|Rules)\]", s["name"])]
    if unknown:
        raise lines.error(f"unknown section {unknown[0]['name']}", unknown[0]["line"])
    for var in outputs:  # MATLAB's Linear has n + 1 coefficients; fuzzylite's may omit the constant
        for label, mf in var.terms.items():
            if type(mf).__name__ == "Linear" and len(mf.params()) == len(inputs):
                var.terms[label] = type(mf)(mf.params(), 0.0)
    defuzz = options.get("DefuzzMethod")
    kind = options.get("Type", "mamdani").lower()
    for var, default_stated in zip(outputs, stated):
        if defuzz in ("Centroid", "Bisector", "MeanOfMaximum", "LargestOfMaximum", "SmallestOfMaximum"):
            points = {"resolution": options.get("Resolution", MATLAB_POINTS),
                      "grid": options.get("Grid", "linspace")} if matlab else {}
            if points.get("grid") == "linspace" and points["resolution"] < 2:  # its two ends at least
                raise lines.error("Resolution=1 samples one point: only with Grid=midpoints", None, "Resolution")
            var.defuzzifier = model.Defuzzifier(defuzz, **points)
            var.aggregation = options.get("AggMethod")
        elif defuzz is not None:
            var.defuzzifier = model.Defuzzifier(defuzz, type="Tsukamoto" if kind == "tsukamoto" else "Automatic")
            var.aggregation = None if matlab and kind == "sugeno" else options.get("AggMethod")
        if matlab and math.isnan(var.default) and not default_stated:  # a stated Default=nan is kept
            var.default = 0.5 * (var.minimum + var.maximum)
    rules, connectives = [], set()
    for section in (s for s in lines.sections if s["name"] == "[Rules]"):
        for _, value, line in section["items"]:
            rule, connective = _rule(value, in_vars, out_vars, lines, line)
            if matlab and negated_conclusion(rule, outputs):  # fuzzylite's answer is semantics="fuzzylite"
                raise lines.error(f"{NEGATED_CONCLUSION} ({negated_conclusion(rule, outputs)!r}): MATLAB's is not "
                                  "computed here", line)
            rules.append(rule)
            connectives.add(connective)
    _check_counts(options, {"NumInputs": len(inputs), "NumOutputs": len(outputs), "NumRules": len(rules)}, lines)
    block = model.RuleBlock(rules, conjunction=options.get("AndMethod"), disjunction=options.get("OrMethod"),
                            implication=options.get("ImpMethod"))
    try:
        return Engine(inputs, outputs, [block], name=options.get("Name", ""))
    except InputError as error:
        raise InputError(error.problem, source=source, field=error.field) from None


def from_fis(text: str, source: str | None = None, semantics: str = "matlab") -> FuzzySystem | Engine:
    """Parse a ``.fis`` file: a :class:`FuzzySystem` when it is exactly one, else an :class:`Engine`."""
    engine = from_fis_engine(text, source, semantics)
    return engine_to_system(engine) or engine


# ---------------------------------------------------------------------------------------- export
def _code(prop: model.Proposition, var) -> str:
    hedges = list(prop.hedges)
    negative = hedges[:1] == ["not"]
    hedges = hedges[1:] if negative else hedges
    fraction = next((f for f, h in _HEDGE_CODES.items() if list(h) == hedges), None) if hedges else 0.0
    if fraction is None:
        raise InputError(f"hedges {' '.join(prop.hedges)} have no .fis code", field=prop.text())
    index = 0 if prop.term is None else var.labels.index(prop.term) + 1
    value = index + fraction
    return repr(-value if negative else value) if fraction else str(-index if negative else index)


def _flat(node) -> tuple[list[model.Proposition], str | None]:
    if isinstance(node, model.Proposition):
        return [node], None
    left, op1 = _flat(node.left)
    right, op2 = _flat(node.right)
    ops = {node.name} | ({op1} if op1 else set()) | ({op2} if op2 else set())
    if len(ops) > 1:
        raise InputError("a .fis rule joins its premises by AND or by OR, not both", field="rules")
    return left + right, node.name


def to_fis(system: FuzzySystem | Engine) -> str:
    """``system`` as a MATLAB ``.fis`` file (full precision); InputError if it cannot be one."""
    from fuzzynav.fuzzy.engine.convert import system_to_engine

    engine = system_to_engine(system) if isinstance(system, FuzzySystem) else system
    refuse_what_fis_lacks(engine)
    block, outs = engine.blocks[0], engine.outputs
    d = outs[0].defuzzifier
    integral = d is not None and d.integral
    kind = "mamdani" if integral else ("tsukamoto" if d and d.type == "Tsukamoto" else "sugeno")
    lines = ["[System]", f"Name='{engine.name}'", f"Type='{kind}'", "Version=2.0",
             f"NumInputs={len(engine.inputs)}", f"NumOutputs={len(outs)}", f"NumRules={len(block.rules)}",
             f"AndMethod='{_inverse(_TNORMS, block.conjunction, 'conjunction') if block.conjunction else 'min'}'",
             f"OrMethod='{_inverse(_SNORMS, block.disjunction, 'disjunction') if block.disjunction else 'max'}'",
             f"ImpMethod='{_inverse(_TNORMS, block.implication, 'implication') if block.implication else 'prod'}'",
             f"AggMethod='{_inverse(_SNORMS, outs[0].aggregation, 'aggregation') if outs[0].aggregation else 'sum'}'",
             f"DefuzzMethod='{_inverse(_DEFUZZ, d.kind, 'defuzzifier') if d else 'wtaver'}'"]
    if integral and (d.resolution, d.grid) != (MATLAB_POINTS, "linspace"):  # else read back on MATLAB's 101 points
        lines += [f"% fuzzynav: Resolution={d.resolution}", f"% fuzzynav: Grid={d.grid}"]
    for section, variables in (("Input", engine.inputs), ("Output", outs)):
        for i, v in enumerate(variables, start=1):
            lines += ["", f"[{section}{i}]", f"Name='{v.name}'", f"Range=[{number(v.minimum)} {number(v.maximum)}]",
                      f"NumMFs={len(v.terms)}"]
            lines += [f"MF{k}='{label}':{term_to_fis(mf)}" for k, (label, mf) in enumerate(v.terms.items(), 1)]
            # without these a round trip would answer differently outside the range (no clipping) or
            # where no rule fires: fuzzylite's keys where its reader takes them (outputs), the others
            # as comments that this reader takes back and MATLAB's and fuzzylite's skip
            output = isinstance(v, model.OutputVariable)
            if v.lock_range:
                lines.append("LockRange=1" if output else "% fuzzynav: LockRange=1")
            if output and v.lock_previous:
                lines.append("LockPrevious=1")
            if output:  # nan too: else MATLAB's reading takes the middle of the range
                default = f"Default={number(v.default)}"
                lines.append(default if math.isfinite(v.default) else f"% fuzzynav: {default}")
    lines += ["", "[Rules]"]
    by_name = {v.name: v for v in engine.inputs + outs}
    for rule in block.rules:
        premises, op = _flat(rule.antecedent)
        if len({p.variable for p in premises}) != len(premises) or any(p.variable not in
                                                                         {v.name for v in engine.inputs}
                                                                         for p in premises):
            raise InputError("a .fis rule names each input at most once", field=rule.text())
        codes = {p.variable: _code(p, by_name[p.variable]) for p in premises}
        results = {c.variable: _code(c, by_name[c.variable]) for c in rule.conclusions}
        ins = " ".join(codes.get(v.name, "0") for v in engine.inputs)
        outs_text = " ".join(results.get(v.name, "0") for v in outs)
        lines.append(f"{ins}, {outs_text} ({number(rule.weight)}) : {2 if op == 'or' else 1}")
    return "\n".join(lines) + "\n"

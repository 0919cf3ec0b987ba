"""The fuzzylite language (FLL): import and export of everything fuzzylite 8 writes.

Import reads every term, hedge, norm, activation and defuzzifier fuzzylite names, several rule
blocks, per-output settings and ``lock-range`` as written (fuzzylite's meaning: an input
without it is fuzzified outside its range as it is). A term name repeated within a variable
keeps its last definition, the one fuzzylite's rules resolve to. The result is a
:class:`~fuzzynav.fuzzy.system.FuzzySystem` when the file says exactly what one computes (as the
files fuzzynav writes do: then the fast kernel runs), otherwise an
:class:`~fuzzynav.fuzzy.engine.Engine`. Every problem raises :class:`InputError` naming the file
and line.

Export writes every number in full precision (shortest round-trip repr; fuzzylite's own
exporter rounds to 3 decimals, which shifts the goal-seeking α by ~3e-4 rad). A FuzzySystem is
written as the engine of :func:`~fuzzynav.fuzzy.engine.convert.system_to_engine`; an output
sampled the MATLAB way (a ``.fis`` file's centroid on 101 points from end to end) is written
with its range widened by half a sample step at each end, which gives fuzzylite the same points.
"""

from __future__ import annotations

import math
from dataclasses import replace

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.engine import Defuzzifier, Engine, InputVariable, OutputVariable, RuleBlock, parse_engine_rule
from fuzzynav.fuzzy.engine.convert import engine_to_system, system_to_engine
from fuzzynav.fuzzy.engine.model import INTEGRAL, WEIGHTED, WEIGHTED_TYPES
from fuzzynav.fuzzy.fll_terms import num, term_from_fll, term_to_fll
from fuzzynav.fuzzy.formula import decimal
from fuzzynav.fuzzy.membership import Linear
from fuzzynav.fuzzy.operators import ACTIVATIONS
from fuzzynav.fuzzy.system import FuzzySystem

_SECTION_KEYS = {  # the keys fuzzylite's FllImporter accepts in each section
    "Engine": {"description"},
    "InputVariable": {"description", "enabled", "range", "lock-range", "term"},
    "OutputVariable": {"description", "enabled", "range", "lock-range", "term", "default", "lock-previous",
                       "aggregation", "defuzzifier"},
    "RuleBlock": {"description", "enabled", "conjunction", "disjunction", "implication", "activation", "rule"},
}


def _flag(value: bool) -> str:
    return "true" if value else "false"


def _variable_lines(kind: str, v) -> list[str]:
    lines = [f"{kind}: {v.name}"]
    if v.description:
        lines.append(f"  description: {v.description}")
    lines += [f"  enabled: {_flag(v.enabled)}", f"  range: {num(v.minimum)} {num(v.maximum)}",
              f"  lock-range: {_flag(v.lock_range)}"]
    if isinstance(v, OutputVariable):
        lines += [f"  aggregation: {v.aggregation or 'none'}",
                  f"  defuzzifier: {v.defuzzifier.text() if v.defuzzifier else 'none'}",
                  f"  default: {num(v.default)}", f"  lock-previous: {_flag(v.lock_previous)}"]
    return lines + [f"  term: {label} {term_to_fll(mf)}" for label, mf in v.terms.items()]


def _fuzzylite_grid(v: OutputVariable) -> OutputVariable:
    """A MATLAB-sampled output (``linspace`` grid) as fuzzylite can write it: the same sample points
    are the midpoints of the range widened by half a step at each end."""
    d = v.defuzzifier
    if d is None or d.grid != "linspace":
        return v
    if d.kind == "Bisector" or (d.kind in ("SmallestOfMaximum", "LargestOfMaximum") and v.minimum < 0):
        raise InputError(f"its {d.kind} is MATLAB's (the bisector: the first sample where the running area reaches "
                         "half, fuzzylite's the closest to half; the smallest / largest of maximum: in magnitude, "
                         "fuzzylite's in value), which an .fll file cannot hold", field=v.name)
    half = 0.5 * (v.maximum - v.minimum) / (d.resolution - 1)
    return replace(v, minimum=v.minimum - half, maximum=v.maximum + half, defuzzifier=replace(d, grid="midpoints"))


def _activation_text(block: RuleBlock) -> str:
    return " ".join([block.activation, *(num(p) if isinstance(p, float) else str(p) for p in block.activation_params)])


def to_fll(system: FuzzySystem | Engine) -> str:
    """``system`` in the fuzzylite language, full precision."""
    engine = system_to_engine(system) if isinstance(system, FuzzySystem) else system
    lines = [f"Engine: {engine.name}".rstrip()]
    if engine.description:
        lines.append(f"  description: {engine.description}")
    for v in engine.inputs:
        lines += _variable_lines("InputVariable", v)
    for v in engine.outputs:
        lines += _variable_lines("OutputVariable", _fuzzylite_grid(v))
    for block in engine.blocks:
        lines.append(f"RuleBlock: {block.name}".rstrip())
        if block.description:
            lines.append(f"  description: {block.description}")
        lines += [f"  enabled: {_flag(block.enabled)}", f"  conjunction: {block.conjunction or 'none'}",
                  f"  disjunction: {block.disjunction or 'none'}", f"  implication: {block.implication or 'none'}",
                  f"  activation: {_activation_text(block)}"]
        lines += [f"  rule: {rule.text()}" for rule in block.rules]
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------------------- import
class _Reader:
    def __init__(self, source):
        self.source = source

    def error(self, message: str, line) -> InputError:
        return InputError(message, source=self.source, field=f"line {line}" if line else None)

    def flag(self, value: str, line) -> bool:
        if value not in ("true", "false"):
            raise self.error(f"expected true or false, got {value!r}", line)
        return value == "true"

    def number(self, value: str, line, what: str) -> float:
        try:
            return decimal(value)  # as fuzzylite: '2_8' and '٢' are no numbers (float read 28 and 2)
        except ValueError:
            raise self.error(f"{what} must be a number, got {value!r}", line) from None

    def defuzzifier(self, value: str, line) -> Defuzzifier | None:
        words = value.split()
        if not words or words[0] == "none":
            return None
        kind = words[0]
        if kind in INTEGRAL:
            if len(words) > 2:
                raise self.error(f"{kind} takes at most a resolution, got {value!r}", line)
            resolution = self.number(words[1], line, "resolution") if len(words) > 1 else 1000
            most = validation.MAX_RESOLUTION
            if not math.isfinite(resolution) or resolution != int(resolution) or not 1 <= resolution <= most:
                raise self.error(f"resolution must be an integer in [1, {most}], got {words[1]!r}", line)
            return Defuzzifier(kind, int(resolution))
        if kind in WEIGHTED:
            kind_type = words[1] if len(words) > 1 else "Automatic"
            if kind_type not in WEIGHTED_TYPES or len(words) > 2:
                raise self.error(f"{kind} type must be one of {', '.join(WEIGHTED_TYPES)}, got {value!r}", line)
            return Defuzzifier(kind, type=kind_type)
        raise self.error(f"unknown defuzzifier {kind!r} (one of {', '.join(INTEGRAL + WEIGHTED)})", line)

    def activation(self, value: str, line) -> tuple[str, tuple]:
        words = value.split()
        if not words or words[0] == "none":
            return "General", ()
        kind, params = words[0], words[1:]
        if kind not in ACTIVATIONS:
            raise self.error(f"unknown activation {kind!r} (one of {', '.join(ACTIVATIONS)})", line)
        try:
            if kind in ("First", "Last"):
                return kind, (int(params[0]), decimal(params[1])) if params else (1, 0.0)
            if kind in ("Highest", "Lowest"):
                return kind, (int(params[0]),) if params else (1,)
            if kind == "Threshold":
                return kind, (params[0], decimal(params[1])) if params else (">", 0.0)
        except (ValueError, IndexError):
            raise self.error(f"bad parameters for {kind}: {' '.join(params)!r}", line) from None
        if params:
            raise self.error(f"{kind} takes no parameters, got {' '.join(params)!r}", line)
        return kind, ()


def _sections(text: str, reader: _Reader) -> list[dict]:
    sections: list[dict] = []
    for number, raw in enumerate(text.splitlines(), start=1):  # its names are printed: no ESC, NUL... (tabs indent)
        validation.text(raw.replace("\t", " "), reader.source, f"line {number}", max_length=len(raw), one_line=True)
        line = raw.split("#", 1)[0].rstrip()
        if not line.strip():
            continue
        key, sep, value = line.strip().partition(":")
        if not sep:
            raise reader.error(f"expected 'key: value', got {line.strip()!r}", number)
        key, value = key.strip(), value.strip()
        if key in _SECTION_KEYS:
            sections.append({"kind": key, "name": value, "line": number, "items": []})
        elif not sections:
            raise reader.error(f"{key!r} before any 'Engine:' section", number)
        elif key not in _SECTION_KEYS[sections[-1]["kind"]]:
            kind = sections[-1]["kind"]
            raise reader.error(f"{key!r} is not a key of {kind} (known: {', '.join(sorted(_SECTION_KEYS[kind]))})",
                               number)
        else:
            sections[-1]["items"].append((key, value, number))
    return sections


def _variable(sec: dict, reader: _Reader):
    cls = InputVariable if sec["kind"] == "InputVariable" else OutputVariable
    var = cls(sec["name"], -math.inf, math.inf)
    if not sec["name"] or len(sec["name"].split()) != 1:
        raise reader.error(f"a variable name is one word, got {sec['name']!r}", sec["line"])
    for key, value, line in sec["items"]:
        if key == "term":
            label, mf = term_from_fll(value, reader.source, line)
            var.terms[label] = mf  # a repeated name: the last one is the term, as fuzzylite's rules read it
            # (its own examples repeat names: takagi_sugeno/matlab/juggler.fll; tests/fll compares)
        elif key == "range":
            parts = value.split()
            if len(parts) != 2:
                raise reader.error(f"range must be two numbers, got {value!r}", line)
            var.minimum, var.maximum = (reader.number(p, line, "range") for p in parts)
        elif key in ("enabled", "lock-range", "lock-previous"):
            setattr(var, key.replace("-", "_"), reader.flag(value, line))
        elif key == "description":
            var.description = value
        elif key == "default":
            var.default = reader.number(value, line, "default")
        elif key == "aggregation":
            var.aggregation = None if value == "none" else value
        elif key == "defuzzifier":
            var.defuzzifier = reader.defuzzifier(value, line)
    return var


def from_fll_engine(text: str, source: str | None = None) -> Engine:
    """Parse an FLL engine into an :class:`Engine` (always; see :func:`from_fll`)."""
    reader = _Reader(source)
    sections = _sections(text, reader)
    if not sections or sections[0]["kind"] != "Engine":
        raise reader.error("an FLL file starts with 'Engine:'", sections[0]["line"] if sections else None)
    name, description = sections[0]["name"], ""
    inputs, outputs, blocks, pending = [], [], [], []
    for sec in sections:
        if sec["kind"] == "Engine":
            if sec is not sections[0]:
                raise reader.error("a second 'Engine:' section", sec["line"])
            description = next((v for k, v, _ in sec["items"] if k == "description"), "")
        elif sec["kind"] == "RuleBlock":
            pending.append(sec)
        else:
            (inputs if sec["kind"] == "InputVariable" else outputs).append(_variable(sec, reader))
    for var in outputs:  # fuzzylite's Linear may omit its constant: n coefficients for n inputs
        for label, mf in var.terms.items():
            if isinstance(mf, Linear) and len(mf.params()) == len(inputs):
                var.terms[label] = Linear(mf.params(), 0.0)
    in_terms = {v.name: v.labels for v in inputs}
    out_terms = {v.name: v.labels for v in outputs}
    for sec in pending:
        block = RuleBlock([], name=sec["name"])
        for key, value, line in sec["items"]:
            if key == "rule":
                try:
                    block.rules.append(parse_engine_rule(value, in_terms, out_terms))
                except ValueError as error:
                    raise reader.error(f"{error} in rule {value!r}", line) from None
            elif key in ("conjunction", "disjunction", "implication"):
                setattr(block, key, None if value in ("none", "") else value)
            elif key == "activation":
                block.activation, block.activation_params = reader.activation(value, line)
            elif key == "enabled":
                block.enabled = reader.flag(value, line)
            elif key == "description":
                block.description = value
        blocks.append(block)
    try:
        return Engine(inputs, outputs, blocks, name=name, description=description)
    except InputError as error:
        raise InputError(error.problem, source=source, field=error.field) from None


def from_fll(text: str, source: str | None = None) -> FuzzySystem | Engine:
    """Parse an FLL engine: a :class:`FuzzySystem` when it is exactly one, else an :class:`Engine`."""
    engine = from_fll_engine(text, source)
    return engine_to_system(engine) or engine

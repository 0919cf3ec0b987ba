"""The fuzzylite language (FLL): export and import for the subset fuzzylite and fuzzynav share.

Mapping (fuzzynav ↔ fuzzylite 6–8):

=====================  =====================================================
terms                  Triangle, Trapezoid, Ramp, Gaussian (mean sd), Bell (center width
                       slope), Sigmoid (inflection slope), Constant (TS singleton), Linear
t-norm                 ``conjunction: AlgebraicProduct`` / ``Minimum``
ts0 / ts1              ``defuzzifier: WeightedSum TakagiSugeno`` / ``WeightedAverage TakagiSugeno``
tsukamoto              ``defuzzifier: WeightedAverage Tsukamoto`` (Ramp / Sigmoid conclusions)
mamdani                ``implication: Minimum`` / ``AlgebraicProduct``, ``aggregation: Maximum`` /
                       ``UnboundedSum``, ``defuzzifier: Centroid <resolution>``
=====================  =====================================================

Export writes every number in full precision (shortest round-trip repr; fuzzylite's own
exporter rounds to 3 decimals, which shifts the goal-seeking α by ~3e-4 rad) and
``lock-range: true`` on inputs, which is fuzzylite's way of clamping them to their range (as
fuzzynav always does). fuzzylite 8's Tsukamoto sums the strengths of rules sharing a
conclusion term before inverting it, fuzzynav inverts rule by rule (the textbook method): the
two agree when no two rules share a Tsukamoto conclusion term. Import reads files written by fuzzylite itself; anything outside the
subset (OR, hedges, other terms or norms) raises :class:`InputError` naming the line.
"""

from __future__ import annotations

import math
import re

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.membership import (Bell, Gaussian, Linear, MembershipFunction, Ramp, Sigmoid, Singleton,
                                       Trapezoidal, Triangular)
from fuzzynav.fuzzy.rules import Rule, parse_rule
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.variable import Variable

FUZZYLITE_RESOLUTION = 1000
# The keys fuzzylite's own FllImporter accepts in each section; it rejects any other, and so do we.
_SECTION_KEYS = {
    "Engine": {"description"},
    "InputVariable": {"description", "enabled", "range", "lock-range", "term"},
    "OutputVariable": {"description", "enabled", "range", "lock-range", "term", "default", "lock-previous",
                       "aggregation", "defuzzifier"},
    "RuleBlock": {"description", "enabled", "conjunction", "disjunction", "implication", "activation", "rule"},
}
_TNORM_OUT = {"product": "AlgebraicProduct", "min": "Minimum"}
_TNORM_IN = {v: k for k, v in _TNORM_OUT.items()}
_AGGREGATION_OUT = {"max": "Maximum", "sum": "UnboundedSum"}
_AGGREGATION_IN = {v: k for k, v in _AGGREGATION_OUT.items()}
_DEFUZZ_OUT = {"weighted_sum": "WeightedSum", "weighted_average": "WeightedAverage"}
_DEFUZZ_IN = {v: k for k, v in _DEFUZZ_OUT.items()}


def _num(x: float) -> str:
    return "nan" if math.isnan(x) else ("inf" if x == math.inf else "-inf" if x == -math.inf else repr(float(x)))


def _term_out(label: str, mf: MembershipFunction) -> str:
    if isinstance(mf, Ramp):
        name, params = "Ramp", mf.params()
    elif isinstance(mf, Triangular):
        name, params = "Triangle", mf.params()
    elif isinstance(mf, Trapezoidal):
        name, params = "Trapezoid", mf.params()
    elif isinstance(mf, Gaussian):
        name, params = "Gaussian", (mf.mean, mf.sigma)
    elif isinstance(mf, Bell):
        name, params = "Bell", (mf.c, mf.a, mf.b)
    elif isinstance(mf, Sigmoid):
        name, params = "Sigmoid", (mf.c, mf.a)
    elif isinstance(mf, Singleton):
        name, params = "Constant", mf.params()
    elif isinstance(mf, Linear):
        name, params = "Linear", mf.params()
    else:  # pragma: no cover - every kind of membership.py is listed above
        raise InputError(f"no FLL equivalent for {mf!r}", field=label)
    return f"  term: {label} {name} {' '.join(_num(p) for p in params)}"


def _rule_out(rule: Rule) -> str:
    premises = " and ".join(f"{v} is {t}" for v, t in rule.premises)
    conclusions = " and ".join(f"{v} is {t}" for v, t in rule.conclusions)
    weight = "" if rule.weight == 1.0 else f" with {_num(rule.weight)}"
    return f"  rule: if {premises} then {conclusions}{weight}"


def to_fll(system: FuzzySystem) -> str:
    """``system`` in the fuzzylite language, full precision."""
    lines = [f"Engine: {system.name}".rstrip()]
    if system.description:
        lines.append(f"  description: {system.description}")
    for v in system.inputs:
        lines += [f"InputVariable: {v.name}", "  enabled: true", f"  range: {_num(v.universe[0])} {_num(v.universe[1])}",
                  "  lock-range: true"]
        lines += [_term_out(label, mf) for label, mf in v.terms.items()]
    if system.method == "mamdani":
        aggregation = _AGGREGATION_OUT[system.aggregation]
        defuzzifier = f"Centroid {system.resolution}"
    else:
        aggregation = "none"
        kind = "Tsukamoto" if system.method == "tsukamoto" else "TakagiSugeno"
        defuzzifier = f"{_DEFUZZ_OUT[system.defuzzifier]} {kind}"
    for v in system.outputs:
        lines += [f"OutputVariable: {v.name}", "  enabled: true", f"  range: {_num(v.universe[0])} {_num(v.universe[1])}",
                  "  lock-range: false", f"  aggregation: {aggregation}", f"  defuzzifier: {defuzzifier}",
                  "  default: nan", "  lock-previous: false"]
        lines += [_term_out(label, mf) for label, mf in v.terms.items()]
    implication = _TNORM_OUT[system.implication] if system.method == "mamdani" else "none"
    lines += ["RuleBlock: rules", "  enabled: true", f"  conjunction: {_TNORM_OUT[system.tnorm]}",
              "  disjunction: none", f"  implication: {implication}", "  activation: General"]
    lines += [_rule_out(rule) for rule in system.rules]
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------------------- import
def _term_in(value: str, source, line: int) -> tuple[str, MembershipFunction]:
    parts = value.split()
    where = f"line {line}"
    if len(parts) < 2:
        raise InputError(f"a term reads 'NAME Kind params...', got {value!r}", source=source, field=where)
    label, kind, raw = parts[0], parts[1], parts[2:]
    try:
        p = [float(x) for x in raw]
    except ValueError:
        raise InputError(f"term {label}: parameters must be numbers, got {' '.join(raw)!r}",
                         source=source, field=where) from None
    arity = {"Triangle": 3, "Trapezoid": 4, "Ramp": 2, "Gaussian": 2, "Bell": 3, "Sigmoid": 2, "Constant": 1}
    if kind != "Linear" and kind not in arity:
        raise InputError(f"term {label}: unsupported term type {kind!r} (supported: {', '.join(arity)}, Linear)",
                         source=source, field=where)
    if kind != "Linear" and len(p) != arity[kind]:
        # fuzzylite allows a trailing height; only height 1 means the same set
        if len(p) == arity[kind] + 1 and p[-1] == 1.0:
            p = p[:-1]
        else:
            raise InputError(f"term {label}: {kind} takes {arity[kind]} parameters, got {len(p)}",
                             source=source, field=where)
    try:
        mf = {
            "Triangle": lambda: Triangular(*p),
            "Trapezoid": lambda: Trapezoidal(*p),
            "Ramp": lambda: Ramp(*p),
            "Gaussian": lambda: Gaussian(p[1], p[0]),
            "Bell": lambda: Bell(p[1], p[2], p[0]),
            "Sigmoid": lambda: Sigmoid(p[1], p[0]),
            "Constant": lambda: Singleton(p[0]),
            "Linear": lambda: Linear(p[:-1], p[-1] if p else 0.0),
        }[kind]()
    except ValueError as error:
        raise InputError(f"term {label}: {error}", source=source, field=where) from None
    return label, mf


def _rule_in(value: str, source, line: int) -> Rule:
    words = value.split()
    lowered = [w.lower() for w in words]
    where = f"line {line}"
    for banned, what in (("or", "OR"), ("not", "NOT"), ("very", "hedges"), ("somewhat", "hedges"),
                         ("extremely", "hedges"), ("seldom", "hedges"), ("any", "hedges")):
        if banned in lowered:
            raise InputError(f"{what} in rules is not supported: {value!r}", source=source, field=where)
    try:
        return parse_rule(value)
    except InputError as error:
        raise InputError(error.problem, source=source, field=where) from None


def from_fll(text: str, source: str | None = None) -> FuzzySystem:
    """Parse an FLL engine (one rule block) into a :class:`FuzzySystem`; errors name the line."""
    sections: list[dict] = []
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("#", 1)[0].rstrip()
        if not line.strip():
            continue
        key, sep, value = line.strip().partition(":")
        if not sep:
            raise InputError(f"expected 'key: value', got {line.strip()!r}", source=source, field=f"line {number}")
        key, value = key.strip(), value.strip()
        if not raw[0].isspace() and key in ("Engine", "InputVariable", "OutputVariable", "RuleBlock"):
            sections.append({"kind": key, "name": value, "line": number, "items": []})
        elif not sections:
            raise InputError(f"{key!r} before any 'Engine:' section", source=source, field=f"line {number}")
        else:
            sections[-1]["items"].append((key, value, number))

    engine = {"name": "", "description": ""}
    inputs, outputs, rules, rule_lines = [], [], [], []
    settings: dict[str, tuple[str, int]] = {}
    blocks = 0
    for sec in sections:
        kind, items = sec["kind"], sec["items"]
        for key, _, number in items:
            if key not in _SECTION_KEYS[kind]:
                raise InputError(f"{key!r} is not a key of {kind} (known: {', '.join(sorted(_SECTION_KEYS[kind]))})",
                                 source=source, field=f"line {number}")
        if kind == "Engine":
            engine["name"] = sec["name"]
            for key, value, number in items:
                if key == "description":
                    engine["description"] = value
            continue
        if kind == "RuleBlock":
            blocks += 1
            if blocks > 1:
                raise InputError("only one RuleBlock is supported", source=source, field=f"line {sec['line']}")
        universe, terms = None, {}
        for key, value, number in items:
            where = f"line {number}"
            if key == "enabled" and value != "true":
                raise InputError(f"disabled {kind} is not supported", source=source, field=where)
            elif key == "range":
                try:
                    universe = tuple(float(v) for v in value.split())
                except ValueError:
                    universe = ()
                if len(universe) != 2:
                    raise InputError(f"range must be two numbers, got {value!r}", source=source, field=where)
            elif key == "term":
                label, mf = _term_in(value, source, number)
                if label in terms:
                    raise InputError(f"duplicate term {label!r}", source=source, field=where)
                terms[label] = mf
            elif key == "rule":
                rules.append(_rule_in(value, source, number))
                rule_lines.append(number)
            elif key in ("conjunction", "implication", "aggregation", "defuzzifier", "activation", "disjunction"):
                settings.setdefault(key, (value, number))
                if settings[key][0] != value:
                    raise InputError(f"{key} differs between variables ({settings[key][0]!r} vs {value!r})",
                                     source=source, field=where)
        if kind in ("InputVariable", "OutputVariable"):
            if universe is None:
                raise InputError(f"{kind} {sec['name']} has no range", source=source, field=f"line {sec['line']}")
            try:
                var = Variable(sec["name"], universe, terms)
            except InputError as error:
                raise InputError(error.problem, source=source, field=f"line {sec['line']} ({error.field})") from None
            (inputs if kind == "InputVariable" else outputs).append(var)

    def setting(key, default):
        return settings.get(key, (default, None))

    def bad(key, value, number, allowed):
        raise InputError(f"{key} {value!r} is not supported (use {' or '.join(allowed)})", source=source,
                         field=f"line {number}" if number else key)

    options = {}
    conj, number = setting("conjunction", "none")
    if conj != "none":
        if conj not in _TNORM_IN:
            bad("conjunction", conj, number, _TNORM_IN)
        options["tnorm"] = _TNORM_IN[conj]
    act, number = setting("activation", "General")
    if act not in ("General", "none", ""):
        bad("activation", act, number, ["General"])
    defuzz, number = setting("defuzzifier", "")
    words = defuzz.split()
    if words and words[0] == "Centroid":
        options["method"] = "mamdani"
        # fuzzylite's IntegralDefuzzifier.default_resolution when the file gives none
        options["resolution"] = (validation.integer(int(words[1]) if re.fullmatch(r"\d{1,9}", words[1]) else words[1],
                                                    source, f"line {number}: resolution", lo=2,
                                                    hi=validation.MAX_RESOLUTION)
                                 if len(words) > 1 else FUZZYLITE_RESOLUTION)
        imp, n_imp = setting("implication", "Minimum")
        if imp not in _TNORM_IN:
            bad("implication", imp, n_imp, _TNORM_IN)
        agg, n_agg = setting("aggregation", "Maximum")
        if agg not in _AGGREGATION_IN:
            bad("aggregation", agg, n_agg, _AGGREGATION_IN)
        options.update(implication=_TNORM_IN[imp], aggregation=_AGGREGATION_IN[agg])
    elif words and words[0] in _DEFUZZ_IN:
        options["defuzzifier"] = _DEFUZZ_IN[words[0]]
        out_terms = [mf for v in outputs for mf in v.terms.values()]
        if all(isinstance(mf, Singleton) for mf in out_terms):
            options["method"] = "ts0"
        elif all(isinstance(mf, (Singleton, Linear)) for mf in out_terms):
            options["method"] = "ts1"
        else:
            options["method"] = "tsukamoto"
    else:
        bad("defuzzifier", defuzz, number, ["Centroid", "WeightedSum", "WeightedAverage"])
    try:
        return FuzzySystem(inputs, outputs, rules, name=engine["name"], description=engine["description"], **options)
    except InputError as error:
        field = error.field
        match = re.match(r"rules\[(\d+)\]", field or "")
        if match:
            field = f"line {rule_lines[int(match.group(1))]}"
        raise InputError(error.problem, source=source, field=field) from None

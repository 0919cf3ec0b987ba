"""A fuzzy system as dependency-free C99 for a microcontroller: one function, no heap, no globals
written at run time.

``to_c(system, name)`` returns ``(header, source)`` declaring

    int NAME_evaluate(const NAME_real in[N_INPUTS], NAME_real out[N_OUTPUTS]);

which computes what :meth:`FuzzySystem.evaluate` computes for one input vector: inputs clamped
to their universes; TS0 / TS1 (weighted sum or average; premises by product or min; rule
weights) and Mamdani by its sampled output (the output terms tabulated at the centroid's
``resolution`` midpoints, clipped or scaled, aggregated by max or sum, centroid). The return
value has bit o set when no rule fired on output o (its value is then 0 for a weighted sum and
for everything in fixed point, NaN for a weighted average or a centroid in double).

``fixed=None`` uses ``double`` (and ``<math.h>`` for Gaussian, bell and sigmoid terms).
``fixed="Q16.16"`` uses ``int32_t`` with 16 fractional bits (inputs and outputs in Q16.16,
products in 64 bits): only piecewise-linear terms (triangles, trapezoids, ramps, shoulders) and
|values| < 32768. Its error comes from rounding each constant and each product to 2⁻¹⁶
(≈ 1.5e-5). Documented bound, tested on 10,000 random inputs: ≤ 1e-3 × the output range for
TS0 / TS1; for Mamdani the same where the strongest rule fires at ≥ 0.01 (a centroid of sets cut
below 0.01 is the ratio of two numbers of a few 2⁻¹⁶ steps: up to a few % of the range).
"""

from __future__ import annotations

import math
import re

import numpy as np

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.inference import centroid_grid
from fuzzynav.fuzzy.membership import Bell, Gaussian, Sigmoid, Singleton, Trapezoidal
from fuzzynav.fuzzy.system import FuzzySystem

FIXED_FORMATS = ("Q16.16",)
_SCALE = 1 << 16

_PRELUDE_DOUBLE = """typedef double {p}_real;
#define {P}_MUL(a, b) ((a) * (b))
#define {P}_DIV(a, b) ((a) / (b))
#define {P}_ONE 1.0
#define {P}_ZERO 0.0
#define {P}_NONE NAN
"""
_PRELUDE_FIXED = """typedef int32_t {p}_real; /* Q16.16 */
#define {P}_MUL(a, b) ((int32_t)(((int64_t)(a) * (int64_t)(b)) / 65536))
#define {P}_DIV(a, b) ((int32_t)(((int64_t)(a) * 65536) / (int64_t)(b)))
#define {P}_ONE 65536
#define {P}_ZERO 0
#define {P}_NONE 0
"""


def _comment(text: str) -> str:
    """``text`` safe inside a C comment: no ``*/`` to end it, no ``/*`` inside it, no line break."""
    return " ".join(str(text).replace("*/", "* /").replace("/*", "/ *").split())


def _identifier(name: str) -> str:
    ident = re.sub(r"\W", "_", name).strip("_").lower() or "fis"
    return ident if not ident[0].isdigit() else f"fis_{ident}"


def _fits(value: float) -> bool:
    """Does ``value`` fit Q16.16 (scaled and rounded, under 2³¹ in magnitude; not NaN or ∞)?"""
    return abs(value * _SCALE) < 2 ** 31 - 0.5


class _Writer:
    def __init__(self, fixed: bool, prefix: str):
        self.fixed, self.p = fixed, prefix

    def const(self, value: float) -> str:
        if self.fixed:
            if not _fits(value):
                raise InputError(f"{value!r} does not fit Q16.16 (|value| < 32768)", field="--fixed")
            return f"((int32_t){round(value * _SCALE)})"
        return "INFINITY" if value == math.inf else "-INFINITY" if value == -math.inf else repr(float(value))

    def sloped(self, width: float) -> bool:
        """Is a ramp of ``width`` a slope in this number format? In Q16.16 a ramp narrower than
        its step (1/65536) is a step: its width rounds to 0, and dividing by it would trap."""
        return width > 0 and (not self.fixed or width * _SCALE > 0.5)  # round(x) ≠ 0, for x = ∞ too

    def within(self, x: str, lo: float, hi: float) -> str:
        """``x`` in fixed point held to [``lo``, ``hi``] before a ramp's division, whose quotient
        would pass int32 where the ramp is narrow and ``x`` far (its slope times the distance); in
        floating point ``x`` itself (the ramp's value is held to [0, 1] after)."""
        if not self.fixed or not (math.isfinite(lo) and math.isfinite(hi)):
            return x
        return f"{self.p}_min({self.p}_max({x}, {self.const(lo)}), {self.const(hi)})"

    def mul(self, a: str, b: str) -> str:
        return f"{self.p.upper()}_MUL({a}, {b})"

    def div(self, a: str, b: str) -> str:
        return f"{self.p.upper()}_DIV({a}, {b})"

    def membership(self, mf, x: str, field: str) -> str:
        """A C expression of μ(x) in [0, 1] (as the Python term computes it)."""
        if isinstance(mf, Trapezoidal):  # triangles, ramps and shoulders too
            a, b, c, d = mf._edges()
            parts = []
            if b > -math.inf:
                rise = (self.div(f"({self.within(x, a, b)} - {self.const(a)})", self.const(b - a)) if self.sloped(b - a)
                        else f"({x} < {self.const(a)} ? {self.p.upper()}_ZERO : {self.p.upper()}_ONE)")
                parts.append(rise)
            if c < math.inf:
                fall = (self.div(f"({self.const(d)} - {self.within(x, c, d)})", self.const(d - c)) if self.sloped(d - c)
                        else f"({x} > {self.const(d)} ? {self.p.upper()}_ZERO : {self.p.upper()}_ONE)")
                parts.append(fall)
            expr = f"{self.p.upper()}_ONE"
            for part in parts:
                expr = f"{self.p}_min({expr}, {part})"
            return f"{self.p}_unit({expr})"
        if self.fixed:
            raise InputError(f"{type(mf).__name__} terms have no fixed-point form (only piecewise-linear terms)",
                             field=field)
        if isinstance(mf, Gaussian):
            return f"exp(-0.5 * (({x} - {mf.mean!r}) / {mf.sigma!r}) * (({x} - {mf.mean!r}) / {mf.sigma!r}))"
        if isinstance(mf, Bell):
            return f"(1.0 / (1.0 + pow(fabs(({x} - {mf.c!r}) / {mf.a!r}), 2.0 * {mf.b!r})))"
        if isinstance(mf, Sigmoid):
            return f"(1.0 / (1.0 + exp(-{mf.a!r} * ({x} - {mf.c!r}))))"
        raise InputError(f"{type(mf).__name__} terms cannot be exported to C", field=field)


def _check(system: FuzzySystem) -> None:
    if not isinstance(system, FuzzySystem):  # a file read as an engine (engine.convert.engine_to_system)
        raise InputError("C export takes TS0, TS1 and Mamdani systems; this one holds what they cannot: what "
                         "makes one is a single rule block, inputs clipped to their range (lock-range), outputs "
                         "with no default, lock-range or lock-previous and one defuzzifier and aggregation, and "
                         "terms of the package's shapes", field="system")
    if system.method not in ("ts0", "ts1", "mamdani"):
        raise InputError(f"C export takes TS0, TS1 and Mamdani systems, got {system.method}", field="system")


def _distinct_in_fixed_point(system: FuzzySystem) -> None:
    """Refuse an input term whose distinct breakpoints Q16.16 rounds, all of them, to one value: the
    term would shrink to a point or a step where it spans a width (theta's terms scaled by 1e-6
    all fired at once at 0, and the C answered a speed of 15.6 where the universe ends at 4). One
    ramp narrower than a step becomes a step (:meth:`_Writer.sloped`); the term keeps its extent."""
    for v in system.inputs:
        for label, mf in v.terms.items():
            edges = sorted({e for e in mf._edges() if math.isfinite(e)}) if isinstance(mf, Trapezoidal) else []
            if len(edges) > 1 and _fits(edges[0]) and _fits(edges[-1]) \
                    and round(edges[0] * _SCALE) == round(edges[-1] * _SCALE):  # (one that does not fit: const)
                raise InputError(f"its breakpoints {', '.join(map(repr, edges))} are one value in Q16.16 (steps of "
                                 "1/65536): export in double, or scale the input", field=f"--fixed: {v.name}.{label}")


def to_c(system: FuzzySystem, name: str | None = None, fixed: str | None = None,
         header_file: str | None = None) -> tuple[str, str]:
    """``(header, source)`` of the C99 evaluator of ``system`` (see module docstring); the functions
    are prefixed by ``name`` (default: the system's name) and the source includes ``header_file``
    (default ``<prefix>.h``)."""
    _check(system)
    if header_file is not None and any(mark in header_file for mark in '"\\\r\n'):
        raise InputError(f"the header's name {header_file!r} holds a quote, a backslash or a line break, which "
                         '#include "..." cannot hold: choose another file name', field="-o")
    if fixed is not None and fixed not in FIXED_FORMATS:
        raise InputError(f"fixed-point format must be one of {', '.join(FIXED_FORMATS)}, got {fixed!r}",
                         field="--fixed")
    if fixed is not None:
        _distinct_in_fixed_point(system)
    p = _identifier(name or system.name)
    P = p.upper()
    w = _Writer(fixed is not None, p)
    n_in, n_out = len(system.inputs), len(system.outputs)
    header = "\n".join([
        f"/* {_comment(system.name or p)}: fuzzy system exported by fuzzynav (C99, no heap). */",
        f"#ifndef {P}_H", f"#define {P}_H", "", "#include <stdint.h>", "",
        (_PRELUDE_FIXED if fixed else _PRELUDE_DOUBLE).format(p=p, P=P).rstrip(), "",
        f"#define {P}_N_INPUTS {n_in}", f"#define {P}_N_OUTPUTS {n_out}", "",
        f"/* inputs: {_comment(', '.join(system.input_names))}; outputs: {_comment(', '.join(system.output_names))}"
        + (" (Q16.16: value * 65536)" if fixed else "") + ".",
        "   Returns a bit mask of the outputs on which no rule fired (0: all fired). */",
        f"int {p}_evaluate(const {p}_real in[{P}_N_INPUTS], {p}_real out[{P}_N_OUTPUTS]);", "", f"#endif /* {P}_H */",
        ""])
    body = [f'#include "{header_file or p + ".h"}"', "", "#include <math.h>", "",
            f"static {p}_real {p}_min({p}_real a, {p}_real b) {{ return a < b ? a : b; }}",
            f"static {p}_real {p}_max({p}_real a, {p}_real b) {{ return a > b ? a : b; }}",
            f"static {p}_real {p}_unit({p}_real a) {{ return {p}_min({p}_max(a, {P}_ZERO), {P}_ONE); }}", ""]
    body += _tables(system, w) + [f"int {p}_evaluate(const {p}_real in[{P}_N_INPUTS], {p}_real out[{P}_N_OUTPUTS])",
                                  "{", "    int none = 0;"]
    for i, v in enumerate(system.inputs):
        lo, hi = (w.const(u) for u in v.universe)
        body.append(f"    const {p}_real x{i} = {p}_min({p}_max(in[{i}], {lo}), {hi}); /* {_comment(v.name)} */")
    for i, v in enumerate(system.inputs):
        values = ", ".join(w.membership(mf, f"x{i}", f"{v.name}.{label}") for label, mf in v.terms.items())
        body.append(f"    const {p}_real mu{i}[{len(v.terms)}] = {{{values}}};")
    body += _rules(system, w) + _outputs(system, w) + ["    return none;", "}", ""]
    return header, "\n".join(body)


def _tables(system: FuzzySystem, w: _Writer) -> list[str]:
    """Mamdani: every output term sampled at the centroid's abscissae, and the abscissae."""
    if system.method != "mamdani":
        return []
    lines = []
    for o, v in enumerate(system.outputs):
        samples = centroid_grid(v.universe, system.resolution)
        lines.append(f"static const {w.p}_real y{o}[{len(samples)}] = {{{', '.join(w.const(s) for s in samples)}}};")
        for t, mf in enumerate(v.terms.values()):
            values = np.asarray(mf(samples), dtype=float)
            lines.append(f"static const {w.p}_real shape{o}_{t}[{len(samples)}] = "
                         f"{{{', '.join(w.const(s) for s in values)}}};")
    return lines + [""]


def _rules(system: FuzzySystem, w: _Writer) -> list[str]:
    c = system.compiled
    lines = [f"    {w.p}_real fire[{len(system.rules)}];"]
    for r in range(len(system.rules)):
        expr = f"{w.p.upper()}_ONE"
        for i in range(len(system.inputs)):
            if c.premises[r, i] >= 0:
                term = f"mu{i}[{c.premises[r, i]}]"
                expr = w.mul(expr, term) if system.tnorm == "product" else f"{w.p}_min({expr}, {term})"
        lines.append(f"    fire[{r}] = {w.mul(expr, w.const(c.weights[r]))}; /* {_comment(system.rules[r].text())} */")
    return lines


def _conclusion(system: FuzzySystem, w: _Writer, o: int, r: int) -> str:
    term = list(system.outputs[o].terms.values())[system.compiled.conclusions[r, o]]
    if isinstance(term, Singleton):
        return w.const(term.value)
    expr = w.const(term.constant)
    for i, coefficient in enumerate(term.coefficients):
        expr = f"({expr} + {w.mul(w.const(coefficient), f'x{i}')})"
    return expr


def _outputs(system: FuzzySystem, w: _Writer) -> list[str]:
    c, p, P = system.compiled, w.p, w.p.upper()
    lines = []
    for o, v in enumerate(system.outputs):
        rules = [r for r in range(len(system.rules)) if c.conclusions[r, o] >= 0]
        lines.append(f"    {{ /* {_comment(v.name)} */")
        if system.method == "mamdani":
            n = system.resolution
            lines += [f"        {p}_real num = {P}_ZERO, area = {P}_ZERO;", "        int k;",
                      f"        for (k = 0; k < {n}; ++k) {{", f"            {p}_real agg = {P}_ZERO, cut;"]
            for r in rules:
                shape = f"shape{o}_{c.conclusions[r, o]}[k]"
                cut = f"{p}_min(fire[{r}], {shape})" if system.implication == "min" else w.mul(f"fire[{r}]", shape)
                join = f"{p}_max(agg, cut)" if system.aggregation == "max" else "agg + cut"
                lines.append(f"            cut = {cut}; agg = {join};")
            lines += [f"            num += {w.mul('agg', f'y{o}[k]')}; area += agg;", "        }",
                      f"        if (area > {P}_ZERO) out[{o}] = {w.div('num', 'area')};",
                      f"        else {{ out[{o}] = {P}_NONE; none |= {1 << o}; }}", "    }"]
            continue
        lines.append(f"        {p}_real num = {P}_ZERO, den = {P}_ZERO;")
        for r in rules:
            lines.append(f"        num += {w.mul(f'fire[{r}]', _conclusion(system, w, o, r))}; den += fire[{r}];")
        if system.defuzzifier == "weighted_sum":
            lines += [f"        out[{o}] = num;", f"        if (!(den > {P}_ZERO)) none |= {1 << o};"]
        else:
            lines += [f"        if (den > {P}_ZERO) out[{o}] = {w.div('num', 'den')};",
                      f"        else {{ out[{o}] = {P}_NONE; none |= {1 << o}; }}"]
        lines.append("    }")
    return lines


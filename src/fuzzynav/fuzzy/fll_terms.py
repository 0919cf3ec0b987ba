"""Terms as the fuzzylite language writes them: ``Name Kind p1 p2 … [height]``.

Parameter orders are fuzzylite's (Gaussian ``mean sd``, Bell ``center width slope``, Sigmoid
``inflection slope``, …); an optional last parameter is the height (a :class:`Scaled` term
when ≠ 1). ``Constant`` and ``Linear`` take no height; ``Discrete`` takes x y pairs (an odd
count ends with the height); ``Function`` takes a formula.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from fuzzynav.errors import InputError
from fuzzynav.fuzzy import terms as extra
from fuzzynav.fuzzy.formula import Function, decimal
from fuzzynav.fuzzy.membership import Bell, Gaussian, Linear, Ramp, Sigmoid, Singleton, Trapezoidal, Triangular

if TYPE_CHECKING:  # annotations only
    from fuzzynav.fuzzy.membership import MembershipFunction

# FLL name: (arity, builder from the FLL parameters, FLL parameters of a term)
_TERMS = {
    "Triangle": (3, lambda p: Triangular(*p), lambda m: m.params()),
    "Trapezoid": (4, lambda p: Trapezoidal(*p), lambda m: m.params()),
    "Ramp": (2, lambda p: Ramp(*p), lambda m: m.params()),
    "Gaussian": (2, lambda p: Gaussian(p[1], p[0]), lambda m: (m.mean, m.sigma)),
    "Bell": (3, lambda p: Bell(p[1], p[2], p[0]), lambda m: (m.c, m.a, m.b)),
    "Sigmoid": (2, lambda p: Sigmoid(p[1], p[0]), lambda m: (m.c, m.a)),
}
_TERMS.update({name: (len(cls.names), lambda p, cls=cls: cls(*p), lambda m: m.params()) for name, cls in (
    ("SShape", extra.SShape), ("ZShape", extra.ZShape), ("PiShape", extra.PiShape), ("Cosine", extra.Cosine),
    ("Concave", extra.Concave), ("Spike", extra.Spike), ("Arc", extra.Arc), ("Binary", extra.Binary),
    ("SemiEllipse", extra.SemiEllipse), ("Rectangle", extra.Rectangle),
    ("SigmoidDifference", extra.SigmoidDifference), ("SigmoidProduct", extra.SigmoidProduct),
    ("GaussianProduct", extra.GaussianProduct))})
_NAME_OF = {Triangular: "Triangle", Trapezoidal: "Trapezoid", Ramp: "Ramp", Gaussian: "Gaussian", Bell: "Bell",
            Sigmoid: "Sigmoid", **{getattr(extra, n): n for n in _TERMS if hasattr(extra, n)}}
KNOWN = (*_TERMS, "Constant", "Linear", "Discrete", "Function")


def num(x: float) -> str:
    """A number as FLL writes it, exactly (``nan``, ``inf``, ``-inf`` or the shortest repr)."""
    return "nan" if math.isnan(x) else ("inf" if x == math.inf else "-inf" if x == -math.inf else repr(float(x)))


def term_to_fll(mf: MembershipFunction) -> str:
    """``Kind params…`` of ``mf`` (full precision)."""
    if isinstance(mf, extra.Scaled):
        return f"{term_to_fll(mf.term)} {num(mf.height)}"
    if isinstance(mf, (Singleton, extra.Constant)):
        return f"Constant {num(mf.params()[0])}"
    if isinstance(mf, Linear):
        return "Linear " + " ".join(num(p) for p in mf.params())
    if isinstance(mf, Function):
        return f"Function {mf.formula}"
    if isinstance(mf, extra.Discrete):
        return "Discrete " + " ".join(num(p) for p in mf.params())
    name = _NAME_OF.get(type(mf))
    if name is None:
        raise InputError(f"no FLL equivalent for {mf!r}", field="term")
    return f"{name} {' '.join(num(p) for p in _TERMS[name][2](mf))}"


def term_from_fll(value: str, source, line: int) -> tuple[str, MembershipFunction]:
    """``(label, term)`` from the text after ``term:``; errors name ``source`` and ``line``."""
    parts = value.split()
    where = f"line {line}"
    if len(parts) < 2:
        raise InputError(f"a term reads 'NAME Kind params...', got {value!r}", source=source, field=where)
    label, kind, raw = parts[0], parts[1], parts[2:]
    if kind not in KNOWN:
        raise InputError(f"term {label}: unknown term type {kind!r} (known: {', '.join(KNOWN)})",
                         source=source, field=where)
    try:
        if kind == "Function":
            return label, Function(value.split(None, 2)[2] if len(parts) > 2 else "")
        arity, build = _TERMS[kind][:2] if kind in _TERMS else (0, None)
        return label, extra.from_numbers(kind.lower(), [decimal(x) for x in raw], build, arity)
    except ValueError as error:
        raise InputError(f"term {label}: {error}", source=source, field=where) from None


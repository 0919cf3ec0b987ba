"""Membership functions as MATLAB ``.fis`` files write them: ``'label':'trimf',[a b c]``.

MATLAB's parameter orders (Fuzzy Logic Toolbox reference): trimf [a b c], trapmf [a b c d],
gaussmf [σ c], gauss2mf [σ1 c1 σ2 c2], gbellmf [a b c], sigmf [a c], dsigmf / psigmf
[a1 c1 a2 c2], smf / zmf [a b], pimf [a b c d], linsmf / linzmf [a b] (the open shoulders of the
thesis' partitions), constant [c], linear [c1 … cn c0]. The other
names are fuzzylite's, with fuzzylite's parameter orders; a parameter beyond the count is a height
(for MATLAB's own names, trailing zeros are the padding older MATLAB versions write).
"""

from __future__ import annotations

import math
import re
from typing import TYPE_CHECKING

from fuzzynav.errors import InputError
from fuzzynav.fuzzy import terms as extra
from fuzzynav.fuzzy.formula import Function, decimal
from fuzzynav.fuzzy.membership import Bell, Gaussian, Linear, Ramp, Sigmoid, Singleton, Trapezoidal, Triangular

if TYPE_CHECKING:  # annotations only
    from fuzzynav.fuzzy.membership import MembershipFunction

# .fis name: (class, number of parameters, from .fis parameters, to .fis parameters)
_MFS = {
    "trimf": (Triangular, 3, lambda p: Triangular(*p), lambda m: m.params()),
    "trapmf": (Trapezoidal, 4, lambda p: Trapezoidal(*p), lambda m: m.params()),
    "gaussmf": (Gaussian, 2, lambda p: Gaussian(*p), lambda m: m.params()),
    "gauss2mf": (extra.GaussianProduct, 4, lambda p: extra.GaussianProduct(p[1], p[0], p[3], p[2]),
                 lambda m: (m.sd_a, m.mean_a, m.sd_b, m.mean_b)),
    "gbellmf": (Bell, 3, lambda p: Bell(*p), lambda m: m.params()),
    "sigmf": (Sigmoid, 2, lambda p: Sigmoid(*p), lambda m: m.params()),
    "dsigmf": (extra.SigmoidDifference, 4, lambda p: extra.SigmoidDifference(p[1], p[0], p[2], p[3]),
               lambda m: (m.rising, m.left, m.falling, m.right)),
    "psigmf": (extra.SigmoidProduct, 4, lambda p: extra.SigmoidProduct(p[1], p[0], p[2], p[3]),
               lambda m: (m.rising, m.left, m.falling, m.right)),
    "smf": (extra.SShape, 2, lambda p: extra.SShape(*p), lambda m: m.params()),
    "zmf": (extra.ZShape, 2, lambda p: extra.ZShape(*p), lambda m: m.params()),
    "pimf": (extra.PiShape, 4, lambda p: extra.PiShape(*p), lambda m: m.params()),
    "rampmf": (Ramp, 2, lambda p: Ramp(*p), lambda m: m.params()),
    "linzmf": (None, 2, lambda p: Trapezoidal(-math.inf, -math.inf, *p), None),
    "linsmf": (None, 2, lambda p: Trapezoidal(*p, math.inf, math.inf), None),
}
_MFS.update({name: (cls, len(cls.names), lambda p, cls=cls: cls(*p), lambda m: m.params()) for name, cls in (
    ("concavemf", extra.Concave), ("cosinemf", extra.Cosine), ("spikemf", extra.Spike), ("rectmf", extra.Rectangle),
    ("binarymf", extra.Binary), ("arcmf", extra.Arc), ("semiellipsemf", extra.SemiEllipse))})
_MATLAB = ("trimf", "trapmf", "gaussmf", "gauss2mf", "gbellmf", "sigmf", "dsigmf", "psigmf", "smf", "zmf", "pimf")
_NAME_OF = {cls: name for name, (cls, *_) in _MFS.items() if cls is not None}


def number(x: float) -> str:
    """A number as a .fis file writes it (shortest exact repr; Inf, -Inf, NaN as MATLAB spells them)."""
    return repr(float(x)) if math.isfinite(x) else ("Inf" if x > 0 else "-Inf" if x < 0 else "NaN")


def _shoulder(mf: Trapezoidal) -> tuple[str, tuple]:
    """An open shoulder as MATLAB's linzmf [c d] (1 up to c, 0 from d) or linsmf [a b]: trimf and
    trapmf would compute ∞/∞ there."""
    a, b, c, d = mf._edges()
    if a == -math.inf and math.isfinite(d):
        return "linzmf", (c, d)
    if d == math.inf and math.isfinite(a):
        return "linsmf", (a, b)
    raise InputError(f"{mf!r} is 1 everywhere: no .fis membership function", field="term")


def term_to_fis(mf: MembershipFunction) -> str:
    """``'kind',[params]`` of ``mf``."""
    height = ()
    if isinstance(mf, extra.Scaled):
        mf, height = mf.term, (mf.height,)
    if isinstance(mf, (Singleton, extra.Constant)):
        kind, params = "constant", (mf.params()[0],)
    elif isinstance(mf, Linear):
        kind, params = "linear", mf.params()
    elif isinstance(mf, Function):
        return f"'function',[{mf.formula}]"
    elif isinstance(mf, extra.Discrete):
        kind, params = "discretemf", mf.params()
    elif isinstance(mf, Trapezoidal) and not isinstance(mf, Ramp) and not all(map(math.isfinite, mf.params())):
        kind, params = _shoulder(mf)
    elif type(mf) in _NAME_OF:
        kind = _NAME_OF[type(mf)]
        params = _MFS[kind][3](mf)
    else:
        raise InputError(f"no .fis equivalent for {mf!r}", field="term")
    return f"'{kind}',[{' '.join(number(p) for p in (*params, *height))}]"


def term_from_fis(value: str, source, line: int) -> tuple[str, MembershipFunction]:
    """``(label, term)`` from ``'label':'kind',[params]``; errors name ``source`` and ``line``."""
    where = f"line {line}"
    match = re.fullmatch(r"'([^']*)'\s*:\s*'([^']*)'\s*,\s*\[(.*)\]\s*(?:,\s*[-\d.eE+]+\s*)?", value.strip())
    if not match:
        raise InputError(f"a membership function reads 'label':'kind',[params], got {value!r}", source=source,
                         field=where)
    label, kind, raw = re.sub(r"\W", "_", match.group(1)) or "_", match.group(2), match.group(3)
    try:
        if kind == "function":
            return label, Function(raw)
        p = [decimal(x) for x in raw.replace(",", " ").split()]  # ('1_0' was read as 10)
        if kind in _MATLAB and len(p) > _MFS[kind][1] and not any(p[_MFS[kind][1]:]):
            p = p[:_MFS[kind][1]]  # older MATLAB files pad every parameter list with zeros to the same length
        if kind not in _MFS and kind not in ("constant", "linear", "discretemf"):
            raise ValueError(f"unknown membership function {kind!r} (known: {', '.join(_MFS)}, constant, linear, "
                             "discretemf, function)")
        _, arity, build, _ = _MFS.get(kind, (None, 0, None, None))
        return label, extra.from_numbers("discrete" if kind == "discretemf" else kind, p, build, arity)
    except ValueError as error:
        raise InputError(f"{label}: {error}", source=source, field=where) from None


"""The rest of fuzzylite's terms: S/Z/Pi shapes, cosine, concave, spike, arc, binary, semi-ellipse,
rectangle, sigmoid difference / product, Gaussian product, discrete, constant, and a scaled height.

Formulas as fuzzylite 8 defines them (J. Rada-Vilela, *The FuzzyLite Libraries for Fuzzy Logic
Control*, 2018; every one is checked against pyfuzzylite in ``tests/fll``). Each term is a
:class:`~fuzzynav.fuzzy.membership.MembershipFunction`: ``mf(x)`` vectorised, ``params()`` in
the order of the FLL line. Monotone terms (S, Z, concave, arc) also give ``inverse(y)``, the
abscissa Tsukamoto's method reads (§II.4.3.3).
"""

from __future__ import annotations

import numpy as np

from fuzzynav.fuzzy.membership import Linear, MembershipFunction, _as_float


def _x(x) -> np.ndarray:
    return np.asarray(x, dtype=float)


class _Params(MembershipFunction):
    """A term defined by a fixed tuple of named numbers (``names`` in FLL order)."""

    names: tuple[str, ...] = ()

    def __init__(self, *values):
        if len(values) != len(self.names):
            raise ValueError(f"{self.kind} takes {len(self.names)} parameters ({', '.join(self.names)}), "
                             f"got {len(values)}")
        for name, value in zip(self.names, values):
            setattr(self, name, _as_float(name, value))
        self.check()

    def check(self) -> None:
        """Reject parameters for which the formula is undefined (ValueError)."""

    def params(self) -> tuple[float, ...]:
        return tuple(getattr(self, n) for n in self.names)


class SShape(_Params):
    """S-shape from ``start`` (0) to ``end`` (1): two parabolas meeting at the midpoint (MATLAB smf)."""

    kind, names = "sshape", ("start", "end")

    def __call__(self, x):
        x, s, e = _x(x), self.start, self.end
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(x <= s, 0.0, np.where(x <= 0.5 * (s + e), 2.0 * ((x - s) / (e - s)) ** 2,
                                                  np.where(x < e, 1.0 - 2.0 * ((x - e) / (e - s)) ** 2, 1.0)))

    def inverse(self, y):
        y, s, e = _x(y), self.start, self.end
        return np.where(y <= 0.5, s + (e - s) * np.sqrt(y / 2.0), e - (e - s) * np.sqrt((1.0 - y) / 2.0))


class ZShape(_Params):
    """Z-shape from ``start`` (1) to ``end`` (0), the mirror of :class:`SShape` (MATLAB zmf)."""

    kind, names = "zshape", ("start", "end")

    def __call__(self, x):
        x, s, e = _x(x), self.start, self.end
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(x <= s, 1.0, np.where(x < 0.5 * (s + e), 1.0 - 2.0 * ((x - s) / (e - s)) ** 2,
                                                  np.where(x < e, 2.0 * ((x - e) / (e - s)) ** 2, 0.0)))

    def inverse(self, y):
        y, s, e = _x(y), self.start, self.end
        return np.where(y <= 0.5, e - (e - s) * np.sqrt(y / 2.0), s + (e - s) * np.sqrt((1.0 - y) / 2.0))


class PiShape(_Params):
    """Pi-shape: S-shape up from a to b, Z-shape down from c to d (MATLAB pimf)."""

    kind, names = "pishape", ("a", "b", "c", "d")

    def __call__(self, x):
        return SShape(self.a, self.b)(x) * ZShape(self.c, self.d)(x)


class Cosine(_Params):
    """Raised cosine of ``width`` centred at ``center``: ½(1 + cos(2π(x − c)/w)) on [c − w/2, c + w/2]."""

    kind, names = "cosine", ("center", "width")

    def check(self) -> None:
        if not self.width > 0:
            raise ValueError(f"cosine needs a width > 0, got {self.width}")

    def __call__(self, x):
        x, c, w = _x(x), self.center, self.width
        within = np.isfinite(x) & (x >= c - 0.5 * w) & (x <= c + 0.5 * w)
        with np.errstate(invalid="ignore"):
            return np.where(within, 0.5 * (1.0 + np.cos(2.0 / w * np.pi * (x - c))), 0.0)


class Concave(_Params):
    """Concave: (e − i)/(2e − i − x) rising to 1 at ``end`` (or falling when i > e), 1 beyond."""

    kind, names = "concave", ("inflection", "end")

    def __call__(self, x):
        x, i, e = _x(x), self.inflection, self.end
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where((i <= e) & (x < e), (e - i) / (2.0 * e - i - x),
                            np.where((i >= e) & (x > e), (i - e) / (i - 2.0 * e + x), 1.0))

    def inverse(self, y):
        with np.errstate(divide="ignore"):
            return (self.inflection - self.end) / _x(y) + 2.0 * self.end - self.inflection


class Spike(_Params):
    """Spike: exp(−|10 (x − c) / w|)."""

    kind, names = "spike", ("center", "width")

    def check(self) -> None:
        if self.width == 0:
            raise ValueError("spike needs a width != 0")

    def __call__(self, x):
        with np.errstate(over="ignore", divide="ignore"):  # a width of 1e-320: 1 at the centre, 0 elsewhere
            return np.exp(-10.0 * np.abs(_x(x) - self.center) / abs(self.width))


class Arc(_Params):
    """Quarter circle from ``start`` (0) to ``end`` (1), 1 beyond ``end``."""

    kind, names = "arc", ("start", "end")

    def __call__(self, x):
        x, s, e = _x(x), self.start, self.end
        r = e - s
        on = ((s > e) & (e <= x) & (x <= s)) | ((s < e) & (s <= x) & (x <= e))
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(on, np.sqrt(r * r - (x - e) ** 2) / abs(r), ((s > e) & (x < e)) | ((s < e) & (x > e)))

    def inverse(self, y):
        s, e = self.start, self.end
        r = e - s
        return e + (-1.0 if s < e else 1.0) * np.sqrt(r * r - (_x(y) * r) ** 2)


class Binary(_Params):
    """Binary: 1 from ``start`` on towards ``direction`` (±inf or any number on that side), else 0."""

    kind, names = "binary", ("start", "direction")

    def __call__(self, x):
        x, s, d = _x(x), self.start, self.direction
        return (((d > s) & (x >= s)) | ((d < s) & (x <= s))).astype(float)


class SemiEllipse(_Params):
    """Upper half of the ellipse over [start, end], height 1 at the centre."""

    kind, names = "semiellipse", ("start", "end")

    def __call__(self, x):
        x = _x(x)
        s, e = min(self.start, self.end), max(self.start, self.end)
        r, c = (e - s) / 2.0, (s + e) / 2.0
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where((x >= s) & (x <= e), np.sqrt(r * r - (x - c) ** 2) / r, 0.0)


class Rectangle(_Params):
    """Rectangle: 1 on [start, end], 0 elsewhere."""

    kind, names = "rectangle", ("start", "end")

    def __call__(self, x):
        x = _x(x)
        return ((min(self.start, self.end) <= x) & (x <= max(self.start, self.end))).astype(float)


class SigmoidDifference(_Params):
    """|sig(x; left, rising) − sig(x; right, falling)| (MATLAB dsigmf, parameters reordered)."""

    kind, names = "sigmoiddifference", ("left", "rising", "falling", "right")

    def __call__(self, x):
        return np.abs(_sigmoid(x, self.rising, self.left) - _sigmoid(x, self.falling, self.right))


class SigmoidProduct(_Params):
    """sig(x; left, rising) · sig(x; right, falling) (MATLAB psigmf, parameters reordered)."""

    kind, names = "sigmoidproduct", ("left", "rising", "falling", "right")

    def __call__(self, x):
        return _sigmoid(x, self.rising, self.left) * _sigmoid(x, self.falling, self.right)


def _sigmoid(x, slope: float, inflection: float) -> np.ndarray:
    """1 / (1 + exp(−slope (x − inflection))); slope 0 gives ½ (as fuzzylite, unlike :class:`Sigmoid`)."""
    with np.errstate(over="ignore"):
        return 1.0 / (1.0 + np.exp(-slope * (_x(x) - inflection)))


class GaussianProduct(_Params):
    """Left half of a Gaussian (mean_a, sd_a) up to mean_a, 1 between, right half (mean_b, sd_b) after
    (MATLAB gauss2mf)."""

    kind, names = "gaussianproduct", ("mean_a", "sd_a", "mean_b", "sd_b")

    def check(self) -> None:
        for name in ("sd_a", "sd_b"):  # as a gaussian's sigma: the formula divides by it
            value = getattr(self, name)
            if not 0 < value < np.inf:
                raise ValueError(f"gaussianproduct needs a finite {name} > 0, got {value}")

    def __call__(self, x):
        x = _x(x)
        with np.errstate(over="ignore", divide="ignore"):  # an sd of 1e-300: its square is 0, μ 0 off the mean
            a = np.where(x < self.mean_a, np.exp(-((x - self.mean_a) ** 2) / (2.0 * self.sd_a ** 2)), 1.0)
            b = np.where(x > self.mean_b, np.exp(-((x - self.mean_b) ** 2) / (2.0 * self.sd_b ** 2)), 1.0)
        return a * b


class Constant(_Params):
    """The same degree ``value`` everywhere (fuzzylite's Constant; as a TS conclusion, z = value)."""

    kind, names = "constant", ("value",)

    def __call__(self, x):
        return np.full_like(_x(x), self.value)


class Discrete(MembershipFunction):
    """Piecewise-linear through the points (x_i, y_i), constant beyond the ends (``np.interp``)."""

    kind = "discrete"

    def __init__(self, *xy):
        if len(xy) < 2 or len(xy) % 2:
            raise ValueError(f"discrete takes pairs x y (at least one), got {len(xy)} numbers")
        values = [_as_float(f"xy[{i}]", v) for i, v in enumerate(xy)]
        self.x = np.array(values[0::2])
        self.y = np.array(values[1::2])

    def params(self) -> tuple[float, ...]:
        return tuple(v for pair in zip(self.x.tolist(), self.y.tolist()) for v in pair)

    def __call__(self, x):
        return np.interp(_x(x), self.x, self.y)


class Scaled(MembershipFunction):
    """A term of ``height`` h ≠ 1: h · μ(x) (fuzzylite's optional last parameter)."""

    def __init__(self, term: MembershipFunction, height: float):
        self.term = term
        self.height = _as_float("height", height)
        self.kind = term.kind

    def params(self) -> tuple[float, ...]:
        return (*self.term.params(), self.height)

    def __call__(self, x):
        return self.height * self.term(x)

    def inverse(self, y):
        return self.term.inverse(_x(y) / self.height)

    def __eq__(self, other) -> bool:
        return isinstance(other, Scaled) and self.term == other.term and self.height == other.height

    def __hash__(self) -> int:
        return hash(("Scaled", self.term, self.height))


def from_numbers(kind: str, p: list[float], build, arity: int) -> MembershipFunction:
    """A term from its parameter list as fuzzylite and MATLAB files give it: ``constant`` c,
    ``linear`` c1 … cn c0, ``discrete`` x y pairs (an odd count ends with a height), otherwise
    ``build(p[:arity])`` with an optional last parameter, the height. ValueError if malformed."""
    if kind == "constant":
        if len(p) != 1:
            raise ValueError(f"constant takes 1 parameter, got {len(p)}")
        return Constant(p[0])
    if kind == "linear":
        return Linear(p[:-1], p[-1]) if p else Linear((), 0.0)
    if kind == "discrete":
        height = p[-1] if len(p) % 2 else 1.0
        mf = Discrete(*(p[:-1] if len(p) % 2 else p))
    else:
        if len(p) not in (arity, arity + 1):
            raise ValueError(f"{kind} takes {arity} parameters (+ an optional height), got {len(p)}")
        height = p[arity] if len(p) > arity else 1.0
        mf = build(p[:arity])
    return mf if height == 1.0 else Scaled(mf, height)


EXTRA_KINDS: dict[str, type[MembershipFunction]] = {
    cls.kind: cls for cls in (SShape, ZShape, PiShape, Cosine, Concave, Spike, Arc, Binary, SemiEllipse, Rectangle,
                              SigmoidDifference, SigmoidProduct, GaussianProduct, Constant, Discrete)
}

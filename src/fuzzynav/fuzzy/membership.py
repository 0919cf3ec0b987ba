"""Membership functions (thesis §II.2.2, Figs II.1–II.2; generalized bell eq V.8).

Every function is a small immutable object whose ``__call__`` takes an array of any shape and
returns the membership degrees in [0, 1] with the same shape (NumPy-vectorised). ``params()``
returns the defining numbers in the order of the constructor, which is also the order used by
the JSON/YAML and FLL files.

Piecewise-linear functions (triangle, trapezoid, ramp) also report their ``breakpoints()``: the
fast inference path of :mod:`fuzzynav.fuzzy.fastpath` uses them to interpolate a strong partition
exactly. Linear consequents of first-order Takagi–Sugeno rules are :class:`Linear` terms
(not membership functions of one variable, but terms of an output variable, as in fuzzylite).
"""

from __future__ import annotations

import inspect
import math
from abc import ABC, abstractmethod

import numpy as np


class MembershipFunction(ABC):
    """A fuzzy set on the real line: ``mf(x) -> μ(x)``, vectorised over ``x``."""

    kind: str = ""

    @abstractmethod
    def __call__(self, x):
        """Membership degree of every element of ``x`` (array in, array out)."""

    @abstractmethod
    def params(self) -> tuple[float, ...]:
        """Defining parameters, in constructor order."""

    def breakpoints(self) -> tuple[float, ...] | None:
        """Finite abscissae between which the function is affine, or ``None`` if not piecewise-linear."""
        return None

    def support(self) -> tuple[float, float]:
        """Closed interval outside which μ = 0 (may be infinite)."""
        return (-math.inf, math.inf)

    def __eq__(self, other) -> bool:
        return type(self) is type(other) and self.params() == other.params()

    def __hash__(self) -> int:
        return hash((type(self).__name__, self.params()))

    def __repr__(self) -> str:
        return f"{type(self).__name__}{self.params()!r}"


def _as_float(name: str, value) -> float:
    value = float(value)
    if math.isnan(value):
        raise ValueError(f"{name} is NaN")
    return value


def _finite(name: str, value) -> float:
    """A parameter that places a term (a centre, a coefficient): at ±∞ the term would never fire,
    or answer NaN; only a trapezoid's shoulders may lie at infinity."""
    value = _as_float(name, value)
    if math.isinf(value):
        raise ValueError(f"{name} must be finite, got {value}")
    return value


class Trapezoidal(MembershipFunction):
    """Trapezoid {a, b, c, d}: 0 below a, rising to 1 on [b, c], falling to 0 at d (§II.2.2).

    Open shoulders (as in fuzzylite): ``a = -inf`` gives μ = 1 for every x ≤ c (left shoulder),
    ``d = +inf`` gives μ = 1 for every x ≥ b (right shoulder). A vertical edge (a = b or c = d)
    is allowed: μ = 1 on the edge itself.
    """

    kind = "trapezoid"

    def __init__(self, a: float, b: float, c: float, d: float):
        a, b, c, d = (_as_float(n, v) for n, v in zip("abcd", (a, b, c, d)))
        if not a <= b <= c <= d:
            raise ValueError(f"trapezoid needs a <= b <= c <= d, got {(a, b, c, d)}")
        self.a, self.b, self.c, self.d = a, b, c, d

    def params(self) -> tuple[float, ...]:
        return (self.a, self.b, self.c, self.d)

    def _edges(self) -> tuple[float, float, float, float]:
        """(a, b, c, d) with the open shoulders made explicit as infinite plateaus."""
        a, b, c, d = self.a, self.b, self.c, self.d
        if a == -math.inf:
            b = -math.inf
        if d == math.inf:
            c = math.inf
        return a, b, c, d

    def __call__(self, x):
        x = np.asarray(x, dtype=float)
        a, b, c, d = self._edges()
        mu = np.ones_like(x)
        with np.errstate(over="ignore"):  # an edge of 1e-320 m: a slope of inf, clipped to 1 below
            if b > -math.inf:
                rise = (x - a) / (b - a) if b > a else np.where(x < a, 0.0, 1.0)
                mu = np.minimum(mu, rise)
            if c < math.inf:
                fall = (d - x) / (d - c) if d > c else np.where(x > d, 0.0, 1.0)
                mu = np.minimum(mu, fall)
        return np.clip(mu, 0.0, 1.0)

    def breakpoints(self) -> tuple[float, ...]:
        return tuple(v for v in self._edges() if math.isfinite(v))

    def support(self) -> tuple[float, float]:
        return (self.a, self.d)


class Triangular(Trapezoidal):
    """Triangle {a, b, c}: 0 outside [a, c], peak 1 at b (§II.2.2, Figs IV.5–IV.6).

    ``a = b`` (or ``b = c``) gives a vertical edge; ``a = -inf`` a left shoulder (μ = 1 for
    x ≤ b), ``c = +inf`` a right shoulder (μ = 1 for x ≥ b), as in fuzzylite.
    """

    kind = "triangle"

    def __init__(self, a: float, b: float, c: float):
        a, b, c = (_as_float(n, v) for n, v in zip("abc", (a, b, c)))
        if not a <= b <= c:
            raise ValueError(f"triangle needs a <= b <= c, got {(a, b, c)}")
        super().__init__(a, b, b, c)

    def params(self) -> tuple[float, ...]:
        return (self.a, self.b, self.d)


class Ramp(Trapezoidal):
    """Monotone ramp from 0 at ``start`` to 1 at ``end`` (either order), saturated outside.

    Used as a monotone consequent by Tsukamoto's method (§II.4.3.3); :meth:`inverse` gives the
    abscissa where μ = y.
    """

    kind = "ramp"

    def __init__(self, start: float, end: float):
        start, end = _as_float("start", start), _as_float("end", end)
        if start == end or not (math.isfinite(start) and math.isfinite(end)):
            raise ValueError(f"ramp needs two different finite ends, got {(start, end)}")
        if start < end:
            super().__init__(start, end, math.inf, math.inf)
        else:
            super().__init__(-math.inf, -math.inf, end, start)
        self.start, self.end = start, end

    def params(self) -> tuple[float, ...]:
        return (self.start, self.end)

    def inverse(self, y):
        """x such that μ(x) = y, for y in [0, 1] (Tsukamoto consequent)."""
        return self.start + np.asarray(y, dtype=float) * (self.end - self.start)


class Gaussian(MembershipFunction):
    """Gaussian {σ, m}: exp(−(x − m)² / (2σ²)) (§II.2.2)."""

    kind = "gaussian"

    def __init__(self, sigma: float, mean: float):
        sigma, mean = _as_float("sigma", sigma), _finite("mean", mean)
        if not sigma > 0 or math.isinf(sigma):
            raise ValueError(f"gaussian needs a finite sigma > 0, got {sigma}")
        self.sigma, self.mean = sigma, mean

    def params(self) -> tuple[float, ...]:
        return (self.sigma, self.mean)

    def __call__(self, x):
        with np.errstate(over="ignore"):  # a sigma of 1e-300: z overflows to inf, μ to 0
            z = (np.asarray(x, dtype=float) - self.mean) / self.sigma
            return np.exp(-0.5 * z * z)


class Bell(MembershipFunction):
    """Generalized bell {a, b, c}: 1 / (1 + |(x − c)/a|^(2b)) (eq V.8, ANFIS premise)."""

    kind = "bell"

    def __init__(self, a: float, b: float, c: float):
        a, b, c = _as_float("a", a), _as_float("b", b), _finite("c", c)
        if a == 0 or not math.isfinite(a) or not b > 0 or not math.isfinite(b):
            raise ValueError(f"bell needs a != 0 and b > 0 (finite), got {(a, b, c)}")
        self.a, self.b, self.c = a, b, c

    def params(self) -> tuple[float, ...]:
        return (self.a, self.b, self.c)

    def __call__(self, x):
        with np.errstate(over="ignore"):  # a tiny a or a huge b: z ** 2b overflows to inf, μ to 0
            z = np.abs((np.asarray(x, dtype=float) - self.c) / self.a)
            return 1.0 / (1.0 + z ** (2.0 * self.b))


class Sigmoid(MembershipFunction):
    """Sigmoid {a, c}: 1 / (1 + exp(−a (x − c))) (§II.2.2); monotone, so usable by Tsukamoto."""

    kind = "sigmoid"

    def __init__(self, a: float, c: float):
        a, c = _as_float("a", a), _finite("c", c)
        if a == 0 or not math.isfinite(a):
            raise ValueError(f"sigmoid needs a finite slope a != 0, got {a}")
        self.a, self.c = a, c

    def params(self) -> tuple[float, ...]:
        return (self.a, self.c)

    def __call__(self, x):
        with np.errstate(over="ignore"):  # a slope of 1e308: z overflows to ±inf, clipped
            z = -self.a * (np.asarray(x, dtype=float) - self.c)
        return 1.0 / (1.0 + np.exp(np.clip(z, -700.0, 700.0)))

    def inverse(self, y):
        """x such that μ(x) = y, for y in (0, 1); ±inf at 0 and 1."""
        y = np.asarray(y, dtype=float)
        with np.errstate(divide="ignore"):
            return self.c + (np.log(y) - np.log1p(-y)) / self.a


class Singleton(MembershipFunction):
    """Singleton at ``value``: μ = 1 there, 0 elsewhere — the TS0 conclusions (IV.4, Figs IV.7–IV.8)."""

    kind = "singleton"

    def __init__(self, value: float):
        self.value = _as_float("value", value)
        if math.isinf(self.value):
            raise ValueError("singleton value must be finite")

    def params(self) -> tuple[float, ...]:
        return (self.value,)

    def __call__(self, x):
        return (np.asarray(x, dtype=float) == self.value).astype(float)

    def support(self) -> tuple[float, float]:
        return (self.value, self.value)


class Linear(MembershipFunction):
    """Affine conclusion of a first-order Takagi–Sugeno rule: y = Σ c_j x_j + r (§II.4.3.2).

    A term of an output variable (as in fuzzylite), evaluated on the *input vector*, not on the
    output axis: ``conclusion(X)`` with ``X`` of shape (N, n_inputs) returns (N,).
    """

    kind = "linear"

    def __init__(self, coefficients, constant: float = 0.0):
        self.coefficients = tuple(_finite(f"coefficients[{i}]", c) for i, c in enumerate(coefficients))
        self.constant = _finite("constant", constant)

    def params(self) -> tuple[float, ...]:
        return (*self.coefficients, self.constant)

    def __call__(self, x):
        x = np.asarray(x, dtype=float)
        if x.shape[-1] != len(self.coefficients):
            raise ValueError(f"linear term has {len(self.coefficients)} coefficients, input has {x.shape[-1]} columns")
        return x @ np.asarray(self.coefficients) + self.constant


# name -> class, for the file formats
KINDS: dict[str, type[MembershipFunction]] = {
    cls.kind: cls for cls in (Triangular, Trapezoidal, Ramp, Gaussian, Bell, Sigmoid, Singleton, Linear)
}


def make(kind: str, params) -> MembershipFunction:
    """Build a membership function from its ``kind`` name and parameter list (file formats)."""
    try:
        cls = KINDS[kind]
    except KeyError:
        raise ValueError(f"unknown membership function {kind!r} (known: {', '.join(KINDS)})") from None
    params = [float(p) for p in params]
    if cls is Linear:
        return Linear(params[:-1], params[-1]) if params else Linear((), 0.0)
    names = list(inspect.signature(cls).parameters)
    try:
        inspect.signature(cls).bind(*params)
    except TypeError:
        raise ValueError(f"a {kind} takes {len(names)} parameter{'s' * (len(names) != 1)} ({', '.join(names)}), "
                         f"got {len(params)}") from None
    return cls(*params)

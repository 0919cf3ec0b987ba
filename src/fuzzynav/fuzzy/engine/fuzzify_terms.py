"""Terms and hedges over a column of values, compiled: the fuzzification of :mod:`fuzzynav.fuzzy.engine.fused_kernel`.

:func:`term_column` evaluates a term given by its code (:func:`pack_term`) on every value of a
column, one loop per term type (so each loop is a plain sequence of arithmetic that the compiler
vectorises), with the formulas, branches and NaN behaviour of the NumPy ``__call__`` of
:mod:`fuzzynav.fuzzy.membership` and :mod:`fuzzynav.fuzzy.terms` (fuzzylite 8's definitions):
each ``np.where`` is the same test here, so a NaN or an infinite input takes the same branch.
:func:`hedge_column` is :data:`fuzzynav.fuzzy.operators.HEDGES`.

Gaussian, Bell and Sigmoid terms take ``exp`` and ``pow`` = exp(b log a) from
:mod:`.vmath`, which the compiler inlines and vectorises in the term's loop (the C library's ``exp``, called
value by value, is several times slower; NumPy's SIMD ``exp`` works only outside the kernel):
within a few ulp of NumPy's (see :mod:`.vmath`), not its very bits. A Bell whose power 2b is 2, 4
or 8 (MATLAB's default b = 2 among them) takes no ``exp`` or ``log``: its power is one to three
squarings, within b ulp of NumPy's ``pow``. The rarer terms built on ``exp``
(Spike, the sigmoid and Gaussian products and difference) have no code here: the engine
fuzzifies them in NumPy before the kernel, as ``Function`` and ``Linear`` premises.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.fuzzy import terms as extra
from fuzzynav.fuzzy.engine.norms import nan_min
from fuzzynav.fuzzy.engine.quotient import divided, usable_reciprocal
from fuzzynav.fuzzy.engine.vmath import exp_of, log_of
from fuzzynav.fuzzy.membership import Bell, Gaussian, Sigmoid, Singleton, Trapezoidal
from fuzzynav.jit import jit

HEDGE_CODES = {"not": 0, "very": 1, "somewhat": 2, "extremely": 3, "seldom": 4, "any": 5}
(TRAPEZOID, SINGLETON, CONSTANT, SSHAPE, ZSHAPE, PISHAPE, COSINE, CONCAVE, ARC, BINARY, SEMIELLIPSE, RECTANGLE,
 DISCRETE, GAUSSIAN, BELL, SIGMOID) = range(16)
_CODES = {Trapezoidal: TRAPEZOID, Singleton: SINGLETON, extra.Constant: CONSTANT, extra.SShape: SSHAPE,
          extra.ZShape: ZSHAPE, extra.PiShape: PISHAPE, extra.Cosine: COSINE, extra.Concave: CONCAVE,
          extra.Arc: ARC, extra.Binary: BINARY, extra.SemiEllipse: SEMIELLIPSE, extra.Rectangle: RECTANGLE,
          extra.Discrete: DISCRETE, Gaussian: GAUSSIAN, Bell: BELL, Sigmoid: SIGMOID}


def pack_term(mf) -> tuple[int, tuple, float] | None:
    """(code, parameters, height) of a term, or None when NumPy evaluates it. Triangles and ramps
    are trapezoids with their open shoulders made explicit; a discrete term's parameters are its
    abscissae then its ordinates."""
    height = 1.0
    if isinstance(mf, extra.Scaled):
        mf, height = mf.term, mf.height
    code = next((c for cls, c in _CODES.items() if isinstance(mf, cls)), None)
    if code is None:
        return None
    params = mf._edges() if code == TRAPEZOID else (*mf.x.tolist(), *mf.y.tolist()) if code == DISCRETE else mf.params()
    return code, tuple(float(p) for p in params), float(height)


@jit
def _trapezoid(x, a, b, c, d):
    mu = 1.0
    if b > -math.inf:
        mu = nan_min(mu, (x - a) / (b - a) if b > a else (0.0 if x < a else 1.0))
    if c < math.inf:
        mu = nan_min(mu, (d - x) / (d - c) if d > c else (0.0 if x > d else 1.0))
    return 0.0 if mu < 0.0 else (1.0 if mu > 1.0 else mu)  # np.clip: NaN stays


@jit
def _sloped(a, b, c, d):
    """Whether the trapezoid (a, b, c, d) has two finite sloped sides: a < b ≤ c < d, b − a and d − c finite."""
    return a < b <= c < d and math.isfinite(b - a) and math.isfinite(d - c)


@jit
def _sloped_trapezoid(x, a, b, c, d, out):
    """:func:`_trapezoid` of a :func:`_sloped` trapezoid with one division a value instead of two:
    below b the rising side (x − a) / (b − a) is at most 1 and the falling one (d − x) / (d − c)
    at least 1 (rounding is monotone), so the minimum is the rising side; from b on the rising
    side is at least 1 and the clipped minimum is the falling side's, clipped. The same bits,
    NaN (which takes the falling side) and infinities included."""
    for k in range(x.shape[0]):
        v = x[k]
        rising = v < b
        mu = (v - a if rising else d - v) / (b - a if rising else d - c)
        out[k] = 0.0 if mu < 0.0 else (1.0 if mu > 1.0 else mu)


@jit
def _sshape(x, s, e):
    """fuzzylite's S-shape: 0 to s, 2 ((x − s) / (e − s))² to the midpoint, 1 − 2 ((x − e) / (e − s))²
    to e, then 1 (NaN: 1); the two halves' numerators selected before one division."""
    low = x <= 0.5 * (s + e)
    t = (x - (s if low else e)) / (e - s)
    q = 2.0 * (t * t)
    mu = q if low else 1.0 - q
    mu = mu if x < e else 1.0
    return 0.0 if x <= s else mu  # three selects in a row: LLVM vectorises them, not the nested ones


@jit
def _zshape(x, s, e):
    """fuzzylite's Z-shape: 1 to s, 1 − 2 ((x − s) / (e − s))² below the midpoint, 2 ((x − e) / (e − s))²
    below e, then 0 (NaN: 0); one division, as :func:`_sshape`."""
    low = x < 0.5 * (s + e)
    t = (x - (s if low else e)) / (e - s)
    q = 2.0 * (t * t)
    mu = 1.0 - q if low else q
    mu = mu if x < e else 0.0
    return 1.0 if x <= s else mu  # as in _sshape


@jit
def _arc(x, s, e):
    r = e - s
    if (s > e and e <= x and x <= s) or (s < e and s <= x and x <= e):
        d = x - e
        return np.sqrt(r * r - d * d) / abs(r)
    return 1.0 if (s > e and x < e) or (s < e and x > e) else 0.0


@jit
def _concave(x, i, e):
    if i <= e and x < e:
        return (e - i) / (2.0 * e - i - x)
    if i >= e and x > e:
        return (i - e) / (i - 2.0 * e + x)
    return 1.0


@jit
def _semiellipse(x, s, e):
    r, c = (e - s) / 2.0, (s + e) / 2.0
    if x >= s and x <= e:
        d = x - c
        return np.sqrt(r * r - d * d) / r
    return 0.0


@jit
def _squared_bell(p, x, out, divide):
    """A Bell of power 2b = 2, 4 or 8: 1 / (1 + z^2b), z = (x − c) / a by a quotient from 1 / a
    (:mod:`.quotient`) unless ``divide``, its power by one to three squarings; returns whether
    every value is exact. (Gaussians and other Bells keep the division: their exp and log hide it.)"""
    width, power, centre = p[0], 2.0 * p[1], p[2]
    y, inexact = 1.0 / width, 0
    for k in range(x.shape[0]):
        z, exact = divided(x[k] - centre, width, y, divide)
        q = z * z
        q = q * q if power >= 4.0 else q
        q = q * q if power == 8.0 else q
        out[k] = 1.0 / (1.0 + q)
        inexact += 0 if exact else 1
    return inexact == 0


@jit
def _exp_term(code, p, x, out):
    """Gaussian (σ, m): exp(−½ z z), z = (x − m) / σ; Bell (a, b, c): 1 / (1 + |(x − c) / a|^(2b));
    Sigmoid (a, c): 1 / (1 + exp(clip(−a (x − c), ±700))) — the NumPy formulas of
    :mod:`fuzzynav.fuzzy.membership`, operation for operation but for exp and log (and a Bell's
    power 2b = 2, 4 or 8, by squarings: :func:`_squared_bell`), each in one loop that the compiler
    vectorises (:mod:`.vmath`)."""
    n = x.shape[0]
    if code == GAUSSIAN:
        sigma, mean = p[0], p[1]
        for k in range(n):
            z = (x[k] - mean) / sigma
            out[k] = exp_of(-0.5 * z * z)
    elif code == BELL:
        width, power, centre = p[0], 2.0 * p[1], p[2]
        if power == 2.0 or power == 4.0 or power == 8.0:
            if not (usable_reciprocal(width) and _squared_bell(p, x, out, False)):
                _squared_bell(p, x, out, True)
        else:  # two loops, the power's exponent stored between: faster than one (README)
            for k in range(n):
                out[k] = power * log_of(abs((x[k] - centre) / width))
            for k in range(n):
                out[k] = 1.0 / (1.0 + exp_of(out[k]))
    else:
        slope, inflection = -p[0], p[1]
        for k in range(n):
            z = slope * (x[k] - inflection)
            out[k] = 1.0 / (1.0 + exp_of(700.0 if z > 700.0 else (-700.0 if z < -700.0 else z)))


@jit
def term_column(code, params, first, end, height, x, out):
    """``out[k]`` = height × the term ``code`` with parameters ``params[first:end]`` at ``x[k]``."""
    p = params[first:end]
    n = x.shape[0]
    if code == TRAPEZOID:
        if _sloped(p[0], p[1], p[2], p[3]):
            _sloped_trapezoid(x, p[0], p[1], p[2], p[3], out)
        else:
            for k in range(n):
                out[k] = _trapezoid(x[k], p[0], p[1], p[2], p[3])
    elif code == SINGLETON:
        for k in range(n):
            out[k] = 1.0 if x[k] == p[0] else 0.0
    elif code == CONSTANT:
        out[:] = p[0]
    elif code == SSHAPE:
        for k in range(n):
            out[k] = _sshape(x[k], p[0], p[1])
    elif code == ZSHAPE:
        for k in range(n):
            out[k] = _zshape(x[k], p[0], p[1])
    elif code == PISHAPE:
        for k in range(n):
            out[k] = _sshape(x[k], p[0], p[1]) * _zshape(x[k], p[2], p[3])
    elif code == COSINE:
        c, w = p[0], p[1]
        for k in range(n):
            on = math.isfinite(x[k]) and x[k] >= c - 0.5 * w and x[k] <= c + 0.5 * w
            out[k] = 0.5 * (1.0 + np.cos(2.0 / w * np.pi * (x[k] - c))) if on else 0.0
    elif code == CONCAVE:
        for k in range(n):
            out[k] = _concave(x[k], p[0], p[1])
    elif code == ARC:
        for k in range(n):
            out[k] = _arc(x[k], p[0], p[1])
    elif code == BINARY:
        s, d = p[0], p[1]
        for k in range(n):
            out[k] = 1.0 if (d > s and x[k] >= s) or (d < s and x[k] <= s) else 0.0
    elif code == SEMIELLIPSE:
        s, e = min(p[0], p[1]), max(p[0], p[1])
        for k in range(n):
            out[k] = _semiellipse(x[k], s, e)
    elif code == RECTANGLE:
        s, e = min(p[0], p[1]), max(p[0], p[1])
        for k in range(n):
            out[k] = 1.0 if s <= x[k] and x[k] <= e else 0.0
    elif code == DISCRETE:
        half = p.shape[0] // 2
        out[:] = np.interp(x, p[:half], p[half:])
    else:
        _exp_term(code, p, x, out)
    if height != 1.0:
        for k in range(n):
            out[k] = height * out[k]


@jit
def hedge_column(code, d):
    """In place: the hedge ``code`` (:data:`HEDGE_CODES`) of every degree of ``d``."""
    n = d.shape[0]
    if code == 0:
        for k in range(n):
            d[k] = 1.0 - d[k]
    elif code == 1:
        for k in range(n):
            d[k] = d[k] * d[k]
    elif code == 2:
        for k in range(n):
            d[k] = np.sqrt(d[k])
    elif code == 3:
        for k in range(n):
            v = d[k]
            d[k] = 2.0 * v * v if v <= 0.5 else 1.0 - 2.0 * ((1.0 - v) * (1.0 - v))
    elif code == 4:
        for k in range(n):
            v = d[k]
            d[k] = np.sqrt(0.5 * v) if v <= 0.5 else 1.0 - np.sqrt(0.5 * (1.0 - v))
    else:
        d[:] = 1.0

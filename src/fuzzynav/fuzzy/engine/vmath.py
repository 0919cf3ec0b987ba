"""``exp`` and ``log`` of one value, written so that the compiler vectorises the loops that call them.

A compiled loop that calls ``math.exp`` calls the C library once per value, several times slower
than NumPy's own ``exp`` (SIMD instructions), which works only on a whole array, outside the
kernel (README, "Speed on fuzzylite's examples"). :func:`exp_of` and :func:`log_of` are plain
arithmetic without branches (selects) or calls, the bits of a double read and written by
:func:`as_bits` / :func:`from_bits` (one LLVM ``bitcast`` each), so LLVM inlines them and
vectorises any loop over them (:mod:`.fuzzify_terms` fuses a term's whole formula into one loop):

- :func:`exp_of` — Cody & Waite's range reduction x = k ln 2 + r, |r| ≤ ln 2 / 2 (ln 2 split
  in two parts so that k ln 2 is exact), exp(r) by a minimax polynomial of degree 11, and 2ᵏ
  applied as two powers of two built from exponent bits (so that gradual underflow and overflow
  to inf round once, as the C library does). NaN stays NaN, exp(inf) = inf, exp(−inf) = 0.
- :func:`log_of` — fdlibm's ``e_log.c`` (Sun Microsystems, 1993): x = 2ᵏ (1 + f) with
  1 + f in [√2/2, √2), log(1 + f) = f − (f²/2 − s (f²/2 + R(s²))), s = f / (2 + f), R its minimax
  polynomial; subnormals are scaled by 2⁵⁴ first. log(0) = −inf, log(x < 0) = NaN, log(inf) = inf.

Both are within 1 ulp of NumPy's (tested on millions of values, edge cases included, in
``tests/fuzzy/test_vmath.py``). A power aᵇ (a ≥ 0) is ``exp(b log a)``: its relative error grows
with v = b ln a (up to ~2 |v| ulp), as every power computed this way without extra precision.
The polynomials may use fused multiply-adds (:func:`fuzzynav.jit.jit`), so the last bit can
differ between processors.
"""

from __future__ import annotations

import numpy as np
from numba import types
from numba.extending import intrinsic, overload

from fuzzynav.jit import jit

_LOG2E = 1.4426950408889634
_LN2_HI = 6.93147180369123816490e-01  # ln 2 = _LN2_HI + _LN2_LO, _LN2_HI with 21 trailing zero bits
_LN2_LO = 1.90821492927058770002e-10
_SHIFT = 6755399441055744.0  # 1.5 × 2⁵²: t + _SHIFT rounds t to an integer held in the low bits
_SHIFT_BITS = 0x4338000000000000  # the bits of _SHIFT
_EXP_POLY = (2.510820016049567e-08, 2.7632597159522586e-07, 2.755724462593623e-06, 2.480148555324402e-05,
             0.0001984126988822903, 0.0013888888952322306, 0.008333333333319837, 0.04166666666648758,
             0.16666666666666677, 0.5000000000000019, 1.0, 1.0)  # highest degree first
_LG = (6.666666666666735130e-01, 3.999999999940941908e-01, 2.857142874366239149e-01, 2.222219843214978396e-01,
       1.818357216161805012e-01, 1.531383769920937332e-01, 1.479819860511658591e-01)  # fdlibm's Lg1..Lg7
_TWO54 = 18014398509481984.0
_TINY = 2.2250738585072014e-308  # the smallest normal double
_SQRT2_BITS = 0x3FF6A09E667F3BCD  # the bits of √2
_MANTISSA, _ONE_BITS = 0x000FFFFFFFFFFFFF, 0x3FF0000000000000


def as_bits(x):
    """The bits of the double x as an int64 (compiled: one LLVM ``bitcast``, no memory, vectorisable;
    as plain Python under ``NUMBA_DISABLE_JIT=1``: a NumPy view)."""
    return int(np.float64(x).view(np.int64))


def from_bits(i):
    """The double whose bits are the int64 i (as :func:`as_bits`; i wraps around as an int64 does)."""
    return float(np.int64((i + 2 ** 63) % 2 ** 64 - 2 ** 63).view(np.float64))


@intrinsic
def _bitcast(typingctx, value, to):
    """``value`` reinterpreted as the type ``to`` (of the same size)."""
    target = to.instance_type

    def codegen(context, builder, signature, args):
        return builder.bitcast(args[0], context.get_value_type(target))
    return target(value, to), codegen


@overload(as_bits)
def _as_bits_compiled(x):
    return lambda x: _bitcast(x, types.int64)


@overload(from_bits)
def _from_bits_compiled(i):
    return lambda i: _bitcast(i, types.float64)


@jit(fastmath=("contract",))
def _exp_r(r):
    """exp(r) for |r| ≤ ln 2 / 2: a minimax polynomial of degree 11 (Remez, relative error
    1.4e-17 with these double coefficients), Horner's scheme."""
    c = _EXP_POLY
    p = c[0]
    for j in range(1, 12):
        p = p * r + c[j]
    return p


@jit(fastmath=("contract",))
def exp_of(x):
    """exp(x): t = x log₂e + _SHIFT holds k = round(x log₂e) in its low bits; exp(r) × 2^h × 2^(k − h),
    h = floor(k / 2), both powers normal (x is clamped to [−746, 710] first: beyond, 0 or inf all
    the same; NaN passes the clamp and the polynomial)."""
    y = 710.0 if x > 710.0 else (-746.0 if x < -746.0 else x)
    t = y * _LOG2E + _SHIFT
    k = t - _SHIFT
    p = _exp_r((y - k * _LN2_HI) - k * _LN2_LO)
    i = as_bits(t) - _SHIFT_BITS
    h = i >> 1
    return p * from_bits((h + 1023) << 52) * from_bits((i - h + 1023) << 52)


@jit(fastmath=("contract",))
def log_of(x):
    """log(x): x = 2^e m, m in [√2/2, √2) from the bits (subnormals scaled by 2^54 first, e by −54),
    then fdlibm's polynomial in s = f / (2 + f), f = m − 1; the special values selected last."""
    tiny = x < _TINY
    b = as_bits(x * _TWO54 if tiny else x)
    high = (b & _MANTISSA) | _ONE_BITS > _SQRT2_BITS  # 1 + f in [√2, 2): halved, e + 1
    e = float(((b >> 52) & 0x7FF) - (1022 if high else 1023) - (54 if tiny else 0))
    f = from_bits((b & _MANTISSA) | (_ONE_BITS - (1 << 52) if high else _ONE_BITS)) - 1.0
    lg = _LG
    s = f / (2.0 + f)
    z = s * s
    w = z * z
    r = w * (lg[1] + w * (lg[3] + w * lg[5])) + z * (lg[0] + w * (lg[2] + w * (lg[4] + w * lg[6])))
    half_f2 = 0.5 * f * f
    y = e * _LN2_HI - ((half_f2 - (s * (half_f2 + r) + e * _LN2_LO)) - f)
    normal = x > 0.0 and x < np.inf
    return y if normal else (x if x != x or x > 0.0 else (-np.inf if x == 0.0 else np.nan))


@jit
def exp_column(x, out):
    """``out[k]`` = exp(``x[k]``) (``out`` may be ``x``)."""
    for k in range(x.shape[0]):
        out[k] = exp_of(x[k])


@jit
def log_column(x, out):
    """``out[k]`` = log(``x[k]``) (``out`` may be ``x``)."""
    for k in range(x.shape[0]):
        out[k] = log_of(x[k])

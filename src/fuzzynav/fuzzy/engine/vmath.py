"""``exp`` and ``log`` over a column of values, in loops the compiler vectorises.

A compiled loop that calls ``math.exp`` calls the C library once per value, several times slower
than NumPy's own ``exp`` (SIMD instructions), which works only on a whole array, outside the
kernel (README, "Speed on fuzzylite's examples"). These are
written as plain arithmetic on arrays, so LLVM vectorises them inside the kernel
(:mod:`.term_columns`), with the bits of a double handled through an ``int64`` view of a scratch
array (no scalar bit casts, no branches in the loops):

- :func:`exp_column` — Cody & Waite's range reduction x = k ln 2 + r, |r| ≤ ln 2 / 2 (ln 2 split
  in two parts so that k ln 2 is exact), exp(r) by a minimax polynomial of degree 11, and 2ᵏ
  applied as two powers of two built from exponent bits (so that gradual underflow and overflow
  to inf round once, as the C library does). NaN stays NaN, exp(inf) = inf, exp(−inf) = 0.
- :func:`log_column` — fdlibm's ``e_log.c`` (Sun Microsystems, 1993): x = 2ᵏ (1 + f) with
  1 + f in [√2/2, √2), log(1 + f) = f − (f²/2 − s (f²/2 + R(s²))), s = f / (2 + f), R its minimax
  polynomial; subnormals are scaled by 2⁵⁴ first. log(0) = −inf, log(x < 0) = NaN, log(inf) = inf.

Both are within 1 ulp of NumPy's (tested on millions of values, edge cases included, in
``tests/fuzzy/test_vmath.py``). A power aᵇ (a ≥ 0) is ``exp(b log a)``: its relative error grows
with v = b ln a (up to ~2 |v| ulp), as every power computed this way without extra precision.
The polynomial loops may use fused multiply-adds (:func:`fuzzynav.jit.jit`), so the last bit can
differ between processors.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.jit import jit

BLOCK = 256  # values per pass through the scratch arrays (they stay in L1 cache)
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
def _reduce(x, p, t):
    """exp's range reduction: ``t`` = x log₂e rounded to an integer k plus _SHIFT, ``p`` = exp(r)."""
    for k in range(x.shape[0]):
        y = x[k]
        y = 710.0 if y > 710.0 else (-746.0 if y < -746.0 else y)  # beyond: inf or 0 all the same
        tk = y * _LOG2E + _SHIFT
        kf = tk - _SHIFT
        p[k] = _exp_r((y - kf * _LN2_HI) - kf * _LN2_LO)
        t[k] = tk


@jit
def _powers_of_two(bits, second):
    """From the bits of t (k + _SHIFT), k in [-1076, 1024]: the bits of 2^h and 2^(k - h),
    h = floor(k / 2), both normal."""
    for k in range(bits.shape[0]):
        i = bits[k] - _SHIFT_BITS
        h = i >> 1
        bits[k] = (h + 1023) << 52
        second[k] = (i - h + 1023) << 52


@jit
def _scale(p, a, b, out):
    for k in range(p.shape[0]):
        out[k] = p[k] * a[k] * b[k]  # NaN: the polynomial already is


@jit
def exp_column(x, out):
    """``out[k]`` = exp(``x[k]``) (``out`` may be ``x``). Each pass its own function over whole
    arrays, reading and writing different ones: so each loop vectorises (the same loops written
    inline did not)."""
    scratch = np.empty(3 * BLOCK)
    p, t, second = scratch[:BLOCK], scratch[BLOCK:2 * BLOCK], scratch[2 * BLOCK:]
    for lo in range(0, x.shape[0], BLOCK):
        hi = min(x.shape[0], lo + BLOCK)
        size = hi - lo
        _reduce(x[lo:hi], p[:size], t[:size])
        _powers_of_two(t[:size].view(np.int64), second[:size].view(np.int64))
        _scale(p[:size], t[:size], second[:size], out[lo:hi])


@jit
def _split(x, m, e):
    """x = 2^e m, m in [√2/2, √2) (subnormals scaled by 2^54 first, e by -54); any m, e elsewhere."""
    bits = m.view(np.int64)
    for k in range(x.shape[0]):
        v = x[k]
        m[k] = v * _TWO54 if v < _TINY else v
    for k in range(x.shape[0]):
        b = bits[k]
        high = (b & _MANTISSA) | _ONE_BITS > _SQRT2_BITS  # 1 + f in [√2, 2): halved, e + 1
        e[k] = ((b >> 52) & 0x7FF) - (1022 if high else 1023) - (54 if x[k] < _TINY else 0)
        bits[k] = (b & _MANTISSA) | (_ONE_BITS - (1 << 52) if high else _ONE_BITS)


@jit(fastmath=("contract",))
def _log_of_split(x, m, e, out):
    lg = _LG
    for k in range(x.shape[0]):
        v, dk = x[k], e[k]
        f = m[k] - 1.0
        s = f / (2.0 + f)
        z = s * s
        w = z * z
        r = w * (lg[1] + w * (lg[3] + w * lg[5])) + z * (lg[0] + w * (lg[2] + w * (lg[4] + w * lg[6])))
        half_f2 = 0.5 * f * f
        y = dk * _LN2_HI - ((half_f2 - (s * (half_f2 + r) + dk * _LN2_LO)) - f)
        normal = v > 0.0 and v < np.inf
        out[k] = y if normal else (v if v != v or v > 0.0 else (-np.inf if v == 0.0 else np.nan))


@jit
def log_column(x, out):
    """``out[k]`` = log(``x[k]``) (``out`` may be ``x``; passes as in :func:`exp_column`)."""
    scratch = np.empty(3 * BLOCK)
    v, m, e = scratch[:BLOCK], scratch[BLOCK:2 * BLOCK], scratch[2 * BLOCK:]
    for lo in range(0, x.shape[0], BLOCK):
        hi = min(x.shape[0], lo + BLOCK)
        size = hi - lo
        v[:size] = x[lo:hi]  # the last pass writes out: it must not read x, which out may be
        _split(v[:size], m[:size], e[:size])
        _log_of_split(v[:size], m[:size], e[:size], out[lo:hi])

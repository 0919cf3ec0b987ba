"""Σ μ and Σ μ x over eight lanes, written as LLVM vector instructions.

The centroid's sums (:func:`fuzzynav.fuzzy.engine.sampled_defuzzify.centroid_sums`) keep eight running sums,
sample k in sum k mod 8, added pairwise at the end: eight independent additions a step instead of
one chain. numba leaves LLVM's SLP vectoriser off, and the loop vectoriser may not reorder a sum,
so written as plain Python those eight sums stay scalar. :func:`lane_sums` compiles to the very
same operations as two 4-wide vectors per sum (<4 x double> loads, ``fadd``, ``fmul``; no fused
multiply-add, no reordering), so the same bits, several times faster; under
``NUMBA_DISABLE_JIT=1`` it runs them as NumPy.
"""

from __future__ import annotations

import numpy as np
from llvmlite import ir
from numba import types
from numba.core import cgutils
from numba.extending import intrinsic, overload


def lane_sums(mu, x, first, end):
    """(Σ μ, Σ μ x) over the samples [first, end) of two C-contiguous float64 arrays, ``first``
    and ``end`` multiples of 8 (both arrays at least ``end`` long): sample k in lane k mod 8, the
    lanes added pairwise. Compiled: :func:`_lane_sums`; this plain Python (``NUMBA_DISABLE_JIT=1``)
    does the same additions in the same order with NumPy."""
    t, m = np.zeros(8), np.zeros(8)
    for k in range(first, end, 8):
        t += mu[k:k + 8]
        m += mu[k:k + 8] * x[k:k + 8]
    return (((t[0] + t[1]) + (t[2] + t[3])) + ((t[4] + t[5]) + (t[6] + t[7])),
            ((m[0] + m[1]) + (m[2] + m[3])) + ((m[4] + m[5]) + (m[6] + m[7])))


@overload(lane_sums)
def _lane_sums_compiled(mu, x, first, end):
    return lambda mu, x, first, end: _lane_sums(mu, x, first, end)


def _lane_total(builder, low, high, lane):
    """((l0 + l1) + (l2 + l3)) + ((l4 + l5) + (l6 + l7)) of the eight lanes of two 4-vectors."""
    v = [builder.extract_element(part, lane(q)) for part in (low, high) for q in range(4)]
    return builder.fadd(builder.fadd(builder.fadd(v[0], v[1]), builder.fadd(v[2], v[3])),
                        builder.fadd(builder.fadd(v[4], v[5]), builder.fadd(v[6], v[7])))


@intrinsic
def _lane_sums(typingctx, mu, x, first, end):
    """:func:`lane_sums` as LLVM vector instructions."""
    if not all(isinstance(a, types.Array) and a.layout == "C" and a.dtype == types.float64 for a in (mu, x)):
        return None

    def codegen(context, builder, signature, args):
        vector = ir.VectorType(ir.DoubleType(), 4)
        index = args[2].type
        data = [context.make_array(t)(context, builder, a).data for t, a in zip(signature.args[:2], args[:2])]
        sums = [cgutils.alloca_once_value(builder, ir.Constant(vector, [0.0] * 4)) for _ in range(4)]
        steps = builder.sdiv(builder.sub(args[3], args[2]), ir.Constant(index, 8))
        with cgutils.for_range(builder, steps) as loop:
            k = builder.add(args[2], builder.mul(loop.index, ir.Constant(index, 8)))
            for half in (0, 1):  # samples k..k+3 in sums[0] and sums[2], k+4..k+7 in sums[1] and sums[3]
                i = builder.add(k, ir.Constant(index, 4 * half))
                m, at = (builder.load(builder.gep(d, [i], source_etype=ir.DoubleType()), align=8, typ=vector)
                         for d in data)
                builder.store(builder.fadd(builder.load(sums[half], typ=vector), m), sums[half])
                builder.store(builder.fadd(builder.load(sums[2 + half], typ=vector), builder.fmul(m, at)),
                              sums[2 + half])
        lane = lambda q: ir.Constant(ir.IntType(32), q)  # noqa: E731
        loaded = [builder.load(s, typ=vector) for s in sums]
        totals = [_lane_total(builder, loaded[0], loaded[1], lane), _lane_total(builder, loaded[2], loaded[3], lane)]
        return context.make_tuple(builder, signature.return_type, totals)

    return types.UniTuple(types.float64, 2)(mu, x, types.intp, types.intp), codegen

"""The bits of n / d by multiplications, for loops that divide many values by one denominator.

A division is the slowest arithmetic instruction (a 4-wide ``vdivpd`` takes several times the
cycles of a fused multiply-add). A Bell of power 2, 4 or 8 (:mod:`.fuzzify_terms`) divides every
value by its width and otherwise only squares and adds, so its loop is bound by the divider; in
loops whose other work hides the division (Gaussians and other Bells, with their exp and log;
trapezoids, with their selects), the extra operations cost more than they save, and those divide.
:func:`quotient` computes n / d from the reciprocal y = 1 / d (divided once, outside the loop)
by Markstein's correction (P. Markstein, "Computation of elementary functions on the IBM RISC
System/6000 processor", IBM J. Res. Dev. 34(1), 1990; J.-M. Muller et al., *Handbook of
Floating-Point Arithmetic*, 2018): q = n y, r = n − d q (exact with a fused
multiply-add), q + r y rounded once — the correctly rounded n / d, that is the very bits of the
division, when y is the correctly rounded reciprocal and nothing is near underflow or overflow.
:func:`quotient` also says whether that holds (every operand and result zero or of magnitude
within [2⁻⁹⁶⁹, 2¹⁰⁰⁰]); where it does not (NaN, infinities, values within 10⁻²⁹² of an edge)
the caller divides (``tests/fuzzy/test_quotient.py`` compares the bits with the division's on
millions of quotients, denominators of every magnitude and edge cases included).

Compiled, :func:`fma` is LLVM's ``llvm.fma.f64`` (one instruction where the processor has FMA,
a correctly rounded library call where it has not); under ``NUMBA_DISABLE_JIT=1`` :func:`quotient`
is the division itself and :func:`fma` is computed exactly with fractions.
"""

from __future__ import annotations

import math
from fractions import Fraction

from llvmlite import ir
from numba import types
from numba.extending import intrinsic, overload

from fuzzynav.jit import jit

SAFE_LOW, SAFE_HIGH = 2.0 ** -969, 2.0 ** 1000  # magnitudes between which the correction is exact
NORMAL = 2.2250738585072014e-308  # the smallest normal double


def fma(a, b, c):
    """a × b + c rounded once (finite operands; plain Python: exactly, with fractions)."""
    return float(Fraction(a) * Fraction(b) + Fraction(c))


@intrinsic
def _fma(typingctx, a, b, c):
    """``llvm.fma.f64``."""
    if not all(isinstance(t, types.Float) for t in (a, b, c)):
        return None

    def codegen(context, builder, signature, args):
        double = ir.DoubleType()
        function = builder.module.declare_intrinsic("llvm.fma", [double], ir.FunctionType(double, [double] * 3))
        return builder.call(function, [builder.fpext(v, double) if v.type != double else v for v in args])
    return types.float64(types.float64, types.float64, types.float64), codegen


@overload(fma)
def _fma_compiled(a, b, c):
    return lambda a, b, c: _fma(a, b, c)


@jit
def usable_reciprocal(d) -> bool:
    """Whether 1 / d is a normal, finite double: the condition on the denominator of :func:`quotient`."""
    if d == 0.0 or d != d:
        return False
    y = abs(1.0 / d)
    return NORMAL <= y < math.inf


def quotient(n, d, y):
    """(n / d, True): plain Python divides (module docstring)."""
    return n / d, True


@overload(quotient)
def _quotient_compiled(n, d, y):
    def compute(n, d, y):
        """(q, exact): q = n / d by Markstein's correction from y = 1 / d (n y itself where n is
        ±0: its sign), and whether q has the division's bits (n zero, or n and q of magnitude
        within [SAFE_LOW, SAFE_HIGH])."""
        q = n * y
        a, b = abs(n), abs(q)
        exact = (a == 0.0) | ((a >= SAFE_LOW) & (a <= SAFE_HIGH) & (b >= SAFE_LOW) & (b <= SAFE_HIGH))  # no branches
        return (q if a == 0.0 else fma(fma(-d, q, n), y, q)), exact
    return compute


@jit
def divided(n, d, y, divide):
    """(n / d, exact): the division itself where ``divide`` (exact), else :func:`quotient`."""
    if divide:
        return n / d, True
    return quotient(n, d, y)


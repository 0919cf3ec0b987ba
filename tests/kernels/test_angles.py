"""The kernels' wrap and remainder skip the float modulo where it changes nothing: the numbers are
those of :func:`fuzzynav.kernels.angles.wrap_formula` and of Python's ``%``, bit for bit."""

import math
import struct

import numpy as np
from hypothesis import given, strategies as st

from fuzzynav.kernels.angles import wrap_formula
from fuzzynav.kernels.motion import turn_remainder, wrap

EDGES = [0.0, -0.0, math.pi, -math.pi, 2.0 * math.pi, -2.0 * math.pi, math.nextafter(math.pi, 0.0),
         math.nextafter(-math.pi, 0.0), math.nextafter(2.0 * math.pi, 0.0), 1e-300, -1e-300, 5e-324,
         3.0 * math.pi, -3.0 * math.pi, 1e6, -1e6, 1e300, math.inf, -math.inf, math.nan]


def bits(value: float) -> bytes:
    """The float's bytes: 0.0 and −0.0 differ, NaN equals NaN."""
    return struct.pack("<d", value)


def test_edges_give_the_formula_bit_for_bit():
    for angle in EDGES:
        assert bits(wrap(angle)) == bits(float(wrap_formula(angle))), angle
        assert bits(turn_remainder(angle)) == bits(angle % (2.0 * math.pi)), angle


@given(st.floats(allow_nan=True, allow_infinity=True))
def test_any_float_gives_the_formula_bit_for_bit(angle):
    assert bits(wrap(angle)) == bits(float(wrap_formula(angle)))
    assert bits(turn_remainder(angle)) == bits(angle % (2.0 * math.pi))


def test_angles_near_the_range_give_the_formula_bit_for_bit():
    angles = np.random.default_rng(3).uniform(-7.0, 7.0, 20_000)
    wrapped = np.array([wrap(a) for a in angles])
    assert np.array_equal(wrapped.view(np.int64), wrap_formula(angles).view(np.int64))
    assert np.all(wrapped > -math.pi) and np.all(wrapped <= math.pi)

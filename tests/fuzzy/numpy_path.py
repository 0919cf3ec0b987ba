"""The fused kernel against an engine's NumPy path (shared by tests/fuzzy and tests/fll)."""

import numpy as np

from fuzzynav.fuzzy.engine.fuzzify_terms import BELL, GAUSSIAN, SIGMOID

OUTPUT_TOLERANCE = 1e-12  # × the output's range, where the kernel fuzzifies a Gaussian, Bell or Sigmoid term


def assert_fused_matches_numpy_path(engine, X) -> np.ndarray:
    """The fused outputs for X: the very bits of the NumPy path, except for an engine with a
    Gaussian, Bell or Sigmoid term, which the kernel evaluates with :mod:`fuzzynav.fuzzy.engine.vmath`'s
    exp and log (a few ulp from NumPy's): there NaN and infinities exactly where NumPy has them, and
    finite outputs within :data:`OUTPUT_TOLERANCE` × the output's range."""
    assert engine.fallback is None
    fused = engine.evaluate(X)
    packed, engine._packed = engine._packed, "forced by the test"  # a reason: the NumPy path
    numpy_path = engine.evaluate(X)
    engine._packed = packed
    if not np.isin(packed[1].term_code, [GAUSSIAN, BELL, SIGMOID]).any():
        np.testing.assert_array_equal(fused, numpy_path)
        return fused
    finite = np.isfinite(numpy_path)
    np.testing.assert_array_equal(np.where(finite, 0.0, fused), np.where(finite, 0.0, numpy_path))
    span = np.array([v.maximum - v.minimum for v in engine.outputs])
    span = np.where(np.isfinite(span) & (span > 0), span, 1.0)
    assert np.all(np.abs(fused - numpy_path)[finite] <= (OUTPUT_TOLERANCE * np.broadcast_to(span, fused.shape))[finite])
    return fused

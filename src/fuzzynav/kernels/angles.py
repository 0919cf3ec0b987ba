"""The angle convention of the package (docs/thesis.md, conventions): radians, wrapped to (−π, π].

:func:`wrap_formula` is the one formula; it runs on floats and on NumPy arrays. Python's float
``%`` and NumPy's ``mod`` give the same numbers. Inside the kernels,
:func:`fuzzynav.kernels.motion.wrap` computes it for one float with the remainder skipped where
it changes nothing, the same numbers bit for bit (``tests/kernels/test_angles.py``).
"""

from __future__ import annotations

import math

import numpy as np


def wrap_formula(angle):
    """``angle`` (a float or an array) wrapped to (−π, π]."""
    return math.pi - (math.pi - angle) % (2.0 * math.pi)


def wrap_angle(angle):
    """Wrap an angle (scalar or array, radians) to (−π, π]; a scalar gives a float."""
    if isinstance(angle, float):
        return float(wrap_formula(angle))
    wrapped = wrap_formula(np.asarray(angle, dtype=float))
    return float(wrapped) if np.ndim(wrapped) == 0 else wrapped

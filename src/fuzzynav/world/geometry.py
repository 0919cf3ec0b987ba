"""Small geometric helpers shared by the robot, world and control layers."""

from __future__ import annotations

import numpy as np


def wrap_angle(angle):
    """Wrap an angle (scalar or array, radians) to (−π, π] (docs/thesis.md, "The sign of the angle error")."""
    if isinstance(angle, float):  # one float: the same formula without NumPy's per-call cost
        return float(np.pi - (np.pi - angle) % (2.0 * np.pi))  # Python's float % is NumPy's mod
    wrapped = np.pi - np.mod(np.pi - np.asarray(angle, dtype=float), 2.0 * np.pi)
    return float(wrapped) if np.ndim(wrapped) == 0 else wrapped

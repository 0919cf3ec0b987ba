"""The supervisor of the five-behaviour navigator (thesis §IV.7, Fig IV.16): which behaviour drives.

The thesis states it in words: with no obstacle sensed, goal seeking alone; otherwise "one of
the behaviours is activated according to the perceived situation" (FOA, ROA or LOA), with the
velocity reducing behaviour VRB in parallel; and (Fig IV.23) the robot runs along a wall "until
the orientation error enters a predefined vision interval", then heads for the goal. Made
precise here, per robot, from the seven readings d1…d7 (thesis §IV.7: d1 ahead; d2, d4, d6 at
−30°, −60°, −90°; d3, d5, d7 at +30°, +60°, +90°):

1. **GSB** when no reading is below ``detection`` (an obstacle-free neighbourhood), or when the
   goal direction is clear: every ray within ``vision`` of the goal bearing (clipped to the ±90°
   the ring covers) reads at least min(d_rg, ``clear``), and no reading is below ``keep`` (room
   to turn towards it).
2. Otherwise an avoider: **FOA** while the front reading d1 is below ``front`` or is the
   nearest reading (an obstacle ahead); else the avoider of the side of the nearest reading,
   **ROA** on the right (d2, d4, d6), **LOA** on the left (d3, d5, d7).

:func:`select` returns one code per robot (:data:`GSB`, :data:`FOA`, :data:`ROA`, :data:`LOA`)
from one step's readings (compiled: :func:`fuzzynav.kernels.guard.select`). Taken alone it chatters: avoiding turns the robot away, the goal comes
into clear view, goal seeking turns it back, the obstacle is in the way again — the behaviour
would flip every step and the steering jump between 0 and ±π/5 (Fig IV.15 instead shows a
handful of switch points A…H). The switch (:func:`fuzzynav.kernels.guard.switch`) adds the
memory the thesis leaves unsaid, with one rule: **a change that adds caution is taken at once, one that removes caution waits.**
Caution ranks GSB < GSB+VRB < FOA, ROA, LOA < the full-lock turn of
:mod:`fuzzynav.control.five_behaviours`. A change to a higher rank happens the step it is asked
for where the caller calls it urgent (the five-behaviour navigators: a reading below ``keep``, or the full-lock
turn), after the dwell elsewhere; a change to the same or a lower rank only after the current behaviour has been held
``dwell`` steps (default 10, 1 s). Goal seeking, once in charge, keeps it with :func:`relaxed` thresholds (``detection``, ``keep``
and ``clear`` times ``slack``, default 0.8), so the readings that gave it the robot do not take it back the
next step.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from fuzzynav.fuzzy.systems_navigation import D_M, D_S
from fuzzynav.kernels.records import Thresholds

GSB, FOA, ROA, LOA = 0, 1, 2, 3  # fuzzynav.kernels.guard.GSB, FOA, ROA, LOA
THESIS_ANGLES_DEG = (0.0, -30.0, 30.0, -60.0, 60.0, -90.0, 90.0)  # C1…C7 (thesis §IV.7)


@dataclass(frozen=True)
class SupervisorParams:
    """Thresholds of the supervisor (m, rad): d_s and d_m of Fig IV.18, a 30° half-window."""

    detection: float = D_S  # a reading below this means "an obstacle is sensed" (d_s)
    front: float = D_M  # FOA takes over while the front reading d1 is below this (d_m)
    keep: float = D_M  # GSB is not handed the robot while any reading is below this (d_m)
    clear: float = D_S  # free distance asked of the goal direction (d_s)
    vision: float = math.radians(30.0)  # half-width of the "vision interval" around the goal bearing


def select(d: np.ndarray, goal_distance, goal_bearing, params: SupervisorParams = SupervisorParams()) -> np.ndarray:
    """Behaviour codes ``(N,)`` from readings ``d`` ``(N, 7)`` in C1…C7 order and the goal's
    distance and bearing ``(N,)`` (bearing CCW, > 0 on the left), by :func:`fuzzynav.kernels.guard.select`."""
    from fuzzynav.kernels import guard

    d = np.ascontiguousarray(d, dtype=float).reshape(-1, 7)
    out = np.empty(len(d), dtype=np.int64)
    guard.select_all(d, column(goal_distance, len(d)), column(goal_bearing, len(d)),
                     Thresholds(params.detection, params.front, params.keep, params.clear, params.vision), out)
    return out


def column(values, n: int, dtype=float) -> np.ndarray:
    """``values`` (a scalar or ``(n,)``) as a contiguous ``(n,)`` array, as the kernels take them."""
    values = np.asarray(values, dtype=dtype)
    return np.ascontiguousarray(values if values.shape == (n,) else np.broadcast_to(values, (n,)))


def relaxed(params: SupervisorParams, slack: float = 0.8) -> SupervisorParams:
    """``params`` with ``detection``, ``keep`` and ``clear`` scaled by ``slack``: the thresholds under
    which goal seeking, already in charge, keeps the robot (the hysteresis of the switch)."""
    return replace(params, detection=params.detection * slack, keep=params.keep * slack, clear=params.clear * slack)

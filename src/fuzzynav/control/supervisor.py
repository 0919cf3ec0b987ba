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
from one step's readings. Taken alone it chatters: avoiding turns the robot away, the goal comes
into clear view, goal seeking turns it back, the obstacle is in the way again — the behaviour
would flip every step and the steering jump between 0 and ±π/5 (Fig IV.15 instead shows a
handful of switch points A…H). :class:`Switch` adds the memory the thesis leaves unsaid, with
one rule: **a change that adds caution is taken at once, one that removes caution waits.**
Caution ranks GSB < GSB+VRB < FOA, ROA, LOA < the full-lock turn of
:mod:`fuzzynav.control.five_behaviours`. A change to a higher rank happens the step it is asked
for where the caller calls it urgent (``fuzzy-5b``: a reading below ``keep``, or the full-lock
turn), after the dwell elsewhere; a change to the same or a lower rank only after the current behaviour has been held
``dwell`` steps (default 10, 1 s); and an avoider hands the robot back to goal seeking only when
``release`` allows it (the navigator asks for the goal "in the vision interval", Fig IV.23).
Goal seeking, once in charge, keeps it with :func:`relaxed` thresholds (``detection``, ``keep``
and ``clear`` times ``slack``, default 0.8), so the readings that gave it the robot do not take it back the
next step.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from fuzzynav.fuzzy.systems_navigation import D_M, D_S

GSB, FOA, ROA, LOA = 0, 1, 2, 3
THESIS_ANGLES_DEG = (0.0, -30.0, 30.0, -60.0, 60.0, -90.0, 90.0)  # C1…C7 (thesis §IV.7)
ANGLES = np.deg2rad(THESIS_ANGLES_DEG)
SIDE = np.array([FOA, ROA, LOA, ROA, LOA, ROA, LOA])  # module of each sensor's side: d2, d4, d6 right
_ANGLES, _SIDE = ANGLES.tolist(), SIDE.tolist()  # the same, for one robot's float path


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
    distance and bearing ``(N,)`` (bearing CCW, > 0 on the left). One robot takes plain floats
    (the same tests; NumPy's fixed cost per call would dominate)."""
    d = np.asarray(d, dtype=float)
    if len(d) == 1:
        row = d[0].tolist()
        look = min(max(float(np.asarray(goal_bearing)[0]), -math.pi / 2), math.pi / 2)
        need = min(float(np.asarray(goal_distance)[0]), params.clear)
        nearest = min(row)
        goal_clear = nearest >= params.keep and all(
            r >= need for a, r in zip(_ANGLES, row) if abs(a - look) <= params.vision + 1e-9)
        if nearest >= params.detection or goal_clear:
            return np.array([GSB])
        return np.array([FOA if row[0] < params.front else _SIDE[row.index(nearest)]])
    look = np.clip(np.asarray(goal_bearing, dtype=float), -math.pi / 2, math.pi / 2)
    window = np.abs(ANGLES[None, :] - look[:, None]) <= params.vision + 1e-9  # around the goal bearing
    need = np.minimum(np.asarray(goal_distance, dtype=float), params.clear)
    nearest = d.min(axis=1)
    goal_clear = np.all(~window | (d >= need[:, None]), axis=1) & (nearest >= params.keep)
    quiet = nearest >= params.detection
    k = np.argmin(d, axis=1)
    avoider = np.where(d[:, 0] < params.front, FOA, SIDE[k])
    return np.where(quiet | goal_clear, GSB, avoider)


def relaxed(params: SupervisorParams, slack: float = 0.8) -> SupervisorParams:
    """``params`` with ``detection``, ``keep`` and ``clear`` scaled by ``slack``: the thresholds under
    which goal seeking, already in charge, keeps the robot (the hysteresis of :class:`Switch`)."""
    return replace(params, detection=params.detection * slack, keep=params.keep * slack, clear=params.clear * slack)


class Switch:
    """The behaviour switch with memory (see the module docstring): one mode and a hold count
    per robot. ``rank`` maps each mode code to its caution rank."""

    def __init__(self, rank, dwell: int = 10):
        self.rank = np.asarray(rank, dtype=int)
        self._rank = self.rank.tolist()
        self.dwell = int(dwell)
        self.reset()

    def reset(self) -> None:
        """Forget the modes (a new episode): the first call takes the modes asked for."""
        self.mode = None
        self.held = None

    def __call__(self, wanted, release, urgent=True) -> np.ndarray:
        """Modes ``(N,)`` for the modes ``wanted`` this step; ``release`` (a bool or ``(N,)`` bools) says where a
        lower rank may be taken (after the dwell); a higher rank is taken at once where ``urgent``
        (default everywhere), elsewhere after the dwell too."""
        wanted = np.asarray(wanted, dtype=int)
        if self.mode is None or len(self.mode) != len(wanted):
            self.mode, self.held = wanted.copy(), np.zeros(len(wanted), dtype=int)
            return self.mode.copy()
        if len(wanted) == 1:  # one robot: the same rule on ints
            w, m, held = int(wanted[0]), int(self.mode[0]), int(self.held[0])
            up, down = self._rank[w] > self._rank[m], self._rank[w] < self._rank[m]
            take = w != m and (up and _first(urgent) or held >= self.dwell and (not down or _first(release)))
            self.mode, self.held = np.array([w if take else m]), np.array([0 if take else held + 1])
            return self.mode.copy()
        up, down = self.rank[wanted] > self.rank[self.mode], self.rank[wanted] < self.rank[self.mode]
        settled = self.held >= self.dwell
        take = (wanted != self.mode) & (up & urgent | settled & (~down | release))
        self.mode = np.where(take, wanted, self.mode)
        self.held = np.where(take, 0, self.held + 1)
        return self.mode.copy()


def _first(flags) -> bool:
    """The one robot's value of a per-robot flag given as an array ``(1,)`` or a plain bool."""
    return flags if isinstance(flags, bool) else bool(np.asarray(flags).reshape(-1)[0])

"""Loop and trap escape of the default chapter IV navigators: circling detection and boundary
following, in the spirit of the Bug algorithms (V. Lumelsky, A. Stepanov, "Path-planning
strategies for a point mobile automaton moving amidst unknown obstacles of arbitrary shape",
Algorithmica 2, 1987; the leaving rule of DistBug, I. Kamon, E. Rivlin, IEEE Trans. Robotics
and Automation 13(6), 1997).

A reactive navigator can circle for ever: around a group of obstacles, or inside a U-shaped
wall whose opening faces away from the goal, goal seeking turns the robot back into the
pocket each time the avoiders have brought it out. The Bug algorithms end this with a memory
of one number: on meeting an obstacle, record the distance to the goal (the *hit* distance),
follow the obstacle's boundary, and leave it only where the goal is nearer than that and the
way towards it is free.

- :class:`LoopDetector` says when the robot circles: it is back within ``revisit`` of a place
  it passed at least ``min_lap`` ago (and at most ``horizon``), and its best distance to the goal has not improved by
  ``gain`` for ``patience``.
- :class:`BoundaryFollowing` is the escape mode (``BF``). It drives the navigator's own
  behaviours towards a *virtual goal* ``offset`` to one side of the heading, ``reach`` ahead,
  so goal seeking pulls the robot towards the followed boundary and the avoiders push it away:
  the robot runs along the boundary the way the thesis' navigator runs along the U-wall of
  Fig IV.23, and wraps around its corners (a lost boundary leaves the pull alone, which
  turns the robot back to it). The mode ends — the real goal handed back — when the goal is
  ``gain`` nearer than at the hit and the range ray nearest the goal direction reads the way
  free (DistBug's leaving rule), or after ``max_time``. A loop while following changes the
  followed side.
"""

from __future__ import annotations

import math
from collections import deque

import numpy as np


class LoopDetector:
    """Circling without progress, from the poses and goal distances of one robot."""

    def __init__(self, revisit: float = 1.5, min_lap: float = 8.0, patience: float = 20.0, gain: float = 0.5,
                 sample_every: float = 0.5, horizon: float = 90.0):
        self.revisit, self.min_lap, self.patience, self.gain = float(revisit), float(min_lap), float(patience), float(gain)
        self.sample_every, self.horizon = float(sample_every), float(horizon)
        self.reset()

    def reset(self) -> None:
        """Forget the places and the progress (a new episode, or after an escape)."""
        self._places: deque = deque()
        self._best = math.inf
        self._t_best = None

    def update(self, t: float, x: float, y: float, goal_distance: float) -> bool:
        """Record this step; True when the robot circles (see the class docstring)."""
        if self._t_best is None or goal_distance < self._best - self.gain:
            self._best, self._t_best = goal_distance, t
        if not self._places or t - self._places[-1][0] >= self.sample_every - 1e-9:
            self._places.append((t, x, y))
        while self._places and t - self._places[0][0] > self.horizon:
            self._places.popleft()
        if t - self._t_best < self.patience:
            return False
        return any(t - s >= self.min_lap and math.hypot(x - px, y - py) < self.revisit for s, px, py in self._places)


class BoundaryFollowing:
    """The ``BF`` mode of the module docstring for one robot."""

    def __init__(self, offset: float = math.radians(75.0), reach: float = 3.0, gain: float = 0.5,
                 free: float = 2.0, max_time: float = 60.0):
        self.offset, self.reach, self.gain, self.free, self.max_time = (float(offset), float(reach), float(gain),
                                                                       float(free), float(max_time))
        self.reset()

    def reset(self) -> None:
        """Not following; the next escape follows the side of the nearest obstacle."""
        self.active = False
        self.side = 0

    def start(self, obs, side: int) -> None:
        """Begin following the boundary on ``side`` (+1 left, −1 right) from here."""
        self.active, self.side = True, int(side)
        self._hit, self._t0 = float(obs.target_distance), obs.t

    def target(self, obs) -> np.ndarray:
        """The virtual goal of this step (world frame)."""
        x, y, theta = (float(v) for v in obs.pose)
        heading = theta + self.side * self.offset
        return np.array([x + self.reach * math.cos(heading), y + self.reach * math.sin(heading)])

    def should_leave(self, obs) -> bool:
        """True when the goal is nearer than at the hit by ``gain`` and its direction is free, or
        after ``max_time`` of following."""
        if obs.t - self._t0 > self.max_time:
            return True
        distance, bearing = obs.target_distance, obs.target_bearing
        if distance > self._hit - self.gain or abs(bearing) > math.pi / 2 + 1e-9:
            return False
        angles = np.asarray(obs.sensor_angles, dtype=float)
        k = int(np.argmin(np.abs(np.remainder(angles - bearing + math.pi, math.tau) - math.pi)))
        return float(np.asarray(obs.ranges)[k]) >= min(distance, self.free)

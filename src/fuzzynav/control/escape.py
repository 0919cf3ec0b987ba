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
  it passed at least ``min_lap`` ago (and at most ``horizon``), and its best distance to the
  goal has not improved by ``gain`` for ``patience``.
- :class:`BoundaryFollowing` is the escape mode (``BF``). It drives the navigator's own
  behaviours towards a *virtual goal*: a point 2.5 m along the shortest route to the goal round
  the obstacles remembered so far (:mod:`fuzzynav.control.route`, unseen space assumed free),
  which runs along the boundaries of what traps the robot, on the side the memory says is
  shorter; the navigator's avoiders keep it off the boundary. Only where the memory leaves no
  route does it fall back on following one side: the virtual goal ``offset`` to that side of
  the heading, ``reach`` ahead (``search``, nearer the heading, while no obstacle is near), so
  goal seeking pulls the robot towards the boundary and the avoiders push it away, the way the
  thesis' navigator runs along the U-wall of Fig IV.23. The mode ends — the real goal handed
  back — when the goal is ``gain`` nearer than the hit distance, taken as the best distance
  reached before following (DistBug's d_min), and the range ray nearest the goal direction reads
  the way free for ``free`` (or up to the goal); or after ``max_time``. (DistBug's own rule,
  leave where the free range towards the goal would beat d_min, hands a reactive navigator back
  to the loop it was caught in: its way to the goal is not the straight line.) The side
  followed without a route is the nearest obstacle's; after a following that ran out of time,
  or looped, the next one takes the other side.
"""

from __future__ import annotations

import math
from collections import deque

import numpy as np

from fuzzynav.control.route import route_target


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

    @property
    def best(self) -> float:
        """The smallest goal distance seen since the last reset (m)."""
        return self._best

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

    def __init__(self, offset: float = math.radians(75.0), search: float = math.radians(25.0), near: float = 2.0,
                 reach: float = 3.0, gain: float = 0.5, free: float = 2.0, max_time: float = 40.0,
                 room: float = 0.7, tight: float = 0.2, ahead: float = 2.5, replan: float = 1.0):
        self.offset, self.search, self.near = float(offset), float(search), float(near)
        self.reach, self.gain, self.free, self.max_time = float(reach), float(gain), float(free), float(max_time)
        self.room, self.tight, self.ahead, self.replan = float(room), float(tight), float(ahead), float(replan)
        self.reset()

    def reset(self) -> None:
        """Not following, no side tried yet (a new episode)."""
        self.active = False
        self.side = 0
        self._failed = 0  # the side whose last following ran out of time or looped (0: none)

    def start(self, obs, best: float) -> None:
        """Begin following here; ``best`` is the smallest goal distance reached so far (the
        leaving rule must beat it). The followed side is the nearest obstacle's (Bug: follow what
        was hit), or the other one after a following on that side
        ran out of time or looped (a loop while following ends it as failed)."""
        if self.active:
            self._failed = self.side
        side = 1 if obs.obstacle_bearing >= 0 else -1
        self.active, self.side = True, -self._failed if self._failed else side
        self._hit, self._t0 = min(float(obs.target_distance), float(best)), obs.t
        self._route, self._planned = None, -math.inf

    def stop(self, succeeded: bool) -> None:
        """End the following (``succeeded``: by the leaving rule, not by time)."""
        self._failed = 0 if succeeded else self.side
        self.active = False

    def target(self, obs, points: np.ndarray, radius: float) -> np.ndarray:
        """The virtual goal of this step (world frame): ``ahead`` m along the route round the
        remembered obstacle ``points`` (:func:`route_target`, keeping ``radius`` + ``room``, the
        room of a turn; where no such route exists, ``radius`` + ``tight``), planned again every ``replan`` s or when the robot is near it; without a route, a point
        ``offset`` to the followed side with an obstacle within ``near`` (D_ro or a reading),
        ``search`` without (a wide arc that finds the boundary again, not a tight circle)."""
        x, y, theta = (float(v) for v in obs.pose)
        stale = self._route is None or math.hypot(self._route[0] - x, self._route[1] - y) < 1.0
        if stale or obs.t - self._planned >= self.replan - 1e-9:
            self._route = route_target(points, obs.pose, obs.target, radius + self.room, self.ahead)
            if self._route is None:
                self._route = route_target(points, obs.pose, obs.target, radius + self.tight, self.ahead)
            self._planned = obs.t
        if self._route is not None:
            return self._route
        nearest = min(float(obs.obstacle_distance), float(np.min(obs.ranges)))
        heading = theta + self.side * (self.offset if nearest < self.near else self.search)
        return np.array([x + self.reach * math.cos(heading), y + self.reach * math.sin(heading)])

    def timed_out(self, obs) -> bool:
        """True after ``max_time`` of following."""
        return obs.t - self._t0 > self.max_time

    def should_leave(self, obs) -> bool:
        """The leaving rule: the goal is ``gain`` nearer than the hit distance and the ray
        nearest the goal direction (within the ring's ±90°) reads at least min(d, ``free``)."""
        distance, bearing = obs.target_distance, obs.target_bearing
        if distance > self._hit - self.gain or abs(bearing) > math.pi / 2 + 1e-9:
            return False
        angles = np.asarray(obs.sensor_angles, dtype=float)
        k = int(np.argmin(np.abs(np.remainder(angles - bearing + math.pi, math.tau) - math.pi)))
        return float(np.asarray(obs.ranges)[k]) >= min(distance, self.free)

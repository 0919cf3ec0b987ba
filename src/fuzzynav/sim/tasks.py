"""Tasks of an episode, vectorised over robots: goal, path tracking, moving target.

- goal (chapter IV): reached when d_rg ≤ goal tolerance.
- path (thesis §V.2–§V.3): the robot aims at the current waypoint; once inside its tolerance
  zone (``path_tolerance``) it switches to the next one (no stop, no turn on the spot); the task
  is complete when the last waypoint's zone is entered. The speed is the path's constant speed.
  With ``path_switching: passed`` (the default; an addition to the thesis) an interior waypoint
  k is also left once the robot has *passed* it: it has crossed the bisector of the corner at k
  (the line through k halving the angle between the segments k − 1 → k and k → k + 1; on a
  straight continuation the normal to the path, i.e. its projection goes beyond k) and it is at
  least as near to the next segment as to the current one. The bisector is crossed whether the
  robot cuts the corner or swings wide of it, so a tracker that rounds a sharp corner outside the
  zone (0.5 m, §V.2; e.g. 0.71 m on the 136° corners of ``example-path``) goes on with the path
  instead of circling back to the missed waypoint. ``path_switching: zone`` is the thesis' rule
  alone. The last waypoint is always the zone.
- target (thesis §V.5): the target moves by its :class:`~fuzzynav.world.motion.TargetMotion`;
  captured when the robot is within the target tolerance.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.world.scenario import Scenario


class TaskState:
    """Per-robot task progress: the point aimed at, waypoint indices, completion flags."""

    def __init__(self, scenario: Scenario, n: int):
        self.scenario = scenario
        self.kind = scenario.task
        self.n = n
        self.waypoint_index = np.zeros(n, dtype=int)
        self.t = 0.0
        if self.kind == "goal":
            self.tolerance = scenario.goal.tolerance
            self._goal = np.broadcast_to(scenario.goal.position, (n, 2))  # fixed: built once
        elif self.kind == "path":
            self.tolerance = scenario.path.tolerance
        else:
            self.tolerance = scenario.target.tolerance

    @property
    def path(self) -> np.ndarray | None:
        return self.scenario.path.waypoints if self.kind == "path" else None

    @property
    def forced_speed(self) -> float | None:
        """The constant speed the simulator applies (path tasks), else None."""
        return self.scenario.path.speed if self.kind == "path" else None

    def target(self) -> np.ndarray:
        """``(N, 2)``: goal, current waypoint or target position at the current time."""
        if self.kind == "goal":
            return self._goal
        if self.kind == "path":
            return self.scenario.path.waypoints[self.waypoint_index]
        return np.broadcast_to(self.scenario.target.motion.position(self.t), (self.n, 2))

    def target_velocity(self) -> np.ndarray | None:
        if self.kind != "target":
            return None
        return np.broadcast_to(self.scenario.target.motion.velocity_at(self.t), (self.n, 2))

    def update(self, positions: np.ndarray, t: float, active: np.ndarray) -> np.ndarray:
        """Advance to time ``t`` with robot positions ``(N, 2)``; returns ``(N,)`` done flags.

        Path tasks switch the waypoint of active robots inside the current tolerance zone or, with
        ``path_switching: passed``, once past it (:meth:`passed`).
        """
        self.t = t
        distance = np.hypot(*(self.target() - positions).T)
        inside = distance <= self.tolerance
        if self.kind != "path":
            return inside
        last = len(self.scenario.path.waypoints) - 1
        done = inside & (self.waypoint_index == last)
        switch = inside & ~done & active
        if self.scenario.path.switching == "passed":
            switch |= self.passed(positions) & active
        self.waypoint_index = self.waypoint_index + switch
        return done

    def passed(self, positions: np.ndarray) -> np.ndarray:
        """``(N,)``: robots past their current interior waypoint k (module docstring): beyond the
        bisector of the corner, (p − w_k)·(u_in + u_out) > 0 with u the unit segment directions,
        and no farther from segment k → k + 1 than from segment k − 1 → k."""
        waypoints = self.scenario.path.waypoints
        k = self.waypoint_index
        interior = (k >= 1) & (k < len(waypoints) - 1)
        k = np.clip(k, 1, len(waypoints) - 2)
        before, corner, after = waypoints[k - 1], waypoints[k], waypoints[k + 1]
        unit = lambda d: d / np.hypot(d[:, 0], d[:, 1])[:, None]
        forward = unit(corner - before) + unit(after - corner)
        beyond = np.einsum("ij,ij->i", positions - corner, forward) > 0
        return interior & beyond & (_segment_distance(positions, corner, after)
                                    <= _segment_distance(positions, before, corner))


def _segment_distance(points: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``(N,)`` distances of ``points`` to the segments ``a[i] → b[i]`` (all ``(N, 2)``)."""
    d = b - a
    s = np.clip(np.einsum("ij,ij->i", points - a, d) / np.einsum("ij,ij->i", d, d), 0.0, 1.0)
    return np.hypot(*(a + s[:, None] * d - points).T)

"""Tasks of an episode, vectorised over robots: goal, path tracking, moving target.

- goal (chapter IV): reached when d_rg ≤ goal tolerance.
- path (SPEC §4, thesis §V.3): the robot aims at the current waypoint; once inside its tolerance
  zone (``path_tolerance``) it switches to the next one (no stop, no turn on the spot); the task
  is complete when the last waypoint's zone is entered. The speed is the path's constant speed.
- target (SPEC §4.4, §V.5): the target moves by its :class:`~fuzzynav.world.motion.TargetMotion`;
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

        Path tasks switch the waypoint of active robots inside the current tolerance zone.
        """
        self.t = t
        distance = np.hypot(*(self.target() - positions).T)
        inside = distance <= self.tolerance
        if self.kind != "path":
            return inside
        last = len(self.scenario.path.waypoints) - 1
        done = inside & (self.waypoint_index == last)
        switch = inside & ~done & active
        self.waypoint_index = self.waypoint_index + switch
        return done

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

The tests run compiled, robot by robot, in the simulator's step (:func:`fuzzynav.kernels.step.task_update`);
:class:`TaskState` describes a scenario's task to it.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.world.fleet import task_fields
from fuzzynav.world.scenario import Scenario

TASK_CODES = {"goal": 0, "path": 1, "target": 2}  # fuzzynav.kernels.step.GOAL, PATH, TARGET


class TaskState:
    """A scenario's task for N robots: the point aimed at, the waypoint indices (``update``)."""

    def __init__(self, scenario: Scenario, n: int):
        self.scenario = scenario
        self.kind = scenario.task
        self.n = n
        self.waypoint_index = np.zeros(n, dtype=int)
        self.tolerance = {"goal": lambda: scenario.goal, "path": lambda: scenario.path,
                          "target": lambda: scenario.target}[self.kind]().tolerance

    @property
    def path(self) -> np.ndarray | None:
        return self.scenario.path.waypoints if self.kind == "path" else None

    @property
    def forced_speed(self) -> float | None:
        """The constant speed the simulator applies (path tasks), else None."""
        return self.scenario.path.speed if self.kind == "path" else None

    def position(self, t: float) -> np.ndarray:
        """``(2,)``: the goal or the moving target at time ``t`` (the first waypoint of a path)."""
        if self.kind == "goal":
            return np.asarray(self.scenario.goal.position, dtype=float)
        if self.kind == "path":
            return self.scenario.path.waypoints[0]
        return self.scenario.target.motion.position(t)

    def target(self, t: float = 0.0) -> np.ndarray:
        """``(N, 2)``: the point each robot aims at — the goal, its current waypoint (after
        :meth:`update`), or the moving target at time ``t``."""
        if self.kind == "path":
            return self.scenario.path.waypoints[self.waypoint_index]
        return np.broadcast_to(self.position(t), (self.n, 2))

    def target_velocity(self, t: float) -> np.ndarray | None:
        """``(N, 2)`` velocity of a moving target at time ``t``, else None."""
        if self.kind != "target":
            return None
        return np.broadcast_to(self.scenario.target.motion.velocity_at(t), (self.n, 2))

    def setup(self, robot: np.ndarray, max_range: float, max_steps: int, angles, t: float,
              half_beam: float = 0.0) -> np.ndarray:
        """The kernels' set-up array (:data:`fuzzynav.kernels.step.SETUP_FIELDS`): ``robot``
        (:meth:`TricycleParams.array`), the sensors, this task at time ``t``, then the sensor
        ``angles`` (of half beam width ``half_beam``) and the path's waypoints."""
        from fuzzynav.kernels.step import setup_array

        fields = (task_fields(path=self.scenario.path) if self.kind == "path"
                  else task_fields(goal=self.position(t), tolerance=self.tolerance, task=TASK_CODES[self.kind]))
        return setup_array(robot, max_range=max_range, max_steps=max_steps, angles=angles, half_beam=half_beam,
                           **fields)

    def update(self, positions: np.ndarray, t: float, active: np.ndarray) -> np.ndarray:
        """Advance to time ``t`` with robot positions ``(N, 2)``; returns ``(N,)`` done flags. Path
        tasks switch the waypoint of active robots inside the current tolerance zone or, with
        ``path_switching: passed``, once past it."""
        from fuzzynav.kernels import step
        from fuzzynav.robot.tricycle import DEFAULT_PARAMS

        setup = self.setup(DEFAULT_PARAMS.array(), 0.0, 0, [], t)
        done = np.zeros(len(positions), dtype=bool)
        for i, ((x, y), live) in enumerate(zip(np.asarray(positions, dtype=float).tolist(), active)):
            done[i], index, _, _ = step.task_update(setup, int(self.waypoint_index[i]), x, y)
            self.waypoint_index[i] = index if live else self.waypoint_index[i]
        return done

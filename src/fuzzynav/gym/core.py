"""N robots, each in its own episode, stepped together: the hot path of every fuzzynav environment.

The single environment (:class:`~fuzzynav.gym.env.FuzzynavEnv`) is a batch of one, the vector
environment (:class:`~fuzzynav.gym.vector.FuzzynavVectorEnv`) a batch of N, so both compute the
same numbers. One decision lasts ``decision_steps`` steps Δt of the simulator's physics: the
command is clipped to the robot's limits, the tricycle steps (eq IV.2,
:func:`fuzzynav.robot.tricycle.step`, one call for all robots), and the stop tests of
:class:`~fuzzynav.sim.simulator.BatchSimulator` follow in its order — collision (footprint disc
against obstacles and boundary, :meth:`~fuzzynav.world.world.World.clearance`), then the task
(goal within its tolerance; a path's waypoints switched by :class:`~fuzzynav.sim.tasks.TaskState`).
Sensing and collision tests are vectorised over the robots that share a world (one call per
distinct world): robots in one world — an empty workspace, one scenario, a small pool — cost one
call; robots in N different worlds cost N.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from fuzzynav.control.learned import goal_inputs, side_distances
from fuzzynav.learn.envs.env import RobotState
from fuzzynav.robot import tricycle
from fuzzynav.robot.sensors import SensorRing
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.sim.tasks import TaskState


class RobotBatch:
    """State of N robots: pose, last command, target, the scenario of each row's episode."""

    def __init__(self, n: int, task, *, params=DEFAULT_PARAMS, sensors: SensorRing | None = None,
                 decision_steps: int = 1):
        self.n = int(n)
        self.task = task
        self.params = params
        self.sensors = sensors if sensors is not None else SensorRing()
        self.decision_steps = int(decision_steps)
        self.scenarios = [None] * self.n
        self.paths: list[TaskState | None] = [None] * self.n
        self.pose = np.zeros((self.n, 3))
        self.speed = np.zeros(self.n)
        self.steering = np.zeros(self.n)
        self.target = np.zeros((self.n, 2))
        self.tolerance = np.full(self.n, -np.inf)  # goal tolerance of the rows with a fixed goal
        self.forced_speed = np.full(self.n, np.nan)  # a path's constant speed (NaN: the agent's)
        self.state: RobotState | None = None
        self._all_groups = None  # _groups() of every row, until an episode starts

    # -- episodes ----------------------------------------------------------------------------
    def start(self, rows, scenarios) -> None:
        """Begin new episodes in ``rows`` on ``scenarios`` (one each): start pose, zero command."""
        self._all_groups = None
        for row, scenario in zip(rows, scenarios):
            self.scenarios[row] = scenario
            self.pose[row] = scenario.start
            self.speed[row] = self.steering[row] = 0.0
            self.paths[row] = TaskState(scenario, 1) if scenario.task == "path" else None
            self.forced_speed[row] = np.nan if self.paths[row] is None else self.paths[row].forced_speed
            self.tolerance[row] = -np.inf
            if scenario.goal is not None and self.task.name != "path" and self.task.goal:
                self.target[row] = scenario.goal.position
                self.tolerance[row] = scenario.goal.tolerance
            elif self.paths[row] is not None:
                self.target[row] = self.paths[row].target()[0]
        rows = np.asarray(list(rows), dtype=int)
        if self.state is None or len(rows) == self.n:
            self.state = self._state(self.pose, self.speed, self.steering, self.target)
            return
        fresh = self._state(self.pose, self.speed, self.steering, self.target, rows=rows)
        for name in ("ranges", "goal", "sides"):
            if getattr(self.state, name) is not None:
                getattr(self.state, name)[rows] = getattr(fresh, name)
        self.state = replace(self.state, pose=self.pose.copy(), speed=self.speed.copy(),
                             steering=self.steering.copy(), target=self.target.copy())

    def _groups(self, rows=None):
        """``rows`` (default all) by distinct world: ``[(world, rows of that world), …]``."""
        if rows is None and self._all_groups is not None:
            return self._all_groups
        groups: dict[int, tuple] = {}
        for row in range(self.n) if rows is None else rows:
            scenario = self.scenarios[row]
            key = id(scenario.world)
            if key not in groups:
                groups[key] = (scenario.world, [])
            groups[key][1].append(row)
        found = [(world, np.array(members)) for world, members in groups.values()]
        if rows is None:
            self._all_groups = found
        return found

    def _state(self, pose, speed, steering, target, goal_target=None, rows=None) -> RobotState:
        """What the observations and rewards read (of ``rows`` only, if given); ``goal_target``
        (default ``target``) is the point d_rg and θ_rg are measured to (the reward holds a
        path's waypoint over a step)."""
        ranges = sides = goal = None
        if rows is not None:
            pose, speed, steering, target = pose[rows], speed[rows], steering[rows], target[rows]
        if self.task.ranges or not self.task.goal:
            ranges = np.empty((len(pose), self.sensors.count))
            index = np.full(self.n, -1)  # row of the batch -> row of these arrays
            index[np.arange(self.n) if rows is None else rows] = np.arange(len(pose))
            for world, members in self._groups(rows):
                ranges[index[members]] = self.sensors.read(world, pose[index[members]])
            sides = side_distances(ranges)
        if self.task.goal:
            goal = goal_inputs(pose, target if goal_target is None else goal_target)
        return RobotState(None, pose, speed, steering, target, ranges, goal, sides)

    def clearance(self, pose) -> np.ndarray:
        """Signed distance (N,) of each robot centre to its world's obstacles or boundary."""
        out = np.empty(self.n)
        for world, rows in self._groups():
            out[rows] = world.clearance(pose[rows, :2])
        return out

    # -- stepping ----------------------------------------------------------------------------
    def step(self, steering, speed, live):
        """One decision of the ``live`` rows (others stand still); returns ``(before, after, held,
        collided, done, passed)``: ``held`` measures d_rg and θ_rg to the targets the step began
        with (the reward of a waypoint just switched), ``done`` is the goal reached or the path
        completed, ``passed`` a waypoint switched."""
        before = self.state
        pose, target = self.pose, self.target.copy()
        collided = np.zeros(self.n, dtype=bool)
        reached = np.zeros(self.n, dtype=bool)
        passed = np.zeros(self.n, dtype=bool)
        speed = np.where(np.isnan(self.forced_speed), speed, self.forced_speed)
        for _ in range(self.decision_steps):
            moving = live & ~collided & ~reached
            if not moving.any():
                break
            a, v = self.params.clip(np.broadcast_to(steering, (self.n,)).astype(float),
                                    np.broadcast_to(speed, (self.n,)).astype(float))
            self.steering = np.where(moving, a, self.steering)
            self.speed = np.where(moving, v, 0.0)
            pose = np.where(moving[:, None], tricycle.step(pose, self.steering, self.speed, self.params), pose)
            collided |= moving & (self.clearance(pose) < self.params.radius)
            done, switched = self._task_update(pose, moving & ~collided)
            reached |= done
            passed |= switched
        self.pose = pose
        self.speed = np.where(live, self.speed, 0.0)
        after = self._state(pose, self.speed, self.steering, self.target)
        held = after if not passed.any() else self._state(pose, self.speed, self.steering, self.target, target)
        self.state = after
        return before, after, held, collided, reached, passed

    def _task_update(self, pose, moving):
        """(done (N,), waypoint switched (N,)) after a move; updates the targets."""
        gap = self.target - pose[:, :2]
        done = moving & (np.hypot(gap[:, 0], gap[:, 1]) <= self.tolerance)
        switched = np.zeros(self.n, dtype=bool)
        for row in np.flatnonzero(moving & ~np.isnan(self.forced_speed)):
            path = self.paths[row]
            index = path.waypoint_index[0]
            done[row] = path.update(pose[row:row + 1, :2], 0.0, np.ones(1, dtype=bool))[0]
            switched[row] = path.waypoint_index[0] != index
            self.target[row] = path.target()[0]
        return done, switched

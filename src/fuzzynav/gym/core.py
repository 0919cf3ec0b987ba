"""N robots, each in its own episode, stepped together: the hot path of every fuzzynav environment.

The single environment (:class:`~fuzzynav.gym.env.FuzzynavEnv`) is a batch of one, the vector
environment (:class:`~fuzzynav.gym.vector.FuzzynavVectorEnv`) a batch of N, so both compute the
same numbers. One decision lasts ``decision_steps`` steps Δt of the simulator's physics: the
command is clipped to the robot's limits, the tricycle steps (eq IV.2,
:func:`fuzzynav.robot.tricycle.step`, one call for all robots), and the stop tests of
:class:`~fuzzynav.sim.simulator.BatchSimulator` follow in its order — collision (footprint disc
against obstacles and boundary, :meth:`~fuzzynav.world.world.World.clearance`), then the task
(goal within its tolerance; a path's waypoints switched as :mod:`fuzzynav.sim.tasks` describes).
Sensing, collision and waypoint tests run for all robots in one compiled call each, every robot in
its own world: the packed scene arrays (:func:`fuzzynav.kernels.layout.pack`) of the distinct
worlds are concatenated and each robot reads its own slice (:func:`fuzzynav.kernels.scene.nearest_worlds`,
:func:`fuzzynav.kernels.beams.read_worlds`), as a path's set-up array for its waypoints
(:func:`fuzzynav.kernels.step.task_update_rows`).

Moving obstacles (docs/dynamic.md): a row whose world has some gets a copy of its world's scene
of its own, and after every step Δt its moving obstacles are written into it where they are at
that row's episode time (:func:`fuzzynav.kernels.traffic.place`, offsets of
:func:`fuzzynav.world.moving.offsets`), before the collision test and the sensing — the order of
the simulator's compiled step, so both see the obstacles at the same place at the same step.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from fuzzynav.control.learned import goal_inputs, side_distances
from fuzzynav.kernels.layout import NEAREST_COLUMNS
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
        self.waypoint = np.zeros(self.n, dtype=np.int64)  # index of a path's current waypoint
        self._setups = [None] * self.n  # a path row's set-up array for the waypoint kernel
        self.pose = np.zeros((self.n, 3))
        self.speed = np.zeros(self.n)
        self.steering = np.zeros(self.n)
        self.target = np.zeros((self.n, 2))
        self.tolerance = np.full(self.n, -np.inf)  # goal tolerance of the rows with a fixed goal
        self.forced_speed = np.full(self.n, np.nan)  # a path's constant speed (NaN: the agent's)
        self.state: RobotState | None = None
        self.scenes = self.scene_bounds = None  # the rows' worlds packed together (_pack_worlds)
        self.path_setups = self.setup_bounds = None  # the path rows' set-up arrays packed together
        self.steps = np.zeros(self.n, dtype=np.int64)  # steps Δt of each row's episode so far
        self._row_scenes = [None] * self.n  # a row's scene: its world's, or its own copy when obstacles move

    # -- episodes ----------------------------------------------------------------------------
    def start(self, rows, scenarios) -> None:
        """Begin new episodes in ``rows`` on ``scenarios`` (one each): start pose, zero command."""
        for row, scenario in zip(rows, scenarios):
            self.scenarios[row] = scenario
            self.steps[row] = 0
            self._row_scenes[row] = scenario.world.scene.copy() if scenario.world.moving else scenario.world.scene
            self.pose[row] = scenario.start
            self.speed[row] = self.steering[row] = 0.0
            path = TaskState(scenario, 1) if scenario.task == "path" else None
            self.forced_speed[row] = np.nan if path is None else path.forced_speed
            self._setups[row] = None if path is None else path.setup(self.params.array(), 0.0, 0, [], 0.0)
            self.waypoint[row] = 0
            self.tolerance[row] = -np.inf
            if scenario.goal is not None and self.task.name != "path" and self.task.goal:
                self.target[row] = scenario.goal.position
                self.tolerance[row] = scenario.goal.tolerance
            elif path is not None:
                self.target[row] = path.target()[0]
        self.scenes, self.scene_bounds = _concatenate(self._row_scenes)
        self.place_obstacles(np.ones(self.n, dtype=bool))
        self.path_setups, self.setup_bounds = _concatenate(self._setups)
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

    def _state(self, pose, speed, steering, target, goal_target=None, rows=None) -> RobotState:
        """What the observations and rewards read (of ``rows`` only, if given); ``goal_target``
        (default ``target``) is the point d_rg and θ_rg are measured to (the reward holds a
        path's waypoint over a step)."""
        ranges = sides = goal = None
        if rows is not None:
            pose, speed, steering, target = pose[rows], speed[rows], steering[rows], target[rows]
        if self.task.ranges or not self.task.goal:
            from fuzzynav.kernels import beams

            ranges = np.empty((len(pose), self.sensors.count))
            bounds = self.scene_bounds if rows is None else self.scene_bounds[rows]
            beams.read_worlds(self.scenes, bounds, np.ascontiguousarray(pose, dtype=float), self.sensors.angles,
                              0.5 * float(self.sensors.beam_width), float(self.sensors.max_range), ranges)
            sides = side_distances(ranges)
        if self.task.goal:
            goal = goal_inputs(pose, target if goal_target is None else goal_target)
        return RobotState(None, pose, speed, steering, target, ranges, goal, sides)

    def obstacle_offsets(self, row: int) -> np.ndarray:
        """Offsets ``(M, 2)`` of the moving obstacles of ``row``'s world at its episode time."""
        from fuzzynav.world import moving

        return moving.offsets(self.scenarios[row].world, [self.steps[row] * self.params.dt])[0]

    def place_obstacles(self, rows) -> None:
        """Write the moving obstacles of the ``rows`` (a mask) into their scenes where they are now."""
        from fuzzynav.kernels import traffic

        for row in np.flatnonzero(rows):
            world = None if self.scenarios[row] is None else self.scenarios[row].world
            if world is None or not world.moving:
                continue
            lo, hi = self.scene_bounds[row]
            traffic.place(world.scene, world.movers, self.obstacle_offsets(row), self.scenes[lo:hi])

    def clearance(self, pose) -> np.ndarray:
        """Signed distance (N,) of each robot centre to its world's obstacles or boundary."""
        from fuzzynav.kernels import scene

        out = np.empty((self.n, NEAREST_COLUMNS))
        scene.nearest_worlds(self.scenes, self.scene_bounds, np.ascontiguousarray(pose[:, :2], dtype=float), out)
        return np.minimum(out[:, 0], out[:, 4])

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
            self.steps += moving
            self.place_obstacles(moving)
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
        on_path = moving & ~np.isnan(self.forced_speed)
        if not on_path.any():
            return done, np.zeros(self.n, dtype=bool)
        from fuzzynav.kernels import step

        before = self.waypoint.copy()
        step.task_update_rows(self.path_setups, self.setup_bounds, self.waypoint,
                              np.ascontiguousarray(pose[:, :2], dtype=float), on_path, done, self.target)
        return done, self.waypoint != before


def _concatenate(arrays):
    """``(one array, bounds (N, 2))``: the distinct ``arrays`` (by identity; None: empty) end to
    end, and where row n's lies in it — how the kernels give each robot its own world or path."""
    bounds = np.zeros((len(arrays), 2), dtype=np.int64)
    placed, parts, size = {}, [], 0
    for row, array in enumerate(arrays):
        if array is None:
            continue
        if id(array) not in placed:
            placed[id(array)] = size
            parts.append(array)
            size += len(array)
        bounds[row] = placed[id(array)], placed[id(array)] + len(array)
    return (np.concatenate(parts) if parts else np.zeros(0)), bounds

"""N robots, each in its own world and episode, stepped together by the simulator's step.

A :class:`Fleet` holds the robots' arrays in the layout of :mod:`fuzzynav.kernels.step` and moves
them with one compiled call per step Δt (:func:`fuzzynav.kernels.worlds.step`), each robot as
the simulator moves its robots: the command clipped to the robot's limits (a path's constant
speed replacing the speed), the kinematic step (eq IV.2, or the exact arc), then the stop tests
in the simulator's order — collision (footprint disc against the obstacles and the boundary),
task done (goal within its tolerance, a path's waypoints switched as :mod:`fuzzynav.sim.tasks`
describes, the last one reached), time limit — and the sensing (range ring, nearest obstacle,
the task's target). The stop tests and sensing also run at a robot's start (step 0), as in the
simulator. The training environments (:class:`fuzzynav.learn.envs.RobotEnv`) and the Gymnasium
environments (:mod:`fuzzynav.gym`) are adapters over it: what a learner trains on is the
simulator's physics.

Each robot has its own world (its packed scene array; a world with moving obstacles a copy of
its own, where they are written at the robot's episode time before it moves,
:mod:`fuzzynav.kernels.traffic`) and its own set-up array (robot, sensors, task:
:meth:`Fleet.setup`). Its range ring is noise-free.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from fuzzynav.errors import InputError
from fuzzynav.kernels import step as core, traffic, worlds as kernel
from fuzzynav.kernels.records import Robots
from fuzzynav.robot.sensors import SensorRing
from fuzzynav.robot.tricycle import DEFAULT_PARAMS, TricycleParams
from fuzzynav.world import moving as motion
from fuzzynav.world.columns import Column


class Fleet:
    """``n`` robots of parameters ``params`` reading the ring ``sensors`` (``None``: no ranges)."""

    def __init__(self, n: int, params: TricycleParams = DEFAULT_PARAMS, sensors: SensorRing | None = None):
        if sensors is not None and sensors.noise_std > 0:
            raise InputError("the training and Gymnasium environments read noise-free sensors", field="sensors")
        self.n, self.params, self.sensors = int(n), params, sensors
        self.state = np.zeros((self.n, len(core.STATE_FIELDS)))
        self.ranges = np.zeros((self.n, 0 if sensors is None else sensors.count))
        self.status = np.zeros((self.n, 3), dtype=np.int64)
        self.worlds: list = [None] * self.n
        self._scenes: list = [None] * self.n  # each row's scene: its world's, or a copy when obstacles move
        self._setups: list = [None] * self.n
        self.scenes, self.scene_bounds = concatenate(self._scenes)  # filled by start
        self.setups, self.setup_bounds = concatenate(self._setups)
        self._moving = False  # some robot's world has moving obstacles (set by start)

    def setup(self, **task) -> np.ndarray:
        """A robot's set-up array: these robots and sensors, the task of :func:`task_fields`."""
        ring = self.sensors
        sensing: dict[str, Any] = {} if ring is None else {
            "max_range": ring.max_range, "angles": ring.angles, "half_beam": 0.5 * float(ring.beam_width)}
        return core.setup_array(self.params.array(), **sensing, **task_fields(**task))

    def start(self, rows, worlds, poses, setups, speed: float = 0.0) -> None:
        """Begin new episodes in ``rows``: robot ``rows[i]`` at pose ``poses[i]`` in
        ``worlds[i]`` (a :class:`~fuzzynav.world.world.World`) with set-up ``setups[i]``, at
        rest but for ``speed``; then their stop tests and sensing at step 0."""
        rows = np.asarray(list(rows), dtype=np.int64)
        for row, world, pose, setup in zip(rows, worlds, poses, setups):
            self.worlds[row] = world
            self._scenes[row] = world.scene.copy() if world.moving else world.scene
            self._setups[row] = setup
            self.state[row] = 0.0
            self.state[row, core.X:core.THETA + 1] = pose
            self.state[row, core.SPEED] = speed
            self.status[row] = 0
        self.scenes, self.scene_bounds = concatenate(self._scenes)
        self.setups, self.setup_bounds = concatenate(self._setups)
        self._moving = any(world is not None and world.moving for world in self.worlds)
        self._place(range(self.n), 0)
        kernel.settle_rows(self.scenes, self.scene_bounds, self.setups, self.setup_bounds, rows, self.state,
                           self.ranges, self.status)

    def step(self, steering, speed, live) -> np.ndarray:
        """One step Δt of the ``live`` rows still running, under commands (α, V) (scalars or
        (n,)); the others stand still at speed 0. Returns the rows that moved (bool (n,))."""
        moved = np.asarray(live, dtype=bool) & self.running
        if self._moving:
            self._place(np.flatnonzero(moved), 1)
        commands = np.empty((self.n, 2))
        commands[:, 0], commands[:, 1] = steering, speed
        kernel.step(self.scenes, self.scene_bounds, self.setups, self.setup_bounds, commands, moved,
                    Robots(self.state, self.ranges, self.status, True))
        return moved

    def obstacle_offsets(self, row: int, ahead: int = 0) -> np.ndarray:
        """Offsets ``(M, 2)`` of the moving obstacles of ``row``'s world at its episode's step
        count plus ``ahead``."""
        t = (self.status[row, core.STEPS] + ahead) * self.params.dt
        return motion.offsets(self.worlds[row], [t])[0]

    def _place(self, rows, ahead: int) -> None:
        """Write the moving obstacles of ``rows`` into their scenes where they are ``ahead``
        steps from now (:func:`fuzzynav.kernels.traffic.place`)."""
        for row in rows:
            world = self.worlds[row]
            if world is not None and world.moving:
                lo, hi = self.scene_bounds[row]
                traffic.place(world.scene, world.movers, self.obstacle_offsets(row, ahead), self.scenes[lo:hi])

    # -- what the adapters read (copies, but the outcome codes) -------------------------------
    pose = Column("state", slice(core.X, core.THETA + 1), "``(n, 3)`` poses (a copy).", copy=True)
    steering = Column("state", core.STEERING, "``(n,)`` steering applied at each robot's last step (a copy).",
                      copy=True)
    speed = Column("state", core.SPEED, "``(n,)`` speed applied at the last step, 0 standing still (a copy).",
                   copy=True)
    target = Column("state", slice(core.TARGET_X, core.TARGET_Y + 1), "``(n, 2)`` the point each robot aims at: "
                    "its goal or its path's current waypoint (a copy).", copy=True)
    waypoint = Column("status", core.WAYPOINT, "``(n,)`` index of each path's current waypoint (a copy).", copy=True)
    steps = Column("status", core.STEPS, "``(n,)`` steps Δt of each robot's episode so far (a copy).", copy=True)
    outcome = Column("status", core.OUTCOME, "``(n,)`` outcome codes of :mod:`fuzzynav.kernels.step` (RUNNING, "
                     "REACHED, COLLISION, TIMEOUT).")

    @property
    def clearance(self) -> np.ndarray:
        """``(n,)`` signed distance of each robot's centre to its world's obstacles or boundary,
        as its last stop test measured it."""
        return np.minimum(self.state[:, core.OBSTACLE_DISTANCE], self.state[:, core.BOUNDARY])

    @property
    def running(self) -> np.ndarray:
        """``(n,)`` bool: the robot's episode goes on."""
        return self.outcome == core.RUNNING

    @property
    def collided(self) -> np.ndarray:
        """``(n,)`` bool: the robot's episode ended on a collision."""
        return self.outcome == core.COLLISION

    @property
    def reached(self) -> np.ndarray:
        """``(n,)`` bool: the robot's task is done (goal reached, path completed)."""
        return self.outcome == core.REACHED


def task_fields(*, goal=None, tolerance: float = -math.inf, path=None, task: int = core.GOAL) -> dict[str, Any]:
    """The task's keywords of :func:`fuzzynav.kernels.step.setup_array`: the path task of
    ``path`` (a :class:`~fuzzynav.world.scenario.PathTask`: its waypoints, zone, constant speed
    and switching rule), else ``task`` (goal or target code) at ``goal`` (x, y) within
    ``tolerance`` (−∞ and no goal: no task, the robot runs until it collides)."""
    if path is not None:
        return {"task": core.PATH, "tolerance": path.tolerance, "forced_speed": path.speed,
                "passed": path.switching == "passed", "goal": path.waypoints[0], "waypoints": path.waypoints}
    return {"task": task, "tolerance": tolerance, "goal": (0.0, 0.0) if goal is None else goal}


def concatenate(arrays) -> tuple[np.ndarray, np.ndarray]:
    """``(one array, bounds (N, 2))``: the distinct ``arrays`` (by identity; None: empty) end to
    end, and where row n's lies in it — how the kernels give each robot its own world or task."""
    bounds = np.zeros((len(arrays), 2), dtype=np.int64)
    placed: dict[int, int] = {}
    parts, size = [], 0
    for row, array in enumerate(arrays):
        if array is None:
            continue
        if id(array) not in placed:
            placed[id(array)] = size
            parts.append(array)
            size += len(array)
        bounds[row] = placed[id(array)], placed[id(array)] + len(array)
    return (np.concatenate(parts) if parts else np.zeros(0)), bounds

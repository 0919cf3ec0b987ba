"""N robots, each in its own episode, stepped together: the hot path of every fuzzynav environment.

The single environment (:class:`~fuzzynav.gym.env.FuzzynavEnv`) is a batch of one, the vector
environment (:class:`~fuzzynav.gym.vector.FuzzynavVectorEnv`) a batch of N, so both compute the
same numbers. One decision lasts ``decision_steps`` steps Δt of the simulator's own step: a
:class:`~fuzzynav.world.fleet.Fleet` moves the robots, each in its own world, and runs the stop
tests in the simulator's order — collision, then the task (goal within its tolerance; a path's
waypoints switched as :mod:`fuzzynav.sim.tasks` describes) — and the sensing; the moving obstacles
of a row's world are where they are at that row's episode time (docs/dynamic.md). This module
adds what an environment reads: the observations' inputs (d_rg, θ_rg, the side distances) and
which rows collided, reached their goal or switched a waypoint during the decision.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.control.learned import goal_inputs, side_distances
from fuzzynav.learn.envs.env import RobotState
from fuzzynav.robot.sensors import SensorRing
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.world.fleet import Fleet
from fuzzynav.world.limits import steps_see_collisions


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
        self.fleet = Fleet(self.n, params, self.sensors if task.ranges or not task.goal else None)
        self.state: RobotState | None = None

    @property
    def pose(self) -> np.ndarray:
        """``(N, 3)`` poses."""
        return self.fleet.pose

    @property
    def target(self) -> np.ndarray:
        """``(N, 2)`` each row's goal or current waypoint."""
        return self.fleet.target

    # -- episodes ----------------------------------------------------------------------------
    def start(self, rows, scenarios) -> None:
        """Begin new episodes in ``rows`` on ``scenarios`` (one each): start pose, zero command."""
        rows = list(rows)
        setups = []
        for row, scenario in zip(rows, scenarios):
            self.scenarios[row] = scenario
            if scenario.task == "path":
                setups.append(self.fleet.setup(path=scenario.path))
            elif scenario.goal is not None and self.task.name != "path" and self.task.goal:
                setups.append(self.fleet.setup(goal=scenario.goal.position, tolerance=scenario.goal.tolerance))
            else:
                setups.append(self.fleet.setup())
        for scenario in scenarios:  # the batch's robot drives these worlds: its movers checked against it
            steps_see_collisions(scenario.world, self.params, self.params.radius)
        self.fleet.start(rows, [s.world for s in scenarios], [s.start for s in scenarios], setups)
        self.state = self._state()

    def _state(self, goal_target=None) -> RobotState:
        """What the observations and rewards read; ``goal_target`` (default the targets) is the
        point d_rg and θ_rg are measured to (the reward holds a path's waypoint over a step)."""
        fleet = self.fleet
        pose, target = fleet.pose, fleet.target
        ranges = sides = goal = None
        if fleet.sensors is not None:
            ranges = fleet.ranges.copy()
            sides = side_distances(ranges)
        if self.task.goal:
            goal = goal_inputs(pose, target if goal_target is None else goal_target)
        return RobotState(None, pose, fleet.speed, fleet.steering, target, ranges, goal, sides)

    def obstacle_offsets(self, row: int) -> np.ndarray:
        """Offsets ``(M, 2)`` of the moving obstacles of ``row``'s world at its episode time."""
        return self.fleet.obstacle_offsets(row)

    # -- stepping ----------------------------------------------------------------------------
    def step(self, steering, speed, live):
        """One decision of the ``live`` rows (others stand still); returns ``(before, after, held,
        collided, done, passed)``: ``held`` measures d_rg and θ_rg to the targets the step began
        with (the reward of a waypoint just switched), ``done`` is the goal reached or the path
        completed, ``passed`` a waypoint switched."""
        before = self.state
        fleet = self.fleet
        target, waypoint = fleet.target, fleet.waypoint
        steering, speed = (np.broadcast_to(np.asarray(v, dtype=float), (self.n,)) for v in (steering, speed))
        for _ in range(self.decision_steps):
            if not (live & fleet.running).any():
                break
            fleet.step(steering, speed, live)
        passed = live & (fleet.waypoint != waypoint)
        after = self._state()
        held = after if not passed.any() else self._state(target)
        self.state = after
        return before, after, held, live & fleet.collided, live & fleet.reached, passed

"""B robot episodes stepped together: the training environment of chapter VI.

The robots move by the simulator's own step (a :class:`~fuzzynav.world.fleet.Fleet`: the
command clipped, tricycle kinematics eq IV.2, the stop tests in the simulator's order, the range
ring), without the simulator's per-step bookkeeping. It follows the protocol of :func:`fuzzynav.learn.checkpoint.train_loop`::

    env.reset(rng) -> obs
    env.step(action, rng) -> obs, reward, terminated, truncated, info

Three plug-ins make one environment per task:

- a *layout* (:mod:`.layouts`) draws the world, start poses and goals of a batch of episodes;
- ``observe(state) -> obs`` maps the :class:`RobotState` to what the learner sees (zone/sector
  indices for tabular Q-learning, input vectors for fuzzy Q-learning);
- ``command(action, state) -> (steering, speed)`` maps the learner's action to the robot's
  commands (e.g. steering learned at a constant speed, or speed learned under a fixed steering);
- ``reward(before, after, collided, reached)`` is one of :mod:`fuzzynav.learn.rewards`;
- ``sides(ranges) -> (B, 3)`` reads the front/right/left distances from the ring (default
  :func:`~fuzzynav.control.learned.side_distances`; the wall follower's single rays:
  :func:`~fuzzynav.control.learned.single_rays`).

An episode ends (``terminated``) on a collision — the footprint disc touching an obstacle or the
workspace boundary ("the walls of the workspace", eq VI.2) — or when the goal is within
``tolerance``, tested first at the start (a robot drawn in collision or at its goal ends at its
first decision without moving, as the simulator ends it at step 0); it is ``truncated`` after ``max_steps`` decisions. A decision lasts
``decision_steps`` steps Δt (default 1): a longer decision period makes the effect of one choice
on the next state — hence the gap between the candidates' qualities — larger. Success (``info["success"]``) is reaching
the goal in goal tasks, and lasting ``max_steps`` without collision in tasks without a goal.
Rows whose episode has ended stand still until the whole batch is done. An episode starts at rest
unless ``start_speed`` says otherwise (a speed phase starting at the steering phase's constant speed);
``timeout_reward`` is added to the reward of a row whose episode runs out of decisions.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from fuzzynav.control.learned import as_column, goal_inputs, side_distances
from fuzzynav.robot.sensors import SensorRing
from fuzzynav.robot.tricycle import DEFAULT_PARAMS, TricycleParams
from fuzzynav.world.fleet import Fleet
from fuzzynav.world.scenario import DEFAULT_GOAL_TOLERANCE
from fuzzynav.world.world import World


@dataclass(frozen=True)
class RobotState:
    """What the plug-ins see of a batch after a step. ``goal`` (B, 2) holds (d_rg, θ_r − θ_d)
    (:func:`~fuzzynav.control.learned.goal_inputs`), ``sides`` (B, 3) the front/right/left
    distances (the env's ``sides`` reading); either is ``None`` when the
    task has no goal / no sensors."""

    world: World
    pose: np.ndarray  # (B, 3)
    speed: np.ndarray  # (B,) applied at the last step
    steering: np.ndarray  # (B,)
    target: np.ndarray | None = None  # (B, 2)
    ranges: np.ndarray | None = None  # (B, 7)
    goal: np.ndarray | None = None  # (B, 2)
    sides: np.ndarray | None = None  # (B, 3)


class RobotEnv:
    """``batch`` episodes of a task in lock-step (see the module docstring)."""

    def __init__(self, layout, observe, command, reward, *, batch: int, max_steps: int,
                 tolerance: float = DEFAULT_GOAL_TOLERANCE, params: TricycleParams = DEFAULT_PARAMS, sensors: SensorRing | None = None,
                 decision_steps: int = 1, sides=side_distances, start_speed: float = 0.0,
                 timeout_reward: float = 0.0):
        self.layout, self.observe, self.command, self.reward = layout, observe, command, reward
        self.batch = int(batch)
        self.max_steps = int(max_steps)
        self.tolerance = float(tolerance)
        self.params = params
        self.sensors = sensors
        self.decision_steps = int(decision_steps)
        self.sides = sides
        self.start_speed = float(start_speed)
        self.timeout_reward = float(timeout_reward)
        self.state: RobotState | None = None
        self.fleet = Fleet(self.batch, params, sensors)

    def _state(self, world, target) -> RobotState:
        fleet = self.fleet
        pose = fleet.pose
        ranges = sides = goal = None
        if self.sensors is not None:
            ranges = fleet.ranges.copy()
            sides = self.sides(ranges)
        if target is not None:
            goal = goal_inputs(pose, target)
        return RobotState(world, pose, fleet.speed, fleet.steering, target, ranges, goal, sides)

    def reset(self, rng: np.random.Generator):
        """New episodes: the layout's world, starts and goals; zero steering, speed ``start_speed``."""
        world, pose, target = self.layout.sample(rng, self.batch)
        if self.fleet.n != self.batch:  # the trainer shrank the batch (a smaller last batch)
            self.fleet = Fleet(self.batch, self.params, self.sensors)
        fleet = self.fleet
        rows = range(self.batch)
        setups = [fleet.setup() if target is None else fleet.setup(goal=target[n], tolerance=self.tolerance)
                  for n in rows]
        fleet.start(rows, [world] * self.batch, pose, setups, speed=self.start_speed)
        self.state = self._state(world, target)
        self.k = 0
        self.done = np.zeros(self.batch, dtype=bool)
        return self.observe(self.state)

    def step(self, action, rng: np.random.Generator):
        """Apply the learner's actions for one decision period (rows already finished stand still).

        The period is ``decision_steps`` steps Δt: the learner's action is held while ``command``
        is re-evaluated on the current state at every step (so a goal seeker blended into the
        command keeps steering); the episode may end at any of them; the reward compares the
        states at both ends of the period, the speed at the end being the one the robot last
        drove at (a row that reached the goal mid-period arrived at that speed, not at rest).
        """
        before = self.state
        now = before
        live = ~self.done
        driven = before.speed.copy()
        for _ in range(self.decision_steps):
            steering, speed = self.command(action, now)
            moved = self.fleet.step(as_column(steering, self.batch), as_column(speed, self.batch), live)
            now = self._state(now.world, now.target)
            driven = np.where(moved, now.speed, driven)
        collided, reached = live & self.fleet.collided, live & self.fleet.reached
        reward = self.reward(before, replace(now, speed=driven) if self.decision_steps > 1 else now, collided, reached)
        self.k += 1
        terminated = collided | reached
        truncated = np.full(self.batch, self.k >= self.max_steps)
        if self.timeout_reward:
            reward = np.where(truncated & ~terminated & ~self.done, reward + self.timeout_reward, reward)
        success = reached if now.goal is not None else truncated & ~collided
        self.done = self.done | terminated | truncated
        self.state = now
        return self.observe(now), reward, terminated, truncated, {"success": success, "collision": collided}

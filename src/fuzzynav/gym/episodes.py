"""What the single and the vector environments share: spaces, observations, rewards, episode ends.

:class:`Episodes` wraps a :class:`~fuzzynav.gym.core.RobotBatch` with the Gymnasium bookkeeping
of N episodes: the spaces of a task (:mod:`.tasks`), the decoding of actions, the observation
vector, the reward (``thesis`` or ``dense``), ``terminated`` (collision; goal reached or path
completed) against ``truncated`` (``max_steps`` decisions), and the ``info`` fields:

- ``reward_heads`` — the task's thesis reinforcement signals, one column each (:mod:`.tasks`);
- ``success`` — goal reached / path completed, or for wall following the episode lasted without
  a collision; ``collision`` — the footprint touched an obstacle or the boundary.
"""

from __future__ import annotations

import math

import numpy as np
from gymnasium import spaces

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.gym.actions import check_actions
from fuzzynav.gym.core import RobotBatch
from fuzzynav.gym.sources import ScenarioSource, check_robot, check_task, make_source
from fuzzynav.gym.tasks import REWARDS, TASKS, dense_reward
from fuzzynav.robot.tricycle import DEFAULT_PARAMS, TricycleParams

ACTIONS = ("continuous", "discrete")
OPTIONS = ("actions", "reward", "scenario", "worlds", "n_worlds", "world_seed", "max_steps", "decision_steps", "params")


def scale_actions(actions, params=DEFAULT_PARAMS) -> np.ndarray:
    """Continuous actions in [−1, 1] (the normalised Box) to (α, V_r): α = a_0 · α_max,
    V_r = (a_1 + 1) / 2 · V_max (rows (N, 1) for path tracking: α only)."""
    actions = np.clip(actions, -1.0, 1.0)
    steering = actions[:, :1] * params.max_steering
    if actions.shape[1] == 1:
        return steering
    return np.column_stack([steering, 0.5 * (actions[:, 1:2] + 1.0) * params.max_speed])


def unscale_actions(steering, speed=None, params=DEFAULT_PARAMS) -> np.ndarray:
    """Inverse of :func:`scale_actions`: (α, V_r) → the normalised Box, float32."""
    columns = [np.asarray(steering, dtype=float) / params.max_steering]
    if speed is not None:
        columns.append(2.0 * np.asarray(speed, dtype=float) / params.max_speed - 1.0)
    return np.clip(np.column_stack(columns), -1.0, 1.0).astype(np.float32)


class Episodes:
    """N episodes of one task. Options are the environments' keyword arguments
    (:class:`~fuzzynav.gym.env.FuzzynavEnv`), each checked before anything is built: ``n_worlds``
    in [1, 100,000], ``world_seed`` in [0, 2**63 - 1], ``max_steps`` in [1, 10**7],
    ``decision_steps`` in [1, 1,000] (``docs/limits.md``); actions as :mod:`.actions` says."""

    def __init__(self, n: int, task: str, *, actions: str = "continuous", reward: str = "thesis", scenario=None,
                 worlds: str | None = None, n_worlds: int = 1000, world_seed: int = 0, max_steps: int | None = None,
                 decision_steps: int | None = None, params=DEFAULT_PARAMS):
        if not isinstance(task, str) or task not in TASKS:
            raise InputError(f"unknown task {task!r} (known: {', '.join(TASKS)})", field="task")
        if actions not in ACTIONS:
            raise InputError(f"must be one of {', '.join(ACTIONS)}, got {actions!r}", field="actions")
        if reward not in REWARDS:
            raise InputError(f"must be one of {', '.join(REWARDS)}, got {reward!r}", field="reward")
        if worlds is not None:
            validation.text(worlds, field="worlds", max_length=100)
        if not isinstance(params, TricycleParams):
            raise InputError(f"must be a TricycleParams, got {type(params).__name__}", field="params")
        validation.count(n_worlds, field="n_worlds", hi=validation.MAX_WORLDS)
        validation.seed(world_seed, field="world_seed")
        self.task = TASKS[task]
        self.discrete = actions == "discrete"
        self.reward_kind = reward
        self.source = make_source(task, scenario, worlds, n_worlds, world_seed)
        self.max_steps = validation.count(self.task.max_steps if max_steps is None else max_steps, field="max_steps",
                                          hi=validation.MAX_EPISODE_STEPS)
        decision = validation.count(self.task.decision_steps if decision_steps is None else decision_steps,
                                    field="decision_steps", hi=validation.MAX_DECISION_STEPS)
        self.batch = RobotBatch(n, self.task, params=params, decision_steps=decision)
        self.candidates = self.task.candidates()
        self.params = params
        self.steps = np.zeros(n, dtype=int)
        self.d_high = float(self._diagonal())
        self.observation_space, self.action_space = self._spaces(params)

    def _diagonal(self) -> float:
        """Largest d_rg possible: the diagonal of the largest world (20 m × 20 m unless scenarios say)."""
        scenarios = getattr(self.source, "scenarios", ())
        return max([20.0 * math.sqrt(2.0)] + [math.hypot(s.world.width, s.world.height) for s in scenarios])

    def _spaces(self, params):
        low, high = [], []
        if self.task.goal:
            low += [0.0, -math.pi]
            high += [self.d_high, math.pi]
        if self.task.ranges or not self.task.goal:
            low += [0.0] * self.batch.sensors.count
            high += [self.batch.sensors.max_range] * self.batch.sensors.count
        observation = spaces.Box(np.array(low, dtype=np.float32), np.array(high, dtype=np.float32), dtype=np.float32)
        if self.discrete:
            return observation, spaces.Discrete(len(self.candidates))
        size = 1 if self.task.steer_only else 2
        return observation, spaces.Box(-1.0, 1.0, (size,), dtype=np.float32)

    # -- per step ----------------------------------------------------------------------------
    def observe(self, state=None) -> np.ndarray:
        """Observations (N, n_obs) float32 of the current state (module docstring of :mod:`.tasks`)."""
        state = self.batch.state if state is None else state
        parts = []
        if self.task.goal:
            parts.append(np.column_stack([np.minimum(state.goal[:, 0], self.d_high), state.goal[:, 1]]))
        if state.ranges is not None and (self.task.ranges or not self.task.goal):
            parts.append(state.ranges)
        return np.concatenate(parts, axis=1).astype(np.float32)

    def decode(self, actions, live=None, *, single: bool = False) -> tuple[np.ndarray, np.ndarray]:
        """(steering (N,), speed (N,)) of a batch of actions (indices or (α, V_r) rows; ``single``:
        one environment's action), checked by :func:`.actions.check_actions` (rows ``live``)."""
        checked = check_actions(actions, self.action_space, self.batch.n, live, single=single)
        if self.discrete:
            values = self.candidates[np.where(live if live is not None else True, checked, 0)]
        else:
            values = scale_actions(np.where(np.isfinite(checked), checked, 0.0), self.params)
        if self.task.steer_only:
            return values[:, 0], np.zeros(len(values))
        return values[:, 0], values[:, 1]

    def start(self, rows, rngs, scenarios=None) -> None:
        """New episodes in ``rows``, each drawn from its own generator (or on the given scenarios)."""
        rows = list(rows)
        if scenarios is None:
            scenarios = [self.source.draw(rng) for rng in rngs]
        else:
            scenarios = validation.sequence(scenarios, field="scenarios")
            if len(scenarios) != len(rows):
                raise InputError(f"{len(scenarios)} scenarios for {len(rows)} environments", field="scenarios")
            scenarios = [ScenarioSource(s).scenarios[0] for s in scenarios]
        for scenario in scenarios:  # (its robot, imperfections or sensor ring were ignored)
            check_task(self.task, scenario)
            check_robot(self.params, scenario)
        self.batch.start(rows, scenarios)
        self.steps[rows] = 0

    def step(self, actions, live, *, single: bool = False):
        """One decision of the ``live`` rows: (rewards, terminated, truncated, info arrays)."""
        steering, speed = self.decode(actions, live, single=single)
        before, after, held, collided, done, passed = self.batch.step(steering, speed, live)
        self.steps += live
        reached = done | passed if self.task.name == "path" else done
        heads = np.column_stack([reward(before, held, collided, reached) for _, reward in self.task.heads])
        if self.reward_kind == "thesis":
            rewards = heads.sum(axis=1)
        else:
            rewards = dense_reward(self.task, before, held, collided, done)
        terminated = live & (collided | done)
        truncated = live & ~terminated & (self.steps >= self.max_steps)
        success = (truncated & ~collided) if self.task.success_on_survival else done
        info = {"reward_heads": heads, "success": live & success, "collision": live & collided}
        return np.where(live, rewards, 0.0), terminated, truncated, info

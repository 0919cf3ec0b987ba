"""The four Gymnasium tasks: what the agent sees, what it commands, how it is rewarded.

A :class:`TaskSpec` holds everything that differs between tasks; the environments
(:mod:`.env`, :mod:`.vector`) and the batch core (:mod:`.core`) are shared.

=====================  ==================================================================  =====================
task                   observation (float32)                                               thesis reward heads
=====================  ==================================================================  =====================
``goal``               d_rg, θ_rg (eq IV.6, eq IV.8 as the thesis' tables read it)         VI.2, VI.14
``avoid``              d_rg, θ_rg, the seven readings d_1…d_7 (§IV.7, 4 m range)           VI.2, VI.20, VI.21
``wall``               the seven readings d_1…d_7                                          VI.21 (§VI.5.3), VI.22
``path``               d_rg, θ_rg towards the current waypoint (§V.3)                      VI.2 per waypoint
=====================  ==================================================================  =====================

θ_rg is θ_r − θ_d (:func:`~fuzzynav.control.learned.goal_inputs`): negative when the goal is on
the left, the sign of the thesis' tables. Actions: a continuous ``Box`` [−1, 1]² scaled to the
robot's limits — α = a_0 · π/4, V_r = (a_1 + 1) / 2 · 4 m/s
(:func:`~fuzzynav.gym.episodes.scale_actions`; path tracking: α only, the path fixes the speed) —
or ``Discrete`` over the thesis' candidate conclusions (:data:`STEERING3` eq VI.12 / VI.18 ×
the task's candidate speeds; path tracking: :data:`STEERING5`, eq VI.15).

Rewards (``reward=``):

- ``"thesis"`` — the sum of the task's thesis reinforcement signals of :mod:`fuzzynav.learn.rewards`,
  each also returned alone in ``info["reward_heads"]`` (the thesis learns steering and speed from
  separate signals; the FQL agent does too). Obstacle avoidance adds the goal-seeking signal VI.2
  to VI.20–VI.21, which say nothing about the goal: the avoider of §VI.5.2 is trained inside a
  navigator whose goal seeking reaches the goal; an agent that drives alone needs the goal in its
  reward. Path tracking has no reinforcement signal in the thesis (its trackers are supervised,
  chapter V): it uses VI.2 towards the waypoint aimed at when the step began, "goal reached" being
  that waypoint left behind.
- ``"dense"`` — a shaped signal for deep RL: the progress towards the target in metres
  (d_rg before − d_rg after, the target held over the step), −0.01 per step, +10 on success,
  −10 on a collision; wall following: +0.1 per step, −0.1 × min(1, |d_side − 1 m|) with d_side
  the nearer of the right and left distances, −10 on a collision.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fuzzynav.fuzzy.constants import SPEED_SINGLETONS, STEERING_SINGLETONS
from fuzzynav.fuzzy.systems_navigation import D_MAX, WALL_D_M, WALL_D_S
from fuzzynav.learn import rewards

STEERING3 = tuple(STEERING_SINGLETONS[label] for label in ("NG", "Z", "PG"))  # eq VI.12 / VI.18
STEERING5 = tuple(STEERING_SINGLETONS[label] for label in ("NG", "NM", "Z", "PM", "PG"))  # eq VI.15
GOAL_SPEEDS = tuple(SPEED_SINGLETONS[label] for label in ("F", "M", "G"))  # eq VI.13, of Fig IV.8
AVOID_SPEEDS = (0.5, 1.0, 1.8)  # candidate speeds near obstacles (the avoider's F, M, G)
REWARDS = ("thesis", "dense")
DENSE_GOAL, DENSE_COLLISION, DENSE_STEP = 10.0, -10.0, -0.01
WALL_KEEP = 1.0  # m: the side distance the dense wall-following reward asks for


@dataclass(frozen=True)
class TaskSpec:
    """One task: observation layout, candidate actions, reward heads, episode defaults.

    ``goal``: the observation starts with (d_rg, θ_rg); ``ranges``: it holds the seven readings;
    ``steer_only``: the action is α alone (the path sets the speed); ``success_on_survival``:
    success is lasting the episode without a collision (no goal).
    """

    name: str
    goal: bool
    ranges: bool
    heads: tuple  # (name, reward callable of learn.rewards)
    steering: tuple
    speeds: tuple
    max_steps: int
    decision_steps: int
    steer_only: bool = False
    success_on_survival: bool = False

    @property
    def head_names(self) -> tuple[str, ...]:
        return tuple(name for name, _ in self.heads)

    def candidates(self) -> np.ndarray:
        """The Discrete action set: (n, 2) (α, V_r) pairs, or (n, 1) α for path tracking."""
        if self.steer_only:
            return np.array(self.steering, dtype=float)[:, None]
        return np.array([(a, v) for v in self.speeds for a in self.steering], dtype=float)


TASKS = {
    "goal": TaskSpec("goal", goal=True, ranges=False,
                     heads=(("VI.2", rewards.GoalSteeringReward()), ("VI.14", rewards.GoalSpeedReward())),
                     steering=STEERING3, speeds=GOAL_SPEEDS, max_steps=300, decision_steps=1),
    "avoid": TaskSpec("avoid", goal=True, ranges=True,
                      heads=(("VI.2", rewards.GoalSteeringReward()), ("VI.20", rewards.AvoidSteeringReward(D_MAX)),
                             ("VI.21", rewards.AvoidSpeedReward(D_MAX, low=1.0))),
                      steering=STEERING3, speeds=AVOID_SPEEDS, max_steps=200, decision_steps=3),
    "wall": TaskSpec("wall", goal=False, ranges=True,
                     heads=(("VI.21", rewards.WallSteeringReward(WALL_D_M)),
                            ("VI.22", rewards.WallSpeedReward(WALL_D_S))),
                     steering=STEERING3, speeds=AVOID_SPEEDS, max_steps=100, decision_steps=3,
                     success_on_survival=True),
    "path": TaskSpec("path", goal=True, ranges=False, heads=(("VI.2", rewards.GoalSteeringReward()),),
                     steering=STEERING5, speeds=(), max_steps=400, decision_steps=1, steer_only=True),
}


def dense_reward(task: TaskSpec, before, after, collided, reached) -> np.ndarray:
    """The shaped reward of the module docstring, (B,)."""
    if task.goal:
        progress = before.goal[:, 0] - after.goal[:, 0]
        return progress + DENSE_STEP + DENSE_GOAL * reached + DENSE_COLLISION * collided
    side = after.sides[:, 1:].min(axis=1)
    return 0.1 - 0.1 * np.minimum(1.0, np.abs(side - WALL_KEEP)) + DENSE_COLLISION * collided

"""The thesis' fuzzy Q-learning of obstacle avoidance (§VI.5.2) through ``fuzzynav/ObstacleAvoidance-v0``.

What ``fuzzynav train fql-avoid`` learns (:mod:`fuzzynav.learn.tasks.fql_avoid`), driven through
the Gymnasium environment's ``step`` instead of the training simulator: the avoider's rules over
the front, right and left distances and which side is more open (Fig VI.17 and the openness
input of that task), inside the goal navigator of Figs VI.20 and VI.24
(:class:`~fuzzynav.control.learned.LearnedAvoidanceNavigator`: chapter IV goal seeking where all
three distances are far, its supervisor handing the robot to goal seeking where the way is
clear). Two phases share the step budget, as the task shares its episodes
(:data:`~fuzzynav.learn.tasks.fql_avoid.AVOID_SPEED_SHARE`): the steering conclusions from
reward VI.20 at the constant speed of the task, starting from the initial table ``prior``
(``thesis``: the a-priori conclusions of §IV.7, turn away from the nearer side; ``none``: q = 0
only, :func:`~fuzzynav.learn.tasks.fql_avoid.initial_tables`); then, the extracted steering frozen, the speeds from
VI.21 — each reward taken from ``info["reward_heads"]``. The environment's decision (3 steps Δt)
is the task's learning decision. Observations carry d_rg and θ_rg, the goal inputs the navigator
reads, and the seven readings.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.control.learned import LearnedAvoidanceNavigator, avoidance_inputs
from fuzzynav.fuzzy.constants import ALPHA_MAX
from fuzzynav.fuzzy.systems_navigation import D_MAX
from fuzzynav.gym.episodes import unscale_actions
from fuzzynav.learn.envs import GridPremise
from fuzzynav.learn.tasks.common import fql_learner, grid_system, output_variable, steering_episodes
from fuzzynav.learn.tasks.fql_avoid import (
    AVOID_SPEED,
    AVOID_SPEED_SHARE,
    AVOID_SPEEDS,
    AVOID_STEERING,
    _avoid_candidates,
    avoid_inputs,
    avoid_rate,
    avoid_system,
    free_rules,
    initial_tables,
    prior_tolerance,
)

HEADS = ("VI.20", "VI.21")  # the reward of the steering phase, of the speed phase


class NavigatorAvoidance:
    """One training run of the avoider for ``batch`` robots and ``total_steps`` environment steps
    (module docstring); :meth:`begin` / :meth:`step` return the environment's actions."""

    def __init__(self, batch: int, total_steps: int, head_names, prior: str = "thesis"):
        self.open_side = True
        self.initial = initial_tables(prior, self.open_side)
        self.tolerance = prior_tolerance(prior, batch)
        self.free = free_rules(self.open_side)
        template = grid_system(avoid_inputs(self.open_side),
                               [output_variable("alpha", AVOID_STEERING, (-ALPHA_MAX, ALPHA_MAX))],
                               [["Z"] * (self.free[-1] + 1)], "premise", "")
        self.premise = GridPremise(template)
        self.navigator = LearnedAvoidanceNavigator(template)  # drives training, as the fql-avoid task
        self.batch = batch
        self.switch_at = steering_episodes(max(int(total_steps), 2), AVOID_SPEED_SHARE)  # steps of phase 1
        self.columns = [list(head_names).index(h) for h in HEADS]
        self.steer = fql_learner(self.premise, _avoid_candidates(AVOID_STEERING, self.open_side), 0.0, batch,
                                 prior=self.initial[0], alpha=avoid_rate())
        self.speed = None  # the speed learner, from the switch on
        self.steering_rules = None  # the extracted steering, frozen at the switch
        self.episodes_at_switch = 0
        self._controller = (None, None)  # (rules' key, the navigator of those rules)

    # -- what the learner sees and how it drives ---------------------------------------------
    def observe(self, obs):
        """(avoider inputs (B, 4), readings (B, 7), goal inputs (B, 2)); where the supervisor hands
        the robot to goal seeking the distances read "all far" (the avoider does not act there)."""
        from fuzzynav.kernels import learned as learned_kernels

        obs = np.asarray(obs, dtype=float)
        goal, ranges = np.ascontiguousarray(obs[:, :2]), np.ascontiguousarray(obs[:, 2:])
        x = avoidance_inputs(ranges, self.open_side)
        learned_kernels.seeking_far(ranges, goal, self.navigator.supervisor, D_MAX, x)
        return x, ranges, goal

    def drive(self, seen, alpha, speed=None):
        """The navigator's command, as normalised actions, for the avoider's shares ``alpha`` and
        ``speed`` (None: the constant speed of the steering phase on the avoider's share)."""
        x, ranges, goal = seen
        free = self.premise.firing_strengths(x, normalise=False)[:, self.free].sum(axis=1)
        speed = (1.0 - free) * AVOID_SPEED if speed is None else speed
        steering, velocity = self.navigator.drive(alpha, speed, free, ranges, goal)[:2]
        return unscale_actions(steering, velocity)

    def _act(self, seen, values):
        if self.speed is None:
            return self.drive(seen, values[:, 0])
        return self.drive(seen, self.steer.action(seen[0], self.steering_rules)[:, 0], values[:, 0])

    # -- learning ----------------------------------------------------------------------------
    def begin(self, obs, rng):
        seen = self.observe(obs)
        return self._act(seen, self.steer.begin(seen[0], rng))

    def step(self, heads, obs, terminated, rng, active, steps: int, episodes: int):
        """Learn from the last decision (reward ``heads`` (B, H) of the environment), return the
        next actions; at ``steps`` past the steering share, freeze the steering, start the speeds."""
        seen = self.observe(obs)
        learner = self.steer if self.speed is None else self.speed
        column = self.columns[0 if self.speed is None else 1]
        learner.episode = (episodes - self.episodes_at_switch) // self.batch  # ε and β: one tick per batch
        values = learner.step(heads[:, column], seen[0], terminated, rng, active=active)
        if self.speed is None and steps >= self.switch_at:
            self.steering_rules = self.steer.greedy_indices(self.tolerance)
            self.speed = fql_learner(self.premise, _avoid_candidates(AVOID_SPEEDS, self.open_side), 0.0, self.batch,
                                     prior=self.initial[1], alpha=avoid_rate())
            self.episodes_at_switch = episodes
            values = self.speed.begin(seen[0], rng)
        return self._act(seen, values)

    # -- the learned controller --------------------------------------------------------------
    def _indices(self):
        """The extracted conclusions (candidate indices) of the learned rules: steering, speed (or None)."""
        learned = self.free[0]
        steering = self.steer.greedy_indices(self.tolerance)[0, 0, :learned]
        return steering, None if self.speed is None else self.speed.greedy_indices(self.tolerance)[0, 0, :learned]

    def system(self):
        """The learned avoider as a TS0 system (steering; and speeds once the speed phase ran)."""
        return avoid_system(*self._indices(), self.open_side)

    def controller(self) -> LearnedAvoidanceNavigator:
        """The navigator a ``fql-avoid`` model of :meth:`system` runs (rebuilt when the rules change)."""
        key = tuple(None if i is None else i.tobytes() for i in self._indices())
        if self._controller[0] != key:
            self._controller = key, LearnedAvoidanceNavigator(self.system(), constant_speed=AVOID_SPEED)
        return self._controller[1]

    def predict(self, obs):
        """Normalised actions of :meth:`controller` for observations (B, 9)."""
        _, ranges, goal = self.observe(obs)
        navigator = self.controller()
        shares = navigator.avoider_shares(avoidance_inputs(ranges, self.open_side))
        steering, velocity = navigator.drive(*shares, ranges, goal)[:2]
        return unscale_actions(steering, velocity)

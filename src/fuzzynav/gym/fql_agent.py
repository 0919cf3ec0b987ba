"""Fuzzy Q-learning (Algorithm VI.1) as an agent of the fuzzynav Gymnasium environments.

:class:`FQLAgent` trains a :class:`~fuzzynav.learn.fql.FuzzyQLearner` through ``reset`` /
``step`` of a :class:`~fuzzynav.gym.vector.FuzzynavVectorEnv` (or one
:class:`~fuzzynav.gym.env.FuzzynavEnv`), so FQL and any Gymnasium agent meet the same task, worlds
and step budget (any Gymnasium vector environment of these tasks goes through the same
``reset`` / ``step``); :meth:`FQLAgent.predict` is the extracted controller (every rule's best
conclusion) and :meth:`FQLAgent.rule_base` exports it as an ordinary TS0
:class:`~fuzzynav.fuzzy.FuzzySystem` (savable, printable as a rule table).

As in the thesis, steering and speed are separate heads, each learned from its own
reinforcement signal — here the environment's ``info["reward_heads"]`` (:mod:`.tasks`). The rule
bases (:data:`DESIGNS`):

- ``goal`` — the 35-rule grid of chapter IV's goal seeker (d_rg × θ_rg, Figs VI.11–VI.12);
  α ∈ {−π/5, 0, π/5} (eq VI.12) learned from VI.2, V_r ∈ {1, 1.8, 3} m/s (eq VI.13) from VI.14;
- ``avoid`` — θ_rg (7 sets of Fig IV.6) × front, right, left distances (P / L of Fig IV.18):
  56 rules; α from VI.2 + VI.20 (goal and obstacles: this agent drives alone, without the
  navigator of §VI.5.2), V_r ∈ {0.5, 1, 1.8} m/s from VI.21;
- ``wall`` — the premise of the hand-made wall follower (Table VI.2, single rays at −90°, 0°,
  +90°), α from VI.21, V_r ∈ {0.5, 1, 1.8} m/s from VI.22;
- ``path`` — the goal seeker's 35 rules towards the current waypoint, α ∈ eq VI.15 from VI.2.

Settings are those of the thesis' tasks: γ = 0.9, β = 1 / (1 + visits) floored at 0.2 / N for N
parallel robots, per-rule ε-greedy with ε decaying 0.3 → 0.02 (× 0.85 every N finished episodes),
extraction tolerance 0.05 over the middle candidate (§VI.4). Continuous action spaces only (the
inferred action Σ w_i a_i is a blend of the candidates).
"""

from __future__ import annotations

import copy
import itertools
from dataclasses import dataclass

import numpy as np

from fuzzynav.control.learned import side_distances, single_rays
from fuzzynav.errors import InputError
from fuzzynav.fuzzy import FuzzySystem, Rule, Singleton, Variable
from fuzzynav.fuzzy.systems import goal_seeking
from fuzzynav.fuzzy.systems_navigation import D_M, D_S, distance_variable, wall_follower
from fuzzynav.gym.episodes import unscale_actions
from fuzzynav.gym.tasks import AVOID_SPEEDS, GOAL_SPEEDS, STEERING3, STEERING5
from fuzzynav.learn.envs.premise import GridPremise
from fuzzynav.learn.exploration import EpsilonGreedy
from fuzzynav.learn.fql import FuzzyQLearner, extract_system
from fuzzynav.learn.schedules import ExponentialDecay, InverseVisits

TOLERANCE = 0.05  # extraction: minimum quality gain over the prior (middle) candidate


@dataclass(frozen=True)
class FQLDesign:
    """Rule base of one task: ``inputs()`` → premise variables, ``features(obs)`` → their values,
    ``heads``: (output name, candidate values, reward heads summed for it)."""

    inputs: object
    features: object
    heads: tuple


def _goal_inputs():
    return list(goal_seeking().inputs)


def _avoid_inputs():
    theta = goal_seeking().inputs[1]
    return [theta] + [distance_variable(name, D_M, D_S) for name in ("front", "right", "left")]


def _avoid_features(obs):
    return np.column_stack([obs[:, 1], side_distances(obs[:, 2:])])


def _wall_features(obs):
    front, right, left = single_rays(obs).T
    return np.column_stack([right, front, left])  # (dd, df, dg) of Table VI.2


DESIGNS = {
    "goal": FQLDesign(_goal_inputs, lambda obs: obs[:, :2],
                      (("alpha", STEERING3, ("VI.2",)), ("v", GOAL_SPEEDS, ("VI.14",)))),
    "avoid": FQLDesign(_avoid_inputs, _avoid_features,
                       (("alpha", STEERING3, ("VI.2", "VI.20")), ("v", AVOID_SPEEDS, ("VI.21",)))),
    "wall": FQLDesign(lambda: list(wall_follower().inputs), _wall_features,
                      (("alpha", STEERING3, ("VI.21",)), ("v", AVOID_SPEEDS, ("VI.22",)))),
    "path": FQLDesign(_goal_inputs, lambda obs: obs[:, :2], (("alpha", STEERING5, ("VI.2",)),)),
}


def grid_rules(inputs, outputs) -> FuzzySystem:
    """TS0 system whose rules cover every combination of one term per input (first input
    slowest), each concluding the middle singleton of every output; product, weighted sum."""
    rules = [Rule(tuple((v.name, label) for v, label in zip(inputs, labels)),
                  tuple((o.name, o.labels[len(o.labels) // 2]) for o in outputs))
             for labels in itertools.product(*[v.labels for v in inputs])]
    return FuzzySystem(inputs, outputs, rules, method="ts0", tnorm="product", defuzzifier="weighted_sum",
                       name="fql-agent", description="premise of the fuzzy Q-learning agent")


class FQLAgent:
    """Fuzzy Q-learning agent of one task (``goal``, ``avoid``, ``wall``, ``path``); see the module
    docstring. Learned state: ``learner_`` (qualities), ``system_`` (the premise grid)."""

    def __init__(self, task: str, *, gamma: float = 0.9, epsilon=None, lam: float = 0.0,
                 tolerance: float = TOLERANCE):
        if task not in DESIGNS:
            raise InputError(f"unknown task {task!r} (known: {', '.join(DESIGNS)})", field="task")
        self.task, self.gamma, self.lam, self.tolerance = task, gamma, lam, tolerance
        self.epsilon = epsilon if epsilon is not None else ExponentialDecay(0.3, 0.85, 0.02)
        self.design = DESIGNS[task]
        self.learner_ = None

    def _setup(self, batch: int, head_names) -> None:
        outputs = [Variable(name, (min(values), max(values)), {f"c{k}": Singleton(float(v))
                                                               for k, v in enumerate(values)})
                   for name, values, _ in self.design.heads]
        self.outputs_ = outputs
        self.system_ = grid_rules(self.design.inputs(), outputs)
        self.learner_ = FuzzyQLearner.separate(
            GridPremise(self.system_), [np.array(values) for _, values, _ in self.design.heads],
            gamma=self.gamma, alpha=InverseVisits(1.0, 1.0, 0.2 / batch), lam=self.lam,
            policy=EpsilonGreedy(self.epsilon), normalise=False)
        missing = [h for _, _, heads in self.design.heads for h in heads if h not in head_names]
        if missing:
            raise InputError(f"the environment has no reward head {missing[0]!r} (it has {list(head_names)})",
                             field="env")
        self._columns = [[list(head_names).index(h) for h in heads] for _, _, heads in self.design.heads]

    def _env_action(self, values) -> np.ndarray:
        """(B, H) learned outputs (α [, V_r]) → the environment's normalised actions."""
        return unscale_actions(values[:, 0], values[:, 1] if values.shape[1] > 1 else None)

    def learn(self, env, total_steps: int, seed: int = 0, callback=None) -> "FQLAgent":
        """Train for ``total_steps`` environment steps (all sub-environments counted).

        ``env`` is a :class:`~fuzzynav.gym.vector.FuzzynavVectorEnv` of the agent's task with
        continuous actions (``num_envs=1`` for one robot); ``callback(agent, steps)`` is called
        after every vector step (e.g. to evaluate); ``episodes_`` counts the episodes finished so far.
        """
        from fuzzynav.gym.vector import FuzzynavVectorEnv

        if not isinstance(env, FuzzynavVectorEnv) or env.episodes.task.name != self.task or env.episodes.discrete:
            raise InputError(f"needs a continuous-action vector environment of task {self.task!r}", field="env")
        batch = env.num_envs
        if self.learner_ is None:
            self._setup(batch, env.episodes.task.head_names)
        rng = np.random.default_rng(seed)
        obs, _ = env.reset(seed=seed)
        values = self.learner_.begin(self.design.features(obs), rng)
        fresh = np.zeros(batch, dtype=bool)  # the step that resets a row: no transition to learn
        steps = finished = self.episodes_ = 0
        while steps < total_steps:
            obs, _, terminated, truncated, info = env.step(self._env_action(values))
            heads = info["reward_heads"]
            rewards = np.column_stack([heads[:, c].sum(axis=1) for c in self._columns])
            values = self.learner_.step(rewards, self.design.features(obs), terminated, rng, active=~fresh)
            steps += int((~fresh).sum())
            fresh = terminated | truncated
            finished += int(fresh.sum())
            self.episodes_ = finished
            self.learner_.episode = finished // batch  # the exploration clock: one tick per N episodes
            if callback is not None:
                callback(self, steps)
        return self

    def predict(self, obs) -> np.ndarray:
        """Greedy actions of the extracted controller for observations (B, n_obs) → (B, n_act)."""
        if self.learner_ is None:
            raise RuntimeError("predict() needs a trained agent: call learn() first")
        values = self.learner_.greedy_action(self.design.features(np.asarray(obs, dtype=float)), self.tolerance)
        return self._env_action(values)

    def rule_base(self) -> FuzzySystem:
        """The learned controller as a TS0 system over the design's inputs (§VI.4)."""
        if self.learner_ is None:
            raise RuntimeError("rule_base() needs a trained agent: call learn() first")
        view = copy.copy(self.learner_)
        view.premise = self.system_
        return extract_system(view, self.outputs_, tolerance=self.tolerance, name=f"fql-{self.task}",
                              description=f"{self.task} controller learned by fuzzy Q-learning through the "
                                          "Gymnasium environment (Algorithm VI.1)")

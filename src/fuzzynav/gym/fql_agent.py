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
- ``avoid`` — the thesis' avoider inside its goal navigator, steering from VI.20 then speed
  from VI.21, starting from the a-priori conclusions (:mod:`.fql_avoid`, the method of
  ``fuzzynav train fql-avoid``);
- ``wall`` — the premise of the hand-made wall follower (Table VI.2, single rays at −90°, 0°,
  +90°), α from VI.21, V_r ∈ {0.5, 1, 1.8} m/s from VI.22;
- ``path`` — the goal seeker's 35 rules towards the current waypoint, α ∈ eq VI.15 from VI.2.

Settings of the grid designs are those of the training tasks' batch learner (``fuzzynav train …
--parallel N``, :func:`fuzzynav.learn.tasks.common.batch_schedules`), for N = 1 too: γ = 0.9,
β = 1 / (1 + visits) floored at 0.2 / N for N parallel robots, per-rule ε-greedy with ε decaying
0.3 → 0.02 (× 0.85 every N finished episodes), extraction tolerance 0.05 over the middle
candidate (§VI.4). (The tasks' one-robot protocol of the thesis, ``fuzzynav train`` without
``--parallel``, is not this agent's.) Continuous action spaces only (the
inferred action Σ w_i a_i is a blend of the candidates).
"""

from __future__ import annotations

import copy
from dataclasses import dataclass

import numpy as np

from fuzzynav import validation
from fuzzynav.control.learned import single_rays
from fuzzynav.errors import InputError
from fuzzynav.fuzzy import FuzzySystem
from fuzzynav.fuzzy.systems import goal_seeking
from fuzzynav.fuzzy.systems_navigation import wall_follower
from fuzzynav.gym.episodes import unscale_actions
from fuzzynav.gym.fql_avoid import HEADS, NavigatorAvoidance
from fuzzynav.gym.tasks import AVOID_SPEEDS, GOAL_SPEEDS, STEERING3, STEERING5, TASKS
from fuzzynav.learn.envs.premise import GridPremise
from fuzzynav.learn.exploration import EpsilonGreedy
from fuzzynav.learn.fql import FuzzyQLearner, extract_system
from fuzzynav.learn.tasks.common import TOLERANCE, batch_schedules, grid_system, output_variable


@dataclass(frozen=True)
class FQLDesign:
    """Rule base of one task: ``inputs()`` → premise variables, ``features(obs)`` → their values,
    ``heads``: (output name, candidate values, reward heads summed for it)."""

    inputs: object
    features: object
    heads: tuple


def _goal_inputs():
    return list(goal_seeking().inputs)


def _wall_features(obs):
    front, right, left = single_rays(obs).T
    return np.column_stack([right, front, left])  # (dd, df, dg) of Table VI.2


DESIGNS = {
    "goal": FQLDesign(_goal_inputs, lambda obs: obs[:, :2],
                      (("alpha", STEERING3, ("VI.2",)), ("v", GOAL_SPEEDS, ("VI.14",)))),
    "wall": FQLDesign(lambda: list(wall_follower().inputs), _wall_features,
                      (("alpha", STEERING3, ("VI.21",)), ("v", AVOID_SPEEDS, ("VI.22",)))),
    "path": FQLDesign(_goal_inputs, lambda obs: obs[:, :2], (("alpha", STEERING5, ("VI.2",)),)),
}


class GridLearning:
    """One training run of a grid design (:data:`DESIGNS`) for ``batch`` robots: both heads learned
    together from their reward heads; :meth:`begin` / :meth:`step` return the environment's actions."""

    def __init__(self, design: FQLDesign, batch: int, head_names, *, gamma, epsilon, lam, tolerance):
        self.design, self.batch, self.tolerance = design, batch, tolerance
        self.outputs = [output_variable(name, {f"c{k}": float(v) for k, v in enumerate(values)},
                                        (min(values), max(values))) for name, values, _ in design.heads]
        inputs = design.inputs()
        rules = int(np.prod([len(v.terms) for v in inputs]))
        self.premise = grid_system(inputs, self.outputs, [[o.labels[len(o.labels) // 2]] * rules for o in self.outputs],
                                   "fql-agent", "premise of the fuzzy Q-learning agent")  # every rule: the middle candidates
        self.learner = FuzzyQLearner.separate(
            GridPremise(self.premise), [np.array(values) for _, values, _ in design.heads],
            gamma=gamma, alpha=batch_schedules(batch)[0], lam=lam,
            policy=EpsilonGreedy(epsilon), normalise=False)
        self.columns = [[list(head_names).index(h) for h in heads] for _, _, heads in design.heads]

    def _env_action(self, values) -> np.ndarray:
        """(B, H) learned outputs (α [, V_r]) → the environment's normalised actions."""
        return unscale_actions(values[:, 0], values[:, 1] if values.shape[1] > 1 else None)

    def begin(self, obs, rng):
        return self._env_action(self.learner.begin(self.design.features(obs), rng))

    def step(self, heads, obs, terminated, rng, active, steps: int, episodes: int):
        """Learn from the last step's reward ``heads`` (B, H); return the next actions."""
        self.learner.episode = episodes // self.batch  # the exploration clock: one tick per N episodes
        rewards = np.column_stack([heads[:, c].sum(axis=1) for c in self.columns])
        return self._env_action(self.learner.step(rewards, self.design.features(obs), terminated, rng, active=active))

    def predict(self, obs) -> np.ndarray:
        values = self.learner.greedy_action(self.design.features(np.asarray(obs, dtype=float)), self.tolerance)
        return self._env_action(values)

    def system(self, task: str) -> FuzzySystem:
        view = copy.copy(self.learner)
        view.premise = self.premise
        return extract_system(view, self.outputs, tolerance=self.tolerance, name=f"fql-{task}",
                              description=f"{task} controller learned by fuzzy Q-learning through the "
                                          "Gymnasium environment (Algorithm VI.1)")


class FQLAgent:
    """Fuzzy Q-learning agent of one task (``goal``, ``avoid``, ``wall``, ``path``); see the module
    docstring. Learned state: ``learning_`` (the run's learners), ``episodes_`` (episodes trained)."""

    def __init__(self, task: str, *, gamma: float = 0.9, epsilon=None, lam: float = 0.0,
                 tolerance: float = TOLERANCE, prior: str = "thesis"):
        if task not in DESIGNS and task != "avoid":
            raise InputError(f"unknown task {task!r} (known: {', '.join(TASKS)})", field="task")
        tolerance = validation.number(tolerance, field="tolerance", lo=0.0)  # (-1 was taken: no tie ever)
        self.task, self.gamma, self.lam, self.tolerance = task, gamma, lam, tolerance
        self.prior = prior  # avoid: the initial table, "thesis" (a-priori conclusions) or "none" (q = 0 only)
        self.epsilon = epsilon if epsilon is not None else batch_schedules(1)[1]  # the batch learner's decay
        self.learning_ = None

    def _setup(self, batch: int, total_steps: int, head_names):
        wanted = HEADS if self.task == "avoid" else [h for _, _, heads in DESIGNS[self.task].heads for h in heads]
        missing = [h for h in wanted if h not in head_names]
        if missing:
            raise InputError(f"the environment has no reward head {missing[0]!r} (it has {list(head_names)})",
                             field="env")
        if self.task == "avoid":
            return NavigatorAvoidance(batch, total_steps, head_names, self.prior)
        return GridLearning(DESIGNS[self.task], batch, head_names, gamma=self.gamma, epsilon=self.epsilon,
                            lam=self.lam, tolerance=self.tolerance)

    def learn(self, env, total_steps: int, seed: int = 0, callback=None) -> FQLAgent:
        """Train for ``total_steps`` environment steps (all sub-environments counted), from scratch.

        ``env`` is a :class:`~fuzzynav.gym.vector.FuzzynavVectorEnv` of the agent's task with
        continuous actions (``num_envs=1`` for one robot); ``callback(agent, steps)`` is called
        after every vector step (e.g. to evaluate); ``episodes_`` counts the episodes finished so far.
        """
        from fuzzynav.gym.vector import FuzzynavVectorEnv

        if not isinstance(env, FuzzynavVectorEnv) or env.episodes.task.name != self.task or env.episodes.discrete:
            raise InputError(f"needs a continuous-action vector environment of task {self.task!r}", field="env")
        total_steps = validation.count(total_steps, field="total_steps", lo=0, hi=validation.MAX_INTEGER)  # (-5 ran none)
        seed = validation.seed(seed, field="seed")
        if callback is not None and not callable(callback):
            raise InputError(f"must be a function callback(agent, steps) or None, got {validation.shown(callback)}",
                             field="callback")
        batch = env.num_envs
        self.observations_ = env.single_observation_space.shape  # what predict() reads
        self.learning_ = self._setup(batch, total_steps, env.episodes.task.head_names)
        rng = np.random.default_rng(seed)
        obs, _ = env.reset(seed=seed)
        actions = self.learning_.begin(obs, rng)
        fresh = np.zeros(batch, dtype=bool)  # the step that resets a row: no transition to learn
        steps = self.episodes_ = 0
        while steps < total_steps:
            obs, _, terminated, truncated, info = env.step(actions)
            steps += int((~fresh).sum())
            actions = self.learning_.step(info["reward_heads"], obs, terminated, rng, ~fresh, steps, self.episodes_)
            fresh = terminated | truncated
            self.episodes_ += int(fresh.sum())
            if callback is not None:
                callback(self, steps)
        return self

    def _trained(self, what: str):
        if self.learning_ is None:
            raise RuntimeError(f"{what}() needs a trained agent: call learn() first")
        return self.learning_

    def predict(self, obs) -> np.ndarray:
        """Greedy actions of the extracted controller for observations (B, n_obs) → (B, n_act)."""
        learning = self._trained("predict")
        obs = validation.finite_array(obs, field="obs", ndim=2)  # NaN answered NaN, text a ValueError
        if obs.shape[1:] != self.observations_:  # three columns of a goal task's two: the first two were read
            raise InputError(f"must be observations of shape (B, {self.observations_[0]}) of the environment learned "
                             f"on, got shape {obs.shape}", field="obs")
        return learning.predict(obs)

    def rule_base(self) -> FuzzySystem:
        """The learned controller as a TS0 system over the design's inputs (§VI.4); for obstacle
        avoidance the avoider that :meth:`controller` runs inside its navigator."""
        learning = self._trained("rule_base")
        return learning.system() if self.task == "avoid" else learning.system(self.task)

    def controller(self):
        """The learned controller as a fuzzynav controller of the simulator: obstacle avoidance
        only (:class:`~fuzzynav.control.learned.LearnedAvoidanceNavigator`); the grid designs'
        rule bases drive through the controllers of :mod:`fuzzynav.control.learned`."""
        if self.task != "avoid":
            raise InputError("controller() is the obstacle-avoidance navigator; use rule_base()", field="task")
        return self._trained("controller").controller()

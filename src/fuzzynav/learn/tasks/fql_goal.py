"""Goal seeking by fuzzy Q-learning: ``fuzzynav train fql-goal | fql-goal-35 | fql-goal-traces`` (thesis §VI.5.1).

- ``fql-goal``: 15 rules × 3 conclusions, steering (reward VI.2) then speed (VI.14), random
  starts (Figs VI.7–VI.10);
- ``fql-goal-35``: the chapter IV partition, 35 rules × 5 conclusions (Figs VI.13–VI.14);
- ``fql-goal-traces``: ``fql-goal``'s steering with eligibility traces (Figs VI.15–VI.16).

The extracted controller (:func:`goal_system`) is a TS0 rule base; the model file (kind
``fql-goal``) is its ``fuzzynav-fis`` document, run by
:class:`~fuzzynav.control.learned.FuzzyGoalSeeker` (:func:`load_model`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from fuzzynav.control.learned import FuzzyGoalSeeker
from fuzzynav.fuzzy.constants import ALPHA_MAX
from fuzzynav.fuzzy.io.document import to_document
from fuzzynav.fuzzy.membership import Trapezoidal, Triangular
from fuzzynav.fuzzy.partition import strong_partition
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.systems import D_MAX_GOAL, goal_seeking
from fuzzynav.fuzzy.variable import Variable
from fuzzynav.learn.envs import FixedGoal, GridPremise, RandomGoal, RobotEnv
from fuzzynav.learn.fql import extract_system
from fuzzynav.learn.rewards import GoalSpeedReward, GoalSteeringReward
from fuzzynav.learn.tasks import common


def goal_partition_15() -> list[Variable]:
    """Inputs of the 15-rule goal seeker (Figs VI.5–VI.6).

    d_rg: P, M, G with breakpoints 0, 0.3, 1, 3, D_max (P flat to 0.3 m, M peaking at 1 m, G
    flat from 3 m); θ_rg: NG, NM, Z, PM, PG peaking at −π/2, −π/6, 0, π/6, π/2 (shoulders to ±π).
    """
    drg = Variable("drg", (0.0, D_MAX_GOAL), {
        "P": Trapezoidal(0.0, 0.0, 0.3, 1.0),
        "M": Triangular(0.3, 1.0, 3.0),
        "G": Trapezoidal(1.0, 3.0, D_MAX_GOAL, D_MAX_GOAL),
    })
    peaks = (-common.PI / 2, -common.PI / 6, 0.0, common.PI / 6, common.PI / 2)
    theta = Variable("theta", (-common.PI, common.PI),
                     strong_partition(peaks, ("NG", "NM", "Z", "PM", "PG"), (-common.PI, common.PI)))
    return [drg, theta]


def goal_partition_35() -> list[Variable]:
    """Inputs of the 35-rule goal seeker: the chapter IV partition (Figs VI.11–VI.12 = IV.5–IV.6)."""
    return list(goal_seeking().inputs)


SPEED_DECISION = 10  # steps Δt (1 s) per decision of the speed phase — a deviation, see below
# Reward VI.14 pays only for arriving slowly (+1) and punishes speeding up; being fast pays through the
# discount alone: the +1 of an arrival T decisions ahead is worth γ^T. With a decision every Δt = 0.1 s
# (T ≈ 100 from 10 m away) γ^T ≈ 0 for every candidate, and a creeping speed that never arrives ties
# with a fast one; one decision per second (T ≈ 10) keeps the arrival visible (docs/results/chapter-vi.md).
# Its episodes start at the steering phase's constant speed ("lorsque le robot est capable de rejoindre son
# but avec une vitesse fixe, on applique le deuxième algorithme", §VI.5.1): from rest, every candidate would
# "speed up" at the first decision and share the −1 of eq VI.14. And an episode that runs out of time
# without arriving ends with SPEED_TIMEOUT: otherwise creeping, never arriving nor speeding up, is never
# punished, and eq VI.14's −1 for speeding up makes it the learner's choice (docs/results/chapter-vi.md).
SPEED_TIMEOUT = -1.0


@dataclass(frozen=True)
class GoalFQL:
    """Settings of one FQL goal-seeking task."""

    name: str
    inputs: callable
    steering: dict
    lam: float = 0.0
    learn_speed: bool = True
    episodes: int = 3000
    fixed: bool = False


GOAL_TASKS = {
    "fql-goal": GoalFQL("fql-goal", goal_partition_15, common.STEERING3),
    "fql-goal-35": GoalFQL("fql-goal-35", goal_partition_35, common.STEERING5, episodes=4000),
    "fql-goal-traces": GoalFQL("fql-goal-traces", goal_partition_15, common.STEERING3, lam=0.7, learn_speed=False,
                               episodes=1500),
}



def goal_fql_phases(task: GoalFQL, out: Path, episodes: int, batch: int = 1):
    """Yields the phases of an FQL goal task (``batch`` robots per batch: 1 is the thesis'
    protocol); the speed phase is built from the trained steering."""
    tolerance = common.extraction_tolerance(batch, common.TOLERANCE)
    inputs = task.inputs()
    alpha = common.output_variable("alpha", task.steering, (-ALPHA_MAX, ALPHA_MAX))
    template = common.grid_system(inputs, [alpha], [[alpha.labels[0]] * math.prod(len(v.terms) for v in inputs)],
                           task.name, "premise")
    premise = GridPremise(template)
    layout = FixedGoal() if task.fixed else RandomGoal()
    steer_values = np.array(list(task.steering.values()))
    n_steer = common.steering_episodes(episodes, common.SPEED_SHARE if task.learn_speed else 0.0)
    steer = common.fql_learner(premise, steer_values, task.lam, batch)
    env = RobotEnv(layout, lambda s: s.goal, lambda a, s: (a[:, 0], common.STEERING_SPEED), GoalSteeringReward(),
                   batch=batch, max_steps=common.MAX_STEPS, tolerance=common.GOAL_TOLERANCE)
    yield common.Phase("steering", env, steer, n_steer, common.checkpoint_path(out, "steering"))
    if task.learn_speed:
        speed = common.fql_learner(premise, speed_candidates(inputs), 0.0, batch)
        env = RobotEnv(layout, lambda s: s.goal,
                       lambda a, s: (steer.greedy_action(s.goal, tolerance)[:, 0], a[:, 0]), GoalSpeedReward(),
                       batch=batch, max_steps=common.MAX_STEPS // SPEED_DECISION, tolerance=common.GOAL_TOLERANCE,
                       decision_steps=SPEED_DECISION, start_speed=common.STEERING_SPEED, timeout_reward=SPEED_TIMEOUT)
        yield common.Phase("speed", env, speed, episodes - n_steer, common.checkpoint_path(out, "speed"))


def speed_candidates(inputs) -> np.ndarray:
    """(R, 3) candidate speeds of every rule of the grid over ``inputs`` (d_rg first, slowest):
    :data:`~fuzzynav.learn.tasks.common.SPEED_CANDIDATES` by the position of the rule's d_rg term."""
    per_term = [common.SPEED_CANDIDATES[min(k, len(common.SPEED_CANDIDATES) - 1)] for k in range(len(inputs[0].terms))]
    rows = math.prod(len(v.terms) for v in inputs[1:])
    return np.array([[common.SPEED3[label] for label in per_term[r // rows]] for r in range(len(per_term) * rows)])


def goal_system(task: GoalFQL, learners: dict, tolerance: float = common.TOLERANCE) -> FuzzySystem:
    """The extracted controller: every rule with its best conclusion(s), as a TS0 system
    (:func:`~fuzzynav.learn.fql.extract_system`)."""
    outputs = {"steering": common.output_variable("alpha", task.steering, (-ALPHA_MAX, ALPHA_MAX)),
               "speed": common.output_variable("v", common.SPEED3, (0.0, 4.0))}
    learned = [name for name in outputs if name in learners]
    rules = math.prod(len(v.terms) for v in task.inputs())
    return extract_system([learners[name] for name in learned], [outputs[name] for name in learned],
                          tolerance=tolerance, name=task.name,
                          description=f"Goal seeking learned by fuzzy Q-learning (thesis §VI.5.1, Algorithm VI.1): "
                                      f"{rules} rules, {len(task.steering)} steering conclusions"
                                      + (", speed learned" if "speed" in learners else ""))


def train_goal_fql(task: GoalFQL, request) -> dict:
    """Train ``task`` and write its model (the steering, and the speed if the task learns it)."""
    batch = common.robots(request)
    episodes = common.episode_budget(request, task.episodes)
    phases, learners = common.run_phases(goal_fql_phases(task, request.out, episodes, batch), request)
    tolerance = common.extraction_tolerance(batch, common.TOLERANCE)
    system = goal_system(task, learners, tolerance)
    learned = list(learners.values())
    document = {"kind": "fql-goal", **to_document(system), "constant_speed": common.STEERING_SPEED,
                "training": {"task": task.name, "seed": request.seed, **common.protocol_record(batch, "none"),
                             "rules_changed": common.rules_changed(learned, tolerance),
                             **common.summarise(phases)}}
    return common.finish(request, document, phases, task.name)


def train_fql_goal(request) -> dict:
    """``fuzzynav train fql-goal``: 15 rules × 3 conclusions, steering then speed (Figs VI.9–VI.10)."""
    return train_goal_fql(GOAL_TASKS["fql-goal"], request)


def train_fql_goal_35(request) -> dict:
    """``fuzzynav train fql-goal-35``: 35 rules × 5 conclusions (Figs VI.13–VI.14)."""
    return train_goal_fql(GOAL_TASKS["fql-goal-35"], request)


def train_fql_goal_traces(request) -> dict:
    """``fuzzynav train fql-goal-traces``: 15 rules × 3, eligibility traces λ = 0.7 (Figs VI.15–VI.16)."""
    return train_goal_fql(GOAL_TASKS["fql-goal-traces"], request)


def load_model(document: dict, path) -> FuzzyGoalSeeker:
    """Model loader of kind ``fql-goal``: the learned rule base over (d_rg, θ_r − θ_d)."""
    return common.load_fuzzy_model(document, path,
                                   lambda system, speed, name: FuzzyGoalSeeker(system, speed, name=name))

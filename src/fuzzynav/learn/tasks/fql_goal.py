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
from fuzzynav.fuzzy.io.document import to_document
from fuzzynav.fuzzy.membership import Trapezoidal, Triangular
from fuzzynav.fuzzy.partition import strong_partition
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.systems import D_MAX_GOAL, goal_seeking
from fuzzynav.fuzzy.variable import Variable
from fuzzynav.learn.envs import FixedGoal, GridPremise, RandomGoal, RobotEnv
from fuzzynav.learn.fql import extract_system
from fuzzynav.learn.rewards import GoalSpeedReward, GoalSteeringReward
from fuzzynav.learn.tasks.common import (
    GOAL_TOLERANCE,
    MAX_STEPS,
    PI,
    SPEED3,
    SPEED_SHARE,
    STEERING3,
    STEERING5,
    STEERING_SPEED,
    TOLERANCE,
    Phase,
    batch_size,
    checkpoint_path,
    episode_budget,
    finish,
    fql_learner,
    grid_system,
    load_fuzzy_model,
    output_variable,
    run_phases,
    steering_episodes,
    summarise,
)


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
    peaks = (-PI / 2, -PI / 6, 0.0, PI / 6, PI / 2)
    theta = Variable("theta", (-PI, PI), strong_partition(peaks, ("NG", "NM", "Z", "PM", "PG"), (-PI, PI)))
    return [drg, theta]


def goal_partition_35() -> list[Variable]:
    """Inputs of the 35-rule goal seeker: the chapter IV partition (Figs VI.11–VI.12 = IV.5–IV.6)."""
    return list(goal_seeking().inputs)


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
    "fql-goal": GoalFQL("fql-goal", goal_partition_15, STEERING3),
    "fql-goal-35": GoalFQL("fql-goal-35", goal_partition_35, STEERING5, episodes=4000),
    "fql-goal-traces": GoalFQL("fql-goal-traces", goal_partition_15, STEERING3, lam=0.7, learn_speed=False,
                               episodes=1500),
}



def goal_fql_phases(task: GoalFQL, out: Path, episodes: int, batch: int | None = None):
    """Yields the phases of an FQL goal task; the speed phase is built from the trained steering."""
    batch = batch_size(task.fixed) if batch is None else batch
    inputs = task.inputs()
    alpha = output_variable("alpha", task.steering, (-PI / 5, PI / 5))
    template = grid_system(inputs, [alpha], [[alpha.labels[0]] * math.prod(len(v.terms) for v in inputs)],
                           task.name, "premise")
    premise = GridPremise(template)
    layout = FixedGoal() if task.fixed else RandomGoal()
    steer_values = np.array(list(task.steering.values()))
    n_steer = steering_episodes(episodes, SPEED_SHARE if task.learn_speed else 0.0)
    steer = fql_learner(premise, steer_values, task.lam, batch)
    env = RobotEnv(layout, lambda s: s.goal, lambda a, s: (a[:, 0], STEERING_SPEED), GoalSteeringReward(),
                   batch=batch, max_steps=MAX_STEPS, tolerance=GOAL_TOLERANCE)
    yield Phase("steering", env, steer, n_steer, checkpoint_path(out, "steering"))
    if task.learn_speed:
        speed_values = np.array(list(SPEED3.values()))
        speed = fql_learner(premise, speed_values, 0.0, batch)
        env = RobotEnv(layout, lambda s: s.goal,
                       lambda a, s: (steer.greedy_action(s.goal, TOLERANCE)[:, 0], a[:, 0]), GoalSpeedReward(),
                       batch=batch, max_steps=MAX_STEPS, tolerance=GOAL_TOLERANCE)
        yield Phase("speed", env, speed, episodes - n_steer, checkpoint_path(out, "speed"))


def goal_system(task: GoalFQL, learners: dict) -> FuzzySystem:
    """The extracted controller: every rule with its best conclusion(s), as a TS0 system
    (:func:`~fuzzynav.learn.fql.extract_system`)."""
    outputs = {"steering": output_variable("alpha", task.steering, (-PI / 5, PI / 5)),
               "speed": output_variable("v", SPEED3, (0.0, 4.0))}
    learned = [name for name in outputs if name in learners]
    rules = math.prod(len(v.terms) for v in task.inputs())
    return extract_system([learners[name] for name in learned], [outputs[name] for name in learned],
                          tolerance=TOLERANCE, name=task.name,
                          description=f"Goal seeking learned by fuzzy Q-learning (thesis §VI.5.1, Algorithm VI.1): "
                                      f"{rules} rules, {len(task.steering)} steering conclusions"
                                      + (", speed learned" if "speed" in learners else ""))


def train_goal_fql(task: GoalFQL, request) -> dict:
    """Train ``task`` and write its model (the steering, and the speed if the task learns it)."""
    phases, learners = run_phases(goal_fql_phases(task, request.out, episode_budget(request, task.episodes)), request)
    system = goal_system(task, learners)
    document = {"kind": "fql-goal", **to_document(system), "constant_speed": STEERING_SPEED,
                "training": {"task": task.name, "seed": request.seed, **summarise(phases)}}
    return finish(request, document, phases, task.name)


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
    return load_fuzzy_model(document, path, lambda system, speed, name: FuzzyGoalSeeker(system, speed, name=name))

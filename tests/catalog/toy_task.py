"""A training task written as CONTRIBUTING.md says, outside the package: one module, one catalog entry.

Tabular Q-learning goal seeking on the 9 states of Table VI.1 from the fixed start of Fig VI.1,
built from the library's pieces; the model (kind ``toy-q-goal``) is the greedy action per state.
"""

from __future__ import annotations

import numpy as np

from fuzzynav import validation
from fuzzynav.control.learned import TabularGoalSeeker
from fuzzynav.learn.tasks.common import Phase, checkpoint_path, episode_budget, finish, run_phases, summarise
from fuzzynav.learn.tasks.tabular_goal import Q_SPEED, q_goal_parts

KIND = "toy-q-goal"


def train_toy(request) -> dict:
    """``fuzzynav train toy``: 9 states x 3 actions from the fixed start."""
    env, learner, disc, steering = q_goal_parts(n_states=9, fixed=True)
    phases, _ = run_phases([Phase("steering", env, learner, episode_budget(request, 200),
                                  checkpoint_path(request.out, "steering"))], request)
    document = {"kind": KIND, "n_states": 9, "greedy": learner.greedy()[0].tolist(), "steering": list(steering),
                "training": {"task": "toy", "seed": request.seed, **summarise(phases)}}
    return finish(request, document, phases, "toy")


def load_model(document: dict, path) -> TabularGoalSeeker:
    """The greedy policy of a ``toy-q-goal`` file."""
    _, _, disc, _ = q_goal_parts(n_states=document["n_states"], fixed=True)
    return TabularGoalSeeker(disc, np.asarray(document["greedy"], dtype=int),
                             validation.finite_array(document["steering"], field="steering", ndim=1, empty=False), Q_SPEED, name="toy")

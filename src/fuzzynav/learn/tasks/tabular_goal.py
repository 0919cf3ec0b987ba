"""Tabular Q-learning goal seeking, ``fuzzynav train q-goal`` (thesis §VI.2, Figs VI.1–VI.4, Table VI.1).

States: zones × sectors of (d_rg, θ_rg) (:func:`q_discretiser`); actions: forward, right, left
steering at a constant speed; reward VI.2 (:class:`~fuzzynav.learn.rewards.GoalSteeringReward`).
The model file (kind ``q-goal``) holds the discretiser, the actions and the Q table;
:func:`load_model` rebuilds the greedy :class:`~fuzzynav.control.learned.TabularGoalSeeker`.
"""

from __future__ import annotations

import numpy as np

from fuzzynav import validation
from fuzzynav.control.learned import TabularGoalSeeker, model_name
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.constants import ALPHA_MAX, STEERING_SINGLETONS
from fuzzynav.learn.envs import FixedGoal, RandomGoal, RobotEnv
from fuzzynav.learn.exploration import EpsilonGreedy
from fuzzynav.learn.rewards import GoalSteeringReward
from fuzzynav.learn.schedules import ExponentialDecay, InverseVisits
from fuzzynav.learn.tabular import TabularLearner, ZoneSectorDiscretiser
from fuzzynav.learn.tasks.common import (
    GOAL_TOLERANCE,
    Phase,
    batch_size,
    checkpoint_path,
    episode_budget,
    finish,
    protocol_record,
    robots,
    run_phases,
    summarise,
    thesis_schedules,
)
from fuzzynav.storage import supported_version

Q_STEERING = (0.0, -ALPHA_MAX, ALPHA_MAX)  # forward (α1), right (α2), left (α3)
Q_SPEED = 1.0  # m/s, constant (the tabular goal seeker only steers)
Q_GOAL_VERSION = 1  # of the model file; a file without the field is of version 1
Q_GOAL_FIELDS = ("kind", "version", "zone_edges", "n_sectors", "merge_inner", "steering", "speed", "q", "training")


FIXED_EPSILON_FLOOR = 0.0  # from a fixed start ε decays to 0 (greedy in the limit): see q_goal_parts


def q_discretiser(n_states: int = 13) -> ZoneSectorDiscretiser:
    """States of Table VI.1: 1 + 2 × sectors — d_rg zones split at 1 m and 4 m, the inner zone
    (d_rg < 1 m) one state, the two outer zones 4, 5, 6 or 9 sectors of θ_rg each."""
    sectors = {9: 4, 11: 5, 13: 6, 19: 9}
    if n_states not in sectors:
        raise InputError(f"Table VI.1 has 9, 11, 13 or 19 states, got {n_states}", field="n_states")
    return ZoneSectorDiscretiser([1.0, 4.0], sectors[n_states], merge_inner=True)


def q_goal_parts(n_states: int = 13, n_actions: int = 3, fixed: bool = False, batch: int | None = None,
                 schedule: str = "own"):
    """(env, learner, discretiser, steering values) of tabular goal seeking (§VI.2, Table VI.1).

    ``batch`` robots per batch (1: the thesis' one robot; default the parallel learner's
    :func:`~fuzzynav.learn.tasks.common.batch_size`). ε decays from 0.3 to 0.02 at × 0.9 per
    :func:`~fuzzynav.learn.tasks.common.batch_size` episodes (so at the same pace per episode
    whatever ``batch``) with random starts; from the fixed start of Fig VI.1
    to 0 (:data:`FIXED_EPSILON_FLOOR`, "greedy in the limit"): there the episodes differ only by
    exploration, and a floor of 0.02 keeps the greedy route flipping between near-equal routes
    (docs/training.md, "Tabular goal seeking"). ``schedule="fql"``: fuzzy Q-learning's ε and β of
    the thesis' protocol (:data:`~fuzzynav.learn.tasks.common.THESIS`) instead, so that a
    comparison with FQL (Fig VI.8 against Fig VI.1) differs in the representation only."""
    if schedule not in ("own", "fql"):
        raise InputError(f"a tabular schedule is 'own' or 'fql', got {schedule!r}", field="schedule")
    batch = batch_size(fixed) if batch is None else batch
    disc = q_discretiser(n_states)
    steering = Q_STEERING if n_actions == 3 else tuple(STEERING_SINGLETONS[label] for label in ("Z", "NM", "PM", "NG", "PG"))
    actions = np.asarray(steering)
    env = RobotEnv(FixedGoal() if fixed else RandomGoal(), lambda s: disc(s.goal[:, 0], s.goal[:, 1]),
                   lambda a, s: (actions[a], Q_SPEED), GoalSteeringReward(), batch=batch, max_steps=500,
                   tolerance=GOAL_TOLERANCE)
    if schedule == "fql":
        alpha, policy = thesis_schedules()
    else:
        alpha = InverseVisits(1.0, 0.8, 0.01)
        policy = EpsilonGreedy(ExponentialDecay(0.3, 0.9 ** (batch / batch_size(fixed)),
                                                FIXED_EPSILON_FLOOR if fixed else 0.02))
    learner = TabularLearner(disc.n_states, len(steering), gamma=0.9, alpha=alpha, policy=policy)
    return env, learner, disc, steering


def q_goal_controller(learner, disc, steering) -> TabularGoalSeeker:
    return TabularGoalSeeker(disc, learner.greedy()[0], steering, Q_SPEED)


def train_q_goal(request) -> dict:
    """``fuzzynav train q-goal``: 13 states × 3 actions, random starts (Figs VI.3–VI.4)."""
    batch = robots(request)
    env, learner, disc, steering = q_goal_parts(batch=batch)
    phases, _ = run_phases([Phase("steering", env, learner, episode_budget(request, 3000),
                                  checkpoint_path(request.out, "steering"))], request)
    document = {"kind": "q-goal", "version": Q_GOAL_VERSION, "zone_edges": disc.zone_edges.tolist(), "n_sectors": disc.n_sectors,
                "merge_inner": disc.merge_inner, "steering": list(steering), "speed": Q_SPEED,
                "q": learner.q[0].tolist(), "training": {"task": "q-goal", "seed": request.seed, **protocol_record(batch, "none"),
                             **summarise(phases)}}
    return finish(request, document, phases, "q-goal")


def load_model(document: dict, path) -> TabularGoalSeeker:
    """Model loader of kind ``q-goal``: every field checked, a bad, missing or unknown one (or a
    version this package does not write) is an InputError naming the file and the field."""
    try:
        validation.known_keys(document, Q_GOAL_FIELDS)
        for name in ("zone_edges", "n_sectors", "merge_inner", "steering", "speed", "q"):
            if name not in document:
                raise InputError("missing field", field=name)
        supported_version(document, Q_GOAL_VERSION)
        sectors, merge = document["n_sectors"], document["merge_inner"]
        if not isinstance(sectors, int) or isinstance(sectors, bool):
            raise InputError(f"must be a positive integer, got {sectors!r}", field="n_sectors")
        if not isinstance(merge, bool):
            raise InputError(f"must be true or false, got {merge!r}", field="merge_inner")
        disc = ZoneSectorDiscretiser(validation.finite_array(document["zone_edges"], field="zone_edges", ndim=1), sectors,
                                     merge)
        q = validation.finite_array(document["q"], field="q", ndim=2, empty=False)
        steering = validation.finite_array(document["steering"], field="steering", ndim=1, empty=False)
        if q.shape != (disc.n_states, steering.size):
            raise InputError(f"Q table of shape {q.shape}, expected {(disc.n_states, steering.size)} "
                             "(states of zone_edges × n_sectors, actions of steering)", field="q")
        return TabularGoalSeeker(disc, np.argmax(q, axis=1), steering, document["speed"], name=model_name(document))
    except InputError as error:
        raise InputError(error.problem, source=str(path), field=error.field) from None


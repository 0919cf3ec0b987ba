"""The wall follower of Table VI.2 optimised by fuzzy Q-learning, ``fuzzynav train fql-wall`` (thesis §VI.5.3.2).

The rules of the hand-made follower (:func:`fuzzynav.fuzzy.systems_navigation.wall_follower`)
keep their premises; FQL chooses, for each conclusion, one of three interpretations of its label
(value − 10°, value, value + 10° for the steering; × 0.7, 1, 1.3 for the speed), steering first
(reward VI.21) then speed (VI.22), on random wall courses (Figs VI.29–VI.30). The model file
(kind ``fql-wall``) is the optimised rule base, run by
:class:`~fuzzynav.control.learned.LearnedWallFollower` (:func:`load_model`).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from fuzzynav.control.learned import SENSING, LearnedWallFollower
from fuzzynav.fuzzy.io.document import to_document
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.systems_navigation import WALL_D_M, WALL_D_S, wall_follower
from fuzzynav.learn.envs import GridPremise, RobotEnv, WallCourse
from fuzzynav.learn.extraction import Interpretations
from fuzzynav.learn.fql import extract_system
from fuzzynav.learn.rewards import WallSpeedReward, WallSteeringReward
from fuzzynav.learn.tasks import common
from fuzzynav.learn.tasks.fql_avoid import AVOID_RATE
from fuzzynav.robot.sensors import SensorRing

WALL_SPREAD = math.radians(10.0)  # three interpretations per steering label: value − 10°, value, value + 10°
WALL_SPEED_SCALE = (0.7, 1.0, 1.3)  # and per speed label: 0.7, 1, 1.3 × its value
WALL_SUFFIXES = ("_lo", "", "_hi")
WALL_DECISION = 3
WALL_TOLERANCE = 0.02  # extraction tolerance of the wall follower's interpretations
WALL_MAX_STEPS = 300


def wall_parts():
    """The hand-made follower (Table VI.2), its premise, and the candidates of every rule."""
    handmade = wall_follower()
    values = handmade.compiled.values  # (R, 2): α and V_r of every rule
    alpha = np.clip(values[:, :1] + WALL_SPREAD * np.array([-1.0, 0.0, 1.0]), -common.PI / 4, common.PI / 4)
    speed = np.clip(values[:, 1:] * np.array(WALL_SPEED_SCALE), 0.0, 4.0)
    return handmade, GridPremise(handmade), alpha, speed


WALL_COLUMNS = [1, 0, 2]  # (d_d, d_f, d_g) = (right, front, left) of the env's sides (front, right, left)


WALL_SENSING = "rays"  # the hand-made follower's single rays (control.learned.SENSING)


def fql_wall_phases(out: Path, episodes: int, batch: int = common.BATCH, sensing: str = WALL_SENSING):
    """Steering (eq VI.21) then speed (eq VI.22) interpretations, from the hand-made follower:
    the a-priori knowledge the thesis injects here ("le contrôleur précédent est optimisé",
    §VI.5.3.2) is that rule base, each rule's prior being its label's own value (every q still
    starts at 0). ``batch`` robots per batch (1: the thesis' protocol, in which a collision's
    step is bootstrapped as Algorithm VI.1 writes it: −2 + γ V*(s'), §VI.4).

    ``sensing`` is how the learner reads d_d, d_f, d_g (:data:`fuzzynav.control.learned.SENSING`):
    by default the single rays at −90°, 0°, +90° of the hand-made follower, so that what learning
    changes is the interpretations only. The rewards' d_i (eqs VI.21–VI.22, "i = 1…3") are the
    same three distances the follower reads ("les valeurs de distances dans les trois directions
    du robot (dd, dg et df)", §VI.5.3.1).
    """
    handmade, premise, alpha, speed = wall_parts()
    layout, sensors, sides = WallCourse(), SensorRing(), SENSING[sensing]

    def observe(s):
        return sides(s.ranges)[:, WALL_COLUMNS]

    tolerance = common.extraction_tolerance(batch, WALL_TOLERANCE)
    steer = common.fql_learner(premise, alpha, 0.0, batch, prior=1, alpha=AVOID_RATE / batch)
    n_steer = common.steering_episodes(episodes, common.SPEED_SHARE)
    env = RobotEnv(layout, observe, lambda a, s: (a[:, 0], handmade.evaluate(observe(s))[:, 1]),
                   WallSteeringReward(WALL_D_M), batch=batch, max_steps=WALL_MAX_STEPS // WALL_DECISION,
                   sensors=sensors, decision_steps=WALL_DECISION, sides=sides)
    yield common.Phase("steering", env, steer, n_steer, common.checkpoint_path(out, "steering"),
                       common.WORLD_CONVERGENCE)
    fast = common.fql_learner(premise, speed, 0.0, batch, prior=1, alpha=AVOID_RATE / batch)
    env = RobotEnv(layout, observe, lambda a, s: (steer.greedy_action(observe(s), tolerance)[:, 0], a[:, 0]),
                   WallSpeedReward(WALL_D_S), batch=batch, max_steps=WALL_MAX_STEPS // WALL_DECISION,
                   sensors=sensors, decision_steps=WALL_DECISION, sides=sides)
    yield common.Phase("speed", env, fast, episodes - n_steer, common.checkpoint_path(out, "speed"),
                       common.WORLD_CONVERGENCE)


def wall_system(handmade, learners: dict, sensing: str = WALL_SENSING, tolerance: float = WALL_TOLERANCE) -> FuzzySystem:
    """The optimised follower: Table VI.2's rules with the chosen interpretation of each label
    (``PG_lo`` / ``PG`` / ``PG_hi`` = value − 10°, value, value + 10°; speeds × 0.7, 1, 1.3),
    extracted by :func:`~fuzzynav.learn.fql.extract_system`."""
    def interpretations(name, universe):
        base = [dict(rule.conclusions)[name] for rule in handmade.rules]
        return Interpretations(name, universe, lambda r, j: base[r] + WALL_SUFFIXES[j])

    return extract_system([learners["steering"], learners["speed"]],
                          [interpretations("alpha", (-common.PI / 4, common.PI / 4)), interpretations("v", (0.0, 4.0))],
                          tolerance=tolerance, name="fql-wall",
                          description="Wall follower of Table VI.2 optimised by fuzzy Q-learning "
                                      f"(thesis §VI.5.3.2, eqs VI.21-VI.22); sensing: {sensing} "
                                      f"({WALL_SENSINGS[sensing]})")


WALL_SENSINGS = {"rays": "single rays at -90, 0, +90 degrees, as the hand-made follower",
                 "modules": "nearest of the three sensors of each module"}


def train_fql_wall(request, sensing: str = WALL_SENSING) -> dict:
    """``fuzzynav train fql-wall``: Table VI.2's interpretations learned (Figs VI.29–VI.30) on the
    hand-made follower's single rays (``sensing``: :data:`WALL_SENSINGS`)."""
    batch = common.robots(request)
    episodes = common.episode_budget(request, 1500)
    phases, learners = common.run_phases(fql_wall_phases(request.out, episodes, batch, sensing), request)
    tolerance = common.extraction_tolerance(batch, WALL_TOLERANCE)
    system = wall_system(wall_follower(), learners, sensing, tolerance)
    document = {"kind": "fql-wall", "sensing": sensing, **to_document(system),
                "training": {"task": "fql-wall", "seed": request.seed,
                             **common.protocol_record(batch, "hand-made follower"),
                             "rules_changed": common.rules_changed(list(learners.values()), tolerance),
                             **common.summarise(phases)}}
    return common.finish(request, document, phases, "fql-wall")


def load_model(document: dict, path) -> LearnedWallFollower:
    """Model loader of kind ``fql-wall``: the optimised rule base and how it reads its distances
    (``sensing``, default ``"modules"``)."""
    return common.load_fuzzy_model(document, path, lambda system, speed, name: LearnedWallFollower(
        system, document.get("sensing", "modules"), name=name), keys=("sensing",))

"""The worlds of chapter VI's figures (§VI.2, §VI.5): seeded random starts and goals for the
trajectories after learning, the fixed start of Figs VI.1 and VI.7, the wall a learned avoider
must follow to its goal (Fig VI.21), a world whose straight route is blocked (Figs VI.23–VI.24)
and the second sharp corner of Fig VI.28."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from fuzzynav.experiments import evaluation
from fuzzynav.learn.envs import FixedGoal, RandomGoal, RandomObstacles
from fuzzynav.learn.tasks import common
from fuzzynav.world.scenario import Goal, Scenario, load_scenario
from fuzzynav.world.shapes import Wall
from fuzzynav.world.world import World


def goal_scenarios(seed: int, n: int = 4, layout=None) -> list[Scenario]:
    """``n`` seeded random start/goal worlds of ``layout`` (default: the goal-seeking training
    layout) for the trajectories after learning (Figs VI.4, VI.10, VI.14, VI.16, VI.22)."""
    layout = layout or RandomGoal()
    rng = np.random.default_rng(seed + 1000)
    scenarios = []
    for k in range(n):
        world, start, goal = layout.sample(rng, 1)
        scenarios.append(evaluation.scenario_of(world, start[0], goal[0], f"start {k + 1}", 60.0))
    return scenarios


def fixed_scenario() -> list[Scenario]:
    """The fixed start and goal of Figs VI.1–VI.2 and VI.7–VI.8."""
    layout = FixedGoal()
    world, start, goal = layout.sample(None, 1)
    return [evaluation.scenario_of(world, start[0], goal[0], "fixed start", 60.0)]


def wall_to_goal_scenario() -> Scenario:
    """Fig VI.21: a closed room whose goal lies behind a long wall with a return (an L): the
    avoider reaches it only by following the wall."""
    walls = (Wall((3.0, 11.0), (15.0, 11.0), 0.3), Wall((15.0, 11.0), (15.0, 7.0), 0.3))
    return Scenario(name="fig-VI-21", world=World(20.0, 20.0, walls), start=np.array([9.0, 4.0, np.pi / 2]),
                    goal=Goal(np.array([9.0, 16.0]), common.GOAL_TOLERANCE), max_time=90.0)


def blocked_scenario(seed: int, tries: int = 200) -> Scenario:
    """A random obstacle world (the training layout, seeded) whose straight route from start to
    goal is blocked: the segment passes within the robot's radius + 0.3 m of an obstacle, so both
    navigators of Figs VI.23–VI.24 must avoid."""
    rng = np.random.default_rng(seed + 2000)
    for k in range(tries):
        world, start, goal = RandomObstacles().sample(rng, 1)
        line = start[0, :2] + np.linspace(0.0, 1.0, 200)[:, None] * (goal[0] - start[0, :2])
        if world.clearance(line).min() < 0.3 + 0.3:
            return evaluation.scenario_of(world, start[0], goal[0], f"blocked world {k}", 60.0)
    raise RuntimeError(f"no blocked world in {tries} draws")  # pragma: no cover - the layout is cluttered


def second_corner() -> Scenario:
    """The second sharp corner of Fig VI.28 (b): the wall of ``fig-VI-28`` turning at nearly a
    right angle towards the robot, the goal beyond the corner along the wall's return (reached
    only by following it round; the hand-made follower of Table VI.2 hits it)."""
    base = load_scenario("fig-VI-28")
    walls = (Wall((2.0, 10.0), (14.0, 10.0), 0.3), Wall((14.0, 10.0), (14.5, 3.0), 0.3))
    return replace(base, name="fig-VI-28b", world=World(20.0, 20.0, walls),
                   goal=Goal(np.array([13.0, 3.0]), 0.5))

"""The worlds of Figs VI.23–VI.24 are fair: both navigators must avoid, and can."""

from dataclasses import replace

import numpy as np
import pytest

from fuzzynav.experiments import chapter6_worlds as worlds
from fuzzynav.learn.envs import RandomObstacles
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.world.generate import TURNING_MARGIN, connected
from fuzzynav.world.shapes import Circle
from fuzzynav.world.world import World


def fair(scenario) -> bool:
    """Start and goal as clear as the training layout asks, and joined by free space wide enough
    for the tricycle to turn round (the footprint plus its tightest turning radius)."""
    world, start, goal = scenario.world, scenario.start[:2], scenario.goal.position
    clear = min(world.clearance(np.array([start, goal]))) >= RandomObstacles().clearance
    return clear and connected(world, start, goal, DEFAULT_PARAMS.radius + TURNING_MARGIN)


@pytest.mark.parametrize("seed", range(5))
def test_the_blocked_world_of_each_seed_blocks_the_straight_route_and_is_fair(seed):
    scenario = worlds.blocked_scenario(seed)
    start, goal = scenario.start, scenario.goal.position
    line = start[:2] + np.linspace(0.0, 1.0, 200)[:, None] * (goal - start[:2])
    assert scenario.world.clearance(line).min() < DEFAULT_PARAMS.radius  # the straight route hits an obstacle
    assert np.isclose(start[2], np.arctan2(*(goal - start[:2])[::-1]))  # facing the goal, as in training
    assert fair(scenario)


def test_the_fairness_check_rejects_a_goal_walled_in():
    scenario = worlds.blocked_scenario(0)
    ring = tuple(Circle(scenario.goal.position + 1.6 * np.array([np.cos(a), np.sin(a)]), 0.6)
                 for a in np.linspace(0.0, 2 * np.pi, 12, endpoint=False))
    walled = replace(scenario, world=World(20.0, 20.0, scenario.world.obstacles + ring))
    assert fair(scenario) and not fair(walled)

"""The hand-made wall follower (Table VI.2, §VI.5.3.1): follows a wall, collides at a sharp corner."""

import numpy as np

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.sim import run_episode
from fuzzynav.world.scenario import load_scenario


def test_follows_the_left_wall_to_the_goal():
    scenario = load_scenario("fig-VI-27")
    trace = run_episode(scenario, make_controller("wall-follow"))
    assert trace.outcome == "reached"
    gap = scenario.world.clearance(trace.pose[:, :2])
    along = trace.pose[:, 0] > 4.0
    assert 0.5 < gap[along].min() and gap[along].max() < 2.5  # a kept distance, neither lost nor hit


def test_collides_at_the_sharp_corner_of_fig_VI_28():
    trace = run_episode(load_scenario("fig-VI-28"), make_controller("wall-follow"))
    assert trace.outcome == "collision"
    assert np.hypot(*(trace.pose[-1, :2] - np.array([14.0, 10.0]))) < 1.5  # at the corner, not elsewhere

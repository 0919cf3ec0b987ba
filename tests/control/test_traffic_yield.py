"""The default navigator (``fuzzy-5b`` version 7) yields among moving obstacles: told its scenario
has movers, it runs the tracked yield / evade layer (control/yield_layer.py) after its compiled
decision; told it has none, it decides inside the compiled step alone, as version 6 did."""

import numpy as np

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.control.through_gaps import fuzzy_5b_gap_robust
from fuzzynav.sim import run_episode
from fuzzynav.world.generate import generate_world
from fuzzynav.world.scenario import load_scenario


def test_the_layer_runs_only_where_obstacles_move():
    navigator = make_controller("fuzzy-5b")
    assert navigator.for_traffic(True).in_step is False
    assert navigator.for_traffic(False).in_step is True
    assert fuzzy_5b_gap_robust(yield_in_traffic=False).for_traffic(True).in_step is True


def test_a_static_run_is_the_compiled_step_alone():
    scenario = load_scenario("fig-IV-22a")
    now = run_episode(scenario, make_controller("fuzzy-5b"), seed=0)
    before = run_episode(scenario, fuzzy_5b_gap_robust(yield_in_traffic=False), seed=0)
    assert np.array_equal(now.pose, before.pose) and list(now.behaviour) == list(before.behaviour)


def test_it_gets_through_a_held_out_world_where_version_6_is_run_into():
    """``dynamic`` seed 11, world 6: version 6 (no yield layer) is run into within 2 s; version 7,
    predicting the movers from its scans, yields and reaches the goal."""
    scenario = generate_world("dynamic", 11, 6)
    then = {"guidance": {"guide_off_heading": 0.0}}  # the start steered straight at the goal, as up to version 12
    before = run_episode(scenario, fuzzy_5b_gap_robust(yield_in_traffic=False, **then), seed=0)
    assert before.outcome == "collision"
    after = run_episode(scenario, make_controller("fuzzy-5b", **then), seed=0)
    assert after.outcome == "reached"
    assert "YIELD" in set(after.behaviour)

"""Waypoint switching of path tasks (sim/tasks.py): the thesis' tolerance zone (§V.2) and the
``passed`` rule added for sharp corners (bisector of the corner crossed, next segment nearer)."""

import dataclasses

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.errors import InputError
from fuzzynav.sim import metrics, run_episode
from fuzzynav.sim.tasks import TaskState
from fuzzynav.world.scenario import load_scenario, scenario_from_dict

# example-path: (4,4) -> (8,14) -> (12,4) -> (16,14), 136° corners, 0.5 m zone
CUT_INSIDE = [9.16, 12.56]  # a fuzzy-tracker position after cutting the corner (8,14) 0.71 m inside
WIDE_OUTSIDE = [8.6, 14.6]  # swung wide of the corner, 0.85 m out, just past the bisector x = 8
APPROACHING = [7.58, 12.99]  # on the incoming segment, 1.1 m before the corner


def _state(switching):
    scenario = load_scenario("example-path")
    scenario = dataclasses.replace(scenario, path=dataclasses.replace(scenario.path, switching=switching))
    state = TaskState(scenario, 4)
    state.waypoint_index[:] = 1
    return state


def test_passed_rule_leaves_a_missed_sharp_corner_but_not_before_it():
    state = _state("passed")
    positions = np.array([CUT_INSIDE, WIDE_OUTSIDE, APPROACHING, [8.3, 13.7]])
    assert np.all(np.hypot(*(positions[:2] - [8, 14]).T) > 0.5)  # outside the thesis' zone
    done = state.update(positions, 0.1, np.ones(4, dtype=bool))
    np.testing.assert_array_equal(state.waypoint_index, [2, 2, 1, 2])  # the last one: in the zone
    assert not done.any()


def test_zone_rule_is_the_thesis_tolerance_zone_only():
    state = _state("zone")
    state.update(np.array([CUT_INSIDE, WIDE_OUTSIDE, [8.3, 13.7], APPROACHING]), 0.1, np.ones(4, dtype=bool))
    np.testing.assert_array_equal(state.waypoint_index, [1, 1, 2, 1])


def test_last_waypoint_needs_its_zone():
    state = _state("passed")
    state.waypoint_index[:] = 3
    done = state.update(np.array([[16.2, 14.2], [16.5, 15.0], [17, 14], [15.9, 13.6]]), 0.1, np.ones(4, dtype=bool))
    np.testing.assert_array_equal(done, [True, False, False, True])


@pytest.mark.slow
@pytest.mark.parametrize("controller", ["fuzzy-tracker", "pure-pursuit"])
def test_trackers_complete_example_path_with_the_passed_rule(controller):
    scenario = load_scenario("example-path")
    numbers = metrics(run_episode(scenario, make_controller(controller), seed=0), scenario)
    assert numbers["outcome"] == "reached" and numbers["waypoints_reached"] == 4
    assert numbers["max_cross_track_m"] < 0.7 and numbers["time_s"] < 35


@pytest.mark.slow
def test_thesis_zone_rule_misses_the_sharp_corner_of_the_fuzzy_tracker():
    scenario = load_scenario("example-path")
    scenario = dataclasses.replace(scenario, path=dataclasses.replace(scenario.path, switching="zone"))
    numbers = metrics(run_episode(scenario, make_controller("fuzzy-tracker"), seed=0, max_time=40.0), scenario)
    assert numbers["outcome"] == "timeout" and numbers["waypoints_reached"] < 4


def test_path_switching_is_validated_and_round_trips():
    document = load_scenario("example-path").to_dict()
    assert document["path_switching"] == "passed"
    document["path_switching"] = "zone"
    assert scenario_from_dict(document).path.switching == "zone"
    document["path_switching"] = "bisector"
    with pytest.raises(InputError, match="path_switching"):
        scenario_from_dict(document, source="x.yaml")
    with pytest.raises(InputError, match="path_switching"):
        scenario_from_dict({"robot": {"x": 1, "y": 1}, "goal": {"x": 5, "y": 5}, "path_switching": "zone"})

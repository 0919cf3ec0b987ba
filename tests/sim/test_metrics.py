"""The values of the run metrics (fuzzynav.sim.metrics), worked out by hand."""

import numpy as np
import pytest

from fuzzynav.sim import metrics, run_episode
from fuzzynav.sim.trace import Trace
from fuzzynav.world.scenario import scenario_from_dict
from tests.sim.controllers import ConstantController

WAYPOINTS = [[4.0, 4.0], [10.0, 4.0], [10.0, 12.0]]


def path_scenario():
    return scenario_from_dict({"robot": {"x": 4.0, "y": 4.0}, "path": WAYPOINTS,
                               "obstacles": [{"circle": {"center": [8.0, 8.0], "radius": 1.0}}]},
                              source="test", name="hand-made")


def hand_made_trace(outcome="timeout"):
    """Three commands of 0.5 s, four visited positions (the metrics read only the recorded arrays)."""
    xy = np.array([[4.0, 4.0], [7.0, 5.0], [12.0, 8.0], [10.0, 11.0]])
    index = np.array([1, 1, 2, 2])  # the waypoint aimed at: (10, 4), then (10, 12)
    return Trace(scenario="hand-made", controller="by-hand", task="path", dt=0.5, t=np.array([0.0, 0.5, 1.0, 1.5]),
                 pose=np.column_stack([xy, np.zeros(4)]), ranges=np.full((4, 1), 5.0),
                 target=np.array(WAYPOINTS)[index], waypoint_index=index,
                 steering=np.array([0.2, -0.4, 0.1]), speed=np.array([2.0, -0.5, 1.0]),
                 behaviour=np.array(["a", "b", "c"]), sensor_angles=np.zeros(1), max_range=5.0,
                 outcome=outcome, robot_radius=0.3)


def test_every_metric_of_a_hand_made_trace():
    m = metrics(hand_made_trace(), path_scenario())
    assert m["time_s"] == 1.5 and m["steps"] == 3
    # the driven polyline: √10 + √34 + √13 (not the 9.22 m from the first to the last position)
    assert m["path_length_m"] == pytest.approx(np.sqrt(10) + np.sqrt(34) + np.sqrt(13), abs=1e-12)
    # nearest approach: (7, 5) is √10 m from the circle's centre (8, 8), less its radius and the robot's 0.3 m;
    # the walls are ≥ 4 m away from every position
    assert m["min_clearance_m"] == pytest.approx(np.sqrt(10) - 1.0 - 0.3, abs=1e-9)
    # signed speeds 2, -0.5 (reversing), 1: mean 2.5 / 3 (mean |V| would be 3.5 / 3); the last is 1 (the first 2)
    assert m["mean_speed_mps"] == pytest.approx(2.5 / 3, abs=1e-12)
    assert m["final_speed_mps"] == 1.0
    # steering 0.2, -0.4, 0.1: mean |α| = 0.7 / 3 (mean α -0.1 / 3); Σ|Δα| = 0.6 + 0.5 (|ΣΔα| = 0.1)
    assert m["steering_effort_rad"] == pytest.approx(0.7 / 3, abs=1e-12)
    assert m["steering_variation_rad"] == pytest.approx(1.1, abs=1e-12)
    # the last position (10, 11) to the last waypoint aimed at (10, 12); the first aimed at, (10, 4), is 7 m away
    assert m["final_distance_m"] == pytest.approx(1.0, abs=1e-12)
    # distances to the path's segments: 0, 1 (below the first), 2 (right of the second), 0: mean 0.75, max 2
    assert m["mean_cross_track_m"] == pytest.approx(0.75, abs=1e-12)
    assert m["max_cross_track_m"] == pytest.approx(2.0, abs=1e-12)
    assert m["waypoints_reached"] == 2 and not m["completed"] and m["timeout"] and not m["collision"]
    assert metrics(hand_made_trace("reached"), path_scenario())["waypoints_reached"] == 3  # and the last one


def test_metrics_of_a_constant_turn_in_closed_loop():
    """α = 0.25 rad, V = 1 m/s for 3 s on the default robot (Euler, Δt = 0.1 s, l = 0.5 m): each step is
    0.1 m long and turns the heading by 0.1 tan(0.25) / 0.5 rad (eq IV.2)."""
    scenario = scenario_from_dict({"robot": {"x": 10.0, "y": 10.0, "theta": 0.0}, "goal": {"x": 15.0, "y": 2.0},
                                   "max_time": 3}, source="test")
    m = metrics(run_episode(scenario, ConstantController(0.25, 1.0)), scenario)
    assert m["outcome"] == "timeout" and m["time_s"] == 3.0 and m["steps"] == 30
    assert m["path_length_m"] == pytest.approx(3.0, abs=1e-9)
    assert m["mean_speed_mps"] == 1.0 and m["final_speed_mps"] == 1.0
    assert m["steering_effort_rad"] == pytest.approx(0.25, abs=1e-12) and m["steering_variation_rad"] == 0.0
    heading = np.arange(30) * 0.1 * np.tan(0.25) / 0.5
    end = np.array([10.0, 10.0]) + 0.1 * np.array([np.cos(heading).sum(), np.sin(heading).sum()])
    assert m["final_distance_m"] == pytest.approx(np.hypot(*(end - [15.0, 2.0])), abs=1e-9)
    assert m["final_distance_m"] > np.hypot(5.0, 8.0)  # it turned left, away from the goal below it


def test_the_target_metrics_of_a_hand_made_pursuit():
    """A target moving along x from (10, 5) at 1 m/s, pursued for 2 s (dt 1 s): captured or not."""
    scenario = scenario_from_dict({"robot": {"x": 2.0, "y": 5.0}, "target": {
        "x": 10.0, "y": 5.0, "tolerance": 0.5, "motion": {"type": "line", "velocity": [1.0, 0.0]}}},
        source="test", name="pursuit")
    target = np.array([[10.0, 5.0], [11.0, 5.0], [12.0, 5.0]])

    def trace(outcome, last):
        xy = np.array([[2.0, 5.0], [6.0, 5.0], last])
        return Trace(scenario="pursuit", controller="by-hand", task="target", dt=1.0, t=np.array([0.0, 1.0, 2.0]),
                     pose=np.column_stack([xy, np.zeros(3)]), ranges=np.full((3, 1), 4.0), target=target,
                     waypoint_index=np.zeros(3, dtype=int), steering=np.zeros(2), speed=np.array([4.0, 4.0]),
                     behaviour=np.array(["a", "a"]), sensor_angles=np.zeros(1), max_range=4.0, outcome=outcome,
                     robot_radius=0.3)

    caught = metrics(trace("reached", [12.0, 5.3]), scenario)  # 0.3 m from the target at t = 2 s
    assert caught["captured"] and caught["capture_time_s"] == 2.0
    assert caught["final_error_m"] == pytest.approx(0.3, abs=1e-12) == caught["final_distance_m"]
    missed = metrics(trace("timeout", [9.0, 5.0]), scenario)  # 3 m behind it when the time is up
    assert not missed["captured"] and missed["capture_time_s"] is None
    assert missed["final_error_m"] == pytest.approx(3.0, abs=1e-12)  # not the 1 m to where the target started

"""Chapter V trackers: sign convention, corner anticipation, closed loop on the thesis' paths and targets."""

import math

import numpy as np
import pytest

from fuzzynav.control.registry import make_controller
from fuzzynav.control.tracking import FuzzyTracker, corner_leads
from fuzzynav.errors import InputError
from fuzzynav.sim import metrics, paths, run_episode
from fuzzynav.sim.observation import BatchObservation
from fuzzynav.world.scenario import load_scenario

TRACKERS = ("fuzzy-tracker", "neural-tracker", "anfis-tracker")


def _obs(pose, target, path=None, index=0):
    pose = np.atleast_2d(np.asarray(pose, dtype=float))
    n = len(pose)
    return BatchObservation(t=0.0, dt=0.1, pose=pose, speed=np.ones(n), steering=np.zeros(n),
                            target=np.tile(np.asarray(target, dtype=float), (n, 1)), ranges=np.zeros((n, 0)),
                            sensor_angles=np.zeros(0), max_range=4.0, obstacle_distance=np.full(n, np.inf),
                            obstacle_bearing=np.zeros(n), active=np.ones(n, dtype=bool), path=path,
                            waypoint_index=np.full(n, index))


@pytest.mark.parametrize("name", TRACKERS)
def test_trackers_steer_towards_the_target_side(name):
    tracker = make_controller(name)
    left, _, _ = tracker.act_batch(_obs([[0, 0, 0.0], [0, 0, 0.0]], [5, 3]))
    tracker.reset()
    right, _, _ = tracker.act_batch(_obs([[0, 0, 0.0]], [5, -3]))
    assert left[0] > 0.05 and right[0] < -0.05
    assert abs(left[0]) <= math.pi / 4 + 1e-12


def test_corner_leads_follow_the_tangent_arc():
    lead = corner_leads(paths.n_path(), 0.5, lag=0.1)
    x = 0.5 * math.tan(math.radians(67.5)) + 0.1
    np.testing.assert_allclose(lead, [0, x, x, 0])


def test_anticipation_switches_before_the_simulator_zone():
    path = paths.n_path()
    tracker = FuzzyTracker(corner_radius=0.5)
    # 1.2 m before the corner (3,17) on the incoming segment: lead is 1.207 + 0.1 m -> aim at (17,3)
    np.testing.assert_array_equal(tracker.aim_points(_obs([3, 15.8, math.pi / 2], path[1], path, 1)), [path[2]])
    thesis = FuzzyTracker(corner_radius=0.0)
    np.testing.assert_array_equal(thesis.aim_points(_obs([3, 15.8, math.pi / 2], path[1], path, 1)), [path[1]])


def test_bad_options_raise_input_error():
    with pytest.raises(InputError):
        FuzzyTracker(speed=0)
    with pytest.raises(InputError):
        FuzzyTracker(corner_radius=-1)


@pytest.mark.slow
@pytest.mark.parametrize("scenario_name", ["path-v", "path-n", "path-trapezoid"])
@pytest.mark.parametrize("name", TRACKERS)
def test_every_tracker_completes_the_thesis_paths(name, scenario_name):
    scenario = load_scenario(scenario_name)
    result = metrics(run_episode(scenario, make_controller(name)), scenario)
    assert result["completed"] and not result["collision"]
    assert result["max_cross_track_m"] < 1.0
    assert result["mean_cross_track_m"] < 0.35


@pytest.mark.slow
@pytest.mark.parametrize("name", TRACKERS)
def test_thesis_variant_completes_the_v_path_of_fig_v_28(name):
    scenario = load_scenario("fig-V-28")
    result = metrics(run_episode(scenario, make_controller(name, corner_radius=0.0)), scenario)
    assert result["completed"] and result["max_cross_track_m"] < 0.8


@pytest.mark.slow
@pytest.mark.parametrize("scenario_name", ["fig-V-29", "fig-V-30", "fig-V-31"])
@pytest.mark.parametrize("name", TRACKERS)
def test_pursuit_captures_the_moving_target(name, scenario_name):
    scenario = load_scenario(scenario_name)
    result = metrics(run_episode(scenario, make_controller(name)), scenario)
    assert result["captured"] and result["capture_time_s"] < 20.0
    assert result["final_error_m"] <= scenario.target.tolerance


@pytest.mark.slow
def test_learned_trackers_beat_the_fuzzy_one_at_the_corner():
    """§V.4: the error at the direction change is smallest for CN and CNF (Fig V.28 d)."""
    scenario = load_scenario("fig-V-28")
    errors = {name: metrics(run_episode(scenario, make_controller(name, corner_radius=0.0)), scenario)["max_cross_track_m"]
              for name in TRACKERS}
    assert errors["neural-tracker"] < errors["fuzzy-tracker"] and errors["anfis-tracker"] < errors["fuzzy-tracker"]

"""Chapter V trackers: sign convention, corner anticipation, closed loop on the thesis' paths and targets."""

import math

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.control.base import BatchObservation
from fuzzynav.control.reference import APPROACH, smoothed_path, swing_offset
from fuzzynav.control.tracking import DEFAULT_CORNER_RADIUS, FuzzyTracker
from fuzzynav.errors import InputError
from fuzzynav.sim import metrics, paths, run_episode
from fuzzynav.sim.metrics import cross_track
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


def test_swing_offset_balances_the_cut_and_the_overshoot():
    # e = R (1 - cos(phi/2)) / 2 for R = R_min = l / tan(pi/4) = 0.5 m: 0.084 m at the 97 deg corner of the V path
    assert DEFAULT_CORNER_RADIUS == pytest.approx(0.5)
    phi = abs(paths.turn_angles(paths.v_path())[0])
    assert swing_offset(phi, 0.5) == pytest.approx(0.25 * (1 - math.cos(phi / 2))) == pytest.approx(0.084, abs=1e-3)
    assert swing_offset(0.0, 0.5) == 0.0
    # from 134.8 deg on the closest approach (R - e)/cos(phi/2) - R is capped at APPROACH
    e = swing_offset(math.radians(160), 0.5)
    assert (0.5 - e) / math.cos(math.radians(80)) - 0.5 == pytest.approx(APPROACH)


@pytest.mark.parametrize("make", [paths.n_path, paths.v_path, paths.trapezoid_path])
def test_smoothed_reference_is_drivable_and_stays_within_the_swing(make):
    path = make()
    ref = smoothed_path(path, 0.5)
    step = np.hypot(*np.diff(ref, axis=0).T)
    heading = np.arctan2(*np.diff(ref, axis=0).T[::-1])
    curvature = np.abs(np.angle(np.exp(1j * np.diff(heading)))) / step[1:]
    assert curvature.max() <= 1 / 0.5 * 1.05  # no tighter than the robot's R_min
    np.testing.assert_allclose(ref[[0, -1]], path[[0, -1]])
    worst = swing_offset(paths.turn_angles(path), 0.5).max()
    assert cross_track(ref, path).max() == pytest.approx(worst, abs=5e-3)  # cut inside = swing outside
    for corner in path[1:-1]:
        assert np.hypot(*(ref - corner).T).min() <= APPROACH + 1e-3  # samples 2 cm apart


def test_anticipation_aims_ahead_on_the_reference_and_the_thesis_at_the_waypoint():
    path = paths.n_path()
    tracker = FuzzyTracker(lookahead=0.35)
    # 1.2 m before the corner (3,17): the reference swings outwards (x < 3) and the aim point is 0.35 m ahead
    aim = tracker.aim_points(_obs([3, 15.8, math.pi / 2], path[1], path, 1))[0]
    assert aim[0] < 3.0 and 15.8 < aim[1] < 17.0
    nearest = np.argmin(np.hypot(*(tracker.reference_ - [3, 15.8]).T))  # first call: searched over the whole path
    np.testing.assert_array_equal(aim, tracker.reference_[nearest + round(0.35 / 0.02)])
    thesis = FuzzyTracker(corner_radius=0.0)
    np.testing.assert_array_equal(thesis.aim_points(_obs([3, 15.8, math.pi / 2], path[1], path, 1)), [path[1]])


def test_bad_options_raise_input_error():
    with pytest.raises(InputError):
        FuzzyTracker(speed=0)
    with pytest.raises(InputError):
        FuzzyTracker(corner_radius=-1)
    with pytest.raises(InputError):
        FuzzyTracker(lookahead=0)


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


@pytest.mark.slow
@pytest.mark.parametrize("name", ["neural-tracker", "anfis-tracker"])
def test_learned_trackers_beat_the_best_pure_pursuit_on_the_n_path(name):
    """Issue 4's goal on the 135° corners: pure pursuit at its best look-ahead there (0.75 m,
    benchmarks/tracking_bench.py) against our tracker with its one default setting."""
    scenario = load_scenario("path-n")
    ours = metrics(run_episode(scenario, make_controller(name)), scenario)
    baseline = metrics(run_episode(scenario, make_controller("pure-pursuit", lookahead=0.75)), scenario)
    assert ours["completed"] and baseline["completed"]
    assert ours["max_cross_track_m"] < 0.9 * baseline["max_cross_track_m"]


def test_anticipation_keeps_one_index_per_robot_of_a_batch():
    path = paths.n_path()
    tracker = FuzzyTracker(lookahead=0.35)
    poses = [[3, 5, math.pi / 2], [10, 10, -math.pi / 4], [17, 8, math.pi / 2]]
    aims = tracker.aim_points(_obs(poses, path[1], path, 1))
    for pose, aim in zip(poses, aims):
        single = FuzzyTracker(lookahead=0.35).aim_points(_obs([pose], path[1], path, 1))[0]
        np.testing.assert_array_equal(aim, single)
        assert 0.3 < np.hypot(*(aim - pose[:2])) < 0.4  # the robots are on straight parts of the path

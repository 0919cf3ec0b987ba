import json

import numpy as np
import pytest

from fuzzynav.robot.sensors import SensorRing
from fuzzynav.robot.tricycle import TricycleParams
from fuzzynav.sim import BatchSimulator, Simulator, metrics, run_episode
from fuzzynav.sim.metrics import cross_track
from fuzzynav.world.scenario import load_scenario, scenario_from_dict
from tests.sim.controllers import ConstantController, CountingController, HeadingController, SingleHeading


def goal_world(**extra):
    doc = {"robot": {"x": 2.0, "y": 2.0, "theta": 0.0}, "goal": {"x": 15.0, "y": 12.0, "tolerance": 0.3}}
    doc.update(extra)
    return scenario_from_dict(doc, source="test")


def test_goal_reached_and_speed_falls_at_the_goal():
    scenario = goal_world()
    trace = run_episode(scenario, HeadingController())
    m = metrics(trace, scenario)
    assert m["reached_goal"] and not m["collision"] and m["outcome"] == "reached"
    assert np.hypot(*(trace.pose[-1, :2] - [15, 12])) <= 0.3
    assert trace.speed[-1] < 0.6 < trace.speed.max()
    assert m["final_speed_mps"] == trace.speed[-1]  # the speed it arrived at, in every run's JSON
    straight = np.hypot(13, 10)
    assert straight - 0.3 <= m["path_length_m"] < straight + 1.0
    assert m["steps"] == trace.steps == len(trace.pose) - 1
    assert m["time_s"] == pytest.approx(trace.steps * 0.1)
    json.dumps(m)


def test_collision_with_an_obstacle_stops_the_episode():
    scenario = goal_world(obstacles=[{"circle": {"center": [8, 2], "radius": 1.0}}], goal={"x": 15, "y": 2})
    trace = run_episode(scenario, ConstantController(0.0, 1.0))
    assert trace.outcome == "collision"
    # stops on the first step whose footprint (0.3 m) overlaps the circle surface at x = 7
    assert trace.pose[-1, 0] > 7.0 - 0.3 >= trace.pose[-2, 0]
    assert metrics(trace, scenario)["min_clearance_m"] < 0


def test_collision_with_the_boundary():
    scenario = goal_world(goal={"x": 15, "y": 2})
    trace = run_episode(scenario, ConstantController(0.0, 1.0), start=[2.0, 2.0, -np.pi / 2])
    assert trace.outcome == "collision" and trace.pose[-1, 1] < 0.3


def test_timeout():
    scenario = goal_world(max_time=5)
    trace = run_episode(scenario, ConstantController(0.0, 0.0))
    assert trace.outcome == "timeout" and trace.steps == 50 and trace.time == pytest.approx(5.0)
    assert run_episode(scenario, ConstantController(0.0, 0.0), max_time=2).steps == 20


def test_commands_are_clipped():
    trace = run_episode(goal_world(max_time=1), ConstantController(3.0, 10.0))
    assert np.all(trace.steering == pytest.approx(np.pi / 4)) and np.all(trace.speed == 4.0)


def test_path_waypoint_switching_and_cross_track():
    scenario = load_scenario("example-path")
    trace = run_episode(scenario, HeadingController(gain=3.0))
    m = metrics(trace, scenario)
    assert m["completed"] and m["waypoints_reached"] == 4
    assert np.all(trace.speed == scenario.path.speed)  # constant tracking speed (thesis §V.2)
    index = trace.waypoint_index
    assert np.all(np.diff(index) >= 0) and index[-1] == 3
    waypoints = scenario.path.waypoints
    for k in np.flatnonzero(np.diff(index)) + 1:  # switched on entering the tolerance zone
        assert np.hypot(*(trace.pose[k, :2] - waypoints[index[k] - 1])) <= scenario.path.tolerance
        assert np.hypot(*(trace.pose[k - 1, :2] - waypoints[index[k] - 1])) > scenario.path.tolerance
    np.testing.assert_allclose(trace.target, waypoints[index])
    assert 0 < m["mean_cross_track_m"] < m["max_cross_track_m"] < 1.0
    # the distance to the polyline's segments, not to the lines through them: (2, 4) is 2 m before the
    # first waypoint (1.86 m from the first line), (8, 16) 2 m beyond the corner (8, 14) (0.74 m from it)
    points = np.array([[4.0, 4.0], [2.0, 4.0], [8.0, 16.0], [10.0, 9.0], [14.0, 9.0]])
    np.testing.assert_allclose(cross_track(points, waypoints), [0.0, 2.0, 2.0, 0.0, 0.0], atol=1e-12)


def test_moving_target_is_captured():
    scenario = load_scenario("example-target")
    trace = run_episode(scenario, HeadingController(cruise=1.5, floor=0.5))
    m = metrics(trace, scenario)
    assert m["captured"] and 5 < m["capture_time_s"] < scenario.max_time
    motion = scenario.target.motion
    np.testing.assert_allclose(trace.target, motion.position(trace.t))
    assert trace.target[-1, 0] > trace.target[0, 0]  # it moved
    assert m["final_error_m"] <= scenario.target.tolerance


def test_observation_contents():
    scenario = load_scenario("example-goal")
    seen = []

    class Spy(ConstantController):
        def act(self, obs):
            seen.append(obs)
            return super().act(obs)

    sensors = SensorRing()
    trace = run_episode(scenario, Spy(0.1, 1.0), sensors=sensors, max_time=1)
    first = seen[0]
    np.testing.assert_allclose(first.target, [18, 18])
    assert first.max_range == 4.0 and len(first.sensor_angles) == 7
    np.testing.assert_allclose(first.ranges, scenario.world.ranges(scenario.start[None], sensors.angles, 4.0)[0])
    # D_ro to the circle (5, 5) r = 1 from (1, 1), bearing 45° left of the heading
    assert first.obstacle_distance == pytest.approx(np.hypot(4, 4) - 1)
    assert first.obstacle_bearing == pytest.approx(np.pi / 4)
    assert seen[1].speed == 1.0 and seen[1].steering == pytest.approx(0.1)
    np.testing.assert_allclose(trace.ranges[3], seen[3].ranges)


def test_batch_matches_single_runs():
    scenario = load_scenario("example-goal")
    starts = np.array([[1, 1, 0], [1, 18, -1.0], [18, 1, 2.0], [10, 16, 3.0], [16, 16, 0.5], [3, 8, 1.0]])
    batch = BatchSimulator(scenario, HeadingController(), starts=starts).run()
    per_robot = BatchSimulator(scenario, SingleHeading(), starts=starts).run()
    outcomes = batch.outcomes()
    assert set(outcomes) >= {"reached", "collision"}
    assert per_robot.outcomes() == outcomes
    for i, start in enumerate(starts):
        single = Simulator(scenario, HeadingController(), start=start).run()
        assert single.outcome == outcomes[i]
        np.testing.assert_allclose(batch.trace(i).pose, single.pose)
        np.testing.assert_array_equal(batch.trace(i).behaviour, single.behaviour)


def test_batch_path_tracking_keeps_one_waypoint_index_per_robot():
    scenario = load_scenario("example-path")
    starts = np.array([[4, 4, 0.0], [4, 8, 1.0], [9, 12, 0.0]])  # the third starts past waypoint 1
    batch = BatchSimulator(scenario, HeadingController(gain=3.0), starts=starts).run()
    assert batch.outcomes() == ["reached"] * 3
    for i, start in enumerate(starts):
        single = Simulator(scenario, HeadingController(gain=3.0), start=start).run()
        np.testing.assert_array_equal(batch.trace(i).waypoint_index, single.waypoint_index)
        np.testing.assert_allclose(batch.trace(i).pose, single.pose)
    assert batch.trace(0).steps != batch.trace(2).steps


def test_stateful_controllers_are_copied_per_robot():
    scenario = goal_world(max_time=1)
    controller = CountingController()
    sim = BatchSimulator(scenario, controller, n=3).run()
    assert [sim.trace(i).behaviour[-1] for i in range(3)] == ["call10"] * 3
    for robot in (3, -1, 1.0, True):  # one of the 3 robots, by its number: nothing else, no wrap-round
        with pytest.raises(IndexError, match=r"robot must be a whole number from 0 to 2, got"):
            sim.trace(robot)


def test_sensor_noise_is_seeded():
    scenario = load_scenario("example-goal")
    sensors = SensorRing(noise_std=0.1)
    a = run_episode(scenario, HeadingController(), sensors=sensors, seed=5, max_time=3)
    b = run_episode(scenario, HeadingController(), sensors=sensors, seed=5, max_time=3)
    c = run_episode(scenario, HeadingController(), sensors=sensors, seed=6, max_time=3)
    np.testing.assert_array_equal(a.ranges, b.ranges)
    assert not np.array_equal(a.ranges, c.ranges)


def test_arc_integrator_and_no_record_mode():
    scenario = goal_world()
    params = TricycleParams(integrator="arc")
    trace = run_episode(scenario, HeadingController(), robot_params=params)
    assert trace.reached
    sim = BatchSimulator(scenario, HeadingController(), n=4, record=False).run()
    assert sim.outcomes() == ["reached"] * 4
    with pytest.raises(RuntimeError):
        sim.trace(0)

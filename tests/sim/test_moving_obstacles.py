"""Moving obstacles in the simulator: the compiled step moves them, the sensors and the collision
test see them where they are, a collision records who moved into whom, and a static scenario runs
bit for bit as before moving obstacles existed."""

import json
from pathlib import Path

import numpy as np
import pytest

from fuzzynav.control.batched import ConstantCommand
from fuzzynav.sim import metrics
from fuzzynav.sim.simulator import BatchSimulator, run_episode
from fuzzynav.world.moving import offsets
from fuzzynav.world.scenario import scenario_from_dict
from fuzzynav.world.world import World
from tests.sim.static_hashes import all_hashes

HASHES = Path(__file__).with_name("static_hashes.json")


def scenario(obstacles, robot=(2.0, 10.0, 0.0), max_time=30.0):
    return scenario_from_dict({"robot": dict(zip("x y theta".split(), robot)), "goal": {"x": 18, "y": 18},
                               "obstacles": obstacles, "max_time": max_time}, source="moving.yaml")


def test_a_standing_robot_hit_by_an_obstacle_is_not_at_fault():
    s = scenario([{"circle": {"center": [8, 10], "radius": 0.4}, "motion": {"type": "line", "velocity": [-1.0, 0]}}])
    trace = run_episode(s, ConstantCommand(0.0, 0.0))
    assert trace.outcome == "collision" and trace.collision_by == "obstacle"
    assert 5.0 < trace.time < 5.4  # the disc's edge reaches the robot's footprint after (6 - 0.7) / 1 m/s
    numbers = metrics(trace, s)
    assert numbers["collision_by"] == "obstacle" and numbers["min_clearance_m"] < 0
    assert np.allclose(trace.pose, [2.0, 10.0, 0.0])


def test_a_robot_driving_into_an_obstacle_is_at_fault():
    moving_away = {"circle": {"center": [8, 10], "radius": 0.4}, "motion": {"type": "line", "velocity": [0.2, 0]}}
    standing = {"circle": {"center": [8, 10], "radius": 0.4}}
    for obstacle in (moving_away, standing):
        trace = run_episode(scenario([obstacle]), ConstantCommand(0.0, 1.0))
        assert trace.outcome == "collision" and trace.collision_by == "robot"


def test_no_collision_no_fault_and_a_wall_hit_is_the_robots():
    s = scenario([{"circle": {"center": [8, 14], "radius": 0.4}, "motion": {"type": "line", "velocity": [0.5, 0]}}])
    trace = run_episode(s, ConstantCommand(0.0, 1.0))  # drives into the east border
    assert trace.outcome == "collision" and trace.collision_by == "robot"
    assert metrics(run_episode(s, ConstantCommand(0.0, 0.0), max_time=3.0), s)["collision_by"] is None


def test_sensors_and_clearance_see_the_obstacle_where_it_is():
    """At every step the rays of a standing robot read what they read in a static world holding
    the obstacle at its offset of that step."""
    entry = {"polygon": {"points": [[6, 12], [7, 12], [7, 13]]},
             "motion": {"type": "waypoints", "points": [[6, 12], [6, 7], [9, 8]], "speed": 1.2, "loop": True}}
    s = scenario([entry, {"circle": {"center": [5, 5], "radius": 0.6}}], robot=(3.5, 10.0, 0.0), max_time=12.0)
    sim = BatchSimulator(s, ConstantCommand(0.0, 0.0), seed=0)
    trace = sim.run().trace(0)
    moved = offsets(s.world, trace.t)
    np.testing.assert_array_equal(trace.obstacle_offsets[:, 0], moved[:, 0])
    shape = s.world.obstacles[0]
    readings = []
    for k in range(0, len(trace.t), 10):
        placed = type(shape)(points=shape.points + moved[k, 0])
        world = World(20.0, 20.0, (placed, s.world.obstacles[1]))
        readings.append(world.ranges(trace.pose[k], trace.sensor_angles, trace.max_range)[0])
        assert world.clearance(trace.pose[k:k + 1, :2])[0] == pytest.approx(
            s.world.clearance_over_time(trace.pose[k:k + 1, :2], moved[k:k + 1])[0], abs=1e-12)
    np.testing.assert_allclose(trace.ranges[::10], readings, rtol=0, atol=1e-9)
    assert np.ptp(trace.ranges[:, 0]) > 1.0  # the obstacle crossed the forward ray


def test_many_robots_each_judged_on_their_own():
    s = scenario([{"circle": {"center": [8, 10], "radius": 0.4}, "motion": {"type": "line", "velocity": [-1.0, 0]}}])
    sim = BatchSimulator(s, ConstantCommand(0.0, 0.0), starts=[[2, 10, 0], [2, 4, 0]], max_time=10.0).run()
    assert sim.outcomes() == ["collision", "timeout"] and sim.collisions_by() == ["obstacle", None]


@pytest.mark.slow
def test_static_scenarios_run_bit_for_bit_as_before():
    """Traces of built-in scenarios under compiled and Python navigators and trackers hash as
    those recorded with the code before moving obstacles (``python -m tests.sim.static_hashes``)."""
    assert all_hashes() == json.loads(HASHES.read_text())


def test_numpy_runs_the_simd_code_the_traces_were_recorded_with():
    """tests/conftest.py keeps NumPy off AVX-512, whose exp, log, arctan and tan differ in the last
    bits (the recorded hashes above would then not match on such a machine)."""
    from tests.conftest import NUMPY_AVX2

    try:
        from numpy._core._multiarray_umath import __cpu_dispatch__, __cpu_features__
    except ImportError:  # NumPy 1.x
        from numpy.core._multiarray_umath import __cpu_dispatch__, __cpu_features__
    assert not [name for name in __cpu_dispatch__ if name in NUMPY_AVX2.split() and __cpu_features__.get(name)]

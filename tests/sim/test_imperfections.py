"""The real robot's imperfections (``robot.sensor_noise``, ``robot.actuation``,
``robot.odometry``): parsed and checked as scenario keys, off by default (the perfect robot bit
for bit), each one seen in closed-loop runs of the compiled step, reproducible from the seed."""

import dataclasses
import json

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.robot.imperfections import NONE, Imperfections, perturbed
from fuzzynav.robot.sensors import named_ring
from fuzzynav.sim import run_episode
from fuzzynav.sim.simulator import BatchSimulator
from fuzzynav.world.scenario import load_scenario, scenario_from_dict
from tests.sim.controllers import ConstantController

OPEN = {"world": {"width": 20, "height": 20}, "robot": {"x": 2.0, "y": 10.0, "theta": 0.0},
        "goal": {"x": 18.0, "y": 10.0}, "max_time": 3.0}


def _open(**robot):
    return scenario_from_dict({**OPEN, "robot": {**OPEN["robot"], **robot}}, source="open.yaml")


def test_keys_parse_round_trip_and_default_off():
    scenario = _open(sensor_noise={"range_sigma": 0.02, "dropout": 0.01, "max_range": 8.0},
                     actuation={"latency": 0.1, "steering_rate": 1.5, "acceleration": 2.0, "slip": 0.05},
                     odometry={"drift": 0.01})
    assert scenario.imperfections == Imperfections(0.02, 0.01, 8.0, 0.1, 1.5, 2.0, 0.05, 0.01)
    assert scenario_from_dict(scenario.to_dict()).imperfections == scenario.imperfections
    assert _open().imperfections == NONE and NONE.off
    assert _open(sensor_noise={"range_sigma": 0}, odometry={"drift": 0.0}).imperfections.off


@pytest.mark.parametrize("robot, field", [
    ({"sensor_noise": {"range_sigma": -0.1}}, "robot.sensor_noise.range_sigma"),
    ({"sensor_noise": {"sigma": 0.1}}, "robot.sensor_noise.sigma"),
    ({"sensor_noise": {"dropout": 1.0}}, "robot.sensor_noise.dropout"),
    ({"sensor_noise": {"max_range": 0}}, "robot.sensor_noise.max_range"),
    ({"actuation": {"latency": "fast"}}, "robot.actuation.latency"),
    ({"actuation": {"slip": 0.5}}, "robot.actuation.slip"),
    ({"actuation": {"acceleration": 0}}, "robot.actuation.acceleration"),
    ({"odometry": [0.01]}, "robot.odometry"),
    ({"odometry": {"drift": float("nan")}}, "robot.odometry.drift"),
])
def test_bad_values_name_the_file_and_field(robot, field):
    with pytest.raises(InputError) as error:
        _open(**robot)
    assert error.value.source == "open.yaml" and error.value.field == field


def test_keys_set_to_zero_give_the_perfect_robot_bit_for_bit():
    scenario = load_scenario("fig-IV-22a")
    zeros = scenario_from_dict({**scenario.to_dict(), "robot": {
        **scenario.to_dict()["robot"], "sensor_noise": {"range_sigma": 0.0, "dropout": 0.0},
        "actuation": {"latency": 0.0, "slip": 0.0}, "odometry": {"drift": 0.0}}})
    perfect = run_episode(scenario, make_controller("fuzzy-5b"), seed=0, max_time=8.0)
    same = run_episode(zeros, make_controller("fuzzy-5b"), seed=0, max_time=8.0)
    assert np.array_equal(perfect.pose, same.pose) and np.array_equal(perfect.ranges, same.ranges)


def _first_ranges(scenario, ring, seed=0):
    return BatchSimulator(scenario, ConstantController(), sensors=named_ring(ring), seed=seed)._ranges[0].copy()


@pytest.mark.parametrize("ring", ["thesis", "beam", "lidar"])
def test_range_noise_and_dropout_on_every_sensor_type(ring):
    scenario = load_scenario("fig-IV-22a")
    exact = _first_ranges(scenario, ring)
    noisy_scenario = dataclasses.replace(scenario, imperfections=Imperfections(range_sigma=0.05))
    noisy = _first_ranges(noisy_scenario, ring)
    inside = exact < 4.0 - 0.3
    assert not np.array_equal(noisy[inside], exact[inside])
    assert np.all(np.abs(noisy - exact) < 6 * 0.05) and np.all((noisy >= 0) & (noisy <= 4.0))
    assert np.array_equal(noisy, _first_ranges(noisy_scenario, ring))  # the seed's draws
    assert not np.array_equal(noisy, _first_ranges(noisy_scenario, ring, seed=1))
    dropped = _first_ranges(dataclasses.replace(scenario, imperfections=Imperfections(dropout=0.999)), ring)
    assert np.all(dropped == 4.0)
    capped = _first_ranges(dataclasses.replace(scenario, imperfections=Imperfections(max_range=1.0)), ring)
    assert np.array_equal(capped, np.minimum(exact, 1.0))


def test_noise_statistics_on_the_lidar():
    scenario = dataclasses.replace(load_scenario("fig-IV-22a"), imperfections=Imperfections(range_sigma=0.02))
    exact = _first_ranges(load_scenario("fig-IV-22a"), "lidar")
    errors = np.concatenate([_first_ranges(scenario, "lidar", seed)[exact < 3.5] - exact[exact < 3.5]
                             for seed in range(20)])
    assert abs(errors.mean()) < 0.002 and errors.std() == pytest.approx(0.02, rel=0.1)


def _drive(imperfections, steering=0.0, speed=1.0, seconds=3.0, seed=0):
    sim = BatchSimulator(dataclasses.replace(_open(), imperfections=imperfections),
                         ConstantController(steering, speed), seed=seed, max_time=seconds)
    return sim.run().trace(0), sim


def test_latency_is_a_command_queue():
    trace, _ = _drive(Imperfections(latency=0.3))
    assert np.all(trace.speed[:3] == 0.0) and np.all(trace.speed[3:] == 1.0)
    assert np.all(trace.pose[:4, 0] == 2.0) and trace.pose[5, 0] > 2.0


def test_acceleration_and_steering_rate_limit_the_applied_commands():
    trace, _ = _drive(Imperfections(acceleration=2.0, steering_rate=1.5), steering=0.6, speed=3.0)
    assert np.allclose(np.diff(np.r_[0.0, trace.speed])[:14], 0.2)  # 2 m/s² × 0.1 s, up to 3 m/s
    assert trace.speed[-1] == pytest.approx(3.0)
    assert np.allclose(trace.steering[:4], [0.15, 0.3, 0.45, 0.6]) and np.all(trace.steering[4:] == 0.6)


def test_slip_loses_speed_and_heading_rate_on_average():
    straight, _ = _drive(NONE)
    slipping, _ = _drive(Imperfections(slip=0.1))
    ratio = (slipping.pose[-1, 0] - 2.0) / (straight.pose[-1, 0] - 2.0)
    assert 0.85 < ratio < 0.95 and np.all(slipping.speed == 1.0)  # the commands applied, the ground lost 10 %
    turning, _ = _drive(NONE, steering=0.3)
    turning_slip, _ = _drive(Imperfections(slip=0.1), steering=0.3)
    turned = np.abs(np.unwrap(turning_slip.pose[:, 2]))[-1] / np.abs(np.unwrap(turning.pose[:, 2]))[-1]
    assert 0.75 < turned < 0.95  # heading rate: (1 − 10 %) of ω on (1 − 10 %) of the distance


def test_odometry_drift_moves_the_believed_pose_not_the_true_one():
    true, _ = _drive(NONE)
    trace, sim = _drive(Imperfections(drift=0.05))
    assert np.array_equal(trace.pose, true.pose)  # the true pose, for collisions and the goal
    believed = sim.observation.pose[0]
    driven = trace.pose[-1, 0] - 2.0
    assert np.hypot(*(believed[:2] - trace.pose[-1, :2])) == pytest.approx(0.05 * driven, rel=1e-6)
    assert believed[2] == trace.pose[-1, 2]


def test_the_default_navigator_sees_its_believed_goal_bearing():
    """fuzzy-5b (compiled) under a large drift ends its run elsewhere than the perfect one:
    it steers on the believed pose."""
    scenario = load_scenario("fig-IV-22a")
    perfect = run_episode(scenario, make_controller("fuzzy-5b"), seed=0, max_time=8.0)
    drifting = run_episode(dataclasses.replace(scenario, imperfections=Imperfections(drift=0.3)),
                           make_controller("fuzzy-5b"), seed=0, max_time=8.0)
    assert not np.allclose(perfect.pose[-1], drifting.pose[-1], atol=0.05)


def test_perturbed_names_the_key():
    assert perturbed(NONE, "robot.actuation.latency", 0.2).latency == 0.2
    with pytest.raises(InputError, match="unknown key"):
        perturbed(NONE, "robot.actuation.delay", 0.2)


def test_bench_perturb_is_recorded_and_checked_on_resume(tmp_path, capsys):
    out = tmp_path / "out"
    argv = ["bench", "circles:1:5", "--controllers", "goal-seeking", "--workers", "1", "--quiet", "--gallery", "0",
            "--out", str(out), "--perturb", "robot.actuation.latency=0.2", "--perturb", "robot.odometry.drift=0.01"]
    assert main(argv) == 0
    assert json.loads((out / "perturb.json").read_text()) == {"robot.actuation.latency": 0.2,
                                                              "robot.odometry.drift": 0.01}
    assert json.loads((out / "summary.json").read_text())["arguments"]["perturb"]["robot.actuation.latency"] == 0.2
    assert main([*argv[:-4], "--resume"]) == 2
    assert "--perturb" in capsys.readouterr().err
    for bad in ("robot.actuation.latency", "robot.actuation.latency=x", "robot.odometry.bias=1",
                "robot.actuation.slip=0.9"):
        assert main(["bench", "circles:1", "--controllers", "dwa", "--out", str(tmp_path / "o"),
                     "--perturb", bad]) == 2
        assert "--perturb" in capsys.readouterr().err


def test_a_rings_noise_std_is_the_one_range_noise_model():
    ring = named_ring("lidar")
    noisy_ring = dataclasses.replace(ring, noise_std=0.03)
    by_ring = BatchSimulator(load_scenario("fig-IV-22a"), ConstantController(), sensors=noisy_ring, seed=3)
    by_key = BatchSimulator(dataclasses.replace(load_scenario("fig-IV-22a"), imperfections=Imperfections(
        range_sigma=0.03)), ConstantController(), sensors=ring, seed=3)
    np.testing.assert_array_equal(by_ring._ranges, by_key._ranges)
    assert np.all(by_ring._ranges[0][by_ring._ranges[0] > 3.99] == ring.max_range)  # no echo: no noise

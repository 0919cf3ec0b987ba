"""The robot's size and limits in the scenario file, and reverse driving in the kinematics."""

import math

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.robot.tricycle import DEFAULT_PARAMS, TricycleParams, step
from fuzzynav.sim.simulator import BatchSimulator
from fuzzynav.world.scenario import scenario_from_dict


def _doc(**robot):
    return {"robot": {"x": 2.0, "y": 2.0, **robot}, "goal": {"x": 10.0, "y": 10.0}}


def test_robot_keys_default_to_the_default_robot_and_round_trip():
    assert scenario_from_dict(_doc()).robot is DEFAULT_PARAMS
    scenario = scenario_from_dict(_doc(radius=0.15, wheelbase=0.4, max_steering=0.5, max_speed=2.0,
                                       max_reverse_speed=0.0))
    robot = scenario.robot
    assert (robot.radius, robot.wheelbase, robot.max_steering, robot.max_speed, robot.max_reverse_speed) == \
        (0.15, 0.4, 0.5, 2.0, 0.0)
    assert scenario_from_dict(scenario.to_dict()).robot == robot
    assert "radius" not in scenario_from_dict(_doc()).to_dict()["robot"]  # defaults are not written out
    pursuit = {"robot": {"x": 2.0, "y": 2.0, "radius": 0.2},
               "target": {"x": 9.0, "y": 9.0, "motion": {"type": "line", "velocity": [0.1, 0.0]}}}
    assert scenario_from_dict(pursuit).robot.radius == 0.2  # every task keeps the robot


@pytest.mark.parametrize("key, value, problem", [
    ("radius", 0.0, "must be > 0"), ("wheelbase", -1.0, "must be > 0"), ("max_speed", "fast", "must be a number"),
    ("max_steering", 2.0, "below π/2"), ("max_reverse_speed", -0.5, "≥ 0"), ("radius", float("nan"), "finite"),
])
def test_bad_robot_values_name_the_field(key, value, problem):
    with pytest.raises(InputError) as error:
        scenario_from_dict(_doc(**{key: value}), source="w.yaml")
    assert f"robot.{key}" in str(error.value) and problem in str(error.value) and "w.yaml" in str(error.value)


def test_a_large_robot_must_fit_at_its_start():
    doc = _doc(radius=1.5)
    doc["obstacles"] = [{"circle": {"center": [4.0, 2.0], "radius": 1.0}}]
    with pytest.raises(InputError, match="robot footprint"):
        scenario_from_dict(doc)


def test_reverse_driving_moves_the_robot_backwards_within_the_limit():
    params = TricycleParams(max_reverse_speed=0.5)
    steering, speed = params.clip(np.array([0.0]), np.array([-2.0]))
    assert speed[0] == -0.5
    moved = step(np.array([[0.0, 0.0, 0.0]]), steering, speed, params)
    np.testing.assert_allclose(moved, [[-0.05, 0.0, 0.0]], atol=1e-12)
    # backing with α > 0 swings the nose right (eq IV.1 with V < 0)
    assert step(np.array([[0.0, 0.0, 0.0]]), np.array([0.5]), speed, params)[0, 2] < 0
    assert TricycleParams(max_reverse_speed=0.0).clip(np.array([0.0]), np.array([-2.0]))[1][0] == 0.0
    assert TricycleParams(max_reverse_speed=0.0, min_speed=0.2).lowest_speed == 0.2


class _Reverse:
    name = "reverse"

    def reset(self, rng=None):
        """Nothing to forget between episodes."""

    def act(self, obs):
        from fuzzynav.control.base import Command

        self.seen = obs.extras["robot"]
        return Command(0.0, -9.0)


def test_the_simulator_uses_the_scenario_robot():
    scenario = scenario_from_dict({**_doc(radius=0.5, max_reverse_speed=0.25, max_speed=1.0), "max_time": 1.0})
    controller = _Reverse()
    sim = BatchSimulator(scenario, controller).run()
    assert controller.seen is scenario.robot and sim.trace(0).robot_radius == 0.5
    assert sim.trace(0).speed.min() == -0.25 and math.isclose(sim.pose[0, 0], 2.0 - 0.25, abs_tol=1e-9)

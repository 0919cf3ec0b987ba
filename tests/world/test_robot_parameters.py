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
    ("max_steering", 2.0, "below π/2"), ("max_reverse_speed", -0.5, ">= 0"), ("radius", float("nan"), "finite"),
    ("max_speed", 1e-4, "at least 0.001 m/s"), ("max_steering", 1e-4, "at least 0.001 rad"),
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


WALL = {"wall": {"start": [6.0, 1.0], "end": [6.0, 3.0], "thickness": 0.01}}


@pytest.mark.parametrize("robot", [{"radius": 0.01}, {"max_speed": 40.0}, {"radius": 0.1, "max_speed": 8.0}])
def test_a_robot_that_steps_past_its_diameter_still_hits_a_thin_wall(robot):
    """Collisions are tested at each step's end, and along a step that spans the robot's diameter:
    a 1 cm robot at 4 m/s (0.4 m a step) drove through a 1 cm wall and "reached" its goal."""
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.sim import run_episode

    scenario = scenario_from_dict({**_doc(**robot), "goal": {"x": 10.0, "y": 2.0}, "obstacles": [WALL]})
    scenario = scenario_from_dict({**scenario.to_dict(), "robot": {**scenario.to_dict()["robot"], "theta": 0.0}})
    trace = run_episode(scenario, make_controller("goal-seeking"))
    assert trace.outcome == "collision"
    assert 5.0 < trace.pose[-1, 0] < 6.0  # stopped against the wall's near side, not past it
    assert scenario.world.clearance(trace.pose[-1:, :2])[0] < scenario.robot.radius


def test_a_physics_plants_long_steps_are_tested_along_the_way_too():
    """The MuJoCo plant moves the robot outside the compiled step (mujoco is in the test extra)."""
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.sim import run_episode

    scenario = scenario_from_dict({**_doc(radius=0.01, theta=0.0), "goal": {"x": 10.0, "y": 2.0}, "obstacles": [WALL]})
    trace = run_episode(scenario, make_controller("goal-seeking"), plant="mujoco")
    assert trace.outcome == "collision" and 5.0 < trace.pose[-1, 0] < 6.0  # it drove through the wall before


def test_a_moving_obstacle_that_could_pass_through_the_robot_is_refused():
    mover = {"circle": {"center": [10.0, 1.05], "radius": 0.5}, "motion": {"type": "line", "velocity": [0.0, 100.0]}}
    with pytest.raises(InputError, match=r"w\.yaml: obstacles\[0\]\.motion: at up to 100 m/s, .* below 2 m/s"):
        scenario_from_dict({**_doc(), "obstacles": [mover]}, source="w.yaml")
    wave = {"circle": {"center": [10.0, 5.0], "radius": 0.5},
            "motion": {"type": "sinusoid", "velocity": [1.0, 0.0], "amplitude": 2.0, "period": 4.0}}
    with pytest.raises(InputError, match=r"obstacles\[0\]\.motion: at up to 3\.2969"):  # √(1 + (2π·2/4)²) m/s
        scenario_from_dict({**_doc(), "obstacles": [wave]})
    mover["motion"]["velocity"] = [0.0, 1.9]
    assert scenario_from_dict({**_doc(), "obstacles": [mover]}).world.moving == (0,)


def test_robot_params_given_to_the_simulator_are_checked_the_same_way():
    from dataclasses import replace

    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.sim.simulator import Simulator

    mover = {"circle": {"center": [10.0, 1.05], "radius": 0.5}, "motion": {"type": "line", "velocity": [0.0, 1.0]}}
    scenario = scenario_from_dict({**_doc(), "obstacles": [mover]})
    with pytest.raises(InputError, match=r"obstacles\[0\]\.motion: at up to 1 m/s, with the robot's 50 m/s"):
        Simulator(scenario, make_controller("goal-seeking"), robot_params=replace(scenario.robot, max_speed=50.0))
    with pytest.raises(InputError, match=r"closes 5 m in a step of 1 s"):
        Simulator(scenario, make_controller("goal-seeking"), robot_params=replace(scenario.robot, dt=1.0))

"""Controllers built from trained models (control/learned.py): inputs, blending, model files."""

import json
import math

import numpy as np
import pytest

from fuzzynav.catalog.tasks import load_controller
from fuzzynav.control import learned
from fuzzynav.control.base import Observation
from fuzzynav.control.learned import (
    FuzzyGoalSeeker,
    LearnedAvoidanceNavigator,
    goal_inputs,
    side_distances,
)
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.io.document import from_document
from fuzzynav.learn.tasks import common, fql_avoid, fql_goal
from fuzzynav.robot.sensors import THESIS_SENSOR_ANGLES
from fuzzynav.storage import save_json_atomic


def test_goal_inputs_use_the_thesis_sign():
    pose = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    x = goal_inputs(pose, np.array([[0.0, 2.0], [0.0, -2.0]]))  # goal on the left, on the right
    assert np.allclose(x[:, 0], 2.0)
    assert np.allclose(x[:, 1], [-math.pi / 2, math.pi / 2])  # θ_r − θ_d: negative = goal on the left


def test_side_distances_group_the_seven_sensors():
    ranges = np.array([[4.0, 3.0, 2.5, 1.0, 3.5, 2.0, 0.5]])  # C1 … C7
    assert side_distances(ranges).tolist() == [[2.5, 1.0, 0.5]]
    with pytest.raises(InputError):
        side_distances(np.ones((1, 5)))


def steering_table(conclusion):
    """A 15-rule goal seeker with the same conclusion for every rule."""
    alpha = common.output_variable("alpha", common.STEERING3, (-math.pi / 5, math.pi / 5))
    return common.grid_system(fql_goal.goal_partition_15(), [alpha], [[conclusion] * 15], "t", "")


def test_fuzzy_goal_seeker_turns_by_its_table_at_constant_speed():
    seeker = FuzzyGoalSeeker(steering_table("PG"), constant_speed=1.5)
    obs = Observation(t=0, dt=0.1, pose=np.zeros(3), speed=0, steering=0, target=np.array([5.0, 0.0]))
    command = seeker.act(obs)
    assert command.steering == pytest.approx(math.pi / 5) and command.speed == 1.5


def test_avoidance_navigator_is_goal_seeking_when_everything_is_far():
    system = fql_avoid.avoid_system(np.full(7, 2), np.full(7, 0), open_side=False)  # every avoid rule: steer PG, speed low
    navigator = LearnedAvoidanceNavigator(system)
    far, near = np.full((1, 3), 4.0), np.array([[0.3, 0.3, 0.3]])
    gs = np.array([[0.1, 3.0]])
    steering, speed, free = navigator.blend(far, gs)
    assert free[0] == 1.0 and steering[0] == pytest.approx(0.1) and speed[0] == pytest.approx(3.0)
    steering, speed, free = navigator.blend(near, gs)
    assert free[0] == 0.0 and steering[0] == pytest.approx(math.pi / 5)



def test_supervisor_hands_a_clear_goal_direction_to_goal_seeking_and_slows_it():
    navigator = LearnedAvoidanceNavigator(fql_avoid.avoid_system(np.full(7, 2), np.full(7, 0), open_side=False))
    assert (navigator.params.front, navigator.params.detection) == (fql_avoid.AVOID_D_MIN, fql_avoid.AVOID_D_SAFE)
    ranges = np.full((2, 7), 4.0)
    ranges[:, 6] = 2.0  # a wall on the left, 2 m away, beside a clear path ahead
    ranges[1, :3] = 1.0  # and for the second robot an obstacle dead ahead, 1 m
    goal = np.array([[10.0, 0.2], [10.0, 0.2]])  # 10 m away, a little to the right
    seeker_steering, seeker_speed, _ = navigator.goal(goal[:, 0], -goal[:, 1])
    assert seeker_speed[0] > 0.5
    steering, speed, goal_seeking = navigator.drive(0.6, 0.5, 0.0, ranges, goal)  # the avoider's (α, V_r)
    assert goal_seeking.tolist() == [True, False]
    assert steering.tolist() == [seeker_steering[0], 0.6]
    assert speed.tolist() == [0.5, 0.5]  # sensed: goal seeking no faster than the avoider

def test_model_files_load_as_controllers_and_errors_name_the_field(tmp_path):
    system = steering_table("Z")
    from fuzzynav.fuzzy.io.document import to_document

    path = tmp_path / "m.json"
    save_json_atomic(path, {"kind": "fql-goal", **to_document(system), "constant_speed": 1.5})
    controller = load_controller(path)
    assert isinstance(controller, FuzzyGoalSeeker)
    assert controller.system == system and controller.constant_speed == 1.5  # the file's, not defaults
    assert from_document(json.loads(path.read_text())) == system  # the model is an ordinary fuzzy system
    save_json_atomic(path, {"kind": "fql-goal", **to_document(system), "constant_speed": 9.0})
    with pytest.raises(InputError, match="constant_speed"):
        load_controller(path)
    save_json_atomic(path, {"kind": "q-goal", "zone_edges": [1.0], "n_sectors": 4, "merge_inner": True,
                            "steering": [0.0, -0.6, 0.6], "speed": 1.0, "q": [[0, 0, 0]]})
    with pytest.raises(InputError, match="Q table"):
        load_controller(path)


def test_sensor_layout_matches_the_groups():
    assert np.allclose(np.rad2deg(THESIS_SENSOR_ANGLES[[1, 3, 5]]), [-30, -60, -90])  # right side
    assert np.allclose(np.rad2deg(THESIS_SENSOR_ANGLES[[2, 4, 6]]), [30, 60, 90])  # left side


def test_wall_follower_sensing_single_rays_or_modules(tmp_path):
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.fuzzy.systems_navigation import wall_follower

    # a corner tip at −30° (C2) only: the single rays at 0°, ±90° do not see it, the modules do
    ranges = np.full((1, 7), 4.0)
    ranges[0, 1] = 0.5
    assert learned.single_rays(ranges).tolist() == [[4.0, 4.0, 4.0]]
    assert side_distances(ranges).tolist() == [[0.5, 0.5, 4.0]]
    obs = Observation(t=0.0, dt=0.1, pose=np.zeros(3), speed=0.0, steering=0.0, target=np.array([9.0, 9.0]),
                      ranges=ranges[0],
                      sensor_angles=THESIS_SENSOR_ANGLES)
    rays = learned.LearnedWallFollower(wall_follower(), "rays").act(obs)
    handmade = make_controller("wall-follow").act(obs)  # the hand-made follower's own sensing
    assert (rays.steering, rays.speed) == pytest.approx((handmade.steering, handmade.speed))
    assert learned.LearnedWallFollower(wall_follower(), "modules").act(obs).steering != pytest.approx(rays.steering)
    with pytest.raises(InputError, match="sensing"):
        learned.LearnedWallFollower(wall_follower(), "sonar")
    from fuzzynav.fuzzy.io.document import to_document

    path = tmp_path / "wall.json"
    save_json_atomic(path, {"kind": "fql-wall", "sensing": "rays", **to_document(wall_follower())})
    assert load_controller(path).sensing == "rays"

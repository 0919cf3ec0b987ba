"""The Gymnasium environments move obstacles: each robot senses and collides with them where they
are at its own episode time, as the simulator does (docs/dynamic.md)."""

import numpy as np

from fuzzynav.gym.core import RobotBatch
from fuzzynav.gym.env import FuzzynavEnv
from fuzzynav.gym.tasks import TASKS
from fuzzynav.robot.sensors import SensorRing
from fuzzynav.world.moving import offsets
from fuzzynav.world.scenario import scenario_from_dict

CROSSING = {"robot": {"x": 10, "y": 4, "theta": 1.5708}, "goal": {"x": 10, "y": 18}, "obstacles": [
    {"circle": {"center": [4, 4], "radius": 0.5}, "motion": {"type": "line", "velocity": [1.0, 0.0]}},
    {"polygon": {"points": [[12, 9], [13, 9], [13, 10], [12, 10]]},
     "motion": {"type": "waypoints", "points": [[12, 9], [7, 9]], "speed": 0.8, "loop": True}},
    {"circle": {"center": [16, 16], "radius": 1.0}}]}


def _standing(scenario, step_offsets):
    """``scenario`` with its moving obstacles standing where ``step_offsets`` put them."""
    document = scenario.to_dict()
    for m, index in enumerate(scenario.world.moving):
        entry = document["obstacles"][index]
        entry.pop("motion")
        ((kind, shape),) = entry.items()
        if kind == "circle":
            shape["center"] = (np.array(shape["center"]) + step_offsets[m]).tolist()
        else:
            shape["points"] = (np.array(shape["points"]) + step_offsets[m]).tolist()
    return scenario_from_dict(document, source="standing")


def test_each_robot_senses_the_obstacles_where_they_are_at_its_own_time():
    scenario = scenario_from_dict(CROSSING, source="crossing.yaml")
    batch = RobotBatch(2, TASKS["avoid"])
    batch.start(range(2), [scenario, scenario])
    live = np.array([True, True])
    for k in range(30):
        batch.step(np.zeros(2), np.zeros(2), live)
        if k == 9:
            batch.start([1], [scenario])  # row 1 starts a new episode: its clock goes back to 0
    fleet = batch.fleet
    assert list(fleet.steps) == [30 * batch.decision_steps, 20 * batch.decision_steps]
    ring = SensorRing()
    for row in range(2):
        moved = offsets(scenario.world, [fleet.steps[row] * batch.params.dt])[0]
        assert np.abs(moved).max() > 1.0
        expected = ring.read(_standing(scenario, moved).world, batch.pose[row][None])[0]
        np.testing.assert_allclose(batch.state.ranges[row], expected, atol=1e-9)
        np.testing.assert_allclose(fleet.clearance[row],
                                   _standing(scenario, moved).world.clearance(batch.pose[row][None, :2])[0], atol=1e-9)
    assert not np.allclose(batch.state.ranges[0], batch.state.ranges[1])


def test_a_standing_robot_is_hit_at_the_step_the_simulator_says():
    """The disc walks into the robot standing in its way: the episode ends in a collision when
    the disc reaches it; with the obstacles standing it would go on."""
    scenario = scenario_from_dict(CROSSING, source="crossing.yaml")
    env = FuzzynavEnv("goal", scenario=scenario)
    env.reset(seed=0)
    stop = np.array([0.0, -1.0], dtype=np.float32)  # α = 0, V = 0
    terminated = truncated = False
    step = 0
    while not (terminated or truncated) and step < 200:
        *_, terminated, truncated, info = env.step(stop)
        step += 1
    assert terminated and info["collision"] and not info["success"]
    # the disc's centre is 6 m away; it touches the robot's 0.3 m disc with its 0.5 m one after 5.2 s
    hit_time = (10.0 - 4.0 - 0.5 - 0.3) / 1.0
    assert abs(step * env.episodes.batch.decision_steps * 0.1 - hit_time) <= 0.1 + 1e-9
    still = _standing(scenario, np.zeros((2, 2)))
    env = FuzzynavEnv("goal", scenario=still)
    env.reset(seed=0)
    for _ in range(step + 10):
        *_, terminated, truncated, info = env.step(stop)
        assert not info["collision"]


def test_render_draws_the_obstacles_where_they_are():
    scenario = scenario_from_dict(CROSSING, source="crossing.yaml")
    env = FuzzynavEnv("goal", scenario=scenario, render_mode="rgb_array")
    env.reset(seed=0)
    first = env.render()
    for _ in range(20):
        env.step(np.array([0.0, -1.0], dtype=np.float32))
    later = env.render()
    env.close()
    assert first.shape == later.shape and (first != later).any()


def test_a_batch_robot_too_fast_for_its_worlds_movers_is_refused():
    """The scenario was checked with its own robot; a batch's ``params`` are checked again, as
    ``Simulator(robot_params=...)`` does: a robot at 50 m/s and a 1 m/s mover pass through each
    other between two steps."""
    from dataclasses import replace

    import pytest

    from fuzzynav.errors import InputError
    from fuzzynav.robot.tricycle import DEFAULT_PARAMS

    scenario = scenario_from_dict(CROSSING, source="crossing.yaml")
    batch = RobotBatch(1, TASKS["avoid"], params=replace(DEFAULT_PARAMS, max_speed=50.0))
    with pytest.raises(InputError, match=r"obstacles\[0\]\.motion: at up to 1 m/s, with the robot's 50 m/s"):
        batch.start([0], [scenario])

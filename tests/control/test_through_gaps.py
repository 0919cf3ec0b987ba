"""The gap-aware navigators inside the recovery and loop-escape layers, guided by a route round
what they have seen (fuzzynav.control.through_gaps): they back out of a pocket of posts too
narrow to turn in, and the route leads round a wall of posts to its opening."""

import math

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.control.base import Observation
from fuzzynav.control.recovery import ObstacleMemory
from fuzzynav.control.through_gaps import RouteGuidance
from fuzzynav.sim import run_episode
from fuzzynav.world.scenario import scenario_from_dict

POST = 0.075


def pocket() -> dict:
    """A dead end of 15 cm posts 0.3 m apart, 1.6 m wide (too narrow for a full-lock turn of the
    car, 2 × 0.69 m + its 0.6 m body), the robot inside facing its closed end, the goal beyond it."""
    left, right, end = 9.2, 10.8, 9.6
    posts = [(x, y) for y in np.arange(7.0, end, 0.3) for x in (left, right)]
    posts += [(float(x), end) for x in np.linspace(left, right, 7)]
    return {"name": "pocket", "world": {"width": 20.0, "height": 20.0},
            "robot": {"x": 10.0, "y": 7.6, "theta": float(np.pi / 2)}, "goal": {"x": 10.0, "y": 15.0},
            "obstacles": [{"circle": {"center": [float(x), float(y)], "radius": POST}} for x, y in posts],
            "max_time": 60.0}


def test_the_combined_navigator_backs_out_of_a_pocket_and_reaches_the_goal():
    world = scenario_from_dict(pocket())
    stuck = run_episode(world, make_controller("fuzzy-5b-gap"), seed=0)
    assert stuck.outcome == "timeout"  # forwards only, the gap navigator cannot leave
    trace = run_episode(world, make_controller("fuzzy-5b-gap-robust"), seed=0)
    assert trace.reached and not trace.collision
    reversing = trace.speed < 0
    assert reversing.any()
    assert set(trace.behaviour[reversing].tolist()) == {"REC-BACK"}
    assert world.world.clearance(trace.pose[:, :2]).min() > world.robot.radius


class _Recorder:
    """A stand-in navigator that records the target it is given."""

    name, sensors, systems, roles = "recorder", None, {}, ()

    def reset(self, rng=None):
        self.targets = []

    def act(self, obs):
        from fuzzynav.control.base import Command

        self.targets.append(np.asarray(obs.target, dtype=float))
        return Command(0.0, 0.5, "GSB")


@pytest.mark.parametrize("side", [1.0, -1.0])
def test_route_guidance_leads_round_a_wall_of_posts_on_the_side_of_its_opening(side):
    memory = _remembered([(side * x, 2.0) for x in np.arange(-4.0, 1.01, 0.1)])  # open beyond x = ±1
    inner = _Recorder()
    guide = RouteGuidance(inner, memory)
    guide.reset()
    guide.act(_at((0.0, 0.0, math.pi / 2)))
    given = inner.targets[-1]
    assert np.hypot(*given) == pytest.approx(10.0)  # the goal's distance kept
    assert side * given[0] > 1.0  # towards the opening, not straight at the goal


def test_route_guidance_gives_the_goal_where_the_straight_line_is_free():
    memory = _remembered([(x, 2.0) for x in np.arange(-4.0, -0.99, 0.1)])  # left of the line only
    inner = _Recorder()
    guide = RouteGuidance(inner, memory)
    guide.reset()
    guide.act(_at((0.0, 0.0, math.pi / 2)))
    np.testing.assert_allclose(inner.targets[-1], [0.0, 10.0])


def _at(pose) -> Observation:
    """The robot at ``pose``, the goal at (0, 10), nothing in range."""
    return Observation(t=0.0, dt=0.1, pose=np.array(pose, dtype=float), speed=0.0, steering=0.0,
                       target=np.array([0.0, 10.0]), ranges=np.full(7, 4.0),
                       sensor_angles=np.deg2rad(np.arange(-90.0, 91.0, 30.0)), max_range=4.0)


def _remembered(points) -> ObstacleMemory:
    """A memory of ``points``: each seen as the nearest obstacle of a robot standing on it."""
    memory = ObstacleMemory()
    for x, y in points:
        memory.add(Observation(t=0.0, dt=0.1, pose=np.array([x, y, 0.0]), speed=0.0, steering=0.0,
                               obstacle_distance=0.0, obstacle_bearing=0.0))
    return memory

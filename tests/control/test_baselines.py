"""Pure pursuit (Coulter 1992) and Stanley (Thrun et al. 2006): formulas and closed loop."""

import math

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.control.base import BatchObservation
from fuzzynav.control.baselines import PurePursuit, Stanley
from fuzzynav.sim import metrics, run_episode
from fuzzynav.world.scenario import load_scenario


def _obs(pose, path, index=1, speed=1.0):
    pose = np.atleast_2d(np.asarray(pose, dtype=float))
    n = len(pose)
    path = None if path is None else np.asarray(path, dtype=float)
    target = np.tile(path[min(index, len(path) - 1)] if path is not None else [5.0, 5.0], (n, 1))
    return BatchObservation(t=0.0, dt=0.1, pose=pose, speed=np.full(n, speed), steering=np.zeros(n), target=target,
                            ranges=np.zeros((n, 0)), sensor_angles=np.zeros(0), max_range=4.0,
                            obstacle_distance=np.full(n, np.inf), obstacle_bearing=np.zeros(n),
                            active=np.ones(n, dtype=bool), path=path, waypoint_index=np.full(n, index))


def test_pure_pursuit_goal_point_and_curvature():
    # robot 0.5 m left of the x axis path, heading along it: goal point at distance L on the path
    controller = PurePursuit(lookahead=1.0)
    pose = [0.0, 0.5, 0.0]
    goal = controller.goal_points(np.array([pose]), np.array([[10.0, 0.0]]), np.array([[-5.0, 0.0], [10.0, 0.0]]),
                                  np.array([1]))
    np.testing.assert_allclose(goal, [[math.sqrt(0.75), 0.0]])
    alpha, _, _ = controller.act_batch(_obs(pose, [[-5, 0], [10, 0]]))
    eta = math.atan2(-0.5, math.sqrt(0.75))
    assert alpha[0] == pytest.approx(math.atan(0.5 * 2 * math.sin(eta) / 1.0))


def test_stanley_law_on_a_straight_path():
    controller = Stanley(gain=2.0, softening=1.0)
    # front axle at (0.5, -0.3): 0.3 m right of the path, heading error 0 -> steer left by atan(k e / (ks + v))
    alpha, _, _ = controller.act_batch(_obs([0.0, -0.3, 0.0], [[-5, 0], [10, 0]]))
    assert alpha[0] == pytest.approx(math.atan(2.0 * 0.3 / 2.0))
    # on the path with a heading error ψ only
    alpha, _, _ = controller.act_batch(_obs([0.0, 0.0, 0.2], [[-5, 0], [10, 0]]))
    assert alpha[0] == pytest.approx(-0.2 - math.atan(2.0 * 0.5 * math.sin(0.2) / 2.0))


def test_without_a_path_both_aim_at_the_target():
    # target at (5, 5): bearing π/4 at distance √50
    pursuit, _, _ = PurePursuit().act_batch(_obs([0.0, 0.0, 0.0], None))
    assert pursuit[0] == pytest.approx(math.atan(0.5 * 2 * math.sin(math.pi / 4) / math.sqrt(50)))
    stanley, _, _ = Stanley().act_batch(_obs([0.0, 0.0, 0.0], None))
    assert stanley[0] == pytest.approx(math.pi / 4)


def test_batch_equals_single():
    controller = Stanley()
    poses = np.array([[0, 0.3, 0.1], [1, -0.2, -0.2], [4, 0.1, 0.0]])
    path = [[-5, 0], [5, 0], [5, 8]]
    batch, _, _ = controller.act_batch(_obs(poses, path))
    single = [controller.act_batch(_obs(p, path))[0][0] for p in poses]
    np.testing.assert_allclose(batch, single)


@pytest.mark.slow
@pytest.mark.parametrize("scenario_name", ["path-v", "path-n", "path-trapezoid"])
@pytest.mark.parametrize("name", ["pure-pursuit", "stanley"])
def test_baselines_complete_the_thesis_paths(name, scenario_name):
    scenario = load_scenario(scenario_name)
    result = metrics(run_episode(scenario, make_controller(name)), scenario)
    assert result["completed"] and result["max_cross_track_m"] < 1.0

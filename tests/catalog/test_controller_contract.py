"""Every registered controller keeps the promises of its spec (after scikit-learn's
``check_estimator``): it is a :class:`Controller` built by its factory, its rule-base roles,
sensor ring and map use are those its spec states, it decides the same under the same seed, it
reads the ranges only if its spec says so, and it does every task its spec lists — reaches the
goal, follows the path or catches the target of a short open scenario — in closed loop."""

import numpy as np
import pytest

from fuzzynav.catalog.controllers import CONTROLLERS, make_controller
from fuzzynav.control.base import BatchController, BatchObservation, Controller
from fuzzynav.control.hooks import BringsSensors, HasRoles, MapAware
from fuzzynav.robot.sensors import named_ring
from fuzzynav.sim import run_episode
from fuzzynav.world.scenario import scenario_from_dict

OPEN = {  # one short scenario per task, without obstacles
    "goal": {"robot": {"x": 3.0, "y": 5.0, "theta": 0.5}, "goal": {"x": 13.0, "y": 12.0}, "max_time": 40},
    "path": {"robot": {"x": 3.0, "y": 5.0, "theta": 0.0}, "path": [[3, 5], [9, 8], [15, 6]], "max_time": 40},
    "target": {"robot": {"x": 3.0, "y": 5.0, "theta": 0.0},
               "target": {"x": 8.0, "y": 12.0, "tolerance": 0.3, "motion": {"type": "line", "velocity": [0.3, 0.0]}},
               "max_time": 40},
}
NAMES = sorted(CONTROLLERS)


def _controller(name):
    controller = make_controller(name)
    assert isinstance(controller, Controller)
    return controller


@pytest.mark.parametrize("name", NAMES)
def test_built_by_its_factory_with_the_roles_ring_and_map_its_spec_states(name):
    spec, controller = CONTROLLERS[name], _controller(name)
    assert controller.name == name
    roles = tuple(controller.roles) if isinstance(controller, HasRoles) else ()
    assert roles == tuple(spec.roles)
    ring = controller.sensors if isinstance(controller, BringsSensors) else None
    lidar = named_ring("lidar")
    assert (ring is not None and np.array_equal(ring.angles, lidar.angles)) == (spec.sensors == "lidar")
    assert isinstance(controller, MapAware) == spec.needs_map


def _observation(ranges, distance: float, angles=None, max_range: float = 4.0) -> BatchObservation:
    """Two robots, goal ahead-left, the range readings ``ranges`` (one for every sensor of ``angles``, the
    thesis ring by default), the nearest obstacle ``distance`` away."""
    angles = named_ring("thesis").angles if angles is None else angles
    return BatchObservation(
        t=0.0, dt=0.1, pose=np.array([[5.0, 5.0, 0.0], [6.0, 4.0, 1.0]]), speed=np.array([0.5, 1.0]),
        steering=np.zeros(2), target=np.array([[12.0, 9.0], [12.0, 9.0]]),
        ranges=np.broadcast_to(np.asarray(ranges, dtype=float), (2, len(angles))).copy(),
        sensor_angles=angles, max_range=max_range, obstacle_distance=np.full(2, distance), obstacle_bearing=np.full(2, 0.3),
        active=np.ones(2, dtype=bool), path=None, waypoint_index=np.zeros(2, dtype=int), target_velocity=None,
        extras={"task": "goal"})


@pytest.mark.parametrize("name", [name for name in NAMES if CONTROLLERS[name].sensors == "none"])
def test_a_controller_that_reads_no_ranges_ignores_them(name):
    spec, controller = CONTROLLERS[name], _controller(name)
    if spec.needs_map:
        controller.prepare(scenario_from_dict(OPEN["goal"]))
    commands = []
    for ranges in (4.0, 0.4):
        controller.reset(np.random.default_rng(0))
        obs = _observation(ranges, distance=3.0)
        if isinstance(controller, BatchController):
            steering, speed, _ = controller.act_batch(obs)
        else:  # decides robot by robot
            steering, speed = np.array([(c.steering, c.speed) for c in map(controller.act, map(obs.single, range(2)))]).T
        commands.append(np.concatenate([steering, speed]))
    np.testing.assert_array_equal(commands[0], commands[1])


@pytest.mark.parametrize("name", [name for name in NAMES if CONTROLLERS[name].sensors != "none"])
def test_a_controller_that_reads_ranges_reacts_to_them(name):
    """The same state (the nearest obstacle 3 m away, as the map says), once with every range at the ring's
    reach, once with the rays within ±0.3 rad of the heading reading 0.5 m: each robot's command changes."""
    controller = _controller(name)
    ring = (controller.sensors if isinstance(controller, BringsSensors) else None) or named_ring("thesis")
    commands = []
    for ahead in (ring.max_range, 0.5):
        controller.reset(np.random.default_rng(0))
        ranges = np.where(np.abs(ring.angles) <= 0.3, ahead, ring.max_range)
        obs = _observation(ranges, distance=3.0, angles=ring.angles, max_range=ring.max_range)
        if isinstance(controller, BatchController):
            steering, speed, _ = controller.act_batch(obs)
        else:
            steering, speed = np.array([(c.steering, c.speed) for c in map(controller.act, map(obs.single, range(2)))]).T
        commands.append(np.column_stack([steering, speed]))
    for robot in range(2):
        assert not np.allclose(commands[0][robot], commands[1][robot], rtol=0.0, atol=1e-6), (
            f"{name}, robot {robot}: {commands[0][robot]} with nothing in range, {commands[1][robot]} with a wall ahead")


@pytest.mark.parametrize("name", NAMES)
def test_the_same_seed_drives_the_same_episode(name):
    task = CONTROLLERS[name].tasks[0]
    scenario = scenario_from_dict({**OPEN[task], "max_time": 4})
    a, b = (run_episode(scenario, _controller(name), seed=3) for _ in range(2))
    np.testing.assert_array_equal(a.pose, b.pose)
    assert list(a.behaviour) == list(b.behaviour)


@pytest.mark.slow
@pytest.mark.parametrize("name, task", [(name, task) for name in NAMES for task in CONTROLLERS[name].tasks])
def test_does_every_task_its_spec_lists(name, task):
    scenario = scenario_from_dict(OPEN[task])
    trace = run_episode(scenario, _controller(name), seed=0)
    expected = "reached" if CONTROLLERS[name].goal_directed else "timeout"  # a behaviour alone runs until the time is up
    assert trace.outcome == expected, f"{name} on the open {task} task: {trace.outcome} after {trace.steps} steps"
    driven = np.hypot(*np.diff(trace.pose[:, :2], axis=0).T).sum()
    assert driven > 3.0, f"{name} on the open {task} task drove {driven:.2f} m"  # a timeout that stood still fails

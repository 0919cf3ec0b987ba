"""A large batch stepped in row blocks on several threads (:func:`fuzzynav.sim.blocks.step_in_blocks`)
drives every robot exactly as one call does: the same states, outcomes and fault, step by step."""

import numpy as np
import pytest

from fuzzynav import threads
from fuzzynav.catalog.controllers import make_controller
from fuzzynav.control.batched import ConstantCommand
from fuzzynav.kernels import step as step_kernel
from fuzzynav.sim import blocks
from fuzzynav.sim.simulator import BatchSimulator
from fuzzynav.world.scenario import scenario_from_dict

ROBOTS = 3 * blocks.ROBOTS_PER_THREAD  # enough for two and three threads


def world(moving: bool, robot=None):
    rng = np.random.default_rng(3)
    obstacles = [{"circle": {"center": [float(v) for v in rng.uniform(3, 17, 2)], "radius": 0.5}} for _ in range(12)]
    if moving:
        for k, obstacle in enumerate(obstacles[:6]):
            obstacle["motion"] = {"type": "line", "velocity": [0.8 * (-1) ** k, 0.4]}
    return scenario_from_dict({"robot": {"x": 1, "y": 1, **(robot or {})}, "goal": {"x": 18, "y": 18}, "obstacles": obstacles,
                               "max_time": 60.0}, source="threads.yaml")


def starts(scenario, n=ROBOTS):
    rng = np.random.default_rng(1)
    free = rng.uniform(0.8, 19.2, (40 * n, 2))
    free = free[scenario.world.clearance(free) > 0.6][:n]
    return np.column_stack([free, rng.uniform(-np.pi, np.pi, n)])


def driven(scenario, make, count, steps, **options):
    """Every step's state and status of a batch on ``count`` threads, and its fault."""
    threads.set_count(count)
    try:
        sim = BatchSimulator(scenario, make(), starts=starts(scenario), record=False, seed=0, **options)
        history = []
        for _ in range(steps):
            sim.step()
            history.append((sim._state.copy(), sim._status.copy()))
        return history, sim.collisions_by()
    finally:
        threads.set_count(None)


@pytest.mark.parametrize("name,moving,steps", [("fuzzy-5b-thesis", False, 80), ("fuzzy-5b", False, 25),
                                               ("fuzzy-5b-thesis", True, 80)])
def test_blocks_on_threads_step_as_one_call(monkeypatch, name, moving, steps):
    calls = []
    kernel = step_kernel.step
    monkeypatch.setattr(step_kernel, "step", lambda *a: calls.append(a[6].state.shape[0]) or kernel(*a))
    scenario = world(moving)
    one, fault_one = driven(scenario, lambda: make_controller(name), 1, steps)
    assert set(calls) == {ROBOTS}  # one thread: one call a step
    calls.clear()
    for count in (2, 3):
        many, fault_many = driven(scenario, lambda: make_controller(name), count, steps)
        assert max(calls) < ROBOTS  # cut into blocks
        calls.clear()
        for (state, status), (state_1, status_1) in zip(many, one):
            np.testing.assert_array_equal(state, state_1)
            np.testing.assert_array_equal(status, status_1)
        assert fault_many == fault_one
    assert kernel.targetoptions["nogil"]  # else the blocks would take turns
    outcomes = one[-1][1][:, step_kernel.OUTCOME]
    assert (outcomes == step_kernel.RUNNING).any()
    if moving:
        assert "obstacle" in fault_one  # movers hit robots: the moved scene is what every block saw


def test_commands_given_and_an_imperfect_robot(monkeypatch):
    calls = []
    kernel = step_kernel.step
    monkeypatch.setattr(step_kernel, "step", lambda *a: calls.append(a[6].state.shape[0]) or kernel(*a))
    scenario = world(False)
    one, _ = driven(scenario, lambda: ConstantCommand(0.3, 0.8), 1, 30)
    many, _ = driven(scenario, lambda: ConstantCommand(0.3, 0.8), 2, 30)
    assert min(calls) < ROBOTS
    np.testing.assert_array_equal(many[-1][0], one[-1][0])
    calls.clear()
    driven(world(False, {"sensor_noise": {"range_sigma": 0.02}}), lambda: make_controller("fuzzy-5b-thesis"), 2, 5)
    assert set(calls) == {ROBOTS}  # the imperfect robot's streams are stepped in one call

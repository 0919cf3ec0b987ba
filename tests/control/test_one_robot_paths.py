"""One robot is a batch of one: a batch of robots drives as the same robots run one by one (the
compiled step loops over the robots; nothing is shared between them)."""

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.sim import BatchSimulator, run_episode
from fuzzynav.world.generate import generate_worlds
from fuzzynav.world.scenario import load_scenario


@pytest.mark.parametrize("controller", ["fuzzy-5b-thesis", "fuzzy-2b-thesis"])
def test_a_batch_of_three_drives_as_three_single_runs(controller):
    scenario = load_scenario("fig-IV-22a")
    starts = np.array([scenario.start, scenario.start + [1.5, -1.0, -0.5], scenario.start + [1.0, -4.0, 0.8]])
    batch = BatchSimulator(scenario, make_controller(controller), starts=starts, max_time=25.0).run()
    labels = set()
    for i, start in enumerate(starts):
        alone = run_episode(scenario, make_controller(controller), start=start, max_time=25.0)
        together = batch.trace(i)
        assert together.outcome == alone.outcome and len(alone.pose) > 50  # every robot drives
        np.testing.assert_array_equal(together.behaviour, alone.behaviour)
        np.testing.assert_allclose(together.pose, alone.pose, rtol=0, atol=1e-9)
        np.testing.assert_allclose(together.speed, alone.speed, rtol=0, atol=1e-9)
        labels |= set(alone.behaviour.tolist())
    assert {"GSB", "FOA+VRB" if controller == "fuzzy-5b-thesis" else "OA"} <= labels  # they avoid obstacles too


def test_a_batch_through_the_safety_stop_stops_as_single_runs():
    world = generate_worlds("mixed", 10, 0)[9]  # mixed-0-009: the stop fires (tests/control/test_switching…)
    starts = np.array([world.start, world.start + [0.0, -1.0, 0.3]])
    batch = BatchSimulator(world, make_controller("fuzzy-5b-layered"), starts=starts, max_time=20.0).run()
    for i, start in enumerate(starts):
        alone = run_episode(world, make_controller("fuzzy-5b-layered"), start=start, max_time=20.0)
        together = batch.trace(i)
        assert together.outcome == alone.outcome
        np.testing.assert_allclose(together.pose, alone.pose, rtol=0, atol=1e-9)
        np.testing.assert_array_equal(together.speed == 0.0, alone.speed == 0.0)
    assert batch.trace(0).speed[-1] == 0.0 and not batch.trace(0).collision  # stopped, as alone

"""The simulator's command guard on the batch path: a NaN command of one robot stops the run
naming the controller, the step, the robot and the value, before any pose turns NaN."""

import numpy as np
import pytest

from fuzzynav.errors import CommandError, InputError
from fuzzynav.sim.simulator import BatchSimulator
from fuzzynav.world.scenario import load_scenario


class NanAtStep3:
    """A batch controller that steers straight, then returns NaN steering for robot 1 at step 3."""

    name = "nan-at-3"

    def __init__(self):
        self.calls = 0

    def reset(self, rng=None):
        self.calls = 0

    def act_batch(self, obs):
        steering = np.zeros(len(obs.pose))
        if self.calls == 3:
            steering[1] = np.nan
        self.calls += 1
        return steering, np.ones(len(obs.pose))


def test_batch_nan_command_is_refused_before_the_pose():
    sim = BatchSimulator(load_scenario("example-goal"), NanAtStep3(), n=3)
    with pytest.raises(CommandError, match=r"controller nan-at-3: step 3: returned a non-finite command for robot 1 "
                                           r"\(steering nan, speed 1.0\)"):
        sim.run()
    assert np.isfinite(sim.pose).all() and sim.k == 3


def test_nan_start_pose_is_refused():
    with pytest.raises(InputError, match="starts: must be finite"):
        BatchSimulator(load_scenario("example-goal"), NanAtStep3(), starts=[[1.0, np.nan, 0.0]])


def test_compiled_navigator_state_is_checked():
    """A compiled navigator decides inside the compiled step: a non-finite command it wrote into
    the state is refused naming the controller, the step it was found by, the robot and the value."""
    from fuzzynav.kernels import step as step_kernel
    from fuzzynav.sim.commands import check_state

    state = np.zeros((2, len(step_kernel.STATE_FIELDS)))
    check_state(state, "fuzzy-5b", 7)  # all finite: nothing to say
    state[1, step_kernel.SPEED] = np.inf
    with pytest.raises(CommandError, match=r"controller fuzzy-5b: by step 7: returned a non-finite command for "
                                           r"robot 1 \(steering 0.0, speed inf\)"):
        check_state(state, "fuzzy-5b", 7)


def test_compiled_run_that_reads_a_nan_stops_naming_the_step():
    """A NaN put into a compiled run's pose after step 3 stops the run at step 5, when the compiled
    navigator reads it, with a CommandError naming the controller and the step."""
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.kernels import step as step_kernel

    sim = BatchSimulator(load_scenario("example-goal"), make_controller("fuzzy-5b-thesis"))
    assert sim._compiled is not None  # the compiled path is the one under test
    for _ in range(3):
        sim.step()
    sim._state[0, step_kernel.X] = np.nan
    with pytest.raises(CommandError, match=r"controller fuzzy-5b-thesis: step 5: stopped: NaN input to a fuzzy system"):
        sim.run()

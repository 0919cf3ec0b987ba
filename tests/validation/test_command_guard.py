"""The simulator's command guard: a NaN or infinite command of one robot stops that robot's
episode before it moves, with the outcome "invalid_command" and the step and values recorded in
its trace and its metrics; the other robots run on. No exception reaches the caller."""

import math

import numpy as np
import pytest

from fuzzynav.control.base import Command
from fuzzynav.errors import CommandError, InputError
from fuzzynav.sim import metrics, run_episode
from fuzzynav.sim.simulator import BatchSimulator
from fuzzynav.world.scenario import load_scenario
from tests.sim.controllers import CountingController


class NanAtStep3:
    """A batch controller that steers straight, then returns NaN steering for robot 1 at step 3."""

    name = "nan-at-3"

    def __init__(self, value=np.nan):
        self.calls, self.value = 0, value

    def reset(self, rng=None):
        self.calls = 0

    def act_batch(self, obs):
        steering = np.zeros(len(obs.pose))
        if self.calls == 3:
            steering[1 % len(steering)] = self.value
        self.calls += 1
        return steering, np.ones(len(obs.pose))


def test_batch_nan_command_stops_that_robot_before_it_moves():
    sim = BatchSimulator(load_scenario("example-goal"), NanAtStep3(), n=3).run()
    assert sim.outcomes()[1] == "invalid_command" and sim.outcomes()[0] == sim.outcomes()[2] != "invalid_command"
    assert sim.invalid_commands() == [None, "step 3: steering nan, speed 1.0", None]
    trace = sim.trace(1)
    assert trace.steps == 3 and np.isfinite(trace.pose).all() and np.isfinite(trace.steering).all()
    assert trace.invalid_command == "step 3: steering nan, speed 1.0"
    assert sim.trace(0).steps > 3 and sim.trace(0).invalid_command is None


class InfiniteSpeed(CountingController):
    """A one-robot controller (``act``) that asks for an infinite speed at its third step."""

    name = "inf-speed"

    def act(self, obs):
        command = super().act(obs)
        return Command(0.0, math.inf) if self.calls == 3 else command


def test_infinite_command_recorded_in_the_run_json():
    scenario = load_scenario("example-goal")
    numbers = metrics(run_episode(scenario, InfiniteSpeed()), scenario)
    assert numbers["outcome"] == "invalid_command" and not numbers["timeout"] and numbers["steps"] == 2
    assert numbers["invalid_command"] == "step 2: steering 0.0, speed inf"
    import json

    assert json.loads(json.dumps(numbers, allow_nan=False))["invalid_command"] == numbers["invalid_command"]


def test_a_command_that_is_not_numbers_is_still_refused_naming_the_controller():
    class Nothing:
        name = "nothing"

        def reset(self, rng=None):
            pass

        def act(self, obs):
            return None

    with pytest.raises(CommandError, match=r"controller nothing: step 0: returned None, not a command"):
        run_episode(load_scenario("example-goal"), Nothing())


def test_nan_start_pose_is_refused():
    with pytest.raises(InputError, match="starts: must be finite"):
        BatchSimulator(load_scenario("example-goal"), NanAtStep3(), starts=[[1.0, np.nan, 0.0]])


def test_compiled_navigator_state_is_checked():
    """A compiled navigator decides inside the compiled step: a non-finite command it wrote into
    the state is found, naming the step it was found by and the value (or the step it was
    taken at, given the recorded states)."""
    from fuzzynav.kernels import step as step_kernel
    from fuzzynav.sim.commands import invalid_states

    state = np.zeros((2, len(step_kernel.STATE_FIELDS)))
    assert invalid_states(state, 7) == {}
    history = [state.copy() for _ in range(5)]
    state[1, step_kernel.SPEED] = np.inf
    assert invalid_states(state, 7) == {1: (7, "by step 7: steering 0.0, speed inf")}
    assert invalid_states(state, 7, [*history, state]) == {1: (4, "step 4: steering 0.0, speed inf")}


def test_compiled_run_that_reads_a_nan_stops_with_the_reason():
    """A NaN put into a compiled run's pose after step 3 stops the run when the compiled
    navigator reads it, with the outcome "invalid_command" and the navigator's reason."""
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.kernels import step as step_kernel

    sim = BatchSimulator(load_scenario("example-goal"), make_controller("fuzzy-5b-thesis"))
    assert sim._compiled is not None  # the compiled path is the one under test
    for _ in range(3):
        sim.step()
    sim._state[0, step_kernel.X] = np.nan
    sim.run()
    assert sim.outcomes() == ["invalid_command"]
    assert sim.invalid_commands()[0].startswith("step 4: NaN input to a fuzzy system")

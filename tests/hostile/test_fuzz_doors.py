"""Hypothesis-generated actions and API arguments: each is used or refused with an InputError,
never another exception, and nothing non-finite ever reaches the robot's pose."""

from __future__ import annotations

import contextlib

import gymnasium
import numpy as np
from hypothesis import HealthCheck, given, settings, strategies as st
from hypothesis.extra import numpy as hnp

import fuzzynav
import fuzzynav.gym  # noqa: F401 - registers the environments
from fuzzynav.errors import InputError

ENV = gymnasium.make("fuzzynav/GoalSeeking-v0")
DISCRETE = gymnasium.make("fuzzynav/GoalSeeking-v0", actions="discrete")
SCENARIO = fuzzynav.load_scenario("example-goal")
CONTROLLER = fuzzynav.make_controller("goal-seeking")

ANY_ARRAY = hnp.arrays(st.sampled_from([np.float32, np.float64, np.int64, np.bool_, np.complex128]),
                       hnp.array_shapes(min_dims=0, max_dims=3, max_side=3),
                       )
VALUES = st.one_of(ANY_ARRAY, st.floats(), st.integers(-10**20, 10**20), st.text(max_size=5), st.none(),
                   st.lists(st.floats(), max_size=4))


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(action=VALUES, discrete=st.booleans())
def test_any_action_is_used_or_refused(action, discrete):
    env = DISCRETE if discrete else ENV
    env.reset(seed=0)
    with contextlib.suppress(InputError):  # refused is fine; what is used must leave the pose finite
        env.step(action)
    assert np.isfinite(env.unwrapped.episodes.batch.pose).all()


@settings(max_examples=60, deadline=None)
@given(controller=st.one_of(st.none(), st.text(max_size=5), st.dictionaries(st.text(max_size=2), st.integers()),
                            st.just(CONTROLLER)),
       seed=st.one_of(st.none(), st.integers(-10, 10**20), st.floats(), st.text(max_size=3)),
       sensors=st.one_of(st.none(), st.sampled_from(["lidar", "thesis", "radar"]), st.integers()),
       max_time=st.one_of(st.none(), st.floats(-1, 2)))
def test_run_episode_arguments_are_used_or_refused(controller, seed, sensors, max_time):
    try:
        trace = fuzzynav.run_episode(SCENARIO, controller, seed=seed, sensors=sensors, max_time=max_time)
    except InputError:
        return
    assert np.isfinite(trace.pose).all()

"""Every registered environment passes Gymnasium's own checker, and refuses a NaN action
(single and vector), leaving the robot's pose finite."""

from __future__ import annotations

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import fuzzynav.gym
from fuzzynav.errors import InputError


@pytest.mark.parametrize("env_id", sorted(fuzzynav.gym.ENV_IDS))
def test_check_env(env_id):
    check_env(gymnasium.make(env_id).unwrapped, skip_render_check=True)


@pytest.mark.parametrize("env_id", sorted(fuzzynav.gym.ENV_IDS))
def test_nan_action_is_refused_and_the_pose_stays_finite(env_id):
    env = gymnasium.make(env_id)
    env.reset(seed=0)
    env.action_space.seed(0)
    with pytest.raises(InputError, match="action: must be finite"):
        env.step(np.full(env.action_space.shape, np.nan, dtype=np.float32))
    assert np.isfinite(env.unwrapped.episodes.batch.pose).all()
    env.step(env.action_space.sample())  # the episode goes on
    vec = gymnasium.make_vec(env_id, num_envs=2, vectorization_mode="vector_entry_point")
    vec.reset(seed=0)
    vec.action_space.seed(0)
    actions = vec.action_space.sample()
    actions[1] = np.nan
    with pytest.raises(InputError, match=r"actions\[1\]: must be finite"):
        vec.step(actions)
    assert np.isfinite(vec.unwrapped.episodes.batch.pose).all()

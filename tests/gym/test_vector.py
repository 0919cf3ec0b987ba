"""The batched vector environment: the single environment's numbers, Gymnasium's autoreset."""

import gymnasium
import numpy as np
import pytest

import fuzzynav.gym  # noqa: F401  (registers the ids)
from fuzzynav.errors import InputError
from fuzzynav.gym import FuzzynavEnv, FuzzynavVectorEnv


@pytest.mark.parametrize("task", ["goal", "avoid", "wall", "path"])
def test_same_observations_as_single_environments_with_the_same_seeds(task):
    """Sub-env i reset with seed + i and driven by the same actions sees exactly what a
    FuzzynavEnv reset with seed + i sees, across episode ends (next-step autoreset)."""
    n = 6
    vec = FuzzynavVectorEnv(n, task)
    singles = [FuzzynavEnv(task) for _ in range(n)]
    obs, _ = vec.reset(seed=11)
    np.testing.assert_array_equal(obs, [env.reset(seed=11 + i)[0] for i, env in enumerate(singles)])
    vec.action_space.seed(0)
    ended, endings = [False] * n, 0
    for _ in range(250):
        actions = vec.action_space.sample()
        obs, rewards, terminated, truncated, info = vec.step(actions)
        for i, env in enumerate(singles):
            if ended[i]:  # the vector env resets this row now, ignoring its action
                expected, _ = env.reset()
                assert rewards[i] == 0.0 and not terminated[i] and not truncated[i]
                ended[i] = False
            else:
                expected, reward, term, trunc, single_info = env.step(actions[i])
                assert (reward, term, trunc) == (rewards[i], terminated[i], truncated[i])
                np.testing.assert_array_equal(single_info["reward_heads"], info["reward_heads"][i])
                ended[i] = term or trunc
                endings += ended[i]
            np.testing.assert_array_equal(obs[i], expected)
    assert endings >= n  # the comparison went through resets


def test_make_vec_gives_the_batched_environment_and_its_spaces():
    vec = gymnasium.make_vec("fuzzynav/ObstacleAvoidance-v0", num_envs=4, vectorization_mode="vector_entry_point",
                             actions="discrete")
    assert isinstance(vec.unwrapped, FuzzynavVectorEnv)
    obs, _ = vec.reset(seed=0)
    assert obs.shape == (4, 9) and obs.dtype == np.float32 and obs in vec.observation_space
    assert vec.single_action_space.n == 9
    obs, rewards, terminated, truncated, info = vec.step(vec.action_space.sample())
    assert rewards.shape == terminated.shape == truncated.shape == (4,)
    assert info["reward_heads"].shape == (4, 3) and info["_reward_heads"].all()
    assert vec.metadata["autoreset_mode"] == gymnasium.vector.AutoresetMode.NEXT_STEP


def test_reset_on_given_scenarios():
    vec = FuzzynavVectorEnv(2, "avoid")
    vec.reset(seed=0, options={"scenarios": ["fig-IV-22a", "fig-IV-22b"]})
    assert [s.name for s in vec.episodes.batch.scenarios] == ["fig-IV-22a", "fig-IV-22b"]
    with pytest.raises(InputError, match="2 scenarios for 3"):
        FuzzynavVectorEnv(3, "avoid").reset(seed=0, options={"scenarios": ["fig-IV-22a", "fig-IV-22b"]})
    with pytest.raises(InputError, match="num_envs"):
        FuzzynavVectorEnv(0, "goal")

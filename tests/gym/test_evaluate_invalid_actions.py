"""``success_rate`` with a policy that answers NaN: that episode ends, counted as an invalid
command, and the evaluation of the others goes on (the environment itself refuses the action)."""

import numpy as np

from fuzzynav.gym.evaluate import success_rate


def test_nan_actions_end_their_episodes_and_are_counted():
    def policy(obs):
        actions = np.zeros((len(obs), 2), dtype=np.float32)
        actions[1] = np.nan  # episode 1 always answers NaN
        actions[3, 1] = np.inf
        return actions

    result = success_rate(policy, "goal", episodes=4, seed=5000)
    assert result["invalid_commands"] == 2
    assert result["success"] * 4 + result["collisions"] + result["timeouts"] + result["invalid_commands"] == 4


def test_a_finite_policy_has_no_invalid_commands():
    result = success_rate(lambda obs: np.zeros((len(obs), 2), dtype=np.float32), "goal", episodes=2, seed=5000)
    assert result["invalid_commands"] == 0 and result["success"] * 2 + result["collisions"] + result["timeouts"] == 2

"""The single environment refuses ``step`` and ``render`` before ``reset`` with a RuntimeError that
says what to do (as the vector environment does), and a refused discrete action is shown as given."""

import numpy as np
import pytest

from fuzzynav.errors import InputError
from fuzzynav.gym import FuzzynavEnv, FuzzynavVectorEnv


def test_a_step_before_any_reset_is_refused_with_what_to_do():
    env = FuzzynavEnv("goal")
    with pytest.raises(RuntimeError, match=r"call reset\(\) before step\(\)"):
        env.step(np.zeros(2, dtype=np.float32))
    env.reset(seed=0)
    env.step(np.zeros(2, dtype=np.float32))


def test_a_render_before_any_reset_is_refused_with_what_to_do():
    env = FuzzynavEnv("goal", render_mode="rgb_array")
    with pytest.raises(RuntimeError, match=r"call reset\(\) before render\(\)"):
        env.render()
    env.reset(seed=0)
    assert env.render().ndim == 3
    env.close()


@pytest.mark.parametrize("action, shown", [(np.uint64(2**64 - 1), "18446744073709551615"),
                                           (np.uint64(2**63), "9223372036854775808"), (9, "9"), (-1, "-1"),
                                           (np.array(np.uint64(2**64 - 1)), "18446744073709551615")])
def test_a_refused_discrete_action_is_shown_as_given(action, shown):
    env = FuzzynavEnv("goal", actions="discrete")
    env.reset(seed=0)
    with pytest.raises(InputError, match=rf"action: must be in \[0, 8\], got {shown}$"):
        env.step(action)
    env.step(np.uint64(2))  # the episode is left as it was


def test_the_vector_environment_shows_the_refused_index_as_given():
    vec = FuzzynavVectorEnv(2, actions="discrete")
    vec.reset(seed=0)
    with pytest.raises(InputError, match=r"actions\[1\]: must be in \[0, 8\], got 18446744073709551615$"):
        vec.step(np.array([0, 2**64 - 1], dtype=np.uint64))

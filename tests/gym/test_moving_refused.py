"""The Gymnasium environments do not move obstacles yet: a dynamic scenario is refused, never run
as if its obstacles stood still."""

import pytest

from fuzzynav.errors import InputError
from fuzzynav.gym.env import FuzzynavEnv
from fuzzynav.world.scenario import scenario_from_dict


def test_a_scenario_with_moving_obstacles_is_refused_naming_it():
    scenario = scenario_from_dict({"robot": {"x": 2, "y": 2}, "goal": {"x": 18, "y": 18}, "obstacles": [
        {"circle": {"center": [10, 10], "radius": 0.5}, "motion": {"type": "line", "velocity": [1, 0]}}]},
        source="crossing.yaml")
    env = FuzzynavEnv("goal", scenario=scenario)
    with pytest.raises(InputError, match="do not move obstacles") as caught:
        env.reset(seed=0)
    assert caught.value.source == "crossing.yaml" and caught.value.field == "obstacles"

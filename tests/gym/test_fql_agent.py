"""Fuzzy Q-learning through the Gymnasium interface: it learns, and its rule base drives."""

import numpy as np
import pytest

from fuzzynav.control.learned import FuzzyGoalSeeker
from fuzzynav.errors import InputError
from fuzzynav.gym import FuzzynavVectorEnv
from fuzzynav.gym.evaluate import success_rate
from fuzzynav.gym.fql_agent import FQLAgent
from fuzzynav.gym.tasks import GOAL_SPEEDS, STEERING3
from fuzzynav.sim.simulator import run_episode
from fuzzynav.world.scenario import Goal, Scenario
from fuzzynav.world.world import World


@pytest.fixture(scope="module")
def trained():
    return FQLAgent("goal").learn(FuzzynavVectorEnv(16, "goal"), 6000, seed=0)


@pytest.mark.slow
def test_fql_trained_briefly_through_the_env_reaches_held_out_goals(trained):
    untrained = FQLAgent("goal").learn(FuzzynavVectorEnv(16, "goal"), 16, seed=0)
    before = success_rate(untrained.predict, "goal", episodes=50, seed=5000)
    after = success_rate(trained.predict, "goal", episodes=50, seed=5000)
    assert before["success"] < 0.2  # the priors (straight ahead) rarely reach a goal
    assert after["success"] >= 0.9, after


@pytest.mark.slow
def test_the_exported_rule_base_drives_the_simulator_to_the_goal(trained):
    system = trained.rule_base()
    assert system.input_names == ["drg", "theta"] and system.output_names == ["alpha", "v"]
    assert len(system.rules) == 35
    values = system.compiled.values
    assert set(np.round(values[:, 0], 9)) <= set(np.round(STEERING3, 9))
    assert set(np.round(values[:, 1], 9)) <= set(np.round(GOAL_SPEEDS, 9))
    controller = FuzzyGoalSeeker(system)
    for start, goal in (((2.0, 2.0, 0.0), (17.0, 15.0)), ((15.0, 4.0, 2.5), (4.0, 16.0))):
        scenario = Scenario(name="open", world=World(), start=np.array(start), goal=Goal(np.array(goal), 0.3),
                            max_time=60.0)
        assert run_episode(scenario, controller).outcome == "reached"


def test_the_agent_refuses_a_discrete_or_foreign_environment():
    with pytest.raises(InputError, match="continuous-action vector environment"):
        FQLAgent("goal").learn(FuzzynavVectorEnv(2, "goal", actions="discrete"), 10)
    with pytest.raises(InputError, match="continuous-action vector environment"):
        FQLAgent("goal").learn(FuzzynavVectorEnv(2, "avoid"), 10)
    with pytest.raises(InputError, match="continuous-action vector environment"):
        FQLAgent("avoid").learn(FuzzynavVectorEnv(2, "avoid", actions="discrete"), 10)
    with pytest.raises(InputError, match="task"):
        FQLAgent("swim")
    with pytest.raises(RuntimeError, match="learn"):
        FQLAgent("goal").predict(np.zeros((1, 2)))


@pytest.mark.slow
def test_fql_avoidance_is_the_thesis_avoider_inside_its_navigator_through_the_env():
    """Steering (VI.20) then speed (VI.21) of the avoider's 14 rules, learned through the
    environment's steps (7,500: past the early dip of the learning curve, README); the exported
    model drives the simulator around obstacles to the goal."""
    options = {"worlds": "circles", "n_worlds": 1000, "world_seed": 0}
    agent = FQLAgent("avoid").learn(FuzzynavVectorEnv(8, "avoid", **options), 7500, seed=0)
    assert agent.learning_.speed is not None and agent.episodes_ > 0  # both phases ran
    system = agent.rule_base()
    assert system.input_names == ["front", "right", "left", "open"] and system.output_names == ["alpha", "v"]
    assert len(system.rules) == 14
    assert set(np.round(system.compiled.values[:, 0], 9)) <= set(np.round(STEERING3, 9))
    held_out = success_rate(agent.predict, "avoid", episodes=30, seed=10_000, worlds="circles", n_worlds=30,
                            world_seed=1)
    assert held_out["success"] >= 0.9, held_out
    from fuzzynav.world.scenario import load_scenario

    assert run_episode(load_scenario("fig-IV-22a"), agent.controller()).outcome == "reached"

"""The registered environments: Gymnasium's checker, spaces, seeding, rewards, worlds, rendering."""

import warnings

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import fuzzynav.gym
from fuzzynav.errors import InputError
from fuzzynav.gym import FuzzynavEnv
from fuzzynav.gym.episodes import scale_actions, unscale_actions
from fuzzynav.world.scenario import Goal, Scenario, load_scenario
from fuzzynav.world.world import World


def open_field(start, goal=(16.0, 12.0)) -> Scenario:
    """The empty workspace, a start pose and a goal."""
    return Scenario(name="open", world=World(), start=np.array(start, dtype=float), goal=Goal(np.array(goal), 0.3))


@pytest.mark.parametrize("actions", ["continuous", "discrete"])
@pytest.mark.parametrize("env_id", sorted(fuzzynav.gym.ENV_IDS))
def test_check_env_passes_with_warnings_as_errors(env_id, actions):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        env = gymnasium.make(env_id, actions=actions, render_mode="rgb_array")
        check_env(env.unwrapped)
        env.close()


def test_discrete_actions_are_the_thesis_candidates():
    env = gymnasium.make("fuzzynav/GoalSeeking-v0", actions="discrete").unwrapped
    assert env.action_space.n == 9
    candidates = env.episodes.candidates
    np.testing.assert_allclose(sorted(set(candidates[:, 0])), [-np.pi / 5, 0.0, np.pi / 5])  # eq VI.12
    np.testing.assert_allclose(sorted(set(candidates[:, 1])), [1.0, 1.8, 3.0])  # eq VI.13
    assert gymnasium.make("fuzzynav/PathTracking-v0", actions="discrete").action_space.n == 5  # eq VI.15


def test_continuous_actions_scale_to_the_robot_limits_and_back():
    values = scale_actions(np.array([[-1.0, -1.0], [1.0, 1.0], [0.0, 0.0]]))
    np.testing.assert_allclose(values, [[-np.pi / 4, 0.0], [np.pi / 4, 4.0], [0.0, 2.0]])
    np.testing.assert_allclose(unscale_actions(values[:, 0], values[:, 1]), [[-1, -1], [1, 1], [0, 0]], atol=1e-6)


def test_reset_with_a_seed_replays_the_episode():
    env = gymnasium.make("fuzzynav/ObstacleAvoidance-v0")
    first, _ = env.reset(seed=7)
    world = env.unwrapped.scenario.world
    env.action_space.seed(3)
    actions = [env.action_space.sample() for _ in range(20)]

    def rollout():
        observations = []
        for action in actions:
            obs, _, terminated, truncated, _ = env.step(action)
            observations.append(obs)
            if terminated or truncated:
                break
        return observations

    trace = rollout()
    again, _ = env.reset(seed=7)
    assert repr(env.unwrapped.scenario.world) == repr(world)
    np.testing.assert_array_equal(first, again)
    np.testing.assert_array_equal(trace, rollout())
    other, _ = env.reset(seed=8)
    assert not np.array_equal(first, other)


def _drive(env, action, limit=2000):
    for _ in range(limit):
        obs, reward, terminated, truncated, info = env.step(action)
        if terminated or truncated:
            return obs, reward, terminated, truncated, info
    raise AssertionError("the episode did not end")


def test_collision_terminates_with_the_thesis_penalty():
    """Straight at full speed from (2, 2, heading −x): the boundary wall, eq VI.2's −3 (+ VI.14's −1)."""
    env = FuzzynavEnv("goal", scenario="example-goal")
    env.reset(seed=0, options={"scenario": open_field([2.0, 2.0, np.pi])})
    _, reward, terminated, truncated, info = _drive(env, np.array([0.0, 1.0], dtype=np.float32))
    assert terminated and not truncated and info["collision"] and not info["success"]
    np.testing.assert_array_equal(info["reward_heads"], [-3.0, -1.0])
    assert reward == -4.0


def test_reaching_the_goal_terminates_with_success():
    """A goal dead ahead: straight on reaches it, eq VI.2's +4."""
    env = FuzzynavEnv("goal", scenario=open_field([4.0, 12.0, 0.0]), max_steps=1000)
    env.reset(seed=0)
    obs, _, terminated, _, info = _drive(env, np.array([0.0, -0.5], dtype=np.float32))
    assert terminated and info["success"] and not info["collision"]
    assert info["reward_heads"][0] == 4.0
    assert obs[0] <= 0.3


def test_truncated_at_max_steps_when_nothing_ends_the_episode():
    env = FuzzynavEnv("goal", max_steps=5)
    env.reset(seed=1)
    results = [env.step(np.array([0.0, -1.0], dtype=np.float32)) for _ in range(5)]  # standing still
    assert [r[3] for r in results] == [False] * 4 + [True]
    assert not any(r[2] for r in results)
    with pytest.raises(RuntimeError, match="reset"):
        env.step(np.array([0.0, 0.0], dtype=np.float32))


def test_dense_reward_pays_the_progress_towards_the_goal():
    env = FuzzynavEnv("goal", scenario=open_field([4.0, 12.0, 0.0]), reward="dense")
    obs, _ = env.reset(seed=0)
    after, reward, *_ = env.step(np.array([0.0, 0.0], dtype=np.float32))  # 2 m/s for 0.1 s
    assert reward == pytest.approx(obs[0] - after[0] - 0.01, abs=1e-5)
    assert reward == pytest.approx(0.19, abs=1e-3)


def test_worlds_from_a_named_scenario_a_family_and_a_layout():
    env = gymnasium.make("fuzzynav/ObstacleAvoidance-v0", scenario="fig-IV-22a")
    env.reset(seed=0)
    assert env.unwrapped.scenario.name == "fig-IV-22a"
    env = FuzzynavEnv("avoid", worlds="circles", n_worlds=3, world_seed=4)
    names = set()
    for seed in range(12):
        env.reset(seed=seed)
        names.add(env.unwrapped.scenario.name)
    assert names <= {f"circles-4-{i:03d}" for i in range(3)} and len(names) > 1
    env = FuzzynavEnv("wall", worlds="wall-course")
    obs, _ = env.reset(seed=0)
    assert obs.shape == (7,) and obs.min() < 4.0  # a wall is in sight


@pytest.mark.parametrize("options, field", [
    ({"task": "fly"}, "task"), ({"reward": "sparse"}, "reward"), ({"actions": "both"}, "actions"),
    ({"max_steps": 0}, "max_steps"), ({"worlds": "swamp"}, "worlds"), ({"scenario": "no-such-world"}, "SCENARIO"),
])
def test_bad_options_are_input_errors_naming_the_field(options, field):
    options = {"task": "goal", **options}
    with pytest.raises(InputError, match=field):
        FuzzynavEnv(**options).reset(seed=0)


def test_a_path_task_refuses_a_goal_scenario():
    with pytest.raises(InputError, match="needs a scenario with a path"):
        FuzzynavEnv("path", scenario="example-goal").reset(seed=0)


def test_path_tracking_follows_waypoints_to_the_end():
    """Aiming at the current waypoint (θ_rg → 0) completes a path: waypoints switch, success at the
    end. The robot starts on the first waypoint: as in the simulator, it aims at the second from
    the start, and each later one is rewarded when reached."""
    env = FuzzynavEnv("path", scenario="example-path")
    obs, _ = env.reset(seed=0)
    assert obs[0] > 1.0  # not the distance 0 to the waypoint it stands on
    passed = 0
    for _ in range(env.episodes.max_steps):
        steer = np.clip(obs[1] / (np.pi / 4), -1.0, 1.0)  # θ_rg > 0: goal on the right, steer right (α < 0)
        obs, _, terminated, truncated, info = env.step(np.array([-steer], dtype=np.float32))
        passed += info["reward_heads"][0] == 4.0
        if terminated or truncated:
            break
    assert terminated and info["success"]
    assert passed == len(load_scenario("example-path").path.waypoints) - 1


@pytest.mark.parametrize("mode", ["rgb_array", "human"])
def test_render_modes(mode):
    env = gymnasium.make("fuzzynav/ObstacleAvoidance-v0", render_mode=mode)
    env.reset(seed=0)
    frame = env.render()
    if mode == "rgb_array":
        assert frame.ndim == 3 and frame.shape[2] == 3 and frame.dtype == np.uint8
        assert len(np.unique(frame.reshape(-1, 3), axis=0)) > 3  # something drawn
    else:
        assert frame is None
    env.close()

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



def test_a_step_before_any_reset_is_refused_with_what_to_do():
    vec = FuzzynavVectorEnv(2)
    with pytest.raises(RuntimeError, match=r"call reset\(\) before step\(\)"):
        vec.step(np.zeros((2, 2)))
    vec.reset(seed=0)
    vec.step(np.zeros((2, 2), dtype=np.float32))


def test_reset_on_given_scenarios():
    vec = FuzzynavVectorEnv(2, "avoid")
    vec.reset(seed=0, options={"scenarios": ["fig-IV-22a", "fig-IV-22b"]})
    assert [s.name for s in vec.episodes.batch.scenarios] == ["fig-IV-22a", "fig-IV-22b"]
    with pytest.raises(InputError, match="2 scenarios for 3"):
        FuzzynavVectorEnv(3, "avoid").reset(seed=0, options={"scenarios": ["fig-IV-22a", "fig-IV-22b"]})
    with pytest.raises(InputError, match="num_envs"):
        FuzzynavVectorEnv(0, "goal")


def test_each_robot_is_sensed_in_its_own_world_as_the_world_itself_answers():
    """One compiled call for robots in different worlds (circles, polygons, walls, ellipses)
    gives each robot the readings and clearance its own world's queries give."""
    from fuzzynav.gym.core import RobotBatch
    from fuzzynav.gym.sources import FamilySource, LayoutSource
    from fuzzynav.gym.tasks import TASKS
    from fuzzynav.robot.sensors import SensorRing

    rng = np.random.default_rng(3)
    scenarios = ([FamilySource(family, 20, world_seed=2).world(i) for family in ("mixed", "dense") for i in range(3)]
                 + [LayoutSource("wall-course").draw(rng) for _ in range(2)])
    batch = RobotBatch(len(scenarios), TASKS["avoid"])
    batch.start(range(len(scenarios)), scenarios)
    assert len({id(s.world) for s in scenarios}) == len(scenarios)
    assert any(type(o).__name__ == "Ellipse" for s in scenarios for o in s.world.obstacles)
    poses = np.column_stack([rng.uniform(0.5, 19.5, (len(scenarios), 2)), rng.uniform(-np.pi, np.pi, len(scenarios))])
    fleet = batch.fleet
    fleet.start(range(len(scenarios)), [s.world for s in scenarios], poses, [fleet.setup() for _ in scenarios])
    expected_ranges = np.array([SensorRing().read(s.world, p[None])[0] for s, p in zip(scenarios, poses)])
    np.testing.assert_array_equal(fleet.ranges, expected_ranges)
    np.testing.assert_array_equal(fleet.clearance, [s.world.clearance(p[None, :2])[0] for s, p in zip(scenarios, poses)])


def test_waypoints_switch_as_the_path_task_says():
    """The compiled waypoint switching of the batch follows TaskState (zone and passed rules)."""
    from fuzzynav.gym.core import RobotBatch
    from fuzzynav.gym.sources import RandomPaths
    from fuzzynav.gym.tasks import TASKS
    from fuzzynav.kernels import worlds
    from fuzzynav.sim.tasks import TaskState

    rng = np.random.default_rng(5)
    scenarios = [RandomPaths().draw(rng) for _ in range(4)]
    batch = RobotBatch(4, TASKS["path"])
    batch.start(range(4), scenarios)
    fleet = batch.fleet
    states = [TaskState(s, 1) for s in scenarios]
    for s, t in zip(scenarios, states):  # the stop tests at the start, as the batch's
        t.update(s.start[None, :2], 0.0, np.ones(1, dtype=bool))
    switches = 0
    for _ in range(200):  # robots hop along their paths with noise
        points = np.array([s.path.waypoints[min(t.waypoint_index[0], len(s.path.waypoints) - 1)]
                           for s, t in zip(scenarios, states)]) + rng.normal(0.0, 0.4, (4, 2))
        before = fleet.waypoint
        fleet.state[:, :2] = points
        worlds.settle_rows(fleet.scenes, fleet.scene_bounds, fleet.setups, fleet.setup_bounds, np.arange(4),
                           fleet.state, fleet.ranges, fleet.status)
        done, switched = fleet.reached, fleet.waypoint != before
        for i, t in enumerate(states):
            before = t.waypoint_index[0]
            assert done[i] == t.update(points[i:i + 1], 0.0, np.ones(1, dtype=bool))[0]
            assert switched[i] == (t.waypoint_index[0] != before)
            switches += switched[i]
        np.testing.assert_array_equal(fleet.target, [t.target()[0] for t in states])
    assert switches >= 4

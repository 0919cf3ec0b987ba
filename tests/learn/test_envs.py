"""The vectorised training environments of chapter VI: physics, termination, layouts, fast premise."""

import math

import numpy as np
import pytest

from fuzzynav.fuzzy import systems
from fuzzynav.learn.envs import FixedGoal, GridPremise, RandomGoal, RandomObstacles, RobotEnv, WallCourse
from fuzzynav.learn.envs.layouts import wall_course
from fuzzynav.learn.rewards import GoalSteeringReward
from fuzzynav.robot import tricycle
from fuzzynav.robot.sensors import SensorRing
from fuzzynav.world import Wall, World


def goal_env(layout, batch=3, max_steps=200, speed=1.0):
    return RobotEnv(layout, lambda s: s.goal, lambda a, s: (np.asarray(a, float), speed), GoalSteeringReward(),
                    batch=batch, max_steps=max_steps, tolerance=0.3)


def test_grid_premise_equals_the_fuzzy_library():
    system = systems.goal_seeking()
    premise = GridPremise(system)
    rng = np.random.default_rng(0)
    X = np.column_stack([rng.uniform(-1, 35, 500), rng.uniform(-4, 4, 500)])  # outside the universes too
    assert np.allclose(premise.firing_strengths(X), system.firing_strengths(X), atol=1e-12)
    assert np.allclose(premise.firing_strengths(X, normalise=False).sum(axis=1), 1.0)  # strong partitions


def test_straight_run_to_an_aligned_goal_is_rewarded_and_succeeds():
    env = goal_env(FixedGoal(start=(2.0, 10.0, 0.0), goal=(8.0, 10.0)), batch=2)
    rng = np.random.default_rng(0)
    env.reset(rng)
    rewards = []
    while True:
        _, r, terminated, truncated, info = env.step(np.zeros(2), rng)
        rewards.append(r[0])
        if terminated.all() or truncated.all():
            break
    assert info["success"].all() and not info["collision"].any()
    assert set(rewards[:-1]) == {3.0} and rewards[-1] == 4.0
    assert abs(len(rewards) - (6.0 - 0.3) / 0.1) <= 1  # 1 m/s, Δt = 0.1 s: d_rg ≤ 0.3 m after ~57 steps


def test_wall_hit_ends_the_episode_and_finished_rows_stand_still():
    env = goal_env(FixedGoal(start=(1.0, 10.0, math.pi), goal=(15.0, 10.0)), batch=2)
    rng = np.random.default_rng(0)
    env.reset(rng)
    _, r, terminated, _, info = env.step(np.zeros(2), rng)
    for _ in range(8):
        _, r, terminated, _, info = env.step(np.zeros(2), rng)
        if terminated.any():
            break
    assert terminated.all() and info["collision"].all() and (r == -3).all()
    pose = env.state.pose.copy()
    env.step(np.zeros(2), rng)
    assert np.array_equal(env.state.pose, pose)


def test_env_kinematics_are_the_robot_layers():
    env = goal_env(FixedGoal(start=(5.0, 5.0, 0.3), goal=(15.0, 15.0)), batch=1)
    rng = np.random.default_rng(0)
    env.reset(rng)
    env.step(np.array([0.4]), rng)
    assert np.allclose(env.state.pose, tricycle.step(np.array([[5.0, 5.0, 0.3]]), 0.4, 1.0))


def test_layouts_draw_valid_reproducible_starts():
    for layout in (RandomGoal(), RandomObstacles(), WallCourse()):
        a = layout.sample(np.random.default_rng(4), 20)
        b = layout.sample(np.random.default_rng(4), 20)
        world, poses, targets = a
        assert np.array_equal(poses, b[1])
        assert (world.clearance(poses[:, :2]) > 0.3).all()
        if targets is not None:
            assert (world.clearance(targets) > 0.3).all()
    _, poses, goals = RandomGoal(min_distance=3.0).sample(np.random.default_rng(1), 200)
    assert (np.hypot(*(goals - poses[:, :2]).T) >= 3.0).mean() > 0.99


@pytest.mark.parametrize("layout", [RandomObstacles(), WallCourse()])
def test_sensing_layouts_give_side_distances(layout):
    env = RobotEnv(layout, lambda s: s.sides, lambda a, s: (0.0, 1.0), lambda b, a, c, r: np.zeros(len(c)),
                   batch=4, max_steps=5, sensors=SensorRing())
    obs = env.reset(np.random.default_rng(2))
    assert obs.shape == (4, 3) and (obs <= 4.0).all() and (obs > 0).all()


def course_corners_drawn_with_numpy(rng):
    """The corners of a wall course drawn in the documented order with numpy arrays and
    ``choice`` (how the training courses were first written): wall_course must keep this stream."""
    for _ in range(100):
        n = int(rng.integers(3, 6))
        heading = rng.uniform(-np.pi, np.pi)
        points = [rng.uniform(5.0, 15.0, 2)]
        for k in range(n):
            if k:
                heading += rng.choice([-1.0, 1.0]) * rng.uniform(np.pi / 6, 5 * np.pi / 6)
            points.append(points[-1] + rng.uniform(3.0, 7.0) * np.array([np.cos(heading), np.sin(heading)]))
        points = np.array(points)
        if (points >= 2.0).all() and (points <= 18.0).all():
            return points


@pytest.mark.parametrize("seed", range(40))
def test_wall_courses_replay_the_training_stream_bit_for_bit(seed):
    rng, reference_rng = np.random.default_rng(seed), np.random.default_rng(seed)
    world = wall_course(rng)
    corners = course_corners_drawn_with_numpy(reference_rng)
    drawn = np.array([wall.start for wall in world.obstacles] + [world.obstacles[-1].end])
    assert drawn.tobytes() == corners.tobytes()
    built = World(20.0, 20.0, [Wall(w.start, w.end, 0.3) for w in world.obstacles])  # the checked, packed world
    assert built.scene.tobytes() == world.scene.tobytes() and built.order.tobytes() == world.order.tobytes()
    assert rng.random() == reference_rng.random()  # the same draws consumed


def starts_placed_with_numpy(rng, world, batch, offset=1.0, side=1.0):
    """Start poses beside a course's walls drawn and placed with numpy arrays (how the training
    starts were first written): WallCourse.sample must keep this stream and these poses. Also
    returns how many starts were blocked in their first direction, and in both."""
    walls = world.obstacles
    which = rng.integers(len(walls), size=batch)
    a = np.array([walls[i].start for i in which])
    b = np.array([walls[i].end for i in which])
    point = a + rng.uniform(0.3, 0.7, batch)[:, None] * (b - a)
    direction = (b - a) / np.hypot(*(b - a).T)[:, None]
    heading = np.where((rng.random(batch) < 0.5)[:, None], -direction, direction)
    counts = []
    for _ in range(2):
        left = np.column_stack([-heading[:, 1], heading[:, 0]])
        position = point - side * offset * left
        blocked = (world.clearance(position) < 0.6) | (world.boundary_distance(position) < 0.6)
        counts.append(int(blocked.sum()))
        if not blocked.any():
            break
        heading = np.where(blocked[:, None], -heading, heading)
    return np.column_stack([position, np.arctan2(heading[:, 1], heading[:, 0])]), counts


@pytest.mark.parametrize("batch, offset, side", [(1, 1.0, 1.0), (7, 1.0, 1.0), (64, 1.0, 1.0), (16, 2.5, -1.0)])
def test_wall_course_starts_replay_the_training_stream_bit_for_bit(batch, offset, side):
    blocked = np.zeros(2, dtype=int)  # starts blocked in their first direction, in both
    for seed in range(60):
        rng, reference_rng = np.random.default_rng(seed), np.random.default_rng(seed)
        world, poses, targets = WallCourse(offset, side).sample(rng, batch)
        reference_world = wall_course(reference_rng)
        assert targets is None and reference_world.scene.tobytes() == world.scene.tobytes()
        reference, counts = starts_placed_with_numpy(reference_rng, reference_world, batch, offset, side)
        assert poses.tobytes() == reference.tobytes()
        assert rng.random() == reference_rng.random()  # the same draws consumed
        blocked[:len(counts)] += counts
    assert (blocked > 0).all()  # both turns of the rule were exercised

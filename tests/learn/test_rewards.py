"""The reinforcement signals of chapter VI (eqs VI.2, VI.14 rebuilt, VI.20, VI.21, VI.22), case by case."""

import math

import numpy as np

from fuzzynav.learn.envs import RobotState
from fuzzynav.learn.rewards import (
    AvoidSpeedReward,
    AvoidSteeringReward,
    GoalSpeedReward,
    GoalSteeringReward,
    WallSpeedReward,
    WallSteeringReward,
)
from fuzzynav.world.world import World

NO = np.zeros(1, dtype=bool)
YES = np.ones(1, dtype=bool)


def goal_state(d, angle, speed=1.0):
    return RobotState(World(), np.zeros((1, 3)), np.array([speed]), np.zeros(1), goal=np.array([[d, angle]]))


def side_state(front, right, left, speed=1.0):
    return RobotState(World(), np.zeros((1, 3)), np.array([speed]), np.zeros(1), sides=np.array([[front, right, left]]))


def test_goal_steering_reward_every_case_of_eq_VI_2():
    r = GoalSteeringReward()
    assert r(goal_state(5, 0.3), goal_state(4.9, 0.2), YES, NO)[0] == -3  # hits the walls
    assert r(goal_state(0.5, 0.3), goal_state(0.25, 0.2), NO, YES)[0] == 4  # goal reached
    assert r(goal_state(5, 0.0), goal_state(4.9, math.radians(2)), NO, NO)[0] == 3  # closer, θ_rg ≈ 0
    assert r(goal_state(5, 0.8), goal_state(4.9, -0.6), NO, NO)[0] == 2  # closer, |θ_rg| decreases
    assert r(goal_state(5, 0.5), goal_state(4.9, 0.6), NO, NO)[0] == -1  # closer, |θ_rg| increases
    assert r(goal_state(5, 0.0), goal_state(5.1, 0.0), NO, NO)[0] == -2  # farther, even aligned


def test_goal_speed_reward_rebuilt_eq_VI_14():
    r = GoalSpeedReward()  # low = 0.2 m/s
    assert r(goal_state(0.5, 0.1, 0.1), goal_state(0.2, 0.1, 0.1), NO, YES)[0] == 1  # arrives slowly
    assert r(goal_state(0.5, 0.1, 1.0), goal_state(0.2, 0.1, 1.0), NO, YES)[0] == 0  # arrives at 1 m/s: too fast
    assert r(goal_state(5, 0.5, 1.0), goal_state(4.8, 0.4, 1.8), NO, NO)[0] == -1  # approaches, speeds up
    assert r(goal_state(5, 0.5, 1.0), goal_state(5.1, 0.4, 1.8), NO, NO)[0] == -1  # turns back speeding up
    assert r(goal_state(5, 0.5, 1.8), goal_state(4.8, 0.4, 1.0), NO, NO)[0] == 0  # slows down
    assert r(goal_state(5, 0.5, 1.0), goal_state(5, 0.5, 1.0), YES, NO)[0] == -1  # the walls


def test_avoidance_rewards_eqs_VI_20_and_VI_21():
    steer, speed = AvoidSteeringReward(d_max=4.0), AvoidSpeedReward(d_max=4.0, low=1.0)
    assert steer(side_state(3, 3, 3), side_state(3, 3, 3), YES, NO)[0] == -4
    assert steer(side_state(1.9, 4, 4), side_state(1.8, 4, 4), NO, NO)[0] == -1  # front closing under 2 m
    assert steer(side_state(3.0, 4, 4), side_state(2.9, 4, 4), NO, NO)[0] == 0  # closing, but beyond 2 m
    assert steer(side_state(1.0, 4, 4), side_state(1.2, 4, 4), NO, NO)[0] == 0  # opening
    assert speed(side_state(4, 4, 4, 0.5), side_state(4, 4, 4, 0.5), NO, NO)[0] == -1  # free and slow
    assert speed(side_state(4, 4, 4, 2.0), side_state(4, 4, 4, 2.0), NO, NO)[0] == 0  # free and fast
    assert speed(side_state(3, 4, 4, 1.0), side_state(3, 4, 4, 1.8), NO, NO)[0] == -1  # obstacle, speeding up
    assert speed(side_state(3, 4, 4, 1.8), side_state(3, 4, 4, 1.0), NO, NO)[0] == 0
    assert speed(side_state(3, 4, 4), side_state(3, 4, 4), YES, NO)[0] == -4


def test_wall_following_rewards_eqs_VI_21_VI_22():
    steer, speed = WallSteeringReward(d_min=0.6), WallSpeedReward(d_safe=2.0)
    assert steer(side_state(3, 1, 4), side_state(3, 1, 4), YES, NO)[0] == -2
    assert steer(side_state(3, 1, 4), side_state(3, 0.5, 4), NO, NO)[0] == -1
    assert steer(side_state(3, 1, 4), side_state(3, 1, 4), NO, NO)[0] == 0
    assert speed(side_state(3, 1, 4, 1.0), side_state(3, 1, 4, 1.5), NO, NO)[0] == -1
    assert speed(side_state(3, 3, 4, 1.0), side_state(3, 3, 4, 1.5), NO, NO)[0] == 0
    assert speed(side_state(3, 1, 4, 1.5), side_state(3, 1, 4, 1.0), NO, NO)[0] == 0


def test_rewards_are_vectorised_over_the_batch():
    before = RobotState(World(), np.zeros((3, 3)), np.ones(3), np.zeros(3), goal=np.array([[5, 0.0], [5, 0.5], [5, 0.5]]))
    after = RobotState(World(), np.zeros((3, 3)), np.ones(3), np.zeros(3), goal=np.array([[4.9, 0.0], [4.9, 0.6], [5.1, 0.4]]))
    assert GoalSteeringReward()(before, after, np.zeros(3, bool), np.zeros(3, bool)).tolist() == [3, -1, -2]
